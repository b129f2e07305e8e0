// proofs/certificate-format.md §7: does the body hold, with margin or just (§7.4 regions, §7.5 format 2, §7.6 format 3:
// the boundary). The checker's side: proofs/checker/hold.cpp.
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

// On the boundary, one distribution: the closed hold witness and the motion that meets the friction's bound, each
// region's block with the cells' forces and the corners' speed bounds.
void write_impending(Json_writer& w, const Hold_impending& h, bool support) {
  write_combination(w.key("combination"), h.holding.combination);
  if (support) write_support_forces(w, h.holding.support.forces);
  write_twist(w, h.twist.twist);
  if (support) w.key("speed_bounds").rationals(h.twist.speed_bounds);
  write_blocks(w, h.holding.support.regions, h.twist.regions);
}

}  // namespace

std::string hold_certificate(const Hold_answer& a) {
  Json_writer w(1024);
  w.object().member("wrenchkit_certificate", 3).member("property", "hold");
  switch (a.verdict) {
    case Hold_verdict::holds:  // with margin: forces strictly inside, the weighted generators and friction span R³
      w.member("holds", true);
      if (!a.unknown) {
        write_holding(w, *a.holding, a.has_support, false);
      } else {
        w.key("vertices").array();
        for (const Hold_witness& v : a.vertices) write_holding(w.object(), v, true, true), w.end_object();
        w.end_array();
      }
      break;
    case Hold_verdict::impending:
      w.member("holds", "impending");
      if (!a.unknown) {
        write_impending(w, *a.impending, a.has_support);
        break;
      }
      w.key("vertices").array();  // every vertex held in the closed set, one motion meeting every distribution's bound
      for (const Hold_witness& v : a.vertices) write_holding(w.object(), v, true, true), w.end_object();
      w.end_array();
      write_failing(w, *a.failing, true, false);
      break;
    case Hold_verdict::fails:
      w.member("holds", false);
      write_failing(w, *a.failing, a.has_support, false);
      break;
    case Hold_verdict::depends:  // one distribution held (closed), another moved, one of them strictly
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
