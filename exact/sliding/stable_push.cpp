// [PU-3] Stable pushing with a line contact. See stable_push.h.
#include "exact/sliding/stable_push.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/contact_generators.h"
#include "exact/io/input_error.h"
#include "exact/sliding/pushing.h"
#include "exact/sliding/sliding.h"

namespace wrenchkit {

const char* stability_name(Stability s) {
  switch (s) {
    case Stability::stable: return "stable";
    case Stability::unstable: return "unstable";
    case Stability::undecided: return "undecided";
  }
  return "?";
}

const char* cone_facet_name(Cone_facet f) {
  switch (f) {
    case Cone_facet::left_edge: return "left edge";
    case Cone_facet::right_edge: return "right edge";
    case Cone_facet::end0: return "end 0";
    case Cone_facet::end1: return "end 1";
  }
  return "?";
}

namespace {

// In the answers' words: "left edge", "right edge", "facet of end 0" (the load's line past that end).
std::string facet_phrase(Cone_facet f) {
  return f == Cone_facet::left_edge || f == Cone_facet::right_edge ? std::string(cone_facet_name(f))
                                                                   : std::string("facet of ") + cone_facet_name(f);
}

// The line contact's frame: its ends, the cone's edges, and the sign s_k of each end (+1 for the end p₁ of PU-3, with
// (p₂ − p₁) × n > 0, whose moment must be ≥ 0; −1 for p₂).
struct Line_contact {
  std::array<Vec2, 2> end;
  Vec2 n, left, right;
  std::array<int, 2> s;
  int sigma = 0;
  std::optional<Vec2> q;
};

// The facet's term h(x) (PU-3 §1, signed so that the load of weights w_k at x_k leaves CF by it when
// Σ w_k h(x_k)/|x_k − q| > 0): σ(x − q)·e₊, −σ(x − q)·e₋, and for end k −s_k σ (x − e_k)·(x − q).
Rational term(const Line_contact& L, Cone_facet f, const Vec2& x) {
  const Vec2 xq = minus(x, *L.q);
  switch (f) {
    case Cone_facet::left_edge: return L.sigma * dot(xq, L.left);
    case Cone_facet::right_edge: return -L.sigma * dot(xq, L.right);
    case Cone_facet::end0:
    case Cone_facet::end1: {
      const int k = f == Cone_facet::end0 ? 0 : 1;
      return -L.s[k] * L.sigma * dot(minus(x, L.end[k]), xq);
    }
  }
  return 0;
}

// The certified interval of Σ w_k h(x_k)/|x_k − q| (square roots bracketed at `bits`): false when some x_k = q.
bool load_interval(const Line_contact& L, Cone_facet f, const std::vector<Vec2>& x, const std::vector<Rational>& w,
                   int bits, Rational& lo, Rational& hi) {
  lo = 0, hi = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const Vec2 xq = minus(x[k], *L.q);
    const auto [l0, l1] = sqrt_bracket(dot(xq, xq), bits);
    if (sgn(l0) <= 0) return false;
    const Rational h = w[k] * term(L, f, x[k]);
    if (sgn(h) >= 0) lo += h / l1, hi += h / l0;
    else lo += h / l0, hi += h / l1;
  }
  return true;
}

// A distribution of S with mean c whose load is certainly beyond facet f: searched in doubles over one, two or three
// of the candidate points (the LP's basic solutions), the best few certified exactly.
bool find_witness(const Line_contact& L, Cone_facet f, const std::vector<Vec2>& candidates, const Vec2& c,
                  Stable_push& out) {
  struct Pick {
    double value;
    std::array<std::size_t, 3> idx;
    std::size_t size;
  };
  const std::size_t n = candidates.size();
  std::vector<double> g(n), dx(n), dy(n);
  std::vector<bool> usable(n);
  const double cx = c.x.get_d(), cy = c.y.get_d();
  double scale = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 xq = minus(candidates[i], *L.q);
    const double l = std::sqrt(dot(xq, xq).get_d());
    usable[i] = !is_zero(xq);
    g[i] = usable[i] ? term(L, f, candidates[i]).get_d() / l : 0;
    dx[i] = candidates[i].x.get_d() - cx, dy[i] = candidates[i].y.get_d() - cy;
    scale = std::max({scale, std::abs(dx[i]), std::abs(dy[i])});
  }
  const double eps = 1e-12 * scale * scale;
  std::vector<Pick> picks;
  for (std::size_t i = 0; i < n; ++i) {
    if (!usable[i]) continue;
    if (std::abs(dx[i]) + std::abs(dy[i]) <= 1e-12 * scale) picks.push_back({g[i], {i, 0, 0}, 1});
    for (std::size_t j = i + 1; j < n; ++j) {
      if (!usable[j]) continue;
      const double cr = dx[i] * dy[j] - dy[i] * dx[j], dt = dx[i] * dx[j] + dy[i] * dy[j];
      if (std::abs(cr) <= eps && dt < 0) {  // c between them: weights |x_j − c| and |x_i − c|
        const double a = std::hypot(dx[j], dy[j]), b = std::hypot(dx[i], dy[i]);
        picks.push_back({(a * g[i] + b * g[j]) / (a + b), {i, j, 0}, 2});
      }
      for (std::size_t k = j + 1; k < n; ++k) {
        if (!usable[k]) continue;
        const double la = dx[j] * dy[k] - dy[j] * dx[k], lb = dx[k] * dy[i] - dy[k] * dx[i],
                     lc = dx[i] * dy[j] - dy[i] * dx[j];
        if (!((la > eps && lb > eps && lc > eps) || (la < -eps && lb < -eps && lc < -eps))) continue;
        picks.push_back({(la * g[i] + lb * g[j] + lc * g[k]) / (la + lb + lc), {i, j, k}, 3});
      }
    }
  }
  picks.erase(std::remove_if(picks.begin(), picks.end(), [](const Pick& p) { return !std::isfinite(p.value); }),
              picks.end());  // (doubles out of range: no proposal from them)
  std::sort(picks.begin(), picks.end(), [](const Pick& a, const Pick& b) { return a.value > b.value; });
  for (std::size_t t = 0; t < picks.size() && t < 8 && picks[t].value > 0; ++t) {
    const Pick& p = picks[t];
    std::vector<Vec2> x;
    std::vector<Rational> w;
    for (std::size_t k = 0; k < p.size; ++k) x.push_back(candidates[p.idx[k]]);
    if (p.size == 1) {
      if (x[0].x != c.x || x[0].y != c.y) continue;
      w = {Rational(1)};
    } else if (p.size == 2) {  // w_0 (x_0 − c) + w_1 (x_1 − c) = 0
      const Vec2 a = minus(x[0], c), b = minus(x[1], c);
      if (cross(a, b) != 0 || dot(a, b) >= 0) continue;
      w = {-dot(a, b) / dot(a, a), Rational(1)};
    } else {  // the barycentric weights of c, exact: all of one sign
      const Vec2 a = minus(x[0], c), b = minus(x[1], c), d = minus(x[2], c);
      w = {cross(b, d), cross(d, a), cross(a, b)};
      const int s0 = sgn(w[0]);
      if (s0 == 0 || sgn(w[1]) != s0 || sgn(w[2]) != s0) continue;
      if (s0 < 0)
        for (Rational& r : w) r = -r;
      const Rational total = w[0] + w[1] + w[2];
      for (Rational& r : w) r /= total;
    }
    for (int bits : {64, 128, 256}) {
      Rational lo, hi;
      if (!load_interval(L, f, x, w, bits, lo, hi)) break;
      if (sgn(lo) > 0) {
        out.facet = f, out.points = std::move(x), out.weights = std::move(w), out.bits = bits;
        return true;
      }
      if (sgn(hi) <= 0) break;
    }
  }
  return false;
}

}  // namespace

