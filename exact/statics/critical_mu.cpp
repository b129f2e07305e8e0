// [QL-2] The critical friction coefficient: see critical_mu.h and proofs/notes/QL-2-critical-friction.md.
#include "exact/statics/critical_mu.h"

#include <boost/container/static_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <type_traits>
#include <utility>
#include <stdexcept>
#include <vector>

#include "exact/io/input_error.h"
#include "exact/io/to_float.h"
#include "exact/numbers/wide_int.h"
#include "float/bounded.h"

namespace wrenchkit {

const char* critical_kind_name(Critical_kind k) {
  switch (k) {
    case Critical_kind::value: return "value";
    case Critical_kind::always: return "always";
    case Critical_kind::never: return "never";
  }
  return "?";
}

void set_mu(Scene& s, const Scene& scene, const Rational& t, Friction_scaling scaling) {
  for (std::size_t i = 0; i < s.contacts.size(); ++i) {
    Contact& c = s.contacts[i];
    if (c.kind != Contact::Kind::point) continue;
    if (c.exact_pending) c = exact_contact(c);
    if (!c.has_twin) c.twin = to_bounded(c), c.has_twin = true;
    if (scaling == Friction_scaling::common) c.mu = t;
    else {
      const Contact& given = scene.contacts[i];
      c.mu = t * (given.exact_pending ? exact_contact(given).mu : given.mu);
    }
    c.mu_given = true;
    c.twin.mu = to_bounded(c.mu);  // (the twin's point and normal stay: derived once, the μ each time)
    c.twin.frictional = c.mu != 0;
    c.has_twin = true;
  }
}

Scene at_mu(const Scene& scene, const Rational& t, Friction_scaling scaling) {
  Scene s = scene;
  set_mu(s, scene, t, scaling);
  return s;
}

namespace {

// Polynomials in μ with rational coefficients, lowest degree first.
using Poly = std::vector<Rational>;

// Horner's rule and Descartes' transforms, once for exact rationals and certified doubles (T = Rational, fl::Bounded).
template <class T>
T number(int k) {
  if constexpr (std::is_same_v<T, fl::Bounded>) return fl::Bounded::exact(k);
  else return T(k);
}
// (P: std::vector<Rational>, or a Small<T> — a minor's at most four coefficients, without the heap)
template <class T>
using Small = boost::container::static_vector<T, 4>;
template <class P, class T>
T eval(const P& p, const T& x) {
  T v = number<T>(0);
  for (std::size_t k = p.size(); k-- > 0;) v = v * x + p[k];
  return v;
}
// Σ_k p_k (c0 + c1 x)^k (1 + x)^(pad − k), pad ≥ deg p: with (c0, c1) = (l, h) and pad = deg p, the polynomial whose
// positive roots are p's roots in (l, h) (Descartes on an interval); with (M, 1) and pad 0 (no (1 + x) factors), p(M + x).
template <class P, class T = typename P::value_type>
P transform(const P& p, const T& c0, const T& c1, std::size_t pad) {
  constexpr std::size_t kMax = 5;  // (degree ≤ 3 here: minors of 3×3 at most)
  const std::size_t n = std::max(pad, p.size() - 1) + 1;
  if (n > kMax - 1) throw std::logic_error("critical mu: a polynomial beyond degree 3");
  P q(n, number<T>(0));
  std::array<T, kMax> t, r;
  for (std::size_t k = 0; k < p.size(); ++k) {
    std::size_t m = 1;
    t[0] = p[k];
    const auto times = [&](const T& a, const T& b) {  // t ← t · (a + b x)
      r[m] = t[m - 1] * b;
      for (std::size_t i = m - 1; i > 0; --i) r[i] = t[i] * a + t[i - 1] * b;
      r[0] = t[0] * a;
      ++m;
      std::swap(t, r);
    };
    for (std::size_t i = 0; i < k; ++i) times(c0, c1);
    for (std::size_t i = k; i < pad; ++i) times(number<T>(1), number<T>(1));
    for (std::size_t i = 0; i < m; ++i) q[i] = q[i] + t[i];
  }
  return q;
}
// The coefficients' signs have no variation: true or false, or nothing when a certified double's sign is uncertain.
std::optional<bool> one_sign(const std::vector<Rational>& q) {
  int last = 0;
  for (const Rational& c : q)
    if (sgn(c) != 0) {
      if (last != 0 && sgn(c) != last) return false;
      last = sgn(c);
    }
  return true;
}
std::optional<bool> one_sign(const Small<fl::Bounded>& q) {
  int last = 0;
  bool variation = false;
  for (const fl::Bounded& c : q) {
    const Sign g = c.sign();
    if (g == Sign::uncertain) return std::nullopt;
    if (g == Sign::zero) continue;
    const int v = g == Sign::positive ? 1 : -1;
    variation = variation || (last != 0 && v != last);
    last = v;
  }
  return !variation;
}
// Descartes' rule on (l, h): no sign variation, no root there; beyond M: p(M + x) without variation, no root > M.
template <class P, class T = typename P::value_type>
std::optional<bool> no_root_between(const P& p, const T& l, const T& h) {
  return one_sign(transform(p, l, h, p.size() - 1));
}
bool no_root_beyond(const Poly& p, const Rational& M) { return *one_sign(transform(p, M, Rational(1), 0)); }
// p keeps one sign on the interval between `excluded` and `included` (that end included): p ≡ 0, or p(included) ≠ 0
// and no root strictly between.
bool constant_on(const Poly& p, const Rational& excluded, const Rational& included) {
  if (p.empty()) return true;
  if (eval(p, included) == 0) return false;
  return *no_root_between(p, std::min(excluded, included), std::max(excluded, included));
}

// The same tests first in certified doubles (float/bounded.h: every sign it gives is the exact one), the exact ones
// only where a sign is uncertain — the hybrid mode's filter. A minor with its certified-double coefficients.
// The rationals are made when an exact test first asks for them (the doubles decide most tests): from 128-bit
// integers for a small scene, else given at once.
struct Minor {
  Small<fl::Bounded> b;
  Small<wide::i128> small;
  mutable Poly exact;
  const Poly& p() const {
    if (exact.empty())
      for (const wide::i128 x : small) exact.push_back(Rational(integer_of(x)));
    return exact;
  }
};
// Certain: the sign of p(x) (positive, negative) when the doubles tell; Sign::uncertain otherwise.
Sign sign_at(const Minor& m, const fl::Bounded& x) { return eval(m.b, x).sign(); }
// The interval's ends as certified doubles, made once for every minor: l, h, the included end x0, the width h − l and
// the powers of R = max(|l|, |h|).
struct Ends {
  fl::Bounded l, h, included, width, r, r2;
  Ends(const Rational& excluded, const Rational& in)
      : l(to_bounded(std::min(excluded, in))), h(to_bounded(std::max(excluded, in))), included(to_bounded(in)),
        width(h - l), r(fl::max(fl::abs(l), fl::abs(h))), r2(r * r) {}
};
// [QL-2 §4a] p keeps one sign on the interval, in certified doubles: p(x0) ≠ 0 and |p(x0)| > (h − l)·Σ k|c_k|R^(k−1),
// which bounds |p(x) − p(x0)| there (the mean value theorem: |p'| ≤ Σ k|c_k|R^(k−1) on [−R, R]) — a few products,
// where Descartes' transform takes some fifty; else Descartes' rule in certified doubles; else exactly.
bool constant_on(const Minor& m, const Rational& excluded, const Rational& included, const Ends* filter) {
  if (filter) {
    const fl::Bounded at_x0 = eval(m.b, filter->included);
    const Sign at = at_x0.sign();
    if (at == Sign::zero) return false;
    if (at != Sign::uncertain) {
      const Small<fl::Bounded>& c = m.b;
      fl::Bounded slope = fl::Bounded::exact(0);  // Σ k|c_k|R^(k−1), degree ≤ 3
      if (c.size() > 1) slope = slope + fl::abs(c[1]);
      if (c.size() > 2) slope = slope + fl::Bounded::exact(2) * fl::abs(c[2]) * filter->r;
      if (c.size() > 3) slope = slope + fl::Bounded::exact(3) * fl::abs(c[3]) * filter->r2;
      if ((fl::abs(at_x0) - filter->width * slope).sign() == Sign::positive) return true;
      const std::optional<bool> r = no_root_between(m.b, filter->l, filter->h);
      if (r) return *r;
    }
  }
  return constant_on(m.p(), excluded, included);
}
// A bound on the absolute values of p's roots (Cauchy): 1 + max |c_k / c_lead|.
Rational root_bound(const Poly& p) {
  Rational m = 0;
  for (std::size_t k = 0; k + 1 < p.size(); ++k) m = std::max(m, Rational(abs(p[k] / p.back())));
  return 1 + m;
}

// The edges as families a + μ b: each point contact's left (a + μ b) and right (a − μ b), each wrench contact's wrench
// (b = 0), and the load (b = 0) when asked.
struct Family {
  Vec3q a, b;
};
std::vector<Family> families(const Scene& scene, bool with_load, Friction_scaling scaling) {
  std::vector<Family> out;
  out.reserve(2 * scene.contacts.size() + 1);
  for (const Contact& c : scene.contacts) {
    if (c.kind == Contact::Kind::wrench) {
      out.push_back({c.wrench, {0, 0, 0}});
      continue;
    }
    const Vec3q a = wrench_at(c.at, c.normal);
    Vec3q b = wrench_at(c.at, {-c.normal.y, c.normal.x});
    if (scaling == Friction_scaling::proportional)
      for (Rational& x : b) x *= c.mu;  // μ_i·t: the tangent wrench weighed by the contact's own μ
    out.push_back({a, b});
    out.push_back({a, {-b[0], -b[1], -b[2]}});
  }
  if (with_load) out.push_back({load_wrench(scene), {0, 0, 0}});
  return out;
}
// Every minor of the families' matrix that is not identically zero: their coordinates (1×1), the coordinates of
// their cross products (2×2) and their determinants (3×3), as polynomials in μ.
// Each family times a positive integer that makes it integral (a minor is then a positive multiple of the original:
// the same signs and roots), in 64-bit integers when every entry is within 2^30 (a 3×3 determinant of such is
// within 6·2^90: 128 bits), else GMP's.
fl::Bounded bounded_of(const Integer& x) { return to_bounded(Rational(x)); }
fl::Bounded bounded_of(wide::i128 x) {  // the nearest double below, and the exact error
  const double v = static_cast<double>(x);
  const wide::i128 back = static_cast<wide::i128>(v), err = x - back;
  return {v, static_cast<double>(err < 0 ? -err : err) * (1 + 0x1p-50)};
}

template <class T>
std::vector<Minor> minors_in(const std::vector<std::array<std::array<T, 3>, 2>>& F, bool maximal) {
  using V = std::array<T, 3>;
  const auto cross = [](const V& x, const V& y) {
    return V{T(x[1] * y[2] - x[2] * y[1]), T(x[2] * y[0] - x[0] * y[2]), T(x[0] * y[1] - x[1] * y[0])};
  };
  std::vector<Minor> out;
  const auto keep = [&](std::initializer_list<T> coefficients) {
    Small<T> c(coefficients);
    while (!c.empty() && c.back() == 0) c.pop_back();
    if (c.empty()) return;
    Minor m;
    for (const T& x : c) {
      m.b.push_back(bounded_of(x));
      if constexpr (std::is_same_v<T, Integer>) m.exact.push_back(Rational(x));
      else m.small.push_back(x);
    }
    out.push_back(std::move(m));
  };
  for (const auto& f : F)
    for (int k = 0; k < 3 && !maximal; ++k) keep({f[0][k], f[1][k]});
  for (std::size_t i = 0; i < F.size() && !maximal; ++i)
    for (std::size_t j = i + 1; j < F.size(); ++j) {
      const V c0 = cross(F[i][0], F[j][0]), c2 = cross(F[i][1], F[j][1]), u = cross(F[i][0], F[j][1]), v = cross(F[i][1], F[j][0]);
      for (int k = 0; k < 3; ++k) keep({c0[k], T(u[k] + v[k]), c2[k]});
    }
  // det(x, y, z) = x · (y × z): the four cross products of each pair (j, k) once, then eight dot products per triple
  const std::size_t n = F.size();
  std::vector<std::array<V, 4>> pair(n * n);  // [BC, bC, Bc, bc] of (j, k), at j·n + k
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = j + 1; k < n; ++k)
      pair[j * n + k] = {cross(F[j][0], F[k][0]), cross(F[j][1], F[k][0]), cross(F[j][0], F[k][1]), cross(F[j][1], F[k][1])};
  const auto dot = [](const V& x, const V& y) { return T(x[0] * y[0] + x[1] * y[1] + x[2] * y[2]); };
  out.reserve(out.size() + n * (n - 1) * (n - 2) / 6);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {
        const V &A = F[i][0], &a = F[i][1];
        const auto& [BC, bC, Bc, bc] = pair[j * n + k];
        // det(A,B,C), det(a,B,C) + det(A,b,C) + det(A,B,c), det(A,b,c) + det(a,B,c) + det(a,b,C), det(a,b,c)
        keep({dot(A, BC), T(dot(a, BC) + dot(A, bC) + dot(A, Bc)), T(dot(A, bc) + dot(a, Bc) + dot(a, bC)), dot(a, bc)});
      }
  return out;
}
// `maximal`: the 3×3 minors alone (the chirotope: enough for closure, QL-2 §2).
std::vector<Minor> minors(const std::vector<Family>& families, bool maximal) {
  std::vector<std::array<std::array<Integer, 3>, 2>> F;
  bool small = true;
  const Integer limit = Integer(1) << 30;
  for (const Family& f : families) {
    Integer L = 1;
    for (const Vec3q* v : {&f.a, &f.b})
      for (const Rational& x : *v) mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), x.get_den().get_mpz_t());
    auto& g = F.emplace_back();
    for (int r = 0; r < 2; ++r)
      for (int k = 0; k < 3; ++k) {
        const Rational& x = r == 0 ? f.a[k] : f.b[k];
        g[r][k] = x.get_num() * (L / x.get_den());
        small = small && abs(g[r][k]) <= limit;
      }
  }
  if (!small) return minors_in(F, maximal);
  std::vector<std::array<std::array<wide::i128, 3>, 2>> S(F.size());
  for (std::size_t i = 0; i < F.size(); ++i)
    for (int r = 0; r < 2; ++r)
      for (int k = 0; k < 3; ++k) S[i][r][k] = F[i][r][k].get_si();
  return minors_in(S, maximal);
}
// Every minor keeps its sign: the one that failed last is tried first (it usually fails again).
bool all_constant_on(const std::vector<Minor>& P, const Rational& excluded, const Rational& included, bool filter,
                     std::size_t& last_failed) {
  const Ends ends(excluded, included);
  const Ends* f = filter ? &ends : nullptr;
  if (last_failed < P.size() && !constant_on(P[last_failed], excluded, included, f)) return false;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (i != last_failed && !constant_on(P[i], excluded, included, f)) return last_failed = i, false;
  return true;
}
bool is_root(const std::vector<Minor>& P, const Rational& x, bool filter) {
  const fl::Bounded xb = to_bounded(x);
  for (const Minor& m : P) {
    if (filter) {
      const Sign g = sign_at(m, xb);
      if (g == Sign::positive || g == Sign::negative) continue;
    }
    if (eval(m.p(), x) == 0) return true;
  }
  return false;
}

