// proofs/checker/hold.cpp - fixtures on a support: does the body hold, with margin or just? certificate-format.md §7
// (property "hold", theory [HD-1]; regions §7.4, format 2 §7.5, format 3 §7.6).
#include "proofs/checker/closure.h"
#include "proofs/checker/support_witnesses.h"

#include <optional>
#include <set>

namespace wrenchkit_checker::detail {

// HD-1 §10: do the generators g (the weighted ones, any positive multiples) and the friction's span make R^3? Two
// places with friction span R^3 themselves; one place (x, y) spans the plane normal to (y, -x, 1), which some g must
// leave; none: the g alone must have rank 3.
template <class N>
bool spans_r3(const std::vector<Int_wrench<N>>& g, const Friction_reach& reach) {
  const auto dot = [](const N (&a)[3], const N (&b)[3]) { return N(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]); };
  if (reach.places >= 2) return true;
  if (reach.places == 1) {
    const Q normal[3] = {reach.y, Q(-reach.x), Q(1)};
    const Int_wrench<N> n = integer_form<N>(normal);
    for (const Int_wrench<N>& w : g)
      if (sgn(dot(n.v, w.v)) != 0) return true;
    return false;
  }
  const N* a = nullptr;
  for (const Int_wrench<N>& w : g)
    if (sgn(w.v[0]) != 0 || sgn(w.v[1]) != 0 || sgn(w.v[2]) != 0) {
      a = w.v;
      break;
    }
  if (!a) return false;
  for (const Int_wrench<N>& w : g) {
    const N c[3] = {N(a[1] * w.v[2] - a[2] * w.v[1]), N(a[2] * w.v[0] - a[0] * w.v[2]), N(a[0] * w.v[1] - a[1] * w.v[0])};
    if (sgn(c[0]) == 0 && sgn(c[1]) == 0 && sgn(c[2]) == 0) continue;
    for (const Int_wrench<N>& x : g)
      if (sgn(dot(c, x.v)) != 0) return true;
    return false;  // the g span the plane of a and w
  }
  return false;
}

// Property "hold" (§7; docs/theory-sliding.md §5; proofs/notes/HD-1): the contacts (the friction generators)
// together with the support's friction hold the body against the scene's load w_L, i.e. -w_L is in W + LS(f).
// Held: contact weights (as §3.3) and support forces in their CLOSED discs with sum lambda_k g_k +
// sum (g_i, r_i x g_i) + w_L = 0; with margin (format 3 "holds": true, -w_L in the interior) when every force is
// strictly inside its disc and the weighted generators with the friction's span make R^3. Moved: a twist t with
// <t, g> >= 0 for every generator and t.w_L > the bound on the frictional power of t (strict; >= on the boundary,
// "impending"). A scene without a support: hold is equilibrium.
class Hold_check {
 public:
  Hold_check(const Certificate& c, const Scene& scene, const Limits& lim)
      : c_(c), m_(members(c)), scene_(scene), lim_(lim), b_(scene.support ? *scene.support : no_support_, lim) {
    for (int k = 0; k < 3; ++k) twist_[k] = rational_value(c.twist[k]);
  }

