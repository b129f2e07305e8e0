// wrenchkit — the command line (interface.md §2, docs/cli.md).
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/demo_scene.h"
#include "exact/closure.h"
#include "exact/equilibrium.h"
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
    "  equilibrium  can the contacts, with their friction, balance the scene's load? With a\n"
    "            certificate either way (the contact forces, or a motion the load drives)\n"
    "  check     wrenchkit check SCENE.json CERT.json: the independent checker (proofs/)\n"
    "            accepts (exit 0) or rejects (exit 1) a certificate\n"
    "  analyze   everything the scene calls for: closure, and equilibrium when it has a load\n"
    "  demo      analyze of a bundled textbook scene (Mason's Example 3), no file needed\n"
    "  batch     wrenchkit batch closure < scenes.jsonl: one scene per line, one answer per line,\n"
    "            on all cores (--jobs N)\n"
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
    "  --mode exact|hybrid    both decide exactly (the float twin of equilibrium is not written yet)\n";

const char* kAnalyzeHelp =
    "usage: wrenchkit analyze [OPTIONS] SCENE.json\n"
    "\n"
    "Everything the scene's contents call for, and nothing else: force and form closure of its\n"
    "contacts, and equilibrium when it has a load, each with a checked certificate. What the scene\n"
    "asks for that this version cannot compute (a support's limit surface) is listed as skipped.\n"
    "\n"
    "options: --json, --mode, --max-* (as for closure)\n";

const char* kCheckHelp =
    "usage: wrenchkit check [OPTIONS] SCENE.json CERT.json\n"
    "\n"
    "Runs the independent checker of proofs/ (GMP only, its own parser, sharing no code with the\n"
    "engine): it recomputes every generator from SCENE.json and accepts CERT.json only if it\n"
    "proves its claim (proofs/certificate-format.md). Exit 0 accepted, 1 rejected, 2 bad scene.\n"
    "\n"
    "options: --json, and the --max-* limits of 'wrenchkit closure --help'\n";

const char* kBatchHelp =
    "usage: wrenchkit batch closure [OPTIONS] < scenes.jsonl\n"
    "\n"
    "Reads one scene per line (JSON lines) on standard input and writes one JSON answer per line,\n"
    "in the same order, computed on --jobs threads: the output of 'closure --json' with a \"line\"\n"
    "field, or {\"line\": N, \"error\": MESSAGE, \"exit_code\": 2} for a bad line (the stream goes\n"
    "on), {\"line\": N, \"undecided\": …, \"exit_code\": 3} when --mode float cannot decide.\n"
    "Every certificate is checked by the independent checker, as in 'closure'.\n"
    "\n"
    "options:\n"
    "  --jobs N           threads (default: all cores)\n"
    "  --verdict-only     skip certificates and their check (throughput runs; the verdicts are\n"
    "                     the same, but nothing proves them)\n"
    "  --mode, --max-*    as for closure (--max-file-size limits each line)\n"
    "Exit code: 0 when every line was answered or reported, 4 if a certificate ever failed its\n"
    "check (a bug), 70 on an internal error.\n";

const char* kDemoHelp =
    "usage: wrenchkit demo [--json]\n"
    "\n"
    "Runs 'analyze' on a bundled textbook scene: Mason's Example 3, a triangle held by three\n"
    "fingers whose normals meet in one point (theory.md §8.7), under its own weight. Frictionless it\n"
    "is not closed; with friction mu = 1/10 it is in force closure, so gravity is balanced.\n";

