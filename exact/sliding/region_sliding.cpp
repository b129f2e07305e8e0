// Sliding over support regions [RG-1] [RG-2]; derivations in proofs/notes/RG-1-regions.md (the certificates) and
// proofs/notes/RG-2-fan-integrals.md (the closed form and its interval evaluation).
#include "exact/sliding/region_sliding.h"

#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <stdexcept>
#include <utility>

#include "exact/numbers/work_budget.h"
#include "exact/sliding/strategies.h"
#include "exact/sliding/sliding.h"

namespace wrenchkit {

namespace {

// ---------------------------------------------------------------------------------------------------------------
// An interval [lo, hi] of MPFR numbers at one precision, every operation rounded outward (lo down, hi up): it
// always contains the exact value of the expression it stands for [RG-2].
class Ival {
 public:
  explicit Ival(long bits) {
    mpfr_init2(lo_, bits);
    mpfr_init2(hi_, bits);
    mpfr_set_zero(lo_, 1);
    mpfr_set_zero(hi_, 1);
  }
  Ival(const Rational& q, long bits) : Ival(bits) {
    mpfr_set_q(lo_, q.get_mpq_t(), MPFR_RNDD);
    mpfr_set_q(hi_, q.get_mpq_t(), MPFR_RNDU);
  }
  Ival(const Ival& o) : Ival(mpfr_get_prec(o.lo_)) {
    mpfr_set(lo_, o.lo_, MPFR_RNDD);
    mpfr_set(hi_, o.hi_, MPFR_RNDU);
  }
  Ival& operator=(const Ival& o) {
    if (this != &o) {
      mpfr_set(lo_, o.lo_, MPFR_RNDD);
      mpfr_set(hi_, o.hi_, MPFR_RNDU);
    }
    return *this;
  }
  ~Ival() {
    mpfr_clear(lo_);
    mpfr_clear(hi_);
  }
  long bits() const { return mpfr_get_prec(lo_); }
  Rational lower() const { return to_q(lo_); }
  Rational upper() const { return to_q(hi_); }

  friend Ival operator+(const Ival& a, const Ival& b) {
    Ival r(a.bits());
    mpfr_add(r.lo_, a.lo_, b.lo_, MPFR_RNDD);
    mpfr_add(r.hi_, a.hi_, b.hi_, MPFR_RNDU);
    return r;
  }
  friend Ival operator-(const Ival& a, const Ival& b) {
    Ival r(a.bits());
    mpfr_sub(r.lo_, a.lo_, b.hi_, MPFR_RNDD);
    mpfr_sub(r.hi_, a.hi_, b.lo_, MPFR_RNDU);
    return r;
  }
  friend Ival operator*(const Ival& a, const Ival& b) {
    Ival r(a.bits());
    mpfr_t t;
    mpfr_init2(t, a.bits());
    const mpfr_srcptr ends[2][2] = {{a.lo_, a.hi_}, {b.lo_, b.hi_}};
    bool first = true;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        mpfr_mul(t, ends[0][i], ends[1][j], MPFR_RNDD);
        if (first || mpfr_less_p(t, r.lo_)) mpfr_set(r.lo_, t, MPFR_RNDD);
        mpfr_mul(t, ends[0][i], ends[1][j], MPFR_RNDU);
        if (first || mpfr_greater_p(t, r.hi_)) mpfr_set(r.hi_, t, MPFR_RNDU);
        first = false;
      }
    mpfr_clear(t);
    return r;
  }
  // Division by an interval that does not contain 0 (throws otherwise: the caller raises the precision).
  friend Ival operator/(const Ival& a, const Ival& b) {
    if (mpfr_sgn(b.lo_) <= 0 && mpfr_sgn(b.hi_) >= 0) throw std::range_error("interval division by an interval holding 0");
    Ival r(a.bits());
    mpfr_t t;
    mpfr_init2(t, a.bits());
    const mpfr_srcptr num[2] = {a.lo_, a.hi_}, den[2] = {b.lo_, b.hi_};
    bool first = true;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        mpfr_div(t, num[i], den[j], MPFR_RNDD);
        if (first || mpfr_less_p(t, r.lo_)) mpfr_set(r.lo_, t, MPFR_RNDD);
        mpfr_div(t, num[i], den[j], MPFR_RNDU);
        if (first || mpfr_greater_p(t, r.hi_)) mpfr_set(r.hi_, t, MPFR_RNDU);
        first = false;
      }
    mpfr_clear(t);
    return r;
  }
  friend Ival operator*(const Ival& a, long k) {
    Ival r(a.bits());
    mpfr_mul_si(r.lo_, k >= 0 ? a.lo_ : a.hi_, k, MPFR_RNDD);
    mpfr_mul_si(r.hi_, k >= 0 ? a.hi_ : a.lo_, k, MPFR_RNDU);
    return r;
  }
  friend Ival operator/(const Ival& a, long k) {  // k > 0
    Ival r(a.bits());
    mpfr_div_si(r.lo_, a.lo_, k, MPFR_RNDD);
    mpfr_div_si(r.hi_, a.hi_, k, MPFR_RNDU);
    return r;
  }
  // √ of a nonnegative interval (a lower end below 0 is a rounding artefact of a true value ≥ 0: clamped).
  friend Ival sqrt_(const Ival& a) {
    Ival r(a.bits());
    if (mpfr_sgn(a.lo_) <= 0) mpfr_set_zero(r.lo_, 1);
    else mpfr_sqrt(r.lo_, a.lo_, MPFR_RNDD);
    mpfr_sqrt(r.hi_, a.hi_, MPFR_RNDU);
    return r;
  }
  friend Ival asinh_(const Ival& a) {  // increasing
    Ival r(a.bits());
    mpfr_asinh(r.lo_, a.lo_, MPFR_RNDD);
    mpfr_asinh(r.hi_, a.hi_, MPFR_RNDU);
    return r;
  }

