// [FC-0] Contact wrench generators (theory.md §4, §8.2) and the exact predicate kernel over them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/contact_generators.h"
#include "core/sign.h"
#include "exact/io/scene.h"
#include "exact/numbers/wide_int.h"

namespace wrenchkit {

struct Generator {
  std::size_t contact = 0;  // index into scene.contacts
  Edge edge = Edge::normal;
  Vec3q w;                 // exact, unscaled: W(p, e) or the wrench given
};

// The generators of the contact wrench cone, in contact order; per point contact: `normal`
// (μ = 0 or frictionless reading) or `left` = W(p, n + μ·rot90 n), `right` = W(p, n − μ·rot90 n).
// Exact; O(#contacts).
std::vector<Generator> generators(const Scene& scene, Reading reading);

// The force each contact exerts on the body under a certificate's weights on its generators (in `reading`: friction
// for closure, equilibrium and hold, frictionless for form closure): Σ_edges weight·(the edge's force); a wrench
// contact's wrench. One entry per contact that carries any weight, in contact order — what a reader of the book wants
// to see instead of weights on unnormalised cone edges.
struct Contact_force {
  std::size_t contact = 0;
  std::string name;  // the contact's `name`, or ""
  Vec3q wrench;      // (fx, fy, m about the origin); for a point contact (fx, fy) acts at its point
  bool point = true;  // a point contact (else a wrench contact: its moment matters too)
};
template <class Ref>
std::vector<Contact_force> contact_forces(const Scene& scene, const std::vector<std::pair<Ref, Rational>>& combination,
                                         Reading reading = Reading::friction) {
  const std::vector<Generator> gens = generators(scene, reading);
  std::vector<Contact_force> out;
  for (const Generator& g : gens)
    for (const auto& [ref, weight] : combination) {
      if (ref.contact != g.contact || ref.edge != g.edge || weight == 0) continue;
      if (out.empty() || out.back().contact != g.contact)
        out.push_back({g.contact, scene.contacts[g.contact].name, {}, scene.contacts[g.contact].kind == Contact::Kind::point});
      for (std::size_t k = 0; k < 3; ++k) out.back().wrench[k] += weight * g.w[k];
    }
  return out;
}

// Exact predicate kernel for core/dual_cone.h over a list of nonzero wrenches. Each wrench is
// replaced by a positive integer multiple (the cone is unchanged). Signs are
// exact integer arithmetic in three tiers: __int128 when every entry of the rows involved is below
// 2^40 (a 3×3 determinant is then below 6·2^120 < 2^127), the fixed-width Int192 of
// exact/numbers/wide_int.h when below 2^62, GMP integers otherwise. Never uncertain, never floating point.
// Zero rows are allowed (their determinants are zero); the dual-cone algorithm itself needs
// nonzero generators, which scenes guarantee.
class Exact_kernel {
 public:
  explicit Exact_kernel(const std::vector<Vec3q>& wrenches);
  // The rows of generators(scene, reading), in the same order, computed directly in integers from
  // each contact's numerators and denominators when they are small (no rational arithmetic, no
  // allocation), through the rationals otherwise. The same primitive rows either way.
  // `extra`: rows appended after the generators (equilibrium's load).
  Exact_kernel(const Scene& scene, Reading reading, const std::vector<Vec3q>& extra = {});
  // [FC-5] The same rows, each with its provenance: the contact and edge it comes from (extra rows:
  // contact kNoContact, edge `wrench`) and the positive factor `scale` with row = scale · W, W the
  // UNSCALED generator of proofs/certificate-format.md §1 (or the extra wrench as given). Integer
  // arithmetic; for the certificates, which must weigh the unscaled generators the checker recomputes.
  struct With_provenance {};
  Exact_kernel(const Scene& scene, Reading reading, const std::vector<Vec3q>& extra, With_provenance);
  static constexpr std::size_t kNoContact = static_cast<std::size_t>(-1);
  std::size_t size() const { return rows_.size(); }
  Sign cross_sign(std::size_t i, std::size_t j) const;          // zero iff parallel
  Sign det_sign(std::size_t i, std::size_t j, std::size_t k) const;

  // Row i: a positive integer multiple of wrench i (for tests).
  std::array<Integer, 3> row(std::size_t i) const;
  // Row i in fixed width when its entries are at most 2^62 − 1 in magnitude (tiers 0 and 1).
  bool small_row(std::size_t i, std::int64_t out[3]) const {
    const Row& r = rows_[i];
    if (r.tier == 2) return false;
    out[0] = r.s[0], out[1] = r.s[1], out[2] = r.s[2];
    return true;
  }
  // Provenance (only when built With_provenance): row i = (num/den) · W_i, num, den > 0.
  bool has_provenance() const { return record_; }
  std::size_t contact(std::size_t i) const { return prov_[i].contact; }
  Edge edge(std::size_t i) const { return prov_[i].edge; }
  void scale(std::size_t i, Integer& num, Integer& den) const;

 private:
  struct Row {
    std::int64_t s[3] = {0, 0, 0};  // tier 0, 1
    std::uint8_t tier = 0;          // 0: |entries| < 2^40; 1: ≤ 2^62 − 1; 2: larger (big_ only)
    std::uint32_t big = 0;          // tier 2: index into big_
  };
  // Where row i comes from: scale = f0·f1·f2 / divisor, or big_scale_[big] when big ≥ 0.
  struct Provenance {
    std::size_t contact = kNoContact;
    Edge edge = Edge::wrench;
    std::int64_t f[3] = {1, 1, 1};
    wide::u128 divisor = 1;
    std::int32_t big = -1;
  };
  void build(const Scene& scene, Reading reading, const std::vector<Vec3q>& extra);
  void push_rational(const Rational in[3], std::size_t contact);
  void push_big(std::array<Integer, 3> v);
  void load(std::size_t i, mpz_ptr out) const;
  wide::u128 push_int128(wide::i128 x, wide::i128 y, wide::i128 z);  // returns the divisor applied
  void note(std::size_t contact, Edge edge, std::int64_t f0, std::int64_t f1, std::int64_t f2, wide::u128 divisor);
  void note_big(std::size_t contact, Edge edge, Integer scale);
  std::vector<Row> rows_;
  std::vector<std::array<Integer, 3>> big_;
  bool record_ = false;  // With_provenance
  std::vector<Provenance> prov_;
  std::vector<Integer> big_scale_;
};

// The number of generators of generators(scene, reading), without building them.
std::size_t generator_count(const Scene& scene, Reading reading);


}  // namespace wrenchkit