// x rounded outward to `digits` decimals (up or down): short numbers for the certificate a person reads
// (the tip line's bounds, a dual proposed in doubles — a double is a rational).
Rational outward(const Rational& x, int digits, bool up) {
  Integer scale, r;
  mpz_ui_pow_ui(scale.get_mpz_t(), 10, static_cast<unsigned long>(digits));
  const Integer t = x.get_num() * scale;
  if (up) mpz_cdiv_q(r.get_mpz_t(), t.get_mpz_t(), x.get_den().get_mpz_t());
  else mpz_fdiv_q(r.get_mpz_t(), t.get_mpz_t(), x.get_den().get_mpz_t());
  Rational out(r, scale);
  out.canonicalize();
  return out;
}

namespace {

// [PU-3 §7] A finite S (points only): the LP max Σ w_i g_i over w ≥ 0, Σ w_i = 1, Σ w_i (x_i − c) = 0 has the dual
// min y0 over y0 + y·(x_i − c) ≥ g_i (g_i = h(x_i)/|x_i − q|). A dual point with y0 < 0 proves the facet holds for every
// distribution: Σ w h/ℓ ≤ Σ w (y0 + y·(x_i − c)) = y0 Σ w < 0. Found at a vertex of three tight constraints in doubles,
// then made exact: y0 halved toward 0 (its slack), y rounded, every constraint certified with √ bracketed at `bits`.
bool find_dual(const Line_contact& L, Cone_facet f, const std::vector<Vec2>& S, const Vec2& c, std::array<Rational, 3>& y,
               int& bits) {
  const std::size_t n = S.size();
  std::vector<double> g(n), ax(n), ay(n);
  double scale = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 xq = minus(S[i], *L.q);
    if (is_zero(xq)) return false;  // a point at the rotation centre: its friction is not one force
    g[i] = term(L, f, S[i]).get_d() / std::sqrt(dot(xq, xq).get_d());
    ax[i] = Rational(S[i].x - c.x).get_d(), ay[i] = Rational(S[i].y - c.y).get_d();
    scale = std::max({scale, std::abs(ax[i]), std::abs(ay[i])});
  }
  double best = 1e300, by[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        // y0 + yx ax + yy ay = g at i, j, k (Cramer's rule)
        const double det = (ax[j] - ax[i]) * (ay[k] - ay[i]) - (ay[j] - ay[i]) * (ax[k] - ax[i]);
        if (std::abs(det) <= 1e-12 * scale * scale) continue;
        const double yx = ((g[j] - g[i]) * (ay[k] - ay[i]) - (ay[j] - ay[i]) * (g[k] - g[i])) / det;
        const double yy = ((ax[j] - ax[i]) * (g[k] - g[i]) - (g[j] - g[i]) * (ax[k] - ax[i])) / det;
        const double y0 = g[i] - yx * ax[i] - yy * ay[i];
        if (y0 >= best) continue;
        bool feasible = true;
        for (std::size_t l = 0; l < n && feasible; ++l) feasible = y0 + yx * ax[l] + yy * ay[l] >= g[l] - 1e-12;
        if (feasible) best = y0, by[0] = y0, by[1] = yx, by[2] = yy;
      }
  if (!(best < -1e-12) || !std::isfinite(by[0]) || !std::isfinite(by[1]) || !std::isfinite(by[2])) return false;
  for (int digits : {6, 12, 0}) {
    const auto near = [&](double x, bool up) { return digits == 0 ? Rational(x) : outward(Rational(x), digits, up); };
    y = {near(by[0] / 2, true), near(by[1], false), near(by[2], false)};
    if (sgn(y[0]) >= 0) continue;
    for (int b : {64, 128}) {
      bool all = true;
      for (std::size_t i = 0; i < n && all; ++i) {
        const Vec2 xq = minus(S[i], *L.q), a = minus(S[i], c);
        const auto [l0, l1] = sqrt_bracket(dot(xq, xq), b);
        const Rational h = term(L, f, S[i]);
        all = (sgn(h) >= 0 ? Rational(h / l0) : Rational(h / l1)) <= y[0] + y[1] * a.x + y[2] * a.y;
      }
      if (all) {
        bits = b;
        return true;
      }
    }
  }
  return false;
}

