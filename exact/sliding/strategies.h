// The strategies behind decide_motion and decide_hold (exact/sliding/motion.h, exact/fixture/hold.h): how a verdict is
// found, and how each witness is made exact. No question of their own: every answer a user sees comes from
// decide_motion or decide_hold. Tests and the stress report call some of them alone, to measure one strategy.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "exact/numbers/exact_lp.h"
#include "exact/sliding/motion.h"
#include "exact/sliding/sliding.h"

namespace wrenchkit {

// ---- Points, every force given: the verdict alone [LS-3] [FL-7] [SL-6] ---------------------------------------------
//   exact  — the polygons: g_in(p) < 1 sticks, g_out(p) ≥ 1 slides, else undecided (refine N);
//   hybrid — the float twin's certified search on the true limit surface first (a tenth of its budget, 20 000
//            twists), the polygons when it abstains, then Newton in multiple precision [SL-6] (its twist kept when it
//            slides), then the search's full budget (a load near a facet);
//   float  — the search alone.
// A flat limit surface (dimension < 3) has no interior: every load slides ("flat"). The polytopes are built here
// when the search is undecided, unless the caller passes them.
struct Points_verdict {
  Motion motion = Motion::undecided;
  Decided_by decided_by = Decided_by::none;  // float_search, polygons, newton, flat, none
  std::size_t cells = 0;                     // twists the search evaluated
  std::array<double, 3> witness{};           // slides by the search: a twist with h(q) ≤ q·p
  std::optional<Vec3q> exact_witness;        // slides by Newton: a primitive integer twist with h(q) < q·p
  std::optional<std::array<double, 3>> proposal;  // undecided: Newton's last minimiser (near the load's normal)
};
Points_verdict points_verdict(const Polygonal_ls& model, const Vec3q& load, Mode mode,
                              const Ls_polytope* inner = nullptr, const Ls_polytope* outer = nullptr);
// The same from the merged support alone: the polygons (N = sides) are set up only when the search cannot tell.
Points_verdict points_verdict(const Ls_support& support, const Vec3q& load, Mode mode, int sides);

// ---- Witnesses of one distribution f [SL-4] [SL-6] -------------------------------------------------------------------
// Rational upper bounds of the speeds |v_i(q)| of every support point (square-root brackets of `bits` bits).
std::vector<Rational> speed_bounds(const Support& s, const Vec3q& q, int bits = 80);

// The slide witness of q (≠ 0) for f when q·p > Σ μ_i f_i u_i (p outside the limit surface; `strict` false: ≥, on or
// outside); nothing otherwise. The speeds are bounded to 80 bits, and when that does not prove it and q has long
// numbers (Newton's twists), to 2·b + 64 bits, b the longest component's bits. Points only (no region blocks).
std::optional<Slide_witness> slide_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                           const Vec3q& q, bool strict = true);

// [SL-1] The witness that p is ON the limit surface of f, from the twist q (≠ 0): every point with friction moves at an
// exactly rational speed u_i = |v_i(q)|, q·p = Σ μ_i f_i u_i exactly, and p is in the face of LS(f) that q supports —
// the forces μ_i f_i v_i/u_i of the moving points, plus at the points at rest (q's rotation centre) one force g in
// their closed disc with moment c × g. Nothing otherwise. Points only.
std::optional<Impending_witness> impending_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                                   const Vec3q& q);

// Support forces and non-negative multiples of the `cone`'s wrenches c_j that sum to p exactly:
// Σ_i (g_i, r_i × g_i) + Σ_j weights_j c_j = p with g_i·g_i < (μ_i f_i)² (g_i = 0 where μ_i f_i = 0). With an empty
// cone, a stick witness (friction at two distinct points is required, as for it); with the contacts' wrench
// generators, the support's part and the contacts' part of a hold witness. Found by Newton's method in double on a
// smoothed dual, then made exact by one rational 3×3 solve and checked exactly (SL-4); nothing when it does not
// verify. `probe`: first whether p itself is reachable (a Newton run at σ → 1); when not, nothing, and `escape` (if
// given) gets the run's last dual iterate λ, along which the smoothed dual decreases without bound: λ·p > h_f(λ) and
// λ·c_j ≤ 0 to first order (a candidate separating twist). `short_numbers`: the exact round's weights rounded to a
// few more bits than the slack needs (shorter certificates).
struct Support_witness {
  std::vector<Vec2> forces;       // g_i, one per support point
  std::vector<Rational> weights;  // one per cone wrench, ≥ 0
};
std::optional<Support_witness> smoothed_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                                const std::vector<Vec3q>& cone, bool probe,
                                                std::array<double, 3>* escape, bool short_numbers);
// The smoothed witness alone as a stick witness (the support's points may be any discrete distribution, e.g. a
// region's cells as points).
std::optional<Stick_witness> smoothed_stick_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p);

