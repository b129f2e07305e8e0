#include "exact/sliding/motion_certificate.h"

#include <cmath>

#include "exact/io/json_writer.h"

namespace wrenchkit {

std::vector<Rational> speed_bounds(const Support& s, const Vec3q& q) {
  std::vector<Rational> u;
  u.reserve(s.points.size());
  for (const Support_point& p : s.points) {
    const Rational vx = q[0] - q[2] * p.at.y, vy = q[1] + q[2] * p.at.x;
    u.push_back(sqrt_bracket(vx * vx + vy * vy).second);
  }
  return u;
}

std::optional<Slide_witness> slide_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                           const Vec3q& q) {
  if (q[0] == 0 && q[1] == 0 && q[2] == 0) return std::nullopt;
  Slide_witness w{f, q, speed_bounds(s, q)};
  Rational bound;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Support_point& pt = s.points[i];
    const Rational mu = pt.mu ? *pt.mu : (s.mu ? *s.mu : Rational(0));
    bound += mu * f[i] * w.speed_bounds[i];
  }
  if (q[0] * p[0] + q[1] * p[1] + q[2] * p[2] >= bound) return w;
  return std::nullopt;
}

// The cheap witness first (SL-4). In double: Newton's method on the smoothed dual
//   φ(λ) = Σ ρ_i H(|v_i(λ)|) − λ·p/σ,   H(t) = t²/2 for t ≤ 1, t − 1/2 beyond (ρ_i = μ_i f_i),
// whose gradient Σ ρ_i A_i v_i/max(|v_i|, 1) − p/σ vanishes where the forces ρ_i v_i/max(|v_i|, 1), each in its
// disc, sum to p/σ (A_i g = (g, r_i × g), v_i(λ) = A_iᵀλ). φ has a minimiser when p/σ is inside the limit
// surface and none when it is outside; σ = 1 − 2^-j for j = 1, 2, … (the first that converges leaves a slack
// ≥ half the load's own). Still points (rotation centres) are handled by the smoothing. Then one exact round:
// rational weights w_i = σ ρ_i/max(|v_i(λ)|, 1), L solves Σ w_i A_i A_iᵀ L = p exactly, g_i = w_i v_i(L), so
// Σ A_i g_i = p exactly, and each disc is checked exactly (|g_i|² < ρ_i²). Nothing when no σ verifies (then
// the LP decides). O(k) per Newton step.

