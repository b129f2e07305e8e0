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

namespace {

// The cheap witness first (SL-4): support forces g_i = w_i v_i(λ) along the velocities of one twist λ, with the
// weights w_i = ρ_i / |v_i(λ_prev)| of a few rounds in double (the direction of λ converges to the twist whose
// boundary load is on p's ray, and |g_i| → s ρ_i with s < 1 for an interior p); the last round is exact: λ solves
// the 3×3 system Σ w_i A_i v_i(λ) = p in rationals, so Σ (g_i, r_i × g_i) = p exactly, and the discs are checked
// exactly (|g_i|² < ρ_i²). Nothing when a disc is not strictly kept (then the LP decides). O(k) per round.
std::optional<Stick_witness> weighted_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p) {
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
  // M(w) = Σ w_i A_i A_i^T with A_i^T λ = v_i(λ) = (λx − λm y_i, λy + λm x_i); A_i g = (g, x_i g_y − y_i g_x).
  const auto solve3 = [](double m[3][3], const double b[3], double out[3]) {
    const double d = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (!(std::fabs(d) > 0)) return false;
    for (int c = 0; c < 3; ++c) {
      double mc[3][3];
      for (int r = 0; r < 3; ++r)
        for (int cc = 0; cc < 3; ++cc) mc[r][cc] = cc == c ? b[r] : m[r][cc];
      out[c] = (mc[0][0] * (mc[1][1] * mc[2][2] - mc[1][2] * mc[2][1]) - mc[0][1] * (mc[1][0] * mc[2][2] - mc[1][2] * mc[2][0]) +
                mc[0][2] * (mc[1][0] * mc[2][1] - mc[1][1] * mc[2][0])) / d;
    }
    return true;
  };
  std::vector<double> w(rho);
  double lam[3] = {pd[0], pd[1], pd[2]};
  for (int round = 0; round < 40; ++round) {
    double m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    for (std::size_t i = 0; i < k; ++i) {
      if (rho[i] == 0) continue;
      const double vx = lam[0] - lam[2] * y[i], vy = lam[1] + lam[2] * x[i], sp = std::hypot(vx, vy);
      w[i] = round == 0 || sp == 0 ? rho[i] : rho[i] / sp;
      // Column j of A_i A_i^T: A_i applied to v_i(e_j).
      const double cols[3][2] = {{1, 0}, {0, 1}, {-y[i], x[i]}};
      for (int c = 0; c < 3; ++c) {
        const double gx = cols[c][0], gy = cols[c][1];
        m[0][c] += w[i] * gx, m[1][c] += w[i] * gy, m[2][c] += w[i] * (x[i] * gy - y[i] * gx);
      }
    }
    double next[3];
    if (!solve3(m, pd, next)) return std::nullopt;
    lam[0] = next[0], lam[1] = next[1], lam[2] = next[2];
  }
  // The exact round with rational weights (the last doubles, exactly).
  Rational M[3][3];
  for (std::size_t i = 0; i < k; ++i) {
    if (rq[i] == 0 || !std::isfinite(w[i])) continue;
    const Rational wi(w[i]);
    const Vec2& r = s.points[i].at;
    const Rational cols[3][2] = {{1, 0}, {0, 1}, {-r.y, r.x}};
    for (int c = 0; c < 3; ++c) {
      M[0][c] += wi * cols[c][0];
      M[1][c] += wi * cols[c][1];
      M[2][c] += wi * (r.x * cols[c][1] - r.y * cols[c][0]);
    }
  }
  const Rational det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                       M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  if (det == 0) return std::nullopt;
  Rational L[3];
  for (int c = 0; c < 3; ++c) {
    Rational mc[3][3];
    for (int r = 0; r < 3; ++r)
      for (int cc = 0; cc < 3; ++cc) mc[r][cc] = cc == c ? p[static_cast<std::size_t>(r)] : M[r][cc];
    L[c] = (mc[0][0] * (mc[1][1] * mc[2][2] - mc[1][2] * mc[2][1]) - mc[0][1] * (mc[1][0] * mc[2][2] - mc[1][2] * mc[2][0]) +
            mc[0][2] * (mc[1][0] * mc[2][1] - mc[1][1] * mc[2][0])) / det;
  }
  Stick_witness out{f, std::vector<Vec2>(k)};
  for (std::size_t i = 0; i < k; ++i) {
    if (rq[i] == 0 || !std::isfinite(w[i])) continue;
    const Rational wi(w[i]);
    const Vec2& r = s.points[i].at;
    out.forces[i] = {wi * (L[0] - L[2] * r.y), wi * (L[1] + L[2] * r.x)};
    if (!(out.forces[i].x * out.forces[i].x + out.forces[i].y * out.forces[i].y < rq[i] * rq[i])) return std::nullopt;
  }
  return out;
}

}  // namespace

std::optional<Stick_witness> stick_witness_refined(const Support& s, const Admissible& a, const Vec3q& p, int sides,
                                                   const std::vector<Rational>& f) {
  if (auto w = weighted_witness(s, f, p)) return w;
  for (int n = sides; n <= 1024 && s.points.size() * static_cast<std::size_t>(n) <= kMaxStickWitnessColumns; n *= 2)
    if (auto w = stick_witness(s, a, p, n, &f)) return w;
  return std::nullopt;
}

namespace {

void write_forces(Json_writer& w, const std::vector<Vec2>& g) {
  w.array();
  for (const Vec2& f : g) w.array().rational(f.x).rational(f.y).end_array();
  w.end_array();
}

// The certificate's object, opened, with its first members: the load and the motion.
Json_writer head(const Vec3q& p, const char* motion) {
  Json_writer w(512);
  w.object().member("wrenchkit_certificate", 1).member("property", "motion").key("load").rationals(p);
  w.member("motion", motion);
  return w;
}

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
