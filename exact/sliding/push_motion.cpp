// [PU-2] The pushed body's contact mode for a support of points with every force given: see pushing.h and
// proofs/notes/PU-2-contact-mode.md. Exact signs of interval sums whose square roots are bracketed by rationals.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <tuple>
#include <utility>

#include "core/contact_generators.h"
#include "exact/sliding/distribution.h"
#include "exact/sliding/pushing.h"
#include "exact/sliding/sliding.h"

namespace wrenchkit {

const char* push_mode_name(Push_mode m) {
  switch (m) {
    case Push_mode::sticks: return "sticks";
    case Push_mode::impending: return "impending";
    case Push_mode::slides_left: return "slides left";
    case Push_mode::slides_right: return "slides right";
    case Push_mode::depends: return "depends";
    case Push_mode::undecided: return "undecided";
  }
  return "?";
}

namespace {

// The interval of Σ ρ_i (ℓ_i · v_i(x)) / |v_i(x)| over x ∈ [lo, hi], ℓ_i = l, or rot90(r_i − p) when `moment` (then the
// sum is the moment about p of the load). The velocities: v_i(x) = u + x·rot90(r_i − p) (x the rotation rate ω), or,
// with `slip`, v_i(x) = u + ω·rot90(r_i − p) + x·slip (x the slip speed along `slip` at the fixed rate *omega). False
// when a speed may vanish on the interval.
bool interval_sum(const std::vector<Rho_point>& pts, const Vec2& p, const Vec2& u, const Vec2& l, bool moment,
                  const Rational& lo, const Rational& hi, int bits, Rational& out_lo, Rational& out_hi,
                  const Vec2* slip = nullptr, const Rational* omega = nullptr) {
  out_lo = 0, out_hi = 0;
  for (const Rho_point& q : pts) {
    if (q.rho == 0) continue;
    const Vec2 d = minus(q.at, p), rd = rot90(d);
    const Vec2 base = slip ? Vec2{u.x + *omega * rd.x, u.y + *omega * rd.y} : u, w = slip ? *slip : rd;
    const Vec2 li = moment ? rd : l;
    // numerator ℓ·base + x ℓ·w, linear; |v|² = |base|² + 2x base·w + x²|w|², convex
    const Rational a = dot(li, base), b = dot(li, w);
    Rational n_lo = a + lo * b, n_hi = a + hi * b;
    if (n_lo > n_hi) std::swap(n_lo, n_hi);
    const Rational uu = dot(base, base), uw = dot(base, w), dd = dot(w, w);
    const auto quad = [&](const Rational& x) { return Rational(uu + 2 * x * uw + x * x * dd); };
    Rational q_min = std::min(quad(lo), quad(hi)), q_max = std::max(quad(lo), quad(hi));
    if (dd != 0) {
      const Rational v = -uw / dd;  // the vertex
      if (lo <= v && v <= hi) q_min = std::min(q_min, quad(v));
    }
    if (q_min <= 0) return false;
    const Rational s_lo = sqrt_bracket(q_min, bits).first, s_hi = sqrt_bracket(q_max, bits).second;
    if (s_lo <= 0) return false;
    Rational t_lo, t_hi;
    if (n_lo >= 0) t_lo = n_lo / s_hi, t_hi = n_hi / s_lo;
    else if (n_hi <= 0) t_lo = n_lo / s_lo, t_hi = n_hi / s_hi;
    else t_lo = n_lo / s_lo, t_hi = n_hi / s_lo;
    out_lo += q.rho * t_lo, out_hi += q.rho * t_hi;
  }
  return true;
}

// The sign of g at ω (the moment about p of the load of the twist u + ω·rotation about p): −1, +1; 0 when not
// certified at up to 1024 bits; 2 when a support point is at rest there (a pivot: its friction anywhere in its disc,
// so g jumps there) and the jump surely holds 0. `bits` becomes the precision that certified it.
int g_sign(const std::vector<Rho_point>& pts, const Vec2& p, const Vec2& u, const Rational& w, int& bits) {
  for (int b = bits; b <= 1024; b *= 2) {
    std::vector<Rho_point> moving;
    Rational reach_lo = 0, reach_hi = 0;  // Σ ρ_j |r_j − p| over the points at rest, bracketed
    for (const Rho_point& q : pts) {
      const Vec2 d = minus(q.at, p), v{u.x - w * d.y, u.y + w * d.x};
      if (v.x != 0 || v.y != 0) {
        moving.push_back(q);
      } else if (q.rho != 0) {
        const auto [l, h] = sqrt_bracket(dot(d, d), b);
        reach_lo += q.rho * l, reach_hi += q.rho * h;
      }
    }
    Rational lo, hi;
    if (!interval_sum(moving, p, u, {0, 0}, true, w, w, b, lo, hi)) return 0;
    if (lo - reach_hi > 0 || hi + reach_hi < 0) {
      bits = b;
      return lo - reach_hi > 0 ? 1 : -1;
    }
    if (reach_lo > 0 && hi - reach_lo < 0 && lo + reach_lo > 0) return 2;
  }
  return 0;
}

// [PU-2 §7] The support point whose rotation moves p with velocity u (u ⟂ r_j − p, r_j ≠ p) and at whose rate
// ω_j = −(u·rot90 d_j)/|d_j|² g's jump surely holds 0 — then that rotation is u's sticking candidate, exactly (g is
// nondecreasing) —, with ω_j; none when there is no such point (the root, if any, is where every point moves).
std::optional<std::pair<std::size_t, Rational>> pivot_of(const std::vector<Rho_point>& pts, const Vec2& p, const Vec2& u) {
  for (std::size_t j = 0; j < pts.size(); ++j) {
    const Vec2 d = minus(pts[j].at, p);
    if (pts[j].rho == 0 || (d.x == 0 && d.y == 0) || dot(u, d) != 0) continue;
    const Rational w = -dot(u, rot90(d)) / dot(d, d);
    int bits = 64;
    if (g_sign(pts, p, u, w, bits) == 2) return std::pair{j, w};
  }
  return std::nullopt;
}

}  // namespace

namespace {

// The sticking candidate of a velocity u at p: ω* (the root of g, nondecreasing) in [lo, hi], certified; exact when
// lo = hi (only ω* = 0: u passes through the centre of friction, the load a translation's, its force D û).
class Candidate {
 public:
  enum class State { ok, pivot, failed };
  // With a proposed bracket [lo, hi] (the doubles' estimate): kept when g's signs there certify it, else searched.
  Candidate(const std::vector<Rho_point>& pts, const Vec2& p, const Vec2& u, const Rational& lo, const Rational& hi)
      : pts_(pts), p_(p), u_(u) {
    if (g0() != 0 && lo < hi && g_sign(pts_, p_, u_, lo, bits_) == -1 && g_sign(pts_, p_, u_, hi, bits_) == 1) {
      lo_ = lo, hi_ = hi;
      return;
    }
    bits_ = 64;
    search();
  }
  Candidate(const std::vector<Rho_point>& pts, const Vec2& p, const Vec2& u) : pts_(pts), p_(p), u_(u) { search(); }
  // g(0) = Σ ρ_i (r_i − p) × u / |u|: its sign, exactly (0: u passes through the centre of friction)
  Rational g0() const {
    Rational g = 0;
    for (const Rho_point& q : pts_) g += q.rho * cross(minus(q.at, p_), u_);
    return g;
  }
  void search() {
    const Rational g0 = this->g0();
    if (g0 == 0) return;  // lo = hi = 0
    const int side = g0 < 0 ? 1 : -1;
    Rational step = 1;
    for (int k = 0; k <= 200; ++k, step *= 2) {
      const Rational w = side * step;
      const int sg = g_sign(pts_, p_, u_, w, bits_);
      if (sg == 2) {
        state_ = State::pivot;
        return;
      }
      if (sg == side) {
        (side > 0 ? hi_ : lo_) = w;
        return;
      }
      if (sg == -side) (side > 0 ? lo_ : hi_) = w;
    }
    state_ = State::failed;
  }
  State state() const { return state_; }
  bool exact() const { return lo_ == hi_; }
  const Rational& lo() const { return lo_; }
  const Rational& hi() const { return hi_; }
  int bits() const { return bits_; }
  // One halving of the bracket (false: nothing more to do, or it failed).
  bool narrow() {
    if (state_ != State::ok || exact()) return false;
    Rational mid = (lo_ + hi_) / 2;
    int sg = g_sign(pts_, p_, u_, mid, bits_);
    if (sg == 0) {  // not certified there: a nearby rational
      mid = lo_ + (hi_ - lo_) * Rational(1, 3);
      sg = g_sign(pts_, p_, u_, mid, bits_);
    }
    if (sg == 2) return state_ = State::pivot, false;
    if (sg == 0) return state_ = State::failed, false;
    (sg < 0 ? lo_ : hi_) = mid;
    return true;
  }
  // The certified interval of ℓ·F over the bracket (false when a speed may vanish on it).
  bool box(const Vec2& l, Rational& out_lo, Rational& out_hi) const {
    if (exact()) {  // F = D û: ℓ·F has the sign of ℓ·u; its size does not matter to a sign
      out_lo = out_hi = dot(l, u_);
      return true;
    }
    return interval_sum(pts_, p_, u_, l, false, lo_, hi_, bits_, out_lo, out_hi);
  }
  // The certified sign of ℓ·F, 0 when not (yet) certain.
  int sign(const Vec2& l) const {
    Rational a, b;
    if (!box(l, a, b)) return 0;
    return a > 0 ? 1 : b < 0 ? -1 : (exact() && a == 0 ? 3 : 0);  // 3: exactly 0
  }

