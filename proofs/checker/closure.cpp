// proofs/checker/closure.cpp - force and form closure, certificate-format.md §3.1 (holds = true, theory [FC-2])
// and §3.2 (holds = false, theory [FC-3]), over the generators of §1.
#include "proofs/checker/closure.h"

#include <algorithm>

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

template <class N>
Combination<N>::Combination(const std::vector<Term>& terms, const std::vector<Contact>& contacts, Reading reading,
                            const Limits& lim)
    : order(terms.size()), generator(terms.size()), weighted(terms.size()), terms_(terms) {
  const std::size_t n = terms.size();
  for (std::size_t k = 0; k < n; ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return std::make_pair(key(a), a) < std::make_pair(key(b), b); });
  // (2) no generator appears twice in combination: the first term to repeat one is named. Checked on the
  // references before (1), so that (1) recomputes each generator once.
  std::size_t twice = n, first = n;
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (key(order[i]) == key(order[i + 1]) && order[i + 1] < twice) twice = order[i + 1], first = order[i];
  if (twice < n)
    throw Failure{terms[twice].ref.path() + ": " + name(terms[twice].ref.contact, terms[twice].ref.edge) +
                  " appears twice (also at " + terms[first].ref.path() + ")"};
  // (1) every reference names a generator of the scene under the reading
  std::vector<int> edge(n);
  for (std::size_t k = 0; k < n; ++k) edge[k] = check_reference(terms[k].ref, contacts, reading);
  // (3) every weight is strictly positive: by the grammar of §2, its text starts with neither '-' nor '0'
  for (const Term& t : terms)
    if (t.weight[0] == '-' || t.weight[0] == '0')
      throw Failure{t.ref.path() + ".weight: " + quote(t.weight) + " is not strictly positive"};
  // g_k and weight_k g_k = (a g.v) / (b g.d) for weight_k = a / b, each contact's generators computed once
  Generators<N> g{};
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = order[i], contact = terms[k].ref.contact;
    if (i == 0 || contact != terms[order[i - 1]].ref.contact) g = generators<N>(contacts[contact], reading, lim);
    const Int_wrench<N>& gk = generator[k] = g.w[edge[k]];
    const Frac<N> w = fraction<N>(terms[k].weight);
    weighted[k] = {{N(w.num * gk.v[0]), N(w.num * gk.v[1]), N(w.num * gk.v[2])}, N(w.den * gk.d)};
  }
}

template <class N>
std::size_t Combination<N>::find(const Ref& ref) const {
  const auto at = std::lower_bound(order.begin(), order.end(), std::make_pair(ref.contact, ref.edge),
                                   [&](std::size_t k, const std::pair<std::size_t, std::string_view>& x) { return key(k) < x; });
  return at != order.end() && key(*at) == std::make_pair(ref.contact, ref.edge) ? *at : terms_.size();
}

template <class N>
void zero_sum(std::vector<Int_wrench<N>> terms, const std::string& what) {
  const Int_wrench<N> total = tree_sum(std::move(terms));
  if (sgn(total.v[0]) != 0 || sgn(total.v[1]) != 0 || sgn(total.v[2]) != 0)
    throw Failure{what + show(total) + ", not (0, 0, 0)"};
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

template <class N>
Int_wrench<N> nonzero_twist(const Certificate& c) {
  const Int_wrench<N> t = integer_form<N>(c.twist);
  if (sgn(t.v[0]) == 0 && sgn(t.v[1]) == 0 && sgn(t.v[2]) == 0) throw Failure{"twist: the zero twist proves nothing"};
  return t;
}

// The motion t is allowed by every contact; with t = T / T.d and g = v / d, the sign of <t, g> is that of <T, v>.
template <class N>
void allowed_by_every_contact(const Int_wrench<N>& t, const std::vector<Contact>& contacts, Reading reading,
                              const Limits& lim, const std::string& prefix) {
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Generators<N> g = generators<N>(contacts[i], reading, lim);
    for (int k = 0; k < g.count; ++k) {
      const N p = power(t, g.w[k]);
      if (sgn(p) < 0)
        throw Failure{prefix + "twist: power " + show(value(to_z(p), to_z(N(t.d * g.w[k].d)))) + " against " + name(i, g.edge[k])};
    }
  }
}

// P(t) = (-vy, vx, w) on the two-sided plane, t = T / T.d.
template <class N>
void check_reading(const Certificate& c, const Int_wrench<N>& T) {
  if (!c.keys.count("reading")) return;
  const auto t = [&c](int k) { return rational_value(c.twist[k]); };  // (the values, for messages)
  const auto where = [&c] { return show(rational_value(c.where[0]), rational_value(c.where[1])); };
  const N &vx = T.v[0], &vy = T.v[1], &w = T.v[2];
  const std::string label = sgn(w) > 0 ? "+" : sgn(w) < 0 ? "-" : "infinity";
  if (c.label != label)
    throw Failure{"reading.label: " + quote(c.label) + " does not match the twist, whose label is " + quote(label)};
  const Frac<N> p[2] = {fraction<N>(c.where[0]), fraction<N>(c.where[1])};
  if (sgn(w) != 0) {  // the rotation centre (-vy/w, vx/w)
    if (sgn(N(p[0].num * w + vy * p[0].den)) != 0 || sgn(N(p[1].num * w - vx * p[1].den)) != 0)
      throw Failure{"reading.point: " + where() + " is not the rotation centre " + show(Q(-t(1) / t(2)), Q(t(0) / t(2))) +
                    " of the twist"};
  } else {  // d = (-vy, vx) != 0 as t != 0; e is a positive multiple of d iff d x e = 0 and d . e > 0
    const N e[2] = {N(p[0].num * p[1].den), N(p[1].num * p[0].den)};  // (a positive multiple of the point)
    if (sgn(N(-vy * e[1] - vx * e[0])) != 0 || sgn(N(vx * e[1] - vy * e[0])) <= 0)
      throw Failure{"reading.direction: " + where() + " is not a positive multiple of (-vy, vx) = " + show(Q(-t(1)), t(0))};
  }
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

// The rules for both number types (numbers.h), as equilibrium.cpp and hold.cpp use them.
template struct Combination<Z>;
template struct Combination<Fixed>;
template void zero_sum(std::vector<Int_wrench<Z>>, const std::string&);
template void zero_sum(std::vector<Int_wrench<Fixed>>, const std::string&);
template Int_wrench<Z> nonzero_twist(const Certificate&);
template Int_wrench<Fixed> nonzero_twist(const Certificate&);
template void allowed_by_every_contact(const Int_wrench<Z>&, const std::vector<Contact>&, Reading, const Limits&,
                                       const std::string&);
template void allowed_by_every_contact(const Int_wrench<Fixed>&, const std::vector<Contact>&, Reading, const Limits&,
                                       const std::string&);
template void check_reading(const Certificate&, const Int_wrench<Z>&);
template void check_reading(const Certificate&, const Int_wrench<Fixed>&);

}  // namespace wrenchkit_checker::detail
