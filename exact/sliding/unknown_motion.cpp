#include "exact/sliding/unknown_motion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "exact/numbers/exact_lp.h"
#include "exact/sliding/motion_certificate.h"

namespace wrenchkit {

const char* motion_over_name(Motion_over m) {
  switch (m) {
    case Motion_over::sticks: return "sticks";
    case Motion_over::slides: return "slides";
    case Motion_over::depends: return "depends";
    case Motion_over::undecided: return "undecided";
  }
  return "?";
}

namespace {


constexpr double kPi = 3.141592653589793;

// A relative gap for a sentence (two significant digits; text only, never a predicate).
std::string gap_text(double g) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2g", g);
  return b;
}

}  // namespace

std::optional<Stick_witness> stick_witness(const Support& s, const Admissible& a, const Vec3q& p, int sides,
                                           const std::vector<Rational>* fixed) {
  // The LP has (3 + k) rows of about k·n columns: refused beyond kMaxStickWitnessColumns (motion_certificate.h).
  if (s.points.size() * static_cast<std::size_t>(sides) > kMaxStickWitnessColumns)
    throw std::length_error("stick_witness: " + std::to_string(s.points.size()) + " support points x " +
                            std::to_string(sides) + " sides, more than " + std::to_string(kMaxStickWitnessColumns) +
                            " columns");
  const Directions d = make_directions(sides);
  const std::size_t k = s.points.size(), n = d.u.size();
  const bool free_f = !fixed && !a.known();
  const std::vector<Rational> f0 = fixed ? *fixed : a.given;
  if (!free_f) {  // friction at two distinct points, or LS(f) is flat and has no interior
    const Vec2* first = nullptr;
    bool two = false;
    for (std::size_t i = 0; i < k && !two; ++i) {
      if (s.mu_of(s.points[i]) * f0[i] == 0) continue;
      if (first && (first->x != s.points[i].at.x || first->y != s.points[i].at.y)) two = true;
      if (!first) first = &s.points[i].at;
    }
    if (!two) return std::nullopt;
  }
  // Columns: λ_ij (k·n), slack s_i (k), the margin t (f fixed), then the unknown forces (free_f only).
  const std::size_t lambda = k * n, slack = lambda, margin = lambda + k, force = margin + 1;
  const std::size_t cols = force + (free_f ? a.unknown.size() : 0);
  std::vector<std::vector<Rational>> A;
  std::vector<Rational> b;
  // Σ_ij λ_ij (u_j, r_i × u_j) = p.
  for (int row = 0; row < 3; ++row) {
    std::vector<Rational> r(cols);
    for (std::size_t i = 0; i < k; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        const Vec2& u = d.u[j];
        const Vec2& at = s.points[i].at;
        r[i * n + j] = row == 0 ? u.x : row == 1 ? u.y : Rational(at.x * u.y - at.y * u.x);
      }
    A.push_back(std::move(r));
    b.push_back(p[static_cast<std::size_t>(row)]);
  }
  // Σ_j λ_ij + s_i (+ t where μ_i f_i > 0, f fixed) = μ_i f_i (f_i a column when free).
  for (std::size_t i = 0; i < k; ++i) {
    std::vector<Rational> r(cols);
    for (std::size_t j = 0; j < n; ++j) r[i * n + j] = 1;
    r[slack + i] = 1;
    const Rational mu = s.mu_of(s.points[i]);
    Rational rhs = mu * f0[i];
    if (!free_f && rhs > 0) r[margin] = 1;
    if (free_f)
      for (std::size_t u = 0; u < a.unknown.size(); ++u)
        if (a.unknown[u] == i) {
          r[force + u] = -mu;
          rhs = 0;
        }
    A.push_back(std::move(r));
    b.push_back(rhs);
  }
  // The rows of F over the unknown forces.
  if (free_f) {
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
  if (!free_f) objective[margin] = 1;  // the largest common margin
  const Lp_result lp = maximise(A, b, objective);
  if (lp.status != Lp_result::Status::optimal) return std::nullopt;
  if (!free_f && lp.x[margin] <= 0) return std::nullopt;  // on the inscribed polygons' boundary: not inside
  Stick_witness w;
  w.distribution = f0;
  if (free_f)
    for (std::size_t u = 0; u < a.unknown.size(); ++u) w.distribution[a.unknown[u]] = lp.x[force + u];
  w.forces.assign(k, Vec2{});
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const Rational& l = lp.x[i * n + j];
      if (l == 0) continue;
      w.forces[i].x += l * d.u[j].x;
      w.forces[i].y += l * d.u[j].y;
    }
  return w;
}