// What the query and the region share: the line contact and the support's friction disc.
struct Prepared {
  Line_contact L;
  std::vector<Vec2> vertices;
  std::optional<Vec2> c;
  std::string why;
  Rational R2;
};

Prepared prepare(const Support_model& model, const Pusher& pusher) {
  const Contact& pc = pusher.contact;
  Prepared P;
  Line_contact& L = P.L;
  L.end = {pc.at, *pusher.end};
  L.n = pc.normal;
  point_contact_generators(pc.at.x, pc.at.y, pc.normal.x, pc.normal.y, pc.mu, true, Reading::friction,
                           [&](Edge e, const Rational& fx, const Rational& fy, const Rational&) {
                             (e == Edge::left ? L.left : L.right) = Vec2{fx, fy};
                           });
  const int first = sgn(cross(minus(L.end[1], L.end[0]), L.n)) > 0 ? 0 : 1;  // PU-3's p₁
  L.s = {first == 0 ? 1 : -1, first == 0 ? -1 : 1};
  L.sigma = sgn(pusher.omega);
  const Vec2 m{(L.end[0].x + L.end[1].x) / 2, (L.end[0].y + L.end[1].y) / 2};
  if (L.sigma != 0) L.q = rotation_centre(m, pusher.velocity, pusher.omega);
  Friction_disc d = friction_disc(model);
  P.vertices = std::move(d.vertices), P.c = d.c, P.why = std::move(d.why), P.R2 = d.R2;
  return P;
}

