// proofs/certificate-format.md §8 (format 6): which way a pushed body turns. The bounds of the friction under the
// body and of the three votes over F (exact; with the LP's duals when some force is not given), the rule's verdict,
// and for "depends" two distributions of F that turn the body opposite ways. The checker's side:
// proofs/checker/push.cpp (it computes the votes from the scene, checks the duals, and applies the rule itself).
#include "exact/certificates/certificates.h"

namespace wrenchkit {

namespace {

void write_range(Json_writer& w, const F_range& r, bool lower_only) {
  w.object().member("lower", r.lower);
  if (r.dual_lower) w.key("dual_lower").rationals(*r.dual_lower);
  if (!lower_only) {
    w.member("upper", r.upper);
    if (r.dual_upper) w.key("dual_upper").rationals(*r.dual_upper);
  }
  w.end_object();
}

// §8.2: a contact mode and what proves it; "depends" (forces not given): its two witnesses, each with its distribution.
void write_contact(Json_writer& w, const Push_contact& c) {
  w.object();
  if (!c.forces.empty()) w.key("forces").rationals(c.forces);  // a witness of "depends"
  w.member("mode", push_mode_name(c.mode));
  if (c.mode == Push_mode::depends) {
    w.key("witnesses").array();
    for (const Push_contact& k : c.witnesses) write_contact(w, k);
    w.end_array().end_object();
    return;
  }
  w.member("bits", c.bits);
  w.key("omega").array().rational(c.omega_lo).rational(c.omega_hi).end_array();
  if (c.pivot) {  // §8.2: the sticking motion a rotation about a support point (PU-2 §7–8)
    w.member("pivot", *c.pivot);
    if (c.force) w.key("force").array().rational(c.force->x).rational(c.force->y).end_array();  // sticks
  }
  if (c.has_tangent) w.key("tangent_omega").array().rational(c.tangent_lo).rational(c.tangent_hi).end_array();
  if (c.tangent_pivot) w.member("tangent_pivot", *c.tangent_pivot);  // F(t) a facet's chord (PU-2 §8)
  if (c.has_motion) {  // §8.2: the sliding motion (PU-2 §5)
    w.key("sliding").object();
    if (c.motion_pivot) w.member("pivot", *c.motion_pivot);  // the rotation about that support point (PU-2 §6)
    w.key("slip").array().rational(c.slip_lo).rational(c.slip_hi).end_array();
    if (!c.motion_pivot) {
      w.key("slip_omega").array();
      for (const auto& b : c.slip_omega) w.array().rational(b[0]).rational(b[1]).end_array();
      w.end_array();
    }
    w.key("omega").array().rational(c.motion_lo).rational(c.motion_hi).end_array();
    w.end_object();
  }
  w.end_object();
}

}  // namespace

// §8.3: a line pusher's stable push (PU-3): the verdict and what proves it.
static std::string line_push_certificate(const Push_answer& a) {
  const Stable_push& st = *a.stable;
  Json_writer w(512);
  w.object().member("wrenchkit_certificate", 6).member("property", "push");
  if (a.rotation != Rotation::undecided) w.member("rotation", rotation_name(a.rotation));
  w.key("center").array().rational(a.center->x).rational(a.center->y).end_array();
  w.key("stable").object().member("verdict", stability_name(st.verdict)).member("R2", st.R2);
  if (st.verdict == Stability::stable && st.sense != 0 && st.tip_line)
    w.member("R_hi", st.R_hi).member("d_lo", st.d_lo).member("alpha_hi", st.alpha_hi);
  if (st.verdict == Stability::stable && !st.duals.empty()) {  // facets proven by the LP's dual (PU-3 §6)
    w.key("duals").object();
    for (const auto& [f, y] : st.duals) w.key(cone_facet_name(f)).rationals(y);
    w.end_object().member("bits", st.bits);
  }
  if (st.verdict == Stability::unstable) {
    w.member("facet", cone_facet_name(st.facet));
    if (st.sense != 0) {
      w.key("witness").object().key("points").array();
      for (const Vec2& x : st.points) w.array().rational(x.x).rational(x.y).end_array();
      w.end_array().key("weights").rationals(st.weights).member("bits", st.bits).end_object();
    }
  }
  w.end_object();
  if (a.region) {  // §8.3: the stable region's tip lines (the other half-planes are the scene's)
    const Stable_region& g = *a.region;
    w.key("region").object().member("R_hi", g.R_hi);
    for (int k = 0; k < 2; ++k) {
      w.key(k == 0 ? "ccw" : "cw");
      if (g.side[k].possible) w.object().member("alpha_hi", g.side[k].alpha_hi).member("T", g.side[k].T).end_object();
      else w.null();
    }
    if (g.translations) {
      w.key("translations").array();
      for (const Vec2& v : *g.translations) w.array().rational(v.x).rational(v.y).end_array();
      w.end_array();
    }
    w.end_object();
  }
  return w.end_object().take();
}

std::string push_certificate(const Push_answer& a) {
  if (a.stable) return line_push_certificate(a);
  Json_writer w(512);
  w.object().member("wrenchkit_certificate", 6).member("property", "push").member("rotation", rotation_name(a.rotation));
  w.key("friction");
  write_range(w, a.friction, true);
  if (a.rotation == Rotation::depends) {
    w.key("turns").object().key("ccw").rationals(a.turns_ccw).key("cw").rationals(a.turns_cw).end_object();
  } else {
    w.key("votes").array();
    for (const Push_vote& v : a.votes) write_range(w, v.value, false);
    w.end_array();
  }
  if (a.center) w.key("center").array().rational(a.center->x).rational(a.center->y).end_array();
  if (a.contact && a.contact->mode != Push_mode::undecided) {  // §8.2: the contact mode
    w.key("contact");
    write_contact(w, *a.contact);
  }
  if (a.locus && a.locus->friction_centre) {  // §8.4: the rotation centres' pieces (their half-planes are the scene's)
    const Push_locus& g = *a.locus;
    w.key("locus").object().member("R_hi", g.R_hi);
    if (g.T) w.member("alpha_hi", g.alpha_hi).member("T", *g.T);
    for (int k = 0; k < 2; ++k) {
      w.key(k == 0 ? "ccw" : "cw");
      if (!g.side[k].possible) {
        w.null();
        continue;
      }
      w.array();
      for (const Locus_piece& piece : g.side[k].pieces) {
        w.object().member("mode", locus_mode_name(piece.mode)).member("bounded", piece.bounded).key("polygon").array();
        for (const Vec2& x : piece.polygon) w.array().rational(x.x).rational(x.y).end_array();
        w.end_array().end_object();
      }
      w.end_array();
    }
    if (g.arm_hi) w.member("arm_hi", *g.arm_hi);
    if (a.slowest) {  // PU-4 §5: a distribution of F whose certified rate puts its centre at least arm_lo away
      w.member("arm_lo", a.slowest->arm_lo).key("slowest");
      write_contact(w, a.slowest->contact);
    }
    w.end_object();
  }
  return w.end_object().take();
}

}  // namespace wrenchkit
