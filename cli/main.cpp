// wrenchkit — the command line (docs/cli.md): usage texts and dispatch. Each
// command lives in cli/<command>_command.cpp; shared pieces in cli/common.h.
#include <iostream>
#include <string>

#include "cli/common.h"
#include "cli/demo_scene.h"
#include "cli/reference.h"
#include "exact/io/input_error.h"

namespace wrenchkit::cli {
namespace {

const char* kUsage =
    "usage: wrenchkit COMMAND [OPTIONS] SCENE.json     (SCENE.json may be - for standard input)\n"
    "\n"
    "commands:\n"
    "  closure   force closure of the contacts with their friction, and first-order form\n"
    "            closure of the same contacts read frictionless (Reuleaux), with certificates\n"
    "  equilibrium  can the contacts, with their friction, balance the scene's load? With a\n"
    "            certificate either way (the contact forces, or a motion the load drives)\n"
    "  labels    the moment labels of the contact wrench cone: the + and - regions, the +- set\n"
    "            and the labeled points at infinity, exactly (Mason ch. 5)\n"
    "  dual      the force-dual polygon of the contact wrench cone on the two-sided plane\n"
    "  reuleaux  Reuleaux's method: feasible rotation centres of the contacts read frictionless,\n"
    "            and per-contact modes (break/slide/stick) of a given motion\n"
    "  render    an SVG picture: render SCENE.json --what labels|dual|reuleaux|limit-surface\n"
    "            -o FILE.svg\n"
    "  check     wrenchkit check SCENE.json CERT.json: the independent checker (proofs/)\n"
    "            accepts (exit 0) or rejects (exit 1) a certificate\n"
    "  limit-surface  certified polygonal inner and outer limit surfaces of the scene's support,\n"
    "            with queries: the load for a twist, sticks/slides for a load (--sides, --tolerance)\n"
    "  sliding   centre of friction and the frictional load of the support for a twist (--twist)\n"
    "  analyze   everything the scene calls for: closure, and equilibrium when it has a load\n"
    "  demo      analyze of a bundled textbook scene (Mason's Example 3), no file needed\n"
    "  batch     wrenchkit batch COMMAND < scenes.jsonl: one scene per line, one JSON answer per\n"
    "            line in order, on all cores (--jobs N), for each command that answers per scene\n"
    "  reference wrenchkit reference --out DIR: the reference corpus for other implementations\n"
    "            (scenes, exact answers, checked certificates, distance to a degenerate boundary)\n"
    "  compare   wrenchkit compare DIR ANSWERS: another implementation's answers (JSON lines or\n"
    "            CSV) against the corpus; each disagreement with its scene (exit 1 if any)\n"
    "\n"
    "Run 'wrenchkit COMMAND --help' for a command's options. Exit codes: 0 answered, 1 check\n"
    "rejected the certificate, 2 bad input or usage, 3 --mode float could not decide, 4 an\n"
    "answer failed its own certificate check (a bug), 70 internal error.\n";

const char* kClosureHelp =
    "usage: wrenchkit closure [OPTIONS] SCENE.json\n"
    "\n"
    "Decides, exactly, whether the scene's contacts hold the body in force closure (every wrench\n"
    "is a possible resultant of the contact forces, friction included) and in first-order form\n"
    "closure (the contacts read frictionless admit no motion: Reuleaux's method). Each verdict\n"
    "comes with a certificate that the independent checker re-verifies before the answer is\n"
    "printed (exit 4 if it ever fails).\n"
    "\n"
    "options:\n"
    "  --json                    machine-readable output (docs/cli.md)\n"
    "  --mode exact|hybrid|float exact: exact arithmetic only; hybrid (default): the float twin's\n"
    "                            certified predicates, exact arithmetic for each one they cannot\n"
    "                            decide; float: the twin alone (exit 3 if it cannot decide)\n"
    "  --certificate FILE        write the force-closure certificate to FILE\n"
    "  --form-certificate FILE   write the form-closure certificate to FILE\n"
    "  --max-digits N            digits allowed in one number (default 10000)\n"
    "  --max-exponent N          largest |decimal exponent| (default 10000)\n"
    "  --max-file-size BYTES     largest scene file (default 67108864)\n"
    "  --max-contacts N          most contacts (default 100000)\n";

const char* kEquilibriumHelp =
    "usage: wrenchkit equilibrium [OPTIONS] SCENE.json\n"
    "\n"
    "Decides, exactly, whether the contacts with their friction can balance the scene's load\n"
    "(\"load\": a force at a point, a wrench, or gravity at body.com): whether minus the load is a\n"
    "possible resultant. Balanced: the certificate gives non-negative multiples of the friction-cone\n"
    "edges that cancel the load. Not balanced: a twist that every contact allows and that the load\n"
    "drives with positive power. The independent checker re-verifies it before the answer is printed.\n"
    "\n"
    "options:\n"
    "  --json, --certificate FILE, --max-* (as for closure)\n"
    "  --mode exact|hybrid|float  exact: the exact cone LP; hybrid (default): the float twin's\n"
    "                             certified signs on the dual cone, exact where they cannot decide;\n"
    "                             float: the twin alone (exit 3 if it cannot decide)\n";

const char* kLabelsHelp =
    "usage: wrenchkit labels [OPTIONS] SCENE.json\n"
    "\n"
    "Moment labeling of the contact wrench cone W (friction included), exactly (theory.md §5):\n"
    "  +   points about which every possible contact wrench has moment >= 0 (the centres of the\n"
    "      counter-clockwise rotations every contact allows), - the same for <= 0 (clockwise),\n"
    "  +-  points about which every moment is zero, and the labeled points at infinity (the\n"
    "      translations every contact allows). Force closure <=> nothing is labeled.\n"
    "Regions are exact: rational corners counter-clockwise and primitive integer directions where\n"
    "they run to infinity; region = conv(vertices) + pos(directions) (docs/cli.md).\n"
    "\n"
    "options:\n"
    "  --json                    machine-readable output (docs/cli.md)\n"
    "  --resultant fx,fy,m       is this wrench a possible resultant of the contact forces?\n"
    "  --max-*                   input limits, as for closure\n"
    "With a load in the scene, also whether it can be balanced (read on the labels).\n";

const char* kDualHelp =
    "usage: wrenchkit dual [OPTIONS] SCENE.json\n"
    "\n"
    "The force dual (theory.md §6): each wrench w = (fx, fy, m) is the point D(w) = (-fy, fx, m) of\n"
    "the two-sided plane (front sheet m > 0, back sheet m < 0, at infinity m = 0), and the wrench\n"
    "cone is a convex polygon through infinity. covers_all <=> force closure. When the + label\n"
    "region has interior points, also the ordinary polygon about a reference point inside it.\n"
    "\n"
    "options: --json, --max-* (as for closure)\n";

const char* kReuleauxHelp =
    "usage: wrenchkit reuleaux [OPTIONS] SCENE.json\n"
    "\n"
    "Reuleaux's method (theory.md §7): the contacts read frictionless; the + / - regions are the\n"
    "feasible counter-clockwise / clockwise rotation centres, the labeled points at infinity the\n"
    "feasible translations. None at all <=> first-order form closure. With a motion, each contact's\n"
    "mode: break (v.n > 0), slide (v.n = 0, v != 0), stick (v = 0), penetrate (v.n < 0).\n"
    "\n"
    "options:\n"
    "  --json\n"
    "  --center x,y [--sense ccw|cw]   a rotation about (x, y) (default counter-clockwise)\n"
    "  --direction dx,dy               the translation toward the point at infinity (dx, dy)\n"
    "                                  (velocity (dy, -dx), theory.md §5.1)\n"
    "  --twist vx,vy,w                 any twist\n"
    "  --max-*                         input limits, as for closure\n";

const char* kRenderHelp =
    "usage: wrenchkit render SCENE.json --what labels|dual|reuleaux|limit-surface [-o FILE.svg]\n"
    "\n"
    "Draws the construction as an SVG picture (standard output without -o): the body, the\n"
    "contacts with their friction cones (or normals), the lines of force, the + / - regions\n"
    "shaded and clipped to a disc whose rim is the circle at infinity (labeled directions drawn\n"
    "on it, arrows where regions run off), the load, and a legend. Exact construction, drawn in\n"
    "floating point. docs/gallery.md shows the textbook cases.\n"
    "\n"
    "With --what limit-surface: the support's inner and outer polygonal limit surfaces (the f_y = 0\n"
    "slice, the (f_x, m) and (f_x, f_y) projections), --sides N as for limit-surface (default 32).\n"
    "\n"
    "options: --what labels|dual|reuleaux|limit-surface, -o/--output FILE, --sides N, --max-*\n";

const char* kAnalyzeHelp =
    "usage: wrenchkit analyze [OPTIONS] SCENE.json\n"
    "\n"
    "Everything the scene's contents call for, and nothing else: force and form closure of its\n"
    "contacts, and equilibrium when it has a load, each with a checked certificate; a summary of the\n"
    "limit surface when it has a support (N = 32 sides or fewer for large supports, or the fewest\n"
    "sides meeting --tolerance), and with a force or wrench load also whether that load sticks or\n"
    "slides on the support. What cannot be computed within analyze's budget is listed as skipped.\n"
    "\n"
    "options: --json, --mode (as for closure; hybrid asks the float twin first everywhere),\n"
    "         --tolerance EPS (the limit surface's certified relative error 1/lambda - 1 <= EPS), --max-*\n";

const char* kCheckHelp =
    "usage: wrenchkit check [OPTIONS] SCENE.json CERT.json\n"
    "\n"
    "Runs the independent checker of proofs/ (GMP only, its own parser, sharing no code with the\n"
    "engine): it recomputes every generator from SCENE.json and accepts CERT.json only if it\n"
    "proves its claim (proofs/certificate-format.md). Exit 0 accepted, 1 rejected, 2 bad scene.\n"
    "\n"
    "options: --json, and the --max-* limits of 'wrenchkit closure --help'\n";

const char* kBatchHelp =
    "usage: wrenchkit batch COMMAND [OPTIONS] < scenes.jsonl\n"
    "       COMMAND: closure, equilibrium, labels, dual, reuleaux, limit-surface, sliding, analyze\n"
    "\n"
    "Reads one scene per line (JSON lines) on standard input and writes one JSON answer per line,\n"
    "in the same order, computed on --jobs threads (the output is the same for any --jobs): the\n"
    "output of 'wrenchkit COMMAND --json' with a \"line\" field first, or {\"line\": N, \"error\":\n"
    "MESSAGE, \"exit_code\": 2} for a bad line (the stream goes on), {\"line\": N, \"undecided\": …,\n"
    "\"exit_code\": 3} when --mode float cannot decide. The command's own options apply to every\n"
    "line (batch sliding --twist 0,0,1, batch labels --resultant 0,1,0, batch limit-surface --sides 8).\n"
    "Every certificate is checked by the independent checker, as in the single commands.\n"
    "\n"
    "options:\n"
    "  --jobs N           threads (default: all cores)\n"
    "  --verdict-only     closure only: skip certificates and their check (throughput runs; the\n"
    "                     verdicts are the same, but nothing proves them)\n"
    "  --mode, --max-*    as for the command (--max-file-size limits each line)\n"
    "  COMMAND's options  except those that write files (--certificate, --off, --obj, --svg)\n"
    "Exit code: 0 when every line was answered or reported, 2 for a usage error (before any line is\n"
    "read), 4 if a certificate ever failed its check (a bug), 70 on an internal error.\n";

const char* kDemoHelp =
    "usage: wrenchkit demo [--json]\n"
    "\n"
    "Runs 'analyze' on a bundled textbook scene: Mason's Example 3, a triangle held by three\n"
    "fingers whose normals meet in one point (theory.md §8.7), under its own weight. Frictionless it\n"
    "is not closed; with friction mu = 1/10 it is in force closure, so gravity is balanced.\n";


int dispatch(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << kUsage;
    return kBadInput;
  }
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    std::cout << kUsage;
    return kAnswered;
  }
  if (command == "--version") {
    std::cout << "wrenchkit 0.1.0\n";
    return kAnswered;
  }
  if (command == "reference") return run_reference(argc, argv);
  if (command == "compare") return run_compare(argc, argv);
  const Options o = parse_options(argc, argv, 2);
  const auto scene_command = [&](const char* help, int (*run)(const Options&, const std::string&, const std::string&)) {
    if (o.help) return std::cout << help, static_cast<int>(kAnswered);
    if (o.positional.size() != 1) throw Usage_error(command + " needs exactly one SCENE.json");
    const std::string& path = o.positional[0];
    return run(o, read_input(path, o.limits.max_file_bytes), path == "-" ? "<stdin>" : path);
  };
  if (command == "labels") return scene_command(kLabelsHelp, run_labels);
  if (command == "dual") return scene_command(kDualHelp, run_dual);
  if (command == "reuleaux") return scene_command(kReuleauxHelp, run_reuleaux);
  if (command == "render") return scene_command(kRenderHelp, run_render);
  if (command == "limit-surface") return scene_command(kLimitSurfaceHelp, run_limit_surface);
  if (command == "sliding") return scene_command(kSlidingHelp, run_sliding);
  if (command == "batch") {
    if (o.help) return std::cout << kBatchHelp, kAnswered;
    return run_batch(o);
  }
  if (command == "analyze") {
    if (o.help) return std::cout << kAnalyzeHelp, kAnswered;
    if (o.positional.size() != 1) throw Usage_error("analyze needs exactly one SCENE.json");
    const std::string& path = o.positional[0];
    return run_analyze(o, read_input(path, o.limits.max_file_bytes), path == "-" ? "<stdin>" : path, "analyze");
  }
  if (!o.values.empty()) throw Usage_error(o.values.begin()->first + " is not an option of " + command);
  if (command == "closure") {
    if (o.help) return std::cout << kClosureHelp, kAnswered;
    if (o.positional.size() != 1) throw Usage_error("closure needs exactly one SCENE.json");
    const std::string& path = o.positional[0];
    const std::string text = read_input(path, o.limits.max_file_bytes);
    return run_closure(o, text, path == "-" ? "<stdin>" : path, "closure");
  }
  if (command == "equilibrium") {
    if (o.help) return std::cout << kEquilibriumHelp, kAnswered;
    if (o.positional.size() != 1) throw Usage_error("equilibrium needs exactly one SCENE.json");
    const std::string& path = o.positional[0];
    return run_equilibrium(o, read_input(path, o.limits.max_file_bytes), path == "-" ? "<stdin>" : path);
  }
  if (command == "check") {
    if (o.help) return std::cout << kCheckHelp, kAnswered;
    return run_check(o);
  }
  if (command == "demo") {
    if (o.help) return std::cout << kDemoHelp, kAnswered;
    if (!o.positional.empty()) throw Usage_error("demo takes no scene file");
    if (!o.json)
      std::cout << "wrenchkit demo: 'wrenchkit analyze' on a bundled scene (theory.md §8.7, with gravity)\n\n";
    return run_analyze(o, kDemoScene, "demo", "demo");
  }
  throw Usage_error("unknown command \"" + command + "\" (try wrenchkit --help)");
}

}  // namespace
}  // namespace wrenchkit::cli

int main(int argc, char** argv) {
  using namespace wrenchkit::cli;
  std::ios::sync_with_stdio(false);  // buffered iostreams (batch reads and writes millions of lines)
  try {
    return dispatch(argc, argv);
  } catch (...) {
    return report(failure_of(std::current_exception()));
  }
}
