// proofs/checker/quality.cpp - the grasp quality ε, certificate-format.md §3.4 (theory: proofs/notes/QL-1-quality.md).
// The claim is ε ∈ [lower, upper] for the grasp wrench space of the scene's contacts (friction reading) under the
// certificate's norm, force normalisation, torque scale and moment point. Exact rationals (mpq) throughout: the sets
// are small (two edges per contact) and this file is read more often than it runs.
#include <algorithm>
#include <map>
#include <utility>

#include "proofs/checker/certificate.h"
#include "proofs/checker/closure.h"

namespace wrenchkit_checker::detail {
namespace {

using V3 = std::array<Q, 3>;
V3 minus(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Q dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool zero(const V3& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }
std::string show3(const V3& a) { return "(" + show(a[0]) + ", " + show(a[1]) + ", " + show(a[2]) + ")"; }

// One generator of the wrench space: its contact, and its point g̃ = scale · (f, s·(m − about × f)).
struct Point {
  std::size_t contact;
  V3 g;
};

// The scaled generators (§3.4 rules 1–2): each contact's scale is within its error of 1/√q (q = 1, |n|² or |n|²(1+μ²),
// read off its edges: |n ± μ·rot90 n|² = |n|²(1 + μ²) and (left + right)/2 = n), and bounds its edges' lengths.
std::vector<Point> scaled_points(const Quality_part& q, const std::vector<Contact>& contacts, const Limits& lim) {
  if (q.scales.size() != contacts.size())
    throw Failure{"scales: " + std::to_string(q.scales.size()) + " entries for " + std::to_string(contacts.size()) +
                  " contacts (expected one per contact, in order)"};
  std::vector<Point> out;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const std::string at = "scales[" + std::to_string(i) + "]";
    const Quality_part::Scale& s = q.scales[i];
    const Generators<Z> gen = generators<Z>(contacts[i], Reading::friction, lim);
    V3 u[2];
    Q moment[2];  // m − about × f, before the torque scale
    for (int k = 0; k < gen.count; ++k) {
      const Z& d = gen.w[k].d;
      const Q fx = value(gen.w[k].v[0], d), fy = value(gen.w[k].v[1], d), m = value(gen.w[k].v[2], d);  // lowest terms
      moment[k] = m - (q.about[0] * fy - q.about[1] * fx);
      u[k] = {fx, fy, q.torque_scale * moment[k]};
    }
    Q sq = 1;  // q: c = 1/√q
    if (!contacts[i].wrench && q.normalize != "as-given") {
      // the force n (one edge) or n ± μ·rot90 n (two): |edge|² = |n|²(1 + μ²), (left + right)/2 = n
      const Q nx = gen.count == 1 ? u[0][0] : Q((u[0][0] + u[1][0]) / 2), ny = gen.count == 1 ? u[0][1] : Q((u[0][1] + u[1][1]) / 2);
      sq = q.normalize == "unit-force" ? Q(u[0][0] * u[0][0] + u[0][1] * u[0][1]) : Q(nx * nx + ny * ny);
    }
    if (sgn(s.error) < 0 || sgn(s.bound) < 0) throw Failure{at + ": the error and the bound must not be negative"};
    if (sgn(s.error) == 0) {
      if (s.scale * s.scale * sq != 1) throw Failure{at + ".scale: " + show(s.scale) + " is not 1/√" + show(sq)};
    } else {
      const Q low = s.scale - s.error, high = s.scale + s.error;
      if (sgn(low) < 0 || low * low * sq > 1 || high * high * sq < 1)
        throw Failure{at + ": 1/√" + show(sq) + " is not within " + show(s.error) + " of " + show(s.scale)};
    }
    // the edge's length at the true torque scale s ≤ torque_scale + its error (rule 2; 7 with a radius)
    const Q top = q.torque_scale + (q.has_radius ? q.torque_error : Q(0));
    if (q.has_radius && !s.has_moment_bound) throw Failure{at + ": missing \"moment_bound\" (the torque scale is not exact)"};
    for (int k = 0; k < gen.count; ++k) {
      if (s.bound * s.bound < u[k][0] * u[k][0] + u[k][1] * u[k][1] + top * top * moment[k] * moment[k])
        throw Failure{at + ".bound: " + show(s.bound) + " is shorter than the edge " + show3(u[k])};
      if (q.has_radius && s.moment_bound * s.moment_bound < moment[k] * moment[k])
        throw Failure{at + ".moment_bound: " + show(s.moment_bound) + " is below the moment " + show(moment[k])};
      out.push_back({i, {s.scale * u[k][0], s.scale * u[k][1], s.scale * u[k][2]}});
    }
  }
  return out;
}

// L1, ε > 0 (rules 3–4): the boundary is a closed surface of outward triangles on supporting planes; ε̃² is the
// least (off/|n|)² over them, attained by `nearest`.
Q l1_epsilon_squared(const Quality_part& q, const std::vector<Point>& P) {
  if (q.boundary.empty()) throw Failure{"boundary: empty (a closed surface has at least four triangles)"};
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edges;  // directed edge → its triangle
  Q best;
  bool nearest = false;
  for (std::size_t t = 0; t < q.boundary.size(); ++t) {
    const std::array<std::size_t, 3>& T = q.boundary[t];
    const std::string at = "boundary[" + std::to_string(t) + "]";
    for (std::size_t v : T)
      if (v >= P.size()) throw Failure{at + ": generator index " + std::to_string(v) + " is out of range (the scene has " +
                                       std::to_string(P.size()) + " generators)"};
    const V3 n = cross(minus(P[T[1]].g, P[T[0]].g), minus(P[T[2]].g, P[T[0]].g));
    const Q off = dot(n, P[T[0]].g);
    if (sgn(off) <= 0) throw Failure{at + ": the origin is not strictly behind the triangle (det " + show(off) + " <= 0)"};
    for (std::size_t j = 0; j < P.size(); ++j)
      if (dot(n, P[j].g) > off) throw Failure{at + ": generator " + std::to_string(j) + " lies outside the triangle's plane"};
    for (int k = 0; k < 3; ++k)
      if (!edges.emplace(std::make_pair(T[k], T[(k + 1) % 3]), t).second)
        throw Failure{at + ": the edge " + std::to_string(T[k]) + "->" + std::to_string(T[(k + 1) % 3]) + " is used twice"};
    const Q d = off * off / dot(n, n);
    if (t == 0 || d < best) best = d;
    nearest = nearest || T == q.nearest;
  }
  for (const auto& [e, t] : edges)
    if (!edges.count({e.second, e.first}))
      throw Failure{"boundary[" + std::to_string(t) + "]: the edge " + std::to_string(e.first) + "->" +
                    std::to_string(e.second) + " has no reverse: the surface is not closed"};
  if (!nearest) throw Failure{"nearest: not a triangle of boundary"};
  const V3 n = cross(minus(P[q.nearest[1]].g, P[q.nearest[0]].g), minus(P[q.nearest[2]].g, P[q.nearest[0]].g));
  const Q off = dot(n, P[q.nearest[0]].g);
  if (off * off / dot(n, n) != best) throw Failure{"nearest: not a triangle nearest the origin"};
  return best;
}

// L∞, ε > 0 (rule 5): h(d) = Σ_contacts max(0, d·g) over every candidate normal d — each contact's triangle normal
// and the cross products of two contacts' edge directions, both signs — is positive; ε̃² is the least h(d)²/|d|²,
// attained by `normal`.
Q linf_epsilon_squared(const Quality_part& q, const std::vector<Point>& P, std::size_t contacts) {
  std::vector<std::vector<V3>> points(contacts), edges(contacts);
  for (const Point& p : P) points[p.contact].push_back(p.g), edges[p.contact].push_back(p.g);
  std::vector<V3> normals;
  for (std::size_t i = 0; i < contacts; ++i)
    if (points[i].size() == 2) {
      edges[i].push_back(minus(points[i][0], points[i][1]));
      normals.push_back(cross(points[i][0], points[i][1]));
    }
  for (std::size_t i = 0; i < contacts; ++i)
    for (std::size_t j = i + 1; j < contacts; ++j)
      for (const V3& e : edges[i])
        for (const V3& f : edges[j]) normals.push_back(cross(e, f));
  const auto support = [&](const V3& d) {
    Q h = 0;
    for (const auto& g : points) {
      Q m = 0;
      for (const V3& x : g) m = std::max(m, Q(dot(d, x)));
      h += m;
    }
    return h;
  };
  bool any = false;
  Q best;
  for (V3& d : normals) {
    if (zero(d)) continue;
    for (int sign = 0; sign < 2; ++sign) {
      if (sign) d = {-d[0], -d[1], -d[2]};
      const Q h = support(d);
      if (sgn(h) <= 0) throw Failure{"the normal " + show3(d) + " has support 0: the origin is on the boundary"};
      const Q v = h * h / dot(d, d);
      if (!any || v < best) best = v, any = true;
    }
  }
  if (!any) throw Failure{"the wrench space has no facet (it is flat)"};
  const V3 n = {q.normal[0], q.normal[1], q.normal[2]};
  if (zero(n)) throw Failure{"normal: the zero vector"};
  const Q h = support(n);
  if (h * h / dot(n, n) != best) throw Failure{"normal: not the normal of a facet nearest the origin"};
  return best;
}

}  // namespace

// §3.4, theory [QL-1].
void check_quality(const Certificate& c, const Scene& scene, const Limits& lim) {
  const auto need = [&c](const char* key) {
    if (!c.keys.count(key)) throw Failure{std::string("missing required key \"") + key + "\""};
  };
  const auto ban = [&c](const char* key, const char* when) {
    if (c.keys.count(key)) throw Failure{std::string("key \"") + key + "\" is not allowed " + when};
  };
  for (const char* key : {"norm", "normalize", "torque_scale", "about", "epsilon"}) need(key);
  for (const char* key : {"holds", "combination", "independent", "load", "motion"}) ban(key, "for property \"quality\"");
  const Quality_part& q = *c.quality_members;
  if (sgn(q.torque_scale) <= 0) throw Failure{"torque_scale: " + show(q.torque_scale) + " is not positive"};
  if (sgn(q.lower) < 0 || q.lower > q.upper)
    throw Failure{"epsilon: [" + show(q.lower) + ", " + show(q.upper) + "] is not a bracket of a number >= 0"};
  if (sgn(q.upper) == 0) {  // ε = 0: the grasp is not in force closure (§3.2 with the friction reading)
    for (const char* key : {"scales", "boundary", "nearest", "normal"}) ban(key, "when epsilon is 0");
    need("twist");
    if (q.has_squared && sgn(q.squared) != 0) throw Failure{"epsilon.squared: " + show(q.squared) + " for epsilon 0"};
    fast_then_exact(lim, [&](auto zero) {
      using N = decltype(zero);
      const Int_wrench<N> t = nonzero_twist<N>(c);
      allowed_by_every_contact(t, scene.contacts, Reading::friction, lim, "");
      check_reading(c, t);
    });
    return;
  }
  ban("twist", "when epsilon is positive"), ban("reading", "when epsilon is positive");
  need("scales");
  const bool l1 = q.norm == "L1";
  if (q.has_radius) {  // rule 7: the torque scale 1/√r2 within its error
    need("torque_scale_error");
    const Q &s = q.torque_scale, &eta = q.torque_error, &r2 = q.radius_squared;
    if (sgn(r2) <= 0 || sgn(eta) < 0) throw Failure{"torque_radius_squared and torque_scale_error: expected r2 > 0, error >= 0"};
    const Q low = s - eta, high = s + eta;
    if (sgn(eta) == 0 ? s * s * r2 != 1 : (sgn(low) < 0 || low * low * r2 > 1 || high * high * r2 < 1))
      throw Failure{"torque_scale: 1/sqrt(" + show(r2) + ") is not within " + show(eta) + " of " + show(s)};
  } else if (c.keys.count("torque_scale_error")) {
    throw Failure{"key \"torque_scale_error\" is not allowed without \"torque_radius_squared\""};
  }
  if (l1) need("boundary"), need("nearest"), ban("normal", "for norm \"L1\"");
  else need("normal"), ban("boundary", "for norm \"Linf\""), ban("nearest", "for norm \"Linf\"");
  const std::vector<Point> P = scaled_points(q, scene.contacts, lim);
  const Q e2 = l1 ? l1_epsilon_squared(q, P) : linf_epsilon_squared(q, P, scene.contacts.size());
  // The bracket (rule 6): ε̃ = √e2 of the rational wrench space, within δ of ε (δ: the largest displacement of a
  // generator for L1, their sum over the contacts for L∞).
  bool exact = !q.has_radius || sgn(q.torque_error) == 0;
  Q delta = 0;
  for (const Quality_part::Scale& s : q.scales) {
    exact = exact && sgn(s.error) == 0;
    const Q d = s.error * s.bound + (q.has_radius ? Q(s.scale * s.moment_bound * q.torque_error) : Q(0));
    delta = l1 ? std::max(delta, d) : Q(delta + d);
  }
  if (exact != q.has_squared)
    throw Failure{exact ? "epsilon: missing \"squared\" (every scale is exact, so epsilon squared is rational)"
                        : "epsilon.squared: not allowed with an inexact scale"};
  if (exact && q.squared != e2) throw Failure{"epsilon.squared: " + show(q.squared) + " is not " + show(e2)};
  const Q low = q.lower + delta, high = q.upper - delta;
  if (low * low > e2) throw Failure{"epsilon.lower: " + show(q.lower) + " is above sqrt(" + show(e2) + ") - " + show(delta)};
  if (sgn(high) < 0 || high * high < e2)
    throw Failure{"epsilon.upper: " + show(q.upper) + " is below sqrt(" + show(e2) + ") + " + show(delta)};
}

}  // namespace wrenchkit_checker::detail