bool slides_for_every(const Support& s, const Admissible& a, const Vec3q& p, const Vec3q& q) {
  if (q[0] == 0 && q[1] == 0 && q[2] == 0) return false;
  std::vector<Rational> coef = speed_bounds(s, q);  // μ_i times the rational upper bound of |v_i(q)|
  for (std::size_t i = 0; i < coef.size(); ++i) coef[i] *= s.mu_of(s.points[i]);
  return dot(q, p) >= maximise_over(s, a, coef).value;
}

// Friction at fewer than two distinct points: LS(f) is flat and has no interior, so every load slides on it (the
// convention of the certificates, proofs/notes/SL-1: a load on the limit surface slides).
bool flat(const Support& s, const std::vector<Rational>& f) {
  const Vec2* first = nullptr;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    if (s.mu_of(s.points[i]) * f[i] == 0) continue;
    if (first && (first->x != s.points[i].at.x || first->y != s.points[i].at.y)) return false;
    if (!first) first = &s.points[i].at;
  }
  return true;
}

std::optional<Vec3q> union_search(const Support& s, const std::vector<std::vector<Rational>>& v, const Vec3q& p,
                                  const Vec3q* start, const std::function<double(const double*)>& common) {
  const std::size_t k = s.points.size();
  std::vector<double> x(k), y(k);
  std::vector<std::vector<double>> rho(v.size(), std::vector<double>(k));
  for (std::size_t i = 0; i < k; ++i) {
    x[i] = s.points[i].at.x.get_d(), y[i] = s.points[i].at.y.get_d();
    const Rational mu = s.mu_of(s.points[i]);
    for (std::size_t j = 0; j < v.size(); ++j) rho[j][i] = Rational(mu * v[j][i]).get_d();
  }
  const auto h_union = [&](const double* q) {
    double best = 0;
    for (const auto& r : rho) {
      double h = 0;
      for (std::size_t i = 0; i < k; ++i)
        if (r[i] != 0) h += r[i] * std::hypot(q[0] - q[2] * y[i], q[1] + q[2] * x[i]);
      best = std::max(best, h);
    }
    return common ? best + common(q) : best;
  };
  const Plane_minimum m = minimise_on_load_plane(p, h_union, start, 1.0);
  if (!m.found || !(m.h < 1)) return std::nullopt;
  return Vec3q{Rational(m.q[0]), Rational(m.q[1]), Rational(m.q[2])};
}

