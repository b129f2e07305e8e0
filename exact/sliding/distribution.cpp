#include "exact/sliding/distribution.h"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

#include "exact/io/support_check.h"
#include "exact/numbers/exact_lp.h"
#include "exact/numbers/work_budget.h"

namespace wrenchkit {

std::vector<Rational> Admissible::with(const std::vector<Rational>& forces) const {
  if (forces.size() != unknown.size()) throw std::invalid_argument("Admissible::with: one force per unknown point");
  std::vector<Rational> f = given;
  for (std::size_t k = 0; k < unknown.size(); ++k) f[unknown[k]] = forces[k];
  return f;
}

bool Admissible::contains(const Support& s, const std::vector<Rational>& f) const {
  if (f.size() != s.points.size()) return false;
  Rational w, mx, my;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f[i] < 0) return false;
    if (s.points[i].force && f[i] != *s.points[i].force) return false;
    if (s.points[i].force) continue;
    w += f[i];
    mx += f[i] * s.points[i].at.x;
    my += f[i] * s.points[i].at.y;
  }
  return w == rest && mx == rest_moment.x && my == rest_moment.y;
}

Admissible admissible_set(const Scene& scene) {
  if (!scene.support) throw std::invalid_argument("admissible_set: no support");
  const Support& s = *scene.support;
  Admissible a;
  a.given.assign(s.points.size(), Rational(0));
  Rational sum;
  Vec2 moment;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Support_point& p = s.points[i];
    if (!p.force) {
      a.unknown.push_back(i);
      continue;
    }
    a.given[i] = *p.force;
  }
  if (a.unknown.empty()) return a;  // F = {given}: the rest below is not needed
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Support_point& p = s.points[i];
    if (!p.force) continue;
    sum += *p.force;
    moment.x += *p.force * p.at.x;
    moment.y += *p.force * p.at.y;
  }
  for (const Support_region& r : s.regions) {  // known pressure: its force and moment count as given
    sum += r.total;
    moment.x += r.moment.x;
    moment.y += r.moment.y;
  }
  const std::optional<Vec2> c = pressure_center_of(scene);
  const std::optional<Rational> weight = support_weight_of(scene);
  if (!weight || !c) throw std::invalid_argument("admissible_set: a scene read_scene would refuse");
  a.rest = *weight - sum;
  a.rest_moment = {*weight * c->x - moment.x, *weight * c->y - moment.y};
  return a;
}

namespace {

// The columns (1, x_i, y_i) of the unknown points and the right-hand side (W', M').
struct Rows {
  std::vector<std::array<Rational, 3>> col;
  std::array<Rational, 3> rhs;
};

Rows rows_of(const Support& s, const Admissible& a) {
  Rows r;
  for (std::size_t i : a.unknown) r.col.push_back({Rational(1), s.points[i].at.x, s.points[i].at.y});
  r.rhs = {a.rest, a.rest_moment.x, a.rest_moment.y};
  return r;
}

// Solves Σ_{j∈B} z_j col_j = rhs for the columns B (1 to 3 of them) by least-squares-free exact elimination
// over the three rows; false when the columns are dependent or the system has no solution.
bool solve_basis(const Rows& r, const std::vector<std::size_t>& B, std::vector<Rational>& z) {
  const std::size_t m = B.size();
  // Augmented 3 × (m + 1) matrix, eliminated to reduced row echelon form.
  std::array<std::array<Rational, 4>, 3> t;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < m; ++j) t[i][j] = r.col[B[j]][i];
    t[i][m] = r.rhs[i];
  }
  std::size_t row = 0;
  for (std::size_t j = 0; j < m; ++j) {
    std::size_t p = row;
    while (p < 3 && t[p][j] == 0) ++p;
    if (p == 3) return false;  // dependent columns
    std::swap(t[p], t[row]);
    for (std::size_t i = 0; i < 3; ++i) {
      if (i == row || t[i][j] == 0) continue;
      const Rational f = t[i][j] / t[row][j];
      for (std::size_t k = j; k <= m; ++k) t[i][k] -= f * t[row][k];
    }
    ++row;
  }
  for (std::size_t i = row; i < 3; ++i)
    if (t[i][m] != 0) return false;  // inconsistent
  z.assign(m, Rational(0));
  for (std::size_t j = 0; j < m; ++j) z[j] = t[j][m] / t[j][j];
  return true;
}

}  // namespace