 private:
  static Rational to_q(const mpfr_t x) {
    Rational q;
    mpfr_get_q(q.get_mpq_t(), x);
    return q;
  }
  mpfr_t lo_, hi_;
};

double sqrt_(double x) { return std::sqrt(std::max(x, 0.0)); }
double asinh_(double x) { return std::asinh(x); }

// The exact scalars of one directed boundary edge a → b seen from the centre c (a' = a − c, b' = b − c,
// e = b − a): cr = a' × b' (≠ 0), L2 = e·e, sa = a'·e, sb = b'·e, a2 = |a'|², b2 = |b'|², and of the pressure
// p(r) = p(c) + g·(r − c): pc = p(c), gxe = g × e, gde = g·e.
template <class N>
struct Edge_scalars {
  N cr, acr, L2, sa, sb, a2, b2, gxe, gde, pc, ex, ey;
};

// [RG-2] The signed fan triangle (c, a, b): adds ∫ |r − c| p dA to K and ∫ (r − c)/|r − c| p dA to J (signed by the
// triangle's orientation). With d = cr/L the signed distance of c from the edge's line, s the tangent coordinate
// (s_a = sa/L, s_b = sb/L), D = |d|, A = asinh(s/D) = asinh(sa/|cr|):
//   K = p_c [d(s|r|)/6 + d D² A/6] + g_n [d²(s|r|)/8 + d⁴ A/8] + g_e d |r|³/12          evaluated from a to b,
//   J_n = d² [(p_c/2 + g_n d/3) A + (g_e/3)|r|],  J_e = d [(p_c/2 + g_n d/3)|r| + (g_e/6)(s|r| − d² A)],
// with g_n = g × e/L, g_e = g·e/L (n̂ = (e_y, −e_x)/L, ê = e/L). Written with one root L per edge.
template <class N>
void fan_edge(const Edge_scalars<N>& e, N& K, N& Jx, N& Jy) {
  const N L = sqrt_(e.L2), na = sqrt_(e.a2), nb = sqrt_(e.b2);
  const N dA = asinh_(e.sb / e.acr) - asinh_(e.sa / e.acr);
  const N cr2 = e.cr * e.cr, L4 = e.L2 * e.L2;
  const N t1 = nb * e.sb - na * e.sa;        // L·(s_b|b| − s_a|a|)
  const N t3 = e.b2 * nb - e.a2 * na;        // |b|³ − |a|³
  const N alpha = e.pc * e.cr / (e.L2 * 6) + e.gxe * cr2 / (L4 * 8);
  const N beta = e.pc * cr2 * e.cr / (e.L2 * 6) + e.gxe * cr2 * cr2 / (L4 * 8);
  const N gamma = e.gde * e.cr / (e.L2 * 12);
  K = K + alpha * t1 + beta * dA / L + gamma * t3;
  const N P = e.pc / 2 + e.gxe * e.cr / (e.L2 * 3);
  const N dn = nb - na;
  const N Jn = cr2 / e.L2 * (P * dA + e.gde * dn / (L * 3));
  const N Je = e.cr / L * P * dn + e.cr * e.gde / (e.L2 * 6) * (t1 / L - cr2 * dA / e.L2);
  Jx = Jx + (Jn * e.ey + Je * e.ex) / L;
  Jy = Jy + (Je * e.ey - Jn * e.ex) / L;
}

template <class F>
void for_each_edge(const Support_region& r, F f) {
  for (const auto& ring : r.rings)
    for (std::size_t i = 0; i < ring.size(); ++i) f(ring[i], ring[(i + 1) % ring.size()]);
}


}  // namespace

Fan_bracket fan_integrals(const Support_region& r, const Vec2& c, long bits) {
  Ival K(bits), Jx(bits), Jy(bits);
  const Rational& g0 = r.pressure[1];
  const Rational& g1 = r.pressure[2];
  const Rational pc = pressure_at(r.pressure, c);
  const Ival pc_i(pc, bits);
  for_each_edge(r, [&](const Vec2& a, const Vec2& b) {
    const Vec2 A{a.x - c.x, a.y - c.y}, B{b.x - c.x, b.y - c.y}, e{b.x - a.x, b.y - a.y};
    const Rational cr = cross(A, B);
    if (cr == 0) return;  // c on the edge's line: a degenerate fan triangle
    const Edge_scalars<Ival> s{Ival(cr, bits), Ival(abs(cr), bits), Ival(e.x * e.x + e.y * e.y, bits),
                               Ival(A.x * e.x + A.y * e.y, bits), Ival(B.x * e.x + B.y * e.y, bits),
                               Ival(A.x * A.x + A.y * A.y, bits), Ival(B.x * B.x + B.y * B.y, bits),
                               Ival(g0 * e.y - g1 * e.x, bits), Ival(g0 * e.x + g1 * e.y, bits), pc_i,
                               Ival(e.x, bits), Ival(e.y, bits)};
    fan_edge(s, K, Jx, Jy);
  });
  return {K.lower(), K.upper(), {Jx.lower(), Jy.lower()}, {Jx.upper(), Jy.upper()}};
}

