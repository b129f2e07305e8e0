// proofs/checker/motion.cpp - sliding: does a load stick, slide, or sit on the limit surface? certificate-format.md
// §6 (property "motion", theory [SL-1]; regions §6.4, format 2 §6.5, format 3 §6.6).
#include "proofs/checker/support_witnesses.h"

#include <set>

namespace wrenchkit_checker::detail {

class Motion_check {
 public:
  Motion_check(const Certificate& c, const Support& s, const Limits& lim)
      : c_(c), m_(members(c)), b_(s, lim), s_(s) {
    for (int k = 0; k < 3; ++k) twist_[k] = rational_value(c.twist[k]);
  }

  void run() {
    const bool known = s_.unknown == 0;
    const bool regions = !s_.regions.empty();
    const bool v3 = c_.version >= 3;
    const std::string_view claim = c_.claim;
    // Format 2 (§6.5): regions together with a force not given; each witness carries its own regions' blocks
    // (sticks and impending: every vertex witness's stick blocks; depends: the sticking one's stick blocks and the
    // sliding one's slide blocks); "slides" and "impending" over F keep the slide blocks at the top level, with the dual.
    const bool per_witness = regions && !known;
    if (per_witness && c_.version < 2)
      throw Failure{"motion: a support with regions and points whose force is not given has no certificate in format 1"};
    if (claim == "impending" && !v3)
      throw Failure{"motion: \"impending\" is a claim of format 3 (\"wrenchkit_certificate\": 3)"};
    for (const Witness* w : {&m_.sticking, &m_.sliding}) b_.witness_regions(*w, per_witness);
    for (const Witness& w : m_.vertices) b_.witness_regions(w, per_witness);
    if (claim == "depends" && known)
      throw Failure{"motion: \"depends\" needs a support with an unknown distribution (every force is given)"};
    std::set<std::string> allowed;
    if (claim == "sticks") allowed = known ? std::set<std::string>{"support_forces"} : std::set<std::string>{"vertices"};
    if (claim == "impending")
      allowed = known ? std::set<std::string>{"support_forces", "twist", "speed_bounds"}
                      : std::set<std::string>{"vertices", "twist", "speed_bounds", "dual"};
    if (claim == "slides")
      allowed = known ? std::set<std::string>{"twist", "speed_bounds"} : std::set<std::string>{"twist", "speed_bounds", "dual"};
    if (claim == "depends") allowed = {"sticking", "sliding"};
    if (regions && (known || claim == "slides" || claim == "impending")) allowed.insert("regions");
    const std::vector<Block>* blocks =
        b_.claim_keys(c_, {"support_forces", "twist", "speed_bounds", "dual", "vertices", "sticking", "sliding", "regions"},
                      allowed, {}, "\"motion\" is " + quote(claim),
                      known ? " and every support force is given" : " and some support force is unknown");
    // What each list of blocks holds: forces where a witness carries the load, speed bounds where a twist is bounded.
    Support_witnesses::block_kinds(blocks, known && (claim == "sticks" || claim == "impending"), claim != "sticks");
    Support_witnesses::block_kinds(own_blocks(m_.sticking), true, false);
    Support_witnesses::block_kinds(own_blocks(m_.sliding), false, true);
    for (const Witness& w : m_.vertices) Support_witnesses::block_kinds(own_blocks(w), true, false);
    const std::vector<Q> f = b_.given();
    if (claim == "sticks" && known) return stick(f, m_.support_forces, "support_forces", true, blocks);
    if (claim == "impending" && known) {  // p in the closed LS(f), and q.p >= a bound on h_f(q): on its surface
      stick(f, m_.support_forces, "support_forces", false, blocks);
      slide(f, twist_, m_.speed_bounds, "", nullptr, blocks, false);
      return;
    }
    if (claim == "slides") return void(slide(f, twist_, m_.speed_bounds, "", known ? nullptr : m_.dual, blocks, v3));
    if (claim == "impending") {  // every vertex of F in its closed set, and one twist meeting every one's bound
      every(false);
      slide(f, twist_, m_.speed_bounds, "", m_.dual, blocks, false);
      return;
    }
    if (claim == "depends") {  // one distribution inside (its closed set), another not (its interior), one strictly
      b_.in_f(m_.sticking.distribution, m_.sticking.path + ".distribution");
      Friction_reach in;
      stick(m_.sticking.distribution, m_.sticking.forces, m_.sticking.path + ".support_forces", !v3,
            own_blocks(m_.sticking), &in);
      b_.in_f(m_.sliding.distribution, m_.sliding.path + ".distribution");
      const bool out = slide(m_.sliding.distribution, m_.sliding.twist, m_.sliding.speeds, m_.sliding.path + ".",
                             nullptr, own_blocks(m_.sliding), false);
      if (!(in.open && in.places >= 2) && !out)
        throw Failure{"depends: neither witness is strict: the sticking forces are not all strictly inside their discs "
                      "at two places or more, and the sliding twist's power only meets its bound (both distributions "
                      "have the load on the limit surface: claim \"impending\")"};
      return;
    }
    every(true);
  }