  void run() {
    if (!scene_.has_load) throw Failure{"property: \"hold\" needs a scene with a load"};
    for (const char* key : {"load", "motion", "independent", "sticking", "sliding"})
      if (c_.keys.count(key)) throw Failure{std::string("key \"") + key + "\" is not allowed when \"property\" is \"hold\""};
    if (!c_.keys.count("holds")) throw Failure{"missing required key \"holds\""};
    const bool support = scene_.support.has_value(), known = !support || scene_.support->unknown == 0;
    const bool regions = support && !scene_.support->regions.empty();
    const bool v3 = c_.version >= 3;
    // Format 2 (§7.5): regions together with a force not given; each witness carries its own regions' blocks
    // (holds, impending: every vertex witness's stick blocks; depends: the holding one's stick blocks and the failing
    // one's slide blocks); "holds": false and "impending" over F keep the slide blocks at the top level, with the dual.
    const bool per_witness = regions && !known;
    if (per_witness && c_.version < 2)
      throw Failure{"holds: a support with regions and points whose force is not given has no certificate in format 1 "
                    "(format 2, \"wrenchkit_certificate\": 2)"};
    if (c_.impending && !v3) throw Failure{"holds: \"impending\" is a claim of format 3 (\"wrenchkit_certificate\": 3)"};
    for (const Witness* w : {&m_.holding, &m_.failing}) b_.witness_regions(*w, per_witness);
    for (const Witness& w : m_.vertices) b_.witness_regions(w, per_witness);
    const std::string claim = c_.depends ? "\"depends\"" : c_.impending ? "\"impending\"" : c_.holds ? "true" : "false";
    if (c_.depends && known)
      throw Failure{"holds: \"depends\" needs a support with an unknown distribution (" +
                    std::string(support ? "every force is given" : "the scene has no support") + ")"};
    std::set<std::string> allowed, optional;
    const bool held = c_.holds || (c_.impending && known);  // a hold witness at the top level (known) or per vertex
    const bool moved = !c_.holds && !c_.depends;            // a twist at the top level (false, impending)
    if (c_.depends) {
      allowed = {"holding", "failing"};
    } else {
      if (held) allowed = known ? std::set<std::string>{"combination"} : std::set<std::string>{"vertices"};
      if (held && known && support) allowed.insert("support_forces");
      if (c_.impending && !known) allowed.insert("vertices");
      if (moved) {
        allowed.insert("twist");
        optional = {"reading"};
        if (support) allowed.insert("speed_bounds");
        if (!known) allowed.insert("dual");
      }
    }
    if (regions && (known || moved)) allowed.insert("regions");
    blocks_ = b_.claim_keys(c_, {"combination", "support_forces", "twist", "reading", "speed_bounds", "dual", "vertices",
                                 "holding", "failing", "regions"},
                            allowed, optional, "\"holds\" is " + claim,
                            !support ? " and the scene has no support"
                            : known  ? " and every support force is given"
                                     : " and some support force is unknown");
    Support_witnesses::block_kinds(blocks_, known && held, moved);
    Support_witnesses::block_kinds(own_blocks(m_.holding), true, false);
    Support_witnesses::block_kinds(own_blocks(m_.failing), false, true);
    for (const Witness& w : m_.vertices) Support_witnesses::block_kinds(own_blocks(w), true, false);
    const std::vector<Q> f = support ? b_.given() : std::vector<Q>();
    if (c_.depends) {  // one distribution held (closed), another moved; format 3: one of them strictly
      if (!m_.holding.has_combination) throw Failure{m_.holding.path + ": missing required key \"combination\""};
      b_.in_f(m_.holding.distribution, m_.holding.path + ".distribution");
      const bool margin = hold(m_.holding.distribution, m_.holding.combination, m_.holding.forces,
                               m_.holding.path + ".", own_blocks(m_.holding), false);
      b_.in_f(m_.failing.distribution, m_.failing.path + ".distribution");
      const bool past = fail(m_.failing.distribution, m_.failing.twist, m_.failing.speeds, m_.failing.path + ".",
                             nullptr, own_blocks(m_.failing), !v3);
      if (!margin && !past)
        throw Failure{"depends: neither witness is strict: the holding one has no margin and the failing twist's power "
                      "only meets its bound (both distributions hold the load just: claim \"impending\")"};
      return;
    }
    if (moved) {  // false: strictly; impending: its bound met, beside the hold witnesses
      fail(f, twist_, m_.speed_bounds, "", known ? nullptr : m_.dual, blocks_, !c_.impending);
      fast_then_exact(lim_, [&](auto zero) { check_reading(c_, integer_form<decltype(zero)>(c_.twist)); });
      if (!c_.impending) return;
    }
    // Format 3 "holds": true is held with margin; format 1 and 2 and "impending", in the closed set.
    const bool margin = c_.holds && v3;
    if (known) return void(hold(f, c_.combination, m_.support_forces, "", blocks_, margin));
    // For every f in F: a hold witness at every vertex of F (W is a convex cone and LS is linear in f).
    b_.every_vertex(m_.vertices, [&](const Witness& v) {
      if (!v.has_combination) throw Failure{v.path + ": missing required key \"combination\""};
      b_.in_f(v.distribution, v.path + ".distribution");
      hold(v.distribution, v.combination, v.forces, v.path + ".", own_blocks(v), margin);
    });
  }