double fan_power_double(const Support_region& r, double cx, double cy) {
  const Support_region::Doubles& d = r.d;
  const double pc = d.pressure[0] + d.pressure[1] * cx + d.pressure[2] * cy, g0 = d.pressure[1], g1 = d.pressure[2];
  double K = 0, Jx = 0, Jy = 0;
  for (const auto& ring : d.rings)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const auto& a = ring[i];
      const auto& b = ring[(i + 1) % ring.size()];
      const double ax = a[0] - cx, ay = a[1] - cy, bx = b[0] - cx, by = b[1] - cy;
      const double ex = bx - ax, ey = by - ay, cr = ax * by - ay * bx;
      if (cr == 0) continue;
      const Edge_scalars<double> s{cr, std::fabs(cr), ex * ex + ey * ey, ax * ex + ay * ey, bx * ex + by * ey,
                                   ax * ax + ay * ay, bx * bx + by * by, g0 * ey - g1 * ex, g0 * ex + g1 * ey, pc, ex, ey};
      fan_edge(s, K, Jx, Jy);
    }
  return K;
}

double region_power_double(const Support_region& r, const double* q) {
  const Support_region::Doubles& d = r.d;
  if (q[2] == 0) return d.total * std::hypot(q[0], q[1]);
  const double cx = -q[1] / q[2], cy = q[0] / q[2];
  // The closed form cancels badly for a centre far from the region (its terms grow like the distance squared, the
  // sum like the distance): there |v| is smooth, and the 7-point rule on the triangles cut in four is accurate.
  if (std::hypot(cx - d.gx, cy - d.gy) <= 8 * d.radius) return std::fabs(q[2]) * fan_power_double(r, cx, cy);
  const double p0 = d.pressure[0], p1 = d.pressure[1], p2 = d.pressure[2];
  double h = 0;
  const auto f = [&](double x, double y) { return std::hypot(q[0] - q[2] * y, q[1] + q[2] * x) * (p0 + p1 * x + p2 * y); };
  for (const auto& t : d.triangles) {
    const double P[3][2] = {{t[0], t[1]}, {t[2], t[3]}, {t[4], t[5]}};
    const double M[3][2] = {{(P[0][0] + P[1][0]) / 2, (P[0][1] + P[1][1]) / 2},
                            {(P[1][0] + P[2][0]) / 2, (P[1][1] + P[2][1]) / 2},
                            {(P[2][0] + P[0][0]) / 2, (P[2][1] + P[0][1]) / 2}};
    const double (*sub[4][3])[2] = {{&P[0], &M[0], &M[2]}, {&M[0], &P[1], &M[1]}, {&M[2], &M[1], &P[2]}, {&M[0], &M[1], &M[2]}};
    for (const auto& tri : sub) {
      const double *a = *tri[0], *b = *tri[1], *c = *tri[2];
      const double area = std::fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
      double v = 27 * f((a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3);
      v += 3 * (f(a[0], a[1]) + f(b[0], b[1]) + f(c[0], c[1]));
      v += 8 * (f((a[0] + b[0]) / 2, (a[1] + b[1]) / 2) + f((b[0] + c[0]) / 2, (b[1] + c[1]) / 2) +
                f((c[0] + a[0]) / 2, (c[1] + a[1]) / 2));
      h += area * v / 60;
    }
  }
  return h;
}

namespace {

// A rational interval scaled by a rational.
std::pair<Rational, Rational> scaled(const Rational& k, const Rational& lo, const Rational& hi) {
  return k >= 0 ? std::make_pair(k * lo, k * hi) : std::make_pair(k * hi, k * lo);
}

}  // namespace

Region_sliding region_sliding(const Support& s, const std::optional<Vec3q>& q, const Rational& tolerance) {
  Region_sliding a;
  Vec2 moment{0, 0}, rho_r{0, 0};
  for (const Support_point& p : s.points) {
    const Rational& f = *p.force;
    const Rational rho = s.mu_of(p) * f;
    a.total_force += f;
    moment.x += f * p.at.x, moment.y += f * p.at.y;
    a.mu_f0 += rho;
    rho_r.x += rho * p.at.x, rho_r.y += rho * p.at.y;
  }
  for (const Support_region& r : s.regions) {
    const Rational mu = s.mu_of(r);
    a.total_force += r.total;
    moment.x += r.moment.x, moment.y += r.moment.y;
    a.mu_f0 += mu * r.total;
    rho_r.x += mu * r.moment.x, rho_r.y += mu * r.moment.y;
  }
  a.center_of_pressure = {moment.x / a.total_force, moment.y / a.total_force};
  a.friction_centroid = a.mu_f0 > 0 ? Vec2{rho_r.x / a.mu_f0, rho_r.y / a.mu_f0} : a.center_of_pressure;
  if (!q) return a;
  const Vec3q& t = *q;
  if (t[0] == 0 && t[1] == 0 && t[2] == 0) throw std::invalid_argument("region_sliding: zero twist");
  a.has_twist = true;
  a.twist = t;
  a.translation = t[2] == 0;
  if (a.translation) {
    // Every point of the body moves with v: h = μW|v|, the load (μW/|v|)(v, c × v) through the friction centroid.
    const Vec2& c = a.friction_centroid;
    a.load_direction = {t[0], t[1], c.x * t[1] - c.y * t[0]};
    a.speed_squared = t[0] * t[0] + t[1] * t[1];
    for (int bits = 64;; bits *= 2) {
      const auto [lo, hi] = sqrt_bracket(a.speed_squared, bits);
      a.h_lo = a.mu_f0 * lo, a.h_hi = a.mu_f0 * hi;
      for (int k = 0; k < 3; ++k) {
        const auto [l, h] = scaled(a.load_direction[k], a.mu_f0 / hi, a.mu_f0 / lo);
        a.load_lo[k] = l, a.load_hi[k] = h;
      }
      if (lo == hi) {
        a.load = Vec3q{a.mu_f0 / lo * t[0], a.mu_f0 / lo * t[1], a.mu_f0 / lo * a.load_direction[2]};
        break;
      }
      if (a.h_hi - a.h_lo <= tolerance * a.h_lo || bits >= 8192) {
        a.met = a.h_hi - a.h_lo <= tolerance * a.h_lo;
        a.bits = bits;
        break;
      }
    }
    return a;
  }
  const Vec2 c{-t[1] / t[2], t[0] / t[2]};
  a.rotation_center = c;
  const Rational w = abs(t[2]);
  const int sense = t[2] > 0 ? 1 : -1;
  for (const Support_point& p : s.points)
    if (p.at.x == c.x && p.at.y == c.y && s.mu_of(p) * *p.force > 0)
      a.center_on_point = true;
  for (long bits = 64;; bits *= 2) {
    Rational h_lo, h_hi;
    Vec3q lo{0, 0, 0}, hi{0, 0, 0};
    for (const Support_point& p : s.points)
      add_point_bracket(p.at, s.mu_of(p) * *p.force, t, static_cast<int>(bits), h_lo,
                        h_hi, lo, hi, true);
    for (const Support_region& r : s.regions) {
      const Rational mu = s.mu_of(r);
      if (mu == 0) continue;
      const Fan_bracket f = fan_integrals(r, c, bits);
      h_lo += mu * w * f.k_lo, h_hi += mu * w * f.k_hi;
      // F = μ sgn(ω) rot90(J) = μ sgn(ω)(−J_y, J_x); m = μ sgn(ω)(K + c·J).
      const Rational ms = mu * sense;
      auto [fx_lo, fx_hi] = scaled(-ms, f.j_lo.y, f.j_hi.y);
      auto [fy_lo, fy_hi] = scaled(ms, f.j_lo.x, f.j_hi.x);
      const auto [cx_lo, cx_hi] = scaled(c.x, f.j_lo.x, f.j_hi.x);
      const auto [cy_lo, cy_hi] = scaled(c.y, f.j_lo.y, f.j_hi.y);
      auto [m_lo, m_hi] = scaled(ms, f.k_lo + cx_lo + cy_lo, f.k_hi + cx_hi + cy_hi);
      lo[0] += fx_lo, hi[0] += fx_hi, lo[1] += fy_lo, hi[1] += fy_hi, lo[2] += m_lo, hi[2] += m_hi;
    }
    a.h_lo = h_lo, a.h_hi = h_hi, a.load_lo = lo, a.load_hi = hi, a.bits = bits;
    a.met = h_hi - h_lo <= tolerance * h_lo;
    if (a.met || bits >= 8192) break;
  }
  return a;
}

// ---------------------------------------------------------------------------------------------------------------
// Certificate blocks.

Vec3q region_stick_wrench(const Support_region& r, const Region_stick_block& b) {
  Vec3q sum{0, 0, 0};
  for (std::size_t k = 0; k < b.cells.triangles.size(); ++k) {
    const auto& t = b.cells.triangles[k];
    const Triangle_measures m =
        triangle_measures({b.cells.vertices[t[0]], b.cells.vertices[t[1]], b.cells.vertices[t[2]]}, r.pressure);
    const Vec2& g = b.forces[k];
    sum[0] += g.x, sum[1] += g.y;
    sum[2] += (m.moment.x * g.y - m.moment.y * g.x) / m.force;  // c_k × g_k, c_k = moment/F_k
  }
  return sum;
}

std::vector<Support_point> cell_points(const Support_region& r, const Rational& mu, const Region_cells& cells) {
  std::vector<Support_point> out;
  out.reserve(cells.triangles.size());
  for (const auto& t : cells.triangles) {
    const Triangle_measures m =
        triangle_measures({cells.vertices[t[0]], cells.vertices[t[1]], cells.vertices[t[2]]}, r.pressure);
    Support_point p;
    p.at = {m.moment.x / m.force, m.moment.y / m.force};
    p.force = m.force;
    p.mu = mu;
    out.push_back(std::move(p));
  }
  return out;
}

Region_slide_block region_slide_block(const Support_region& r, const Rational& mu, const Vec3q& q,
                                      const std::optional<Rational>& target, std::size_t max_cells) {
  // The speed bounds share one power-of-two denominator 2^k (u = (⌊√⌊|v|² 4^k⌋⌋ + 1)/2^k ≥ |v|, about 2^-44 of the
  // largest speed above it), so the exact sum of the cells' bounds keeps small denominators. Refinement runs in
  // double (each cell's bound Σ_j w_j u_j and its excess over Jensen's lower bound F·|v(c_T)|, c_T the pressure
  // centroid: the cell with the largest excess is cut into four at its edges' midpoints); the exact bound is
  // summed once at the end and, should rounding have fooled the doubles, the refinement goes on.
  const double qd[3] = {q[0].get_d(), q[1].get_d(), q[2].get_d()};
  const auto speed_d = [&](double x, double y) { return std::hypot(qd[0] - qd[2] * y, qd[1] + qd[2] * x); };
  double vmax = 0;
  for (const auto& ring : r.rings)
    for (const Vec2& v : ring) vmax = std::max(vmax, speed_d(v.x.get_d(), v.y.get_d()));
  int e = 0;
  std::frexp(vmax > 0 && std::isfinite(vmax) ? vmax : 1.0, &e);
  const long k = std::max(0L, 44L - e);  // 2^k: u to about 2^-44 of vmax
  Integer scale;
  mpz_ui_pow_ui(scale.get_mpz_t(), 2, static_cast<unsigned long>(k));
  const Rational step(Integer(1), scale);
  struct Cell {
    std::array<std::size_t, 3> v;
    double bound = 0, excess = 0;
    bool alive = true;
  };
  std::vector<Vec2> vertices;
  std::vector<double> xd, yd;
  std::vector<Rational> u;
  std::vector<double> ud;
  std::map<std::pair<Rational, Rational>, std::size_t> index;
  const auto vertex = [&](const Vec2& p) {
    const auto [at, fresh] = index.emplace(std::make_pair(p.x, p.y), vertices.size());
    if (fresh) {
      vertices.push_back(p);
      xd.push_back(p.x.get_d());
      yd.push_back(p.y.get_d());
      const Rational speed2 = speed_squared(q, p);
      if (mpz_perfect_square_p(speed2.get_num_mpz_t()) && mpz_perfect_square_p(speed2.get_den_mpz_t())) {
        Integer n, d;  // a rational speed is its own bound (a translation with |v| rational: the bound is exact)
        mpz_sqrt(n.get_mpz_t(), speed2.get_num_mpz_t());
        mpz_sqrt(d.get_mpz_t(), speed2.get_den_mpz_t());
        u.push_back(Rational(n, d));
      } else {
        const Rational s2 = speed2 * scale * scale;  // |v|² 4^k
        Integer floor_s2 = s2.get_num() / s2.get_den(), root;
        mpz_sqrt(root.get_mpz_t(), floor_s2.get_mpz_t());
        u.push_back(Rational(root + 1, scale));
      }
      u.back().canonicalize();
      ud.push_back(u.back().get_d());
    }
    return at->second;
  };
  const double p0 = r.pressure[0].get_d(), p1 = r.pressure[1].get_d(), p2 = r.pressure[2].get_d();
  std::vector<Cell> cells;
  std::priority_queue<std::pair<double, std::size_t>> queue;
  double total = 0, lower = 0;  // the bound, and Jensen's lower bound Σ F_T |v(c_T)| ≤ ∫ |v| p (doubles)
  const auto add = [&](const std::array<std::size_t, 3>& v) {
    const double ax = xd[v[0]], ay = yd[v[0]], bx = xd[v[1]], by = yd[v[1]], cx = xd[v[2]], cy = yd[v[2]];
    const double area = std::fabs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) / 2;
    const double pa = p0 + p1 * ax + p2 * ay, pb = p0 + p1 * bx + p2 * by, pc = p0 + p1 * cx + p2 * cy, all = pa + pb + pc;
    Cell c{v};
    c.bound = area * ((pa + all) * ud[v[0]] + (pb + all) * ud[v[1]] + (pc + all) * ud[v[2]]) / 12;
    // Pressure centroid: (∫ r p)/F with the edge-midpoint rule.
    const double F = area * all / 3;
    double gx = (ax + bx + cx) / 3, gy = (ay + by + cy) / 3;
    if (F > 0) {
      const double m[3][2] = {{(ax + bx) / 2, (ay + by) / 2}, {(bx + cx) / 2, (by + cy) / 2}, {(cx + ax) / 2, (cy + ay) / 2}};
      double sx = 0, sy = 0;
      for (const auto& t : m) {
        const double pm = p0 + p1 * t[0] + p2 * t[1];
        sx += t[0] * pm, sy += t[1] * pm;
      }
      gx = area * sx / 3 / F, gy = area * sy / 3 / F;
    }
    c.excess = c.bound - F * speed_d(gx, gy);
    total += c.bound;
    lower += c.bound - c.excess;
    queue.emplace(c.excess, cells.size());
    cells.push_back(c);
  };
  std::size_t size = 1;  // [WORK] each cell made is charged kPerCell × the size of the region's numbers
  for (const auto& ring : r.rings)
    for (const Vec2& v : ring) size = std::max({size, Work::size(v.x), Work::size(v.y)});
  Work::charge(Work::times(Work::times(r.triangles.size(), kPerCell), size), "making a region's slide block");
  for (const Region_triangle& t : r.triangles) add({vertex(t.a), vertex(t.b), vertex(t.c)});
  std::size_t alive = cells.size();
  const auto split = [&] {
    Work::charge(Work::times(4 * kPerCell, size), "refining a region's slide block (" + std::to_string(alive) + " cells)");
    const std::size_t c = queue.top().second;
    queue.pop();
    cells[c].alive = false;
    total -= cells[c].bound;
    lower -= cells[c].bound - cells[c].excess;
    const std::array<std::size_t, 3> v = cells[c].v;
    const Vec2 a = vertices[v[0]], b = vertices[v[1]], d = vertices[v[2]];
    const std::size_t ab = vertex({(a.x + b.x) / 2, (a.y + b.y) / 2}), bd = vertex({(b.x + d.x) / 2, (b.y + d.y) / 2}),
                      da = vertex({(d.x + a.x) / 2, (d.y + a.y) / 2});
    add({v[0], ab, da});
    add({ab, v[1], bd});
    add({da, bd, v[2]});
    add({ab, bd, da});
    alive += 3;
  };
  const double mud = mu.get_d();
  double aim = target ? target->get_d() : 0;
  Region_slide_block out;
  for (int round = 0;; ++round) {
    // Refine while the bound misses the aim — unless Jensen's lower bound of the true integral misses it too: then
    // no cells can reach it (the load is inside, or too close to the limit surface for doubles).
    bool hopeless = false;
    while (target && alive + 3 <= max_cells && !queue.empty() && mud * total > aim) {
      if (mud * lower > aim * (1 + 1e-12)) {
        hopeless = true;
        break;
      }
      split();
    }
    // The exact bound of the living cells.
    std::vector<Rational> terms;
    out.cells.triangles.clear();
    for (const Cell& c : cells) {
      if (!c.alive) continue;
      out.cells.triangles.push_back(c.v);
      const Triangle_measures m = triangle_measures({vertices[c.v[0]], vertices[c.v[1]], vertices[c.v[2]]}, r.pressure);
      terms.push_back(m.vertex_weights[0] * u[c.v[0]] + m.vertex_weights[1] * u[c.v[1]] + m.vertex_weights[2] * u[c.v[2]]);
    }
    while (terms.size() > 1) {  // pairwise: the denominators stay small, the sums balanced
      std::size_t n = 0;
      for (std::size_t i = 0; i + 1 < terms.size(); i += 2) terms[n++] = terms[i] + terms[i + 1];
      if (terms.size() % 2) terms[n++] = terms.back();
      terms.resize(n);
    }
    out.bound = mu * (terms.empty() ? Rational(0) : terms[0]);
    if (!target || out.bound <= *target || hopeless || alive + 3 > max_cells || queue.empty() || round == 3) break;
    // Rounding fooled the doubles: aim lower (10^-9, 10^-7, 10^-5 of the bound), at most three times.
    aim = std::min(aim, mud * total) * (1 - 1e-9 * std::pow(100.0, round));
  }
  out.speed_bounds = std::move(u);
  out.cells.vertices = std::move(vertices);
  return out;
}