// PU-3 §5's correction E at the bounds R ≥ R, d ≤ |q − c|, α ≥ |c − e_t| (an upper bound of the true E: it grows with
// R and α and falls with d). Precondition: d > R ≥ 0.
Rational tip_correction(const Rational& R, const Rational& d, const Rational& al) {
  const Rational K = R * (2 * al + R) / (2 * d - R);
  return K * K * (2 * d + R) / (8 * d) + al * R * R * R / (d * (2 * d - R));
}

}  // namespace

Friction_disc friction_disc(const Support_model& model) {
  const Support& s = model.support();
  Friction_disc P;
  std::set<Rational> mus;
  for (const Support_point& p : s.points) {
    mus.insert(s.mu_of(p));
    if (s.mu_of(p) > 0) P.vertices.push_back(p.at);
  }
  for (const Support_region& r : s.regions) {
    mus.insert(s.mu_of(r));
    if (s.mu_of(r) > 0)
      for (const auto& ring : r.rings) P.vertices.insert(P.vertices.end(), ring.begin(), ring.end());
  }
  const Admissible& F = model.admissible();
  Rational D = 0;
  for (std::size_t i = 0; i < s.points.size(); ++i) D += s.mu_of(s.points[i]) * F.given[i];
  for (const Support_region& r : s.regions) D += s.mu_of(r) * r.total;
  if (P.vertices.empty() || (model.known() && D <= 0))
    throw Input_error("support: no friction under the body (no support point or region with a force and mu > 0): "
                      "nothing resists the pusher, so the body does not slide quasi-statically; give the support a "
                      "friction coefficient (support.mu)");
  if (model.known()) {
    P.c = friction_center(s, F.given);
  } else if (mus.size() == 1) {  // one μ > 0 under the whole body: the centre of pressure W c (distribution.h's rows)
    Vec2 mo = F.rest_moment;
    Rational W = F.rest;
    for (std::size_t i = 0; i < s.points.size(); ++i)
      mo.x += F.given[i] * s.points[i].at.x, mo.y += F.given[i] * s.points[i].at.y, W += F.given[i];
    for (const Support_region& r : s.regions) mo.x += r.moment.x, mo.y += r.moment.y, W += r.total;
    P.c = Vec2{mo.x / W, mo.y / W};
  } else {
    P.why = "the centre of friction moves with the distribution (the support's coefficients differ and some forces are "
            "not given): answered about one centre of friction only";
    return P;
  }
  for (const Vec2& x : P.vertices) P.R2 = std::max(P.R2, dot(minus(x, *P.c), minus(x, *P.c)));
  return P;
}

std::optional<Rational> tip_line_T(const Rational& R2, const Rational& R_hi, const Rational& al) {
  const auto holds = [&](const Rational& T) {
    const Rational d = T / al;
    return d > R_hi && T >= R2 + tip_correction(R_hi, d, al);
  };
  // E falls as T grows: bisect in doubles, then certify a short decimal a little above the fixed point, doubling the
  // margin until it holds
  const double Rd = R_hi.get_d(), ad = al.get_d(), R2d = R2.get_d();
  const auto f = [&](double T) {
    const double d = T / ad, K = Rd * (2 * ad + Rd) / (2 * d - Rd);
    return T - R2d - (K * K * (2 * d + Rd) / (8 * d) + ad * Rd * Rd * Rd / (d * (2 * d - Rd)));
  };
  double tlo = ad * Rd * (1 + 1e-12), thi = std::max(tlo * 2, R2d + 2 * ad * Rd + 8 * (ad + Rd) * (ad + Rd) + 1);
  for (int it = 0; it < 200 && f(thi) < 0; ++it) thi *= 2;
  for (int it = 0; it < 100; ++it) (f((tlo + thi) / 2) < 0 ? tlo : thi) = (tlo + thi) / 2;
  for (double margin = 1e-9; margin < 1e6 && std::isfinite(thi); margin *= 16) {
    const Rational T = outward(Rational(thi * (1 + margin) + margin), 6, true);
    if (holds(T)) return T;
  }
  // (the doubles out of range: the exact value a step at a time)
  Rational T = R2 + al * R_hi + 1;
  for (int it = 0; it < 64 && !holds(T); ++it) T *= 2;
  if (holds(T)) return T;
  return std::nullopt;
}