// The limit cone pos{a_i, ±b_i, wrenches} as a scene of wrench contacts (with the load, for balance); scaled, ±b_i
// only where μ_i > 0.
Scene limit_scene(const Scene& scene, Friction_scaling scaling) {
  Scene s;
  s.name = scene.name;
  s.load = scene.load;
  s.body = scene.body;
  s.contacts.reserve(3 * scene.contacts.size());
  const auto add = [&s](const Vec3q& w) {
    Contact c;
    c.kind = Contact::Kind::wrench;
    c.wrench = w;
    s.contacts.push_back(std::move(c));
  };
  for (const Contact& c : scene.contacts) {
    if (c.kind == Contact::Kind::wrench) {
      add(c.wrench);
      continue;
    }
    const Vec3q b = wrench_at(c.at, {-c.normal.y, c.normal.x});
    add(wrench_at(c.at, c.normal));
    if (scaling == Friction_scaling::common || c.mu != 0) add(b), add({-b[0], -b[1], -b[2]});
  }
  return s;
}

Rational two_to(int bits) {
  Integer p = 1;
  mpz_mul_2exp(p.get_mpz_t(), p.get_mpz_t(), static_cast<mp_bitcnt_t>(bits));
  return Rational(p);
}

// Where the search looks first: the minors' positive real roots, approximately, in doubles — each monotone piece of a
// minor (split at its critical points, up to its Cauchy bound) with a sign change is solved by Newton's steps kept
// inside a shrinking bracket. Only hints: every answer is still decided and proved exactly, a wrong hint costs time.
void positive_roots(const Small<fl::Bounded>& b, std::vector<double>& out) {
  double c[4] = {0, 0, 0, 0};
  std::size_t n = std::min<std::size_t>(b.size(), 4);
  for (std::size_t k = 0; k < n; ++k) c[k] = b[k].v;
  while (n > 0 && c[n - 1] == 0) --n;
  if (n < 2) return;
  const std::size_t deg = n - 1;
  const auto f = [&](double x) { double v = 0; for (std::size_t k = n; k-- > 0;) v = v * x + c[k]; return v; };
  const auto df = [&](double x) { double v = 0; for (std::size_t k = n; k-- > 1;) v = v * x + k * c[k]; return v; };
  double bound = 0;
  for (std::size_t k = 0; k < deg; ++k) bound = std::max(bound, std::abs(c[k] / c[deg]));
  bound = 1 + bound;
  if (!std::isfinite(bound)) return;
  double pts[4] = {0, bound, bound, bound};
  std::size_t np = 1;
  const auto critical = [&](double x) { if (x > 0 && x < bound) pts[np++] = x; };
  if (deg == 2) critical(-c[1] / (2 * c[2]));
  if (deg == 3) {  // f' = 3c3 x² + 2c2 x + c1
    const double A = 3 * c[3], B = 2 * c[2], C = c[1], disc = B * B - 4 * A * C;
    if (disc >= 0) {
      const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
      if (q != 0) critical(C / q);
      critical(q / A);
    }
  }
  pts[np++] = bound;
  for (std::size_t i = 1; i < np; ++i)  // (insertion: at most four points)
    for (std::size_t j = i; j > 0 && pts[j] < pts[j - 1]; --j) std::swap(pts[j], pts[j - 1]);
  for (std::size_t i = 0; i + 1 < np; ++i) {
    double lo = pts[i], hi = pts[i + 1], flo = f(lo), fhi = f(hi);
    if (flo == 0) {
      if (lo > 0) out.push_back(lo);
      continue;
    }
    if ((flo < 0) == (fhi < 0) || fhi == 0) continue;  // (a root at hi is the next piece's lo, or the bound's: none)
    double x = (lo + hi) / 2;
    for (int it = 0; it < 100; ++it) {
      const double fx = f(x);
      if (fx == 0) break;
      ((fx < 0) == (flo < 0) ? lo : hi) = x;
      const double d = df(x), step = d != 0 ? fx / d : 0, next = x - step;
      const double y = (d != 0 && next > lo && next < hi) ? next : (lo + hi) / 2;
      if (std::abs(y - x) <= 1e-16 * std::abs(x) || hi - lo <= 1e-16 * hi) { x = y; break; }
      x = y;
    }
    out.push_back(x);
  }
}
std::vector<double> root_hints(const std::vector<Minor>& P) {
  std::vector<double> r;
  for (const Minor& m : P) positive_roots(m.b, r);
  std::sort(r.begin(), r.end());
  std::vector<double> u;
  for (const double x : r)
    if (std::isfinite(x) && (u.empty() || x - u.back() > 1e-12 * std::max(1.0, x))) u.push_back(x);
  return u;
}