std::vector<std::vector<Rational>> vertices(const Support& s, const Admissible& a) {
  if (a.known()) return {a.given};
  if (a.unknown.size() > kMaxEnumeratedUnknowns)
    throw std::length_error("vertices: " + std::to_string(a.unknown.size()) + " unknown forces, more than " +
                            std::to_string(kMaxEnumeratedUnknowns));
  const Rows r = rows_of(s, a);
  const std::size_t k = a.unknown.size();
  {  // [WORK] one unit per candidate basis, times the size of the rows' numbers
    std::size_t size = 1;
    for (const auto& col : r.col)
      for (const Rational& x : col) size = std::max(size, Work::size(x));
    for (const Rational& x : r.rhs) size = std::max(size, Work::size(x));
    const std::size_t bases = k + k * (k - 1) / 2 + k * (k - 1) * (k - 2) / 6;
    Work::charge(Work::times(bases, size), "enumerating the extreme distributions of the " + std::to_string(k) +
                                               " support forces not given (" + std::to_string(bases) +
                                               " candidate bases)");
  }
  std::vector<std::vector<Rational>> out;
  std::set<std::vector<std::pair<std::size_t, Rational>>> seen;  // each vertex's nonzero unknown forces, once
  const auto consider = [&](const std::vector<std::size_t>& B) {
    std::vector<Rational> z;
    if (!solve_basis(r, B, z)) return;
    for (const Rational& x : z)
      if (x < 0) return;
    std::vector<std::pair<std::size_t, Rational>> nonzero;
    for (std::size_t j = 0; j < B.size(); ++j)
      if (z[j] != 0) nonzero.emplace_back(B[j], z[j]);
    std::sort(nonzero.begin(), nonzero.end());
    if (!seen.insert(nonzero).second) return;
    std::vector<Rational> u(k, Rational(0));
    for (std::size_t j = 0; j < B.size(); ++j) u[B[j]] = z[j];
    out.push_back(a.with(u));
  };
  // The rank of the columns decides the basis size: a vertex has at most rank-many nonzero unknown forces,
  // and every basic solution of a smaller support is also reached as a degenerate basis of full size, except
  // when the rank itself is smaller; so try every size up to 3 (the zero distribution when W' = 0).
  if (r.rhs[0] == 0 && r.rhs[1] == 0 && r.rhs[2] == 0) return {a.with(std::vector<Rational>(k, Rational(0)))};
  for (std::size_t i = 0; i < k; ++i) consider({i});
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = i + 1; j < k; ++j) consider({i, j});
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = i + 1; j < k; ++j)
      for (std::size_t l = j + 1; l < k; ++l) consider({i, j, l});
  return out;
}

void charge_distributions(const Support& s, const std::vector<std::vector<Rational>>& distributions) {
  std::size_t size = 1;
  for (const Support_point& p : s.points) {
    size = std::max({size, Work::size(p.at.x), Work::size(p.at.y)});
    if (p.force) size = std::max(size, Work::size(*p.force));
  }
  for (const std::vector<Rational>& f : distributions)
    for (const Rational& x : f) size = std::max(size, Work::size(x));
  std::size_t edges = 0;
  for (const Support_region& g : s.regions)
    for (const std::vector<Vec2>& ring : g.rings) edges += ring.size();
  const std::size_t n = distributions.size(), k = s.points.size() + Work::times(kPerRegionEdge, edges);
  Work::charge(Work::times(Work::times(n, kPerDistribution), Work::times(k, size)),
               "deciding each of the " + std::to_string(n) + " extreme distributions of the support (" +
                   std::to_string(s.points.size()) + " points" +
                   (edges ? ", regions of " + std::to_string(edges) + " edges" : "") +
                   (size > 1 ? ", numbers of size " + std::to_string(size) : "") + ")");
}

F_optimum maximise_over(const Support& s, const Admissible& a, const std::vector<Rational>& coef) {
  if (coef.size() != s.points.size()) throw std::invalid_argument("maximise_over: one coefficient per point");
  F_optimum o;
  Rational fixed;
  for (std::size_t i = 0; i < coef.size(); ++i) fixed += coef[i] * a.given[i];
  if (a.known()) {
    o.distribution = a.given;
    o.value = fixed;
    return o;
  }
  const Rows r = rows_of(s, a);
  std::vector<std::vector<Rational>> A(3, std::vector<Rational>(a.unknown.size()));
  std::vector<Rational> c(a.unknown.size());
  for (std::size_t j = 0; j < a.unknown.size(); ++j) {
    for (std::size_t i = 0; i < 3; ++i) A[i][j] = r.col[j][i];
    c[j] = coef[a.unknown[j]];
  }
  const Lp_result lp = maximise(A, {r.rhs[0], r.rhs[1], r.rhs[2]}, c);
  if (lp.status != Lp_result::Status::optimal) throw std::logic_error("maximise_over: F is empty or unbounded");
  o.distribution = a.with(lp.x);
  o.value = fixed + lp.value;
  o.dual = {lp.y[0], lp.y[1], lp.y[2]};
  return o;
}

}  // namespace wrenchkit

#include "exact/sliding/sliding.h"

namespace wrenchkit {

Power_range power_range(const Support& s, const Admissible& a, const std::array<Rational, 3>& q) {
  if (q[0] == 0 && q[1] == 0 && q[2] == 0) throw std::invalid_argument("power_range: zero twist");
  std::vector<Rational> lo(s.points.size()), hi(s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Support_point& p = s.points[i];
    const Rational mu = s.mu_of(p);
    const auto [l, u] = sqrt_bracket(speed_squared(q, p.at));
    lo[i] = -(mu * l);  // the minimum of Σ μ l f is minus the maximum of Σ −μ l f
    hi[i] = mu * u;
  }
  Power_range r;
  const F_optimum low = maximise_over(s, a, lo), high = maximise_over(s, a, hi);
  r.lower = -low.value;
  r.min_distribution = low.distribution;
  r.upper = high.value;
  r.max_distribution = high.distribution;
  return r;
}

}  // namespace wrenchkit
