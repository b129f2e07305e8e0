// [FC-4] Exact cone membership with certificates both ways (theory.md §3, item 4–5).
//
// Decides whether x ∈ pos{g_0 … g_{n-1}} ⊂ R³ by phase 1 of the simplex method on
// {μ ≥ 0 : Σ μ_i g_i = x} in exact rationals, with Bland's rule (no cycling, so it terminates).
// Feasible: returns a basic solution μ (at most 3 nonzero weights — Carathéodory). Infeasible:
// returns a Farkas twist z with ⟨z, g_i⟩ ≥ 0 for every i and ⟨z, x⟩ < 0 (a separating twist).
// Cost: O(n) rational operations per pivot; a handful of pivots in practice.
#pragma once

#include <array>
#include <vector>

#include "exact/statics/generators.h"
#include "exact/io/scene.h"

namespace wrenchkit {

struct Cone_membership {
  bool member = false;
  std::vector<Rational> weights;   // member: size n, ≥ 0, Σ weights_i g_i = x
  std::array<Rational, 3> twist;   // not member: ⟨twist, g_i⟩ ≥ 0 ∀i, ⟨twist, x⟩ < 0
};

// The rational tableau above: the reference the integer version below is tested against.
Cone_membership cone_membership(const std::vector<Vec3q>& gens, const Vec3q& x);

// [FC-5] The same phase 1, with the same pivots (Bland's rule), in integers: the revised simplex in
// Cramer form. Columns are rows `columns` of an exact kernel (positive integer multiples of the
// generators), the target is x = −Σ_{k ∈ negated} row_k (closure: minus an independent triple;
// equilibrium: minus the load). Every quantity the tableau holds is a ratio of integer
// determinants with the basis determinant as denominator, so each decision is the sign of an integer:
// fixed width (__int128, the 192-bit Int192) when every entry is below 2^62 and the target's below
// 2^63, GMP integers otherwise. No rational arithmetic.
struct Integer_cone_membership {
  bool member = false;
  // member: weight of columns[k] is numerators[k] / denominator (≥ 0, at most three nonzero), with
  // Σ weights · row = x exactly.
  std::vector<Integer> numerators;
  Integer denominator;
  // not member: ⟨twist, row_j⟩ ≥ 0 for every column, ⟨twist, x⟩ < 0; primitive integers.
  std::array<Integer, 3> twist;
  std::size_t pivots = 0;
  bool fixed_width = false;  // decided in fixed width (for tests)
};

// `fixed_width` false: GMP integers whatever the sizes (tests compare both).
Integer_cone_membership cone_membership(const Exact_kernel& kernel, const std::vector<std::size_t>& columns,
                                        const std::vector<std::size_t>& negated, bool fixed_width = true);

// [FC-2] [FC-5] Four rows that positively span R³ have one combination Σ λ_i·row_i = 0 up to scale (the
// null space of four vectors of rank 3 is a line): λ_i = (−1)^i·det(the other three rows) — the expansion
// of a 4×4 determinant with a repeated column — and, as some combination is strictly positive, all λ_i
// have one sign, made positive here. So the positive certificate of four generators needs no LP: scaled
// to coprime integers it is the LP's (tests/certificate_lp_test.cpp). Fixed width only (rows at most
// 2^62 − 1, so every λ_i < 2^189); false otherwise, or when the signs differ (not positively spanning).
bool four_spanning_weights(const Exact_kernel& kernel, const std::size_t (&rows)[4], std::array<Integer, 4>& lambda);

}  // namespace wrenchkit