struct Options {
  bool json = false;
  bool help = false;
  bool verdict_only = false;  // batch: skip certificates (throughput); never the default
  unsigned jobs = 0;          // batch: threads, 0 = all cores
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
    else if (a == "--verdict-only") o.verdict_only = true;
    else if (a == "--jobs") {
      const std::size_t j = parse_count(a, value());
      if (j < 1 || j > 1024) throw Usage_error("--jobs: must be between 1 and 1024");
      o.jobs = static_cast<unsigned>(j);
    }
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

struct Closure_result {
  Scene scene;
  Closure_answer fc, fo;
  std::string fc_json, fo_json;  // empty when not certified (batch --verdict-only)
};

// Reads, decides both properties, builds both certificates and has the independent checker accept
// them before anything is reported. Throws Input_error, Undecided or Self_check_failure.
Closure_result compute_closure(const Options& o, const std::string& scene_text, const std::string& source) {
  Closure_result r;
  r.scene = read_scene(scene_text, o.limits, source);
  const Mode mode = mode_of(o.mode);
  const bool certify = !o.verdict_only;
  r.fc = decide_closure(r.scene, Property::force_closure, mode, certify);
  r.fo = decide_closure(r.scene, Property::form_closure, mode, certify);
  if (!r.fc.decided || !r.fo.decided)
    throw Undecided(std::string("the float twin could not certify ") +
                    (!r.fc.decided ? (!r.fo.decided ? "force or form closure" : "force closure") : "form closure") +
                    " of this scene (a predicate is within its error bound of zero); use --mode hybrid or exact");
  if (!certify) return r;
  r.fc_json = certificate_json(r.fc.certificate);
  r.fo_json = certificate_json(r.fo.certificate);
  // Test hook: the suite corrupts a certificate to prove the self-check path (exit 4) works.
  if (const char* f = std::getenv("WRENCHKIT_FAULT_INJECTION"); f && std::string(f) == "corrupt-certificate")
    r.fc_json.insert(1, "\"injected_fault\": true, ");
  for (const std::string* cert : {&r.fc_json, &r.fo_json}) {
    const auto c = wrenchkit_checker::check(scene_text, *cert, checker_limits(o.limits));
    if (c.outcome != wrenchkit_checker::Outcome::accepted)
      throw Self_check_failure("the independent checker rejected our own certificate: " + c.message +
                               "\ncertificate: " + *cert);
  }
  return r;
}

// One line of JSON (no newline); `line` > 0 adds the input line number (batch).
std::string closure_json(const Options& o, const Closure_result& r, const char* command, std::size_t line = 0) {
  std::ostringstream s;
  s << "{";
  if (line) s << "\"line\": " << line << ", ";
  s << "\"command\": \"" << command << "\", \"name\": " << json::quote(r.scene.name) << ", \"mode\": \""
    << o.mode << "\", \"decided_by\": \"" << decided_by(r.fc, r.fo) << "\""
    << ", \"force_closure\": " << (r.fc.holds ? "true" : "false")
    << ", \"form_closure\": " << (r.fo.holds ? "true" : "false")
    << ", \"rank\": {\"force\": " << r.fc.rank << ", \"form\": " << r.fo.rank << "}"
    << ", \"generators\": {\"force\": " << r.fc.generators << ", \"form\": " << r.fo.generators
    << "}, \"predicates\": {\"force\": " << r.fc.predicates << ", \"form\": " << r.fo.predicates
    << "}, \"exact_predicates\": {\"force\": " << r.fc.exact_predicates << ", \"form\": "
    << r.fo.exact_predicates << "}, \"certificates_checked\": " << (r.fc_json.empty() ? "false" : "true");
  if (!r.fc_json.empty()) s << ", \"certificate\": " << r.fc_json << ", \"form_certificate\": " << r.fo_json;
  s << "}";
  return s.str();
}

int run_closure(const Options& o, const std::string& scene_text, const std::string& source,
                const char* command) {
  if (o.verdict_only) throw Usage_error("--verdict-only is for batch; closure always certifies");
  const Closure_result r = compute_closure(o, scene_text, source);
  if (!o.certificate_file.empty()) write_file(o.certificate_file, r.fc_json + "\n");
  if (!o.form_certificate_file.empty()) write_file(o.form_certificate_file, r.fo_json + "\n");
  if (o.json) {
    std::cout << closure_json(o, r, command) << "\n";
  } else {
    std::cout << "scene: " << (r.scene.name.empty() ? source : r.scene.name) << "\n"
              << "force closure: " << human_verdict(r.fc, false) << "\n"
              << "form closure:  " << human_verdict(r.fo, true) << "\n"
              << "decided by: " << decided_by(r.fc, r.fo) << " (" << r.fc.exact_predicates + r.fo.exact_predicates
              << " of " << r.fc.predicates + r.fo.predicates << " predicates in exact arithmetic)\n"
              << "both certificates accepted by the independent checker (exact arithmetic)\n";
  }
  return kAnswered;
}

// Reads one line of at most `limit` bytes (the rest of a longer line is skipped, bounded memory).
bool read_line(std::istream& in, std::string& line, std::size_t limit, bool& too_long) {
  line.clear();
  too_long = false;
  std::streambuf* sb = in.rdbuf();
  bool any = false;
  for (;;) {
    const int c = sb->sbumpc();
    if (c == std::char_traits<char>::eof()) return any;
    any = true;
    if (c == '\n') return true;
    if (line.size() < limit) line.push_back(static_cast<char>(c));
    else too_long = true;
  }
}

std::string error_line(std::size_t line, const char* kind, int code, const std::string& message) {
  return "{\"line\": " + std::to_string(line) + ", \"" + kind + "\": " + json::quote(message) +
         ", \"exit_code\": " + std::to_string(code) + "}";
}

// wrenchkit batch closure: one scene per input line, one JSON answer per output line, in order.
int run_batch(const Options& o) {
  if (o.positional.size() != 1 || o.positional[0] != "closure")
    throw Usage_error("batch needs a command: wrenchkit batch closure [OPTIONS] < scenes.jsonl");
  if (!o.certificate_file.empty() || !o.form_certificate_file.empty())
    throw Usage_error("batch writes certificates in its output lines, not to files");
  unsigned jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  const std::size_t chunk = 256 * std::size_t(jobs);
  std::vector<std::string> lines, out;
  std::vector<char> too_long;
  std::atomic<bool> self_check_failed{false}, internal_error{false};
  std::size_t first_line = 1;
  std::string line;
  bool eof = false;
  while (!eof) {
    lines.clear();
    too_long.clear();
    while (lines.size() < chunk) {
      bool longer = false;
      if (!read_line(std::cin, line, o.limits.max_file_bytes, longer)) {
        eof = true;
        break;
      }
      lines.push_back(line);
      too_long.push_back(longer);
    }
    if (lines.empty()) break;
    out.assign(lines.size(), std::string());
    std::atomic<std::size_t> next{0};
    auto work = [&] {
      for (std::size_t i; (i = next++) < lines.size();) {
        const std::size_t n = first_line + i;
        try {
          if (too_long[i])
            throw Input_error("line larger than the size limit of " + std::to_string(o.limits.max_file_bytes) +
                              " bytes (--max-file-size)");
          out[i] = closure_json(o, compute_closure(o, lines[i], "line " + std::to_string(n)), "closure", n);
        } catch (const Input_error& e) {
          out[i] = error_line(n, "error", kBadInput, e.what());
        } catch (const Undecided& e) {
          out[i] = error_line(n, "undecided", kUndecided, e.what());
        } catch (const Self_check_failure& e) {
          self_check_failed = true;
          out[i] = error_line(n, "internal_error", kSelfCheck, e.what());
        } catch (const std::exception& e) {
          internal_error = true;
          out[i] = error_line(n, "internal_error", kInternal, e.what());
        }
      }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < jobs && t < lines.size(); ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    for (const std::string& s : out) std::cout << s << '\n';
    first_line += lines.size();
  }
  std::cout.flush();
  return self_check_failed ? kSelfCheck : (internal_error ? kInternal : kAnswered);
}

struct Equilibrium_result {
  Equilibrium_answer a;
  std::string cert;
};

// Decides equilibrium of a parsed scene and has the independent checker accept the certificate.
Equilibrium_result compute_equilibrium(const Options& o, const Scene& scene, const std::string& scene_text) {
  Equilibrium_result r{decide_equilibrium(scene), ""};
  r.cert = certificate_json(r.a.certificate);
  const auto c = wrenchkit_checker::check(scene_text, r.cert, checker_limits(o.limits));
  if (c.outcome != wrenchkit_checker::Outcome::accepted)
    throw Self_check_failure("the independent checker rejected our own certificate: " + c.message +
                             "\ncertificate: " + r.cert);
  return r;
}

std::string equilibrium_json(const Options& o, const Scene& scene, const Equilibrium_result& r, const char* command) {
  const Wrench& l = r.a.load;
  return "{\"command\": \"" + std::string(command) + "\", \"name\": " + json::quote(scene.name) +
         ", \"mode\": \"" + o.mode + "\", \"decided_by\": \"exact\", \"balanced\": " +
         (r.a.balanced ? "true" : "false") + ", \"load\": [" + json::quote(to_string(l.fx)) + ", " +
         json::quote(to_string(l.fy)) + ", " + json::quote(to_string(l.m)) + "], \"generators\": " +
         std::to_string(r.a.generators) + ", \"certificate_checked\": true, \"certificate\": " + r.cert + "}";
}

std::string equilibrium_human(const Equilibrium_result& r) {
  const Equilibrium_answer& a = r.a;
  const std::array<Rational, 3> load = {a.load.fx, a.load.fy, a.load.m};
  std::ostringstream s;
  s << "load: the wrench " << vec_text(load) << " (force, moment about the origin)\n"
    << "balanced: " << (a.balanced ? "yes" : "no") << "\n    certificate: ";
  if (a.balanced) {
    if (a.certificate.combination.empty()) s << "the load is zero";
    else s << "the contact wrenches";
    for (const auto& [ref, w] : a.certificate.combination)
      s << " " << to_string(w) << "·c" << ref.contact << "." << edge_name(ref.edge);
    if (!a.certificate.combination.empty()) s << " cancel the load exactly";
  } else {
    const Twist_reading tr = read_twist(a.certificate.twist);
    s << "the twist " << vec_text(a.certificate.twist)
      << " has power >= 0 against every contact wrench and > 0 against the load";
    if (tr.label == 'i')
      s << " (a translation toward direction (" << to_string(tr.point[0]) << ", " << to_string(tr.point[1])
        << ") at infinity)";
    else
      s << " (a " << (tr.label == '+' ? "counter-clockwise" : "clockwise") << " rotation about ("
        << to_string(tr.point[0]) << ", " << to_string(tr.point[1]) << "))";
    s << ": the load drives a motion the contacts allow";
  }
  s << "\n";
  return s.str();
}

int run_equilibrium(const Options& o, const std::string& scene_text, const std::string& source) {
  if (o.mode == "float")
    throw Usage_error("--mode float: equilibrium has no float twin yet; use --mode exact or hybrid");
  if (o.verdict_only) throw Usage_error("--verdict-only is for batch");
  if (!o.form_certificate_file.empty()) throw Usage_error("--form-certificate is for closure");
  const Scene scene = read_scene(scene_text, o.limits, source);
  const Equilibrium_result r = compute_equilibrium(o, scene, scene_text);
  if (!o.certificate_file.empty()) write_file(o.certificate_file, r.cert + "\n");
  if (o.json) {
    std::cout << equilibrium_json(o, scene, r, "equilibrium") << "\n";
  } else {
    std::cout << "scene: " << (scene.name.empty() ? source : scene.name) << "\n"
              << equilibrium_human(r) << "certificate accepted by the independent checker (exact arithmetic)\n";
  }
  return kAnswered;
}

// analyze: everything the scene's contents call for, and nothing else — closure of its contacts
// (always: no contacts is an answer too), equilibrium when it has a load. What a scene asks for
// that this version cannot compute yet is listed under "skipped", never silently dropped.
int run_analyze(const Options& o, const std::string& scene_text, const std::string& source, const char* command) {
  if (o.verdict_only) throw Usage_error("--verdict-only is for batch");
  if (!o.certificate_file.empty() || !o.form_certificate_file.empty())
    throw Usage_error("analyze writes its certificates in its JSON output; use closure or equilibrium for files");
  const Closure_result c = compute_closure(o, scene_text, source);
  std::optional<Equilibrium_result> e;
  if (c.scene.load) {
    if (o.mode == "float")
      throw Usage_error("--mode float: equilibrium has no float twin yet; use --mode exact or hybrid");
    e = compute_equilibrium(o, c.scene, scene_text);
  }
  std::vector<std::pair<std::string, std::string>> skipped;
  if (c.scene.support)
    skipped.push_back({"limit_surface", "the scene has a support; limit surfaces are not implemented in this version"});
  if (o.json) {
    std::cout << "{\"command\": \"" << command << "\", \"name\": " << json::quote(c.scene.name)
              << ", \"closure\": " << closure_json(o, c, "closure");
    if (e) std::cout << ", \"equilibrium\": " << equilibrium_json(o, c.scene, *e, "equilibrium");
    std::cout << ", \"skipped\": [";
    for (std::size_t i = 0; i < skipped.size(); ++i)
      std::cout << (i ? ", " : "") << "{\"what\": " << json::quote(skipped[i].first)
                << ", \"why\": " << json::quote(skipped[i].second) << "}";
    std::cout << "]}\n";
    return kAnswered;
  }
  std::cout << "scene: " << (c.scene.name.empty() ? source : c.scene.name) << "\n"
            << "force closure: " << human_verdict(c.fc, false) << "\n"
            << "form closure:  " << human_verdict(c.fo, true) << "\n";
  if (e) std::cout << equilibrium_human(*e);
  for (const auto& [what, why] : skipped) std::cout << "skipped " << what << ": " << why << "\n";
  std::cout << "decided by: " << decided_by(c.fc, c.fo) << " for closure"
            << (e ? ", exact for equilibrium" : "") << "\n"
            << "every certificate accepted by the independent checker (exact arithmetic)\n";
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
  if (command == "analyze") {
    if (o.help) return std::cout << kAnalyzeHelp, kAnswered;
    if (o.positional.size() != 1) throw Usage_error("analyze needs exactly one SCENE.json");
    const std::string& path = o.positional[0];
    return run_analyze(o, read_input(path, o.limits.max_file_bytes), path == "-" ? "<stdin>" : path, "analyze");
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
  if (command == "batch") {
    if (o.help) return std::cout << kBatchHelp, kAnswered;
    return run_batch(o);
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