Region_slide_blocks region_slide_blocks(const Support& s, const Vec3q& q, const Rational& slack, std::size_t max_cells) {
  Region_slide_blocks out;
  std::vector<double> est;
  const double qd[3] = {q[0].get_d(), q[1].get_d(), q[2].get_d()};
  for (const Support_region& r : s.regions) {
    const double h = s.mu_of(r).get_d() * region_power_double(r, qd);
    est.push_back(std::isfinite(h) ? std::max(h, 0.0) : 0.0);
    out.estimate += est.back();
  }
  if (out.estimate > slack.get_d() * (1 + 1e-9)) return out;
  for (std::size_t k = 0; k < s.regions.size(); ++k) {
    const Support_region& r = s.regions[k];
    const Rational share = out.estimate > 0 ? Rational(slack * Rational(est[k] / out.estimate))
                                            : Rational(slack / static_cast<long>(s.regions.size()));
    out.blocks.push_back(region_slide_block(r, s.mu_of(r), q, share, max_cells / std::max<std::size_t>(1, s.regions.size())));
    out.bound += out.blocks.back().bound;
    out.cells += out.blocks.back().cells.triangles.size();
  }
  out.ok = true;
  return out;
}

// ---------------------------------------------------------------------------------------------------------------
// Stick / slide.

