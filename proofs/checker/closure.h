// proofs/checker/closure.h - the rules of certificate-format.md §3.1 and §3.2, written once over a number type N
// (numbers.h: Fixed or Z). closure.cpp checks §3.1 and §3.2 with them, equilibrium.cpp §3.3, hold.cpp the contacts'
// part of §7.2.
#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "proofs/checker/certificate.h"

namespace wrenchkit_checker::detail {

std::string name(std::size_t contact, std::string_view edge);  // "contacts[i] edge E"
// Rule (1) of §3.1: the reference names an existing contact and an edge it has under the reading (its index).
int check_reference(const Ref& ref, const std::vector<Contact>& contacts, Reading reading);

// Rules (1)-(3) of §3.1 for the terms of a combination: each names a generator of the scene under the reading,
// no generator appears twice, every weight is strictly positive. Holds each term's generator g_k, recomputed from
// the scene, and weight_k g_k.
template <class N>
struct Combination {
  std::vector<std::size_t> order;  // the terms by generator (contact, edge), then by place
  std::vector<Int_wrench<N>> generator, weighted;

  Combination(const std::vector<Term>& terms, const std::vector<Contact>& contacts, Reading reading, const Limits& lim)
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
    for (const Term& t : terms) check_reference(t.ref, contacts, reading);
    // (3) every weight is strictly positive: by the grammar of §2, its text starts with neither '-' nor '0'
    for (const Term& t : terms)
      if (t.weight[0] == '-' || t.weight[0] == '0')
        throw Failure{t.ref.path() + ".weight: " + quote(t.weight) + " is not strictly positive"};
    // g_k and weight_k g_k = (a g.v) / (b g.d) for weight_k = a / b, each contact's generators computed once
    Generators<N> g;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = order[i], contact = terms[k].ref.contact;
      if (i == 0 || contact != terms[order[i - 1]].ref.contact) g = generators<N>(contacts[contact], reading, lim);
      const Int_wrench<N>& gk = generator[k] = g.w[check_reference(terms[k].ref, contacts, reading)];
      const Frac<N> w = fraction<N>(terms[k].weight);
      weighted[k] = {{N(w.num * gk.v[0]), N(w.num * gk.v[1]), N(w.num * gk.v[2])}, N(w.den * gk.d)};
    }
  }
  // The term whose generator the reference names, or none (terms.size()).
  std::size_t find(const Ref& ref) const {
    const auto at = std::lower_bound(order.begin(), order.end(), std::make_pair(ref.contact, ref.edge),
                                     [&](std::size_t k, const std::pair<std::size_t, std::string_view>& x) { return key(k) < x; });
    return at != order.end() && key(*at) == std::make_pair(ref.contact, ref.edge) ? *at : terms_.size();
  }

 private:
  std::pair<std::size_t, std::string_view> key(std::size_t k) const { return {terms_[k].ref.contact, terms_[k].ref.edge}; }
  const std::vector<Term>& terms_;
};

// Rule (4) of §3.1: the integer wrenches (not none) sum to (0, 0, 0); else the Failure `what`, the sum, ", not (0, 0, 0)".
template <class N>
void zero_sum(std::vector<Int_wrench<N>> terms, const std::string& what) {
  const Int_wrench<N> total = tree_sum(std::move(terms));
  if (sgn(total.v[0]) != 0 || sgn(total.v[1]) != 0 || sgn(total.v[2]) != 0)
    throw Failure{what + show(total) + ", not (0, 0, 0)"};
}

// Rule (1) of §3.2: the certificate's twist t = T / T.d, and it is not zero.
template <class N>
Int_wrench<N> nonzero_twist(const Certificate& c) {
  const Int_wrench<N> t = integer_form<N>(c.twist);
  if (sgn(t.v[0]) == 0 && sgn(t.v[1]) == 0 && sgn(t.v[2]) == 0) throw Failure{"twist: the zero twist proves nothing"};
  return t;
}

// Rule (2) of §3.2: <t, g> >= 0 for every generator g of the scene under the reading (`prefix`: where t is): the
// motion t is allowed by every contact. With t = T / T.d and g = v / d, the sign of <t, g> is that of <T, v>.
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

// Rule (3) of §3.2: the reading, if present, is P(t) = (-vy, vx, w) on the two-sided plane, t = T / T.d.
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

}  // namespace wrenchkit_checker::detail
