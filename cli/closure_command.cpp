// wrenchkit closure: force closure and first-order form closure, with checked certificates.
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

#include "cli/common.h"
#include "exact/json.h"

namespace wrenchkit::cli {

namespace {

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

}  // namespace

std::string decided_by(const Closure_answer& a, const Closure_answer& b) {
  const std::string x = a.decided_by(), y = b.decided_by();
  return x == y ? x : "hybrid";
}

Closure_result compute_closure(const Options& o, const std::string& scene_text, const std::string& source,
                               bool lazy) {
  Closure_result r;
  r.scene = read_scene(scene_text, o.limits, source, lazy && o.mode != "exact");
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
std::string closure_json(const Options& o, const Closure_result& r, const char* command, std::size_t line) {
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

std::string closure_human(const Closure_result& r) {
  return "force closure: " + human_verdict(r.fc, false) + "\nform closure:  " + human_verdict(r.fo, true) + "\n";
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
              << closure_human(r)
              << "decided by: " << decided_by(r.fc, r.fo) << " (" << r.fc.exact_predicates + r.fo.exact_predicates
              << " of " << r.fc.predicates + r.fo.predicates << " predicates in exact arithmetic)\n"
              << "both certificates accepted by the independent checker (exact arithmetic)\n";
  }
  return kAnswered;
}

// Reads one line of at most `limit` bytes (the rest of a longer line is skipped, bounded memory).

}  // namespace wrenchkit::cli