 private:
  // Contact weights and support forces (closed discs) that cancel the load exactly. Returns whether they hold it with
  // margin (HD-1 §10: every force strictly inside its disc, the weighted generators and the friction's span R^3);
  // `margin` asks for it.
  bool hold(const std::vector<Q>& f, const std::vector<Term>& combination, const std::vector<Pair>& g,
            const std::string& prefix, const std::vector<Block>* blocks, bool margin) const {
    std::optional<std::array<Q, 3>> sum;  // the support forces' wrench, computed once (a rerun on Z reuses it)
    Friction_reach reach;
    bool spans = false;
    fast_then_exact(lim_, [&](auto zero) {
      using N = decltype(zero);
      const Combination<N> terms_of(combination, scene_.contacts, Reading::friction, lim_);
      std::vector<Int_wrench<N>> terms = terms_of.weighted;
      if (scene_.support.has_value()) {
        if (!sum) sum = b_.support_sum(f, g, prefix + "support_forces", false, blocks, &reach);
        terms.push_back(integer_form<N>({(*sum)[0], (*sum)[1], (*sum)[2]}));
      }
      terms.push_back(integer_form<N>({scene_.load->fx, scene_.load->fy, scene_.load->m}));
      zero_sum(std::move(terms), prefix + "combination: the contact forces" +
                                     (scene_.support.has_value() ? ", the support forces" : "") + " and the load sum to ");
      spans = spans_r3(terms_of.generator, reach);
    });
    const bool with_margin = reach.open && spans;
    if (margin && !with_margin)
      throw Failure{prefix + "combination: the load is held, but with no margin: " +
                    (!reach.open ? std::string("a support force is on its disc's circle")
                                 : std::string("the weighted generators and the friction's span do not make R^3")) +
                    " (a load held only just is the claim \"impending\")"};
    return with_margin;
  }

  // A motion every contact allows that the load drives harder than the support's friction can resist (`strict`;
  // else at least as hard: the boundary). Returns whether strictly harder.
  bool fail(const std::vector<Q>& f, const Q (&t)[3], const std::vector<Q>& u, const std::string& prefix,
            const Q* dual, const std::vector<Block>* blocks, bool strict) const {
    // The zero twist meets every bound with equality and proves nothing (strict: it cannot pass anyway).
    if (sgn(t[0]) == 0 && sgn(t[1]) == 0 && sgn(t[2]) == 0) throw Failure{prefix + "twist: the zero twist"};
    fast_then_exact(lim_, [&](auto zero) {
      allowed_by_every_contact(integer_form<decltype(zero)>(t), scene_.contacts, Reading::friction, lim_, prefix);
    });
    const Q bound = scene_.support.has_value() ? b_.friction_bound(f, t, u, prefix, dual, blocks) : Q(0);
    const Q power = t[0] * scene_.load->fx + t[1] * scene_.load->fy + t[2] * scene_.load->m;
    const std::string what = !scene_.support.has_value() ? std::string("0")
                                                         : (dual ? "the dual bound " : "sum mu_i f_i u_i = ") + show(bound);
    if (strict ? !(power > bound) : power < bound)
      throw Failure{prefix + "twist: power against the load t.w_L = " + show(power) + " is not " +
                    (strict ? "more than " : "at least ") + what};
    return power > bound;
  }

  static inline const Support no_support_{};  // a scene without a support (b_ is then not used)
  const Certificate& c_;
  const Motion_part& m_;
  Q twist_[3];
  const Scene& scene_;
  const Limits& lim_;
  Support_witnesses b_;
  const std::vector<Block>* blocks_ = nullptr;  // the regions' blocks (§6.4), when the support has regions
};

void check_hold(const Certificate& c, const Scene& scene, const Limits& lim) { Hold_check(c, scene, lim).run(); }

}  // namespace wrenchkit_checker::detail