// The first bracket from the hints r: the property fails at lo (0) and, by a binary search over points in the gaps
// between consecutive hints (one decision per halving), fails at the last gap point below a hint (or at 0) and holds
// at the next gap point; the hint between them is returned (0 when it holds below the first hint). `top`: a point known to hold (balance's bound), else the point beyond
// the last hint is decided, and past it, when it fails (a root the doubles missed), doubling takes over (no hint).
// `never()`, asked once before the doubling (closure: the limit cone, whose decision the common case — closed beyond
// the last hint — does not need): true stops the search (`stopped`).
template <class Holds, class Never>
std::optional<double> narrow(const std::vector<double>& r, Rational& lo, Rational& hi, const std::optional<Rational>& top,
                             Holds holds, Never never, bool& stopped) {
  const std::size_t K = r.size();
  const auto gap = [&](std::size_t j) -> Rational {  // a simple rational between r[j−1] and r[j] (j = K: beyond)
    if (j == K) return top ? *top : Rational(std::ceil(2 * r[K - 1] + 1));
    const double w = r[j] - (j ? r[j - 1] : 0.0);
    return simplest_in(Rational(r[j] - 3 * w / 4), Rational(r[j] - w / 4));
  };
  if (K > 0) {
    hi = gap(K);
    if (top || holds(hi, false)) {
      // indices: −1 is lo (0: fails), j ≥ 0 the point gap(j) below hint j (j = K: beyond the last); holds at gap(H)
      long L = -1, H = static_cast<long>(K);
      while (H - L > 1) {
        const long mid = (L + H) / 2;
        const Rational g = gap(static_cast<std::size_t>(mid));
        if (g <= lo || g >= hi) break;  // (hints too close for the doubles: the search below goes on from here)
        (holds(g, false) ? H : L) = mid;
        (H == mid ? hi : lo) = g;
      }
      if (H - L == 1) return H == 0 ? 0.0 : r[static_cast<std::size_t>(H - 1)];  // (H = 0: μ* is 0, the only root below)
      return std::nullopt;
    }
    lo = hi;
  }
  if (top) return hi = *top, std::nullopt;
  if ((stopped = never())) return std::nullopt;
  hi = lo == 0 ? Rational(1) : Rational(lo * 2);
  for (int guard = 0; !holds(hi, false); ++guard) {
    if (guard > 100000) throw std::logic_error("critical mu: the property never holds although the limit cone does");
    lo = hi, hi *= 2;
  }
  return std::nullopt;
}

