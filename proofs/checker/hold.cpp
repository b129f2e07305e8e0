// proofs/checker/hold.cpp - fixtures on a support: does the body hold? certificate-format.md §7 (property "hold",
// theory [HD-1]; regions §7.4, format 2 §7.5).
#include "proofs/checker/closure.h"
#include "proofs/checker/support_witnesses.h"

#include <optional>
#include <set>

namespace wrenchkit_checker::detail {

// Property "hold" (§7; docs/theory-sliding.md §5; proofs/notes/HD-1): the contacts (the friction generators)
// together with the support's friction hold the body against the scene's load w_L, i.e. -w_L is in W + LS(f).
// Holds: contact weights (as §3.3) and support forces in their CLOSED discs with sum lambda_k g_k +
// sum (g_i, r_i x g_i) + w_L = 0. Does not hold: a twist t with <t, g> >= 0 for every generator and
// t.w_L > the bound on the frictional power of t (strict). A scene without a support: hold is equilibrium.
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
    // Format 2 (§7.5): regions together with a force not given; each witness carries its own regions' blocks
    // (holds: every vertex witness's stick blocks; depends: the holding one's stick blocks and the failing one's
    // slide blocks); "holds": false keeps them at the top level, with the dual.
    const bool per_witness = regions && !known;
    if (per_witness && c_.version < 2)
      throw Failure{"holds: a support with regions and points whose force is not given has no certificate in format 1 "
                    "(format 2, \"wrenchkit_certificate\": 2)"};
    for (const Witness* w : {&m_.holding, &m_.failing}) b_.witness_regions(*w, per_witness);
    for (const Witness& w : m_.vertices) b_.witness_regions(w, per_witness);
    const std::string claim = c_.depends ? "\"depends\"" : c_.holds ? "true" : "false";
    if (c_.depends && known)
      throw Failure{"holds: \"depends\" needs a support with an unknown distribution (" +
                    std::string(support ? "every force is given" : "the scene has no support") + ")"};
    std::set<std::string> allowed, optional;
    if (c_.depends) {
      allowed = {"holding", "failing"};
    } else if (c_.holds) {
      allowed = known ? std::set<std::string>{"combination"} : std::set<std::string>{"vertices"};
      if (known && support) allowed.insert("support_forces");
    } else {
      allowed = {"twist"};
      optional = {"reading"};
      if (support) allowed.insert("speed_bounds");
      if (!known) allowed.insert("dual");
    }
    if (regions && (known || (!c_.holds && !c_.depends))) allowed.insert("regions");
    blocks_ = b_.claim_keys(c_, {"combination", "support_forces", "twist", "reading", "speed_bounds", "dual", "vertices",
                                 "holding", "failing", "regions"},
                            allowed, optional, "\"holds\" is " + claim,
                            !support ? " and the scene has no support"
                            : known  ? " and every support force is given"
                                     : " and some support force is unknown");
    const std::vector<Q> f = support ? b_.given() : std::vector<Q>();
    if (c_.depends) {
      if (!m_.holding.has_combination) throw Failure{m_.holding.path + ": missing required key \"combination\""};
      b_.in_f(m_.holding.distribution, m_.holding.path + ".distribution");
      hold(m_.holding.distribution, m_.holding.combination, m_.holding.forces, m_.holding.path + ".",
           own_blocks(m_.holding));
      b_.in_f(m_.failing.distribution, m_.failing.path + ".distribution");
      return fail(m_.failing.distribution, m_.failing.twist, m_.failing.speeds, m_.failing.path + ".", nullptr,
                  own_blocks(m_.failing));
    }
    if (!c_.holds) {
      fail(f, twist_, m_.speed_bounds, "", known ? nullptr : m_.dual, blocks_);
      return fast_then_exact(lim_, [&](auto zero) { check_reading(c_, integer_form<decltype(zero)>(c_.twist)); });
    }
    if (known) return hold(f, c_.combination, m_.support_forces, "", blocks_);
    // Holds for every f in F: a hold witness at every vertex of F (W is a convex cone and LS is linear in f).
    b_.every_vertex(m_.vertices, [&](const Witness& v) {
      if (!v.has_combination) throw Failure{v.path + ": missing required key \"combination\""};
      b_.in_f(v.distribution, v.path + ".distribution");
      hold(v.distribution, v.combination, v.forces, v.path + ".", own_blocks(v));
    });
  }

 private:
  // Contact weights and support forces (closed discs) that cancel the load exactly.
  void hold(const std::vector<Q>& f, const std::vector<Term>& combination, const std::vector<Pair>& g,
            const std::string& prefix, const std::vector<Block>* blocks) const {
    std::optional<std::array<Q, 3>> sum;  // the support forces' wrench, computed once (a rerun on Z reuses it)
    fast_then_exact(lim_, [&](auto zero) {
      using N = decltype(zero);
      std::vector<Int_wrench<N>> terms = Combination<N>(combination, scene_.contacts, Reading::friction, lim_).weighted;
      if (scene_.support.has_value()) {
        if (!sum) sum = b_.support_sum(f, g, prefix + "support_forces", false, blocks);
        terms.push_back(integer_form<N>({(*sum)[0], (*sum)[1], (*sum)[2]}));
      }
      terms.push_back(integer_form<N>({scene_.load->fx, scene_.load->fy, scene_.load->m}));
      zero_sum(std::move(terms), prefix + "combination: the contact forces" +
                                     (scene_.support.has_value() ? ", the support forces" : "") + " and the load sum to ");
    });
  }

  // A motion every contact allows that the load drives harder than the support's friction can resist.
  void fail(const std::vector<Q>& f, const Q (&t)[3], const std::vector<Q>& u, const std::string& prefix,
            const Q* dual, const std::vector<Block>* blocks) const {
    fast_then_exact(lim_, [&](auto zero) {
      allowed_by_every_contact(integer_form<decltype(zero)>(t), scene_.contacts, Reading::friction, lim_, prefix);
    });
    const Q bound = scene_.support.has_value() ? b_.friction_bound(f, t, u, prefix, dual, blocks) : Q(0);
    const Q power = t[0] * scene_.load->fx + t[1] * scene_.load->fy + t[2] * scene_.load->m;
    if (!(power > bound))
      throw Failure{prefix + "twist: power against the load t.w_L = " + show(power) + " is not more than " +
                    (!scene_.support.has_value() ? std::string("0") : (dual ? "the dual bound " : "sum mu_i f_i u_i = ") + show(bound))};
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
