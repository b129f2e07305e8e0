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

#include "exact/scene.h"

namespace wrenchkit {

struct Cone_membership {
  bool member = false;
  std::vector<Rational> weights;   // member: size n, ≥ 0, Σ weights_i g_i = x
  std::array<Rational, 3> twist;   // not member: ⟨twist, g_i⟩ ≥ 0 ∀i, ⟨twist, x⟩ < 0
};

Cone_membership cone_membership(const std::vector<Wrench>& gens, const Wrench& x);

}  // namespace wrenchkit