// The search both properties share. `holds(μ, certify)`: the property at μ (certify: keep its certificate as the
// `below` or `above` evidence). Closure holds on an open half-line (μ*, ∞) (`open_set`); balance on [μ*, ∞) or, where
// the cone at μ* holds a line, (μ*, ∞). `hint`: μ* approximately (a root of a minor in doubles, the only one between
// lo and hi as far as the doubles tell).
template <class Holds>
void search(Critical_mu& out, const std::vector<Minor>& P, Rational lo, Rational hi, const Rational& tol, bool open_set,
            bool filter, Holds holds, std::optional<double> hint) {
  // With a hint, the bracket is narrowed by the sign of one minor that changes sign across it (the hint's root: no
  // decision per halving); the property is decided at the ends before they are claimed, and where it disagrees (that
  // root is not μ*) the property itself narrows again from the first bracket. A halving point where the minor vanishes
  // is returned: a rational root, tried as μ* at once.
  const auto exact_sign = [&](const Minor& m, const Rational& x) {
    const Sign g = filter ? sign_at(m, to_bounded(x)) : Sign::uncertain;
    if (g == Sign::positive) return 1;
    if (g == Sign::negative) return -1;
    return sgn(eval(m.p(), x));
  };
  const Minor* tracker = nullptr;
  int tracker_lo = 0;
  if (hint)
    for (const Minor& m : P) {
      const int a = exact_sign(m, lo), b = exact_sign(m, hi);
      if (a * b < 0) {
        tracker = &m, tracker_lo = a;
        break;
      }
    }
  const auto bisect_until = [&](const Rational& width) -> std::optional<Rational> {
    while (hi - lo > width) {
      const Rational mid = (lo + hi) / 2;
      if (!tracker) {
        (holds(mid, false) ? hi : lo) = mid;
        continue;
      }
      const int g = exact_sign(*tracker, mid);
      if (g == 0) return mid;
      (g == tracker_lo ? lo : hi) = mid;
    }
    return std::nullopt;
  };
  // Exact: the simplest rational s of a narrow bracket that is a root of a minor, with the minors' signs constant on
  // a one-sided interval beside it — (s, other] where the property fails at s and holds at other, [other, s) where it
  // holds at s and fails at other —, tried from the first bracket's far end halving toward s, then its simplest
  // rational in the outer half (a readable μ).
  const Rational lo0 = lo, hi0 = hi;
  const auto exact_at = [&](const Rational& s) {
    if (!is_root(P, s, filter)) return false;
    const bool at_s = holds(s, true);  // (certified at once: a later answer overwrites the evidence it leaves)
    if (at_s && open_set) return false;  // (closed at s: s is above μ*)
    // from the first bracket's far end, halving a few times, then from this bracket's end (close to s: it passes
    // unless a root of another minor lies between) halving further
    Rational other = at_s ? lo0 : hi0;
    std::size_t last_failed = P.size();
    for (int t = 0; t < 200 && other != s; ++t, other = (other + s) / 2) {
      if (t == 6 && (at_s ? lo : hi) != s) other = at_s ? lo : hi;
      if (!all_constant_on(P, s, other, filter, last_failed)) continue;
      other = at_s ? simplest_in(other, (other + s) / 2) : simplest_in((other + s) / 2, other);
      if (holds(other, true) == at_s) return false;  // the same answer on both sides: s is not μ*
      out.kind = Critical_kind::value;
      out.lower = out.upper = s;
      out.constant = true;
      out.holds_at_critical = at_s;
      (at_s ? out.above_mu : out.below_mu) = s;
      (at_s ? out.below_mu : out.above_mu) = other;
      return true;
    }
    return false;
  };
  // the hint first: the simplest rational within a few ulps' worth of it (a rational μ* of small height is found at
  // once), then the bracket's own halvings
  if (hint && std::isfinite(*hint)) {
    const double d = std::abs(*hint) * 0x1p-30 + 0x1p-60;
    const Rational a = std::max(lo, Rational(*hint - d)), b = std::min(hi, Rational(*hint + d));
    if (a <= b && exact_at(simplest_in(a, b))) return;
  }
  for (int bits : {32, 64, 128, 256}) {
    if (const std::optional<Rational> root = bisect_until((hi + 1) / two_to(bits))) {  // (absolute near 0: μ* may be 0)
      if (exact_at(*root)) return;
      tracker = nullptr;  // (a root of the tracked minor, not μ*: the property narrows from the first bracket)
      lo = lo0, hi = hi0;
      bisect_until((hi + 1) / two_to(bits));
    }
    if (exact_at(simplest_in(lo, hi))) return;
  }
  for (;;) {
    if (const std::optional<Rational> root = bisect_until(tol * (hi + 1 / two_to(64)))) {
      tracker = nullptr;  // (not μ*, or exact_at would have found it above: narrow by the property)
      lo = lo0, hi = hi0;
      continue;
    }
    out.kind = Critical_kind::value;
    out.lower = lo, out.upper = hi;
    if (!holds(lo, true) && holds(hi, true)) break;
    if (!tracker) throw std::logic_error("critical mu: the property is not monotone in mu");
    tracker = nullptr;  // the tracked minor's root is not μ*
    lo = lo0, hi = hi0;
  }
  out.below_mu = lo, out.above_mu = hi;
}