 private:
  const std::vector<Rho_point>& pts_;
  Vec2 p_, u_;
  Rational lo_ = 0, hi_ = 0;
  int bits_ = 64;
  State state_ = State::ok;
};

// The support's points in double about p, for the doubles' proposals (never a verdict): ω*(u), the root of g by
// bisection, and optionally l·F there.
class Double_points {
 public:
  Double_points(const std::vector<Rho_point>& pts, const Vec2& p) {
    for (const Rho_point& q : pts)
      if (q.rho != 0) d_.push_back({Rational(q.at.x - p.x).get_d(), Rational(q.at.y - p.y).get_d(), q.rho.get_d()});
  }
  double rate(double ux, double uy, const double* l = nullptr, double* side = nullptr) const {
    const auto g = [&](double w, double* f) {
      double m = 0, fx = 0, fy = 0;
      for (const auto& q : d_) {
        const double wx = ux - w * q[1], wy = uy + w * q[0], sp = std::hypot(wx, wy);
        if (sp == 0) continue;
        m += q[2] * (q[0] * wy - q[1] * wx) / sp, fx += q[2] * wx / sp, fy += q[2] * wy / sp;
      }
      if (f) *f = l[0] * fx + l[1] * fy;
      return m;
    };
    double lo = -1, hi = 1;
    for (int i = 0; i < 200 && g(lo, nullptr) > 0; ++i) lo *= 2;
    for (int i = 0; i < 200 && g(hi, nullptr) < 0; ++i) hi *= 2;
    for (int i = 0; i < 100 && lo < hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (g(mid, nullptr) < 0 ? lo : hi) = mid;
    }
    const double w = 0.5 * (lo + hi);
    if (side) g(w, side);
    return w;
  }