// [SL-6] The precise witnesses of f (exact/sliding/precise_motion.h, the points with ρ_i = μ_i f_i): a stick witness,
// or a slide witness (strict: Σ μ_i f_i u_i < q·p), or neither.
struct Precise_witness {
  std::optional<Stick_witness> sticks;
  std::optional<Slide_witness> slides;
};
Precise_witness precise_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p);

// A stick witness for f: the smoothed witness, else the precise one, else the exact LP on inscribed N-gons,
// N = sides, 2·sides, … up to 256 sides, as long as the LP stays within kMaxStickWitnessColumns columns.
constexpr std::size_t kMaxStickWitnessColumns = 2048;
std::optional<Stick_witness> stick_witness_refined(const Support& s, const Admissible& a, const Vec3q& p, int sides,
                                                   const std::vector<Rational>& f);

// ---- The friction LP [LP-1] ----------------------------------------------------------------------------------------
// The one exact LP on the support's friction discs replaced by inscribed polygons (|Σ_j λ_ij u_ij| ≤ Σ_j λ_ij when
// every u_ij is a rational unit vector): columns the wrenches of `cone` (weights ≥ 0), then per listed point its
// polygon's λ_ij, the points' slacks, the goal's columns, and with a free distribution the unknown forces; rows the
// three wrench rows, one disc row per listed point (Σ_j λ_ij + s_i (+ t) = μ_i f_i), the goal's, and F's three rows.
//   margin — Σ_j λ_ij (u_ij, r_i × u_ij) + cone = load, the common margin t (in each disc row with μ_i f_i > 0, f
//            fixed) maximised: t > 0 puts every force strictly inside its disc (the stick witness);
//   scale  — cone + Σ λ_ij (u_ij, r_i × u_ij) + t·load = rhs with t ≤ 1 maximised: with rhs 0, t = 1 balances the load
//            (a hold); the dual of the wrench rows is then a candidate motion (exact/fixture/hold.h).
// `fixed` null: the distribution is free in F (its unknown forces are columns, F's rows added).
struct Friction_lp {
  enum class Goal { margin, scale };
  Goal goal = Goal::margin;
  const Support* support = nullptr;
  const Admissible* admissible = nullptr;
  const std::vector<Rational>* fixed = nullptr;
  Vec3q load;
  Vec3q rhs{};  // scale: the wrench rows' right-hand side
  std::vector<Vec3q> cone;
  std::vector<std::size_t> points;            // the points with columns, in order
  std::vector<std::vector<Vec2>> directions;  // each listed point's u_ij
};
struct Friction_lp_solution {
  Lp_result lp;
  Rational goal;                        // t
  std::vector<Vec2> forces;             // per support point: Σ_j λ_ij u_ij (0 for unlisted points)
  std::vector<Rational> distribution;   // per support point
  std::vector<Rational> cone_weights;   // per cone wrench
};
// Nothing when the LP is not feasible and bounded.
std::optional<Friction_lp_solution> solve(const Friction_lp& problem);

// ---- The polygon rounds [LP-1]: the friction LP on inscribed polygons refined where friction acts -----------------
// Each disc's inscribed polygon: the 16-gon (φ_j = 2π(j + ½)/16), the four axes (a load that friction carries with
// forces along an axis — a translation along one, a rotation about a point on one — is a polygon point), `common`
// (the exact unit velocities of candidate twists: friction saturated along a twist's velocities is then a polygon
// point, and the LP finds the exact witness), and each point's own refinements near where its force goes.
struct Polygon_rounds {
  const Support* support = nullptr;
  const Admissible* admissible = nullptr;
  const std::vector<Rational>* fixed = nullptr;  // null: the distribution free in F
  std::vector<Vec3q> cone;                       // the contacts' generators (a hold), or none
  std::vector<Vec2> common;
  std::vector<std::vector<Vec2>> own;  // per support point
  // The scale LP: the largest t ≤ 1 with cone + Σ_ij λ_ij (u_ij, r_i × u_ij) + t·load = rhs. With rhs 0, t = 1 says
  // −load is in W ⊕ LS_in(f) (the primal is the witness); t < 1: the dual y of the wrench rows has y·load > h_in(y)
  // and ⟨y, c⟩ ≥ 0 on the cone, a candidate twist.
  Friction_lp_solution scale(const Vec3q& load, const Vec3q& rhs = {}) const;
  // f fixed, no cone: a stick witness strictly inside the polygons (the largest common margin of the discs, > 0) with
  // friction at two distinct points; nothing otherwise.
  std::optional<Stick_witness> margin(const Vec3q& p) const;
  // After round `round` with dual twist τ: τ's exact unit velocities join `common`, and each point's polygon is refined
  // (δ = 2^-(4+3·round)) about the direction against its velocity under τ, where its force goes at the optimum, and
  // about the round's own `forces` (τ is not unique where LS is not strictly convex; τ = 0 once the load is held).
  void refine(const Vec3q& twist, int round, const std::vector<Vec2>& forces = {});
};
// The exact unit directions ±v_i(t)/|v_i(t)| of the support points' velocities under t where |v_i(t)| is rational.
void add_exact_directions(const Support& s, const Vec3q& t, std::vector<Vec2>& out);
// Rounds of r.scale(load) then r.refine (kPolygonRounds, to about 10^-11 of the discs); `decide` gets each round's
// solution and says whether it decided. Returns the last round's t; `rounds` counts the rounds run.
constexpr int kPolygonRounds = 6;
Rational polygon_rounds(Polygon_rounds& r, const Vec3q& load,
                        const std::function<bool(const Friction_lp_solution&)>& decide, int& rounds);

