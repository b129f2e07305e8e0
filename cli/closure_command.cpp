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
#include "exact/io/json_writer.h"

namespace wrenchkit::cli {

namespace {

std::string human_verdict(const Closure_answer& a, const Scene& scene, bool form) {
  std::ostringstream s;
  s << (a.holds ? "yes" : "no") << "  (" << a.generators << " generator"
    << (a.generators == 1 ? "" : "s") << ", rank " << a.rank << ")\n    ";
  const Closure_certificate& c = a.certificate;
  if (a.holds) {
    // The certificate's weights on cone edges, as the forces they put on each contact (the certificate keeps the weights).
    s << "certificate: the contact forces "
      << contact_forces_text(contact_forces(scene, c.combination, form ? Reading::frictionless : Reading::friction))
      << " sum to the zero wrench (strictly positive weights on " << c.combination.size()
      << (form ? " contact normals" : " friction cones' edges") << " in the certificate); so every wrench is a"
      << (form ? " resisted load: no motion is possible" : " possible resultant");
  } else {
    const Twist_reading r = read_twist(c.twist);
    s << "certificate: the twist " << twist_text(c.twist) << " has power >= 0 against every generator";
    if (r.label == 'i')
      s << " (a translation; its centre is at infinity in direction " << vec_text(Vec2{r.point[0], r.point[1]}) << ")";
    else
      s << " (a " << (r.label == '+' ? "counter-clockwise" : "clockwise") << " rotation about "
        << vec_text(Vec2{r.point[0], r.point[1]}) << ", labeled " << r.label << ")";
    s << (form ? "; the contacts allow this motion to first order"
               : "; so the contact forces cannot resist a load along -t (the wrench -t is not a possible "
                 "resultant of the contact forces)");
  }
  return s.str();
}

template <std::size_t N>
void write_pair(Json_writer& w, const char (&key)[N], std::size_t force, std::size_t form) {
  w.key(key).object().member("force", force).member("form", form).end_object();
}

}  // namespace

void write_closure(Json_writer& w, const Options& o, const Closure_item& r, const char* command) {
  w.member("command", command).member("name", r.name).member("mode", mode_name(o.mode));
  w.member("decided_by", arithmetic_name(r.decided_by())).member("force_closure", r.force.holds).member("form_closure", r.form.holds);
  write_pair(w, "rank", static_cast<std::size_t>(r.force.rank), static_cast<std::size_t>(r.form.rank));
  write_pair(w, "generators", r.force.generators, r.form.generators);
  write_pair(w, "predicates", r.force.predicates, r.form.predicates);
  write_pair(w, "exact_predicates", r.force.exact_predicates, r.form.exact_predicates);
  w.member("certificates_checked", !r.force_certificate.empty());
  if (!r.force_certificate.empty())
    w.key("certificate").raw(r.force_certificate).key("form_certificate").raw(r.form_certificate);
}

std::string closure_human(const Closure_item& r, const Scene& scene) {
  return "force closure: " + human_verdict(r.force, scene, false) + "\nform closure:  " + human_verdict(r.form, scene, true) +
         "\n";
}

Scene_answer prepare_closure_json(const Options& o) {
  return [o, request = request_of(o)](Json_writer& w, const std::string& text, const std::string& source) {
    thread_local Scene scratch;  // reused from one scene to the next: no allocation once warm
    write_closure(w, o, answered(answer_closure(text, source, request, scratch)), "closure");
  };
}

int run_closure(const Options& o, const std::string& scene_text, const std::string& source,
                const char* command) {
  Scene scene;
  const Closure_item r = answered(answer_closure(scene_text, source, request_of(o), scene));
  if (!o.certificate_file.empty()) write_file(o.certificate_file, r.force_certificate + "\n");
  if (!o.form_certificate_file.empty()) write_file(o.form_certificate_file, r.form_certificate + "\n");
  if (o.json) {
    std::cout << json_answer([&](Json_writer& w) { write_closure(w, o, r, command); }) << "\n";
  } else {
    std::cout << scene_line(scene, source) << frictionless_note(scene)
              << closure_human(r, scene)
              << "decided by: " << arithmetic_name(r.decided_by()) << " (" << r.force.exact_predicates + r.form.exact_predicates
              << " of " << r.force.predicates + r.form.predicates << " predicates in exact arithmetic)\n"
              << "both certificates accepted by the independent checker (exact arithmetic)\n";
  }
  return kAnswered;
}

}  // namespace wrenchkit::cli