namespace {


// Sticks: the regions cut into m² cells per coarse triangle, each cell a support point at its pressure centroid
// carrying F_k (LS of these points ⊆ the regions' LS: a cell force spread ∝ p has moment c_k × g_k), and the
// smoothed Newton witness on points and cells together.
// (q_hint: the twist minimising the true power on the plane q·p = 1, or null: the cells' power there must exceed 1
// for p to be inside their limit surface, a cheap necessary condition checked in double before the witness.)
bool try_stick(const Support& s, const Vec3q& p, int m, Motion_answer& out, const double* q_hint) {
  Support aug;
  aug.mu = s.mu;
  aug.points = s.points;
  std::vector<Rational> f;
  for (const Support_point& pt : s.points) f.push_back(*pt.force);
  std::vector<Region_cells> cells;
  for (const Support_region& r : s.regions) {
    cells.push_back(region_cells(r, m));
    for (Support_point& c : cell_points(r, s.mu_of(r), cells.back())) {
      f.push_back(*c.force);
      aug.points.push_back(std::move(c));
    }
  }
  if (q_hint) {
    double h = 0;
    for (std::size_t i = 0; i < aug.points.size(); ++i) {
      const Support_point& pt = aug.points[i];
      h += s.mu_of(pt).get_d() * f[i].get_d() *
           std::hypot(q_hint[0] - q_hint[2] * pt.at.y.get_d(), q_hint[1] + q_hint[2] * pt.at.x.get_d());
    }
    if (!(h > 1 + 1e-12)) return false;  // p is not (certainly) inside the cells' limit surface
  }
  const std::optional<Stick_witness> w = smoothed_stick_witness(aug, f, p);
  if (!w) return false;
  const auto at = [&w](std::size_t i) { return w->forces.begin() + static_cast<std::ptrdiff_t>(i); };
  Stick_witness& out_w = out.sticking.emplace();
  out_w.distribution.assign(f.begin(), f.begin() + static_cast<std::ptrdiff_t>(s.points.size()));
  out_w.forces.assign(at(0), at(s.points.size()));
  std::size_t next = s.points.size();
  out.cells = 0;
  for (Region_cells& c : cells) {
    Region_stick_block b{std::move(c), {}};
    b.forces.assign(at(next), at(next + b.cells.triangles.size()));
    next += b.cells.triangles.size();
    out.cells += b.cells.triangles.size();
    out_w.regions.push_back(std::move(b));
  }
  return true;
}

// Slides: the twist q, the points' rational speed bounds, and each region's slide block refined until the whole
// bound is at most q·p (its share of the slack proportional to its estimated power).
bool try_slide(const Support& s, const Vec3q& p, const Vec3q& q, Motion_answer& out, std::size_t max_cells) {
  if (is_zero(q)) return false;
  const Rational power = dot(q, p);
  std::vector<Rational> u = speed_bounds(s, q);
  std::vector<Rational> f;
  Rational bound;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    f.push_back(*s.points[i].force);
    bound += s.mu_of(s.points[i]) * f.back() * u[i];
  }
  if (bound > power) return false;
  Region_slide_blocks r = region_slide_blocks(s, q, Rational(power - bound), max_cells);
  if (!r.ok) return false;
  out.cells = r.cells;
  if (bound + r.bound >= power) return false;  // strictly outside
  out.sliding = Slide_witness{std::move(f), q, std::move(u), std::move(r.blocks), {}};
  return true;
}