 private:
  std::vector<std::array<double, 3>> d_;  // r_i − p, ρ_i
};

// The slip speed at which the tangent velocity matches the normal one: |v·n| / |n|² (n = −rot90 t), 1 when 0.
double step_hint(const Vec2& v, const Vec2& t) {
  const Vec2 n{t.y, -t.x};
  const Rational s = abs(dot(v, n)) / dot(n, n);
  return s == 0 ? 1.0 : s.get_d();
}

// [lo, hi] of k·x for x in [x0, x1]
void scaled_range(const Rational& k, const Rational (&x)[2], Rational (&out)[2]) {
  out[0] = k * x[0], out[1] = k * x[1];
  if (out[0] > out[1]) std::swap(out[0], out[1]);
}

// [PU-2 §6–8] The facet of the rotation about support point j — rate ω, velocity u at p, so u = −ω·rot90(d_j),
// d_j = r_j − p: its loads are the other points' friction (unit speeds v̂_i) plus ρ_j g at r_j for any |g| ≤ 1. The
// others' force F' and moment M' about p, bracketed with the square roots at `bits`; false when another point is at
// rest too.
bool facet_rest(const std::vector<Rho_point>& pts, std::size_t j, const Vec2& p, const Vec2& u, const Rational& omega,
                int bits, Rational (&fx)[2], Rational (&fy)[2], Rational (&m)[2]) {
  std::vector<Rho_point> rest;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (i != j) rest.push_back(pts[i]);
  return interval_sum(rest, p, u, {1, 0}, false, omega, omega, bits, fx[0], fx[1]) &&
         interval_sum(rest, p, u, {0, 1}, false, omega, omega, bits, fy[0], fy[1]) &&
         interval_sum(rest, p, u, {0, 0}, true, omega, omega, bits, m[0], m[1]);
}

// [PU-2 §6–7] Does the facet hold a force λ e through p, λ > 0? The moment about p gives λ = (d_j × F' − M')/(d_j × e),
// and |λ e − F'| < ρ_j certifies g — strictly, with the square roots bracketed (`bits`). False when not certified.
bool facet_holds(const std::vector<Rho_point>& pts, std::size_t j, const Vec2& p, const Vec2& u, const Rational& omega,
                 const Vec2& e, int bits) {
  const Vec2 d = minus(pts[j].at, p);
  const Rational de = cross(d, e);
  Rational fx[2], fy[2], m[2];
  if (pts[j].rho == 0 || de == 0 || !facet_rest(pts, j, p, u, omega, bits, fx, fy, m)) return false;
  // λ (d × e) = d × F' − M' = d.x F'_y − d.y F'_x − M', by interval ends
  Rational a[2], b[2];
  scaled_range(d.x, fy, a), scaled_range(-d.y, fx, b);
  Rational num[2] = {a[0] + b[0] - m[1], a[1] + b[1] - m[0]}, lambda[2];
  scaled_range(1 / de, num, lambda);
  if (lambda[0] <= 0) return false;
  // |λ e − F'|² < ρ_j², each component's interval squared
  const auto square_max = [](const Rational& lo, const Rational& hi) { return std::max(Rational(lo * lo), Rational(hi * hi)); };
  Rational gx[2], gy[2], ex[2], ey[2];
  scaled_range(e.x, lambda, ex), scaled_range(e.y, lambda, ey);
  gx[0] = ex[0] - fx[1], gx[1] = ex[1] - fx[0], gy[0] = ey[0] - fy[1], gy[1] = ey[1] - fy[0];
  return square_max(gx[0], gx[1]) + square_max(gy[0], gy[1]) < pts[j].rho * pts[j].rho;
}

// [PU-2 §8] Does the facet hold forces through p at all, and is every one of them strictly on the positive side of l
// (l·F > 0)? They are the chord S = {F : d × F = d × F' − M', |F − F'| ≤ ρ_j}: not empty, and more than a point, when
// M'² < ρ_j²|d|² (then g's jump at the pivot holds 0 strictly); its middle F' − M'·rot90(d)/|d|², its half-length
// √(ρ_j² − M'²/|d|²) along d̂. So l·F > 0 on S when A = |d|²(l·F') − M'(l·rot90 d) > 0 and A² > (l·d)²(ρ_j²|d|² − M'²).
bool facet_beyond(const std::vector<Rho_point>& pts, std::size_t j, const Vec2& p, const Vec2& u, const Rational& omega,
                  const Vec2& l, int bits) {
  const Vec2 d = minus(pts[j].at, p);
  Rational fx[2], fy[2], m[2];
  if (pts[j].rho == 0 || !facet_rest(pts, j, p, u, omega, bits, fx, fy, m)) return false;
  const Rational dd = dot(d, d), reach = pts[j].rho * pts[j].rho * dd;
  const Rational m2_max = std::max(Rational(m[0] * m[0]), Rational(m[1] * m[1]));
  const Rational m2_min = m[0] <= 0 && m[1] >= 0 ? Rational(0) : std::min(Rational(m[0] * m[0]), Rational(m[1] * m[1]));
  if (!(m2_max < reach)) return false;
  Rational a[2], b[2], c[2];
  scaled_range(l.x * dd, fx, a), scaled_range(l.y * dd, fy, b), scaled_range(-dot(l, rot90(d)), m, c);
  const Rational A = a[0] + b[0] + c[0], ld = dot(l, d);
  return A > 0 && A * A > ld * ld * (reach - m2_min);
}

// [PU-2 §6] Is the sliding motion the rotation about support point j (a pivot: a facet of the limit surface)? Its
// velocity at p is u(τ_j) = v + τ_j t ⟂ r_j − p, its rate ω_j; it is the motion when its facet holds a force along the
// edge e through p (facet_holds).
bool pivot_motion(const std::vector<Rho_point>& pts, std::size_t j, const Vec2& p, const Vec2& v, const Vec2& t,
                  const Vec2& e, bool right, int bits, Rational& tau, Rational& omega) {
  const Vec2 d = minus(pts[j].at, p);
  if (pts[j].rho == 0 || dot(t, d) == 0 || cross(d, e) == 0) return false;
  tau = -dot(v, d) / dot(t, d);
  if (right ? tau <= 0 : tau >= 0) return false;  // the slip opposes the edge's friction
  const Vec2 u{v.x + tau * t.x, v.y + tau * t.y};
  omega = -dot(u, rot90(d)) / dot(d, d);  // u = −ω rot90(d): the velocity at p of the rotation about r_j
  return facet_holds(pts, j, p, u, omega, e, bits);
}

// [PU-2 §7] The sticking motion as a pivot: the pusher's velocity u ⟂ r_j − p, so the rotation about support point j at
// ω_j = −(u · rot90 d_j)/|d_j|² moves p with u, and g jumps across 0 there (the caller's g_sign). Its facet's forces
// through p lie on the chord of the line d_j × F = d_j × F' − M' inside the disc |F − F'| ≤ ρ_j; the contact sticks
// when a force of that chord is strictly inside the friction cone: the doubles propose the middle of the chord's part
// inside the cone, rounded to a rational direction e; the exact cone test and facet_holds certify it: `sticks`, with `r`
// filled (the pivot, the rate, the force's direction). When the doubles put S outside the cone, §8: S beyond one edge
// (every force of it), certified by facet_beyond: `slides_left` or `slides_right` with the pivot and the rate in `r`
// (the caller answers the rest). `undecided` when not certified (r.why says why).
Push_mode sticking_pivot(const std::vector<Rho_point>& pts, std::size_t j, const Vec2& p, const Vec2& u, const Rational& w,
                    const Vec2& eL, const Vec2& eR, Push_contact& r) {
  const double dx = pts[j].at.x.get_d() - p.x.get_d(), dy = pts[j].at.y.get_d() - p.y.get_d(), wd = w.get_d();
  double fx = 0, fy = 0, m = 0;  // F', M' in doubles (proposals only)
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (i == j) continue;
    const double qx = pts[i].at.x.get_d() - p.x.get_d(), qy = pts[i].at.y.get_d() - p.y.get_d();
    const double vx = u.x.get_d() - wd * qy, vy = u.y.get_d() + wd * qx, len = std::sqrt(vx * vx + vy * vy);
    if (len == 0) continue;
    const double rho = pts[i].rho.get_d();
    fx += rho * vx / len, fy += rho * vy / len, m += rho * (qx * vy - qy * vx) / len;
  }
  // the chord F(s) = F0 + s·d̂ (d × F0 = K, F0 ⟂ d), |F(s) − F'| ≤ ρ_j
  const double len = std::sqrt(dx * dx + dy * dy), K = dx * fy - dy * fx - m, rho = pts[j].rho.get_d();
  const double ux = dx / len, uy = dy / len, f0x = -uy * K / len, f0y = ux * K / len;
  const double off = (fx - f0x) * -uy + (fy - f0y) * ux, along = (fx - f0x) * ux + (fy - f0y) * uy;
  const double h2 = rho * rho - off * off;
  double lo = along - std::sqrt(std::max(0.0, h2)), hi = along + std::sqrt(std::max(0.0, h2));
  // inside the cone: e_R × F(s) > 0 and F(s) × e_L > 0, each a + b·s
  const auto cut = [&](double a, double b) {
    if (b > 0) lo = std::max(lo, -a / b);
    else if (b < 0) hi = std::min(hi, -a / b);
    else if (a <= 0) hi = lo - 1;
  };
  const double rx = eR.x.get_d(), ry = eR.y.get_d(), lx = eL.x.get_d(), ly = eL.y.get_d();
  cut(rx * f0y - ry * f0x, rx * uy - ry * ux);
  cut(f0x * ly - f0y * lx, ux * ly - uy * lx);
  const auto pivot_at = [&](int bits) { r.pivot = j, r.omega_lo = r.omega_hi = w, r.bits = bits; };
  if (h2 > 0 && !(lo < hi)) {  // §8: S misses the cone — beyond e_L (e_L × F > 0) or beyond e_R (e_R × F < 0)?
    const double mx = fx - off * -uy, my = fy - off * ux;  // the chord's middle
    const bool left = lx * my - ly * mx > 0, right = rx * my - ry * mx < 0;
    if (left != right) {
      const Vec2 l = left ? rot90(eL) : Vec2{-rot90(eR).x, -rot90(eR).y};
      for (int bits = 64; bits <= 1024; bits *= 2)
        if (facet_beyond(pts, j, p, u, w, l, bits)) return pivot_at(bits), left ? Push_mode::slides_left : Push_mode::slides_right;
    }
  }
  if (!(h2 > 0) || !(lo < hi)) {
    r.why = "a rotation about support point " + std::to_string(j) + " (a facet of the limit surface) meets the pusher's "
            "motion, and its forces are within the resolution of the friction cone's edge";
    return Push_mode::undecided;
  }
  // the middle of the chord's part in the cone, as a readable direction (each coordinate's simplest rational within a
  // 10⁻⁶ of the chord's length, scaled to that length: any direction of the part will do)
  const double s = (lo + hi) / 2, slack = 1e-6 * (hi - lo);
  const auto readable = [slack](double x) { return simplest_in(Rational(x - slack), Rational(x + slack)); };
  const Vec2 e{readable(f0x + s * ux), readable(f0y + s * uy)};
  if (cross(eR, e) > 0 && cross(e, eL) > 0)
    for (int bits = 64; bits <= 1024; bits *= 2)
      if (facet_holds(pts, j, p, u, w, e, bits)) {
        pivot_at(bits);
        r.force = e;
        return Push_mode::sticks;
      }
  r.why = "a rotation about support point " + std::to_string(j) + " (a facet of the limit surface) meets the pusher's "
          "motion, and its forces are within the resolution of the friction cone's edge";
  return Push_mode::undecided;
}

// [PU-2 §3, §8] The tangent velocity t = rot90 n at p: its force F(t) bounds the half-plane H of the forces that push
// (e in H: e × F(t) > 0). Its sticking candidate, proposed by the doubles; or, when t ⟂ r_k − p and g's jump at that
// rotation's rate ω_k holds 0, the rotation about support point k (a facet of K_p): its forces through p are the facet's
// chord, and e is in H when every one of them is on e's left (facet_beyond), out of it when every one is on its right.
class Tangent {
 public:
  Tangent(const std::vector<Rho_point>& pts, const Vec2& p, const Vec2& t, const Rational& tolerance)
      : pts_(pts), p_(p), t_(t) {
    if (const auto pivot = pivot_of(pts, p, t)) {
      std::tie(pivot_, w_) = *pivot;
      return;
    }
    const double wt = Double_points(pts, p).rate(t.x.get_d(), t.y.get_d());
    const double pad = std::max(1e-300, 0.25 * tolerance.get_d() * std::max(1.0, std::fabs(wt)));
    if (std::isfinite(wt) && wt != 0) candidate_.emplace(pts, p, t, Rational(wt - pad), Rational(wt + pad));
    else candidate_.emplace(pts, p, t);
  }
  const std::optional<Candidate>& candidate() const { return candidate_; }
  const std::optional<std::size_t>& pivot() const { return pivot_; }
  // +1: e certainly in H; −1: certainly not; 0: not (yet) certain
  int side(const Vec2& e) {
    if (candidate_) return candidate_->sign(rot90(e));
    for (const auto& [seen, sg] : sides_)
      if (seen.x == e.x && seen.y == e.y) return sg;
    int sg = 0;
    const Vec2 l = rot90(e), minus_l{-l.x, -l.y};
    for (int b = std::max(64, bits_); b <= 1024 && sg == 0; b *= 2)
      if (facet_beyond(pts_, *pivot_, p_, t_, w_, l, b)) sg = 1, bits_ = b;
      else if (facet_beyond(pts_, *pivot_, p_, t_, w_, minus_l, b)) sg = -1;
    sides_.push_back({e, sg});
    return sg;
  }
  bool narrow() { return candidate_ && candidate_->narrow(); }
  Rational lo() const { return candidate_ ? candidate_->lo() : w_; }
  Rational hi() const { return candidate_ ? candidate_->hi() : w_; }
  int bits() const { return candidate_ ? candidate_->bits() : bits_; }

