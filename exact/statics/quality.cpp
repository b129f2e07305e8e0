// [QL-1] The Ferrari–Canny quality ε, exact or in a certified bracket. See quality.h and
// proofs/notes/QL-1-quality.md for the constructions and why they are right.
#include "exact/statics/quality.h"

#include "exact/io/to_float.h"
#include "float/quality_twin.h"

#include <algorithm>
#include <optional>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>

#include <boost/multiprecision/cpp_int.hpp>
#include <iterator>

#include "exact/io/input_error.h"
#include "exact/numbers/wide_int.h"
#include "float/bounded.h"

namespace wrenchkit {

const char* quality_norm_name(Quality_norm n) { return n == Quality_norm::l1 ? "L1" : "Linf"; }

const char* normalization_name(Force_normalization n) {
  switch (n) {
    case Force_normalization::unit_normal: return "unit-normal";
    case Force_normalization::unit_force: return "unit-force";
    case Force_normalization::as_given: return "as-given";
  }
  return "?";
}

Vec3q quality_wrench(const Vec3q& g, const Rational& c, const Rational& s, const Vec2& about) {
  const Rational m = g[2] - (about.x * g[1] - about.y * g[0]);
  return {c * g[0], c * g[1], c * s * m};
}

namespace {

Integer pow2(unsigned k) {
  Integer r = 1;
  mpz_mul_2exp(r.get_mpz_t(), r.get_mpz_t(), k);
  return r;
}
long bit_size(const Integer& z) { return z == 0 ? 0 : static_cast<long>(mpz_sizeinbase(z.get_mpz_t(), 2)); }
Integer isqrt(const Integer& z) {
  Integer r;
  mpz_sqrt(r.get_mpz_t(), z.get_mpz_t());
  return r;
}
bool square(const Integer& z) { return mpz_perfect_square_p(z.get_mpz_t()) != 0; }
Rational canonical(Integer num, Integer den) {
  Rational q(std::move(num), std::move(den));
  q.canonicalize();
  return q;
}

// √x for a rational x ≥ 0 as [lo, hi] with hi − lo = 2^−k (k ≥ `bits`, more for a small x), or lo = hi = √x when x is
// the square of a rational.
std::pair<Rational, Rational> sqrt_bracket(const Rational& x, unsigned bits) {
  const Integer &a = x.get_num(), &b = x.get_den();
  if (square(a) && square(b)) {
    const Rational r = canonical(isqrt(a), isqrt(b));
    return {r, r};
  }
  const unsigned k = bits + static_cast<unsigned>(std::max(0L, (bit_size(b) - bit_size(a)) / 2 + 2));
  const Integer scale = pow2(k);
  const Integer r = isqrt(Integer(a * scale * scale / b));  // r ≤ 2^k √x < r + 1
  return {canonical(r, scale), canonical(r + 1, scale)};
}

// c = 1/√q for a rational q > 0: exact when q is the square of a rational, else c̃ ≤ c < c̃ + η with η = 2^−k, k
// ≥ `bits` relative to c's size.
void set_scale(Quality_scale& s, unsigned bits) {
  const Integer &a = s.q.get_num(), &b = s.q.get_den();  // c = √(b/a)
  if (square(a) && square(b)) {
    s.scale = canonical(isqrt(b), isqrt(a));
    s.error = 0;
    return;
  }
  const unsigned k = bits + static_cast<unsigned>(std::max(0L, (bit_size(a) - bit_size(b)) / 2 + 2));
  const Integer scale = pow2(k);
  s.scale = canonical(isqrt(Integer(b * scale * scale / a)), scale);
  s.error = canonical(1, scale);
}

// A rational R ≥ √x (x ≥ 0), within a few parts in 16 of it.
Rational upper_root(const Rational& x) {
  if (x == 0) return 0;
  const Integer &a = x.get_num(), &b = x.get_den();
  const unsigned t = static_cast<unsigned>(std::max(0L, (bit_size(b) - bit_size(a)) / 2 + 4));
  const Integer scale = pow2(t);
  Integer f = a * scale * scale;
  mpz_cdiv_q(f.get_mpz_t(), f.get_mpz_t(), b.get_mpz_t());  // ⌈4^t x⌉
  return canonical(isqrt(f) + 1, scale);
}

using P3 = std::array<Integer, 3>;
Integer dot3(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The points times a common positive denominator D: integers (the hull and the distances scale by D).
std::vector<P3> integer_points(const std::vector<Vec3q>& pts, Integer& D) {
  D = 1;
  for (const Vec3q& p : pts)
    for (const Rational& x : p) mpz_lcm(D.get_mpz_t(), D.get_mpz_t(), x.get_den().get_mpz_t());
  std::vector<P3> out(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (int k = 0; k < 3; ++k) out[i][k] = pts[i][k].get_num() * (D / pts[i][k].get_den());
  return out;
}

// A plane n·x = off at distance off/|n| from the origin; `closer(a, b)`: a's distance below b's (off > 0).
struct Plane {
  P3 n;
  Integer off;
};
bool closer(const Plane& a, const Plane& b) {
  return a.off * a.off * dot3(b.n, b.n) < b.off * b.off * dot3(a.n, a.n);
}
Rational distance_squared(const Plane& p, const Integer& D) {
  return canonical(p.off * p.off, dot3(p.n, p.n) * D * D);
}

// The convex hull of integer points with a nonempty interior, by exact incremental insertion: its boundary as
// triangles of point indices, each oriented outward (the interior behind it), with their planes. Points on the
// boundary but not extreme may be left out; no triangle when the points are flat. O(points · facets) predicates. Coordinates C, products W: GMP's integers,
// or (every coordinate within 2^20) 64-bit coordinates with 128-bit products — a difference is within 2^21, a normal
// coordinate within 2^43, an offset within 3·2^63.
template <class W>
struct Hull {
  std::vector<std::array<std::size_t, 3>> tri;
  std::vector<std::array<W, 3>> n;
  std::vector<W> off;
};
// GMP's integer as a certified double: truncated, within one unit of its 53rd bit (exact below 2^53).
fl::Bounded bounded(const Integer& x) {
  const double d = mpz_get_d(x.get_mpz_t());
  return {d, mpz_sizeinbase(x.get_mpz_t(), 2) > 53 ? std::fabs(d) * 0x1p-51 : 0.0};
}

template <class C, class W>
Hull<W> convex_hull(const std::vector<std::array<C, 3>>& P, bool filter) {
  using V = std::array<W, 3>;
  // GMP's tier, hybrid: each visibility sign first in certified doubles (float/bounded.h), exactly when uncertain
  constexpr bool big = std::is_same_v<W, Integer>;
  using B3 = std::array<fl::Bounded, 3>;
  std::vector<B3> Pb, nb;
  std::vector<fl::Bounded> offb;
  if constexpr (big)
    if (filter)
      for (const auto& p : P) Pb.push_back({bounded(p[0]), bounded(p[1]), bounded(p[2])});
  const auto diff = [&](std::size_t b, std::size_t a) { return V{W(P[b][0]) - W(P[a][0]), W(P[b][1]) - W(P[a][1]), W(P[b][2]) - W(P[a][2])}; };
  const auto cross = [](const V& a, const V& b) {
    return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  const auto dot = [](const V& a, const auto& b) { return W(a[0] * W(b[0]) + a[1] * W(b[1]) + a[2] * W(b[2])); };
  const auto zero = [](const V& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; };
  const std::size_t n = P.size();
  std::size_t i1 = n, i2 = n, i3 = n;
  for (std::size_t i = 1; i < n && i1 == n; ++i)
    if (!zero(diff(i, 0))) i1 = i;
  for (std::size_t i = 1; i1 < n && i < n && i2 == n; ++i)
    if (!zero(cross(diff(i1, 0), diff(i, 0)))) i2 = i;
  for (std::size_t i = 1; i2 < n && i < n && i3 == n; ++i)
    if (dot(cross(diff(i1, 0), diff(i2, 0)), diff(i, 0)) != 0) i3 = i;
  if (i3 == n) return {};  // flat: no interior
  V inside;  // four times the first tetrahedron's centroid: interior to every later hull
  for (int k = 0; k < 3; ++k) inside[k] = W(P[0][k]) + W(P[i1][k]) + W(P[i2][k]) + W(P[i3][k]);

  Hull<W> h;
  std::vector<char> alive;
  // directed edge (u, v) → its facet: a flat table for up to 512 points, a hash map beyond
  const bool flat = n <= 512;
  std::vector<std::size_t> table(flat ? n * n : 0);
  std::unordered_map<std::uint64_t, std::size_t> map;
  const auto key = [](std::size_t u, std::size_t v) { return (static_cast<std::uint64_t>(u) << 32) | v; };
  const auto set_edge = [&](std::size_t u, std::size_t v, std::size_t f) {
    if (flat) table[u * n + v] = f;
    else map[key(u, v)] = f;
  };
  const auto edge_of = [&](std::size_t u, std::size_t v) { return flat ? table[u * n + v] : map.at(key(u, v)); };
  const auto drop_edge = [&](std::size_t u, std::size_t v) {
    if (!flat) map.erase(key(u, v));
  };
  h.tri.reserve(4 * n), h.n.reserve(4 * n), h.off.reserve(4 * n), alive.reserve(4 * n);
  const auto add = [&](std::size_t a, std::size_t b, std::size_t c) {
    V nv = cross(diff(b, a), diff(c, a));
    W off = dot(nv, P[a]);
    if (dot(nv, inside) > 4 * off) {  // facing inward: turn it
      std::swap(b, c);
      for (W& x : nv) x = -x;
      off = -off;
    }
    const std::size_t f = h.tri.size();
    if constexpr (big)
      if (filter) nb.push_back({bounded(nv[0]), bounded(nv[1]), bounded(nv[2])}), offb.push_back(bounded(off));
    h.tri.push_back({a, b, c});
    h.n.push_back(std::move(nv));
    h.off.push_back(std::move(off));
    alive.push_back(1);
    set_edge(a, b, f), set_edge(b, c, f), set_edge(c, a, f);
  };
  add(0, i1, i2), add(0, i1, i3), add(0, i2, i3), add(i1, i2, i3);

  std::vector<std::size_t> visible;
  std::vector<char> seen;
  std::vector<std::pair<std::size_t, std::size_t>> horizon;
  for (std::size_t p = 1; p < n; ++p) {
    if (p == i1 || p == i2 || p == i3) continue;
    visible.clear();
    seen.assign(h.tri.size(), 0);
    const auto sees = [&](std::size_t f) {
      if constexpr (big)
        if (filter) {
          const Sign g = (nb[f][0] * Pb[p][0] + nb[f][1] * Pb[p][1] + nb[f][2] * Pb[p][2] - offb[f]).sign();
          if (g != Sign::uncertain) return g == Sign::positive;
        }
      return dot(h.n[f], P[p]) > h.off[f];
    };
    for (std::size_t f = 0; f < h.tri.size(); ++f)
      if (alive[f] && sees(f)) visible.push_back(f), seen[f] = 1;
    if (visible.empty()) continue;  // inside or on the boundary
    horizon.clear();
    for (std::size_t f : visible)
      for (int k = 0; k < 3; ++k) {
        const std::size_t u = h.tri[f][k], v = h.tri[f][(k + 1) % 3];
        if (!seen[edge_of(v, u)]) horizon.push_back({u, v});
      }
    for (std::size_t f : visible) {
      alive[f] = 0;
      for (int k = 0; k < 3; ++k) drop_edge(h.tri[f][k], h.tri[f][(k + 1) % 3]);
    }
    for (const auto& [u, v] : horizon) add(u, v, p);
  }
  Hull<W> out;
  for (std::size_t f = 0; f < h.tri.size(); ++f)
    if (alive[f]) out.tri.push_back(h.tri[f]), out.n.push_back(std::move(h.n[f])), out.off.push_back(std::move(h.off[f]));
  return out;
}

// The wrench space's points as integers over one positive denominator D (the hull and the distances scale by D):
// GMP's integers, and when every coordinate is within 2^20 also 64-bit ones with 128-bit products (the small tier), or
// within 2^61 with 256-bit products (the medium tier: an irrational scale's 2^−56 steps) — a difference is within
// 2^62, a normal coordinate within 2^125, an offset or a point's side within 3·2^188, 4·(0's side) within 2^193.
using I256 = boost::multiprecision::number<
    boost::multiprecision::cpp_int_backend<256, 256, boost::multiprecision::signed_magnitude, boost::multiprecision::unchecked, void>,
    boost::multiprecision::et_off>;
struct Int_points {
  Integer D = 1;
  std::vector<P3> big;
  std::vector<std::array<std::int64_t, 3>> small;
  enum class Tier { small, medium, big } tier = Tier::big;
};
Int_points int_points(const std::vector<Vec3q>& pts) {
  Int_points r;
  r.big = integer_points(pts, r.D);
  const Integer small = Integer(1) << 20, medium = Integer(1) << 61;
  Integer top = 0;
  for (const P3& p : r.big)
    for (const Integer& x : p) top = std::max(top, Integer(abs(x)));
  r.tier = top <= small ? Int_points::Tier::small : top <= medium ? Int_points::Tier::medium : Int_points::Tier::big;
  if (r.tier != Int_points::Tier::big) {
    r.small.resize(r.big.size());
    for (std::size_t i = 0; i < r.big.size(); ++i)
      for (int k = 0; k < 3; ++k) r.small[i][k] = r.big[i][k].get_si();
  }
  return r;
}
Integer big_of(const Integer& x) { return x; }
Integer big_of(wide::i128 x) { return integer_of(x); }
Integer big_of(const I256& x) {
  std::vector<std::uint64_t> limbs;
  boost::multiprecision::export_bits(boost::multiprecision::abs(x), std::back_inserter(limbs), 64, false);
  Integer r;
  mpz_import(r.get_mpz_t(), limbs.size(), -1, sizeof(std::uint64_t), 0, 0, limbs.data());
  return x < 0 ? Integer(-r) : r;
}
long double approx(const Integer& x) { return static_cast<long double>(x.get_d()); }
long double approx(wide::i128 x) { return static_cast<long double>(x); }
long double approx(const I256& x) {  // (from the limbs, most significant first: within 2^−60 relative)
  const auto& b = x.backend();
  long double v = 0;
  for (std::size_t i = b.size(); i-- > 0;) v = v * 0x1p64L + static_cast<long double>(b.limbs()[i]);
  return b.sign() ? -v : v;
}

// (off/|n|)² of plane a below that of plane b (offsets > 0): with `filter`, in long double when the two differ by more
// than 1e-9 relative (each ratio is within 3e-15 of the true one; an overflow gives NaN or ∞ and falls through:
// proofs/notes/QL-1-quality.md §3, the engine's filters); else, or without it, exactly in GMP's integers.
template <class W>
bool nearer(const W& off_a, const std::array<W, 3>& n_a, const W& off_b, const std::array<W, 3>& n_b, bool filter) {
  if (filter) {
    const auto ratio = [](const W& o, const std::array<W, 3>& n) {
      const long double x = approx(o);
      return x * x / (approx(n[0]) * approx(n[0]) + approx(n[1]) * approx(n[1]) + approx(n[2]) * approx(n[2]));
    };
    const long double a = ratio(off_a, n_a), b = ratio(off_b, n_b);
    if (a < b * (1 - 1e-9L)) return true;
    if (a > b * (1 + 1e-9L)) return false;
  }
  return closer(Plane{{big_of(n_a[0]), big_of(n_a[1]), big_of(n_a[2])}, big_of(off_a)},
                Plane{{big_of(n_b[0]), big_of(n_b[1]), big_of(n_b[2])}, big_of(off_b)});
}

void inside_check(bool inside) {
  if (!inside) throw std::logic_error("quality: the origin is not inside the wrench space of a closed grasp");
}

// ε̃² of L1: the hull's nearest facet. Fills the boundary (indices into the points), the nearest facet and its
// normal, and (the query keeping them) every facet's plane. None when the origin is not interior to the hull (the
// hull flat, or a facet's offset ≤ 0): the points are positive multiples of the friction-cone edges, so the grasp is
// then not in force closure (QL-1 §3), and nothing is filled.
template <class C, class W>
std::optional<Rational> epsilon_l1_tier(const std::vector<std::array<C, 3>>& P, const Integer& D, Quality_answer& a,
                                        bool filter) {
  Hull<W> h = convex_hull<C, W>(P, filter);
  if (h.tri.empty()) return std::nullopt;
  std::size_t best = 0;
  for (std::size_t f = 0; f < h.tri.size(); ++f) {
    if (!(h.off[f] > 0)) return std::nullopt;
    if (f && nearer(h.off[f], h.n[f], h.off[best], h.n[best], filter)) best = f;
  }
  std::vector<char> on(P.size(), 0);
  for (const auto& t : h.tri) on[t[0]] = on[t[1]] = on[t[2]] = 1;
  a.hull_points = static_cast<std::size_t>(std::count(on.begin(), on.end(), 1));
  a.nearest = h.tri[best];
  a.planes.clear();
  if (a.query.keep_planes)
    for (std::size_t f = 0; f < h.tri.size(); ++f)
      a.planes.push_back({{Rational(big_of(h.n[f][0])), Rational(big_of(h.n[f][1])), Rational(big_of(h.n[f][2]))},
                          canonical(big_of(h.off[f]), D)});
  const Plane nearest{{big_of(h.n[best][0]), big_of(h.n[best][1]), big_of(h.n[best][2])}, big_of(h.off[best])};
  a.boundary = std::move(h.tri);
  for (int k = 0; k < 3; ++k) a.normal[k] = Rational(nearest.n[k]);
  return distance_squared(nearest, D);
}

// ε̃² of L∞: the minimum of h(d)²/|d|² over the candidate normals d (each triangle's normal, and the cross products
// of two contacts' edge directions), h(d) = Σ_i max(0, d·g over contact i's points).
template <class C, class W>
Rational epsilon_linf_tier(const std::vector<std::array<C, 3>>& P, const Integer& D, const std::vector<Generator_ref>& refs,
                           Quality_answer& a, bool filter) {
  using V = std::array<W, 3>;
  const auto cross = [](const V& x, const V& y) {
    return V{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  };
  std::vector<std::vector<std::size_t>> group;  // the points of each contact, in order
  for (std::size_t j = 0; j < refs.size(); ++j) {
    if (j == 0 || refs[j].contact != refs[j - 1].contact) group.emplace_back();
    group.back().push_back(j);
  }
  const auto point = [&P](std::size_t j) { return V{W(P[j][0]), W(P[j][1]), W(P[j][2])}; };
  std::vector<V> normals;
  std::vector<std::vector<V>> edges(group.size());
  for (std::size_t i = 0; i < group.size(); ++i) {
    for (std::size_t j : group[i]) edges[i].push_back(point(j));
    if (group[i].size() == 2) {
      const V l = point(group[i][0]), r = point(group[i][1]);
      edges[i].push_back({l[0] - r[0], l[1] - r[1], l[2] - r[2]});
      normals.push_back(cross(l, r));
    }
  }
  for (std::size_t i = 0; i < group.size(); ++i)
    for (std::size_t j = i + 1; j < group.size(); ++j)
      for (const V& e : edges[i])
        for (const V& f : edges[j]) normals.push_back(cross(e, f));
  bool found = false;
  V best_d;
  W best_h = 0;
  a.planes.clear();
  for (V& d : normals) {
    if (d[0] == 0 && d[1] == 0 && d[2] == 0) continue;
    for (int sign = 0; sign < 2; ++sign) {
      if (sign) for (W& x : d) x = -x;
      W h = 0;
      for (const auto& g : group) {
        W m = 0;
        for (std::size_t j : g) {
          const W v = d[0] * W(P[j][0]) + d[1] * W(P[j][1]) + d[2] * W(P[j][2]);
          if (v > m) m = v;
        }
        h += m;
      }
      inside_check(h > 0);
      if (a.query.keep_planes)
        a.planes.push_back({{Rational(big_of(d[0])), Rational(big_of(d[1])), Rational(big_of(d[2]))}, canonical(big_of(h), D)});
      if (!found || nearer(h, d, best_h, best_d, filter)) best_d = d, best_h = h, found = true;
    }
  }
  if (!found) throw std::logic_error("quality: no facet normal for a closed grasp");
  for (int k = 0; k < 3; ++k) a.normal[k] = Rational(big_of(best_d[k]));
  return distance_squared(Plane{{big_of(best_d[0]), big_of(best_d[1]), big_of(best_d[2])}, big_of(best_h)}, D);
}

// ε̃² of the points (L1: none when the origin is not interior, see epsilon_l1_tier; L∞ is asked only of a closed grasp)
std::optional<Rational> epsilon_of(const Int_points& P, const std::vector<Generator_ref>& refs, Quality_answer& a,
                                   bool filter) {
  const bool l1 = a.query.norm == Quality_norm::l1;
  if (P.tier == Int_points::Tier::small)
    return l1 ? epsilon_l1_tier<std::int64_t, wide::i128>(P.small, P.D, a, filter)
              : epsilon_linf_tier<std::int64_t, wide::i128>(P.small, P.D, refs, a, filter);
  if (P.tier == Int_points::Tier::medium)
    return l1 ? epsilon_l1_tier<std::int64_t, I256>(P.small, P.D, a, filter)
              : epsilon_linf_tier<std::int64_t, I256>(P.small, P.D, refs, a, filter);
  return l1 ? epsilon_l1_tier<Integer, Integer>(P.big, P.D, a, filter)
            : epsilon_linf_tier<Integer, Integer>(P.big, P.D, refs, a, filter);
}

// The fast path (hybrid and exact alike: integer arithmetic, no rationals) for the common scene: small numbers and
// rational scales. A contact's scaled edge g = c·u does not change when its normal n is multiplied by a positive
// number under unit-normal or unit-force (c = 1/|n|, 1/|edge|), so each contact's normal is made integral first. Every
// point comes out as integers over its own denominator, then over their least common multiple D; any number past
// 2^62 (before a product) or a coordinate past 2^20 (the hull's small tier) gives up: the general path answers.
struct Too_big {};
using wide::i128;
constexpr i128 kLimit62 = i128(1) << 62;
i128 checked(i128 x) {
  if (x > kLimit62 || x < -kLimit62) throw Too_big{};
  return x;
}
i128 mul(i128 a, i128 b) { return checked(checked(a) * checked(b)); }  // (|a|, |b| ≤ 2^62: no overflow; the product ≤ 2^62)
i128 small_of(const Integer& z) {
  if (!mpz_fits_slong_p(z.get_mpz_t())) throw Too_big{};
  return checked(z.get_si());
}
std::uint64_t gcd64(std::uint64_t a, std::uint64_t b) {
  while (b) a %= b, std::swap(a, b);
  return a;
}
i128 gcd(i128 a, i128 b) { return gcd64(static_cast<std::uint64_t>(a < 0 ? -a : a), static_cast<std::uint64_t>(b < 0 ? -b : b)); }
i128 lcm(i128 a, i128 b) { return mul(a / gcd(a, b), b); }
// √x for an integer x ≥ 0 that is a perfect square, or -1.
i128 exact_root(i128 x) {
  if (x < 0) return -1;
  i128 r = static_cast<i128>(std::sqrt(static_cast<long double>(x)));
  while (r > 0 && r * r > x) --r;
  while ((r + 1) * (r + 1) <= x) ++r;
  return r * r == x ? r : -1;
}

// Fills a.refs, a.scales (exact: error 0; bound an integer ≥ |u|) and the points; false when the scene is not small
// or a scale is irrational.
bool fast_points(const Scene& scene, const Quality_query& q, Quality_answer& a, Int_points& out) {
  try {
    const i128 t1 = small_of(q.torque_scale.get_num()), t2 = small_of(q.torque_scale.get_den());
    struct Pt {
      i128 x, y, z, den;
    };
    std::vector<Pt> pts;
    a.refs.clear();
    a.scales.assign(scene.contacts.size(), {});
    for (std::size_t i = 0; i < scene.contacts.size(); ++i) {
      const Contact& c = scene.contacts[i];
      if (c.kind != Contact::Kind::point) return false;  // (wrench contacts: the general path)
      // r = p − about over dr; the normal made integral (N), or kept over its denominator (as given)
      const Rational rx = c.at.x - a.about.x, ry = c.at.y - a.about.y;
      const i128 dr = lcm(small_of(rx.get_den()), small_of(ry.get_den()));
      const i128 RX = mul(small_of(rx.get_num()), dr / small_of(rx.get_den())), RY = mul(small_of(ry.get_num()), dr / small_of(ry.get_den()));
      const i128 dnx = small_of(c.normal.x.get_den()), dny = small_of(c.normal.y.get_den());
      const i128 Nx = mul(small_of(c.normal.x.get_num()), dny), Ny = mul(small_of(c.normal.y.get_num()), dnx);  // n·dnx·dny
      const i128 M = small_of(c.mu.get_num()), dm = small_of(c.mu.get_den());
      const i128 N2 = checked(mul(Nx, Nx) + mul(Ny, Ny)), S2 = checked(mul(dm, dm) + mul(M, M));
      // the edges F = dm·N ± M·rot90 N = dm·dnx·dny·(n ± μ rot90 n); K = dm·dnx·dny; the scale's denominator `sc` (g = u·K/sc)
      const i128 K = mul(mul(dm, dnx), dny);
      i128 sc = K;  // as given: g = u = F/K
      Quality_scale& s = a.scales[i];
      s.error = 0;
      if (q.normalize == Force_normalization::unit_normal) {
        const i128 r = exact_root(N2);  // |n| = r/(dnx dny): c = dnx dny / r; g = F/(dm·r)
        if (r <= 0) return false;
        sc = mul(dm, r);
        s.q = canonical(big_of(N2), big_of(mul(dnx, dny)) * big_of(mul(dnx, dny)));
        s.scale = canonical(big_of(mul(dnx, dny)), big_of(r));
      } else if (q.normalize == Force_normalization::unit_force) {
        const i128 r = exact_root(N2), r2 = exact_root(S2);  // |edge| = r·r2/K: g = F/(r·r2)
        if (r <= 0 || r2 <= 0) return false;
        sc = mul(r, r2);
        const i128 qd = mul(mul(dnx, dny), dm);
        s.q = canonical(big_of(N2) * big_of(S2), big_of(qd) * big_of(qd));
        s.scale = canonical(big_of(qd), big_of(mul(r, r2)));
      } else {
        s.q = 1, s.scale = 1;
      }
      const bool frictional = M != 0;
      const int count = frictional ? 2 : 1;
      Integer bound = 0;
      for (int e = 0; e < count; ++e) {
        const i128 sign = e == 0 ? 1 : -1;  // left: N + μ rot90 N, right: N − μ rot90 N (rot90 N = (−Ny, Nx))
        const i128 Fx = frictional ? checked(mul(dm, Nx) - sign * mul(M, Ny)) : Nx;
        const i128 Fy = frictional ? checked(mul(dm, Ny) + sign * mul(M, Nx)) : Ny;
        const i128 k = frictional ? K : mul(dnx, dny);  // F = k·f
        const i128 s_den = frictional ? sc : (q.normalize == Force_normalization::as_given ? k : sc / dm);
        // u = (F/k, F/k, t1 (RX Fy − RY Fx)/(t2 dr k)); g = u·k/s_den = (F, t1 (RX Fy − RY Fx)/(t2 dr)) / s_den
        const i128 m = checked(mul(RX, Fy) - mul(RY, Fx));
        const i128 den = mul(mul(t2, dr), s_den);
        pts.push_back({mul(mul(Fx, t2), dr), mul(mul(Fy, t2), dr), mul(t1, m), den});
        a.refs.push_back({i, frictional ? (e == 0 ? Edge::left : Edge::right) : Edge::normal});
        // |u| ≤ |ux| + |uy| + |uz|, each rounded up: an integer bound
        const auto ceil_abs = [](i128 n, i128 d) { n = n < 0 ? -n : n; return (n + d - 1) / d; };
        const Integer b = big_of(ceil_abs(Fx, k) + ceil_abs(Fy, k) + ceil_abs(mul(t1, m), mul(mul(t2, dr), k)));
        if (b > bound) bound = b;
      }
      s.bound = bound;
    }
    i128 D = 1;
    for (const Pt& p : pts) D = lcm(D, p.den);
    out.D = big_of(D);
    out.tier = Int_points::Tier::small;
    out.small.resize(pts.size());
    const i128 small = i128(1) << 20, medium = i128(1) << 61;
    for (std::size_t j = 0; j < pts.size(); ++j) {
      const i128 f = D / pts[j].den, v[3] = {mul(pts[j].x, f), mul(pts[j].y, f), mul(pts[j].z, f)};
      for (int k = 0; k < 3; ++k) {
        if (v[k] > medium || v[k] < -medium) return false;
        if (v[k] > small || v[k] < -small) out.tier = Int_points::Tier::medium;
        out.small[j][k] = static_cast<std::int64_t>(v[k]);
      }
    }
    return true;
  } catch (const Too_big&) {
    return false;
  }
}

}  // namespace

namespace {

// [QL-1 §8] ε by the float twin (float/quality_twin.h) for point contacts: true when it certified the answer (set in
// `a`: closure's verdict, ε's bracket as the doubles' exact values, `twin`).
bool twin_epsilon(const Scene& scene, Quality_answer& a) {
  std::vector<fl::Quality_twin_contact> in;
  const std::vector<fl::Bounded_contact> bc = to_bounded(scene);
  for (const fl::Bounded_contact& c : bc) {
    if (c.is_wrench) return false;
    in.push_back({c.ax, c.ay, c.nx, c.ny, c.frictional ? c.mu : fl::Bounded::exact(0)});
  }
  const Quality_query& q = a.query;
  const fl::Twin_normalization how = q.normalize == Force_normalization::unit_normal ? fl::Twin_normalization::unit_normal
                                     : q.normalize == Force_normalization::unit_force ? fl::Twin_normalization::unit_force
                                                                                      : fl::Twin_normalization::as_given;
  const fl::Quality_twin_answer t =
      fl::epsilon_twin(in, how, to_bounded(q.torque_scale), to_bounded(a.about.x), to_bounded(a.about.y));
  if (!t.certain) return false;
  a.twin = true;
  a.closure.mode = Mode::float_only;
  a.closure.decided = true;
  a.closure.holds = t.closed;
  a.lower = Rational(t.lower), a.upper = Rational(t.upper);
  a.exact = !t.closed;  // ε = 0 exactly when open
  if (a.exact) a.squared = 0;
  return true;
}

}  // namespace

namespace {
// The query with its preset resolved against the scene (the centre of mass and the outline it needs).
Quality_query resolved(const Scene& scene, Quality_query q) {
  if (q.preset == Quality_preset::none) return q;
  const char* name = q.preset == Quality_preset::graspit ? "graspit" : "dexnet";
  if (!scene.body.com)
    throw Input_error(std::string("body.com: --preset ") + name + " takes moments about the centre of mass; the scene has none (add body.com)");
  q.normalize = Force_normalization::unit_normal;  // (the norm is the query's: GraspIt! has both, Dex-Net L1)
  q.about = *scene.body.com;
  if (q.preset == Quality_preset::graspit) {
    if (scene.body.outline.empty())
      throw Input_error("body.outline: --preset graspit divides moments by the body's largest radius from body.com; the scene has no outline");
    Rational r2 = 0;
    for (const Vec2& v : scene.body.outline) {
      const Vec2 d{v.x - scene.body.com->x, v.y - scene.body.com->y};
      r2 = std::max(r2, dot(d, d));
    }
    if (r2 == 0) throw Input_error("body.outline: every vertex is at body.com (no radius to divide moments by)");
    q.torque_radius_squared = r2;
  }
  return q;
}
}  // namespace

void decide_quality_into(const Scene& given, const Quality_query& asked, Mode mode, Quality_answer& a) {
  if (given.contacts.empty()) throw Input_error("contacts: the scene has no contacts, so no grasp to measure");
  Quality_query resolved_query;  // (a preset resolved; else the query as asked, not copied)
  const Quality_query& query =
      asked.preset == Quality_preset::none ? asked : (resolved_query = resolved(given, asked));
  if (query.torque_scale <= 0)
    throw Input_error("--torque-scale: " + to_string(query.torque_scale) + " is not positive (the moment's weight)");
  if (query.tolerance <= 0) throw Input_error("--tolerance: " + to_string(query.tolerance) + " is not positive");
  a.query = query;
  a.about = query.about ? *query.about : given.body.com ? *given.body.com : Vec2{};
  const bool radius = query.torque_radius_squared.has_value();
  // the float twin first, on the contacts as read (lazily read ones carry their certified doubles)
  if (query.norm == Quality_norm::l1 && !radius && !query.keep_planes && mode != Mode::exact && query.twin_first &&
      twin_epsilon(given, a))
    return;
  // contacts read lazily (the array API's doubles, the streaming reader) get their rationals first
  std::optional<Scene> storage;
  const Scene& scene = exact_contacts(given, storage);
  Quality_scale torque;  // s = 1/√r2: exact when r2 is a rational square
  if (radius) {
    torque.q = *query.torque_radius_squared;
    set_scale(torque, 64);
    if (torque.error == 0) a.query.torque_scale = torque.scale;
  }
  const bool irrational_torque = radius && torque.error != 0;
  const std::size_t edges = generator_count(scene, Reading::friction);
  // [QL-1 §3] L1: the hull of the scaled edges decides closure itself (the origin interior to it exactly when the
  // edges positively span the wrench space), so the closure engine runs first only for L∞, in float_only and past the
  // edge bound (an open grasp has none); after the hull only for an open grasp, for its certificate.
  const bool hull_decides = query.norm == Quality_norm::l1 && mode != Mode::float_only && edges <= kQualityMaxL1Edges;
  const auto open = [&](const Quality_query& q) {  // ε = 0: the closure's twist shows the origin on the boundary or outside
    a = Quality_answer{};
    a.query = q;
    a.about = query.about ? *query.about : given.body.com ? *given.body.com : Vec2{};
    a.closure = decide_closure(scene, Property::force_closure, mode, true);
    if (a.closure.holds) throw std::logic_error("quality: the hull misses the origin of a grasp in force closure");
    a.exact = true;
  };
  if (!hull_decides) {
    a.closure = decide_closure(scene, Property::force_closure, mode, false);  // (a certificate only when open)
    if (!a.closure.decided) return;
    if (!a.closure.holds) a.closure = decide_closure(scene, Property::force_closure, mode, true);
    if (!a.closure.holds) {  // ε = 0: the closure's twist shows the origin on the boundary or outside
      a.exact = true;
      return;
    }
    if (mode == Mode::float_only) return;  // ε has no float twin: the caller says undecided
  } else {  // closed unless the hull says otherwise below (open() then replaces the answer)
    a.closure.mode = mode;
    a.closure.decided = a.closure.holds = true;
    a.closure.rank = 3;
    a.closure.shape = Dual_shape::zero;
    a.closure.generators = edges;
    a.closure.predicates = 1;  // (the hull's signs: exact in exact mode, filtered otherwise)
    a.closure.exact_predicates = mode == Mode::exact;
  }
  if (query.norm == Quality_norm::l1 && edges > kQualityMaxL1Edges)
    throw Input_error("contacts: epsilon (L1) of " + std::to_string(edges) + " friction-cone edges, more than " +
                      std::to_string(kQualityMaxL1Edges) + " (its hull grows as their square); the grasp is in force closure");
  if (query.norm == Quality_norm::linf && scene.contacts.size() > kQualityMaxLinfContacts)
    throw Input_error("contacts: epsilon (Linf) of " + std::to_string(scene.contacts.size()) + " contacts, more than " +
                      std::to_string(kQualityMaxLinfContacts) + " (its candidate facets grow as the cube); use --norm L1");
  const Quality_query before = a.query;  // (the query as an open grasp's answer states it)
  Int_points fast;
  if (!query.keep_planes && !irrational_torque && fast_points(scene, a.query, a, fast)) {  // rational scales, small numbers
    const std::optional<Rational> e2 = epsilon_of(fast, a.refs, a, mode != Mode::exact);
    if (!e2) return open(before);
    a.exact = true;
    a.squared = *e2;
    unsigned bits = 16;
    for (Rational t = query.tolerance; t < 1 && bits < 4096; t *= 2) ++bits;
    for (;; bits *= 2) {
      const auto [lo, hi] = sqrt_bracket(a.squared, bits);
      a.lower = lo, a.upper = hi;
      if (hi - lo <= query.tolerance * lo || bits >= (1u << 16)) return;
    }
  }
  a.refs.clear();
  a.scales.clear();
  const std::vector<Generator> gens = generators(scene, Reading::friction);
  // each edge's force and moment about `about` (the torque scale applied below)
  std::vector<Vec3q> fm;
  for (const Generator& g : gens) {
    a.refs.push_back({g.contact, g.edge});
    fm.push_back(quality_wrench(g.w, 1, 1, a.about));
  }
  a.scales.resize(scene.contacts.size());
  for (std::size_t i = 0; i < scene.contacts.size(); ++i) {
    const Contact& c = scene.contacts[i];
    Quality_scale& s = a.scales[i];
    const Rational n2 = c.kind == Contact::Kind::point ? dot(c.normal, c.normal) : Rational(1);
    s.q = c.kind == Contact::Kind::wrench || query.normalize == Force_normalization::as_given ? Rational(1)
          : query.normalize == Force_normalization::unit_force                               ? n2 * (1 + c.mu * c.mu)
                                                                                              : n2;
  }
  if (irrational_torque)
    for (std::size_t j = 0; j < fm.size(); ++j) {
      Quality_scale& s = a.scales[a.refs[j].contact];
      s.moment_bound = std::max(s.moment_bound, upper_root(fm[j][2] * fm[j][2]));
    }
  // Scales (and an irrational torque scale) to `bits` of precision, ε̃² of the rational polytope, and the bracket; more
  // bits until the bracket is within the tolerance (the exact case needs only the square root's bits).
  Rational eps2;
  bool built = false;
  // start from the bits the tolerance asks (its binary digits and a margin), at least 16
  unsigned start = 16;
  for (Rational t = query.tolerance; t < 1 && start < 4096; t *= 2) ++start;
  for (unsigned bits = start;; bits *= 2) {
    bool exact = true;
    if (!built || !a.exact) {
      if (irrational_torque) {
        set_scale(torque, bits);
        a.query.torque_scale = torque.scale;
        a.torque_scale_error = torque.error;
        exact = false;
      }
      const Rational& ts = a.query.torque_scale;
      const Rational top = ts + a.torque_scale_error;  // |u(s)| for the true s ≤ this with s ≤ top
      for (Quality_scale& s : a.scales) s.bound = 0;
      for (std::size_t j = 0; j < fm.size(); ++j) {
        Quality_scale& s = a.scales[a.refs[j].contact];
        s.bound = std::max(s.bound, upper_root(fm[j][0] * fm[j][0] + fm[j][1] * fm[j][1] + top * top * fm[j][2] * fm[j][2]));
      }
      for (Quality_scale& s : a.scales) set_scale(s, bits), exact = exact && s.error == 0;
      a.points.resize(fm.size());
      for (std::size_t j = 0; j < fm.size(); ++j) {
        const Rational& c = a.scales[a.refs[j].contact].scale;
        a.points[j] = {c * fm[j][0], c * fm[j][1], c * ts * fm[j][2]};
      }
      const std::optional<Rational> e2 = epsilon_of(int_points(a.points), a.refs, a, mode != Mode::exact);
      if (!e2) {
        if (built) throw std::logic_error("quality: the origin left the hull at a finer scale");
        return open(before);
      }
      eps2 = *e2;
      a.exact = exact;
      built = true;
    }
    Rational delta = 0;
    for (const Quality_scale& s : a.scales) {
      const Rational d = s.error * s.bound + s.scale * s.moment_bound * a.torque_scale_error;
      delta = query.norm == Quality_norm::l1 ? std::max(delta, d) : delta + d;
    }
    const auto [lo, hi] = sqrt_bracket(eps2, bits);
    a.squared = eps2;
    a.lower = std::max(Rational(0), Rational(lo - delta));
    a.upper = hi + delta;
    if (a.upper - a.lower <= query.tolerance * a.lower || bits >= (1u << 16)) break;
  }
}

Quality_answer decide_quality(const Scene& scene, const Quality_query& query, Mode mode) {
  Quality_answer a;
  decide_quality_into(scene, query, mode, a);
  return a;
}

Contact_margins contact_margins(const Scene& given, const Quality_query& asked) {
  std::optional<Scene> storage;
  const Scene& scene = exact_contacts(given, storage);
  if (scene.contacts.empty()) throw Input_error("contacts: the scene has no contacts, so no grasp to measure");
  const Quality_query query = resolved(scene, asked);
  Contact_margins out;
  out.about = query.about ? *query.about : scene.body.com ? *scene.body.com : Vec2{};
  out.torque_scale = query.torque_scale;
  if (query.torque_radius_squared) {
    Quality_scale torque;
    torque.q = *query.torque_radius_squared;
    set_scale(torque, 64);
    out.torque_scale = torque.scale;
    out.exact = torque.error == 0;
  }
  if (out.torque_scale <= 0)
    throw Input_error("--torque-scale: " + to_string(out.torque_scale) + " is not positive (the moment's weight)");
  const std::vector<Generator> gens = generators(scene, Reading::friction);
  if (gens.size() > kContactMarginsMaxEdges)
    throw Input_error("contacts: the contact margins of " + std::to_string(gens.size()) + " friction-cone edges, more than " +
                      std::to_string(kContactMarginsMaxEdges) + " (every triple of them is measured); ask without --contact-margins");
  // each edge as a primitive integer vector (the measure is invariant under positive scaling) and its squared length;
  // a point contact with friction also as its normal and tangent wrenches W(p, n), W(p, rot90 n) — the plane of its
  // two edges, measured without the cone's width
  using Iv = std::array<Integer, 3>;
  const auto integral = [](const Vec3q& w) { return sgn(w[0]) == 0 && sgn(w[1]) == 0 && sgn(w[2]) == 0 ? Iv{} : primitive(w); };
  const auto len2 = [](const Iv& v) { return Integer(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); };
  std::vector<Iv> u;
  std::vector<Integer> n2;
  for (const Generator& g : gens) {
    u.push_back(integral(quality_wrench(g.w, 1, out.torque_scale, out.about)));
    n2.push_back(len2(u.back()));
  }
  std::vector<std::array<Iv, 2>> plane(scene.contacts.size());
  std::vector<std::array<Integer, 2>> plane2(scene.contacts.size());
  for (std::size_t c = 0; c < scene.contacts.size(); ++c) {
    const Contact& k = scene.contacts[c];
    if (k.kind != Contact::Kind::point) continue;
    plane[c][0] = integral(quality_wrench(wrench_at(k.at, k.normal), 1, out.torque_scale, out.about));
    plane[c][1] = integral(quality_wrench(wrench_at(k.at, {-k.normal.y, k.normal.x}), 1, out.torque_scale, out.about));
    plane2[c] = {len2(plane[c][0]), len2(plane[c][1])};
  }
  out.contacts.resize(scene.contacts.size());
  for (std::size_t i = 0; i < out.contacts.size(); ++i) out.contacts[i].contact = i;
  Integer d;
  Rational r2;
  for (std::size_t i = 0; i < u.size(); ++i)
    for (std::size_t j = i + 1; j < u.size(); ++j)
      for (std::size_t k = j + 1; k < u.size(); ++k) {
        const Iv *x = &u[i], *y = &u[j], *z = &u[k];
        Integer den = n2[i] * n2[j] * n2[k];
        const std::size_t ci = gens[i].contact, cj = gens[j].contact, ck = gens[k].contact;
        if (ci == cj) x = &plane[ci][0], y = &plane[ci][1], den = plane2[ci][0] * plane2[ci][1] * n2[k];
        else if (cj == ck) y = &plane[cj][0], z = &plane[cj][1], den = n2[i] * plane2[cj][0] * plane2[cj][1];
        const Iv& X = *x;
        const Iv& Y = *y;
        const Iv& Z = *z;
        d = (X[1] * Y[2] - X[2] * Y[1]) * Z[0] + (X[2] * Y[0] - X[0] * Y[2]) * Z[1] + (X[0] * Y[1] - X[1] * Y[0]) * Z[2];
        if (sgn(d) == 0) r2 = 0;
        else r2 = Rational(d * d, den), r2.canonicalize();
        const std::array<Generator_ref, 3> triple{{{ci, gens[i].edge}, {cj, gens[j].edge}, {ck, gens[k].edge}}};
        const std::size_t cs[3] = {ci, cj, ck};
        for (std::size_t t = 0; t < 3; ++t) {
          if ((t >= 1 && cs[t] == cs[0]) || (t == 2 && cs[2] == cs[1])) continue;  // (each contact once)
          Contact_margin& m = out.contacts[cs[t]];
          ++m.triples;
          m.zeros += sgn(d) == 0;
          if (!m.squared || r2 < *m.squared) m.squared = r2, m.nearest = triple;
        }
      }
  return out;
}

}  // namespace wrenchkit
