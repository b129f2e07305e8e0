// [GR-1] Where two fingers may go: the exact force-closure regions of two frictional fingers on a polygon's edges
// (docs/grasp-regions.md, proofs/notes/GR-1-two-finger-regions.md, proofs/certificate-format.md §3.6).
//
// Fingers on edges i and j of body.outline (edge k from vertex k to k + 1), at p_i(s) = v_i + s·d_i and
// p_j(t) = v_j + t·d_j, (s, t) ∈ [0, 1]², each pushing along its edge's inward normal n with friction μ (the cone
// pos{n − μ·rot90 n, n + μ·rot90 n}). Nguyen's theorem: two frictional point contacts are in force closure exactly
// when the segment between them lies strictly inside both friction cones — p_j − p_i in the open cone at p_i and
// p_i − p_j in the open cone at p_j. Each of the four strict conditions is cross(e, v) > 0 with v affine in (s, t):
// a strict linear inequality. So the closure set of a pair is the unit square cut by four open half-planes — a convex
// polygon, exact, with rational corners; it is empty or has positive area (an open set meeting the square meets its
// interior). Exact arithmetic only (no square root): the edges' normals are rot90 of the edge vectors, not unit.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "exact/io/scene.h"

namespace wrenchkit {

// a·s + b·t + c > 0 (strict: its line is outside the closure set)
struct Region_constraint {
  Rational a, b, c;
};

struct Pair_region {
  std::size_t i = 0, j = 0;                    // i < j
  std::array<Region_constraint, 4> cones;      // finger i's cone (right, left edge), then finger j's
  std::vector<std::array<Rational, 2>> polygon;  // the closure set's closure in (s, t), counter-clockwise, no three
                                                 // corners collinear; empty: no placement closes
  Rational area;                               // of the polygon (0 when empty)
  // Independent contact regions: `side` the supremum of the sides of the axis-aligned squares [s0, s0 + a] ×
  // [t0, t0 + a] inside the region (exact: a 3-variable LP solved at its vertices; the square of that side touches
  // the region's open sides, so it is not attained), and `box` = [[s0, s1], [t0, t1]] the square of side
  // (1 − 2⁻¹⁰)·side about the same centre: every placement in it closes (the region is convex and the box's corners
  // lie strictly inside). None when the region is empty.
  Rational side;
  std::optional<std::array<std::array<Rational, 2>, 2>> box;
};

// [GR-2] Three fingers on edges i < j < k at parameters (s_0, s_1, s_2) ∈ [0, 1]³. Each finger's two friction-cone
// edges give two wrenches, affine in its own parameter; "R0" is finger 0's right edge n − μ·rot90 n, "L2" finger 2's
// left edge. An independent box [[a_0, b_0], [a_1, b_1], [a_2, b_2]] (a cube) is certified by four of the six wrenches
// whose four signed cofactors c_m = (−1)^m det(w without w_m) have one strict sign at every corner: each cofactor is
// affine in each parameter (multilinear), so it keeps that sign inside the box, and then Σ c_m w_m = 0 makes the four
// wrenches positively span the wrench space — force closure at every placement of the box
// (proofs/notes/GR-2-three-finger-boxes.md). `never`: no placement of the triple closes — μ = 0 (three wrenches cannot
// positively span a 3-dimensional space), or a wrench-space direction u with u · w ≤ 0 for the six wrenches at both
// ends of every edge (each u · w is affine in its parameter, so ≤ 0 everywhere). Neither: no box was found by the
// search (a grid of centres, the pairs' boxes, then a local search, proposed in doubles and checked exactly) — not a
// claim that none exists.
struct Triple_region {
  std::array<std::size_t, 3> edges{};       // increasing
  std::optional<std::array<std::array<Rational, 2>, 3>> box;
  std::array<int, 4> wrenches{};            // the box's certificate: 2·finger + (0 right, 1 left), increasing
  Rational side;                            // the box's side (0 without a box)
  bool never = false;
  std::optional<std::array<Rational, 3>> never_direction;  // absent with never: frictionless
};

// The wrench's name in answers and certificates: "R0", "L0", "R1", … (finger = position in the triple's edges).
std::string wrench_label(int w);

struct Grasp_regions {
  int fingers = 2;
  Rational mu;
  std::size_t edges = 0;
  bool ccw = true, convex = false;  // the outline's (exact/io/outline.h)
  std::vector<std::size_t> asked;   // the edges paired, increasing, when not every edge
  std::vector<Pair_region> pairs;  // fingers 2: every pair i < j of the edges asked (all by default), in order
  std::vector<Triple_region> triples;  // fingers 3: every triple i < j < k of the edges asked, in order
  std::size_t closed_pairs() const;
  std::size_t boxed_triples() const;   // with an independent box
  std::size_t never_triples() const;
};

// Throws Input_error for a scene without body.outline (or an outline that is not a simple polygon), μ < 0, an edge
// index out of range. `only`: the edges to pair (empty: every edge). Bounded work: refused past 2 000 edges (the
// pairs grow as the square: 2 million).
constexpr std::size_t kGraspRegionsMaxEdges = 2000;
Grasp_regions two_finger_regions(const Scene& scene, const Rational& mu, const std::vector<std::size_t>& only = {});

// Three fingers (GR-2): every triple of the edges asked; refused past kGraspRegionsMaxTriples triples (ask for some
// edges with `only`).
constexpr std::size_t kGraspRegionsMaxTriples = 20000;
Grasp_regions three_finger_regions(const Scene& scene, const Rational& mu, const std::vector<std::size_t>& only = {});

// The pair's four constraints at (s, t) — Nguyen's closure test of the placement, exact.
bool closed_at(const Pair_region& r, const Rational& s, const Rational& t);

}  // namespace wrenchkit
