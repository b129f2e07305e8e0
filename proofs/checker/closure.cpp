// proofs/checker/closure.cpp - force and form closure, certificate-format.md §3.1 (holds = true, theory [FC-2])
// and §3.2 (holds = false, theory [FC-3]), over the generators of §1.
#include "proofs/checker/closure.h"

namespace wrenchkit_checker::detail {

std::string name(std::size_t contact, std::string_view edge) {
  return "contacts[" + std::to_string(contact) + "] edge " + std::string(edge);
}

int check_reference(const Ref& ref, const std::vector<Contact>& contacts, Reading reading) {
  if (ref.contact >= contacts.size())
    throw Failure{ref.path() + ".contact: index " + clip(std::string(ref.index)) + " is out of range (the scene has " +
                  std::to_string(contacts.size()) + " contacts)"};
  const char* names[2];
  const int n = edge_names(contacts[ref.contact], reading, names);
  for (int k = 0; k < n; ++k)
    if (ref.edge == names[k]) return k;
  const std::string edges = quote(names[0]) + (n == 2 ? " or " + quote(names[1]) : "");
  throw Failure{ref.path() + ".edge: contacts[" + std::to_string(ref.contact) + "] has no edge " + quote(ref.edge) +
                " under the " + (reading == Reading::friction ? "friction" : "frictionless") + " reading (it has " +
                edges + ")"};
}

// §3.1, theory [FC-2]. With S the generators of `combination`: (3) and (4) give, for every g_j in S,
// -g_j = sum_{k != j} (l_k / l_j) g_k in pos(S), so pos(S) is a linear subspace; (5) makes it
// 3-dimensional, so W contains pos(S) = R^3.
template <class N>
void check_positive(const Certificate& c, const std::vector<Contact>& contacts, const Limits& lim) {
  Combination<N> terms(c.combination, contacts, c.reading, lim);
  for (const Ref& ref : c.independent) check_reference(ref, contacts, c.reading);
  // (4) sum_k weight_k g_k = (0, 0, 0) exactly: the numerator of the sum over the product of the (positive)
  // denominators is zero (combination is not empty)
  zero_sum(std::move(terms.weighted), "combination: the weighted sum of the generators is ");
  // (5) the three independent generators are in combination, and their determinant is not zero
  std::size_t row[3];
  for (std::size_t r = 0; r < 3; ++r)
    if ((row[r] = terms.find(c.independent[r])) == c.combination.size())
      throw Failure{c.independent[r].path() + ": " + name(c.independent[r].contact, c.independent[r].edge) + " is not in combination"};
  if (sgn(det3(terms.generator[row[0]], terms.generator[row[1]], terms.generator[row[2]])) == 0)
    throw Failure{"independent: the three generators are linearly dependent (determinant 0)"};
}

// §3.2, theory [FC-3]. Every x in W is sum mu_g g with mu >= 0, so <t, x> >= 0, while <t, -t> < 0:
// the wrench -t is not in W, and W != R^3.
template <class N>
void check_negative(const Certificate& c, const std::vector<Contact>& contacts, const Limits& lim) {
  const Int_wrench<N> t = nonzero_twist<N>(c);                // (1) the twist is not zero
  allowed_by_every_contact(t, contacts, c.reading, lim, "");  // (2) <t, g> >= 0 for every generator g
  check_reading(c, t);                                        // (3) the reading, if present, is P(t)
}

void check_closure(const Certificate& c, const Scene& scene, const Limits& lim) {
  fast_then_exact(lim, [&](auto zero) {
    if (c.holds) check_positive<decltype(zero)>(c, scene.contacts, lim);
    else check_negative<decltype(zero)>(c, scene.contacts, lim);
  });
}

}  // namespace wrenchkit_checker::detail