 private:
  // Sticks under f: the support forces in their discs (and the regions' cell forces, with `blocks`) carry the load p
  // exactly (SL-1, RG-1); `strict`: in the open discs at two places at least (p in the interior), else closed (p in
  // LS(f)), `reach` telling how.
  void stick(const std::vector<Q>& f, const std::vector<Pair>& g, const std::string& path, bool strict,
             const std::vector<Block>* blocks = nullptr, Friction_reach* reach = nullptr) const {
    const std::array<Q, 3> sum = b_.support_sum(f, g, path, strict, blocks, reach);
    if (sum[0] != m_.load[0] || sum[1] != m_.load[1] || sum[2] != m_.load[2])
      throw Failure{path + ": the support forces give the load (" + show(sum[0]) + ", " + show(sum[1]) + ", " +
                    show(sum[2]) + "), not (" + show(m_.load[0]) + ", " + show(m_.load[1]) + ", " +
                    show(m_.load[2]) + ")"};
  }

  // Not in the interior of LS(f): q != 0 and q.p >= the bound on the frictional power h_f(q) (the regions' bounds
  // included, with `blocks`); `strict` (slides, format 3): q.p > it, p outside LS(f). Returns whether q.p > it.
  bool slide(const std::vector<Q>& f, const Q (&q)[3], const std::vector<Q>& u, const std::string& prefix,
             const Q* dual, const std::vector<Block>* blocks, bool strict) const {
    b_.size(u.size(), prefix + "speed_bounds");
    if (sgn(q[0]) == 0 && sgn(q[1]) == 0 && sgn(q[2]) == 0) throw Failure{prefix + "twist: the zero twist"};
    const Q bound = b_.friction_bound(f, q, u, prefix, dual, blocks);
    const Q power = q[0] * m_.load[0] + q[1] * m_.load[1] + q[2] * m_.load[2];
    const char* what = dual ? "the dual bound " : "sum mu_i f_i u_i = ";
    if (power < bound) throw Failure{prefix + "twist: power q.p = " + show(power) + " is less than " + what + show(bound)};
    if (strict && power == bound)
      throw Failure{prefix + "twist: power q.p = " + show(power) + " only equals " + what + show(bound) +
                    ": the load is not shown past the limit surface (on it, the claim is \"impending\")"};
    return power > bound;
  }

  // Every f in F (§6.2, §6.6): every witness is in F and carries the load (strictly: sticks; closed: impending), and
  // every vertex of F is the distribution of a witness.
  void every(bool strict) const {
    b_.every_vertex(m_.vertices, [&](const Witness& v) {
      b_.in_f(v.distribution, v.path + ".distribution");
      stick(v.distribution, v.forces, v.path + ".support_forces", strict, own_blocks(v));
    });
  }

  const Certificate& c_;
  const Motion_part& m_;
  Q twist_[3];
  Support_witnesses b_;
  const Support& s_;
};

// Property "motion" (§6).
void check_motion(const Certificate& c, const Scene& scene, const Limits& lim) {
  for (const char* key : {"load", "motion"})
    if (!c.keys.count(key)) throw Failure{std::string("missing required key \"") + key + "\""};
  for (const char* key : {"holds", "combination", "independent", "reading", "holding", "failing"})
    if (c.keys.count(key)) throw Failure{std::string("key \"") + key + "\" is not allowed when \"property\" is \"motion\""};
  if (c.motion_members) {
    for (const Witness* w : {&c.motion_members->sticking})
      if (w->has_combination) throw Failure{w->path + ": unknown key \"combination\""};
    for (const Witness& w : c.motion_members->vertices)
      if (w.has_combination) throw Failure{w.path + ": unknown key \"combination\""};
  }
  if (!scene.support) throw Failure{"property: \"motion\" needs a scene with a support"};
  Motion_check(c, *scene.support, lim).run();
}

}  // namespace wrenchkit_checker::detail
