// [LP-1] A small exact linear program in standard form, solved by the two-phase simplex method in exact
// rationals with Bland's rule (no cycling, so it terminates):
//
//   maximise c·x  subject to  A x = b,  x ≥ 0      (A: m × n, m small; any b)
//
// Answers infeasible, unbounded, or optimal with an optimal basic solution x (at most rank(A) nonzero
// entries) and an optimal dual y (A^T y ≥ c, b·y = c·x: the certificate of optimality; weak duality gives
// c·x' ≤ b·y for every feasible x'). Redundant rows (rank(A) < m) are found exactly and dropped from the
// basis (their dual value is 0). Exact: every pivot is a rational computation; O(m·n) per pivot.
// Used for the admissible distributions of a support (docs/theory-sliding.md §1–§3).
#pragma once

#include <cstddef>
#include <vector>

#include "exact/numbers/rational.h"

namespace wrenchkit {

struct Lp_result {
  enum class Status { optimal, infeasible, unbounded } status = Status::infeasible;
  std::vector<Rational> x;  // optimal: size n, a basic feasible solution
  std::vector<Rational> y;  // optimal: size m, A^T y ≥ c and b·y = c·x
  Rational value;           // optimal: c·x
  std::size_t pivots = 0;
};

// `a`: m rows of n entries each.
Lp_result maximise(const std::vector<std::vector<Rational>>& a, const std::vector<Rational>& b,
                   const std::vector<Rational>& c);

}  // namespace wrenchkit
