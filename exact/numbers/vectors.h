// The engine's small exact vocabulary (theory.md §1): planar points and vectors, and the one 3-vector that is a
// wrench (fx, fy, m), m about the origin, or a twist (vx, vy, ω); their products, and power. Every name here is the
// only one of its kind in exact/: a file that needs a dot product or a velocity uses these.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "exact/numbers/rational.h"

namespace wrenchkit {

// A point or a vector of the plane.
struct Vec2 {
  Rational x, y;
};

// A wrench (fx, fy, m) or a twist (vx, vy, ω), exact.
using Vec3q = std::array<Rational, 3>;
// Its integer form (primitive rays and twists, the polytopes' normals).
using Vec3z = std::array<Integer, 3>;

inline Rational dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
// a × b = ax·by − ay·bx.
inline Rational cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

// ⟨a, b⟩: the power of a twist against a wrench when one is each.
inline Rational dot(const Vec3q& a, const Vec3q& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3q cross(const Vec3q& a, const Vec3q& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// a − b, and rot90(v) = (−vy, vx): v turned a quarter counter-clockwise.
inline Vec2 minus(const Vec2& a, const Vec2& b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 rot90(const Vec2& v) { return {-v.y, v.x}; }
inline Vec2 scaled(const Vec2& v, const Rational& k) { return {v.x * k, v.y * k}; }
inline bool is_zero(const Vec2& v) { return v.x == 0 && v.y == 0; }
inline bool is_zero(const Vec3q& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }
inline bool is_zero(const Vec3z& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

// W(p, f) = (fx, fy, p × f): the wrench of the force f acting at p.
inline Vec3q wrench_at(const Vec2& p, const Vec2& f) { return {f.x, f.y, cross(p, f)}; }

// v(r) = (vx − ω·y, vy + ω·x): the velocity of the point r under the twist q.
inline Vec2 velocity(const Vec3q& q, const Vec2& r) { return {q[0] - q[2] * r.y, q[1] + q[2] * r.x}; }
// |v(r)|², the square of the point's speed (its speed itself is a square root: the engine brackets it).
inline Rational speed_squared(const Vec3q& q, const Vec2& r) {
  const Vec2 v = velocity(q, r);
  return dot(v, v);
}

// primitive(v) of exact/numbers/rational.h (v ≠ 0, else std::logic_error), as rationals: how twists and rays are
// written in answers and certificates.
inline Vec3q primitive_vec(const Vec3q& v) {
  const Vec3z z = primitive(v);
  return {Rational(z[0]), Rational(z[1]), Rational(z[2])};
}

// A twist (or any 3-vector) in double with its small-denominator ratios made exact: each component over the largest
// by continued fractions, denominators ≤ 10^4, within 10^-10 of it; nothing when one has no such ratio. A load exactly
// on a limit surface is met by a rational normal twist when one exists with short numbers (a translation along
// (3, 4), a rotation about (1/2, 0)), which rounding alone misses.
std::optional<Vec3q> rationalized(const std::array<double, 3>& d);

// The motion a twist describes, in words: "a counter-clockwise rotation about (x, y)", "a clockwise rotation about
// (x, y)", "a translation along (dx, dy)" (the velocity's direction, primitive integers). t ≠ 0.
std::string motion_words(const Vec3q& twist);

}  // namespace wrenchkit