 private:
  const std::vector<Rho_point>& pts_;
  Vec2 p_, t_;
  std::optional<Candidate> candidate_;
  std::optional<std::size_t> pivot_;
  Rational w_;
  int bits_ = 64;
  std::vector<std::pair<Vec2, int>> sides_;
};

// [PU-2 §5] The body's motion while the contact slides with its force on the edge e: the velocity at p is
// u(τ) = v + τ t (t = rot90 n: the pusher's normal velocity kept, a slip τ along the tangent) and the force F(u(τ))
// lies along e. F(u(τ)) turns counter-clockwise as τ grows (u turns counter-clockwise; the normal map of K_p is
// monotone), so e × F(u(τ)) changes sign once, from − to +: at τ = 0 it is − when sliding right (F_s beyond e_R,
// clockwise), + when sliding left. The slip bracket [τ_a, τ_b] has certified signs − at τ_a and + at τ_b (each by its
// candidate's ω bracket), and the rate's bracket [w0, w1] certified for every τ there: g(w0; u(τ)) < 0 < g(w1; u(τ)).
// `at_zero`: the sticking candidate (τ = 0); none when the sticking motion is a pivot (§8: its forces all beyond e).
void sliding_motion(const std::vector<Rho_point>& pts, const Vec2& p, const Vec2& v, const Vec2& t, const Vec2& e,
                    bool right, const Candidate* at_zero, const Rational& tolerance, Push_contact& r) {
  const Vec2 l = rot90(e);  // l·F = e × F
  // Exact: the edge's line through p passes through the centre of friction. The translation along e, with the
  // pusher's normal velocity, has its force D ê along e: u = k e with k = (v·n)/(e·n), τ* = (u − v)·t / t·t, ω* = 0.
  Rational rho = 0;
  Vec2 moment{0, 0};
  for (const Rho_point& q : pts) rho += q.rho, moment = {moment.x + q.rho * q.at.x, moment.y + q.rho * q.at.y};
  const Vec2 n{t.y, -t.x};
  if (rho > 0 && cross(Vec2{moment.x - rho * p.x, moment.y - rho * p.y}, e) == 0 && dot(e, n) != 0) {
    const Rational k = dot(v, n) / dot(e, n), tau = (k * dot(e, t) - dot(v, t)) / dot(t, t);  // u = k e = v + τ t
    r.slip_lo = r.slip_hi = tau, r.motion_lo = r.motion_hi = 0;
    r.slip_omega = {{{Rational(0), Rational(0)}, {Rational(0), Rational(0)}}};
    r.has_motion = true;
    return;
  }
  // The doubles propose: τ* and the rates at τ* ± δ, δ within the tolerance; the exact probes below certify them (or,
  // when they cannot, search from τ = 0).
  const Double_points dp(pts, p);
  const double vx = v.x.get_d(), vy = v.y.get_d(), tx = t.x.get_d(), ty = t.y.get_d();
  const double ll[2] = {l.x.get_d(), l.y.get_d()};
  const auto rate = [&](double ux, double uy, double& side) { return dp.rate(ux, uy, ll, &side); };
  std::optional<std::array<double, 3>> guess;  // τ*, ω at τ* − δ and τ* + δ
  double delta = 0;
  {
    double side = 0, a = 0, b = 0, step = std::max(std::fabs(step_hint(v, t)), 1e-300);
    bool bracketed = false;
    for (int i = 0; i < 200 && !bracketed; ++i, step *= 2) {
      const double tau = right ? step : -step;
      rate(vx + tau * tx, vy + tau * ty, side);
      if ((right && side > 0) || (!right && side < 0)) bracketed = true, (right ? b : a) = tau;
      else (right ? a : b) = tau;
    }
    if (bracketed && std::isfinite(a) && std::isfinite(b)) {
      for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (a + b);
        if (mid <= a || mid >= b) break;
        rate(vx + mid * tx, vy + mid * ty, side);
        (side < 0 ? a : b) = mid;
      }
      const double tau = 0.5 * (a + b);
      delta = 0.25 * tolerance.get_d() * std::max(1.0, std::fabs(tau));
      double s0 = 0, s1 = 0;
      const double w0 = rate(vx + (tau - delta) * tx, vy + (tau - delta) * ty, s0);
      const double w1 = rate(vx + (tau + delta) * tx, vy + (tau + delta) * ty, s1);
      if (std::isfinite(w0) && std::isfinite(w1) && delta > 0) guess = std::array<double, 3>{tau, w0, w1};
    }
  }
  // A pivot (PU-2 §6): exact, the rotation about a support point, when its facet holds the force along e. Tried for
  // the points whose pivot slip τ_j the doubles put within 10⁻⁶ of τ* (every point when they propose nothing).
  for (std::size_t j = 0; j < pts.size(); ++j) {
    const Vec2 d = minus(pts[j].at, p);
    if (guess && dot(t, d) != 0) {
      const double tj = Rational(-dot(v, d) / dot(t, d)).get_d();
      if (!(std::fabs(tj - (*guess)[0]) <= 1e-6 * (1 + std::fabs((*guess)[0])))) continue;
    }
    Rational tau, omega;
    if (pivot_motion(pts, j, p, v, t, e, right, std::max(64, r.bits), tau, omega)) {
      r.slip_lo = r.slip_hi = tau, r.motion_lo = r.motion_hi = omega;
      r.motion_pivot = j;
      r.has_motion = true;
      return;
    }
  }
  // The sign of e × F(u(τ)) at τ, its candidate narrowed until certain: ±1; 0 when not certain or a pivot. `w`: the
  // doubles' rate there, proposing the candidate's bracket.
  const auto probe = [&](const Rational& tau, std::optional<Candidate>& k, const double* w = nullptr) {
    const Vec2 at{v.x + tau * t.x, v.y + tau * t.y};
    if (w) {
      const double e = std::max(1e-300, delta / 16 * (1 + std::fabs(*w)));
      k.emplace(pts, p, at, Rational(*w - e), Rational(*w + e));
    } else {
      k.emplace(pts, p, at);
    }
    for (int i = 0; i < 400; ++i) {
      if (k->state() != Candidate::State::ok) return 0;
      const int sg = k->sign(l);
      if (sg == 1 || sg == -1) return sg;
      if (!k->narrow()) return 0;
    }
    return 0;
  };
  Rational step = abs(dot(v, n)) / dot(n, n);
  if (step == 0) step = 1;
  std::optional<Candidate> ka, kb, km;
  Rational ta = 0, tb = 0;
  bool found = false;
  if (guess) {  // the doubles' bracket, certified: e × F < 0 at τ* − δ and > 0 at τ* + δ
    const Rational a((*guess)[0] - delta), b((*guess)[0] + delta);
    if (probe(a, ka, &(*guess)[1]) == -1 && probe(b, kb, &(*guess)[2]) == 1) ta = a, tb = b, found = true;
  }
  if (!found) {
    ka.reset(), kb.reset();
    if (at_zero) {
      (right ? ka : kb).emplace(*at_zero);
    } else {  // §8: τ = 0 is the pivot (no bracket there); its side's sign holds near it — halve toward it
      for (int i = 0; i < 200; ++i, step /= 2) {
        const Rational tau = right ? step : -step;
        const int sg = probe(tau, km);
        if (sg == 0) break;
        const bool near = sg == (right ? -1 : 1);
        (near == right ? ta : tb) = tau, (near == right ? ka : kb).emplace(*km);
        if (near) {
          found = ka && kb;  // the far side seen on the way down: bracketed
          step *= 2;
          break;
        }
      }
      if (!(right ? ka : kb)) {
        r.motion_why = "the slip of the sliding motion could not be bracketed (near the pivot)";
        return;
      }
    }
  }
  for (int i = 0; i < 200 && !found; ++i, step *= 2) {
    const Rational tau = right ? step : -step;
    const int sg = probe(tau, km);
    if (sg == 0) break;
    if (sg == (right ? 1 : -1)) (right ? tb : ta) = tau, (right ? kb : ka).emplace(*km), found = true;
    else (right ? ta : tb) = tau, (right ? ka : kb).emplace(*km);
  }
  if (!found) {
    r.motion_why = "the slip of the sliding motion could not be bracketed (a rotation about a support point meets it)";
    return;
  }
  const auto wide = [&] {
    return tb - ta > tolerance * std::max(Rational(1), Rational(abs(ta) + abs(tb)));
  };
  for (int i = 0; i < 400 && wide(); ++i) {
    Rational mid = (ta + tb) / 2;
    int sg = probe(mid, km);
    if (sg == 0) mid = ta + (tb - ta) / 3, sg = probe(mid, km);
    if (sg == 0) break;
    if (sg < 0) ta = mid, ka.emplace(*km);
    else tb = mid, kb.emplace(*km);
  }
  // The rate over the slip bracket: the hull of the ends' brackets (each narrowed to the tolerance), widened until
  // certified for every τ between.
  const auto narrow_to_tolerance = [&](Candidate& k) {
    for (int i = 0; i < 400 && k.hi() - k.lo() > tolerance * std::max(Rational(1), Rational(abs(k.lo()) + abs(k.hi())));
         ++i)
      if (!k.narrow()) break;
  };
  narrow_to_tolerance(*ka), narrow_to_tolerance(*kb);
  Rational w0 = std::min(ka->lo(), kb->lo()), w1 = std::max(ka->hi(), kb->hi());
  const int bits = std::max({ka->bits(), kb->bits(), r.bits});
  for (int i = 0; i < 60; ++i) {
    Rational lo0, hi0, lo1, hi1;
    const bool ok0 = interval_sum(pts, p, v, {0, 0}, true, ta, tb, bits, lo0, hi0, &t, &w0);
    const bool ok1 = interval_sum(pts, p, v, {0, 0}, true, ta, tb, bits, lo1, hi1, &t, &w1);
    if (ok0 && ok1 && hi0 < 0 && lo1 > 0) {
      r.has_motion = true;
      r.slip_lo = ta, r.slip_hi = tb, r.motion_lo = w0, r.motion_hi = w1;
      r.slip_omega = {{{ka->lo(), ka->hi()}, {kb->lo(), kb->hi()}}};
      r.bits = bits;
      return;
    }
    const Rational pad = (w1 - w0) / 2 + tolerance * (abs(w0) + abs(w1) + 1) / 16;
    if (!(ok0 && hi0 < 0)) w0 -= pad;
    if (!(ok1 && lo1 > 0)) w1 += pad;
  }
  r.motion_why = "the rotation rate of the sliding motion could not be bracketed (a support point may be at rest in it)";
}

}  // namespace

