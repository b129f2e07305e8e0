// [LP-1] The one friction-polygon LP (exact/sliding/strategies.h): the stick witness on inscribed N-gons, and the
// hold's LP on refined inscribed polygons with the contacts' cone (exact/fixture/hold.cpp) — one builder, two goals.
#include <algorithm>
#include <stdexcept>
#include <string>


#include "exact/sliding/strategies.h"

namespace wrenchkit {

std::optional<Friction_lp_solution> solve(const Friction_lp& q) {
  const Support& s = *q.support;
  const Admissible& a = *q.admissible;
  const bool free_f = !q.fixed && !a.known();
  const std::vector<Rational>& f0 = q.fixed ? *q.fixed : a.given;
  const bool margin_goal = q.goal == Friction_lp::Goal::margin;
  const std::size_t k = s.points.size(), m = q.cone.size(), P = q.points.size();
  // Columns: the cone's weights, each listed point's λ_ij, the slacks, the goal's (margin t; or t and its slack), the
  // unknown forces (free only).
  std::vector<std::size_t> first(P);
  std::size_t columns = m;
  for (std::size_t i = 0; i < P; ++i) {
    first[i] = columns;
    columns += q.directions[i].size();
  }
  const std::size_t slack = columns, goal = slack + P, force = goal + (margin_goal ? 1 : 2);
  const std::size_t cols = force + (free_f ? a.unknown.size() : 0);
  std::vector<std::vector<Rational>> A;
  std::vector<Rational> b;
  // The wrench rows: Σ_j c_j w_j + Σ_ij λ_ij (u_ij, r_i × u_ij) = load (margin), or + t·load = rhs (scale).
  for (std::size_t row = 0; row < 3; ++row) {
    std::vector<Rational> r(cols);
    for (std::size_t j = 0; j < m; ++j) r[j] = q.cone[j][row];
    for (std::size_t i = 0; i < P; ++i) {
      const Vec2& at = s.points[q.points[i]].at;
      for (std::size_t j = 0; j < q.directions[i].size(); ++j) {
        const Vec2& u = q.directions[i][j];
        r[first[i] + j] = row == 0 ? u.x : row == 1 ? u.y : cross(at, u);
      }
    }
    if (!margin_goal) r[goal] = q.load[row];
    A.push_back(std::move(r));
    b.push_back(margin_goal ? q.load[row] : q.rhs[row]);
  }
  // The discs: Σ_j λ_ij + s_i (+ t where μ_i f_i > 0, margin with f fixed) = μ_i f_i (f_i a column when free).
  for (std::size_t i = 0; i < P; ++i) {
    const std::size_t pt = q.points[i];
    std::vector<Rational> r(cols);
    for (std::size_t j = 0; j < q.directions[i].size(); ++j) r[first[i] + j] = 1;
    r[slack + i] = 1;
    const Rational& mu = s.mu_of(s.points[pt]);
    Rational rhs = mu * f0[pt];
    if (margin_goal && !free_f && rhs > 0) r[goal] = 1;
    if (free_f)
      for (std::size_t u = 0; u < a.unknown.size(); ++u)
        if (a.unknown[u] == pt) {
          r[force + u] = -mu;
          rhs = 0;
        }
    A.push_back(std::move(r));
    b.push_back(rhs);
  }
  if (!margin_goal) {  // t ≤ 1
    std::vector<Rational> r(cols);
    r[goal] = 1;
    r[goal + 1] = 1;
    A.push_back(std::move(r));
    b.push_back(1);
  }
  if (free_f) {  // F's rows over the unknown forces
    for (int row = 0; row < 3; ++row) {
      std::vector<Rational> r(cols);
      for (std::size_t u = 0; u < a.unknown.size(); ++u) {
        const Vec2& at = s.points[a.unknown[u]].at;
        r[force + u] = row == 0 ? Rational(1) : row == 1 ? at.x : at.y;
      }
      A.push_back(std::move(r));
    }
    b.push_back(a.rest);
    b.push_back(a.rest_moment.x);
    b.push_back(a.rest_moment.y);
  }
  std::vector<Rational> objective(cols);
  if (!margin_goal || !free_f) objective[goal] = 1;  // the largest margin, or the largest share of the load
  Friction_lp_solution out;
  out.lp = maximise(A, b, objective);
  if (out.lp.status != Lp_result::Status::optimal) return std::nullopt;
  out.goal = out.lp.x[goal];
  out.distribution = f0;
  if (free_f)
    for (std::size_t u = 0; u < a.unknown.size(); ++u) out.distribution[a.unknown[u]] = out.lp.x[force + u];
  out.cone_weights.assign(out.lp.x.begin(), out.lp.x.begin() + static_cast<std::ptrdiff_t>(m));
  out.forces.assign(k, Vec2{});
  for (std::size_t i = 0; i < P; ++i)
    for (std::size_t j = 0; j < q.directions[i].size(); ++j) {
      const Rational& l = out.lp.x[first[i] + j];
      if (l == 0) continue;
      out.forces[q.points[i]].x += l * q.directions[i][j].x;
      out.forces[q.points[i]].y += l * q.directions[i][j].y;
    }
  return out;
}

std::optional<Stick_witness> stick_witness(const Support& s, const Admissible& a, const Vec3q& p, int sides,
                                           const std::vector<Rational>* fixed) {
  // The LP has (3 + k) rows of about k·n columns: refused beyond kMaxStickWitnessColumns.
  if (s.points.size() * static_cast<std::size_t>(sides) > kMaxStickWitnessColumns)
    throw std::length_error("stick_witness: " + std::to_string(s.points.size()) + " support points x " +
                            std::to_string(sides) + " sides, more than " + std::to_string(kMaxStickWitnessColumns) +
                            " columns");
  const bool free_f = !fixed && !a.known();
  const std::vector<Rational>& f0 = fixed ? *fixed : a.given;
  if (!free_f) {  // friction at two distinct points, or LS(f) is flat and has no interior
    const Vec2* first = nullptr;
    bool two = false;
    for (std::size_t i = 0; i < s.points.size() && !two; ++i) {
      if (s.mu_of(s.points[i]) * f0[i] == 0) continue;
      if (first && (first->x != s.points[i].at.x || first->y != s.points[i].at.y)) two = true;
      if (!first) first = &s.points[i].at;
    }
    if (!two) return std::nullopt;
  }
  Friction_lp q;
  q.support = &s;
  q.admissible = &a;
  q.fixed = fixed;
  q.load = p;
  const Directions d = make_directions(sides);
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    q.points.push_back(i);
    q.directions.push_back(d.u);
  }
  const std::optional<Friction_lp_solution> lp = solve(q);
  if (!lp) return std::nullopt;
  if (!free_f && lp->goal <= 0) return std::nullopt;  // on the inscribed polygons' boundary: not inside
  return Stick_witness{lp->distribution, lp->forces, {}};
}

