// [SL-6] Stick or slide near the limit surface: multiple-precision Newton proposes, exact rationals decide
// (proofs/notes/SL-6-precise-motion.md).
#include "exact/sliding/precise_motion.h"

#include <mpfr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <cstdlib>

#include "exact/sliding/sliding.h"

namespace wrenchkit {

namespace {

// An MPFR number at one precision, every operation rounded to nearest: Newton's proposals only (nothing
// computed with it is kept without an exact check).
class Big {
 public:
  explicit Big(long bits) {
    mpfr_init2(v_, bits);
    mpfr_set_zero(v_, 1);
  }
  Big(const Rational& q, long bits) : Big(bits) { mpfr_set_q(v_, q.get_mpq_t(), MPFR_RNDN); }
  Big(const Big& o) : Big(mpfr_get_prec(o.v_)) { mpfr_set(v_, o.v_, MPFR_RNDN); }
  Big& operator=(const Big& o) {
    if (this != &o) mpfr_set(v_, o.v_, MPFR_RNDN);
    return *this;
  }
  ~Big() { mpfr_clear(v_); }
  long bits() const { return mpfr_get_prec(v_); }

  friend Big operator+(const Big& a, const Big& b) { return op(mpfr_add, a, b); }
  friend Big operator-(const Big& a, const Big& b) { return op(mpfr_sub, a, b); }
  friend Big operator*(const Big& a, const Big& b) { return op(mpfr_mul, a, b); }
  friend Big operator/(const Big& a, const Big& b) { return op(mpfr_div, a, b); }
  Big& operator+=(const Big& b) {
    mpfr_add(v_, v_, b.v_, MPFR_RNDN);
    return *this;
  }
  friend Big sqrt(const Big& a) {
    Big r(a.bits());
    mpfr_sqrt(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  Big neg() const {
    Big r(bits());
    mpfr_neg(r.v_, v_, MPFR_RNDN);
    return r;
  }
  Big times_2exp(long e) const {
    Big r(bits());
    mpfr_mul_2si(r.v_, v_, e, MPFR_RNDN);
    return r;
  }
  int sign() const { return mpfr_sgn(v_); }
  bool finite() const { return mpfr_number_p(v_) != 0; }
  bool less(const Big& b) const { return mpfr_less_p(v_, b.v_) != 0; }
  long exponent() const { return mpfr_zero_p(v_) ? 0 : mpfr_get_exp(v_); }  // |v| ∈ [2^(e−1), 2^e)
  // The value rounded to `keep` significant bits, as an exact rational.
  Rational rounded(long keep) const {
    mpfr_t t;
    mpfr_init2(t, keep);
    mpfr_set(t, v_, MPFR_RNDN);
    Rational q;
    mpfr_get_q(q.get_mpq_t(), t);
    mpfr_clear(t);
    return q;
  }
  // round(v·2^e) as an integer.
  Integer scaled_integer(long e) const {
    Big s = times_2exp(e);
    Integer z;
    mpfr_get_z(z.get_mpz_t(), s.v_, MPFR_RNDN);
    return z;
  }

 private:
  template <class F>
  static Big op(F f, const Big& a, const Big& b) {
    Big r(a.bits());
    f(r.v_, a.v_, b.v_, MPFR_RNDN);
    return r;
  }
  mpfr_t v_;
};

struct Point {
  Big x, y, rho;
};

// h on the plane q = q0 + z1 e1 + z2 e2, with its reduced gradient and Hessian (Σ (ρ/s) a aᵀ, a = A_i n_i, n_i
// the unit normal of v_i: h is positively homogeneous of degree one).
struct Eval {
  bool smooth = true;  // every moving point's speed nonzero
  Big h, g1, g2, h11, h12, h22;
  explicit Eval(long bits) : h(bits), g1(bits), g2(bits), h11(bits), h12(bits), h22(bits) {}
};

using Big3 = std::array<Big, 3>;

Big dot(const Big3& a, const Big3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
using wrenchkit::dot;

Big3 at_z(const Big3& q0, const Big3& e1, const Big3& e2, const Big& z1, const Big& z2) {
  return {q0[0] + z1 * e1[0] + z2 * e2[0], q0[1] + z1 * e1[1] + z2 * e2[1], q0[2] + z1 * e1[2] + z2 * e2[2]};
}

Eval evaluate(const std::vector<Point>& pts, const Big3& q, const Big3& e1, const Big3& e2, bool derivatives) {
  const long bits = q[0].bits();
  Eval e(bits);
  Big3 grad{Big(bits), Big(bits), Big(bits)};
  for (const Point& p : pts) {
    const Big vx = q[0] - q[2] * p.y, vy = q[1] + q[2] * p.x;
    const Big s = sqrt(vx * vx + vy * vy);
    e.h += p.rho * s;
    if (!derivatives) continue;
    if (s.sign() == 0) {
      e.smooth = false;
      return e;
    }
    const Big ux = vx / s, uy = vy / s;
    grad[0] += p.rho * ux;
    grad[1] += p.rho * uy;
    grad[2] += p.rho * (p.x * uy - p.y * ux);
    // n = (−u_y, u_x); a = (n, r × n)
    const Big nx = uy.neg(), ny = ux;
    const Big3 a{nx, ny, p.x * ny - p.y * nx};
    const Big c = p.rho / s, a1 = dot(a, e1), a2 = dot(a, e2);
    e.h11 += c * a1 * a1;
    e.h12 += c * a1 * a2;
    e.h22 += c * a2 * a2;
  }
  e.g1 = dot(grad, e1);
  e.g2 = dot(grad, e2);
  return e;
}

// 3×3 exact solve M L = b (M symmetric positive definite here; nothing when singular).
std::optional<Vec3q> solve3(std::array<std::array<Rational, 3>, 3> m, Vec3q b) {
  for (int c = 0; c < 3; ++c) {
    int pivot = -1;
    for (int r = c; r < 3; ++r)
      if (m[r][c] != 0) {
        pivot = r;
        break;
      }
    if (pivot < 0) return std::nullopt;
    std::swap(m[c], m[pivot]);
    std::swap(b[c], b[pivot]);
    for (int r = 0; r < 3; ++r) {
      if (r == c || m[r][c] == 0) continue;
      const Rational k = m[r][c] / m[c][c];
      for (int j = c; j < 3; ++j) m[r][j] -= k * m[c][j];
      b[r] -= k * b[c];
    }
  }
  return Vec3q{b[0] / m[0][0], b[1] / m[1][1], b[2] / m[2][2]};
}

// The exact stick witness from the weights w_i (SL-6 (a)).
std::optional<std::vector<Vec2>> stick_from_weights(const std::vector<Rho_point>& pts, const std::vector<Rational>& w,
                                                    const Vec3q& p) {
  std::array<std::array<Rational, 3>, 3> m{};
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (w[i] == 0) continue;
    const Rational &x = pts[i].at.x, &y = pts[i].at.y;
    m[0][0] += w[i];
    m[1][1] += w[i];
    m[0][2] -= w[i] * y;
    m[1][2] += w[i] * x;
    m[2][2] += w[i] * (x * x + y * y);
  }
  m[2][0] = m[0][2];
  m[2][1] = m[1][2];
  const std::optional<Vec3q> l = solve3(m, p);
  if (!l) return std::nullopt;
  std::vector<Vec2> g(pts.size(), Vec2{Rational(0), Rational(0)});
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (w[i] == 0) continue;
    const Rational gx = w[i] * ((*l)[0] - (*l)[2] * pts[i].at.y), gy = w[i] * ((*l)[1] + (*l)[2] * pts[i].at.x);
    if (gx * gx + gy * gy >= pts[i].rho * pts[i].rho) return std::nullopt;
    g[i] = {gx, gy};
  }
  return g;
}

// The exact slide witness of the integer twist q (SL-6 (b)): u_i ≥ |v_i(q)|, Σ ρ_i u_i < q·p.
std::optional<std::vector<Rational>> slide_bounds(const std::vector<Rho_point>& pts, const Vec3q& q, const Vec3q& p,
                                                  int bits) {
  std::vector<Rational> u;
  u.reserve(pts.size());
  Rational bound;
  for (const Rho_point& pt : pts) {
    u.push_back(sqrt_bracket(speed_squared(q, pt.at), bits).second);
    bound += pt.rho * u.back();
  }
  if (dot(q, p) > bound) return u;
  return std::nullopt;
}

}  // namespace

Precise_motion precise_motion(const std::vector<Rho_point>& points, const Vec3q& p) {
  Precise_motion out;
  if (points.size() > kMaxPreciseMotionPoints || (p[0] == 0 && p[1] == 0 && p[2] == 0)) return out;
  {
    const Rho_point* first = nullptr;
    bool two = false;
    for (const Rho_point& pt : points) {
      if (pt.rho < 0) return out;
      if (pt.rho == 0) continue;
      if (!first) first = &pt;
      else if (pt.at.x != first->at.x || pt.at.y != first->at.y) two = true;
    }
    if (!two) return out;
  }
  // The plane q·p = 1: q0 = p/|p|², e1 ⟂ p along the axis where p is smallest, e2 = p × e1 (both unit, in MPFR).
  int axis = 0;
  for (int c = 1; c < 3; ++c)
    if (abs(p[c]) < abs(p[axis])) axis = c;
  Big z1(64), z2(64);
  std::size_t work = 0;
  bool spent = false;
  const auto evaluate_counted = [&](const std::vector<Point>& pts, const Big3& q, const Big3& e1, const Big3& e2,
                                    bool derivatives) {
    work += pts.size();
    spent = spent || work > kMaxPreciseMotionWork;
    return evaluate(pts, q, e1, e2, derivatives);
  };
  for (const long bits : {128L, 256L, 512L}) {
    std::vector<Point> pts;
    for (const Rho_point& pt : points)
      if (pt.rho > 0) pts.push_back({Big(pt.at.x, bits), Big(pt.at.y, bits), Big(pt.rho, bits)});
    const Big3 pb{Big(p[0], bits), Big(p[1], bits), Big(p[2], bits)};
    const Big pp = dot(pb, pb);
    const Big3 q0{pb[0] / pp, pb[1] / pp, pb[2] / pp};
    Big3 e1{Big(bits), Big(bits), Big(bits)};
    {
      Big3 ek{Big(bits), Big(bits), Big(bits)};
      ek[axis] = Big(Rational(1), bits);
      const Big k = pb[axis] / pp;
      for (int c = 0; c < 3; ++c) e1[c] = ek[c] - k * pb[c];
      const Big n = sqrt(dot(e1, e1));
      for (Big& c : e1) c = c / n;
    }
    Big3 e2{pb[1] * e1[2] - pb[2] * e1[1], pb[2] * e1[0] - pb[0] * e1[2], pb[0] * e1[1] - pb[1] * e1[0]};
    {
      const Big n = sqrt(dot(e2, e2));
      for (Big& c : e2) c = c / n;
    }
    Big a1(z1.rounded(z1.bits()), bits), a2(z2.rounded(z2.bits()), bits);  // the last precision's iterate
    const Big one(Rational(1), bits);
    // The exact certificate from the iterate q with h = h(q) (SL-6): its sign of h − 1 says which to try; the bits
    // the margin asks (2^(m−1) ≤ |h − 1| < 2^m) plus 24 are what the rationals keep.
    const auto certify = [&](const Big3& q, const Big& h) {
      const Big margin = h - one;
      if (margin.sign() == 0) return false;
      const long need = std::max(24L, 24 - margin.exponent());
      if (need > bits - 16) return false;
      if (margin.sign() < 0) {  // slides: q rounded to `need` bits of its largest component, made primitive
        long top = q[0].exponent();
        for (int c = 1; c < 3; ++c) top = std::max(top, q[c].exponent());
        Vec3q qi;
        Integer g(0);
        for (int c = 0; c < 3; ++c) {
          const Integer z = q[c].scaled_integer(need - top);
          qi[c] = Rational(z);
          mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), z.get_mpz_t());
        }
        if (g == 0) return false;
        for (Rational& c : qi) c /= Rational(g);
        auto u = slide_bounds(points, qi, p, static_cast<int>(need) + 16);
        if (!u) return false;
        out.motion = Motion::slides;
        out.twist = qi;
        out.speed_bounds = std::move(*u);
        return true;
      }
      // sticks: w_i = ρ_i/(h·|v_i(q)|), rounded to `need` bits each
      std::vector<Rational> w(points.size());
      std::size_t j = 0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        if (!(points[i].rho > 0)) continue;
        const Point& pt = pts[j++];
        const Big vx = q[0] - q[2] * pt.y, vy = q[1] + q[2] * pt.x;
        w[i] = (pt.rho / (h * sqrt(vx * vx + vy * vy))).rounded(need);
      }
      auto g = stick_from_weights(points, w, p);
      if (!g) return false;
      out.motion = Motion::sticks;
      out.forces = std::move(*g);
      return true;
    };
    // Newton with backtracking (Armijo, 1/4). From the fourth iterate on, each one whose h − 1 keeps the last one's
    // binary exponent is tried exactly: near a nearly flat surface (h almost a kink) Newton's decrement says
    // little, and what is needed is only an iterate good to the margin's bits.
    Eval e = evaluate_counted(pts, at_z(q0, e1, e2, a1, a2), e1, e2, true);
    long last_exponent = 1L << 30;
    for (int it = 0; it < 120 && e.smooth && e.h.finite() && !spent; ++it) {
      const long exponent = (e.h - one).exponent();
      if (it >= 3 && exponent == last_exponent && certify(at_z(q0, e1, e2, a1, a2), e.h)) return out;
      last_exponent = exponent;
      const Big det = e.h11 * e.h22 - e.h12 * e.h12;
      if (det.sign() <= 0) break;
      const Big d1 = (e.h12 * e.g2 - e.h22 * e.g1) / det, d2 = (e.h12 * e.g1 - e.h11 * e.g2) / det;
      const Big dec = (e.g1 * d1 + e.g2 * d2).neg();  // λ² = gᵀH⁻¹g ≥ 0
      if (dec.less(e.h.times_2exp(-(bits - 8)))) break;  // at this precision's level: nothing more to gain
      Big t = one, n1 = a1 + d1, n2 = a2 + d2;
      for (long k = 0; k < bits / 2 && !spent; ++k) {
        const Eval f = evaluate_counted(pts, at_z(q0, e1, e2, n1, n2), e1, e2, false);
        if (f.h.less(e.h - dec * t.times_2exp(-2))) break;
        t = t.times_2exp(-1);
        n1 = a1 + t * d1;
        n2 = a2 + t * d2;
      }
      const Eval f = evaluate_counted(pts, at_z(q0, e1, e2, n1, n2), e1, e2, true);
      if (!f.h.less(e.h)) break;  // no descent left at this precision
      a1 = n1;
      a2 = n2;
      e = f;
    }
    if (!e.smooth) return out;  // a rotation about a support point: the facet, not Newton's to decide
    const Big3 last = at_z(q0, e1, e2, a1, a2);
    if (certify(last, e.h)) return out;
    out.proposal = {last[0].rounded(53).get_d(), last[1].rounded(53).get_d(), last[2].rounded(53).get_d()};
    if (spent) return out;  // the work bound: undecided
    z1 = a1;
    z2 = a2;
  }
  return out;
}

}  // namespace wrenchkit
