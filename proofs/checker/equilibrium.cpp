// proofs/checker/equilibrium.cpp - equilibrium, certificate-format.md §3.3 (theory [EQ-1]): the rules of §3.1 and
// §3.2 (closure.h) with the scene's load w_ext, over the friction generators.
#include "proofs/checker/closure.h"

namespace wrenchkit_checker::detail {

// holds = true: (1)-(3) of §3.1 and (4') sum_k l_k g_k + w_ext = 0, so -w_ext = sum_k l_k g_k is in W: the contact
// forces l_k (force of g_k) balance the load. There is no (5), and the combination may be empty (then w_ext = 0).
// holds = false: (1)-(3) of §3.2 and <t, w_ext> > 0, so <t, -w_ext> < 0 <= <t, x> for every x in W: -w_ext is not
// in W, and no admissible contact forces balance the load.
void check_equilibrium(const Certificate& c, const Scene& scene, const Limits& lim) {
  if (!scene.has_load) throw Failure{"property: \"equilibrium\" needs a scene with a load"};
  fast_then_exact(lim, [&](auto zero) {
    using N = decltype(zero);
    const Int_wrench<N> w_ext = integer_form<N>({scene.load->fx, scene.load->fy, scene.load->m});
    if (c.holds) {
      Combination<N> terms(c.combination, scene.contacts, c.reading, lim);
      terms.weighted.push_back(w_ext);
      return zero_sum(std::move(terms.weighted), "combination: the weighted sum of the generators plus the load is ");
    }
    const Int_wrench<N> t = nonzero_twist<N>(c);
    allowed_by_every_contact(t, scene.contacts, c.reading, lim, "");
    if (sgn(power(t, w_ext)) <= 0)
      throw Failure{"twist: power against the load is " + show(value(to_z(power(t, w_ext)), to_z(N(t.d * w_ext.d)))) +
                    ", not > 0"};
    check_reading(c, t);
  });
}

}  // namespace wrenchkit_checker::detail