namespace {

// [SL-3] step 4: the union's minimax by a log barrier (doubles propose; the caller checks exactly; proofs/notes/SL-6 §6).
//
//   min_{q·p = 1} max_v h_v(q)  =  min { t : h_v(q) ≤ t for every vertex v, q·p = 1 }
//
// solved by the barrier t − μ Σ_v log(t − h_v(q)) (Newton's method in the plane's two coordinates and t, μ divided
// by 10 until μ·V is below 10^-13 of t). At each centre λ_v = μ/(t − h_v) sums to 1 and is the LP dual: the
// distribution f* = Σ λ_v f_v maximises min_{q·p=1} h_f(q) over F (minimax: h_f(q) is convex in q and linear in f),
// so t* < 1: q* separates p from U (slides for every distribution); t* > 1: p is inside LS(f*) (f* sticks: depends
// when a vertex slides). |v| is smoothed to √(|v|² + δ²), δ = 10^-9 of the plane's scale, so h is twice
// differentiable at the support points; the smoothing and the rounding only move the proposals.
struct Union_minimax {
  bool found = false;
  std::array<double, 3> q{};
  double t = 0;
  std::vector<double> lambda;  // one per vertex, ≥ 0, sum ≈ 1
};

Union_minimax union_minimax(const Support& s, const std::vector<std::vector<Rational>>& v, const Vec3q& p) {
  Union_minimax out;
  const std::size_t k = s.points.size(), nv = v.size();
  const double px = p[0].get_d(), py = p[1].get_d(), pm = p[2].get_d();
  const double pp = px * px + py * py + pm * pm;
  if (!(pp > 0) || !std::isfinite(pp) || nv == 0) return out;
  std::vector<double> x(k), y(k);
  std::vector<std::vector<double>> rho(nv, std::vector<double>(k));
  for (std::size_t i = 0; i < k; ++i) {
    x[i] = s.points[i].at.x.get_d(), y[i] = s.points[i].at.y.get_d();
    const Rational mu = s.mu_of(s.points[i]);
    for (std::size_t j = 0; j < nv; ++j) rho[j][i] = Rational(mu * v[j][i]).get_d();
  }
  // The plane q = q0 + a e1 + b e2: q0 = p/|p|², e1, e2 an orthonormal basis of p's orthogonal complement.
  const double n = std::sqrt(pp);
  const std::array<double, 3> u{px / n, py / n, pm / n}, q0{px / pp, py / pp, pm / pp};
  std::array<double, 3> e1 = std::abs(u[0]) < 0.9 ? std::array<double, 3>{1, 0, 0} : std::array<double, 3>{0, 1, 0};
  {
    const double d = e1[0] * u[0] + e1[1] * u[1] + e1[2] * u[2];
    for (int c = 0; c < 3; ++c) e1[c] -= d * u[c];
    const double l = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    for (int c = 0; c < 3; ++c) e1[c] /= l;
  }
  const std::array<double, 3> e2{u[1] * e1[2] - u[2] * e1[1], u[2] * e1[0] - u[0] * e1[2], u[0] * e1[1] - u[1] * e1[0]};
  double scale = 0;  // the support's extent, for the smoothing
  for (std::size_t i = 0; i < k; ++i) scale = std::max({scale, std::abs(x[i]), std::abs(y[i])});
  const double delta2 = std::pow(1e-9 * (1 + scale) / n, 2);
  // h_v, its gradient (a, b) and Hessian at (a, b), all vertices at once.
  struct Piece {
    double h, g[2], H[3];  // H = (aa, ab, bb)
  };
  std::vector<Piece> pieces(nv);
  const auto evaluate = [&](double a, double b) {
    const double q[3] = {q0[0] + a * e1[0] + b * e2[0], q0[1] + a * e1[1] + b * e2[1], q0[2] + a * e1[2] + b * e2[2]};
    for (std::size_t j = 0; j < nv; ++j) pieces[j] = {};
    for (std::size_t i = 0; i < k; ++i) {
      const double vx = q[0] - q[2] * y[i], vy = q[1] + q[2] * x[i];
      const double s2 = vx * vx + vy * vy + delta2, sv = std::sqrt(s2);
      // v = B q with B = [[1, 0, −y], [0, 1, x]]: in the plane's coordinates, v_a = B e1, v_b = B e2.
      const double ax = e1[0] - e1[2] * y[i], ay = e1[1] + e1[2] * x[i];
      const double bx = e2[0] - e2[2] * y[i], by = e2[1] + e2[2] * x[i];
      const double da = (vx * ax + vy * ay) / sv, db = (vx * bx + vy * by) / sv;
      const double haa = (ax * ax + ay * ay - da * da) / sv, hab = (ax * bx + ay * by - da * db) / sv,
                   hbb = (bx * bx + by * by - db * db) / sv;
      for (std::size_t j = 0; j < nv; ++j) {
        const double r = rho[j][i];
        if (r == 0) continue;
        Piece& pc = pieces[j];
        pc.h += r * sv, pc.g[0] += r * da, pc.g[1] += r * db;
        pc.H[0] += r * haa, pc.H[1] += r * hab, pc.H[2] += r * hbb;
      }
    }
  };
  double a = 0, b = 0;
  evaluate(a, b);
  double t = 0;
  for (const Piece& pc : pieces) t = std::max(t, pc.h);
  if (!std::isfinite(t)) return out;
  t = 2 * t + 1;
  const double target = 1e-13;
  double mu = 0.1 * t;
  std::size_t work = 0;
  const std::size_t budget = 400000;  // point evaluations
  const auto barrier = [&](double t_, bool& ok) {
    double f = t_;
    ok = true;
    for (const Piece& pc : pieces) {
      const double sl = t_ - pc.h;
      if (!(sl > 0)) return ok = false, 0.0;
      f -= mu * std::log(sl);
    }
    return f;
  };
  for (int outer = 0; outer < 60; ++outer) {
    for (int it = 0; it < 100; ++it) {
      // Newton on (a, b, t).
      double G[3] = {0, 0, 1}, Hm[6] = {0, 0, 0, 0, 0, 0};  // Hm: (aa, ab, bb, at, bt, tt)
      for (const Piece& pc : pieces) {
        const double sl = t - pc.h, w = mu / sl, w2 = w / sl;
        G[0] += w * pc.g[0], G[1] += w * pc.g[1], G[2] -= w;
        Hm[0] += w * pc.H[0] + w2 * pc.g[0] * pc.g[0];
        Hm[1] += w * pc.H[1] + w2 * pc.g[0] * pc.g[1];
        Hm[2] += w * pc.H[2] + w2 * pc.g[1] * pc.g[1];
        Hm[3] -= w2 * pc.g[0], Hm[4] -= w2 * pc.g[1], Hm[5] += w2;
      }
      // Solve the 3×3 symmetric system H d = −G (Cramer's rule; H is positive definite inside the barrier).
      const double A = Hm[0], B = Hm[1], C = Hm[3], D = Hm[2], E = Hm[4], Fv = Hm[5];
      const double det = A * (D * Fv - E * E) - B * (B * Fv - E * C) + C * (B * E - D * C);
      if (!(std::abs(det) > 0) || !std::isfinite(det)) break;
      const double r0 = -G[0], r1 = -G[1], r2 = -G[2];
      const double d0 = (r0 * (D * Fv - E * E) - B * (r1 * Fv - E * r2) + C * (r1 * E - D * r2)) / det;
      const double d1 = (A * (r1 * Fv - E * r2) - r0 * (B * Fv - E * C) + C * (B * r2 - r1 * C)) / det;
      const double d2 = (A * (D * r2 - r1 * E) - B * (B * r2 - r1 * C) + r0 * (B * E - D * C)) / det;
      const double decrement = -(G[0] * d0 + G[1] * d1 + G[2] * d2);
      if (!(decrement > 1e-20 * mu)) break;  // centred
      bool ok = false;
      const double f0 = barrier(t, ok);
      double step = 1;
      for (; step > 1e-12; step /= 2) {
        evaluate(a + step * d0, b + step * d1);
        work += k;
        const double f1 = barrier(t + step * d2, ok);
        if (ok && f1 <= f0 - 0.25 * step * decrement) break;
      }
      if (step <= 1e-12 || work > budget) {
        evaluate(a, b);
        break;
      }
      a += step * d0, b += step * d1, t += step * d2;
      if (decrement < 1e-14 * mu) break;
    }
    if (work > budget) break;
    if (mu * static_cast<double>(nv) < target * t) break;
    mu /= 10;
  }
  evaluate(a, b);
  double h = 0, sum = 0;
  out.lambda.resize(nv);
  for (std::size_t j = 0; j < nv; ++j) {
    h = std::max(h, pieces[j].h);
    out.lambda[j] = mu / std::max(t - pieces[j].h, 1e-300);
    sum += out.lambda[j];
  }
  if (!(sum > 0) || !std::isfinite(sum) || !std::isfinite(h)) return out;
  for (double& l : out.lambda) l /= sum;
  out.q = {q0[0] + a * e1[0] + b * e2[0], q0[1] + a * e1[1] + b * e2[1], q0[2] + a * e1[2] + b * e2[2]};
  out.t = h;
  out.found = true;
  return out;
}

}  // namespace