std::optional<Stick_witness> smoothed_stick_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p) {
  const std::size_t k = s.points.size();
  std::vector<double> x(k), y(k), rho(k);
  std::vector<Rational> rq(k);
  std::size_t carrying = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const Support_point& pt = s.points[i];
    rq[i] = (pt.mu ? *pt.mu : (s.mu ? *s.mu : Rational(0))) * f[i];
    x[i] = pt.at.x.get_d(), y[i] = pt.at.y.get_d(), rho[i] = rq[i].get_d();
    carrying += rq[i] > 0;
  }
  if (carrying < 2) return std::nullopt;
  const double pd[3] = {p[0].get_d(), p[1].get_d(), p[2].get_d()};
  for (double v : pd)
    if (!std::isfinite(v)) return std::nullopt;
  const auto det3 = [](const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const auto solve3 = [&](double m[3][3], const double b[3], double out[3]) {
    const double d = det3(m);
    if (!(std::fabs(d) > 0) || !std::isfinite(d)) return false;
    for (int c = 0; c < 3; ++c) {
      double mc[3][3];
      for (int r = 0; r < 3; ++r)
        for (int cc = 0; cc < 3; ++cc) mc[r][cc] = cc == c ? b[r] : m[r][cc];
      out[c] = det3(mc) / d;
    }
    return std::isfinite(out[0]) && std::isfinite(out[1]) && std::isfinite(out[2]);
  };
  const auto phi = [&](const double l[3], double sigma) {
    double v = -(l[0] * pd[0] + l[1] * pd[1] + l[2] * pd[2]) / sigma;
    for (std::size_t i = 0; i < k; ++i) {
      if (rho[i] == 0) continue;
      const double t = std::hypot(l[0] - l[2] * y[i], l[1] + l[2] * x[i]);
      v += rho[i] * (t <= 1 ? t * t / 2 : t - 0.5);
    }
    return v;
  };
  // Minimise φ for one σ: the minimiser, or false when Newton does not converge (p/σ outside, or numerics).
  const auto minimise = [&](double sigma, double l[3]) {
    l[0] = l[1] = l[2] = 0;
    double pnorm = std::fabs(pd[0]) + std::fabs(pd[1]) + std::fabs(pd[2]);
    for (int it = 0; it < 200; ++it) {
      double g[3] = {-pd[0] / sigma, -pd[1] / sigma, -pd[2] / sigma}, h[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
      for (std::size_t i = 0; i < k; ++i) {
        if (rho[i] == 0) continue;
        const double vx = l[0] - l[2] * y[i], vy = l[1] + l[2] * x[i], t = std::hypot(vx, vy), m = std::max(t, 1.0);
        const double a[3][2] = {{1, 0}, {0, 1}, {-y[i], x[i]}};  // rows of A_iᵀ... A_i maps g to (g, x g_y − y g_x)
        const double gx = rho[i] * vx / m, gy = rho[i] * vy / m;
        g[0] += gx, g[1] += gy, g[2] += x[i] * gy - y[i] * gx;
        // Hessian block ρ_i A_i B A_iᵀ, B = I (slow) or (I − v̂ v̂ᵀ)/t (fast).
        double b[2][2] = {{1, 0}, {0, 1}};
        if (t > 1) {
          const double ux = vx / t, uy = vy / t;
          b[0][0] = (1 - ux * ux) / t, b[0][1] = b[1][0] = -ux * uy / t, b[1][1] = (1 - uy * uy) / t;
        }
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c)
            h[r][c] += rho[i] * (a[r][0] * (b[0][0] * a[c][0] + b[0][1] * a[c][1]) +
                                 a[r][1] * (b[1][0] * a[c][0] + b[1][1] * a[c][1]));
      }
      const double gn = std::fabs(g[0]) + std::fabs(g[1]) + std::fabs(g[2]);
      if (gn <= 1e-14 * pnorm) return true;
      double step[3];
      if (!solve3(h, g, step)) return false;
      double t = 1, f0 = phi(l, sigma), trial[3];
      for (;; t /= 2) {  // backtracking: φ must decrease
        for (int c = 0; c < 3; ++c) trial[c] = l[c] - t * step[c];
        if (phi(trial, sigma) <= f0 || t < 1e-12) break;
      }
      if (t < 1e-12) return gn <= 1e-9 * pnorm;  // no more progress: accept only a small gradient
      for (int c = 0; c < 3; ++c) l[c] = trial[c];
      if (!(std::fabs(l[0]) + std::fabs(l[1]) + std::fabs(l[2]) < 1e150)) return false;  // unbounded: outside
    }
    return false;
  };
  for (int j = 1; j <= 50; ++j) {
    const double sigma = 1 - std::ldexp(1.0, -j);
    double l[3];
    if (!minimise(sigma, l)) continue;
    // The exact round with rational weights (the doubles, exactly).
    std::vector<Rational> w(k);
    Rational M[3][3];
    for (std::size_t i = 0; i < k; ++i) {
      if (rq[i] == 0) continue;
      const double t = std::hypot(l[0] - l[2] * y[i], l[1] + l[2] * x[i]);
      const double wi = sigma * rho[i] / std::max(t, 1.0);
      if (!std::isfinite(wi) || !(wi > 0)) break;
      w[i] = Rational(wi);
      const Vec2& r = s.points[i].at;
      const Rational cols[3][2] = {{1, 0}, {0, 1}, {-r.y, r.x}};
      for (int c = 0; c < 3; ++c) {
        M[0][c] += w[i] * cols[c][0];
        M[1][c] += w[i] * cols[c][1];
        M[2][c] += w[i] * (r.x * cols[c][1] - r.y * cols[c][0]);
      }
    }
    const Rational det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
                         M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                         M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
    if (det == 0) continue;
    Rational L[3];
    for (int c = 0; c < 3; ++c) {
      Rational mc[3][3];
      for (int r = 0; r < 3; ++r)
        for (int cc = 0; cc < 3; ++cc) mc[r][cc] = cc == c ? p[static_cast<std::size_t>(r)] : M[r][cc];
      L[c] = (mc[0][0] * (mc[1][1] * mc[2][2] - mc[1][2] * mc[2][1]) -
              mc[0][1] * (mc[1][0] * mc[2][2] - mc[1][2] * mc[2][0]) +
              mc[0][2] * (mc[1][0] * mc[2][1] - mc[1][1] * mc[2][0])) /
             det;
    }
    Stick_witness out{f, std::vector<Vec2>(k)};
    bool inside = true;
    for (std::size_t i = 0; i < k && inside; ++i) {
      if (rq[i] == 0) continue;
      const Vec2& r = s.points[i].at;
      out.forces[i] = {w[i] * (L[0] - L[2] * r.y), w[i] * (L[1] + L[2] * r.x)};
      inside = out.forces[i].x * out.forces[i].x + out.forces[i].y * out.forces[i].y < rq[i] * rq[i];
    }
    if (inside) return out;
  }
  return std::nullopt;
}

