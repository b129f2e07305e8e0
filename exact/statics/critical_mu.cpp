// [QL-2] The critical friction coefficient: see critical_mu.h and proofs/notes/QL-2-critical-friction.md.
#include "exact/statics/critical_mu.h"

#include <algorithm>
#include <optional>
#include <type_traits>
#include <stdexcept>
#include <vector>

#include "exact/io/input_error.h"
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

Scene at_mu(const Scene& scene, const Rational& t, Friction_scaling scaling) {
  Scene s = scene;
  for (Contact& c : s.contacts) {
    if (c.kind != Contact::Kind::point) continue;
    c = exact_contact(c);
    c.mu = scaling == Friction_scaling::common ? t : Rational(t * c.mu);
    c.mu_given = true;
    c.has_twin = false;  // the twin is derived from the new rationals
  }
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
template <class T>
T eval(const std::vector<T>& p, const T& x) {
  T v = number<T>(0);
  for (std::size_t k = p.size(); k-- > 0;) v = v * x + p[k];
  return v;
}
// Σ_k p_k (c0 + c1 x)^k (1 + x)^(pad − k), pad ≥ deg p: with (c0, c1) = (l, h) and pad = deg p, the polynomial whose
// positive roots are p's roots in (l, h) (Descartes on an interval); with (M, 1) and pad 0 (no (1 + x) factors), p(M + x).
template <class T>
std::vector<T> transform(const std::vector<T>& p, const T& c0, const T& c1, std::size_t pad) {
  std::vector<T> q(std::max(pad, p.size() - 1) + 1, number<T>(0));
  for (std::size_t k = 0; k < p.size(); ++k) {
    std::vector<T> t{p[k]};
    const auto times = [&t](const T& a, const T& b) {  // t ← t · (a + b x)
      std::vector<T> r(t.size() + 1, number<T>(0));
      for (std::size_t i = 0; i < t.size(); ++i) r[i] = r[i] + t[i] * a, r[i + 1] = r[i + 1] + t[i] * b;
      t = std::move(r);
    };
    for (std::size_t i = 0; i < k; ++i) times(c0, c1);
    for (std::size_t i = k; i < pad; ++i) times(number<T>(1), number<T>(1));
    for (std::size_t i = 0; i < t.size(); ++i) q[i] = q[i] + t[i];
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
std::optional<bool> one_sign(const std::vector<fl::Bounded>& q) {
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
template <class T>
std::optional<bool> no_root_between(const std::vector<T>& p, const T& l, const T& h) {
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
struct Minor {
  Poly p;
  std::vector<fl::Bounded> b;
};
// Certain: the sign of p(x) (positive, negative) when the doubles tell; Sign::uncertain otherwise.
Sign sign_at(const Minor& m, const fl::Bounded& x) { return eval(m.b, x).sign(); }
// The interval's ends as certified doubles, made once for every minor.
struct Ends {
  fl::Bounded l, h, included;
  Ends(const Rational& excluded, const Rational& in)
      : l(to_bounded(std::min(excluded, in))), h(to_bounded(std::max(excluded, in))), included(to_bounded(in)) {}
};
bool constant_on(const Minor& m, const Rational& excluded, const Rational& included, const Ends* filter) {
  if (m.p.empty()) return true;
  if (filter) {
    const Sign at = sign_at(m, filter->included);
    if (at == Sign::zero) return false;
    if (at != Sign::uncertain) {
      const std::optional<bool> r = no_root_between(m.b, filter->l, filter->h);
      if (r) return *r;
    }
  }
  return constant_on(m.p, excluded, included);
}
// A bound on the absolute values of p's roots (Cauchy): 1 + max |c_k / c_lead|.
Rational root_bound(const Poly& p) {
  Rational m = 0;
  for (std::size_t k = 0; k + 1 < p.size(); ++k) m = std::max(m, Rational(abs(p[k] / p.back())));
  return 1 + m;
}

// The simplest rational (least denominator, then numerator) in [l, h], 0 ≤ l ≤ h.
Rational simplest(const Rational& l, const Rational& h) {
  Integer f;
  mpz_fdiv_q(f.get_mpz_t(), l.get_num_mpz_t(), l.get_den_mpz_t());
  if (Rational(f) == l) return l;
  if (Rational(f + 1) <= h) return Rational(f + 1);
  return Rational(f) + 1 / simplest(1 / (h - f), 1 / (l - f));
}

// The edges as families a + μ b: each point contact's left (a + μ b) and right (a − μ b), each wrench contact's wrench
// (b = 0), and the load (b = 0) when asked.
struct Family {
  Vec3q a, b;
};
std::vector<Family> families(const Scene& scene, bool with_load, Friction_scaling scaling) {
  std::vector<Family> out;
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
std::vector<Minor> minors_in(const std::vector<std::array<std::array<T, 3>, 2>>& F) {
  using V = std::array<T, 3>;
  const auto cross = [](const V& x, const V& y) {
    return V{T(x[1] * y[2] - x[2] * y[1]), T(x[2] * y[0] - x[0] * y[2]), T(x[0] * y[1] - x[1] * y[0])};
  };
  const auto det = [&cross](const V& x, const V& y, const V& z) {
    const V c = cross(y, z);
    return T(x[0] * c[0] + x[1] * c[1] + x[2] * c[2]);
  };
  const auto q = [](const T& x) {
    if constexpr (std::is_same_v<T, Integer>) return Rational(x);
    else return Rational(integer_of(x));
  };
  std::vector<Minor> out;
  const auto keep = [&](std::initializer_list<T> coefficients) {
    std::vector<T> c(coefficients);
    while (!c.empty() && c.back() == 0) c.pop_back();
    if (c.empty()) return;
    Minor m;
    for (const T& x : c) m.p.push_back(q(x)), m.b.push_back(bounded_of(x));
    out.push_back(std::move(m));
  };
  for (const auto& f : F)
    for (int k = 0; k < 3; ++k) keep({f[0][k], f[1][k]});
  for (std::size_t i = 0; i < F.size(); ++i)
    for (std::size_t j = i + 1; j < F.size(); ++j) {
      const V c0 = cross(F[i][0], F[j][0]), c2 = cross(F[i][1], F[j][1]), u = cross(F[i][0], F[j][1]), v = cross(F[i][1], F[j][0]);
      for (int k = 0; k < 3; ++k) keep({c0[k], T(u[k] + v[k]), c2[k]});
    }
  for (std::size_t i = 0; i < F.size(); ++i)
    for (std::size_t j = i + 1; j < F.size(); ++j)
      for (std::size_t k = j + 1; k < F.size(); ++k) {
        const V &A = F[i][0], &B = F[j][0], &C = F[k][0], &a = F[i][1], &b = F[j][1], &c = F[k][1];
        keep({det(A, B, C), T(det(a, B, C) + det(A, b, C) + det(A, B, c)), T(det(A, b, c) + det(a, B, c) + det(a, b, C)), det(a, b, c)});
      }
  return out;
}
std::vector<Minor> minors(const std::vector<Family>& families) {
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
  if (!small) return minors_in(F);
  std::vector<std::array<std::array<wide::i128, 3>, 2>> S(F.size());
  for (std::size_t i = 0; i < F.size(); ++i)
    for (int r = 0; r < 2; ++r)
      for (int k = 0; k < 3; ++k) S[i][r][k] = F[i][r][k].get_si();
  return minors_in(S);
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
    if (m.p.empty()) continue;
    if (filter) {
      const Sign g = sign_at(m, xb);
      if (g == Sign::positive || g == Sign::negative) continue;
    }
    if (eval(m.p, x) == 0) return true;
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
  const auto add = [&s](const Vec3q& w) {
    Contact c;
    c.kind = Contact::Kind::wrench;
    c.wrench = w;
    s.contacts.push_back(c);
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

// The search both properties share. `holds(μ, certify)`: the property at μ (certify: keep its certificate as the
// `below` or `above` evidence). Closure holds on an open half-line (μ*, ∞) (`open_set`); balance on [μ*, ∞) or, where
// the cone at μ* holds a line, (μ*, ∞).
template <class Holds>
void search(Critical_mu& out, const std::vector<Minor>& P, Rational lo, Rational hi, const Rational& tol, bool open_set,
            bool filter, Holds holds) {
  const auto bisect_until = [&](const Rational& width) {
    while (hi - lo > width) {
      const Rational mid = (lo + hi) / 2;
      (holds(mid, false) ? hi : lo) = mid;
    }
  };
  // Exact: the simplest rational s of a narrow bracket that is a root of a minor, with the minors' signs constant on
  // a one-sided interval beside it — (s, other] where the property fails at s and holds at other, [other, s) where it
  // holds at s and fails at other —, tried from the first bracket's far end halving toward s, then its simplest
  // rational in the outer half (a readable μ).
  const Rational lo0 = lo, hi0 = hi;
  for (int bits : {32, 64, 128, 256}) {
    bisect_until((hi + 1) / two_to(bits));  // (absolute near 0: μ* may be 0)
    const Rational s = simplest(lo, hi);
    if (!is_root(P, s, filter)) continue;
    const bool at_s = holds(s, false);
    if (at_s && open_set) continue;  // (closed at s: s is above μ*)
    // from the first bracket's far end, halving a few times, then from this bracket's end (close to s: it passes
    // unless a root of another minor lies between) halving further
    Rational other = at_s ? lo0 : hi0;
    std::size_t last_failed = P.size();
    for (int t = 0; t < 200 && other != s; ++t, other = (other + s) / 2) {
      if (t == 6 && (at_s ? lo : hi) != s) other = at_s ? lo : hi;
      if (!all_constant_on(P, s, other, filter, last_failed)) continue;
      other = at_s ? simplest(other, (other + s) / 2) : simplest((other + s) / 2, other);
      if (holds(other, false) == at_s) break;  // the same answer on both sides: s is not μ*
      out.kind = Critical_kind::value;
      out.lower = out.upper = s;
      out.constant = true;
      out.holds_at_critical = at_s;
      holds(s, true);
      holds(other, true);
      (at_s ? out.above_mu : out.below_mu) = s;
      (at_s ? out.below_mu : out.above_mu) = other;
      return;
    }
  }
  bisect_until(tol * (hi + 1 / two_to(64)));
  out.kind = Critical_kind::value;
  out.lower = lo, out.upper = hi;
  holds(lo, true);
  holds(hi, true);
  out.below_mu = lo, out.above_mu = hi;
}

Critical_mu closure_mu(const Scene& scene, Mode mode, const Rational& tol, Friction_scaling scaling) {
  Critical_mu out;
  out.scaling = scaling;
  const auto closed = [&](const Rational& mu, bool certify) {
    ++out.decisions;
    const Closure_answer a = decide_closure(at_mu(scene, mu, scaling), Property::force_closure, mode, certify);
    if (certify) (a.holds ? out.above_closure : out.below_closure) = a.certificate;
    return a.holds;
  };
  if (closed(0, true)) {
    out.kind = Critical_kind::always;
    out.above_mu = Rational(0);
    return out;
  }
  const Closure_answer limit = decide_closure(limit_scene(scene, scaling), Property::force_closure, mode, true);
  ++out.decisions;
  if (!limit.holds) {  // no μ closes: a twist orthogonal to every b_i
    out.kind = Critical_kind::never;
    out.limit_twist = limit.certificate.twist;
    return out;
  }
  Rational lo = 0, hi = 1;
  for (int guard = 0; !closed(hi, false); ++guard) {
    if (guard > 100000) throw std::logic_error("critical mu: closure never reached although the limit cone closes");
    lo = hi, hi *= 2;
  }
  search(out, minors(families(scene, false, scaling)), lo, hi, tol, true, mode != Mode::exact, closed);
  return out;
}

Critical_mu balance_mu(const Scene& scene, Mode mode, const Rational& tol) {
  Critical_mu out;
  const auto balanced = [&](const Rational& mu, bool certify) {
    ++out.decisions;
    const Equilibrium_answer a = decide_equilibrium(at_mu(scene, mu, Friction_scaling::common), mode, certify);
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
  const std::vector<Minor> P = minors(families(scene, true, Friction_scaling::common));
  Rational M = 1;
  for (const Minor& m : P) M = std::max(M, root_bound(m.p));
  M += 1;  // beyond every minor's roots (complex ones too): the answer there is the answer for every larger μ
  for (const Minor& m : P)
    if (eval(m.p, M) == 0 || !no_root_beyond(m.p, M)) throw std::logic_error("critical mu: a minor has a root beyond its bound");
  if (!balanced(M, true)) {  // the load is on the limit cone's boundary: reached by no finite μ
    out.kind = Critical_kind::never;
    out.below_mu = M;
    out.constant_beyond = true;
    return out;
  }
  Rational lo = 0, hi = 1;
  while (!balanced(hi, false)) lo = hi, hi = std::min(Rational(hi * 2), M);
  search(out, P, lo, hi, tol, false, mode != Mode::exact, balanced);
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