namespace {

void add_once(std::vector<Vec2>& to, const Vec2& e) {
  if (std::none_of(to.begin(), to.end(), [&](const Vec2& v) { return v.x == e.x && v.y == e.y; })) to.push_back(e);
}

// Rational unit directions near the direction of g ≠ 0: u(τ) = ((1 − τ²), 2τ)/(1 + τ²) at the half-angle parameters
// τ ± δ about τ ≈ tan(θ/2) of g (of −g, negated, when g points left: τ stays in [−1, 1]), each rounded to a dyadic
// of `bits` bits. Exact rationals throughout (|g| by an integer square root); the inscribed polygon through them
// reaches within about δ²/2 of its disc along g.
void add_refined(const Vec2& g, const Rational& delta, int bits, std::vector<Vec2>& out) {
  if (g.x == 0 && g.y == 0) return;
  const bool flip = g.x < 0;
  const Rational gx = flip ? Rational(-g.x) : g.x, gy = flip ? Rational(-g.y) : g.y;
  const Rational len = sqrt_bracket(gx * gx + gy * gy, bits).second;
  Rational tau = gy / (len + gx);
  Integer scaled;
  Rational two_b(Integer(1) << bits);
  mpz_fdiv_q(scaled.get_mpz_t(), Rational(tau * two_b).get_num_mpz_t(), Rational(tau * two_b).get_den_mpz_t());
  tau = Rational(scaled) / two_b;
  for (const Rational& t : {Rational(tau - delta), tau, Rational(tau + delta)}) {
    const Rational d = 1 + t * t;
    Vec2 u{Rational((1 - t * t) / d), Rational(2 * t / d)};
    if (flip) u = {Rational(-u.x), Rational(-u.y)};
    add_once(out, u);
  }
}

// The LP's columns: the points that can carry friction, each with its polygon's directions.
void directions_of(const Polygon_rounds& r, Friction_lp& q) {
  const Support& s = *r.support;
  std::vector<Vec2> base = make_directions(16).u;
  for (const Vec2& axis : {Vec2{Rational(1), Rational(0)}, Vec2{Rational(0), Rational(1)}, Vec2{Rational(-1), Rational(0)},
                           Vec2{Rational(0), Rational(-1)}})
    add_once(base, axis);
  for (const Vec2& e : r.common) add_once(base, e);
  const bool free_f = r.fixed == nullptr;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Rational& mu = s.mu_of(s.points[i]);
    const Rational rho = mu * (free_f ? r.admissible->given[i] : (*r.fixed)[i]);
    if (!((free_f && !s.points[i].force && mu > 0) || rho > 0)) continue;
    q.points.push_back(i);
    q.directions.push_back(base);
    if (i < r.own.size())
      for (const Vec2& e : r.own[i]) add_once(q.directions.back(), e);
  }
}

}  // namespace

