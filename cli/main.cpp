// wrenchkit — the command line (interface.md §2, docs/cli.md).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/demo_scene.h"
#include "exact/closure.h"
#include "exact/input_error.h"
#include "exact/json.h"
#include "exact/scene.h"
#include "proofs/checker/checker.h"

namespace wrenchkit::cli {
namespace {

enum Exit { kAnswered = 0, kRejected = 1, kBadInput = 2, kUndecided = 3, kSelfCheck = 4, kInternal = 70 };

const char* kUsage =
    "usage: wrenchkit COMMAND [OPTIONS] SCENE.json     (SCENE.json may be - for standard input)\n"
    "\n"
    "commands:\n"
    "  closure   force closure of the contacts with their friction, and first-order form\n"
    "            closure of the same contacts read frictionless (Reuleaux), with certificates\n"
    "  check     wrenchkit check SCENE.json CERT.json: the independent checker (proofs/)\n"
    "            accepts (exit 0) or rejects (exit 1) a certificate\n"
    "  demo      closure of a bundled textbook scene (Mason's Example 3), no file needed\n"
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

const char* kCheckHelp =
    "usage: wrenchkit check [OPTIONS] SCENE.json CERT.json\n"
    "\n"
    "Runs the independent checker of proofs/ (GMP only, its own parser, sharing no code with the\n"
    "engine): it recomputes every generator from SCENE.json and accepts CERT.json only if it\n"
    "proves its claim (proofs/certificate-format.md). Exit 0 accepted, 1 rejected, 2 bad scene.\n"
    "\n"
    "options: --json, and the --max-* limits of 'wrenchkit closure --help'\n";

const char* kDemoHelp =
    "usage: wrenchkit demo [--json]\n"
    "\n"
    "Runs 'closure' on a bundled textbook scene: Mason's Example 3, a triangle held by three\n"
    "fingers whose normals meet in one point (theory.md §8.7). Frictionless it is not closed;\n"
    "with friction mu = 1/10 it is in force closure.\n";

struct Options {
  bool json = false;
  bool help = false;
  std::string mode = "hybrid";
  std::string certificate_file, form_certificate_file;
  Input_limits limits;
  std::vector<std::string> positional;
};

struct Usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::size_t parse_count(const std::string& opt, const std::string& v) {
  if (v.empty() || v.size() > 18 || v.find_first_not_of("0123456789") != std::string::npos)
    throw Usage_error(opt + ": \"" + v + "\" is not a non-negative integer");
  return std::stoull(v);
}

Options parse_options(int argc, char** argv, int first) {
  Options o;
  for (int i = first; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw Usage_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--json") o.json = true;
    else if (a == "--help" || a == "-h") o.help = true;
    else if (a == "--mode") o.mode = value();
    else if (a == "--certificate") o.certificate_file = value();
    else if (a == "--form-certificate") o.form_certificate_file = value();
    else if (a == "--max-digits") o.limits.max_digits = parse_count(a, value());
    else if (a == "--max-exponent") o.limits.max_exponent = static_cast<long>(parse_count(a, value()));
    else if (a == "--max-file-size") o.limits.max_file_bytes = parse_count(a, value());
    else if (a == "--max-contacts") o.limits.max_contacts = parse_count(a, value());
    else if (a.size() > 1 && a[0] == '-' && a != "-") throw Usage_error("unknown option " + a);
    else o.positional.push_back(a);
  }
  if (o.mode != "exact" && o.mode != "hybrid" && o.mode != "float")
    throw Usage_error("--mode: \"" + o.mode + "\" is not one of exact, hybrid, float");
  return o;
}

// Reads a whole file (or standard input for "-"), refusing more than `limit` bytes.
std::string read_input(const std::string& path, std::size_t limit) {
  std::istream* in = &std::cin;
  std::ifstream file;
  if (path != "-") {
    file.open(path, std::ios::binary);
    if (!file) throw Input_error(path + ": cannot open (" + std::strerror(errno) + ")");
    in = &file;
  }
  std::string data;
  char buf[1 << 16];
  while (*in) {
    in->read(buf, sizeof buf);
    data.append(buf, static_cast<std::size_t>(in->gcount()));
    if (data.size() > limit)
      throw Input_error(path + ": larger than the size limit of " + std::to_string(limit) +
                        " bytes (--max-file-size)");
  }
  if (in->bad()) throw Input_error(path + ": read error");
  return data;
}

// Writes FILE atomically: a temporary beside it, then a rename, so nothing is half-written.
void write_file(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp-wrenchkit";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Input_error(path + ": cannot write (" + std::strerror(errno) + ")");
    out << text;
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw Input_error(path + ": write failed");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw Input_error(path + ": cannot write (" + std::strerror(errno) + ")");
  }
}

wrenchkit_checker::Limits checker_limits(const Input_limits& l) {
  wrenchkit_checker::Limits c;
  c.max_digits = l.max_digits;
  c.max_exponent = l.max_exponent;
  c.max_depth = l.max_depth;
  c.max_contacts = l.max_contacts;
  return c;
}

struct Self_check_failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string vec_text(const std::array<Rational, 3>& v) {
  return "(" + to_string(v[0]) + ", " + to_string(v[1]) + ", " + to_string(v[2]) + ")";
}

std::string human_verdict(const Closure_answer& a, bool form) {
  std::ostringstream s;
  s << (a.holds ? "yes" : "no") << "  (" << a.generators << " generator"
    << (a.generators == 1 ? "" : "s") << ", rank " << a.rank << ")\n    ";
  const Closure_certificate& c = a.certificate;
  if (a.holds) {
    s << "certificate: strictly positive weights on " << c.combination.size()
      << " generators sum to the zero wrench:";
    for (const auto& [ref, w] : c.combination)
      s << " " << to_string(w) << "·c" << ref.contact << "." << edge_name(ref.edge);
    s << "; so every wrench is a" << (form ? " resisted load: no motion is possible" : " possible resultant");
  } else {
    const Twist_reading r = read_twist(c.twist);
    s << "certificate: the twist " << vec_text(c.twist) << " has power >= 0 against every generator";
    if (r.label == 'i')
      s << " (a translation; its centre is at infinity in direction (" << to_string(r.point[0])
        << ", " << to_string(r.point[1]) << "))";
    else
      s << " (a " << (r.label == '+' ? "counter-clockwise" : "clockwise") << " rotation about ("
        << to_string(r.point[0]) << ", " << to_string(r.point[1]) << "), labeled " << r.label << ")";
    s << (form ? "; the contacts allow this motion to first order"
               : "; the wrench -t is not a possible resultant");
  }
  return s.str();
}

struct Undecided : std::runtime_error {
  using std::runtime_error::runtime_error;
};

Mode mode_of(const std::string& m) {
  return m == "exact" ? Mode::exact : (m == "float" ? Mode::float_only : Mode::hybrid);
}

std::string decided_by(const Closure_answer& a, const Closure_answer& b) {
  const std::string x = a.decided_by(), y = b.decided_by();
  return x == y ? x : "hybrid";
}

int run_closure(const Options& o, const std::string& scene_text, const std::string& source,
                const char* command) {
  const Scene scene = read_scene(scene_text, o.limits, source);
  const Mode mode = mode_of(o.mode);
  const Closure_answer fc = decide_closure(scene, Property::force_closure, mode);
  const Closure_answer fo = decide_closure(scene, Property::form_closure, mode);
  if (!fc.decided || !fo.decided)
    throw Undecided(std::string("the float twin could not certify ") +
                    (!fc.decided ? (!fo.decided ? "force or form closure" : "force closure") : "form closure") +
                    " of this scene (a predicate is within its error bound of zero); use --mode hybrid or exact");
  const std::string fc_json = certificate_json(fc.certificate);
  const std::string fo_json = certificate_json(fo.certificate);
  // Every verdict is re-checked by the independent checker before it is reported.
  for (const std::string* cert : {&fc_json, &fo_json}) {
    const auto r = wrenchkit_checker::check(scene_text, *cert, checker_limits(o.limits));
    if (r.outcome != wrenchkit_checker::Outcome::accepted)
      throw Self_check_failure("the independent checker rejected our own certificate: " +
                               r.message + "\ncertificate: " + *cert);
  }
  if (!o.certificate_file.empty()) write_file(o.certificate_file, fc_json + "\n");
  if (!o.form_certificate_file.empty()) write_file(o.form_certificate_file, fo_json + "\n");

  if (o.json) {
    std::cout << "{\"command\": \"" << command << "\", \"name\": " << json::quote(scene.name)
              << ", \"mode\": \"" << o.mode << "\", \"decided_by\": \"" << decided_by(fc, fo) << "\""
              << ", \"force_closure\": " << (fc.holds ? "true" : "false")
              << ", \"form_closure\": " << (fo.holds ? "true" : "false")
              << ", \"rank\": {\"force\": " << fc.rank << ", \"form\": " << fo.rank << "}"
              << ", \"generators\": {\"force\": " << fc.generators << ", \"form\": " << fo.generators
              << "}, \"predicates\": {\"force\": " << fc.predicates << ", \"form\": " << fo.predicates
              << "}, \"exact_predicates\": {\"force\": " << fc.exact_predicates << ", \"form\": "
              << fo.exact_predicates << "}, \"certificates_checked\": true"
              << ", \"certificate\": " << fc_json << ", \"form_certificate\": " << fo_json << "}\n";
  } else {
    std::cout << "scene: " << (scene.name.empty() ? source : scene.name) << "\n"
              << "force closure: " << human_verdict(fc, false) << "\n"
              << "form closure:  " << human_verdict(fo, true) << "\n"
              << "decided by: " << decided_by(fc, fo) << " (" << fc.exact_predicates + fo.exact_predicates
              << " of " << fc.predicates + fo.predicates << " predicates in exact arithmetic)\n"
              << "both certificates accepted by the independent checker (exact arithmetic)\n";
  }
  return kAnswered;
}

int run_check(const Options& o) {
  if (o.positional.size() != 2) throw Usage_error("check needs SCENE.json and CERT.json");
  if (o.positional[0] == "-" && o.positional[1] == "-")
    throw Usage_error("check: SCENE.json and CERT.json cannot both be standard input");
  const std::string scene = read_input(o.positional[0], o.limits.max_file_bytes);
  const std::string cert = read_input(o.positional[1], o.limits.max_file_bytes);
  const auto r = wrenchkit_checker::check(scene, cert, checker_limits(o.limits));
  using wrenchkit_checker::Outcome;
  if (r.outcome == Outcome::bad_scene) throw Input_error(o.positional[0] + ": " + r.message);
  const bool ok = r.outcome == Outcome::accepted;
  if (o.json)
    std::cout << "{\"accepted\": " << (ok ? "true" : "false")
              << ", \"reason\": " << json::quote(ok ? "" : r.message) << "}\n";
  else
    std::cout << (ok ? "accepted" : "rejected: " + r.message) << "\n";
  return ok ? kAnswered : kRejected;
}

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
  const Options o = parse_options(argc, argv, 2);
  if (command == "closure") {
    if (o.help) return std::cout << kClosureHelp, kAnswered;
    if (o.positional.size() != 1) throw Usage_error("closure needs exactly one SCENE.json");
    const std::string& path = o.positional[0];
    const std::string text = read_input(path, o.limits.max_file_bytes);
    return run_closure(o, text, path == "-" ? "<stdin>" : path, "closure");
  }
  if (command == "check") {
    if (o.help) return std::cout << kCheckHelp, kAnswered;
    return run_check(o);
  }
  if (command == "demo") {
    if (o.help) return std::cout << kDemoHelp, kAnswered;
    if (!o.positional.empty()) throw Usage_error("demo takes no scene file");
    if (!o.json)
      std::cout << "wrenchkit demo: 'wrenchkit closure' on a bundled scene (theory.md §8.7)\n\n";
    return run_closure(o, kDemoScene, "demo", "demo");
  }
  throw Usage_error("unknown command \"" + command + "\" (try wrenchkit --help)");
}

}  // namespace
}  // namespace wrenchkit::cli

int main(int argc, char** argv) {
  using namespace wrenchkit::cli;
  try {
    return dispatch(argc, argv);
  } catch (const Usage_error& e) {
    std::cerr << "wrenchkit: usage error: " << e.what() << "\n";
    return kBadInput;
  } catch (const wrenchkit::Input_error& e) {
    std::cerr << "wrenchkit: error: " << e.what() << "\n";
    return kBadInput;
  } catch (const Undecided& e) {
    std::cerr << "wrenchkit: undecided: " << e.what() << "\n";
    return kUndecided;
  } catch (const Self_check_failure& e) {
    std::cerr << "wrenchkit: internal error (please report): " << e.what() << "\n";
    return kSelfCheck;
  } catch (const std::bad_alloc&) {
    std::cerr << "wrenchkit: internal error: out of memory\n";
    return kInternal;
  } catch (const std::exception& e) {
    std::cerr << "wrenchkit: internal error (please report): " << e.what() << "\n";
    return kInternal;
  }
}