// A stick witness on the inscribed N-gons (N = sides) for the distribution `fixed` (the margin goal): nothing when p
// is not strictly inside LS_in^N(f) or friction acts at fewer than two distinct points. With `fixed` null: some
// distribution of F with p in LS_in^N(f) (closed; the caller confirms it strictly with that f fixed). Throws
// std::length_error beyond kMaxStickWitnessColumns columns.
std::optional<Stick_witness> stick_witness(const Support& s, const Admissible& a, const Vec3q& p, int sides,
                                           const std::vector<Rational>* fixed = nullptr);

// ---- Over F [SL-3] [RG-3] -------------------------------------------------------------------------------------------
// Does q prove that p slides for every distribution of F (q ≠ 0 and q·p ≥ max_F Σ μ_i f_i u_i, the LP over F with its
// dual; `strict`: q·p > …, a hold's failing motion)? Points only; exact. The witness (distribution empty, `dual` set)
// or nothing.
std::optional<Slide_witness> slides_for_every(const Support& s, const Admissible& a, const Vec3q& p, const Vec3q& q,
                                              bool strict = false);

// A twist that may separate p from U = ∪_F LS(f) (all in double; the caller checks it exactly): min over the plane
// q·p = 1 of max_v h_{f_v}(q) < 1 (compass search, sliding.h), stopped as soon as it is below 1. `common`, if given,
// adds a power every distribution shares (support regions'). Nothing when p = 0 or the doubles overflow.
std::optional<Vec3q> union_search(const Support& s, const std::vector<std::vector<Rational>>& v, const Vec3q& p,
                                  const Vec3q* start, const std::function<double(const double*)>& common = nullptr);
// The union's minimax min_{q·p=1} max_v h_{f_v}(q) by a log barrier in double (hybrid only; proofs/notes/SL-6 §6): its
// minimiser q (a separating twist when t < 1) and the multipliers λ_v (a distribution Σ λ_v f_v that holds p when
// t > 1). Proposals only.
struct Union_minimax {
  bool found = false;
  std::array<double, 3> q{};
  double t = 0;
  std::vector<double> lambda;  // one per vertex, ≥ 0, sum ≈ 1
};
Union_minimax union_minimax(const Support& s, const std::vector<std::vector<Rational>>& v, const Vec3q& p);

// ---- Regions, every point force given [RG-1] -----------------------------------------------------------------------
// The twist minimising the true power on the plane q·p = 1 (the closed form in double) proposes; sticks: forces on
// the regions' cells (m² per coarse triangle) strictly inside their discs, by the smoothed witness on the cells as
// points; slides: a twist with the points' speed bounds and each region's slide block refined until the bound is at
// most q·p. Hybrid and exact alike (the doubles only propose).
constexpr std::size_t kMaxRegionCells = 20000;       // slide: the adaptive cells of every region together
constexpr std::size_t kMaxRegionStickCells = 5000;   // stick: m² cells per coarse triangle, m = 1, 2, 4, …
Motion_answer decide_on_regions(const Support& s, const Vec3q& load);

// ---- Scaled frames [WORK] ------------------------------------------------------------------------------------------
// A similarity r ↦ k·r (k > 0 rational) maps the support's points, regions (scaled_region: each pressure divided by k²,
// the same forces) and pressure centre; a load (f, m) is (f, k·m) there. A witness in that frame is one in the scene's:
// forces, distributions and speed bounds are unchanged, cells scale back by 1/k, a twist's rate and the LP dual's
// (yx, yy) by k (the same velocities at corresponding points). unscale maps every witness of an answer back.
Support scaled_support(const Support& s, const Rational& k);
// Each coordinate of the support's points and regions' rings (the lengths both frames look at), in order.
template <class F>
void for_each_coordinate(const Support& s, F&& f) {
  for (const Support_point& pt : s.points) f(pt.at.x), f(pt.at.y);
  for (const Support_region& r : s.regions)
    for (const auto& ring : r.rings)
      for (const Vec2& v : ring) f(v.x), f(v.y);
}
void unscale(Motion_answer& a, const Rational& k);

}  // namespace wrenchkit
