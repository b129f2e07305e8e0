// proofs/certificate-format.md §6: does a load stick or slide? (§6.4 regions, §6.5 format 2). The checker's side:
// proofs/checker/ (the motion check).
#include "exact/certificates/certificates.h"
#include "exact/certificates/witnesses.h"

#include <stdexcept>

namespace wrenchkit {

namespace {

// A stick witness: {"distribution", "support_forces", "regions"}, its distribution only where F has more than one.
void write_stick(Json_writer& w, const Stick_witness& s, bool distribution) {
  if (distribution) w.key("distribution").rationals(s.distribution);
  write_support_forces(w, s.forces);
  write_blocks(w, s.regions);
}

// A slide witness: {"distribution", "twist", "speed_bounds", "dual", "regions"}: its distribution where F has more
// than one and the witness is one distribution's; the LP's dual over F where it is every distribution's.
void write_slide(Json_writer& w, const Slide_witness& s, bool distribution) {
  if (distribution) w.key("distribution").rationals(s.distribution);
  w.key("twist").rationals(s.twist).key("speed_bounds").rationals(s.speed_bounds);
  if (s.dual) w.key("dual").rationals(*s.dual);
  write_blocks(w, s.regions);
}

}  // namespace

std::string motion_certificate(const Support_model& model, const Vec3q& p, const Motion_answer& a) {
  if (a.motion == Motion::undecided) throw std::logic_error("motion_certificate: an undecided answer has no certificate");
  const bool over = !model.known();
  Json_writer w(512);
  // Format 2 (§6.5) only where format 1 has no certificate: regions together with a point force not given.
  w.object().member("wrenchkit_certificate", over && model.has_regions() ? 2 : 1).member("property", "motion");
  w.key("load").rationals(p).member("motion", motion_name(a.motion));
  if (a.motion == Motion::sticks && over) {
    w.key("vertices").array();
    for (const Stick_witness& s : a.vertices) write_stick(w.object(), s, true), w.end_object();
    w.end_array();
  } else if (a.motion == Motion::sticks) {
    write_stick(w, *a.sticking, false);
  } else if (a.motion == Motion::slides) {
    write_slide(w, *a.sliding, false);
  } else {
    write_stick(w.key("sticking").object(), *a.sticking, true);
    write_slide(w.end_object().key("sliding").object(), *a.sliding, true);
    w.end_object();
  }
  return w.end_object().take();
}

}  // namespace wrenchkit
