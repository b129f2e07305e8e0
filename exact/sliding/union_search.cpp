// [SL-3] Twists for the union of the limit surfaces over F, proposed in double (every caller checks exactly what it
// keeps): the compass search on max_v h_v, and the union's minimax by a log barrier (proofs/notes/SL-6 §6).
#include <algorithm>
#include <array>
#include <cmath>

#include "exact/sliding/strategies.h"

namespace wrenchkit {

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

}  // namespace wrenchkit
