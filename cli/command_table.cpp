// The command line's one table (cli/command_table.h): the options (each with the reader that
// validates its value into Options), the commands, the parser on Boost.Program_options, the help
// texts generated from the table, and the dispatch.
#include "cli/command_table.h"

#include <boost/program_options.hpp>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/demo_scene.h"
#include "exact/io/suggest.h"
#include "exact/numbers/rational.h"
#include "exact/sliding/limit_surface.h"

namespace wrenchkit::cli {

namespace po = boost::program_options;

namespace {

using Role = Option::Role;

// ---------------------------------------------------------------------------------------------
// Readers: a value's text into its typed field, or a Usage_error naming the option.

[[noreturn]] void bad_value(const std::string& option, const std::string& value, const std::string& why) {
  throw Usage_error(option + ": \"" + value + "\" " + why);
}

bool digits_only(const std::string& v, std::size_t max_digits) {
  return !v.empty() && v.size() <= max_digits && v.find_first_not_of("0123456789") == std::string::npos;
}

// A count (--max-*, --jobs): a non-negative decimal integer.
std::size_t count_value(const std::string& option, const std::string& v) {
  if (!digits_only(v, 18)) bad_value(option, v, "is not a non-negative integer");
  return std::stoull(v);
}

// An integer in [lo, hi] (reference's --cases, --random).
int int_between(const std::string& option, const std::string& v, int lo, int hi) {
  if (!digits_only(v, 9) || std::stol(v) < lo || std::stol(v) > hi)
    bad_value(option, v, "is not an integer between " + std::to_string(lo) + " and " + std::to_string(hi));
  return static_cast<int>(std::stol(v));
}

// --sides N: even, 4..max.
int sides_value(const std::string& option, const std::string& v, int max) {
  if (!digits_only(v, 6)) bad_value(option, v, "is not a positive integer");
  const int n = std::stoi(v);
  if (n < 4 || n % 2 != 0 || n > max)
    throw Usage_error(option + ": " + v + " must be even and between 4 and " + std::to_string(max));
  return n;
}

// One exact number, as in scenes (decimal or p/q), within the scene limits.
Rational exact_value(const Options& o, const std::string& option, const std::string& v) {
  std::string why;
  const std::optional<Rational> q = parse_rational(v, false, o.limits, why);
  if (!q) bad_value(option, v, why);
  return *q;
}

// N exact numbers "a,b[,c]" (named `names` in messages, e.g. "vx,vy,w").
template <std::size_t N>
std::array<Rational, N> exact_values(const Options& o, const std::string& option, const std::string& text,
                                     const char* names) {
  std::vector<std::string> parts(1);
  for (char c : text) {
    if (c == ',') parts.emplace_back();
    else parts.back() += c;
  }
  if (parts.size() != N)
    bad_value(option, text, std::string("is not ") + (N == 2 ? "two" : "three") + " numbers " + names +
                                " separated by commas");
  std::array<Rational, N> v;
  for (std::size_t i = 0; i < N; ++i) v[i] = exact_value(o, option, parts[i]);
  return v;
}

Rational non_negative(const Options& o, const std::string& option, const std::string& v) {
  const Rational q = exact_value(o, option, v);
  if (q < 0) bad_value(option, v, "must be >= 0");
  return q;
}

std::string file_value(const std::string& option, const std::string& v) {
  if (v.empty()) throw Usage_error(option + ": empty value");
  return v;
}

// An option that names a file the command writes (not in batch): its value goes into the field F.
template <std::string Options::*F>
void read_file_name(Options& o, const std::string& n, const std::string& v) {
  o.*F = file_value(n, v);
}
template <std::string Options::*F>
Option file_option(const char* name, const char* help) {
  return {name, "FILE", help, read_file_name<F>, Option::Role::file};
}

template <std::size_t N>
bool all_zero(const std::array<Rational, N>& v) {
  for (const Rational& x : v)
    if (x != 0) return false;
  return true;
}

// ---------------------------------------------------------------------------------------------
// The options. Shared ones first (the groups every command that decides takes), then each
// command's own.

using S = const std::string&;

const Option kHelp{"help,h", nullptr, "this help", [](Options& o, S, S) { o.help = true; }};
const Option kJson{"json", nullptr, "machine-readable output (docs/cli.md)", [](Options& o, S, S) { o.json = true; }};

const Option kMode{"mode", "exact|hybrid|float",
                   "exact: exact arithmetic only; hybrid (default): the float twin's certified predicates, exact "
                   "arithmetic for each one they cannot decide; float: the twin alone (exit 3 if it cannot decide)",
                   [](Options& o, S n, S v) {
                     for (Mode m : {Mode::exact, Mode::hybrid, Mode::float_only})
                       if (v == mode_name(m)) return void(o.mode = m);
                     bad_value(n, v, "is not one of exact, hybrid, float");
                   }};

// The same option with the help line of one command.
Option with_help(Option o, const char* help) {
  o.help = help;
  return o;
}

// The same group with the help line of one of its options (`name`) for one command.
std::vector<Option> with_help(std::vector<Option> group, const std::string& name, const char* help) {
  for (Option& o : group)
    if (o.name == name) o.help = help;
  return group;
}

const std::vector<Option> kLimits = {
    {"max-digits", "N", "digits allowed in one number (default 10000)",
     [](Options& o, S n, S v) { o.limits.max_digits = count_value(n, v); }, Role::limit},
    {"max-exponent", "N", "largest |decimal exponent| (default 10000)",
     [](Options& o, S n, S v) { o.limits.max_exponent = static_cast<long>(count_value(n, v)); }, Role::limit},
    {"max-file-size", "BYTES", "largest scene file (default 67108864)",
     [](Options& o, S n, S v) { o.limits.max_file_bytes = count_value(n, v); }, Role::limit},
    {"max-contacts", "N", "most contacts, support points, outline points (default 100000)",
     [](Options& o, S n, S v) { o.limits.max_contacts = count_value(n, v); }, Role::limit},
    {"max-region-vertices", "N", "most vertices of all support regions together (default 4096)",
     [](Options& o, S n, S v) { o.limits.max_region_vertices = count_value(n, v); }, Role::limit},
    {"max-total-digits", "N", "budget: the digits of all the scene's numbers together (default 20000000)",
     [](Options& o, S n, S v) { o.limits.max_total_digits = count_value(n, v); }, Role::limit},
    {"max-digits-times-contacts", "N",
     "budget: the longest number's digits times the contacts and support points (default 10000000)",
     [](Options& o, S n, S v) { o.limits.max_digits_times_contacts = count_value(n, v); }, Role::limit},
    {"max-work", "N",
     "budget: the work units one question may spend (default 10000000; past it: undecided, exit 3; docs/scene-format.md, Limits)",
     [](Options& o, S n, S v) { o.limits.max_work = count_value(n, v); }, Role::limit},
    {"max-certificate-size", "BYTES",
     "the longest certificate a question may write and check reads (default 8388608; past it: undecided, exit 3)",
     [](Options& o, S n, S v) { o.limits.max_certificate_bytes = count_value(n, v); }, Role::limit},
    {"lenient", nullptr,
     "analyse a scene whose contacts are off body.outline or point out of the body (or whose outline is not a simple "
     "polygon) as given, with a warning, instead of refusing it",
     [](Options& o, S, S) { o.limits.lenient = true; }, Role::limit},
};

const Option kCertificate =
    file_option<&Options::certificate_file>("certificate", "write the force-closure certificate to FILE");
const Option kFormCertificate =
    file_option<&Options::form_certificate_file>("form-certificate", "write the form-closure certificate to FILE");

const Option kTwist{"twist", "vx,vy,w", "the motion (exact numbers: 1, -1/2, 0.25); not the zero twist",
                    [](Options& o, S n, S v) {
                      o.twist = exact_values<3>(o, n, v, "vx,vy,w");
                      if (all_zero(*o.twist)) bad_value(n, v, "is the zero twist (no motion, no load)");
                    }};
const Option kSides{"sides", "N", "polygon sides, even, 4..4096 (default 32)",
                    [](Options& o, S n, S v) { o.sides = sides_value(n, v, kMaxSides); }};
const Option kPushContact{"contact", nullptr,
                          "also the contact mode: sticks, slides left or right (a support of points with every force "
                          "given), and the sticking motion's rotation rate, certified; with forces not given, depends "
                          "(two distributions whose modes differ) where the extreme distributions show it",
                          [](Options& o, S, S) { o.push.contact = true; }};
const Option kPushRegion{"region", nullptr,
                         "a line pusher: also its stable region — the rotation centres of each sense certified stable "
                         "for every distribution (half-planes and polygons), and the stable translations",
                         [](Options& o, S, S) { o.push.region = true; }};
const Option kPushLocus{"locus", nullptr,
                        "a point pusher: also where the body may turn about — an outer bound of the rotation centres "
                        "over every distribution, per sense and contact mode (half-planes and polygons), and the slowest "
                        "it can turn",
                        [](Options& o, S, S) { o.push.locus = true; }};
const Option kTolerance{"tolerance", "EPS",
                        "the limit surface's certified relative error 1/lambda - 1 <= EPS (EPS > 0, exact: 0.01, "
                        "1/100, 1e-3)",
                        [](Options& o, S n, S v) {
                          const Rational e = exact_value(o, n, v);
                          if (e <= 0) bad_value(n, v, "must be > 0");
                          o.tolerance = e;
                          o.tolerance_text = v;
                        }};

const Option kResultant{"resultant", "fx,fy,m", "is this wrench a possible resultant of the contact forces?",
                        [](Options& o, S n, S v) { o.resultant = exact_values<3>(o, n, v, "fx,fy,m"); }};
const Option kNorm{"norm", "L1|Linf",
                   "the grasp wrench space: L1 (default), the hull of the edges (the normal forces sum to at most 1), "
                   "or Linf, the sum of the contacts' cones (each normal force at most 1)",
                   [](Options& o, S n, S v) {
                     if (v == "L1" || v == "l1") o.quality.norm = Quality_norm::l1;
                     else if (v == "Linf" || v == "linf" || v == "Linfinity") o.quality.norm = Quality_norm::linf;
                     else bad_value(n, v, "is not one of L1, Linf");
                   }};
const Option kNormalize{"normalize", "unit-normal|unit-force|as-given",
                        "each contact's edges scaled to normal component 1 (unit-normal, the default; Dex-Net's and "
                        "GraspIt!'s), to unit forces (unit-force), or the edges n +- mu rot90(n) as the scene writes n",
                        [](Options& o, S n, S v) {
                          for (Force_normalization f : {Force_normalization::unit_normal, Force_normalization::unit_force,
                                                        Force_normalization::as_given})
                            if (v == normalization_name(f)) return void(o.quality.normalize = f);
                          bad_value(n, v, "is not one of unit-normal, unit-force, as-given");
                        }};
const Option kTorqueScale{"torque-scale", "T",
                          "the moment's weight against a force in the wrench space (T > 0, exact: 1 (default), 1/10, "
                          "0.25): a wrench is (fx, fy, T*m)",
                          [](Options& o, S n, S v) {
                            const Rational t = exact_value(o, n, v);
                            if (t <= 0) bad_value(n, v, "must be > 0");
                            o.quality.torque_scale = t;
                          }};
const Option kOnly{"only", "epsilon|critical-mu",
                   "answer only the quality epsilon, or only the critical friction coefficient (default: both)",
                   [](Options& o, S n, S v) {
                     if (v == "epsilon") o.quality.critical_mu = false;
                     else if (v == "critical-mu") o.quality.epsilon = false;
                     else bad_value(n, v, "is not one of epsilon, critical-mu");
                   }};
const Option kContactMargins{"contact-margins", nullptr,
                             "also each contact's distance to a degenerate configuration: the least relative volume "
                             "|det|/(|u||v||w|) of three friction-cone edges holding one of its edges (exact, squared)",
                             [](Options& o, S, S) { o.quality.contact_margins = true; }};
const Option kFingerMu{"mu", "M", "the fingers' friction coefficient (exact, >= 0: 1/2, 0.3; default: the scene's \"mu\")",
                       [](Options& o, S n, S v) { o.regions.mu = non_negative(o, n, v); }};
const Option kEdges{"edges", "i,j,...", "pair only these edges of body.outline (edge i from vertex i to i + 1; default: all)",
                    [](Options& o, S n, S v) {
                      o.regions.edges.clear();
                      std::string part;
                      for (std::size_t k = 0; k <= v.size(); ++k) {
                        if (k < v.size() && v[k] != ',') {
                          part += v[k];
                          continue;
                        }
                        if (part.empty() || part.size() > 9 || part.find_first_not_of("0123456789") != std::string::npos)
                          bad_value(n, v, "is not a list of edge indices i,j,... (non-negative integers)");
                        o.regions.edges.push_back(static_cast<std::size_t>(std::stoul(part)));
                        part.clear();
                      }
                    }};
const Option kRank{"rank", "side|epsilon",
                   "rank the closed pairs' (triples') independent boxes by their side (default) or by the grasp's "
                   "epsilon at each box's centre (L1, unit-normal, moments about body.com else the outline's centroid; "
                   "the best one's certificate in --json)",
                   [](Options& o, S n, S v) {
                     if (v != "side" && v != "epsilon") bad_value(n, v, "is not side or epsilon");
                     o.regions.rank_epsilon = v == "epsilon";
                     o.regions.rank_asked = true;
                   }};
const Option kMinSide{"min-side", "X", "rank only independent boxes of side at least X (exact, >= 0; default 0)",
                      [](Options& o, S n, S v) {
                        o.regions.min_side = non_negative(o, n, v);
                        o.regions.rank_asked = true;
                      }};
const Option kFingers{"fingers", "2|3",
                      "how many fingers (2: Nguyen's exact regions, default; 3: per edge triple a certified independent "
                      "cube of placements, or a proof that none closes)",
                      [](Options& o, S n, S v) {
                        if (v != "2" && v != "3") bad_value(n, v, "is not 2 or 3 (frictional fingers)");
                        o.regions.fingers = v == "3" ? 3 : 2;
                      }};
const Option kPreset{"preset", "graspit|dexnet",
                     "a peer's conventions: graspit — L1, unit-normal edges, moments about body.com divided by the body's "
                     "largest radius from it (its outline's farthest vertex; certified when irrational); dexnet — L1, "
                     "unit-normal edges, moments about body.com times --torque-scale (Dex-Net's torque_scaling)",
                     [](Options& o, S n, S v) {
                       if (v == "graspit") o.quality.preset = Quality_preset::graspit;
                       else if (v == "dexnet") o.quality.preset = Quality_preset::dexnet;
                       else bad_value(n, v, "is not one of graspit, dexnet");
                     }};
const Option kAbout{"about", "x,y", "the point the moments are taken about (default: body.com if the scene has one, else the origin)",
                    [](Options& o, S n, S v) {
                      const std::array<Rational, 2> p = exact_values<2>(o, n, v, "x,y");
                      o.quality.about = Vec2{p[0], p[1]};
                    }};
const Option kCenter{"center", "x,y", "a rotation about (x, y), counter-clockwise unless --sense cw",
                     [](Options& o, S n, S v) { o.center = exact_values<2>(o, n, v, "x,y"); }};
const Option kSense{"sense", "ccw|cw", "the sense of the rotation of --center (default ccw)", [](Options& o, S n, S v) {
                      if (v == "ccw" || v == "+") o.sense = 1;
                      else if (v == "cw" || v == "-") o.sense = -1;
                      else bad_value(n, v, "is not one of ccw, cw");
                    }};
const Option kDirection{"direction", "dx,dy",
                        "the translation toward the point at infinity (dx, dy) (velocity (dy, -dx), theory.md §5.1)",
                        [](Options& o, S n, S v) {
                          o.direction = exact_values<2>(o, n, v, "dx,dy");
                          if (all_zero(*o.direction)) throw Usage_error(n + ": the zero vector is no direction");
                        }};

const Option kWhat{"what", "labels|dual|reuleaux|limit-surface|hold|quality|grasp-regions|push", "what to draw (required)", [](Options& o, S n, S v) {
                     if (v == "labels") o.what = Picture::labels;
                     else if (v == "dual") o.what = Picture::dual;
                     else if (v == "reuleaux") o.what = Picture::reuleaux;
                     else if (v == "limit-surface") o.what = Picture::limit_surface;
                     else if (v == "hold") o.what = Picture::hold;
                     else if (v == "quality") o.what = Picture::quality;
                     else if (v == "grasp-regions") o.what = Picture::grasp_regions;
                     else if (v == "push") o.what = Picture::push;
                     else bad_value(n, v, "is not one of labels, dual, reuleaux, limit-surface, hold, quality, grasp-regions, push");
                   }};
const Option kOutput = file_option<&Options::output>("output,o", "write the SVG to FILE (default: standard output)");

const Option kLoad{"load", "fx,fy,m",
                   "also \"motion\": sticks (certainly inside LS), slides (certainly not inside), or undecided "
                   "(refine N); the gauge bounds, and the cones of twists of LS_out and LS_in at the load's direction",
                   [](Options& o, S n, S v) { o.load = exact_values<3>(o, n, v, "fx,fy,m"); }};
const Option kList{"list", nullptr, "list every facet (normal, offset, vertex indices) and vertex, exactly",
                   [](Options& o, S, S) { o.list = true; }};
const Option kOff = file_option<&Options::off_file>(
    "off", "write both polytopes as one OFF mesh with face colours (inner blue, then outer red; CGAL's writer)");
const Option kObj = file_option<&Options::obj_file>(
    "obj", "write both polytopes as one Wavefront OBJ mesh (the inner polytope's vertices and faces first)");
const Option kPly = file_option<&Options::ply_file>(
    "ply", "write both polytopes as one binary PLY mesh (face colours; face property polytope: 0 inner, 1 outer)");
const Option kExactCoordinates{"exact-coordinates", nullptr,
                               "mesh files with exact coordinates where the format has them: OFF as homogeneous "
                               "integers X Y Z W (4OFF); OBJ and PLY hold doubles (the answer says which)",
                               [](Options& o, S, S) { o.exact_coordinates = true; }, Option::Role::file};
const Option kSvg =
    file_option<&Options::svg_file>("svg", "write the picture of 'wrenchkit render --what limit-surface' to FILE");

const Option kJobs{"jobs", "N", "threads (default: all cores); the output is the same for any N",
                   [](Options& o, S n, S v) {
                     const std::size_t j = count_value(n, v);
                     if (j < 1 || j > 1024) throw Usage_error(n + ": must be between 1 and 1024");
                     o.jobs = static_cast<unsigned>(j);
                   }};
const Option kVerdictOnly{"verdict-only", nullptr,
                          "skip certificates and their check (throughput runs; the verdicts are the same, but "
                          "nothing proves them)",
                          [](Options& o, S, S) { o.verdict_only = true; }};

// ---------------------------------------------------------------------------------------------
// The commands.

std::vector<Option> join(std::initializer_list<std::vector<Option>> groups) {
  std::vector<Option> all;
  for (const std::vector<Option>& g : groups) all.insert(all.end(), g.begin(), g.end());
  return all;
}

int run_scene_closure(const Options& o, const std::string& text, const std::string& source) {
  return run_closure(o, text, source, "closure");
}
int run_scene_analyze(const Options& o, const std::string& text, const std::string& source) {
  return run_analyze(o, text, source, "analyze");
}
int run_demo(const Options& o) {
  if (!o.json) std::cout << "wrenchkit demo: 'wrenchkit analyze' on a bundled scene (theory.md §8.7, with gravity)\n\n";
  return run_analyze(o, kDemoScene, "demo", "demo");
}

const char* const kScene = "SCENE.json";

std::vector<Command> make_table() {
  std::vector<Command> t;
  t.push_back(
      {"closure",
       "force closure of the contacts with their friction, and first-order form closure of the same contacts read "
       "frictionless (Reuleaux), with certificates",
       "[OPTIONS] SCENE.json",
       "Decides, exactly, whether the scene's contacts hold the body in force closure (every wrench\n"
       "is a possible resultant of the contact forces, friction included) and in first-order form\n"
       "closure (the contacts read frictionless admit no motion: Reuleaux's method). Each verdict\n"
       "comes with a certificate that the independent checker re-verifies before the answer is\n"
       "printed (exit 4 if it ever fails).\n",
       join({{kHelp, kJson, kMode, kCertificate, kFormCertificate}, kLimits}),
       {kScene},
       run_scene_closure,
       nullptr,
       prepare_closure_json,
       {kVerdictOnly}});
  t.push_back(
      {"equilibrium",
       "can the contacts, with their friction, balance the scene's load? With a certificate either way (the contact "
       "forces, or a motion the load drives)",
       "[OPTIONS] SCENE.json",
       "Decides, exactly, whether the contacts with their friction can balance the scene's load\n"
       "(\"load\": a force at a point, a wrench, or gravity at body.com): whether minus the load is a\n"
       "possible resultant. Balanced: the certificate gives non-negative multiples of the friction-cone\n"
       "edges that cancel the load. Not balanced: a twist that every contact allows and that the load\n"
       "drives with positive power. The independent checker re-verifies it before the answer is printed.\n",
       join({{kHelp, kJson,
              with_help(kMode,
                        "exact: the exact cone LP; hybrid (default): the float twin's certified signs on the dual "
                        "cone, exact where they cannot decide; float: the twin alone (exit 3 if it cannot decide)"),
              with_help(kCertificate, "write the certificate to FILE")},
             kLimits}),
       {kScene},
       run_equilibrium,
       nullptr,
       prepare_equilibrium_json});
  t.push_back(
      {"labels",
       "the moment labels of the contact wrench cone: the + and - regions, the +- set and the labeled points at "
       "infinity, exactly (Mason ch. 5)",
       "[OPTIONS] SCENE.json",
       "Moment labeling of the contact wrench cone W (friction included), exactly (theory.md §5):\n"
       "  +   points about which every possible contact wrench has moment >= 0 (the centres of the\n"
       "      counter-clockwise rotations every contact allows), - the same for <= 0 (clockwise),\n"
       "  +-  points about which every moment is zero, and the labeled points at infinity (the\n"
       "      translations every contact allows). Force closure <=> nothing is labeled.\n"
       "Regions are exact: rational corners counter-clockwise and primitive integer directions where\n"
       "they run to infinity; region = conv(vertices) + pos(directions) (docs/cli.md).\n"
       "With a load in the scene, also whether it can be balanced (read on the labels).\n",
       join({{kHelp, kJson, kMode, kResultant}, kLimits}),
       {kScene},
       run_labels,
       nullptr,
       prepare_labels_json});
  t.push_back(
      {"dual", "the force-dual polygon of the contact wrench cone on the two-sided plane", "[OPTIONS] SCENE.json",
       "The force dual (theory.md §6): each wrench w = (fx, fy, m) is the point D(w) = (-fy, fx, m) of\n"
       "the two-sided plane (front sheet m > 0, back sheet m < 0, at infinity m = 0), and the wrench\n"
       "cone is a convex polygon through infinity. covers_all <=> force closure. When the + label\n"
       "region has interior points, also the ordinary polygon about a reference point inside it.\n",
       join({{kHelp, kJson, kMode}, kLimits}),
       {kScene},
       run_dual,
       nullptr,
       prepare_dual_json});
  t.push_back(
      {"reuleaux",
       "Reuleaux's method: feasible rotation centres of the contacts read frictionless, and per-contact modes "
       "(break/slide/stick) of a given motion",
       "[OPTIONS] SCENE.json",
       "Reuleaux's method (theory.md §7): the contacts read frictionless; the + / - regions are the\n"
       "feasible counter-clockwise / clockwise rotation centres, the labeled points at infinity the\n"
       "feasible translations. None at all <=> first-order form closure. With a motion (at most one of\n"
       "--center, --direction, --twist), each contact's mode: break (v.n > 0), slide (v.n = 0, v != 0),\n"
       "stick (v = 0), penetrate (v.n < 0).\n",
       join({{kHelp, kJson, kMode, kCenter, kSense, kDirection, with_help(kTwist, "any twist vx,vy,w but zero")},
             kLimits}),
       {kScene},
       run_reuleaux,
       nullptr,
       prepare_reuleaux_json});
  t.push_back(
      {"render", "an SVG picture: render SCENE.json --what labels|dual|reuleaux|limit-surface|hold|quality -o FILE.svg",
       "SCENE.json --what labels|dual|reuleaux|limit-surface|hold|quality [-o FILE.svg]",
       "Draws the construction as an SVG picture (standard output without -o): the body, the\n"
       "contacts with their friction cones (or normals), the lines of force, the + / - regions\n"
       "shaded and clipped to a disc whose rim is the circle at infinity (labeled directions drawn\n"
       "on it, arrows where regions run off), the load, and a legend. Exact construction, drawn in\n"
       "floating point. docs/gallery.md shows the textbook cases.\n"
       "\n"
       "With --what limit-surface: the support's inner and outer polygonal limit surfaces (the f_y = 0\n"
       "slice, the (f_x, m) and (f_x, f_y) projections), --sides N as for limit-surface (default 32).\n"
       "\n"
       "With --what hold: the contacts, the support points (discs grow with mu*f), the load and, when it does\n"
       "not hold, the motion of the certificate's twist (its rotation centre and sense, or its direction),\n"
       "decided as 'wrenchkit hold' (hybrid) decides it.\n"
       "\n"
       "With --what quality: three slices of the grasp wrench space through the origin (m = 0, f_y = 0, f_x = 0)\n"
       "with the ball of radius epsilon, as 'wrenchkit quality' computes them (--norm, --normalize,\n"
       "--torque-scale, --about).\n"
       "\n"
       "With --what grasp-regions: the part with the largest two-finger region's reach on its two edges, and the\n"
       "(s, t) squares of the largest regions with their force-closure polygons, as 'wrenchkit grasp-regions'\n"
       "computes them (--mu, --edges).\n"
       "\n"
       "With --what push: the body on its support, the centre of friction, the pusher with its friction cone and\n"
       "velocity, and the three voting lines through it coloured by their votes, as 'wrenchkit push' decides;\n"
       "--contact adds the contact mode and where the body turns (its rotation centre, or its direction); with a\n"
       "line pusher, the segment, its cones and the verdict, and --region shades its stable region; --locus (a point\n"
       "pusher) shades where the body may turn about, every distribution.\n",
       join({{kHelp, kWhat, kOutput,
              with_help(kSides, "with --what limit-surface: polygon sides, even, 4..4096 (default 32)"), kNorm, kNormalize,
              kTorqueScale, kAbout, kFingerMu, kEdges, kFingers,
              with_help(kPushContact, "with --what push: also the contact mode and the body's rotation centre"),
              with_help(kPushRegion, "with --what push and a line pusher: also its stable region"),
              with_help(kPushLocus, "with --what push and a point pusher: also where the body may turn about")},
             kLimits}),
       {kScene},
       run_render});
  t.push_back(
      {"check", "the independent checker (proofs/): accepts (exit 0) or rejects (exit 1) a certificate",
       "[OPTIONS] SCENE.json CERT.json",
       "Runs the independent checker of proofs/ (GMP only, its own parser, sharing no code with the\n"
       "engine): it recomputes every generator from SCENE.json and accepts CERT.json only if it\n"
       "proves its claim (proofs/certificate-format.md). Exit 0 accepted, 1 rejected, 2 bad scene.\n",
       join({{kHelp, kJson}, kLimits}),
       {kScene, "CERT.json"},
       nullptr,
       run_check});
  t.push_back(
      {"limit-surface",
       "certified polygonal inner and outer limit surfaces of the scene's support, with queries: the load for a "
       "twist, sticks/slides for a load (--sides, --tolerance)",
       "[OPTIONS] SCENE.json",
       "Builds, exactly, the polygonal inner and outer limit surfaces of the scene's \"support\"\n"
       "(theory.md §12): every friction disc is replaced by the inscribed and the circumscribed N-gon of\n"
       "rational unit directions, and the Minkowski sums LS_in and LS_out are computed as exact polytopes\n"
       "(facets and vertices; coplanar facets merged). The certificate lambda^2 = (1 + min u_j.u_(j+1))/2\n"
       "guarantees  lambda*LS <= LS_in <= LS <= LS_out <= LS/lambda, i.e. for every twist q the true\n"
       "frictional power h(q) satisfies lambda*h <= h_in <= h <= h_out <= h/lambda.\n"
       "\n"
       "Sign convention (theory.md §1.5): every wrench here is the LOAD the slider applies to the support\n"
       "(parallel to the sliding velocity); the friction wrench on the slider is its negative. Wrenches are\n"
       "fx,fy,m with m about the origin; twists vx,vy,w with w counter-clockwise.\n"
       "\n"
       "Modes: hybrid (default): the polytopes exactly; --load's motion by the float twin's certified\n"
       "search on the TRUE limit surface first, the polytopes when it cannot tell; with --twist also the\n"
       "true power and load (certified float bounds). exact: exact arithmetic only (the motion from the\n"
       "polytopes: may be undecided). float: the float twin alone: no polytopes; lambda^2, the polygonal\n"
       "and true powers and loads with certified bounds, the motion by the search (exit 3 if undecided).\n"
       "\n"
       "Exact rationals are printed in lowest terms. Mesh files (--off, --obj, --ply; CGAL's writers) hold\n"
       "both polytopes, inner first, with every coordinate as its nearest double; --exact-coordinates\n"
       "writes OFF exactly (homogeneous integers, 4OFF), and the answer says how each file was written.\n"
       "\n"
       "Support regions (docs/regions.md): their limit surface is strictly convex, so there is no exact\n"
       "polytope (--sides, --list, --off, --obj, --ply are refused; --svg draws the support shaded by its\n"
       "pressure); --twist gives the certified power\n"
       "and load (--tolerance: their relative width, default 1e-6), --load sticks or slides with a\n"
       "certificate (cells of the regions with forces inside their discs, or a twist with speed bounds\n"
       "at the cells' vertices) that the independent checker accepts; float mode answers undecided.\n",
       join({{kHelp, kJson, with_help(kMode, "hybrid (default), exact or float: see Modes above"), kSides,
              with_help(kTolerance,
                        "instead of --sides: the smallest N whose certified relative error 1/lambda - 1 is <= EPS "
                        "(EPS > 0, exact: 0.01, 1/100, 1e-3)"),
              with_help(kTwist,
                        "also the load for this twist on LS_in and LS_out (a point, a segment or a facet), the "
                        "bounds h_in <= h <= h_out, and what the twist is on the true LS"),
              kLoad, with_help(kCertificate, "write the certificate of --load's motion to FILE (checked first)"), kList,
              kOff, kObj, kPly, kExactCoordinates, kSvg},
             kLimits}),
       {kScene},
       run_limit_surface,
       nullptr,
       prepare_limit_surface_json});
  t.push_back(
      {"sliding", "centre of friction and the frictional load of the support for a twist (--twist)",
       "[OPTIONS] SCENE.json",
       "Planar sliding of the body on the scene's \"support\" (theory.md §10): the centre of friction\n"
       "(pressure centroid, exact) and, with --twist, the frictional load for that motion.\n"
       "  translation (w = 0): the load is the force mu*f0 along v through the friction centroid,\n"
       "    exactly: load = (mu*f0/|v|) * (vx, vy, c x v); printed as an exact vector when |v| is rational;\n"
       "  rotation about a point c: the power h = sum mu_i f_i |v_i| lies between the exact polygonal\n"
       "    bounds h_in <= h <= h_out (theory.md §12.3), the loads of LS_in and LS_out are given exactly,\n"
       "    and an exact rational box contains the true load. When c is a support point the load is a\n"
       "    FACET: that point's friction disc, translated; the box then contains the facet's centre.\n"
       "\n"
       "Sign convention (theory.md §1.5): the LOAD is the wrench the slider applies to the support,\n"
       "parallel to the sliding velocity; the friction wrench on the slider is its negative.\n"
       "\n"
       "Modes: hybrid (default): the exact answer above, plus the TRUE power and load from the float\n"
       "twin with certified bounds (\"true_power\", \"true_load\"). exact: exact arithmetic only.\n"
       "float: the float twin alone: centre of friction, polygonal and true power, true load, each\n"
       "with a certified bound (no exact polygons).\n"
       "\n"
       "Support regions (polygons with holes and a continuous pressure, docs/regions.md): the total\n"
       "force and the centre of friction exactly; for a rotation the power and the load are certified\n"
       "brackets (closed forms in interval arithmetic) whose relative width meets --tolerance (default\n"
       "1e-6); translations are exact as for points. exact and hybrid answer alike; float has no twin\n"
       "of regions (exit 3).\n",
       join({{kHelp, kJson, with_help(kMode, "hybrid (default), exact or float: see Modes above"), kTwist,
              with_help(kSides, "sides of the polygons for the bounds (even, 4..4096, default 64; points only)"),
              with_help(kTolerance, "support regions: the relative width of the power's certified bracket (EPS > 0, "
                                    "exact: 1e-6 (the default), 1/1000)")},
             kLimits}),
       {kScene},
       run_sliding,
       nullptr,
       prepare_sliding_json});
  t.push_back(
      {"hold",
       "fixtures on a support: can the contacts together with the support's friction hold the body against the "
       "scene's load? Holds, does not (with the motion), or depends, with a certificate",
       "[OPTIONS] SCENE.json",
       "A body on a horizontal support (\"support\": its points, their normal forces and friction) is touched\n"
       "by the scene's contacts (with their friction) and pushed by the scene's in-plane \"load\" (a force at a\n"
       "point or a wrench). Does it hold — can contact forces in their friction cones and support friction\n"
       "forces in their discs balance the load (minus the load in W + LS(f), docs/fixtures.md)? The answer is\n"
       "\"holds\": true (with the forces), false (with the motion the body takes: a rotation centre or a\n"
       "translation direction, allowed by every contact and driven past the most the support's friction can\n"
       "resist), or, when some support forces are not given, \"depends\" (one admissible distribution holds,\n"
       "another does not) — each with a certificate the independent checker re-verifies first. A load that\n"
       "friction can just carry (on the boundary) holds; one within the resolution of inscribed 256-gons of\n"
       "that boundary whose witnesses are irrational is \"undecided\", with the reason.\n"
       "No support: hold is equilibrium. No contacts: hold is stick/slide, except on the limit surface itself\n"
       "(stick/slide says a load there slides; hold says friction can just carry it).\n",
       join({{kHelp, kJson,
              with_help(kMode,
                        "hybrid (default): float witnesses checked exactly, then exact LPs on inscribed N-gons; exact: "
                        "exact arithmetic only; float: the float witnesses alone (exit 3 if they decide nothing)"),
              with_help(kCertificate, "write the certificate to FILE (checked first)")},
             kLimits}),
       {kScene},
       run_hold,
       nullptr,
       prepare_hold_json});
  t.push_back(
      {"quality",
       "how good is the grasp: the Ferrari-Canny quality epsilon of the contacts with their friction, exact or in a "
       "certified bracket, with a certificate",
       "[OPTIONS] SCENE.json",
       "The grasp wrench space of the contacts (each friction cone's two edges, scaled to unit normal force by\n"
       "default, as wrenches (fx, fy, T*m) about body.com or the origin) is a convex polytope; epsilon is the\n"
       "radius of the largest ball about the origin inside it: 0 unless the grasp is in force closure, and the\n"
       "size of the smallest wrench the grasp cannot resist with unit contact forces. L1: the hull of the edges\n"
       "(the normal forces sum to at most 1); Linf: each normal force at most 1. epsilon^2 is given exactly when\n"
       "the scales are rational (unit normals such as (3/5, 4/5), or --normalize as-given); otherwise epsilon is\n"
       "certified in a bracket of relative width --tolerance. The certificate (the closed boundary of the wrench\n"
       "space and its nearest facet, or a facet normal, or the twist of an open grasp) is re-verified first.\n"
       "Also the critical friction coefficient mu*: with one mu for every point contact, the least mu at which the\n"
       "contacts are in force closure (closed for every mu above it) and, with a load, at which they balance it —\n"
       "exact when rational (the two-finger grasp: the tangent of the contact line's angle), else a bracket of\n"
       "relative width --tolerance; \"always\" (closed without friction) or \"never\" said as such; certificates on\n"
       "both sides (the property failing just below and holding at or above, each re-verified).\n",
       join({{kHelp, kJson, kOnly, kContactMargins, kPreset, kNorm, kNormalize, kTorqueScale, kAbout,
              with_help(kTolerance, "the bracket's width relative to its lower end when epsilon is irrational (EPS > 0, "
                                    "exact: 1e-12 (the default), 1/1000)"),
              with_help(kMode,
                        "hybrid (default) and exact: force closure in that mode, then epsilon and mu* in exact arithmetic; "
                        "float: force closure by the twin alone, and exit 3 for a closed grasp or mu* (no float twin)"),
              with_help(kCertificate, "write the certificate to FILE (checked first)")},
             kLimits}),
       {kScene},
       run_quality,
       nullptr,
       prepare_quality_json});
  t.push_back(
      {"grasp-regions",
       "where two or three fingers may go: exact force-closure regions on a polygon part, with a certificate",
       "[OPTIONS] PART.json",
       "Two frictional fingers on body.outline, each pushing along its edge's inward normal with friction --mu: a\n"
       "finger on edge i (from vertex i to i + 1) at v_i + s (v_{i+1} - v_i), the other on edge j at t. By Nguyen's\n"
       "theorem the pair is in force closure exactly when the segment between the fingers lies strictly inside both\n"
       "friction cones: four strict linear inequalities in (s, t). So each edge pair's region is a convex polygon in\n"
       "the unit square of (s, t), exact, with rational corners (its sides on the cones' lines excluded). Every pair\n"
       "i < j is answered (\"closed\": [] when no placement closes); the certificate (the regions) is re-derived and\n"
       "accepted by the independent checker first. The scene's contacts are not used.\n"
       "With --fingers 3, every edge triple i < j < k: an independent cube of placements (s_0, s_1, s_2) that all\n"
       "close, certified by four friction-cone wrenches whose signed cofactors keep one sign at its eight corners\n"
       "(they are multilinear in the parameters), the largest a search finds; or \"never\" with a proof that no\n"
       "placement closes (mu = 0, or a wrench-space direction no wrench of the triple exceeds).\n",
       join({{kHelp, kJson, kFingerMu, kEdges, kFingers, kRank, kMinSide,
              with_help(kCertificate, "write the certificate to FILE (checked first)")},
             kLimits}),
       {"PART.json"},
       run_grasp_regions,
       nullptr,
       prepare_grasp_regions_json});
  t.push_back(
      {"push",
       "which way a pushed body turns, for every pressure distribution: Mason's voting theorem, exact, with a certificate",
       "[OPTIONS] SCENE.json",
       "The scene's \"pusher\" (a point contact on the body: at, inward normal, mu, and its velocity into the body)\n"
       "pushes the body sliding quasi-statically on its \"support\". Three directed lines through the pusher vote:\n"
       "the friction cone's two edges and the velocity, each ccw or cw by the side of the centre of friction c it\n"
       "passes. The edges voting alike decide; voting apart, the velocity decides (Mason 1986). Every tie (a line\n"
       "through c) is answered: \"none\" (a translation) where the theorem says so. Exact signs; with support forces\n"
       "not given, every admissible distribution is covered by the exact LP over them (\"depends\", with two\n"
       "distributions that turn the body apart, when c moves with them). The certificate is accepted by the\n"
       "independent checker first. Exit 3 when undecided (the reason is said).\n",
       join({{kHelp, kJson,
              with_help(kMode, "exact or hybrid (the default): the votes in rationals, with the certificate; float: the "
                               "float twin's certified signs (a support of points with every force given), no "
                               "certificate, exit 3 when a sign is within its error bound"),
              kPushContact, kPushRegion, kPushLocus,
              with_help(kTolerance, "with --contact: the sticking rotation rate's relative bracket width (default 1e-12)"),
              with_help(kCertificate, "write the certificate to FILE (checked first)")},
             kLimits}),
       {kScene},
       run_push,
       nullptr,
       prepare_push_json});
  t.push_back(
      {"analyze",
       "everything the scene calls for: closure, equilibrium when it has a load, a summary of the limit surface "
       "when it has a support",
       "[OPTIONS] SCENE.json",
       "Everything the scene's contents call for, and nothing else: force and form closure of its\n"
       "contacts, and equilibrium when it has a load, each with a checked certificate; a summary of the\n"
       "limit surface when it has a support (N = 32 sides or fewer for large supports, or the fewest\n"
       "sides meeting --tolerance), and with a force or wrench load also whether that load sticks or\n"
       "slides on the support. What cannot be computed within analyze's budget is listed as skipped.\n",
       join({{kHelp, kJson,
              with_help(kMode, "as for closure; hybrid asks the float twin first everywhere"),
              with_help(kTolerance, "the limit surface's certified relative error 1/lambda - 1 <= EPS (EPS > 0)")},
             kLimits}),
       {kScene},
       run_scene_analyze,
       nullptr,
       prepare_analyze_json});
  t.push_back({"demo", "analyze of a bundled textbook scene (Mason's Example 3), no file needed", "[OPTIONS]",
               "Runs 'analyze' on a bundled textbook scene: Mason's Example 3, a triangle held by three\n"
               "fingers whose normals meet in one point (theory.md §8.7), under its own weight. Frictionless it\n"
               "is not closed; with friction mu = 1/10 it is in force closure, so gravity is balanced.\n",
               {kHelp, kJson, kMode},
               {},
               nullptr,
               run_demo});
  t.push_back(
      {"batch",
       "wrenchkit batch COMMAND [FILE ...]: one scene per line, one JSON answer per line in order, on all "
       "cores (--jobs N), for each command that answers per scene",
       "COMMAND [OPTIONS] [FILE ...]",
       "Reads one scene per line (JSON lines) from the files in their order, or standard input (- or no\n"
       "file), and writes one JSON answer per line, in the same order, lines numbered on across the files,\n"
       "computed on --jobs threads (the output is the same for any --jobs): the\n"
       "output of 'wrenchkit COMMAND --json' with a \"line\" field first, or {\"line\": N, \"error\":\n"
       "MESSAGE, \"exit_code\": 2} for a bad line (the stream goes on), {\"line\": N, \"undecided\": …,\n"
       "\"exit_code\": 3} when --mode float cannot decide. The command's own options apply to every\n"
       "line (batch sliding --twist 0,0,1, batch labels --resultant 0,1,0, batch limit-surface --sides 8),\n"
       "except those that write files (--certificate, --off, --obj, --ply, --svg); --max-file-size limits\n"
       "each line. Every certificate is checked by the independent checker, as in the single commands.\n"
       "Exit code: 0 when every line was answered or reported, 2 for a usage error (before any line is\n"
       "read), 4 if a certificate ever failed its check (a bug), 70 on an internal error.\n",
       {kHelp, kJobs},
       {"COMMAND"}});
  t.push_back(
      {"reference",
       "wrenchkit reference --out DIR: the reference corpus for other implementations (scenes, exact answers, "
       "checked certificates, distance to a degenerate boundary)",
       "--out DIR [OPTIONS]",
       "Writes the reference corpus for testing other grasp and sliding implementations against exact\n"
       "answers (docs/reference-format.md): the golden textbook scenes of tests/golden, the near-degenerate\n"
       "families of docs/stability.md at several distances eps, and random scenes (generic decimal text;\n"
       "degenerate-rich integer grids). Each scene comes with its exact answers (force and form closure,\n"
       "equilibrium when it has a load, moment labels, limit-surface bounds when it has a support), its\n"
       "certificates (each accepted by the independent checker before it is written), and how close it is\n"
       "to a degenerate boundary. Deterministic: the same options give the same bytes on every run.\n"
       "\n"
       "DIR gets reference.jsonl (one scene per line), scenes/ID.json (each scene's canonical text),\n"
       "expected.csv (the simple verdicts) and manifest.json. DIR must not exist, be empty, or hold an\n"
       "earlier corpus (which is replaced); nothing is written unless the whole corpus was built.\n"
       "\n"
       "With --scenes FILE.jsonl|DIR, the corpus holds your own scenes instead, in the same format:\n"
       "FILE has one scene per line (id line.N) or {\"id\": ID, \"family\": F, \"scene\": SCENE} per line;\n"
       "DIR holds scene files *.json (id: the path without .json, family: the directory).\n"
       "Compare an implementation's answers with: wrenchkit compare DIR answers.jsonl\n",
       {kHelp, with_help(kJson, "print the summary as JSON"),
        {"out", "DIR", "where to write the corpus (required)",
         [](Options& o, S n, S v) { o.out_dir = file_value(n, v); }},
        {"seed", "S", "seed of the families and random scenes (default 20261122)",
         [](Options& o, S n, S v) {
           if (!digits_only(v, 19)) bad_value(n, v, "is not a non-negative integer");
           o.reference.seed = std::stoull(v);
         }},
        {"cases", "N", "scenes per near-degenerate family and eps (default 2; 20 for a big corpus)",
         [](Options& o, S n, S v) { o.reference.cases = int_between(n, v, 0, 1000); }},
        {"random", "N", "scenes per random family (default 100; 2000 for a big corpus)",
         [](Options& o, S n, S v) { o.reference.random = int_between(n, v, 0, 100000); }},
        {"sides", "N", "polygon sides of the limit-surface bounds (even, 4..64, default 16)",
         [](Options& o, S n, S v) { o.reference.sides = sides_value(n, v, 64); }},
        {"scenes", "FILE|DIR", "your own scenes (JSON lines, or a directory of scene files) instead of the families",
         [](Options& o, S n, S v) { o.reference.scenes = file_value(n, v); }}},
       {},
       nullptr,
       nullptr,
       nullptr,
       {},
       &Conformance_commands::reference});
  t.push_back(
      {"compare",
       "wrenchkit compare DIR ANSWERS: another implementation's answers (JSON lines or CSV) against the corpus; each "
       "disagreement with its scene (exit 1 if any)",
       "[OPTIONS] CORPUS ANSWERS",
       "Compares another implementation's answers with the reference corpus written by 'wrenchkit\n"
       "reference' (CORPUS: its directory, or its reference.jsonl). ANSWERS (- for standard input) is\n"
       "JSON lines, one object per answered scene:\n"
       "  {\"id\": \"golden.ladder_mu_1_7\", \"force_closure\": false, \"form_closure\": false}\n"
       "with any of the fields force_closure, form_closure, equilibrium (true/false, 1/0, 1.0/0.0, null),\n"
       "motion (sticks/slides/depends),\n"
       "center_of_friction ([x, y]), power ([h, ...]: the frictional power for each of the scene's\n"
       "limit_surface.twists), labels ({\"plus\": R, \"minus\": R}, R with any of empty, shape,\n"
       "vertices), error (a string: the implementation gave no answer). Fields starting with _ are\n"
       "ignored; null means no answer. Or CSV (a name ending in .csv, or --format csv) with a header\n"
       "line: id and any of force_closure, form_closure, equilibrium; cells true, false, 1, 0 or empty.\n"
       "Numbers are read exactly from their text and compared within --rtol/--atol; power must lie in\n"
       "the exact bracket of the true power (widened by the tolerance).\n"
       "\n"
       "Reports per field and per family the agreements and the disagreements, the unsafe ones (falsely\n"
       "closed, falsely balanced, falsely sticks) apart from the lost ones (falsely open, unbalanced,\n"
       "slides), and each disagreement with its scene id, family, eps, the field's own distance to a\n"
       "degenerate boundary and the scene's file: disagreements far from any boundary are listed first\n"
       "(likely bugs), then those within --near (or your documented --tolerance) of one or on an exact\n"
       "degeneracy (likely tolerance issues). Scenes without an answer are counted, not failed.\n"
       "\n"
       "Exit codes: 0 every given answer agrees, 1 disagreements found, 2 bad input (a malformed line,\n"
       "an unknown id or field: the message names the line and the field).\n",
       join({{kHelp, with_help(kJson, "machine-readable report (docs/reference-format.md)"),
              {"format", "jsonl|csv", "the answers' format (default: by the file name; jsonl for -)",
               [](Options& o, S n, S v) {
                 if (v != "jsonl" && v != "csv") bad_value(n, v, "is not one of jsonl, csv");
                 o.compare.format = v;
               }},
              {"rtol", "R", "relative tolerance (default 1e-9): |a - r| <= atol + rtol*|r|",
               [](Options& o, S n, S v) { o.compare.rtol = non_negative(o, n, v); }},
              {"atol", "A", "absolute tolerance (default 1e-12)",
               [](Options& o, S n, S v) { o.compare.atol = non_negative(o, n, v); }},
              {"near", "D", "a distance <= D counts as near a boundary (default 1e-9)",
               [](Options& o, S n, S v) { o.compare.near = non_negative(o, n, v); }},
              with_help(kTolerance, "the tolerance your implementation documents: a disagreement within EPS of a "
                                    "degenerate boundary counts as near (EPS > 0)")},
             with_help(kLimits, "max-file-size", "largest answers file (default 67108864)")}),
       {"CORPUS", "ANSWERS"},
       nullptr,
       nullptr,
       nullptr,
       {},
       &Conformance_commands::compare});
  return t;
}

const Command* find_command(const std::string& name) {
  for (const Command& c : commands())
    if (name == c.name) return &c;
  return nullptr;
}

// ---------------------------------------------------------------------------------------------
// Parsing.

// What one command line may hold: `name` for messages ("closure", "batch closure").
struct Grammar {
  std::string name;
  std::vector<Option> options;
  const Command* batch_of = nullptr;  // batch COMMAND: that command
};

po::options_description describe(const std::vector<Option>& options) {
  po::options_description d("options", 100, 50);
  auto add = d.add_options();
  for (const Option& o : options) {
    if (o.value) add(o.name, po::value<std::string>()->value_name(o.value), o.help);
    else add(o.name, o.help);
  }
  return d;
}

// The long name of Boost's spelling "output,o".
std::string long_name(const char* name) {
  const std::string n = name;
  return n.substr(0, n.find(','));
}

// Whether the option token ("--center", "-o", "--center=1,1") is one of `o`'s spellings.
bool spells(const Option& o, std::string token) {
  token = token.substr(0, token.find('='));
  const std::string n = o.name;
  const std::size_t comma = n.find(',');
  return token == "--" + n.substr(0, comma) || (comma != std::string::npos && token == "-" + n.substr(comma + 1));
}

// An option the command does not take: another command's (or batch's file writers), or none at all.
[[noreturn]] void not_an_option(const Grammar& g, const std::string& token) {
  if (g.batch_of)
    for (const Option& o : g.batch_of->options)
      if (o.role == Role::file && spells(o, token))
        throw Usage_error("batch writes certificates and answers in its output lines, not to files");
  for (const Command& c : commands())
    for (const std::vector<Option>* list : {&c.options, &c.batch_options})
      for (const Option& o : *list)
        if (spells(o, token)) throw Usage_error(token.substr(0, token.find('=')) + " is not an option of " + g.name);
  const std::string name = token.substr(0, token.find('='));
  std::vector<std::string> known;
  for (const Option& o : g.options) known.push_back(long_name(o.name));
  const std::string meant = name.rfind("--", 0) == 0 ? closest_word(name.substr(2), known) : std::string();
  throw Usage_error("unknown option " + token + (meant.empty() ? "" : " (did you mean --" + meant + "?)"));
}

Options parse(const Grammar& g, const std::vector<std::string>& args) {
  const po::options_description d = describe(g.options);
  po::parsed_options parsed(&d);
  try {
    using namespace po::command_line_style;
    // No guessing of abbreviations, no "-abc" bundles; a value may start with '-' (-1/2,0,1).
    parsed = po::command_line_parser(args)
                 .options(d)
                 .style(unix_style & ~allow_guessing & ~allow_sticky)
                 .run();
  } catch (const po::unknown_option& e) {
    not_an_option(g, e.get_option_name());
  } catch (const po::invalid_command_line_syntax& e) {
    if (e.kind() == po::invalid_command_line_syntax::missing_parameter)
      throw Usage_error(e.get_option_name() + " needs a value");
    if (e.kind() == po::invalid_command_line_syntax::extra_parameter)
      throw Usage_error(e.get_option_name() + " takes no value");
    throw Usage_error(e.what());
  } catch (const po::error& e) {
    throw Usage_error(e.what());
  }
  // Each value into its typed field: the limits first (the exact numbers are read within them), then
  // the others in their order on the command line.
  Options o;
  std::set<std::string> seen;
  for (const bool limits : {true, false})
    for (const po::option& p : parsed.options) {
      if (p.position_key >= 0) {
        if (!limits) o.positional.push_back(p.value.at(0));
        continue;
      }
      for (const Option& spec : g.options) {
        if (long_name(spec.name) != p.string_key || (spec.role == Role::limit) != limits) continue;
        const std::string option = "--" + p.string_key;
        if (spec.value && !seen.insert(p.string_key).second) throw Usage_error(option + " given twice");
        spec.read(o, option, spec.value ? p.value.at(0) : std::string());
      }
    }
  return o;
}

// ---------------------------------------------------------------------------------------------
// Help texts, generated from the table.

// `text` wrapped at `width` columns, continuation lines indented by `indent` spaces.
std::string wrap(const std::string& text, std::size_t column, std::size_t indent, std::size_t width) {
  std::istringstream words(text);
  std::string out, word;
  std::size_t at = column;
  bool first = true;
  while (words >> word) {
    if (!first && at + 1 + word.size() > width) {
      out += "\n" + std::string(indent, ' ');
      at = indent;
    } else if (!first) {
      out += ' ';
      ++at;
    }
    out += word;
    at += word.size();
    first = false;
  }
  return out;
}

std::string main_help() {
  std::string s =
      "usage: wrenchkit COMMAND [OPTIONS] SCENE.json     (SCENE.json may be - for standard input)\n"
      "       wrenchkit --help | COMMAND --help | --version\n"
      "\n"
      "commands:\n";
  const std::size_t column = 17;
  for (const Command& c : commands()) {
    std::string line = "  " + std::string(c.name);
    line += std::string(column - line.size(), ' ');
    s += line + wrap(c.summary, column, column, 100) + "\n";
  }
  return s +
         "\n"
         "Run 'wrenchkit COMMAND --help' for a command's options. Exit codes: 0 answered, 1 check\n"
         "rejected the certificate, 2 bad input or usage, 3 --mode float could not decide, 4 an\n"
         "answer failed its own certificate check (a bug), 70 internal error.\n";
}

std::string options_text(const std::vector<Option>& options) {
  std::ostringstream s;
  s << describe(options);
  std::string text = s.str(), out;  // without the blanks Boost leaves where it wraps a line
  for (char c : text) {
    if (c == '\n')
      while (!out.empty() && out.back() == ' ') out.pop_back();
    out += c;
  }
  return out;
}

std::string command_help(const Command& c) {
  std::string s = "usage: wrenchkit " + std::string(c.name) + " " + c.usage + "\n\n" + c.description;
  if (std::string(c.name) == "batch") {
    std::string names;
    for (const Command& x : commands())
      if (x.prepare) names += (names.empty() ? "" : ", ") + std::string(x.name);
    s += "\n" + wrap("COMMAND: " + names + "; 'wrenchkit batch COMMAND --help' lists its options.", 0, 0, 100) + "\n";
  }
  return s + "\n" + options_text(c.options);
}

// batch COMMAND's options: batch's own, the command's batch-only ones, and the command's own but those
// that write files.
Grammar batch_grammar(const Command& batch, const Command& c) {
  Grammar g{"batch " + std::string(c.name), batch.options, &c};
  g.options.insert(g.options.end(), c.batch_options.begin(), c.batch_options.end());
  for (const Option& o : c.options)
    if (o.role != Role::file && std::string(o.name) != kHelp.name) g.options.push_back(o);
  return g;
}

int run_batch_command(const Command& batch, const std::vector<std::string>& args) {
  std::string names;
  for (const Command& x : commands())
    if (x.prepare) names += (names.empty() ? "" : "|") + std::string(x.name);
  const std::string usage = "wrenchkit batch " + names + " [OPTIONS] [FILE ...]";
  if (args.size() >= 2 && (args[1] == "--help" || args[1] == "-h")) return std::cout << command_help(batch), kAnswered;
  if (args.size() < 2 || (args[1].size() > 1 && args[1][0] == '-')) throw Usage_error("batch needs a command: " + usage);
  const Command* c = find_command(args[1]);
  if (!c || !c->prepare) {
    std::vector<std::string> per_scene;
    for (const Command& x : commands())
      if (x.prepare) per_scene.push_back(x.name);
    throw Usage_error("batch: \"" + args[1] + "\" is not a command that answers per scene" +
                      did_you_mean(closest_word(args[1], per_scene)) + ": " + usage);
  }
  const Grammar g = batch_grammar(batch, *c);
  const Options o = parse(g, std::vector<std::string>(args.begin() + 2, args.end()));
  if (o.help) {
    std::cout << "usage: wrenchkit batch " << c->name << " [OPTIONS] [FILE ...]\n\n"
              << "For each scene of the files (- or none: standard input), one line: the answer of 'wrenchkit "
              << c->name << " --json'\n"
              << "('wrenchkit batch --help'). What " << c->name << " answers:\n\n"
              << c->description << "\n"
              << options_text(g.options);
    return kAnswered;
  }
  return run_batch(o, c->prepare(o));  // the command's options combined once, before any line
}

}  // namespace

Batch_job prepare_batch(const std::vector<std::string>& args) {
  const Command* batch = find_command("batch");
  const Command* c = args.empty() ? nullptr : find_command(args[0]);
  if (!c || !c->prepare)
    throw Usage_error("batch: \"" + (args.empty() ? std::string() : args[0]) + "\" is not a command that answers per scene");
  const Options o = parse(batch_grammar(*batch, *c), std::vector<std::string>(args.begin() + 1, args.end()));
  if (o.help || !o.positional.empty()) throw Usage_error("batch " + args[0] + ": takes options only, no --help or scene files");
  return {o, c->prepare(o)};
}

Options parse_options(const std::string& command, const std::vector<std::string>& args) {
  const Command* c = find_command(command);
  if (!c) throw std::logic_error("parse_options: no command " + command);
  return parse(Grammar{c->name, c->options}, args);
}

const std::vector<Command>& commands() {
  static const std::vector<Command> table = make_table();
  return table;
}

int run_command_line(const std::vector<std::string>& args, const Conformance_commands& conformance) {
  if (args.empty()) {
    std::cerr << main_help();
    return kBadInput;
  }
  const std::string& name = args[0];
  if (name == "--help" || name == "-h" || name == "help") return std::cout << main_help(), kAnswered;
  if (name == "--version") return std::cout << "wrenchkit 0.1.0\n", kAnswered;
  const Command* c = find_command(name);
  if (!c) {
    std::vector<std::string> names;
    for (const Command& x : commands()) names.push_back(x.name);
    const std::string meant = closest_word(name, names);
    throw Usage_error("unknown command \"" + name + "\" (" + (meant.empty() ? "" : "did you mean \"" + meant + "\"? ") +
                      "try wrenchkit --help)");
  }
  if (std::string(c->name) == "batch") return run_batch_command(*c, args);
  const Options o = parse(Grammar{c->name, c->options}, std::vector<std::string>(args.begin() + 1, args.end()));
  if (o.help) return std::cout << command_help(*c), kAnswered;
  const std::size_t n = c->positionals.size();
  if (o.positional.size() != n) {
    if (n == 0) throw Usage_error(name + " takes no scene file");
    if (n == 1) throw Usage_error(name + " needs exactly one " + c->positionals[0]);
    throw Usage_error(name + " needs " + c->positionals[0] + " and " + c->positionals[1]);
  }
  if (c->scene) {
    const std::string& path = o.positional[0];
    return c->scene(o, read_input(path, o.limits.max_file_bytes), path == "-" ? "<stdin>" : path);
  }
  return c->conformance ? (conformance.*c->conformance)(o) : c->run(o);
}

}  // namespace wrenchkit::cli
