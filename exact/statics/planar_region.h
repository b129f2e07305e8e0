// [LB-1] Exact convex regions of the plane and cones of directions, and the slices of a 3-D
// polyhedral cone that turn a cone on the two-sided plane into the pictures a reader draws
// (theory.md §2, §5.7, §6).
//
// A 3-D cone C = pos{g_k} (homogeneous points (X, Y, Z) of the two-sided plane T²) is read as
//   front sheet   {(x, y) : (x, y, 1) ∈ C}        — slice_front(gens)
//   back sheet    {(x, y) : (x, y, 1) ∈ −C}       — slice_front(negated gens)
//   infinity      {(dx, dy) : (dx, dy, 0) ∈ C}    — slice_infinity(gens)
// Slices (Fourier–Motzkin on the Z coordinate; proofs/notes/LB-1.md): the front sheet is
// conv{g/Z : Z > 0} + pos(D) and the points at infinity are pos(D), where D holds the (X, Y) parts of
// the generators with Z = 0 and of the combinations (−Z_b) g_a + Z_a g_b for Z_a > 0 > Z_b. When the
// generators are the extreme rays of a *pointed* cone in cyclic order, only consecutive pairs cross
// Z = 0 and D is built in O(K); otherwise from all pairs (the non-pointed cones have ≤ 6 generators).
//
// Everything is exact rational arithmetic; no square root, no division by a quantity that may be
// zero, no perturbation: degenerate regions (a point, a segment, a line, …) are ordinary answers.
// The float twin slices only pointed cones by a walk of their cycle (float/labels_twin.h); why there are
// two slicings and which test ties them: proofs/notes/LB-5-slicing-twins.md.
#pragma once

#include <string>
#include <vector>

#include "exact/statics/generators.h"
#include "exact/io/scene.h"

namespace wrenchkit {

// A closed convex cone of directions in R² (an arc of the circle at infinity), by its extreme
// directions in counter-clockwise order, each a primitive integer vector:
//   zero        {}                         nothing
//   ray         [d]                        one direction
//   wedge       [lo, hi], lo × hi > 0      the arc from lo counter-clockwise to hi (< 180°)
//   half_plane  [d, n, −d], n = rot90(d)   the half-circle from d counter-clockwise to −d
//   line        [d, −d]                    an antipodal pair
//   plane       []                         every direction
struct Cone2 {
  enum class Shape { zero, ray, wedge, half_plane, line, plane };
  Shape shape = Shape::zero;
  std::vector<Vec2> extreme;
};
const char* shape_name(Cone2::Shape s);

// pos(dirs), classified; zero vectors are ignored. O(n log n) exact comparisons.
Cone2 cone_hull(const std::vector<Vec2>& dirs);
bool contains(const Cone2& c, const Vec2& d);  // is d (any length, d ≠ 0) in the cone?

// A closed convex region of the plane, exactly: region = conv(vertices) + pos(directions).
//   vertices    the corners in counter-clockwise order (empty, point, segment, ray, wedge, polygon,
//               unbounded polygon); for regions without corners, one point on each boundary line:
//               line: a point of it; strip: a point on each of its two lines; half-plane: a point
//               of its boundary line; plane: the origin.
//   directions  the extreme recession directions in counter-clockwise order (Cone2's `extreme`),
//               primitive integer vectors; empty when bounded.
struct Region {
  enum class Shape { empty, point, segment, ray, line, strip, half_plane, wedge, polygon, unbounded_polygon, plane };
  Shape shape = Shape::empty;
  std::vector<Vec2> vertices;
  std::vector<Vec2> directions;
  bool empty() const { return shape == Shape::empty; }
  bool bounded() const { return directions.empty(); }
  // Has interior points (a 2-D region).
  bool full_dimensional() const;
};
const char* shape_name(Region::Shape s);

// conv(points) + cone, in normal form. O(n log n).
Region region_of(std::vector<Vec2> points, const Cone2& cone);

// Slices of C = pos(gens) (see the file comment). `cyclic_pointed`: gens are the extreme rays of a
// pointed cone in cyclic order (O(K) crossings); otherwise every pair is combined.
Region slice_front(const std::vector<Vec3q>& gens, bool cyclic_pointed);
Cone2 slice_infinity(const std::vector<Vec3q>& gens, bool cyclic_pointed);
std::vector<Vec3q> negated(std::vector<Vec3q> gens);

// primitive(x, y) of exact/numbers/rational.h ((x, y) ≠ 0, else std::logic_error), as a rational Vec2.
Vec2 primitive2(const Rational& x, const Rational& y);

}  // namespace wrenchkit
