// wrenchkit closure: force closure and first-order form closure, with checked certificates.
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cli/common.h"
#include "exact/io/input_error.h"
#include "exact/io/json.h"

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

namespace {

// The CLI's closure options: its mode, limits and --verdict-only, and the independent checker of
// proofs/ on every certificate (reading the scene once for both).
Closure_batch_options closure_options(const Options& o) {
  Closure_batch_options c;
  c.mode = o.mode;
  c.certify = !o.verdict_only;
  c.limits = o.limits;
  // Test hook: the suite corrupts a certificate to prove the self-check path (exit 4) works.
  const char* f = std::getenv("WRENCHKIT_FAULT_INJECTION");
  const bool corrupt = f && std::string(f) == "corrupt-certificate";
  c.check = [limits = checker_limits(o.limits), corrupt](std::string_view scene,
                                                          const std::vector<std::string_view>& certs) {
    std::string injected;
    std::vector<std::string_view> checked = certs;
    if (corrupt && !certs.empty()) {
      injected = std::string(certs[0]);
      injected.insert(1, "\"injected_fault\": true, ");
      checked[0] = injected;
    }
    const std::vector<wrenchkit_checker::Result> results = wrenchkit_checker::check_all(scene, checked, limits);
    for (std::size_t k = 0; k < results.size(); ++k)
      if (results[k].outcome != wrenchkit_checker::Outcome::accepted)
        return "the independent checker rejected our own certificate: " + results[k].message +
               "\ncertificate: " + std::string(checked[k]);
    return std::string();
  };
  return c;
}

// A closure item's failure as the exception the command reports.
void throw_unless_answered(const Closure_item& r) {
  switch (r.status) {
    case Batch_status::answered: return;
    case Batch_status::bad_input: throw Input_error(r.message);
    case Batch_status::undecided: throw Undecided(r.message);
    case Batch_status::check_failed: throw Self_check_failure(r.message);
    case Batch_status::internal_error: throw std::runtime_error(r.message);
  }
}

void append_pair(std::string& s, const char* key, std::size_t force, std::size_t form) {
  s += ", \"";
  s += key;
  s += "\": {\"force\": ";
  s += std::to_string(force);
  s += ", \"form\": ";
  s += std::to_string(form);
  s += "}";
}

}  // namespace

Closure_item compute_closure(const Options& o, const std::string& scene_text, const std::string& source, Scene* scene) {
  Scene local;
  Closure_item r = closure_item(scene_text, source, closure_options(o), scene ? *scene : local);
  throw_unless_answered(r);
  return r;
}

// One line of JSON (no newline).
std::string closure_json(const Options& o, const Closure_item& r, const char* command) {
  std::string s;
  s.reserve(512 + r.force_certificate.size() + r.form_certificate.size());
  s += "{\"command\": \"";
  s += command;
  s += "\", \"name\": ";
  s += json::quote(r.name);
  s += ", \"mode\": \"";
  s += mode_name(o.mode);
  s += "\", \"decided_by\": \"";
  s += decided_by(r.force, r.form);
  s += "\", \"force_closure\": ";
  s += r.force.holds ? "true" : "false";
  s += ", \"form_closure\": ";
  s += r.form.holds ? "true" : "false";
  append_pair(s, "rank", static_cast<std::size_t>(r.force.rank), static_cast<std::size_t>(r.form.rank));
  append_pair(s, "generators", r.force.generators, r.form.generators);
  append_pair(s, "predicates", r.force.predicates, r.form.predicates);
  append_pair(s, "exact_predicates", r.force.exact_predicates, r.form.exact_predicates);
  s += ", \"certificates_checked\": ";
  s += r.force_certificate.empty() ? "false" : "true";
  if (!r.force_certificate.empty()) {
    s += ", \"certificate\": ";
    s += r.force_certificate;
    s += ", \"form_certificate\": ";
    s += r.form_certificate;
  }
  s += "}";
  return s;
}

std::string closure_human(const Closure_item& r) {
  return "force closure: " + human_verdict(r.force, false) + "\nform closure:  " + human_verdict(r.form, true) + "\n";
}

Scene_answer prepare_closure_json(const Options& o) {
  return [o, c = closure_options(o)](const std::string& text, const std::string& source) {
    thread_local Scene scratch;  // reused from one scene to the next: no allocation once warm
    const Closure_item r = closure_item(text, source, c, scratch);
    throw_unless_answered(r);
    return closure_json(o, r, "closure");
  };
}

int run_closure(const Options& o, const std::string& scene_text, const std::string& source,
                const char* command) {
  const Closure_item r = compute_closure(o, scene_text, source);
  if (!o.certificate_file.empty()) write_file(o.certificate_file, r.force_certificate + "\n");
  if (!o.form_certificate_file.empty()) write_file(o.form_certificate_file, r.form_certificate + "\n");
  if (o.json) {
    std::cout << closure_json(o, r, command) << "\n";
  } else {
    std::cout << "scene: " << (r.name.empty() ? source : r.name) << "\n"
              << closure_human(r)
              << "decided by: " << decided_by(r.force, r.form) << " (" << r.force.exact_predicates + r.form.exact_predicates
              << " of " << r.force.predicates + r.form.predicates << " predicates in exact arithmetic)\n"
              << "both certificates accepted by the independent checker (exact arithmetic)\n";
  }
  return kAnswered;
}

}  // namespace wrenchkit::cli
