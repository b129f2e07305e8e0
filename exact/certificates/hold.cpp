// proofs/certificate-format.md §7: does the body hold? (§7.4 regions, §7.5 format 2). The checker's side:
// proofs/checker/ (the hold check).
#include "exact/certificates/certificates.h"
#include "exact/certificates/witnesses.h"

#include <stdexcept>

namespace wrenchkit {

namespace {

// A hold witness: {"distribution", "combination", "support_forces", "regions"}: its distribution where F has more
// than one, its support forces where there is a support.
void write_holding(Json_writer& w, const Hold_witness& h, bool support, bool distribution) {
  if (distribution) w.key("distribution").rationals(h.support.distribution);
  write_combination(w.key("combination"), h.combination);
  if (support) write_support_forces(w, h.support.forces);
  write_blocks(w, h.support.regions);
}

// A fail witness: at the top level the twist comes with its reading (the motion as a rotation centre or a direction,
// checked), inside "failing" with its distribution; then the speed bounds (with a support), the regions' blocks, and
// the LP's dual over F for every distribution.
void write_failing(Json_writer& w, const Slide_witness& f, bool support, bool distribution) {
  if (distribution) w.key("distribution").rationals(f.distribution).key("twist").rationals(f.twist);
  else write_twist(w, f.twist);
  if (support) w.key("speed_bounds").rationals(f.speed_bounds);
  write_blocks(w, f.regions);
  if (f.dual) w.key("dual").rationals(*f.dual);
}

}  // namespace

std::string hold_certificate(const Hold_answer& a) {
  Json_writer w(1024);
  // Format 2 (§7.5) only where format 1 has no certificate: regions together with a force not given.
  w.object().member("wrenchkit_certificate", a.regions && a.unknown ? 2 : 1).member("property", "hold");
  switch (a.verdict) {
    case Hold_verdict::holds:
      w.member("holds", true);
      if (!a.unknown) {
        write_holding(w, *a.holding, a.has_support, false);
      } else {
        w.key("vertices").array();
        for (const Hold_witness& v : a.vertices) write_holding(w.object(), v, true, true), w.end_object();
        w.end_array();
      }
      break;
    case Hold_verdict::fails:
      w.member("holds", false);
      write_failing(w, *a.failing, a.has_support, false);
      break;
    case Hold_verdict::depends:
      w.member("holds", "depends");
      write_holding(w.key("holding").object(), *a.holding, true, true);
      write_failing(w.end_object().key("failing").object(), *a.failing, true, true);
      w.end_object();
      break;
    case Hold_verdict::undecided:
      throw std::logic_error("hold_certificate: an undecided answer has no certificate");
  }
  return w.end_object().take();
}

}  // namespace wrenchkit