Critical_mu closure_mu(const Scene& scene, Mode mode, const Rational& tol, Friction_scaling scaling) {
  Critical_mu out;
  out.scaling = scaling;
  Scene work = scene;  // (one copy: each decision sets its μs)
  const auto closed = [&](const Rational& mu, bool certify) {
    ++out.decisions;
    set_mu(work, scene, mu, scaling);
    const Closure_answer a = decide_closure(work, Property::force_closure, mode, certify);
    if (certify) (a.holds ? out.above_closure : out.below_closure) = a.certificate;
    return a.holds;
  };
  // (certificates only where they are the answer: the search leaves its own evidence on both sides)
  if (closed(0, false)) {
    closed(0, true);
    out.kind = Critical_kind::always;
    out.above_mu = Rational(0);
    return out;
  }
  const auto never = [&] {  // no μ closes when the limit cone is not all of R³: a twist orthogonal to every b_i
    const Scene limit_cone = limit_scene(scene, scaling);
    ++out.decisions;
    if (decide_closure(limit_cone, Property::force_closure, mode, false).holds) return false;
    out.kind = Critical_kind::never;
    out.limit_twist = decide_closure(limit_cone, Property::force_closure, mode, true).certificate.twist;
    return true;
  };
  // (closure holds on (μ*, ∞), of rank 3: the chirotope decides it there, and μ* is a root of a 3×3 minor — QL-2 §2)
  const std::vector<Minor> P = minors(families(scene, false, scaling), true);
  Rational lo = 0, hi = 1;
  bool is_never = false;
  const std::optional<double> hint = narrow(root_hints(P), lo, hi, std::nullopt, closed, never, is_never);
  if (is_never) return out;
  search(out, P, lo, hi, tol, true, mode != Mode::exact, closed, hint);
  return out;
}