void add_exact_directions(const Support& s, const Vec3q& t, std::vector<Vec2>& out) {
  for (const Support_point& p : s.points) {
    const Vec2 v = velocity(t, p.at);
    const Rational s2 = dot(v, v);
    if (s2 == 0) continue;
    const std::pair<Rational, Rational> b = sqrt_bracket(s2, 64);
    if (b.first != b.second) continue;  // |v| irrational (or not found exactly)
    const Vec2 u{Rational(v.x / b.first), Rational(v.y / b.first)};
    add_once(out, u);
    add_once(out, {Rational(-u.x), Rational(-u.y)});
    if (out.size() > 64) return;
  }
}

Friction_lp_solution Polygon_rounds::scale(const Vec3q& load, const Vec3q& rhs) const {
  Friction_lp q;
  q.goal = Friction_lp::Goal::scale;
  q.support = support;
  q.admissible = admissible;
  q.fixed = fixed;
  q.load = load;
  q.rhs = rhs;
  q.cone = cone;
  directions_of(*this, q);
  std::optional<Friction_lp_solution> lp = solve(q);
  if (!lp) throw std::logic_error("the polygon LP is feasible (t = 0) and bounded (t ≤ 1)");
  return std::move(*lp);
}

std::optional<Stick_witness> Polygon_rounds::margin(const Vec3q& p) const {
  const Support& s = *support;
  const Vec2* first = nullptr;
  bool two = false;
  for (std::size_t i = 0; i < s.points.size() && !two; ++i) {
    if (s.mu_of(s.points[i]) * (*fixed)[i] == 0) continue;
    if (first && (first->x != s.points[i].at.x || first->y != s.points[i].at.y)) two = true;
    if (!first) first = &s.points[i].at;
  }
  if (!two) return std::nullopt;  // LS(f) is flat: no interior
  // The rounds refine where the forces carrying −p go (scale: friction + t·p = 0); LS(f) is symmetric, so the margin
  // LP carries −p on those polygons and the witness for p is its forces negated.
  Friction_lp q;
  q.support = support;
  q.admissible = admissible;
  q.fixed = fixed;
  q.load = {-p[0], -p[1], -p[2]};
  directions_of(*this, q);
  std::optional<Friction_lp_solution> lp = solve(q);
  if (!lp || lp->goal <= 0) return std::nullopt;
  for (Vec2& g : lp->forces) g = {Rational(-g.x), Rational(-g.y)};
  return Stick_witness{lp->distribution, lp->forces, {}};
}

void Polygon_rounds::refine(const Vec3q& t, int round, const std::vector<Vec2>& forces) {
  const Support& s = *support;
  add_exact_directions(s, t, common);
  own.resize(s.points.size());
  const Rational delta(Integer(1), Integer(1) << (4 + 3 * round));
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Vec2& r = s.points[i].at;
    const Vec2 against{Rational(t[2] * r.y - t[0]), Rational(-t[1] - t[2] * r.x)};
    add_refined(against, delta, 12 + 5 * round, own[i]);
    if (i < forces.size()) add_refined(forces[i], delta, 12 + 5 * round, own[i]);  // where it went this round
  }
}

Rational polygon_rounds(Polygon_rounds& r, const Vec3q& load,
                        const std::function<bool(const Friction_lp_solution&)>& decide, int& rounds) {
  Rational best;
  for (int round = 0; round < kPolygonRounds; ++round) {
    rounds = round + 1;
    const Friction_lp_solution lp = r.scale(load);
    best = lp.goal;
    if (decide(lp)) return best;
    r.refine({lp.lp.y[0], lp.lp.y[1], lp.lp.y[2]}, round, lp.forces);
  }
  return best;
}

}  // namespace wrenchkit
