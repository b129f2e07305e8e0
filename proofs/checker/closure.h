// proofs/checker/closure.h - the rules of certificate-format.md §3.1 and §3.2, written once over a number type N
// (numbers.h: Fixed or Z, both instantiated in closure.cpp). closure.cpp checks §3.1 and §3.2 with them,
// equilibrium.cpp §3.3, hold.cpp the contacts' part of §7.2.
#pragma once

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
  Combination(const std::vector<Term>& terms, const std::vector<Contact>& contacts, Reading reading, const Limits& lim);
  std::size_t find(const Ref& ref) const;  // the term whose generator the reference names, or terms.size()
  std::vector<std::size_t> order;          // the terms by generator (contact, edge), then by place
  std::vector<Int_wrench<N>> generator, weighted;

 private:
  std::pair<std::size_t, std::string_view> key(std::size_t k) const { return {terms_[k].ref.contact, terms_[k].ref.edge}; }
  const std::vector<Term>& terms_;
};

// Rule (4) of §3.1: the integer wrenches (not none) sum to (0, 0, 0); else the Failure `what`, the sum, ", not (0, 0, 0)".
template <class N>
void zero_sum(std::vector<Int_wrench<N>> terms, const std::string& what);
// Rule (1) of §3.2: the certificate's twist t = T / T.d, and it is not zero.
template <class N>
Int_wrench<N> nonzero_twist(const Certificate& c);
// Rule (2) of §3.2: <t, g> >= 0 for every generator g of the scene under the reading (`prefix`: where t is).
template <class N>
void allowed_by_every_contact(const Int_wrench<N>& t, const std::vector<Contact>& contacts, Reading reading,
                              const Limits& lim, const std::string& prefix);
// Rule (3) of §3.2: the reading, if present, is P(t) for the certificate's twist t.
template <class N>
void check_reading(const Certificate& c, const Int_wrench<N>& t);

}  // namespace wrenchkit_checker::detail