// Along a translation q with a rational speed |v|: every point and every cell corner moves at |v| exactly, so the
// points' bound and each region's slide block (its coarse cells) are the exact power μ W |v| = q·p_q, where p_q is the
// load the forces μ f v̂ of the points and μ F_k v̂ of the cells (on their circles) carry. A load p = λ p_q on that
// ray is decided by λ: below 1 it sticks (the forces scaled by λ, strictly inside their discs), at 1 it is impending
// (the forces on their circles, the twist's power met), above 1 it slides (q·p = λ q·p_q beats the exact bound).
// A stick witness needs friction at two distinct places (else the surface is flat): a region that is one coarse cell
// (a triangle) is cut once more then.
bool try_translation(const Support& s, const Vec3q& p, const Vec3q& q, Motion_answer& out, int level = 1) {
  if (q[2] != 0 || is_zero(q)) return false;
  const auto [lo, hi] = sqrt_bracket(q[0] * q[0] + q[1] * q[1]);
  if (lo != hi) return false;
  const Vec2 dir{q[0] / lo, q[1] / lo};
  Impending_witness w;
  Rational bound;
  Vec3q sum{};
  for (const Support_point& pt : s.points) {
    const Rational rho = s.mu_of(pt) * *pt.force;
    w.forces.distribution.push_back(*pt.force);
    w.forces.forces.push_back({rho * dir.x, rho * dir.y});
    w.twist.speed_bounds.push_back(lo);
    bound += rho * lo;
    const Vec3q a = wrench_at(pt.at, w.forces.forces.back());
    for (std::size_t c = 0; c < 3; ++c) sum[c] += a[c];
  }
  std::size_t cells = 0, places = 0;
  for (const Support_point& pt : s.points) places += s.mu_of(pt) * *pt.force != 0;
  for (const Support_region& r : s.regions) {  // one block of cells for both: forces per cell, speeds per corner
    const Rational& mu = s.mu_of(r);
    Region_stick_block stick{region_cells(r, level), {}};
    if (mu != 0) places += stick.cells.triangles.size();
    for (const Support_point& c : cell_points(r, mu, stick.cells))
      stick.forces.push_back({mu * *c.force * dir.x, mu * *c.force * dir.y});
    Region_slide_block slide{stick.cells, std::vector<Rational>(stick.cells.vertices.size(), lo), mu * lo * r.total};
    bound += slide.bound;
    const Vec3q a = region_stick_wrench(r, stick);
    for (std::size_t c = 0; c < 3; ++c) sum[c] += a[c];
    cells += stick.cells.triangles.size();
    w.forces.regions.push_back(std::move(stick));
    w.twist.regions.push_back(std::move(slide));
  }
  if (is_zero(sum) || !is_zero(cross(sum, p))) return false;  // p is not on the ray of p_q
  const Rational lambda = dot(sum, p) / dot(sum, sum);
  if (lambda <= 0) return false;
  out.cells = cells;
  w.twist.distribution = w.forces.distribution;
  w.twist.twist = q;
  if (lambda == 1) {
    if (dot(q, p) != bound) return false;
    out.impending = std::move(w);
    out.motion = Motion::impending;
  } else if (lambda < 1) {
    if (places < 2) return level == 1 && try_translation(s, p, q, out, 2);
    Stick_witness& st = w.forces;
    for (Vec2& g : st.forces) g = scaled(g, lambda);
    for (Region_stick_block& b : st.regions)
      for (Vec2& g : b.forces) g = scaled(g, lambda);
    out.sticking = std::move(st);
    out.motion = Motion::sticks;
  } else {
    if (dot(q, p) <= bound) return false;
    out.sliding = std::move(w.twist);
    out.motion = Motion::slides;
  }
  return true;
}

}  // namespace