Vec2 rotation_centre(const Vec2& p, const Vec2& u, const Rational& omega) {
  return {p.x - u.y / omega, p.y + u.x / omega};
}

namespace {

// PU-2 for the support points with forces `f` (every one given).
Push_contact contact_mode_on(const Support& s, const std::vector<Rational>& f, const Pusher& pusher,
                             const Rational& tolerance) {
  Push_contact r;
  std::vector<Rho_point> pts;
  for (std::size_t i = 0; i < s.points.size(); ++i) pts.push_back({s.points[i].at, s.mu_of(s.points[i]) * f[i]});
  const Contact& c = pusher.contact;
  const Vec2 p = c.at, u = pusher.velocity, t = rot90(c.normal);
  std::array<Vec2, 2> edge;  // left, right: the contacts' one construction
  point_contact_generators(c.at.x, c.at.y, c.normal.x, c.normal.y, c.mu, true, Reading::friction,
                           [&](Edge e, const Rational& fx, const Rational& fy, const Rational&) {
                             edge[e == Edge::left ? 0 : 1] = Vec2{fx, fy};
                           });
  const Vec2 &eL = edge[0], &eR = edge[1];
  // F in the cone pos{e_R, e_L}: cross(e_R, F) > 0 and cross(F, e_L) > 0; cross(a, F) = rot90(a)·F
  const Vec2 l_right = rot90(eR), l_left{-rot90(eL).x, -rot90(eL).y};
  std::optional<Tangent> plus;  // the tangent velocity rot90 n: the end F(t) of the pushing forces
  const auto failed = [&](const Candidate& k) {
    if (k.state() == Candidate::State::pivot) {
      r.why = "a rotation about a support point (a facet of the limit surface) meets the motion, and whether its jump "
              "holds the root could not be certified";
      return true;
    }
    if (k.state() == Candidate::State::failed) {
      r.why = "the sticking motion could not be bracketed";
      return true;
    }
    return false;
  };
  const auto tangent = [&] {  // false (r.why) when its candidate fails
    if (!plus) plus.emplace(pts, p, t, tolerance);
    return !plus->candidate() || !failed(*plus->candidate());
  };
  const auto keep_tangent = [&] {
    r.has_tangent = true, r.tangent_lo = plus->lo(), r.tangent_hi = plus->hi(), r.tangent_pivot = plus->pivot();
    r.bits = std::max(r.bits, plus->bits());
  };
  // the edge e in the pushing half-plane H (e × F(t) > 0), the tangent's candidate narrowed until certain; false (r.why)
  // when it is not or cannot be told
  const auto in_pushing_half_plane = [&](const Vec2& e) {
    for (int k = 0; k < 300; ++k) {
      const int in = plus->side(e);
      if (in == 1) return keep_tangent(), true;
      if (in == -1 || !plus->narrow() || !tangent()) break;
    }
    if (r.why.empty()) r.why = "the friction-cone edge the pivot's forces passed is not certainly among the forces that push";
    return false;
  };
  // [PU-2 §7] The sticking candidate at a pivot: the pusher's velocity ⟂ r_j − p and g's jump at ω_j holding 0 (then
  // ω* = ω_j exactly: g is nondecreasing). Only there can a support point be at rest while p moves with u.
  // Every force of its facet beyond an edge (§8): it slides from the facet, on that edge.
  if (const auto pivot = c.mu != 0 ? pivot_of(pts, p, u) : std::nullopt) {
    const auto& [j, w] = *pivot;
    const Push_mode m = sticking_pivot(pts, j, p, u, w, eL, eR, r);
    if (m == Push_mode::slides_left || m == Push_mode::slides_right) {  // §8: from the facet, on the edge it passed
      const bool right = m == Push_mode::slides_right;
      if (!tangent() || !in_pushing_half_plane(right ? eR : eL)) return r;
      r.mode = m;
      sliding_motion(pts, p, u, t, right ? eR : eL, right, nullptr, tolerance, r);
      return r;
    }
    r.mode = m;
    return r;
  }
  // The sticking candidate: the doubles propose ω* within a quarter of the tolerance, the exact signs keep it (else
  // the exact search brackets it).
  const double w_guess = Double_points(pts, p).rate(u.x.get_d(), u.y.get_d());
  const double w_pad = std::max(1e-300, 0.25 * tolerance.get_d() * std::max(1.0, std::fabs(w_guess)));
  Candidate stick = std::isfinite(w_guess) && w_guess != 0
                        ? Candidate(pts, p, u, Rational(w_guess - w_pad), Rational(w_guess + w_pad))
                        : Candidate(pts, p, u);
  for (int k = 0; k < 300; ++k) {
    if (failed(stick)) return r;
    const int right = stick.sign(l_right), left = stick.sign(l_left);
    if (c.mu != 0 && right == 1 && left == 1) {
      r.mode = Push_mode::sticks;
    } else if (right == 3 || left == 3) {  // exactly on an edge (a translation along it)
      r.mode = Push_mode::impending;
    } else if (right == -1 || left == -1 || (c.mu == 0 && right != 0)) {
      // Outside the cone. The forces whose outward normals on the boundary of K_p (the forces at p the support
      // resists) push into the body, v·n > 0, are the open half-plane H from F(−t) = −F(t) counter-clockwise to F(t),
      // t = rot90 n (PU-2 §3): F_s is in it. It slides on the edge it passed: left when e_L is in H and F_s beyond it
      // (counter-clockwise), right when e_R is in H and F_s beyond it (clockwise).
      if (!tangent()) return r;
      const Vec2 rl = rot90(eL), rr = rot90(eR);
      const int eL_in = plus->side(eL), eR_in = plus->side(eR);  // cross(e, F(t)) > 0: e in H
      const int beyond_left = stick.sign(rl), beyond_right = -stick.sign(rr);
      if (eL_in == 1 && beyond_left == 1) r.mode = Push_mode::slides_left;
      else if (eR_in == 1 && beyond_right == 1) r.mode = Push_mode::slides_right;
      else if (eL_in == -1 && eR_in == -1) {
        r.why = "neither edge of the friction cone has a pushing motion (the cone misses the forces that push)";
        return r;
      }
    }
    if (r.mode == Push_mode::slides_left || r.mode == Push_mode::slides_right || r.mode == Push_mode::impending) break;
    if (r.mode == Push_mode::sticks &&
        stick.hi() - stick.lo() <= tolerance * std::max(Rational(1), Rational(abs(stick.lo()) + abs(stick.hi()))))
      break;
    bool moved = stick.narrow();
    if (plus) moved = plus->narrow() | moved;
    if (!moved && r.mode == Push_mode::undecided) break;
  }
  r.omega_lo = stick.lo(), r.omega_hi = stick.hi(), r.bits = stick.bits();
  if (plus && (r.mode == Push_mode::slides_left || r.mode == Push_mode::slides_right)) {
    keep_tangent();
    const bool right = r.mode == Push_mode::slides_right;
    sliding_motion(pts, p, u, t, right ? eR : eL, right, &stick, tolerance, r);
  }
  if (r.mode == Push_mode::undecided && r.why.empty())
    r.why = "the sticking motion's force is within the resolution of a friction-cone edge (the boundary of sticking)";
  return r;
}

}  // namespace

