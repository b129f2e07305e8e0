// [SL-4] [SL-6] The witnesses of one distribution: rational speed bounds and slide witnesses, the smoothed Newton
// witness of support forces (and a cone's weights), the precise one, and the refined stick witness.
#include <algorithm>
#include <cmath>

#include "exact/sliding/precise_motion.h"
#include "exact/sliding/strategies.h"

namespace wrenchkit {

std::vector<Rational> speed_bounds(const Support& s, const Vec3q& q, int bits) {
  std::vector<Rational> u;
  u.reserve(s.points.size());
  for (const Support_point& p : s.points) u.push_back(sqrt_bracket(speed_squared(q, p.at), bits).second);
  return u;
}

std::optional<Slide_witness> slide_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                           const Vec3q& q0, bool strict) {
  if (is_zero(q0)) return std::nullopt;
  const Vec3q q = primitive_vec(q0);  // (the same motion, written with integers)
  const Rational power = dot(q, p);
  const auto proves = [&](const std::vector<Rational>& u) {
    Rational bound;
    for (std::size_t i = 0; i < s.points.size(); ++i) bound += s.mu_of(s.points[i]) * f[i] * u[i];
    return strict ? power > bound : power >= bound;
  };
  Slide_witness w{f, q, speed_bounds(s, q), {}, {}};
  if (proves(w.speed_bounds)) return w;
  std::size_t b = 0;
  for (const Rational& c : q)
    b = std::max(b, mpz_sizeinbase(c.get_num_mpz_t(), 2) + mpz_sizeinbase(c.get_den_mpz_t(), 2));
  if (b <= 64) return std::nullopt;
  w.speed_bounds = speed_bounds(s, q, static_cast<int>(2 * b + 64));
  if (proves(w.speed_bounds)) return w;
  return std::nullopt;
}

