#include "exact/numbers/exact_lp.h"

#include <stdexcept>

namespace wrenchkit {

namespace {

using Row = std::vector<Rational>;

// Rows of [A | b] independent of the earlier ones (exact elimination), or nothing when a dependent row
// contradicts them (the system A x = b has no solution at all).
bool independent_rows(const std::vector<Row>& a, const Row& b, std::vector<std::size_t>& kept) {
  std::vector<Row> basis;   // reduced rows of [A | b]
  std::vector<std::size_t> pivot_col;
  const std::size_t n = a.empty() ? 0 : a[0].size();
  for (std::size_t i = 0; i < a.size(); ++i) {
    Row r = a[i];
    r.push_back(b[i]);
    for (std::size_t k = 0; k < basis.size(); ++k) {
      const std::size_t p = pivot_col[k];
      if (r[p] == 0) continue;
      const Rational f = r[p] / basis[k][p];
      for (std::size_t j = 0; j <= n; ++j) r[j] -= f * basis[k][j];
    }
    std::size_t p = 0;
    while (p < n && r[p] == 0) ++p;
    if (p == n) {
      if (r[n] != 0) return false;  // 0 = nonzero
      continue;                     // a redundant row
    }
    basis.push_back(std::move(r));
    pivot_col.push_back(p);
    kept.push_back(i);
  }
  return true;
}

// The square system M z = v (nonsingular), exactly.
Row solve(std::vector<Row> m, Row v) {
  const std::size_t r = v.size();
  for (std::size_t c = 0; c < r; ++c) {
    std::size_t p = c;
    while (p < r && m[p][c] == 0) ++p;
    if (p == r) throw std::logic_error("exact_lp: a singular basis");
    std::swap(m[p], m[c]);
    std::swap(v[p], v[c]);
    for (std::size_t i = 0; i < r; ++i) {
      if (i == c || m[i][c] == 0) continue;
      const Rational f = m[i][c] / m[c][c];
      for (std::size_t j = c; j < r; ++j) m[i][j] -= f * m[c][j];
      v[i] -= f * v[c];
    }
  }
  for (std::size_t i = 0; i < r; ++i) v[i] /= m[i][i];
  return v;
}

}  // namespace

Lp_result maximise(const std::vector<Row>& a, const Row& b, const Row& c) {
  Lp_result res;
  const std::size_t n = c.size();
  for (const Row& r : a)
    if (r.size() != n) throw std::invalid_argument("maximise: rows of different lengths");
  if (b.size() != a.size()) throw std::invalid_argument("maximise: b of another length");
  std::vector<std::size_t> kept;
  if (!independent_rows(a, b, kept)) return res;  // infeasible
  const std::size_t m = kept.size();
  // Tableau: m rows over n original and m artificial columns, then the right-hand side (≥ 0).
  const std::size_t width = n + m;
  std::vector<Row> t(m, Row(width + 1));
  for (std::size_t i = 0; i < m; ++i) {
    const bool flip = b[kept[i]] < 0;
    for (std::size_t j = 0; j < n; ++j) t[i][j] = flip ? Rational(-a[kept[i]][j]) : a[kept[i]][j];
    t[i][n + i] = 1;
    t[i][width] = flip ? Rational(-b[kept[i]]) : b[kept[i]];
  }
  std::vector<std::size_t> basis(m);
  for (std::size_t i = 0; i < m; ++i) basis[i] = n + i;

  // Maximises obj over the tableau from the current feasible basis, with columns < `allowed` entering.
  const auto run = [&](const Row& obj, std::size_t allowed) -> bool {
    for (;;) {
      // Reduced cost of column j: obj_j − Σ_i obj_{basis_i} t[i][j]; Bland: the first positive one enters.
      std::size_t enter = allowed;
      for (std::size_t j = 0; j < allowed && enter == allowed; ++j) {
        Rational d = obj[j];
        for (std::size_t i = 0; i < m; ++i)
          if (obj[basis[i]] != 0 && t[i][j] != 0) d -= obj[basis[i]] * t[i][j];
        if (d > 0) enter = j;
      }
      if (enter == allowed) return true;  // optimal
      std::size_t leave = m;
      Rational best;
      for (std::size_t i = 0; i < m; ++i) {
        if (t[i][enter] <= 0) continue;
        const Rational ratio = t[i][width] / t[i][enter];
        if (leave == m || ratio < best || (ratio == best && basis[i] < basis[leave])) {
          leave = i;
          best = ratio;
        }
      }
      if (leave == m) return false;  // unbounded
      const Rational p = t[leave][enter];
      for (Rational& x : t[leave]) x /= p;
      for (std::size_t i = 0; i < m; ++i) {
        if (i == leave || t[i][enter] == 0) continue;
        const Rational f = t[i][enter];
        for (std::size_t j = 0; j <= width; ++j)
          if (t[leave][j] != 0) t[i][j] -= f * t[leave][j];
      }
      basis[leave] = enter;
      ++res.pivots;
    }
  };

  // Phase 1: maximise −Σ artificials.
  Row phase1(width, Rational(0));
  for (std::size_t i = 0; i < m; ++i) phase1[n + i] = -1;
  run(phase1, width);
  for (std::size_t i = 0; i < m; ++i)
    if (basis[i] >= n && t[i][width] != 0) return res;  // infeasible
  // Artificials still basic (at zero) leave for an original column: the rows are independent, so one exists.
  for (std::size_t i = 0; i < m; ++i) {
    if (basis[i] < n) continue;
    std::size_t j = 0;
    while (j < n && t[i][j] == 0) ++j;
    if (j == n) throw std::logic_error("exact_lp: a dependent row survived");
    const Rational p = t[i][j];
    for (Rational& x : t[i]) x /= p;
    for (std::size_t k = 0; k < m; ++k) {
      if (k == i || t[k][j] == 0) continue;
      const Rational f = t[k][j];
      for (std::size_t l = 0; l <= width; ++l) t[k][l] -= f * t[i][l];
    }
    basis[i] = j;
    ++res.pivots;
  }
  // Phase 2: the objective over the original columns only.
  Row obj(width, Rational(0));
  for (std::size_t j = 0; j < n; ++j) obj[j] = c[j];
  if (!run(obj, n)) {
    res.status = Lp_result::Status::unbounded;
    return res;
  }
  res.status = Lp_result::Status::optimal;
  res.x.assign(n, Rational(0));
  for (std::size_t i = 0; i < m; ++i) res.x[basis[i]] = t[i][width];
  for (std::size_t j = 0; j < n; ++j) res.value += c[j] * res.x[j];
  // The dual from the basis over the kept rows (B^T y = c_B); dropped rows get 0.
  std::vector<Row> bt(m, Row(m));
  Row cb(m);
  for (std::size_t i = 0; i < m; ++i) {
    cb[i] = c[basis[i]];
    for (std::size_t k = 0; k < m; ++k) bt[i][k] = a[kept[k]][basis[i]];
  }
  const Row yk = m ? solve(bt, cb) : Row{};
  res.y.assign(a.size(), Rational(0));
  for (std::size_t k = 0; k < m; ++k) res.y[kept[k]] = yk[k];
  // Optimality, checked exactly: A^T y ≥ c and b·y = c·x.
  Rational by;
  for (std::size_t i = 0; i < a.size(); ++i) by += b[i] * res.y[i];
  if (by != res.value) throw std::logic_error("exact_lp: dual value differs");
  for (std::size_t j = 0; j < n; ++j) {
    Rational s;
    for (std::size_t i = 0; i < a.size(); ++i) s += a[i][j] * res.y[i];
    if (s < c[j]) throw std::logic_error("exact_lp: dual infeasible");
  }
  return res;
}

}  // namespace wrenchkit
