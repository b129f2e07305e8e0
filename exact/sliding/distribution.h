// [SL-1] The admissible distributions of a support (docs/theory-sliding.md §1):
//
//   F = { f ≥ 0 : f_i = the given force where given, Σ f_i + Σ_R W_R = W, Σ f_i r_i + Σ_R ∫_R r p = W c }
//
// (support regions have a known pressure: W' and M' below subtract their forces and moments with the given ones;
// their friction itself is the regions' path, exact/sliding/region_sliding.h)
//
// a polytope cut by three equality rows in the unknown forces. read_scene has checked that F is not empty
// (exact/io/support_check.h). Everything here is exact.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "exact/io/scene.h"

namespace wrenchkit {

struct Admissible {
  std::vector<std::size_t> unknown;  // the points whose force is not given, in input order
  std::vector<Rational> given;       // per point: its given force, 0 where unknown
  Rational rest;                     // W' = W − Σ given − Σ_R W_R
  Vec2 rest_moment;                  // M' = W c − Σ given f_i r_i − Σ_R ∫_R r p dA
  bool known() const { return unknown.empty(); }
  // The distribution with `forces` (one per unknown point, in order) put in place.
  std::vector<Rational> with(const std::vector<Rational>& forces) const;
  // Is f (one force per point) in F?
  bool contains(const Support& s, const std::vector<Rational>& f) const;
};

// Precondition: the scene has a support and read_scene accepted it.
Admissible admissible_set(const Scene& scene);

// The vertices of F (its extreme distributions), each once, in a fixed order: the basic feasible
// solutions of the three rows over 1, 2 or 3 unknown forces with independent columns (1, x_i, y_i).
// O(C(k,3)) exact 3×3 solves for k unknown points; one distribution when every force is given.
// At most kMaxEnumeratedUnknowns unknown points (C(60,3) = 34 220 solves, at most 60 + 1 770 + 34 220 vertices of
// k rationals each): beyond, it throws std::length_error before any work (callers check first and say why).
constexpr std::size_t kMaxEnumeratedUnknowns = 60;
std::vector<std::vector<Rational>> vertices(const Support& s, const Admissible& a);

// max over F of Σ_i coef_i f_i (one coefficient per point) [LP-1]: an optimal distribution (a vertex of F)
// and the dual (y0, yx, yy) of the three rows: coef_i ≤ y0 + yx x_i + yy y_i for every unknown i, and the
// maximum is Σ_given coef_i f_i + y0 W' + yx M'_x + yy M'_y.
struct F_optimum {
  std::vector<Rational> distribution;
  Rational value;
  std::array<Rational, 3> dual;
};
F_optimum maximise_over(const Support& s, const Admissible& a, const std::vector<Rational>& coef);

// [WORK] The work budget's charge for deciding the given distributions of the support one by one (each an extreme
// distribution's full decision, its witness and its certificate part): kPerDistribution × points × size units, size the
// largest of the points' numbers and of the distributions' forces (exact/numbers/work_budget.h); throws Work_exhausted
// before any of them is decided when the request cannot afford them all.
void charge_distributions(const Support& s, const std::vector<std::vector<Rational>>& distributions);

}  // namespace wrenchkit

namespace wrenchkit {

// [SL-2] The frictional power of the twist q over F: h_f(q) = Σ_i μ_i f_i |v_i(q)| is linear in f, so its
// range over F is [min_F, max_F], attained at vertices (docs/theory-sliding.md §2). The speeds |v_i| are
// square roots: each is bracketed by rationals l_i ≤ |v_i| ≤ u_i (80 bits), and the LPs over F with the
// coefficients μ_i l_i and μ_i u_i give lower ≤ min_F h_f(q) and max_F h_f(q) ≤ upper, with the minimising
// and maximising distributions. Exact when every speed is rational. Precondition: q ≠ 0.
struct Power_range {
  Rational lower, upper;
  std::vector<Rational> min_distribution, max_distribution;
};
Power_range power_range(const Support& s, const Admissible& a, const std::array<Rational, 3>& q);

}  // namespace wrenchkit