Stable_push decide_stable_push(const Support_model& model, const Pusher& pusher) {
  Stable_push a;
  const Prepared P = prepare(model, pusher);
  const Line_contact& L = P.L;
  const Support& s = model.support();
  a.sense = L.sigma;
  a.centre = L.q;
  a.friction_centre = P.c;
  a.why = P.why;
  if (!P.c) return a;
  const std::vector<Vec2>& vertices = P.vertices;
  const Vec2 c = *P.c;
  a.R2 = P.R2;
  // the corners: a force of the composite cone is a sum of forces along e₊, e₋ at points of the segment, its moment
  // about c a positive combination of (e_k − c) × e at the four corners (affine along the segment)
  std::set<int> corner;
  for (const Vec2& e : L.end)
    for (const Vec2& d : {L.left, L.right}) corner.insert(sgn(cross(minus(e, c), d)));
  a.corners = corner.size() == 1 ? *corner.begin() : 0;

  if (L.sigma == 0) {  // the load is v through c (PU-3 §1 with every point moving along v): exact
    const Vec2& v = pusher.velocity;
    a.values = {cross(v, L.left), cross(L.right, v), L.s[0] * cross(minus(c, L.end[0]), v),
                L.s[1] * cross(minus(c, L.end[1]), v)};
    for (int k = 0; k < 4; ++k)
      if (sgn(a.values[k]) < 0) {
        a.verdict = Stability::unstable;
        a.facet = static_cast<Cone_facet>(k);
        a.why = "translating, the load is the pusher's velocity through the centre of friction for every "
                "distribution, and it is beyond the composite cone's " + facet_phrase(a.facet) + ": the contact cannot stick";
        return a;
      }
    a.verdict = Stability::stable;
    std::string on;
    for (int k = 0; k < 4; ++k)
      if (sgn(a.values[k]) == 0) on += std::string(on.empty() ? "" : ", ") + cone_facet_name(static_cast<Cone_facet>(k));
    a.why = "translating, the load is the pusher's velocity through the centre of friction for every distribution, "
            "inside the composite friction cone" +
            (on.empty() ? std::string() : " (on its boundary: " + on + ")");
    return a;
  }

  // Rotating about q: the four sufficient conditions (PU-3 §2, §3, §5).
  const Vec2 q = *L.q;
  std::vector<Cone_facet> failing;
  Rational left_max = term(L, Cone_facet::left_edge, vertices[0]), right_max = term(L, Cone_facet::right_edge, vertices[0]);
  for (const Vec2& x : vertices)
    left_max = std::max(left_max, term(L, Cone_facet::left_edge, x)),
    right_max = std::max(right_max, term(L, Cone_facet::right_edge, x));
  if (sgn(left_max) > 0) failing.push_back(Cone_facet::left_edge);
  if (sgn(right_max) > 0) failing.push_back(Cone_facet::right_edge);
  const std::size_t bis = L.s[0] * L.sigma > 0 ? 0 : 1, tip = 1 - bis;
  a.tip = tip;
  const Vec2 qb = minus(q, L.end[bis]), w = minus(q, c), tip_a = minus(c, L.end[tip]);
  if (dot(qb, qb) > dot(w, w)) failing.push_back(bis == 0 ? Cone_facet::end0 : Cone_facet::end1);
  bool tip_holds = false;
  // The bounds as short decimals when they suffice (10⁻³, 10⁻⁶, 10⁻¹²: a certificate a person can read), else the
  // square roots bracketed at 256 bits.
  for (int digits : {3, 6, 12, 0}) {
    const int bits = digits == 0 ? 256 : 64;
    a.R_hi = sqrt_bracket(a.R2, bits).second;
    a.d_lo = sqrt_bracket(dot(w, w), bits).first;
    a.alpha_hi = sqrt_bracket(dot(tip_a, tip_a), bits).second;
    if (digits != 0)
      a.R_hi = outward(a.R_hi, digits, true), a.d_lo = outward(a.d_lo, digits, false),
      a.alpha_hi = outward(a.alpha_hi, digits, true);
    if (a.d_lo <= a.R_hi) continue;
    if (dot(tip_a, w) >= a.R2 + tip_correction(a.R_hi, a.d_lo, a.alpha_hi)) {
      tip_holds = true;
      break;
    }
  }
  a.tip_line = tip_holds;
  if (!tip_holds) failing.push_back(tip == 0 ? Cone_facet::end0 : Cone_facet::end1);
  if (failing.empty()) {
    a.verdict = Stability::stable;
    a.why = "for every distribution with this centre of friction: every place of the support is behind both "
            "friction-cone edges' lines through the rotation centre, which is at least as close to end " +
            std::to_string(bis) + " as to the centre of friction (the bisector) and beyond end " + std::to_string(tip) +
            "'s corrected tip line (PU-3 §2, §3, §5)";
    return a;
  }
  // A witness: candidates are S's vertices and, for regions, points along their rings' edges.
  std::vector<Vec2> candidates;
  for (const Support_point& p : s.points)
    if (s.mu_of(p) > 0) candidates.push_back(p.at);
  for (const Support_region& r : s.regions)
    if (s.mu_of(r) > 0)
      for (const auto& ring : r.rings)
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const Vec2 &u = ring[i], &v = ring[(i + 1) % ring.size()];
          for (int t = 0; t < 4; ++t)
            candidates.push_back({u.x + Rational(t, 4) * (v.x - u.x), u.y + Rational(t, 4) * (v.y - u.y)});
        }
  std::sort(candidates.begin(), candidates.end(),
            [](const Vec2& x, const Vec2& y) { return x.x < y.x || (x.x == y.x && x.y < y.y); });
  candidates.erase(std::unique(candidates.begin(), candidates.end(),
                               [](const Vec2& x, const Vec2& y) { return x.x == y.x && x.y == y.y; }),
                   candidates.end());
  constexpr std::size_t kMaxCandidates = 48;
  // S finite and small (points only): the witness search is the whole LP, and its dual proves a facet it finds holds
  const bool finite = vertices.size() <= kMaxCandidates &&
                      std::none_of(s.regions.begin(), s.regions.end(), [&](const Support_region& r) { return s.mu_of(r) > 0; });
  std::vector<Cone_facet> unproven;
  for (const Cone_facet f : failing) {
    std::vector<Vec2> pool = candidates;
    if (pool.size() > kMaxCandidates) {  // the 40 largest terms and the 8 extreme points around c (to balance them)
      std::vector<std::pair<double, std::size_t>> by;
      for (std::size_t i = 0; i < pool.size(); ++i) {
        const Vec2 xq = minus(pool[i], q);
        const double g = is_zero(xq) ? -1e300 : term(L, f, pool[i]).get_d() / std::sqrt(dot(xq, xq).get_d());
        by.push_back({std::isnan(g) ? -1e300 : g, i});
      }
      std::sort(by.rbegin(), by.rend());
      std::vector<Vec2> kept;
      for (std::size_t i = 0; i < 40; ++i) kept.push_back(pool[by[i].second]);
      static const int dirs[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
      for (const auto& d : dirs) {
        std::size_t best = 0;
        for (std::size_t i = 1; i < pool.size(); ++i)
          if (d[0] * pool[i].x + d[1] * pool[i].y > d[0] * pool[best].x + d[1] * pool[best].y) best = i;
        kept.push_back(pool[best]);
      }
      pool = std::move(kept);
    }
    std::array<Rational, 3> y;
    int bits = 64;
    if (finite && find_dual(L, f, vertices, c, y, bits)) {
      a.duals.push_back({f, y});
      a.bits = std::max(a.bits, bits);
      continue;
    }
    unproven.push_back(f);
    if (find_witness(L, f, pool, c, a)) {
      a.duals.clear();
      a.verdict = Stability::unstable;
      a.why = std::string("a distribution with this centre of friction (") + std::to_string(a.points.size()) +
              (a.points.size() == 1 ? " point" : " points") + " of the support) puts the load beyond the composite "
              "cone's " + facet_phrase(f) + ": the body does not stay with the pusher";
      return a;
    }
  }
  if (unproven.empty()) {  // every facet by its condition or by the LP's dual over the support's points
    a.verdict = Stability::stable;
    std::string names;
    for (const auto& [f, y] : a.duals) names += std::string(names.empty() ? "the " : " and the ") + facet_phrase(f);
    a.why = "for every distribution on the support's points with this centre of friction: " + names +
            " by the dual of the linear program over those distributions (the most any of them can lean on it is "
            "negative), the other facets of the composite cone by PU-3's distribution-free conditions";
    return a;
  }
  a.duals.clear();
  std::string names;
  for (const Cone_facet f : unproven) names += std::string(names.empty() ? "the " : " and the ") + facet_phrase(f);
  a.why = "the distribution-free conditions (PU-3 §2, §3, §5) do not hold at " + names + ", and no distribution " +
          (finite ? "of the support's points breaks the contact, nor does the linear program's dual prove it (the load "
                    "may be on the composite cone's boundary)"
                  : "tried breaks the contact: they are sufficient, not necessary");
  return a;
}