std::optional<Stick_witness> stick_witness_refined(const Support& s, const Admissible& a, const Vec3q& p, int sides,
                                                   const std::vector<Rational>& f) {
  if (auto w = smoothed_stick_witness(s, f, p)) return w;
  for (int n = sides; n <= 256 && s.points.size() * static_cast<std::size_t>(n) <= kMaxStickWitnessColumns; n *= 2)
    if (auto w = stick_witness(s, a, p, n, &f)) return w;
  return std::nullopt;
}

void write_forces(Json_writer& w, const std::vector<Vec2>& g) {
  w.array();
  for (const Vec2& f : g) w.array().rational(f.x).rational(f.y).end_array();
  w.end_array();
}

Json_writer motion_certificate_head(const Vec3q& p, const char* motion) {
  Json_writer w(512);
  w.object().member("wrenchkit_certificate", 1).member("property", "motion").key("load").rationals(p);
  w.member("motion", motion);
  return w;
}

namespace {

Json_writer head(const Vec3q& p, const char* motion) { return motion_certificate_head(p, motion); }

void write_stick(Json_writer& w, const Stick_witness& s) {
  w.object().key("distribution").rationals(s.distribution);
  write_forces(w.key("support_forces"), s.forces);
  w.end_object();
}

}  // namespace

std::string sticks_certificate(const Vec3q& p, const Stick_witness& s) {
  Json_writer w = head(p, "sticks");
  write_forces(w.key("support_forces"), s.forces);
  return w.end_object().take();
}

std::string slides_certificate(const Vec3q& p, const Slide_witness& s) {
  Json_writer w = head(p, "slides");
  w.key("twist").rationals(s.twist).key("speed_bounds").rationals(s.speed_bounds);
  return w.end_object().take();
}

std::string sticks_for_every_certificate(const Vec3q& p, const std::vector<Stick_witness>& vertices) {
  Json_writer w = head(p, "sticks");
  w.key("vertices").array();
  for (const Stick_witness& s : vertices) write_stick(w, s);
  return w.end_array().end_object().take();
}

std::string slides_for_every_certificate(const Vec3q& p, const Vec3q& twist, const std::vector<Rational>& u,
                                         const std::array<Rational, 3>& dual) {
  Json_writer w = head(p, "slides");
  w.key("twist").rationals(twist).key("speed_bounds").rationals(u).key("dual").rationals(dual);
  return w.end_object().take();
}

std::string depends_certificate(const Vec3q& p, const Stick_witness& sticking, const Slide_witness& sliding) {
  Json_writer w = head(p, "depends");
  write_stick(w.key("sticking"), sticking);
  w.key("sliding").object().key("distribution").rationals(sliding.distribution).key("twist").rationals(sliding.twist);
  w.key("speed_bounds").rationals(sliding.speed_bounds).end_object();
  return w.end_object().take();
}

}  // namespace wrenchkit
