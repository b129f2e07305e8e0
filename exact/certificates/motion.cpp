// proofs/certificate-format.md §6: does a load stick, slide, or sit on the limit surface? (§6.4 regions, §6.5 format 2,
// §6.6 format 3: the three outcomes). The checker's side: proofs/checker/motion.cpp.
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

// A load on the surface of the one distribution: {"support_forces", "twist", "speed_bounds", "regions"}, each region's
// block with the cells' forces and the corners' speed bounds.
void write_impending(Json_writer& w, const Impending_witness& s) {
  write_support_forces(w, s.forces.forces);
  w.key("twist").rationals(s.twist.twist).key("speed_bounds").rationals(s.twist.speed_bounds);
  write_blocks(w, s.forces.regions, s.twist.regions);
}

}  // namespace

std::string motion_certificate(const Support_model& model, const Vec3q& p, const Motion_answer& a) {
  if (a.motion == Motion::undecided) throw std::logic_error("motion_certificate: an undecided answer has no certificate");
  const bool over = !model.known();
  Json_writer w(512);
  w.object().member("wrenchkit_certificate", 3).member("property", "motion");
  w.key("load").rationals(p).member("motion", motion_name(a.motion));
  switch (a.motion) {
    case Motion::sticks:
      if (!over) {
        write_stick(w, *a.sticking, false);
        break;
      }
      w.key("vertices").array();
      for (const Stick_witness& s : a.vertices) write_stick(w.object(), s, true), w.end_object();
      w.end_array();
      break;
    case Motion::impending:
      if (!over) {
        write_impending(w, *a.impending);
        break;
      }
      w.key("vertices").array();  // every vertex's forces in the closed discs, one twist for all of F
      for (const Stick_witness& s : a.vertices) write_stick(w.object(), s, true), w.end_object();
      w.end_array();
      write_slide(w, *a.sliding, false);
      break;
    case Motion::slides: write_slide(w, *a.sliding, false); break;
    case Motion::depends:  // one distribution in its closed set and another not in its interior, one of them strictly
      write_stick(w.key("sticking").object(), *a.sticking, true);
      write_slide(w.end_object().key("sliding").object(), *a.sliding, true);
      w.end_object();
      break;
    case Motion::undecided: break;
  }
  return w.end_object().take();
}

}  // namespace wrenchkit