// The convex polygon `poly` (counter-clockwise) cut by a·q ≤ b (Sutherland–Hodgman, exact).
std::vector<Vec2> clip(const std::vector<Vec2>& poly, const Halfplane& h) {
  std::vector<Vec2> out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &p = poly[i], &q = poly[(i + 1) % n];
    const Rational fp = dot(h.a, p) - h.b, fq = dot(h.a, q) - h.b;
    if (sgn(fp) <= 0) out.push_back(p);
    if ((sgn(fp) < 0 && sgn(fq) > 0) || (sgn(fp) > 0 && sgn(fq) < 0)) {
      const Rational t = fp / (fp - fq);
      out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    }
  }
  return out;
}


Stable_region stable_region(const Support_model& model, const Pusher& pusher) {
  Stable_region g;
  const Prepared P = prepare(model, pusher);
  g.friction_centre = P.c;
  g.why = P.why;
  if (!P.c) return g;
  const Line_contact& L = P.L;
  const Vec2 c = *P.c;
  g.R2 = P.R2;
  g.R_hi = outward(sqrt_bracket(g.R2, 64).second, 6, true);
  // the box: everything in the scene, widened by ten times its size on every side (the region opens away from the body)
  Vec2 lo = c, hi = c;
  const auto add = [&](const Vec2& x) {
    lo = {std::min(lo.x, x.x), std::min(lo.y, x.y)}, hi = {std::max(hi.x, x.x), std::max(hi.y, x.y)};
  };
  for (const Vec2& x : P.vertices) add(x);
  for (const Vec2& x : L.end) add(x);
  const Rational size = std::max({Rational(hi.x - lo.x), Rational(hi.y - lo.y), Rational(1)});
  g.box = {Vec2{lo.x - 10 * size, lo.y - 10 * size}, Vec2{hi.x + 10 * size, hi.y + 10 * size}};
  for (int k = 0; k < 2; ++k) {
    Stable_region_side& side = g.side[k];
    const int sigma = k == 0 ? 1 : -1;
    Rational left = sigma * dot(P.vertices[0], L.left), right = sigma * dot(P.vertices[0], L.right);
    for (const Vec2& x : P.vertices)
      left = std::max(left, Rational(sigma * dot(x, L.left))), right = std::min(right, Rational(sigma * dot(x, L.right)));
    side.halfplanes[0] = {Vec2{-sigma * L.left.x, -sigma * L.left.y}, -left};  // σ(x − q)·e₊ ≤ 0 for every x
    side.halfplanes[1] = {Vec2{sigma * L.right.x, sigma * L.right.y}, right};   // −σ(x − q)·e₋ ≤ 0 for every x
    const std::size_t bis = L.s[0] * sigma > 0 ? 0 : 1, tip = 1 - bis;
    side.tip = tip;
    const Vec2 eb = L.end[bis], et = L.end[tip], a = minus(c, et);
    side.halfplanes[2 + bis] = {Vec2{2 * (c.x - eb.x), 2 * (c.y - eb.y)}, dot(c, c) - dot(eb, eb)};  // |q − e_b| ≤ |q − c|
    if (is_zero(a)) continue;  // the tip end at c: no tip line
    side.possible = true;
    side.alpha_hi = outward(sqrt_bracket(dot(a, a), 64).second, 6, true);
    // T: the least short decimal with T/α_hi > R_hi and T ≥ R² + E(T/α_hi) (PU-3 §6)
    const std::optional<Rational> T = tip_line_T(g.R2, g.R_hi, side.alpha_hi);
    if (!T) {
      side.possible = false;
      continue;
    }
    side.T = *T;
    side.halfplanes[2 + tip] = {Vec2{-a.x, -a.y}, -(side.T + dot(a, c))};  // (c − e_t)·(q − c) ≥ T
    std::vector<Vec2> poly = {g.box[0], {g.box[1].x, g.box[0].y}, g.box[1], {g.box[0].x, g.box[1].y}};
    for (const Halfplane& h : side.halfplanes) poly = clip(poly, h);
    side.polygon = std::move(poly);
  }
  // translations: v with v × e₊ ≥ 0, e₋ × v ≥ 0 and s_k (c − e_k) × v ≥ 0 — a cone; its extreme rays are among the
  // inequalities' boundary rays
  const auto valid = [&](const Vec2& v) {
    return sgn(cross(v, L.left)) >= 0 && sgn(cross(L.right, v)) >= 0 &&
           L.s[0] * sgn(cross(minus(c, L.end[0]), v)) >= 0 && L.s[1] * sgn(cross(minus(c, L.end[1]), v)) >= 0 &&
           sgn(dot(v, L.n)) > 0;
  };
  std::vector<Vec2> rays;
  for (const Vec2& r : {L.left, L.right, minus(c, L.end[0]), minus(c, L.end[1])})
    for (const Vec2& v : {r, Vec2{-r.x, -r.y}})
      if (!is_zero(v) && valid(v)) rays.push_back(v);
  if (!rays.empty()) {
    std::array<Vec2, 2> cone = {rays[0], rays[0]};
    for (const Vec2& v : rays) {
      if (sgn(cross(cone[0], v)) < 0) cone[0] = v;  // (the set lies within the friction cone: less than a half-turn)
      if (sgn(cross(v, cone[1])) < 0) cone[1] = v;
    }
    g.translations = cone;
  }
  return g;
}

