// proofs/checker/motion.cpp - sliding: does a load stick or slide? certificate-format.md §6 (property "motion",
// theory [SL-1]; regions §6.4, format 2 §6.5).
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
    // Format 2 (§6.5): regions together with a force not given; each witness carries its own regions' blocks
    // (sticks: every vertex witness's stick blocks; depends: the sticking one's stick blocks and the sliding one's
    // slide blocks); "slides" keeps them at the top level, with the dual.
    const bool per_witness = regions && !known;
    if (per_witness && c_.version < 2)
      throw Failure{"motion: a support with regions and points whose force is not given has no certificate in format 1"};
    for (const Witness* w : {&m_.sticking, &m_.sliding}) b_.witness_regions(*w, per_witness);
    for (const Witness& w : m_.vertices) b_.witness_regions(w, per_witness);
    if (c_.claim == "depends" && known)
      throw Failure{"motion: \"depends\" needs a support with an unknown distribution (every force is given)"};
    std::set<std::string> allowed;
    if (c_.claim == "sticks") allowed = known ? std::set<std::string>{"support_forces"} : std::set<std::string>{"vertices"};
    if (c_.claim == "slides")
      allowed = known ? std::set<std::string>{"twist", "speed_bounds"} : std::set<std::string>{"twist", "speed_bounds", "dual"};
    if (c_.claim == "depends") allowed = {"sticking", "sliding"};
    if (regions && (known || c_.claim == "slides")) allowed.insert("regions");
    const std::vector<Block>* blocks =
        b_.claim_keys(c_, {"support_forces", "twist", "speed_bounds", "dual", "vertices", "sticking", "sliding", "regions"},
                      allowed, {}, "\"motion\" is " + quote(c_.claim),
                      known ? " and every support force is given" : " and some support force is unknown");
    if (c_.claim == "sticks" && known) return stick(b_.given(), m_.support_forces, "support_forces", blocks);
    if (c_.claim == "slides" && known) return slide(b_.given(), twist_, m_.speed_bounds, "", nullptr, blocks);
    if (c_.claim == "slides") return slide(b_.given(), twist_, m_.speed_bounds, "", m_.dual, blocks);
    if (c_.claim == "depends") {
      b_.in_f(m_.sticking.distribution, m_.sticking.path + ".distribution");
      stick(m_.sticking.distribution, m_.sticking.forces, m_.sticking.path + ".support_forces", own_blocks(m_.sticking));
      b_.in_f(m_.sliding.distribution, m_.sliding.path + ".distribution");
      return slide(m_.sliding.distribution, m_.sliding.twist, m_.sliding.speeds, m_.sliding.path + ".", nullptr,
                   own_blocks(m_.sliding));
    }
    sticks_for_every();
  }

 private:
  // Sticks under f: the support forces strictly inside their discs (and the regions' cell forces, with `blocks`)
  // carry the load p exactly (SL-1, RG-1).
  void stick(const std::vector<Q>& f, const std::vector<Pair>& g, const std::string& path,
             const std::vector<Block>* blocks = nullptr) const {
    const std::array<Q, 3> sum = b_.support_sum(f, g, path, true, blocks);
    if (sum[0] != m_.load[0] || sum[1] != m_.load[1] || sum[2] != m_.load[2])
      throw Failure{path + ": the support forces give the load (" + show(sum[0]) + ", " + show(sum[1]) + ", " +
                    show(sum[2]) + "), not (" + show(m_.load[0]) + ", " + show(m_.load[1]) + ", " +
                    show(m_.load[2]) + ")"};
  }

  // Slides: p not in the interior of LS(f) (on or past the limit surface): q != 0 and q.p >= the bound on the
  // frictional power h_f(q) (the regions' bounds included, with `blocks`).
  void slide(const std::vector<Q>& f, const Q (&q)[3], const std::vector<Q>& u, const std::string& prefix,
             const Q* dual, const std::vector<Block>* blocks = nullptr) const {
    b_.size(u.size(), prefix + "speed_bounds");
    if (sgn(q[0]) == 0 && sgn(q[1]) == 0 && sgn(q[2]) == 0) throw Failure{prefix + "twist: the zero twist"};
    const Q bound = b_.friction_bound(f, q, u, prefix, dual, blocks);
    const Q power = q[0] * m_.load[0] + q[1] * m_.load[1] + q[2] * m_.load[2];
    if (power < bound)
      throw Failure{prefix + "twist: power q.p = " + show(power) + " is less than " +
                    (dual ? "the dual bound " : "sum mu_i f_i u_i = ") + show(bound)};
  }

  // Sticks for every f in F: every witness is in F and sticks, and every vertex of F is the distribution of a
  // witness.
  void sticks_for_every() const {
    b_.every_vertex(m_.vertices, [&](const Witness& v) {
      b_.in_f(v.distribution, v.path + ".distribution");
      stick(v.distribution, v.forces, v.path + ".support_forces", own_blocks(v));
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
