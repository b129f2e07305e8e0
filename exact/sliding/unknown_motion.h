// [SL-3] Does a load stick or slide when the support's distribution is unknown (docs/theory-sliding.md §2)?
//
//   sticks   for every admissible distribution  ⇔  p ∈ LS(f_v) for every vertex f_v of F (LS is linear in f
//            under Minkowski sums, so every f = Σ λ_v f_v sticks too);
//   slides   for every one  ⇔  p ∉ U = ∪_F LS(f)  ⇔  some twist q has q·p > max_F h_f(q);
//   depends  otherwise: one admissible distribution sticks and another slides.
//
// Decided as follows, every step certified:
//   1. each vertex: decide_motion on its own support (hybrid: the float twin's certified search on the true
//      limit surface first, the exact polygons when it cannot tell) — all stick: sticks; a stick and a slide:
//      depends;
//   2. every vertex slides: twists that separate p from all of U — the vertices' sliding twists and their sum,
//      checked exactly with the speeds bounded above by rationals (u_i² ≥ |v_i(q)|²) and the LP over F:
//      q·p ≥ max_F Σ μ_i f_i u_i proves slides;
//      hybrid: the union's minimax min_{q·p=1} max_v h_{f_v}(q) by a log barrier in double (U is convex; proofs/notes/
//      SL-6 §6): its minimiser is such a twist, or its multipliers give a distribution f* = Σ λ_v f_v of F that holds
//      p strictly (a stick witness of f*, checked exactly: depends); then a compass search on the same function;
//   3. else an exact LP over F × (inscribed N-gons) looks for one distribution that sticks (a stick witness:
//      rational support forces strictly inside the discs summing to p): found: depends;
//   4. else undecided (the load is within the resolution of U's boundary).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/mode.h"
#include "exact/sliding/distribution.h"
#include "exact/sliding/sliding.h"

namespace wrenchkit {

// Rational support forces of one distribution holding the load: g_i·g_i < (μ_i f_i)² (g_i = 0 where μ_i f_i = 0),
// Σ (g_i, r_i × g_i) = p, with friction at two distinct points: p is in the interior of LS(f), so it sticks (a
// load on the limit surface slides; proofs/notes/SL-1).
struct Stick_witness {
  std::vector<Rational> distribution;  // one force per support point
  std::vector<Vec2> forces;            // g_i, one per support point
};

// A stick witness on the inscribed N-gons (N = sides) for the distribution `fixed`: the exact LP [LP-1]
// maximising a common margin t with Σ_j λ_ij + t ≤ μ_i f_i (|u_j| = 1, so |g_i| ≤ Σ_j λ_ij < μ_i f_i when
// t > 0); nothing when p is not strictly inside LS_in^N(f) or friction acts at fewer than two distinct points.
// With `fixed` null: some distribution of F with p in LS_in^N(f) (closed; the caller confirms it strictly with
// that f fixed).
std::optional<Stick_witness> stick_witness(const Support& s, const Admissible& a, const Vec3q& p, int sides,
                                           const std::vector<Rational>* fixed = nullptr);

// Does q prove that p slides for every distribution of F (q ≠ 0 and q·p ≥ max_F Σ μ_i f_i u_i, u_i the rational
// upper bounds of the speeds: p is nowhere inside a limit surface of F)? Exact.
bool slides_for_every(const Support& s, const Admissible& a, const Vec3q& p, const Vec3q& q);

// A twist that may separate p from U = ∪_F LS(f) (all in double; the caller checks it exactly): slides for every
// distribution iff q·p > h_U(q) = max_v h_{f_v}(q) for some q (v the vertices of F). On the plane q·p = 1 that is
// min max_v h_{f_v}(q) < 1, a convex problem in two variables (minimise_on_load_plane, sliding.h), stopped as soon as
// h_U < 1. `common`, if given, adds a power every distribution shares (support regions' [RG-3]). Nothing when p = 0
// or the doubles overflow.
std::optional<Vec3q> union_search(const Support& s, const std::vector<std::vector<Rational>>& v, const Vec3q& p,
                                  const Vec3q* start, const std::function<double(const double*)>& common = nullptr);

enum class Motion_over { sticks, slides, depends, undecided };
const char* motion_over_name(Motion_over m);

struct Motion_over_f {
  Motion_over motion = Motion_over::undecided;
  std::vector<Motion> per_vertex;                 // each vertex's own answer (decide_motion)
  std::vector<Motion_decision> decisions;         // … and how it was decided (the search's witness twist)
  std::optional<std::size_t> sticking_vertex, sliding_vertex;  // depends: witnesses among the vertices
  std::optional<Stick_witness> sticking;          // depends found by the LP (step 2)
  std::optional<Vec3q> separating_twist;          // slides (step 3)
  std::string decided_by;                         // "vertices", "lp", "twist", "minimax" or "none"
  // undecided: why, with the distance from a limit surface within which the load lies (relative, along its ray).
  std::string undecided_why;
};
// Precondition: some force unknown, at most kMaxEnumeratedUnknowns of them.
Motion_over_f decide_motion_over(const Support& s, const Admissible& a, const Vec3q& p, Mode mode, int sides);

}  // namespace wrenchkit