Push_contact push_contact_mode(const Support_model& model, const Pusher& pusher, const Rational& tolerance) {
  const Support& s = model.support();
  if (!s.regions.empty()) {
    Push_contact r;
    r.why = "the contact mode is answered for support points (not yet for regions)";
    return r;
  }
  if (model.known()) return contact_mode_on(s, model.given(), pusher, tolerance);
  // Forces not given: the mode at each extreme distribution of F (PU-2 each, certified); two that differ prove
  // "depends". Agreeing everywhere proves nothing between them (the mode is not convex in the distribution).
  Push_contact r;
  if (model.admissible().unknown.size() > kMaxContactUnknowns) {
    r.why = "the contact mode over forces not given is sought at F's extreme distributions, for at most " +
            std::to_string(kMaxContactUnknowns) + " unknown forces";
    return r;
  }
  const std::vector<std::vector<Rational>> corners = vertices(s, model.admissible());
  std::optional<Push_contact> first;
  std::size_t tried = 0;
  for (const std::vector<Rational>& f : corners) {
    if (++tried > kMaxContactCorners) break;
    Push_contact k = contact_mode_on(s, f, pusher, tolerance);
    if (k.mode == Push_mode::undecided || k.mode == Push_mode::impending) continue;
    k.forces = f;
    if (!first) {
      first = std::move(k);
    } else if (k.mode != first->mode) {
      r.mode = Push_mode::depends;
      r.witnesses = {std::move(*first), std::move(k)};
      return r;
    }
  }
  const std::string which = tried > kMaxContactCorners ? "the first " + std::to_string(kMaxContactCorners) +
                                                             " extreme distributions of F"
                                                       : "the extreme distributions of F";
  r.why = first ? "each of " + which + " whose mode was certified " + push_mode_name(first->mode) +
                      ", but the mode between them is not certified (it is not convex in the distribution)"
                : "none of " + which + " had a certified contact mode";
  return r;
}

