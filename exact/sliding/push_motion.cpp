// [PU-2] The pushed body's contact mode for a support of points with every force given: see pushing.h and
// proofs/notes/PU-2-contact-mode.md. Exact signs of interval sums whose square roots are bracketed by rationals.
#include <algorithm>
#include <optional>

#include "core/contact_generators.h"
#include "exact/sliding/pushing.h"
#include "exact/sliding/sliding.h"

namespace wrenchkit {

const char* push_mode_name(Push_mode m) {
  switch (m) {
    case Push_mode::sticks: return "sticks";
    case Push_mode::impending: return "impending";
    case Push_mode::slides_left: return "slides left";
    case Push_mode::slides_right: return "slides right";
    case Push_mode::undecided: return "undecided";
  }
  return "?";
}

namespace {

// The interval of Σ ρ_i (ℓ_i · v_i(ω)) / |v_i(ω)| over [lo, hi], ℓ_i = l, or rot90(r_i − p) when `moment` (then the
// sum is the moment about p of the load). False when a speed may vanish on the interval.
bool interval_sum(const std::vector<Rho_point>& pts, const Vec2& p, const Vec2& u, const Vec2& l, bool moment,
                  const Rational& lo, const Rational& hi, int bits, Rational& out_lo, Rational& out_hi) {
  out_lo = 0, out_hi = 0;
  for (const Rho_point& q : pts) {
    if (q.rho == 0) continue;
    const Vec2 d = minus(q.at, p), w = rot90(d);
    const Vec2 li = moment ? w : l;
    // numerator ℓ·u + ω ℓ·w, linear; |v|² = |u|² + 2ω u·w + ω²|d|², convex
    const Rational a = dot(li, u), b = dot(li, w);
    Rational n_lo = a + lo * b, n_hi = a + hi * b;
    if (n_lo > n_hi) std::swap(n_lo, n_hi);
    const Rational uu = dot(u, u), uw = dot(u, w), dd = dot(d, d);
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

}  // namespace

namespace {

// The sticking candidate of a velocity u at p: ω* (the root of g, nondecreasing) in [lo, hi], certified; exact when
// lo = hi (only ω* = 0: u passes through the centre of friction, the load a translation's, its force D û).
class Candidate {
 public:
  enum class State { ok, pivot, failed };
  Candidate(const std::vector<Rho_point>& pts, const Vec2& p, const Vec2& u) : pts_(pts), p_(p), u_(u) {
    Rational g0 = 0;
    for (const Rho_point& q : pts_) g0 += q.rho * cross(minus(q.at, p_), u_);
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

}  // namespace

Push_contact push_contact_mode(const Support_model& model, const Pusher& pusher, const Rational& tolerance) {
  Push_contact r;
  const Support& s = model.support();
  if (!model.known() || !s.regions.empty()) {
    r.why = "the contact mode is answered for support points with every force given (not yet for regions or forces "
            "not given)";
    return r;
  }
  std::vector<Rho_point> pts;
  for (std::size_t i = 0; i < s.points.size(); ++i) pts.push_back({s.points[i].at, s.mu_of(s.points[i]) * model.given()[i]});
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
  Candidate stick(pts, p, u);
  std::optional<Candidate> plus;  // the candidate of the tangent velocity rot90 n: the end F(t) of the pushing forces
  const auto failed = [&](const Candidate& k) {
    if (k.state() == Candidate::State::pivot) {
      r.why = "a rotation about a support point (a facet of the limit surface) meets the pusher's motion: not yet "
              "answered";
      return true;
    }
    if (k.state() == Candidate::State::failed) {
      r.why = "the sticking motion could not be bracketed";
      return true;
    }
    return false;
  };
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
      if (!plus) plus.emplace(pts, p, t);
      if (failed(*plus)) return r;
      const Vec2 rl = rot90(eL), rr = rot90(eR);
      const int eL_in = plus->sign(rl), eR_in = plus->sign(rr);  // cross(e, F(t)) > 0: e in H
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
    r.has_tangent = true, r.tangent_lo = plus->lo(), r.tangent_hi = plus->hi();
    r.bits = std::max(r.bits, plus->bits());
  }
  if (r.mode == Push_mode::undecided && r.why.empty())
    r.why = "the sticking motion's force is within the resolution of a friction-cone edge (the boundary of sticking)";
  return r;
}

}  // namespace wrenchkit