Push_answer decide_line_push(const Support_model& model, const Pusher& pusher) {
  Push_answer a;
  const Contact& pc = pusher.contact;
  a.at = pc.at, a.normal = pc.normal, a.velocity = pusher.velocity, a.mu = pc.mu;
  a.known = model.known();
  a.votes_known = false;
  a.stable = decide_stable_push(model, pusher);
  a.center = a.stable->friction_centre;
  if (a.stable->verdict == Stability::stable) {
    a.rotation = a.stable->sense > 0 ? Rotation::ccw : a.stable->sense < 0 ? Rotation::cw : Rotation::none;
    a.why = "the push is stable: the body moves with the pusher, " +
            std::string(a.stable->sense == 0 ? "translating" : a.stable->sense > 0 ? "turning ccw" : "turning cw");
  } else if (a.stable->verdict == Stability::unstable && a.stable->corners != 0) {
    // PU-1's first lemma: the body turns as the pusher's force passes the centre of friction, whatever the contact does
    a.rotation = a.stable->corners > 0 ? Rotation::ccw : Rotation::cw;
    a.why = std::string("the push is not stable, but every force the pusher can apply passes the centre of friction on ") +
            (a.stable->corners > 0 ? "its left" : "its right") + " (both friction-cone edges' lines through both ends "
            "vote " + rotation_name(a.rotation) + "): the body turns " + rotation_name(a.rotation);
  } else {
    a.why = a.stable->verdict == Stability::unstable
                ? "the push is not stable: the body leaves the pusher's motion, the pusher's forces pass the centre of "
                  "friction on both sides, and a line contact's sliding is not answered"
                : "whether the push is stable is not decided";
  }
  return a;
}

}  // namespace wrenchkit
