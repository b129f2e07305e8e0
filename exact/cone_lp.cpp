#include "exact/cone_lp.h"

#include <stdexcept>

namespace wrenchkit {

Cone_membership cone_membership(const std::vector<Wrench>& gens, const Wrench& x) {
  const std::size_t n = gens.size();
  const std::size_t cols = n + 3;  // originals, then artificials a_0 … a_2
  // Tableau rows r = 0 … 2: [A' | I | b'] with rows negated where x_r < 0 so that b' ≥ 0.
  std::array<std::vector<Rational>, 3> T;
  std::array<Rational, 3> b;
  std::array<int, 3> flip{};
  const Rational xs[3] = {x.fx, x.fy, x.m};
  for (int r = 0; r < 3; ++r) {
    flip[r] = xs[r] < 0 ? -1 : 1;
    T[r].assign(cols, Rational(0));
    for (std::size_t j = 0; j < n; ++j) {
      const Rational& v = r == 0 ? gens[j].fx : (r == 1 ? gens[j].fy : gens[j].m);
      T[r][j] = flip[r] < 0 ? Rational(-v) : v;
    }
    T[r][n + r] = 1;
    b[r] = flip[r] < 0 ? Rational(-xs[r]) : xs[r];
  }
  std::array<std::size_t, 3> basic = {n, n + 1, n + 2};
  // Reduced costs of the phase-1 objective Σ a_r: c̄_j = c_j − Σ_r T_rj over basic artificials.
  std::vector<Rational> cbar(cols, Rational(0));
  for (std::size_t j = 0; j < n; ++j) cbar[j] = -(T[0][j] + T[1][j] + T[2][j]);

  for (;;) {
    std::size_t enter = cols;
    for (std::size_t j = 0; j < cols; ++j)
      if (cbar[j] < 0) {
        enter = j;  // Bland: smallest index
        break;
      }
    if (enter == cols) break;
    int leave = -1;
    Rational best;
    for (int r = 0; r < 3; ++r) {
      if (T[r][enter] <= 0) continue;
      Rational ratio = b[r] / T[r][enter];
      if (leave < 0 || ratio < best || (ratio == best && basic[r] < basic[leave])) {
        leave = r;
        best = ratio;
      }
    }
    if (leave < 0) throw std::logic_error("cone_membership: unbounded phase 1 (impossible)");
    const Rational piv = T[leave][enter];
    for (std::size_t j = 0; j < cols; ++j) T[leave][j] /= piv;
    b[leave] /= piv;
    for (int r = 0; r < 3; ++r) {
      if (r == leave || T[r][enter] == 0) continue;
      const Rational f = T[r][enter];
      for (std::size_t j = 0; j < cols; ++j)
        if (T[leave][j] != 0) T[r][j] -= f * T[leave][j];
      b[r] -= f * b[leave];
    }
    const Rational f = cbar[enter];
    for (std::size_t j = 0; j < cols; ++j)
      if (T[leave][j] != 0) cbar[j] -= f * T[leave][j];
    basic[leave] = enter;
  }

  Cone_membership out;
  Rational infeasibility = 0;
  for (int r = 0; r < 3; ++r)
    if (basic[r] >= n) infeasibility += b[r];
  if (infeasibility == 0) {
    out.member = true;
    out.weights.assign(n, Rational(0));
    for (int r = 0; r < 3; ++r)
      if (basic[r] < n) out.weights[basic[r]] = b[r];
    return out;
  }
  // Simplex multipliers y_r = c_{a_r} − c̄_{a_r} = 1 − c̄_{n+r}; optimality gives y·A'_j ≤ 0 and
  // y·b' > 0, so z = −(flip ∘ y) has ⟨z, g_j⟩ ≥ 0 and ⟨z, x⟩ < 0.
  for (int r = 0; r < 3; ++r) {
    const Rational y = 1 - cbar[n + r];
    out.twist[r] = flip[r] < 0 ? y : Rational(-y);
  }
  return out;
}

}  // namespace wrenchkit
