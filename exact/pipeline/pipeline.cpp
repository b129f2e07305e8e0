#include "exact/pipeline/pipeline.h"

#include <cstdlib>
#include <string>

#include "exact/certificates/certificates.h"
#include "exact/io/streaming_scene_reader.h"
#include "proofs/checker/checker.h"

namespace wrenchkit {

int exit_code(Status s) {
  switch (s) {
    case Status::answered: return 0;
    case Status::bad_input: return 2;
    case Status::undecided: return 3;
    case Status::check_failed: return 4;
    case Status::internal_error: return 70;
  }
  return 70;
}

wrenchkit_checker::Limits checker_limits(const Input_limits& l) {
  wrenchkit_checker::Limits c;
  c.max_digits = l.max_digits;
  c.max_exponent = l.max_exponent;
  c.max_depth = l.max_depth;
  c.max_contacts = l.max_contacts;
  c.max_region_vertices = l.max_region_vertices;
  c.max_total_digits = l.max_total_digits;
  c.max_digits_times_contacts = l.max_digits_times_contacts;
  c.max_certificate_bytes = l.max_certificate_bytes;
  return c;
}

std::string check_certificates(std::string_view scene_text, const std::vector<std::string_view>& certificates,
                               const Request& request) {
  if (request.check == Check::none || certificates.empty()) return std::string();  // (nothing to read the scene for)
  const char* fault = std::getenv("WRENCHKIT_FAULT_INJECTION");
  const bool corrupt = fault && std::string(fault) == "corrupt-certificate";
  std::string injected;
  std::vector<std::string_view> checked = certificates;
  if (corrupt && !certificates.empty()) {
    injected = std::string(certificates[0]);
    injected.insert(1, "\"injected_fault\": true, ");
    checked[0] = injected;
  }
  const std::vector<wrenchkit_checker::Result> results =
      wrenchkit_checker::check_all(scene_text, checked, checker_limits(request.limits));
  for (std::size_t k = 0; k < results.size(); ++k)
    if (results[k].outcome != wrenchkit_checker::Outcome::accepted)
      return "the independent checker rejected our own certificate: " + results[k].message +
             "\ncertificate: " + std::string(checked[k]);
  return std::string();
}

namespace {

void decide_closure_item(const Scene& scene, std::string_view text, const Request& r, Closure_item& item) {
  item.name = scene.name;
  item.force = decide_closure(scene, Property::force_closure, r.mode, r.certify);
  item.form = decide_closure(scene, Property::form_closure, r.mode, r.certify);
  if (!item.force.decided || !item.form.decided) {
    item.status = Status::undecided;
    item.message = std::string("the float twin could not certify ") +
                   (!item.force.decided ? (!item.form.decided ? "force or form closure" : "force closure")
                                        : "form closure") +
                   " of this scene (a predicate is within its error bound of zero)";
    return;
  }
  if (!r.certify) return;
  item.force_certificate = certificate_json(item.force.certificate);
  item.form_certificate = certificate_json(item.form.certificate);
  check_into(item, text, {item.force_certificate, item.form_certificate}, r);
}

void decide_equilibrium_item(const Scene& scene, std::string_view text, const Request& r, Equilibrium_item& item) {
  item.name = scene.name;
  item.answer = decide_equilibrium(scene, r.mode, r.certify);
  if (!item.answer.decided) {
    item.status = Status::undecided;
    item.message = "the float twin could not certify equilibrium of this scene (a predicate is within its error "
                   "bound of zero, or the contact wrenches have rank < 3)";
    return;
  }
  if (item.answer.balanced) item.forces = contact_forces(scene, item.answer.certificate.combination);
  if (!r.certify) return;
  item.certificate = certificate_json(item.answer.certificate);
  check_into(item, text, {item.certificate}, r);
}

// Closure reads lazily (certified doubles from the digits, rationals only where an exact predicate needs
// them) unless the mode is exact or certificates are built: those need every contact's rationals.
bool lazy_for(const Request& r) { return r.mode != Mode::exact && !r.certify; }

// The text forms read the scene into `scratch` first (lazily only where the question allows it).
template <class Item, class Decide>
Item read_and_answer(std::string_view text, std::string_view source, const Request& r, Scene& scratch, bool lazy,
                     Decide decide) {
  Item item;
  guarded(item, r.limits, [&] {
    read_scene_into(scratch, text, r.limits, source, lazy);
    decide(scratch, text, r, item);
  });
  return item;
}

template <class Item, class Decide>
Item answer_read_scene(const Scene& scene, std::string_view text, const Request& r, Decide decide) {
  Item item;
  guarded(item, r.limits, [&] { decide(scene, text, r, item); });
  return item;
}

}  // namespace

Closure_item answer_closure(std::string_view text, std::string_view source, const Request& r, Scene& scratch) {
  return read_and_answer<Closure_item>(text, source, r, scratch, lazy_for(r), decide_closure_item);
}

Closure_item answer_closure(const Scene& scene, std::string_view text, const Request& r) {
  return answer_read_scene<Closure_item>(scene, text, r, decide_closure_item);
}

Equilibrium_item answer_equilibrium(std::string_view text, std::string_view source, const Request& r,
                                    Scene& scratch) {
  // Eagerly: the load needs its rationals.
  return read_and_answer<Equilibrium_item>(text, source, r, scratch, false, decide_equilibrium_item);
}

Equilibrium_item answer_equilibrium(const Scene& scene, std::string_view text, const Request& r) {
  return answer_read_scene<Equilibrium_item>(scene, text, r, decide_equilibrium_item);
}

}  // namespace wrenchkit
