// [FC-0] Contact wrench generators (theory.md §4, §8.2) and the exact predicate kernel over them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/contact_generators.h"
#include "core/sign.h"
#include "exact/scene.h"

namespace wrenchkit {

struct Generator {
  std::size_t contact = 0;  // index into scene.contacts
  Edge edge = Edge::normal;
  Wrench w;                 // exact, unscaled: W(p, e) or the wrench given
};

// W(p, f) = (fx, fy, p × f).
Wrench wrench_at(const Vec2& p, const Vec2& f);

// The generators of the contact wrench cone, in contact order; per point contact: `normal`
// (μ = 0 or frictionless reading) or `left` = W(p, n + μ·rot90 n), `right` = W(p, n − μ·rot90 n).
// Exact; O(#contacts).
std::vector<Generator> generators(const Scene& scene, Reading reading);

// Exact predicate kernel for core/dual_cone.h over a list of nonzero wrenches. Each wrench is
// replaced by its primitive integer multiple (a positive scaling: the cone is unchanged); signs
// are computed in 128-bit integers when every coordinate is below 2^40 in magnitude (exact:
// a 3×3 determinant is then below 6·2^120 < 2^127) and in GMP integers otherwise. Never uncertain.
// Zero rows are allowed (their determinants are zero); the dual-cone algorithm itself needs
// nonzero generators, which scenes guarantee.
class Exact_kernel {
 public:
  explicit Exact_kernel(const std::vector<Wrench>& wrenches);
  std::size_t size() const { return rows_.size(); }
  Sign cross_sign(std::size_t i, std::size_t j) const;          // zero iff parallel
  Sign det_sign(std::size_t i, std::size_t j, std::size_t k) const;

 private:
  struct Row {
    Integer v[3];
    bool small = false;
    std::int64_t s[3] = {0, 0, 0};
  };
  std::vector<Row> rows_;
};

// The primitive integer vector positively parallel to a nonzero rational 3-vector.
void primitive(const Rational in[3], Integer out[3]);

using Vec3 = std::array<Rational, 3>;
Vec3 as_vec(const Wrench& w);
Vec3 cross(const Vec3& a, const Vec3& b);
// `primitive` for a Vec3, as rationals (how twists are written in certificates).
Vec3 primitive_vec(const Vec3& v);

}  // namespace wrenchkit
