// [QL-1] The Ferrari–Canny quality ε, exact or in a certified bracket. See quality.h and
// proofs/notes/QL-1-quality.md for the constructions and why they are right.
#include "exact/statics/quality.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "exact/io/input_error.h"

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
P3 sub(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
P3 cross3(const P3& a, const P3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Integer dot3(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool zero3(const P3& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

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
// triangles of point indices, each oriented outward (the interior behind it). Points on the boundary but not
// extreme may be left out. O(points · facets) predicates.
struct Hull {
  std::vector<std::array<std::size_t, 3>> tri;
  std::vector<Plane> plane;
};
Hull convex_hull(const std::vector<P3>& P) {
  const std::size_t n = P.size();
  std::size_t i1 = n, i2 = n, i3 = n;
  for (std::size_t i = 1; i < n && i1 == n; ++i)
    if (!zero3(sub(P[i], P[0]))) i1 = i;
  for (std::size_t i = 1; i1 < n && i < n && i2 == n; ++i)
    if (!zero3(cross3(sub(P[i1], P[0]), sub(P[i], P[0])))) i2 = i;
  for (std::size_t i = 1; i2 < n && i < n && i3 == n; ++i)
    if (dot3(cross3(sub(P[i1], P[0]), sub(P[i2], P[0])), sub(P[i], P[0])) != 0) i3 = i;
  if (i3 == n) throw std::logic_error("quality: the wrench space of a grasp in closure is flat");
  P3 inside;  // four times the first tetrahedron's centroid: interior to every later hull
  for (int k = 0; k < 3; ++k) inside[k] = P[0][k] + P[i1][k] + P[i2][k] + P[i3][k];

  Hull h;
  std::vector<char> alive;
  std::unordered_map<std::uint64_t, std::size_t> edge;  // directed edge (u, v) → its facet
  const auto key = [](std::size_t u, std::size_t v) { return (static_cast<std::uint64_t>(u) << 32) | v; };
  const auto add = [&](std::size_t a, std::size_t b, std::size_t c) {
    Plane p{cross3(sub(P[b], P[a]), sub(P[c], P[a])), 0};
    p.off = dot3(p.n, P[a]);
    if (dot3(p.n, inside) > 4 * p.off) {  // facing inward: turn it
      std::swap(b, c);
      for (Integer& x : p.n) x = -x;
      p.off = -p.off;
    }
    const std::size_t f = h.tri.size();
    h.tri.push_back({a, b, c});
    h.plane.push_back(std::move(p));
    alive.push_back(1);
    edge[key(a, b)] = f, edge[key(b, c)] = f, edge[key(c, a)] = f;
  };
  add(0, i1, i2), add(0, i1, i3), add(0, i2, i3), add(i1, i2, i3);

  std::vector<std::size_t> visible;
  std::vector<char> seen;
  std::vector<std::pair<std::size_t, std::size_t>> horizon;
  for (std::size_t p = 1; p < n; ++p) {
    if (p == i1 || p == i2 || p == i3) continue;
    visible.clear();
    seen.assign(h.tri.size(), 0);
    for (std::size_t f = 0; f < h.tri.size(); ++f)
      if (alive[f] && dot3(h.plane[f].n, P[p]) > h.plane[f].off) visible.push_back(f), seen[f] = 1;
    if (visible.empty()) continue;  // inside or on the boundary
    horizon.clear();
    for (std::size_t f : visible)
      for (int k = 0; k < 3; ++k) {
        const std::size_t u = h.tri[f][k], v = h.tri[f][(k + 1) % 3];
        if (!seen[edge.at(key(v, u))]) horizon.push_back({u, v});
      }
    for (std::size_t f : visible) {
      alive[f] = 0;
      for (int k = 0; k < 3; ++k) edge.erase(key(h.tri[f][k], h.tri[f][(k + 1) % 3]));
    }
    for (const auto& [u, v] : horizon) add(u, v, p);
  }
  Hull out;
  for (std::size_t f = 0; f < h.tri.size(); ++f)
    if (alive[f]) out.tri.push_back(h.tri[f]), out.plane.push_back(std::move(h.plane[f]));
  return out;
}

// ε̃² of L1: the hull's nearest facet. Fills the boundary (indices into the points) and the nearest facet.
Rational epsilon_l1(const std::vector<Vec3q>& pts, Quality_answer& a) {
  Integer D;
  const std::vector<P3> P = integer_points(pts, D);
  Hull h = convex_hull(P);
  std::size_t best = 0;
  for (std::size_t f = 0; f < h.tri.size(); ++f) {
    if (h.plane[f].off <= 0) throw std::logic_error("quality: the origin is not inside the wrench space of a closed grasp");
    if (closer(h.plane[f], h.plane[best])) best = f;
  }
  std::vector<char> on(P.size(), 0);
  for (const auto& t : h.tri) on[t[0]] = on[t[1]] = on[t[2]] = 1;
  a.hull_points = static_cast<std::size_t>(std::count(on.begin(), on.end(), 1));
  a.boundary = h.tri;
  a.nearest = h.tri[best];
  a.planes.clear();
  for (const Plane& p : h.plane) a.planes.push_back({{Rational(p.n[0]), Rational(p.n[1]), Rational(p.n[2])}, canonical(p.off, D)});
  for (int k = 0; k < 3; ++k) a.normal[k] = Rational(h.plane[best].n[k]);
  return distance_squared(h.plane[best], D);
}

// ε̃² of L∞: the minimum of h(d)²/|d|² over the candidate normals d (each triangle's normal, and the cross products
// of two contacts' edge directions), h(d) = Σ_i max(0, d·g over contact i's points).
Rational epsilon_linf(const std::vector<Vec3q>& pts, const std::vector<Generator_ref>& refs, Quality_answer& a) {
  Integer D;
  const std::vector<P3> P = integer_points(pts, D);
  std::vector<std::vector<std::size_t>> group;  // the points of each contact, in order
  for (std::size_t j = 0; j < refs.size(); ++j) {
    if (j == 0 || refs[j].contact != refs[j - 1].contact) group.emplace_back();
    group.back().push_back(j);
  }
  std::vector<P3> normals;
  std::vector<std::vector<P3>> edges(group.size());
  for (std::size_t i = 0; i < group.size(); ++i) {
    for (std::size_t j : group[i]) edges[i].push_back(P[j]);
    if (group[i].size() == 2) {
      const P3 &l = P[group[i][0]], &r = P[group[i][1]];
      edges[i].push_back(sub(l, r));
      normals.push_back(cross3(l, r));
    }
  }
  for (std::size_t i = 0; i < group.size(); ++i)
    for (std::size_t j = i + 1; j < group.size(); ++j)
      for (const P3& e : edges[i])
        for (const P3& f : edges[j]) normals.push_back(cross3(e, f));
  bool found = false;
  Plane best;
  a.planes.clear();
  for (P3& d : normals) {
    if (zero3(d)) continue;
    for (int sign = 0; sign < 2; ++sign) {
      if (sign) for (Integer& x : d) x = -x;
      Integer h = 0;
      for (const auto& g : group) {
        Integer m = 0;
        for (std::size_t j : g) m = std::max(m, Integer(dot3(d, P[j])));
        h += m;
      }
      if (h <= 0) throw std::logic_error("quality: the origin is not inside the wrench space of a closed grasp");
      a.planes.push_back({{Rational(d[0]), Rational(d[1]), Rational(d[2])}, canonical(h, D)});
      Plane p{d, h};
      if (!found || closer(p, best)) best = std::move(p), found = true;
    }
  }
  if (!found) throw std::logic_error("quality: no facet normal for a closed grasp");
  for (int k = 0; k < 3; ++k) a.normal[k] = Rational(best.n[k]);
  return distance_squared(best, D);
}

}  // namespace

Quality_answer decide_quality(const Scene& scene, const Quality_query& query, Mode mode) {
  if (scene.contacts.empty()) throw Input_error("contacts: the scene has no contacts, so no grasp to measure");
  if (query.torque_scale <= 0)
    throw Input_error("--torque-scale: " + to_string(query.torque_scale) + " is not positive (the moment's weight)");
  if (query.tolerance <= 0) throw Input_error("--tolerance: " + to_string(query.tolerance) + " is not positive");
  Quality_answer a;
  a.query = query;
  a.about = query.about ? *query.about : scene.body.com ? *scene.body.com : Vec2{};
  a.closure = decide_closure(scene, Property::force_closure, mode, true);
  if (!a.closure.decided) return a;
  if (!a.closure.holds) {  // ε = 0: the closure's twist shows the origin on the boundary or outside
    a.exact = true;
    return a;
  }
  if (mode == Mode::float_only) return a;  // ε has no float twin: the caller says undecided
  const std::vector<Generator> gens = generators(scene, Reading::friction);
  std::vector<Vec3q> unscaled;
  for (const Generator& g : gens) {
    a.refs.push_back({g.contact, g.edge});
    unscaled.push_back(quality_wrench(g.w, 1, query.torque_scale, a.about));
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
  for (std::size_t j = 0; j < unscaled.size(); ++j) {
    Quality_scale& s = a.scales[a.refs[j].contact];
    s.bound = std::max(s.bound, upper_root(dot(unscaled[j], unscaled[j])));
  }
  // Scales to `bits` of precision, ε̃² of the rational polytope, and the bracket; more bits until the bracket is
  // within the tolerance (the exact case needs only the square root's bits).
  Rational eps2;
  bool built = false;
  // start from the bits the tolerance asks (its binary digits and a margin), at least 16
  unsigned start = 16;
  for (Rational t = query.tolerance; t < 1 && start < 4096; t *= 2) ++start;
  for (unsigned bits = start;; bits *= 2) {
    bool exact = true;
    if (!built || !a.exact) {
      for (Quality_scale& s : a.scales) set_scale(s, bits), exact = exact && s.error == 0;
      a.points.resize(unscaled.size());
      for (std::size_t j = 0; j < unscaled.size(); ++j) {
        const Rational& c = a.scales[a.refs[j].contact].scale;
        for (int k = 0; k < 3; ++k) a.points[j][k] = c * unscaled[j][k];
      }
      eps2 = query.norm == Quality_norm::l1 ? epsilon_l1(a.points, a) : epsilon_linf(a.points, a.refs, a);
      a.exact = exact;
      built = true;
    }
    Rational delta = 0;
    for (const Quality_scale& s : a.scales) {
      const Rational d = s.error * s.bound;
      delta = query.norm == Quality_norm::l1 ? std::max(delta, d) : delta + d;
    }
    const auto [lo, hi] = sqrt_bracket(eps2, bits);
    a.squared = eps2;
    a.lower = std::max(Rational(0), Rational(lo - delta));
    a.upper = hi + delta;
    if (a.upper - a.lower <= query.tolerance * a.lower || bits >= (1u << 16)) break;
  }
  return a;
}

}  // namespace wrenchkit