Critical_mu balance_mu(const Scene& scene, Mode mode, const Rational& tol) {
  Critical_mu out;
  Scene work = scene;  // (one copy: each decision sets its μs)
  const auto balanced = [&](const Rational& mu, bool certify) {
    ++out.decisions;
    set_mu(work, scene, mu, Friction_scaling::common);
    const Equilibrium_answer a = decide_equilibrium(work, mode, certify);
    if (certify) (a.balanced ? out.above_balance : out.below_balance) = a.certificate;
    return a.balanced;
  };
  if (balanced(0, true)) {
    out.kind = Critical_kind::always;
    out.above_mu = Rational(0);
    return out;
  }
  const Equilibrium_answer limit = decide_equilibrium(limit_scene(scene, Friction_scaling::common), mode, true);
  ++out.decisions;
  if (!limit.balanced) {
    out.kind = Critical_kind::never;
    out.limit_twist = limit.certificate.twist;
    return out;
  }
  const std::vector<Minor> P = minors(families(scene, true, Friction_scaling::common), false);
  Rational M = 1;
  for (const Minor& m : P) M = std::max(M, root_bound(m.p()));
  M += 1;  // beyond every minor's roots (complex ones too): the answer there is the answer for every larger μ
  for (const Minor& m : P)
    if (eval(m.p(), M) == 0 || !no_root_beyond(m.p(), M)) throw std::logic_error("critical mu: a minor has a root beyond its bound");
  if (!balanced(M, true)) {  // the load is on the limit cone's boundary: reached by no finite μ
    out.kind = Critical_kind::never;
    out.below_mu = M;
    out.constant_beyond = true;
    return out;
  }
  Rational lo = 0, hi = 1;
  std::vector<double> r = root_hints(P);
  while (!r.empty() && r.back() >= M.get_d()) r.pop_back();  // (the bound is beyond every root: a hint past it is off)
  bool stopped = false;  // (balance has its bound M: no doubling)
  const std::optional<double> hint = narrow(r, lo, hi, M, balanced, [] { return false; }, stopped);
  search(out, P, lo, hi, tol, false, mode != Mode::exact, balanced, hint);
  return out;
}

}  // namespace