namespace {

// [WORK] The scale-free frame of the doubles (issue 34): log2 of the largest |coordinate| of the support's points and
// regions (from the numbers' bit lengths, ±1), and whether every coordinate is zero.
long largest_log2(const Support& s, bool& all_zero) {
  long best = 0;
  all_zero = true;
  const auto see = [&](const Rational& x) {
    if (x == 0) return;
    const long l = static_cast<long>(mpz_sizeinbase(x.get_num_mpz_t(), 2)) -
                   static_cast<long>(mpz_sizeinbase(x.get_den_mpz_t(), 2));
    if (all_zero || l > best) best = l;
    all_zero = false;
  };
  for_each_coordinate(s, see);
  return best;
}

Motion_answer decide_in_frame(const Support& s, const Vec3q& p);

void unscale_cells(Region_cells& c, const Rational& back) {
  for (Vec2& v : c.vertices) v = scaled(v, back);
}
void unscale(Stick_witness& w, const Rational& back) {
  for (Region_stick_block& b : w.regions) unscale_cells(b.cells, back);
}
void unscale(Slide_witness& w, const Rational& k) {  // the twist's rate: ω = k ω' (k the frame's scale)
  w.twist[2] *= k;
  if (w.dual) (*w.dual)[1] *= k, (*w.dual)[2] *= k;  // y0 + yx x_i + yy y_i, the same at x_i = x'_i / k
  for (Region_slide_block& b : w.regions) unscale_cells(b.cells, 1 / k);
}

}  // namespace

Support scaled_support(const Support& s, const Rational& k) {
  Support t = s;
  for (Support_point& pt : t.points) pt.at = scaled(pt.at, k);
  for (Support_region& r : t.regions) r = scaled_region(r, k);
  if (t.pressure_center) t.pressure_center = scaled(*t.pressure_center, k);
  return t;
}

void unscale(Motion_answer& a, const Rational& k) {
  const Rational back = 1 / k;
  if (a.sticking) unscale(*a.sticking, back);
  if (a.sliding) unscale(*a.sliding, k);
  if (a.impending) unscale(a.impending->forces, back), unscale(a.impending->twist, k);
  for (Stick_witness& w : a.vertices) unscale(w, back);
  a.search_twist[2] *= k.get_d();
}