std::optional<Slowest_turn> slowest_turn(const Support_model& model, const Pusher& pusher, const Rational& tolerance,
                                         const std::optional<Push_contact>& given) {
  const Support& s = model.support();
  if (!s.regions.empty() || model.admissible().unknown.size() > kMaxContactUnknowns) return std::nullopt;
  const std::vector<std::vector<Rational>> corners =
      model.known() ? std::vector<std::vector<Rational>>{model.given()} : vertices(s, model.admissible());
  std::optional<Push_contact> best;
  Rational best_hi;
  std::size_t tried = 0;
  for (const std::vector<Rational>& f : corners) {
    if (++tried > kMaxSlowestCorners) break;
    Push_contact k = model.known() && given ? *given : contact_mode_on(s, f, pusher, tolerance);
    const bool sticks = k.mode == Push_mode::sticks, slides = (k.mode == Push_mode::slides_left ||
                                                                k.mode == Push_mode::slides_right) && k.has_motion;
    if (!sticks && !slides) continue;
    const Rational lo = sticks ? k.omega_lo : k.motion_lo, hi = sticks ? k.omega_hi : k.motion_hi;
    if (sgn(lo) == 0 || sgn(lo) != sgn(hi)) continue;  // (a translation, or its sense not certain)
    const Rational most = std::max(abs(lo), abs(hi));
    if (best && most >= best_hi) continue;
    k.forces = f;
    best = std::move(k), best_hi = most;
  }
  if (!best) return std::nullopt;
  // arm_lo ≤ v·n / (|ω|_hi |n|): the contact advances at v·n whether it sticks or slips (the slip is along rot90 n)
  const Rational vn = dot(pusher.velocity, pusher.contact.normal);
  const Rational arm2 = vn * vn / (best_hi * best_hi * dot(pusher.contact.normal, pusher.contact.normal));
  return Slowest_turn{std::move(*best), outward(sqrt_bracket(arm2, 64).first, 6, false)};
}

}  // namespace wrenchkit