void check_critical_size(const Scene& scene) {
  std::size_t points = 0;
  for (const Contact& c : scene.contacts) points += c.kind == Contact::Kind::point;
  if (points == 0) throw Input_error("contacts: no point contact, so no friction coefficient to find");
  if (points > kCriticalMaxPointContacts)
    throw Input_error("contacts: the critical friction of " + std::to_string(points) + " point contacts, more than " +
                      std::to_string(kCriticalMaxPointContacts) + " (its minors grow as the cube of their number); ask "
                      "for epsilon alone (--only epsilon)");
}

Critical_answer decide_critical_mu(const Scene& given, Mode mode, const Rational& tolerance) {
  // contacts read lazily (the array API's doubles, the streaming reader) get their rationals first
  std::optional<Scene> storage;
  const Scene& scene = exact_contacts(given, storage);
  check_critical_size(scene);
  if (tolerance <= 0) throw Input_error("--tolerance: " + to_string(tolerance) + " is not positive");
  Critical_answer a;
  a.closure = closure_mu(scene, mode, tolerance, Friction_scaling::common);
  if (scene.load) a.equilibrium = balance_mu(scene, mode, tolerance);
  bool friction = false;  // the margin: a factor on the scene's own μ (none to scale without any)
  for (const Contact& c : scene.contacts) friction = friction || (c.kind == Contact::Kind::point && c.mu != 0);
  if (friction) a.margin = closure_mu(scene, mode, tolerance, Friction_scaling::proportional);
  return a;
}

}  // namespace wrenchkit