// The cheap witness first (SL-4). In double: Newton's method on the smoothed dual
//   φ(λ) = Σ ρ_i H(|v_i(λ)|) + Σ_j P(λ·ĉ_j) − λ·p/σ,   H(t) = t²/2 for t ≤ 1, t − 1/2 beyond (ρ_i = μ_i f_i),
//   P(s) = s²/2 for s > 0, 0 below (the cone's wrenches c_j, scaled to ĉ_j; none for stick/slide),
// whose gradient Σ ρ_i A_i v_i/max(|v_i|, 1) + Σ_j max(λ·ĉ_j, 0) ĉ_j − p/σ vanishes where the forces
// ρ_i v_i/max(|v_i|, 1), each in its disc, and the non-negative multiples max(λ·ĉ_j, 0) of the cone's wrenches sum
// to p/σ (A_i g = (g, r_i × g), v_i(λ) = A_iᵀλ). φ has a minimiser when p/σ is inside the limit surface (plus the
// cone) and none when it is outside; σ = 1 − 2^-j for j = 1, 2, … (the first that converges leaves a slack
// ≥ half the load's own); each Newton run starts at the last minimiser found (the probe's, then the previous σ's:
// a few steps) and stops as soon as two steps leave λ where it was (rounding has the last word: the minimiser when
// the gradient is within 10^-9 of its terms, which the exact round then verifies, else no minimiser). Still points
// (rotation centres) are handled by the smoothing. Then one exact round: rational weights w_i = σ ρ_i/max(|v_i(λ)|, 1) and cone weights (the doubles, exactly), L solves
// Σ w_i A_i A_iᵀ L = p − Σ_j λ_j c_j exactly, g_i = w_i v_i(L), so Σ A_i g_i + Σ λ_j c_j = p exactly, and each disc
// is checked exactly (|g_i|² < ρ_i²). Nothing when no σ verifies (then the LP decides). O(k + cone) per Newton step.
std::optional<Support_witness> smoothed_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                                const std::vector<Vec3q>& cone, bool probe,
                                                std::array<double, 3>* escape, bool short_numbers) {
  // short_numbers: the exact round's weights rounded to 12 + j significant bits for σ = 1 − 2^-j (the slack
  // 2^-j absorbs the change), and cone weights below 2^-(12+j) of the forces' scale dropped: shorter rationals.
  const auto rounded = [&](double v, int j) {
    if (!short_numbers || !(v > 0)) return v;
    int e = 0;
    const double m = std::frexp(v, &e);
    return std::ldexp(std::nearbyint(std::ldexp(m, 12 + j)), e - 12 - j);
  };
  const std::size_t k = s.points.size();
  std::vector<double> x(k), y(k), rho(k);
  std::vector<Rational> rq(k);
  std::size_t carrying = 0;
  double rho_sum = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const Support_point& pt = s.points[i];
    rq[i] = s.mu_of(pt) * f[i];
    x[i] = pt.at.x.get_d(), y[i] = pt.at.y.get_d(), rho[i] = rq[i].get_d();
    carrying += rq[i] > 0;
    rho_sum += rho[i];
  }
  if (carrying < 2) return std::nullopt;
  const double pd[3] = {p[0].get_d(), p[1].get_d(), p[2].get_d()};
  for (double v : pd)
    if (!std::isfinite(v)) return std::nullopt;
  // The cone's wrenches scaled to length Σρ_i (their weights then compare with the forces), with the scale kept.
  std::vector<std::array<double, 3>> c;
  std::vector<double> c_scale;
  for (const Vec3q& w : cone) {
    const double d[3] = {w[0].get_d(), w[1].get_d(), w[2].get_d()};
    const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(n > 0) || !std::isfinite(n) || !(rho_sum > 0) || !std::isfinite(rho_sum)) return std::nullopt;
    c_scale.push_back(rho_sum / n);
    c.push_back({d[0] * c_scale.back(), d[1] * c_scale.back(), d[2] * c_scale.back()});
  }
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
    for (const auto& cj : c) {
      const double d = l[0] * cj[0] + l[1] * cj[1] + l[2] * cj[2];
      if (d > 0) v += d * d / 2;
    }
    return v;
  };
  // Minimise φ for one σ: the minimiser, or false when Newton does not converge (p/σ outside, or numerics).
  const auto minimise = [&](double sigma, double l[3]) {
    int still = 0;  // consecutive steps that left λ where it was (to rounding): Newton is done, converged or not
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
      double scale = pnorm;  // the gradient's terms' size: the load's, and the cone's forces (rounding cancels them)
      for (const auto& cj : c) {  // the cone's penalty: gradient max(λ·ĉ, 0) ĉ, Hessian ĉĉᵀ where active
        const double d = l[0] * cj[0] + l[1] * cj[1] + l[2] * cj[2];
        if (!(d > 0)) continue;
        for (std::size_t r = 0; r < 3; ++r) {
          g[r] += d * cj[r];
          scale += std::fabs(d * cj[r]);
          for (std::size_t cc = 0; cc < 3; ++cc) h[r][cc] += cj[r] * cj[cc];
        }
      }
      const double gn = std::fabs(g[0]) + std::fabs(g[1]) + std::fabs(g[2]);
      if (gn <= 1e-14 * scale) return true;
      double step[3];
      if (!solve3(h, g, step)) return false;
      double t = 1, f0 = phi(l, sigma), trial[3];
      for (;; t /= 2) {  // backtracking: φ must decrease
        for (int c = 0; c < 3; ++c) trial[c] = l[c] - t * step[c];
        if (phi(trial, sigma) <= f0 || t < 1e-12) break;
      }
      if (t < 1e-12) return gn <= 1e-9 * scale;  // no more progress: accept only a small gradient
      const double moved = std::fabs(trial[0] - l[0]) + std::fabs(trial[1] - l[1]) + std::fabs(trial[2] - l[2]);
      still = moved <= 1e-13 * (std::fabs(l[0]) + std::fabs(l[1]) + std::fabs(l[2])) ? still + 1 : 0;
      if (still >= 2) return gn <= 1e-9 * scale;  // the same stop
      for (int c = 0; c < 3; ++c) l[c] = trial[c];
      if (!(std::fabs(l[0]) + std::fabs(l[1]) + std::fabs(l[2]) < 1e150)) return false;  // unbounded: outside
    }
    return false;
  };
  // probe: first whether p itself (σ → 1) is inside at all. If not, no σ below can verify; the last iterate λ is
  // the escape: φ decreases along it without bound, so λ·p > h_f(λ) and λ·c_j ≤ 0 to first order.
  double start[3] = {0, 0, 0};  // each run starts at the last minimiser found (warm: a few Newton steps)
  if (probe) {
    double l[3] = {0, 0, 0};
    if (!minimise(1 - std::ldexp(1.0, -40), l)) {
      if (escape) *escape = {l[0], l[1], l[2]};
      return std::nullopt;
    }
    std::copy(l, l + 3, start);
  }
  for (int j = 1; j <= 50; ++j) {
    const double sigma = 1 - std::ldexp(1.0, -j);
    double l[3] = {start[0], start[1], start[2]};
    if (!minimise(sigma, l)) continue;
    std::copy(l, l + 3, start);
    // The exact round with rational weights (the doubles, exactly).
    std::vector<Rational> w(k);
    Rational M[3][3];
    for (std::size_t i = 0; i < k; ++i) {
      if (rq[i] == 0) continue;
      const double t = std::hypot(l[0] - l[2] * y[i], l[1] + l[2] * x[i]);
      const double wi = rounded(sigma * rho[i] / std::max(t, 1.0), j);
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
    // The cone's weights σ·max(λ·ĉ_j, 0) on ĉ_j = scale_j c_j, exactly as doubles; the forces carry the rest.
    Support_witness out{std::vector<Vec2>(k), std::vector<Rational>(cone.size())};
    Vec3q rest = p;
    for (std::size_t jj = 0; jj < cone.size(); ++jj) {
      const double d = l[0] * c[jj][0] + l[1] * c[jj][1] + l[2] * c[jj][2];  // the weight on ĉ_jj, |ĉ_jj| = Σρ_i
      const double lambda =
          d > 0 && !(short_numbers && sigma * d < std::ldexp(1.0, -12 - j)) ? rounded(sigma * d * c_scale[jj], j) : 0;
      if (!std::isfinite(lambda)) continue;
      out.weights[jj] = Rational(lambda);
      if (lambda > 0)
        for (std::size_t r = 0; r < 3; ++r) rest[r] -= out.weights[jj] * cone[jj][r];
    }
    Rational L[3];
    for (int col = 0; col < 3; ++col) {
      Rational mc[3][3];
      for (int r = 0; r < 3; ++r)
        for (int cc = 0; cc < 3; ++cc) mc[r][cc] = cc == col ? rest[static_cast<std::size_t>(r)] : M[r][cc];
      L[col] = (mc[0][0] * (mc[1][1] * mc[2][2] - mc[1][2] * mc[2][1]) -
                mc[0][1] * (mc[1][0] * mc[2][2] - mc[1][2] * mc[2][0]) +
                mc[0][2] * (mc[1][0] * mc[2][1] - mc[1][1] * mc[2][0])) /
               det;
    }
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

std::optional<Impending_witness> impending_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                                   const Vec3q& q0) {
  if (is_zero(q0)) return std::nullopt;
  const Vec3q q = primitive_vec(q0);  // (the same motion, written with small integers)
  const std::size_t k = s.points.size();
  Impending_witness w{{f, std::vector<Vec2>(k), {}}, {f, q, std::vector<Rational>(k), {}, {}}};
  Rational bound, still;  // still: the friction of the points at rest (the rotation centre's)
  Vec3q rest = p;         // what the points at rest must carry
  std::vector<std::size_t> at_rest;
  for (std::size_t i = 0; i < k; ++i) {
    const Support_point& pt = s.points[i];
    const Rational rho = s.mu_of(pt) * f[i];
    const Rational s2 = speed_squared(q, pt.at);
    Rational& u = w.twist.speed_bounds[i];
    if (s2 == 0) {
      if (rho > 0) at_rest.push_back(i), still += rho;
      continue;  // u = 0
    }
    const auto [lo, hi] = sqrt_bracket(s2);
    if (lo != hi && rho > 0) return std::nullopt;  // an irrational speed: no rational bound meets the power
    u = hi;
    if (rho == 0) continue;
    bound += rho * u;
    const Vec2 v = velocity(q, pt.at);
    Vec2& g = w.forces.forces[i];
    g = {rho * v.x / u, rho * v.y / u};
    const Vec3q a = wrench_at(pt.at, g);
    for (std::size_t c = 0; c < 3; ++c) rest[c] -= a[c];
  }
  if (dot(q, p) != bound) return std::nullopt;
  if (at_rest.empty()) return is_zero(rest) ? std::optional<Impending_witness>(std::move(w)) : std::nullopt;
  // The rest as one force g at the centre c (the points at rest coincide there): moment c × g, |g| ≤ their friction.
  const Vec2& c = s.points[at_rest.front()].at;
  const Vec2 g{rest[0], rest[1]};
  if (rest[2] != cross(c, g) || dot(g, g) > still * still) return std::nullopt;
  for (const std::size_t i : at_rest) {
    const Rational share = s.mu_of(s.points[i]) * f[i] / still;
    w.forces.forces[i] = {share * g.x, share * g.y};
  }
  return w;
}

std::optional<Slide_witness> slides_for_every(const Support& s, const Admissible& a, const Vec3q& p, const Vec3q& q,
                                              bool strict) {
  if (is_zero(q)) return std::nullopt;
  std::vector<Rational> u = speed_bounds(s, q);
  std::vector<Rational> coef(u.size());  // μ_i times the rational upper bound of |v_i(q)|
  for (std::size_t i = 0; i < coef.size(); ++i) coef[i] = s.mu_of(s.points[i]) * u[i];
  const F_optimum o = maximise_over(s, a, coef);
  const Rational power = dot(q, p);
  if (strict ? !(power > o.value) : power < o.value) return std::nullopt;
  return Slide_witness{{}, q, std::move(u), {}, o.dual};
}

std::optional<Stick_witness> stick_witness_refined(const Support& s, const Admissible& a, const Vec3q& p, int sides,
                                                   const std::vector<Rational>& f) {
  if (auto w = smoothed_stick_witness(s, f, p)) return w;
  if (auto w = precise_witness(s, f, p).sticks) return w;
  for (int n = sides; n <= 256 && s.points.size() * static_cast<std::size_t>(n) <= kMaxStickWitnessColumns; n *= 2)
    if (auto w = stick_witness(s, a, p, n, &f)) return w;
  return std::nullopt;
}

std::optional<Stick_witness> smoothed_stick_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p) {
  if (auto w = smoothed_witness(s, f, p, {}, false, nullptr, false)) return Stick_witness{f, std::move(w->forces), {}};
  return std::nullopt;
}

Precise_witness precise_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p) {
  std::vector<Rho_point> pts;
  pts.reserve(s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Support_point& pt = s.points[i];
    pts.push_back({pt.at, s.mu_of(pt) * f[i]});
  }
  Precise_motion m = precise_motion(pts, p);
  Precise_witness w;
  if (m.motion == Motion::sticks) w.sticks = Stick_witness{f, std::move(m.forces), {}};
  if (m.motion == Motion::slides) w.slides = Slide_witness{f, m.twist, std::move(m.speed_bounds), {}, {}};
  return w;
}

}  // namespace wrenchkit