// A support far from unit scale (beyond 2^±200: a region at 10^9990) is decided in a frame scaled by an exact power of
// two k = 2^-e, where its doubles are finite: scaled_support, the load's moment times k, and the witness mapped back
// (unscale). The checker verifies it in the scene's own frame.
Motion_answer decide_on_regions(const Support& s, const Vec3q& p) {
  bool all_zero = false;
  const long e = largest_log2(s, all_zero);
  if (all_zero || (e <= 200 && e >= -200)) return decide_in_frame(s, p);
  Rational k = 1;
  if (e > 0) mpz_mul_2exp(k.get_den_mpz_t(), k.get_den_mpz_t(), static_cast<mp_bitcnt_t>(e));
  else mpz_mul_2exp(k.get_num_mpz_t(), k.get_num_mpz_t(), static_cast<mp_bitcnt_t>(-e));
  Motion_answer a = decide_in_frame(scaled_support(s, k), {p[0], p[1], p[2] * k});
  unscale(a, k);
  return a;
}

namespace {

Motion_answer decide_in_frame(const Support& s, const Vec3q& p) {
  for (const Support_point& pt : s.points)
    if (!pt.force) throw std::invalid_argument("decide_on_regions: every point force must be given");
  Motion_answer out;
  // The power in double (points and regions), for the search only.
  struct Point_d {
    double x, y, rho;
  };
  std::vector<Point_d> pts;
  for (const Support_point& pt : s.points)
    pts.push_back({pt.at.x.get_d(), pt.at.y.get_d(), Rational(s.mu_of(pt) * *pt.force).get_d()});
  std::vector<std::pair<const Support_region*, double>> regions;
  for (const Support_region& r : s.regions) regions.emplace_back(&r, s.mu_of(r).get_d());
  const auto h = [&](const double* q) {
    double v = 0;
    for (const Point_d& t : pts) v += t.rho * std::hypot(q[0] - q[2] * t.y, q[1] + q[2] * t.x);
    for (const auto& [r, mu] : regions)
      if (mu != 0) v += mu * region_power_double(*r, q);
    return v;
  };
  const bool zero = p[0] == 0 && p[1] == 0 && p[2] == 0;
  // A load on the ray of a translation's boundary load (the force's direction with a rational length): decided by
  // its scale alone, however close to the surface.
  if (!zero && (p[0] != 0 || p[1] != 0) && try_translation(s, p, {p[0], p[1], Rational(0)}, out)) {
    out.decided_by = Decided_by::certificate;
    return out;
  }
  const Plane_minimum m = zero ? Plane_minimum{} : minimise_on_load_plane(p, h);
  out.gauge_estimate = zero ? 0 : m.found && m.h > 0 ? 1 / m.h : HUGE_VAL;
  // Within 10^-12 of the limit surface (by the doubles) the witnesses found in double cannot resolve the side: only
  // the cheap attempts (exact candidates, coarse cells) are made.
  const bool unresolvable = m.found && std::fabs(m.h - 1) < 1e-12;
  std::vector<Vec3q> twists;
  if (m.found) twists.push_back({Rational(m.q[0]), Rational(m.q[1]), Rational(m.q[2])});
  if (p[0] != 0 || p[1] != 0) twists.push_back({p[0], p[1], Rational(0)});  // the translation along the force
  if (!zero) twists.push_back(p);
  const auto slide = [&] {
    // Every candidate with a small budget first (an exact candidate, such as the translation along the force of a
    // load on a translation's boundary point, needs few cells), then the search's twist with the whole budget.
    for (const std::size_t budget : {std::size_t(500), unresolvable ? std::size_t(500) : kMaxRegionCells})
      for (const Vec3q& q : twists) {
        if (try_slide(s, p, q, out, budget)) {
          out.motion = Motion::slides;
          out.decided_by = Decided_by::certificate;
          return true;
        }
        if (budget == kMaxRegionCells) break;
      }
    return false;
  };
  const auto stick = [&] {
    std::size_t coarse = 0;
    for (const Support_region& r : s.regions) coarse += r.triangles.size();
    for (int level = 1; coarse * static_cast<std::size_t>(level * level) <= kMaxRegionStickCells && (level <= 2 || !unresolvable);
         level *= 2)
      if (try_stick(s, p, level, out, m.found ? m.q.data() : nullptr)) {
        out.motion = Motion::sticks;
        out.decided_by = Decided_by::certificate;
        return true;
      }
    return false;
  };
  const bool outside = !zero && m.found && m.h < 1;
  if (outside ? slide() || stick() : stick() || slide()) return out;
  // On the surface: translations along the load's force and the search's twist, made rational.
  std::vector<Vec3q> on;
  if (p[0] != 0 || p[1] != 0) on.push_back({p[0], p[1], Rational(0)});
  if (m.found)
    if (const auto r = rationalized(m.q)) on.push_back(*r);
  for (const Vec3q& q : on)
    if (try_translation(s, p, q, out)) {
      out.decided_by = Decided_by::certificate;
      return out;
    }
  out.cells = 0;
  char buf[320];
  if (m.found)
    std::snprintf(buf, sizeof buf,
                  "the load is within about %.2g (relative) of the limit surface (the estimate of its gauge is %.17g): %s",
                  std::fabs(out.gauge_estimate - 1), out.gauge_estimate,
                  unresolvable ? "beyond the resolution of the double-precision search that proposes the witnesses"
                               : "no certificate with the cells allowed (20000 for slides, 5000 for sticks)");
  else
    std::snprintf(buf, sizeof buf, "no certificate with at most %zu cells", kMaxRegionCells);
  out.undecided_why = buf;
  return out;
}

}  // namespace
}  // namespace wrenchkit
