// [FL-6] The float twin of moment labeling and the force dual (theory.md §5, §6), and certified point
// queries on a wrench cone. Standard library only.
//
// The combinatorics come from core/dual_cone.h [FC-1] over the certified Float_kernel [FL-2] (the
// same code, the same branch decisions as the exact engine); the constructions are Bounded [FL-1,
// FL-5]: the extreme rays of W* are cross products g_a × g_b of consecutive edge generators, and a
// region's corner is (X/Z, Y/Z) of such a ray under J (theory.md §2.2). Every constructed coordinate
// carries a bound on its distance to the exact coordinate of the scene as written.
//
// Exactness: certified-or-undecided. A decided answer has exactly the exact engine's shapes, corner
// counts and corner order (exact/statics/moment_labels.h, exact/statics/force_dual.h), and every corner lies within
// its stated bound of the exact corner. Undecided when a sign is within its error bound of zero, and
// for the cones this twin does not represent: rank W < 3 (the ± lineality; only exactly degenerate
// data can be certified to have it) and, for the force dual, a W that is not pointed (W* an arc or a
// ray). `--mode hybrid` answers those exactly.
//
// Slicing [LB-1], for a pointed cone whose extreme rays p_0 … p_{K−1} (homogeneous points of the
// two-sided plane) are in counter-clockwise cyclic order: the front sheet is conv{p_j/Z_j : Z_j > 0}
// + pos(D), where D holds (X, Y) of the rays with Z = 0 and of the crossings Z_a p_b − Z_b p_a of
// consecutive rays with Z_a > 0 > Z_b (and symmetrically); the back sheet is the front sheet of the
// negated cone (its cycle reversed); the points at infinity are pos(D). Complexity O(K) after FC-1. Why this
// walk is not exact/statics/planar_region.h's slicing written over Bounded: proofs/notes/LB-5-slicing-twins.md.
#pragma once

#include <cstddef>
#include <vector>

#include "core/dual_cone.h"
#include "float/closure_twin.h"
#include "float/float_kernel.h"

namespace wrenchkit::fl {

// A constructed point or direction of the plane, each coordinate with its bound.
struct Point2 {
  Bounded x, y;
};

// conv(vertices) + pos(directions), the float counterpart of exact/statics/planar_region.h's Region for the
// shapes a pointed cone can slice to (plus `plane`, the dual of a force-closed cone). Vertices in
// counter-clockwise order; directions (not normalised) as exact/statics/planar_region.h orders them: the
// boundary leaves the last vertex along directions[0] and returns along directions.back().
struct Region2 {
  enum class Shape { empty, point, segment, ray, wedge, polygon, unbounded_polygon, plane };
  Shape shape = Shape::empty;
  std::vector<Point2> vertices;
  std::vector<Point2> directions;
};
const char* shape_name(Region2::Shape s);  // the names of exact/statics/planar_region.h

// A closed cone of directions (an arc of the circle at infinity): nothing, one direction, the arc
// from extreme[0] counter-clockwise to extreme[1] (< 180°), or the whole circle.
struct Arc2 {
  enum class Shape { zero, ray, wedge, full };
  Shape shape = Shape::zero;
  std::vector<Point2> extreme;
};

enum class Twin_status {
  decided,        // every sign certified
  uncertain,      // a sign was within its error bound of zero
  rank_deficient, // rank W < 3: the ± lineality is not represented by the twin
  not_pointed     // force dual only: W contains a line (W* is an arc or a ray)
};
const char* status_name(Twin_status s);

struct Labels_twin {
  Twin_status status = Twin_status::uncertain;
  int rank = 0;
  Dual_shape shape = Dual_shape::lineality;
  std::vector<Bounded3> rays;  // extreme rays of W* (twists), in the cycle's order
  Region2 plus, minus;         // R₊ (counter-clockwise centres), R₋ (clockwise centres)
  Arc2 infinity;               // R∞ (translations)
  bool decided() const { return status == Twin_status::decided; }
  // Force closure ⇔ nothing is labeled (theory.md §5.5); meaningful when decided().
  bool nothing_labeled() const {
    return plus.shape == Region2::Shape::empty && minus.shape == Region2::Shape::empty &&
           infinity.shape == Arc2::Shape::zero;
  }
};

// The labels of W = pos(generators) (wrenches (fx, fy, m), nonzero), from a dual cone the caller
// computed over the same generators (`dc`), or computing it.
Labels_twin moment_labels(const std::vector<Bounded3>& generators, const Dual_cone& dc);
Labels_twin moment_labels(const std::vector<Bounded3>& generators);
// The NAIVE variant, for benchmarks and stress tests only: raw double signs everywhere (Naive_kernel for
// the cone, unchecked signs in the slicing). It guesses and is sometimes wrong; never answer a user with it.
Labels_twin moment_labels_naive(const std::vector<Bounded3>& generators);
// Robot-side: the labels of point contacts with their friction (Reading::friction) or read
// frictionless (Reuleaux's feasible rotation centres). Throws std::invalid_argument as force_closure.
Labels_twin moment_labels(const std::vector<Point_contact>& contacts, Reading reading = Reading::friction);

struct Dual_point_twin {
  char sheet = '+';  // '+', '-', 'i' (at infinity: `at` is a direction), '?' (uncertain)
  Point2 at;
};
Dual_point_twin dual_point(const Bounded3& w);  // D(w) = (−fy, fx, m) (theory.md §6.1)

struct Dual_twin {
  Twin_status status = Twin_status::uncertain;
  bool covers_all = false;          // W = R³: force closure
  Region2 plus_sheet, minus_sheet;  // D(W) on the front and back sheets
  Arc2 infinity;
  bool decided() const { return status == Twin_status::decided; }
};
Dual_twin force_dual(const std::vector<Bounded3>& generators, const Dual_cone& dc);

// Certified queries straight from the generators (O(n), no cone construction):
enum class Truth { no, yes, uncertain };
// Is w a possible resultant (w ∈ W)? Uses the extreme rays of W* (rank 3); uncertain for rank < 3.
Truth in_cone(const Labels_twin& labels, const Bounded3& w);
// The moment label of the point c (theory.md §5.1): '+', '-', 'b' (±: every generator's moment about
// c is zero), '0' (unlabeled) or '?' (uncertain).
char label_of(const std::vector<Bounded3>& generators, const Bounded& cx, const Bounded& cy);

// Reuleaux's test of a twist t = (v_x, v_y, ω) at one contact (theory.md §7), certified: the sign of the
// power ⟨t, W(p, n)⟩ = v(p)·n (⟨t, w⟩ for a wrench generator) and the sign of |v(p)|² (zero: the contact
// point is the rotation centre, it sticks). Sign::uncertain where the bound cannot decide.
struct Contact_motion {
  Sign power = Sign::uncertain;
  Sign speed = Sign::uncertain;  // positive or zero (or uncertain); wrench generators: zero
};
Contact_motion contact_motion(const Bounded_contact& c, const Bounded3& t);

}  // namespace wrenchkit::fl