Motion_over_f decide_motion_over(const Support& s, const Admissible& a, const Vec3q& p, Mode mode, int sides) {
  if (a.known() || a.unknown.size() > kMaxEnumeratedUnknowns)
    throw std::invalid_argument("decide_motion_over: needs a few unknown forces");
  Motion_over_f r;
  const std::vector<std::vector<Rational>> v = vertices(s, a);
  std::vector<Vec3q> twists;  // the sliding vertices' twists (from the certified search), candidates for step 3
  for (std::size_t i = 0; i < v.size(); ++i) {
    Motion_decision m;
    if (flat(s, v[i])) {
      m.motion = Motion::slides;
      m.decided_by = "flat";
    } else {
      m = decide_motion(merge_support(s, &v[i]), p, mode, sides);
    }
    r.per_vertex.push_back(m.motion);
    r.decisions.push_back(m);
    if (m.motion == Motion::sticks && !r.sticking_vertex) r.sticking_vertex = i;
    if (m.motion == Motion::slides && !r.sliding_vertex) r.sliding_vertex = i;
    if (m.motion == Motion::slides && std::string(m.decided_by) == "float")
      twists.push_back({Rational(m.witness[0]), Rational(m.witness[1]), Rational(m.witness[2])});
    if (m.exact_witness) twists.push_back(*m.exact_witness);
  }
  if (r.sticking_vertex && r.sliding_vertex) {
    r.motion = Motion_over::depends;
    r.decided_by = "vertices";
    return r;
  }
  bool all_stick = true, all_slide = true;
  for (Motion m : r.per_vertex) {
    all_stick &= m == Motion::sticks;
    all_slide &= m == Motion::slides;
  }
  if (all_stick) {
    r.motion = Motion_over::sticks;
    r.decided_by = "vertices";
    return r;
  }
  if (!all_slide) {  // some vertices undecided and none of the other kind: not decided
    r.decided_by = "none";
    for (std::size_t i = 0; i < r.per_vertex.size(); ++i)
      if (r.per_vertex[i] == Motion::undecided) {
        r.undecided_why = "extreme distribution " + std::to_string(i + 1) + " of " + std::to_string(v.size()) +
                          " is undecided: the load lies between its inscribed and circumscribed " + std::to_string(sides) +
                          "-gon limit surfaces, within " + gap_text(1 / std::cos(kPi / sides) - 1) +
                          " of its limit surface (relative, along the load's ray; refine --sides)";
        break;
      }
    return r;
  }
  if (twists.size() > 1) {  // their sum first: a twist between the vertices' own
    Vec3q sum{};
    for (const Vec3q& q : twists)
      for (std::size_t c = 0; c < 3; ++c) sum[c] += q[c];
    twists.insert(twists.begin(), sum);
  }
  for (const Vec3q& q : twists)
    if (slides_for_every(s, a, p, q)) {
      r.motion = Motion_over::slides;
      r.separating_twist = q;
      r.decided_by = "twist";
      return r;
    }
  // [SL-3] step 4 (hybrid): the union's minimax and its dual distribution f*, proposed by the barrier in doubles;
  // kept only when exact: q* separates (slides_for_every), or f* sticks (a stick witness of f*, which is in F as a
  // convex combination of vertices with rational weights). Only margins the doubles resolve (|t* − 1| > 10^-9).
  if (mode == Mode::hybrid)
    if (const Union_minimax m = union_minimax(s, v, p); m.found) {
      if (m.t < 1) {
        const Vec3q q{Rational(m.q[0]), Rational(m.q[1]), Rational(m.q[2])};
        if (slides_for_every(s, a, p, q)) {
          r.motion = Motion_over::slides;
          r.separating_twist = q;
          r.decided_by = "minimax";
          return r;
        }
      } else if (m.t > 1 + 1e-9) {
        std::vector<Rational> l(v.size());
        Rational total = 0;
        for (std::size_t j = 0; j < v.size(); ++j) total += l[j] = Rational(m.lambda[j]);
        std::vector<Rational> f(s.points.size());
        for (std::size_t j = 0; j < v.size(); ++j)
          if (l[j] != 0)
            for (std::size_t i = 0; i < f.size(); ++i) f[i] += l[j] / total * v[j][i];
        r.sticking = smoothed_stick_witness(s, f, p);
        if (!r.sticking) r.sticking = precise_witness(s, f, p).sticks;
        if (r.sticking) {
          r.motion = Motion_over::depends;
          r.decided_by = "minimax";
          return r;
        }
      }
    }
  // The search for a twist separating p from U, from the best of those.
  if (const auto q = union_search(s, v, p, twists.empty() ? nullptr : &twists.front()))
    if (slides_for_every(s, a, p, *q)) {
      r.motion = Motion_over::slides;
      r.separating_twist = *q;
      r.decided_by = "twist";
      return r;
    }
  // A distribution that sticks: the exact LP over F × inscribed N-gons, N doubled while the LP stays small.
  int largest = 0;
  for (int n = sides; n <= 256 && s.points.size() * static_cast<std::size_t>(n) <= 1024; n *= 2) {
    largest = n;
    if (const auto some = stick_witness(s, a, p, n)) {  // closed: confirmed strictly with that distribution
      if ((r.sticking = stick_witness_refined(s, a, p, n, some->distribution))) {
        r.motion = Motion_over::depends;
        r.decided_by = "lp";
        return r;
      }
    }
  }
  r.decided_by = "none";
  r.undecided_why = "every extreme distribution slides, no twist tried separates the load from the union of the limit "
                    "surfaces, and no distribution holds it with forces on inscribed " +
                    std::to_string(largest ? largest : sides) + "-gons: if inside that union, the load is within " +
                    gap_text(1 - std::cos(kPi / (largest ? largest : sides))) +
                    " of its boundary (relative, along the load's ray)";
  return r;
}

}  // namespace wrenchkit
