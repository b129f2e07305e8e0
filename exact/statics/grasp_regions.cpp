// [GR-1] Two-finger force-closure regions: see grasp_regions.h and proofs/notes/GR-1-two-finger-regions.md.
#include "exact/statics/grasp_regions.h"

#include <algorithm>
#include <string>

#include "exact/io/input_error.h"
#include "exact/io/outline.h"

namespace wrenchkit {

namespace {

using Corner = std::array<Rational, 2>;

Rational value(const Region_constraint& h, const Corner& p) { return h.a * p[0] + h.b * p[1] + h.c; }

// The polygon cut by the closed half-plane value ≥ 0 (Sutherland–Hodgman, exact).
std::vector<Corner> clip(const std::vector<Corner>& P, const Region_constraint& h) {
  std::vector<Corner> out;
  for (std::size_t k = 0; k < P.size(); ++k) {
    const Corner &a = P[k], &b = P[(k + 1) % P.size()];
    const Rational va = value(h, a), vb = value(h, b);
    if (sgn(va) >= 0) out.push_back(a);
    if ((sgn(va) > 0 && sgn(vb) < 0) || (sgn(va) < 0 && sgn(vb) > 0)) {
      const Rational r = va / (va - vb);  // the crossing a + r (b − a), 0 < r < 1
      out.push_back({a[0] + r * (b[0] - a[0]), a[1] + r * (b[1] - a[1])});
    }
  }
  return out;
}

// Repeated and collinear corners dropped: a strictly convex polygon, or nothing when its area is 0.
std::vector<Corner> strict(std::vector<Corner> P, Rational& area) {
  for (bool changed = true; changed && P.size() >= 3;) {
    changed = false;
    for (std::size_t k = 0; k < P.size() && P.size() >= 3; ++k) {
      const Corner &a = P[(k + P.size() - 1) % P.size()], &b = P[k], &c = P[(k + 1) % P.size()];
      if (sgn((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) == 0) {
        P.erase(P.begin() + static_cast<long>(k));
        changed = true;
        break;
      }
    }
  }
  area = 0;
  if (P.size() < 3) return {};
  for (std::size_t k = 0; k < P.size(); ++k) {
    const Corner &a = P[k], &b = P[(k + 1) % P.size()];
    area += a[0] * b[1] - a[1] * b[0];
  }
  area /= 2;
  if (sgn(area) <= 0) return {};
  return P;
}

// The largest axis-aligned square [s0, s0 + a] × [t0, t0 + a] in the closed region: maximise a subject to every
// corner satisfying every cone's closed half-plane (its worst corner: a_h s0 + b_h t0 + (min(a_h, 0) + min(b_h, 0)) a
// + c_h ≥ 0) and the unit square; the LP's optimum is at a vertex, an intersection of three constraint planes, so every
// triple is solved exactly (Cramer) and the feasible one with the largest a kept (ties: the least s0, then t0).
void independent(Pair_region& r) {
  struct Plane {
    Rational s, t, a, c;  // s·s0 + t·t0 + a·a + c ≥ 0
  };
  std::vector<Plane> P;
  for (const Region_constraint& h : r.cones)
    P.push_back({h.a, h.b, Rational(std::min(h.a, Rational(0)) + std::min(h.b, Rational(0))), h.c});
  P.push_back({1, 0, 0, 0}), P.push_back({0, 1, 0, 0});
  P.push_back({-1, 0, -1, 1}), P.push_back({0, -1, -1, 1});
  P.push_back({0, 0, 1, 0});  // a ≥ 0: last (below)
  std::optional<std::array<Rational, 3>> best;
  const auto det3 = [](const std::array<std::array<Rational, 3>, 3>& m) -> Rational {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  // (a ≥ 0, the last plane, is never tight at an optimum with a > 0: its triples are skipped; a vertex whose a is
  // below the best so far is dropped before its s0, t0 and its feasibility are computed)
  const std::size_t m = P.size() - 1;
  for (std::size_t x = 0; x < m; ++x)
    for (std::size_t y = x + 1; y < m; ++y)
      for (std::size_t z = y + 1; z < m; ++z) {
        const Plane* q[3] = {&P[x], &P[y], &P[z]};
        std::array<std::array<Rational, 3>, 3> mat;
        for (int k = 0; k < 3; ++k) mat[k] = {q[k]->s, q[k]->t, q[k]->a};
        const Rational d = det3(mat);
        if (d == 0) continue;
        const auto solve = [&](int col) {
          auto mc = mat;
          for (int k = 0; k < 3; ++k) mc[k][col] = -q[k]->c;
          return Rational(det3(mc) / d);
        };
        const Rational a = solve(2);
        if (sgn(a) <= 0 || (best && a < (*best)[2])) continue;
        const std::array<Rational, 3> v{solve(0), solve(1), a};
        bool feasible = true;
        for (const Plane& p : P) feasible = feasible && sgn(p.s * v[0] + p.t * v[1] + p.a * v[2] + p.c) >= 0;
        if (!feasible) continue;
        if (!best || v[2] > (*best)[2] || (v[2] == (*best)[2] && (v[0] < (*best)[0] || (v[0] == (*best)[0] && v[1] < (*best)[1]))))
          best = v;
      }
  if (!best || sgn((*best)[2]) <= 0) return;
  r.side = (*best)[2];
  const Rational a = r.side * Rational(1023, 1024), cs = (*best)[0] + r.side / 2, ct = (*best)[1] + r.side / 2;
  r.box = std::array<std::array<Rational, 2>, 2>{{{cs - a / 2, cs + a / 2}, {ct - a / 2, ct + a / 2}}};
}

}  // namespace

std::size_t Grasp_regions::closed_pairs() const {
  std::size_t n = 0;
  for (const Pair_region& p : pairs) n += !p.polygon.empty();
  return n;
}

bool closed_at(const Pair_region& r, const Rational& s, const Rational& t) {
  for (const Region_constraint& h : r.cones)
    if (sgn(value(h, {s, t})) <= 0) return false;
  return true;
}

Grasp_regions two_finger_regions(const Scene& scene, const Rational& mu, const std::vector<std::size_t>& only) {
  const std::vector<Vec2>& V = scene.body.outline;
  if (V.empty()) throw Input_error("body.outline: missing (grasp regions are places on the outline's edges: give the part's polygon)");
  if (!scene.warnings.empty()) throw Input_error("body.outline: " + scene.warnings.front() + " (grasp regions need a valid outline; drop --lenient)");
  if (mu < 0) throw Input_error("--mu: " + to_string(mu) + " is negative");
  const std::size_t n = V.size();
  if (n > kGraspRegionsMaxEdges)
    throw Input_error("body.outline: " + std::to_string(n) + " edges, more than " + std::to_string(kGraspRegionsMaxEdges) +
                      " (the edge pairs grow as their square); ask for some with --edges");
  std::vector<std::size_t> edges = only;
  if (edges.empty())
    for (std::size_t k = 0; k < n; ++k) edges.push_back(k);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const std::size_t e : edges)
    if (e >= n)
      throw Input_error("--edges: " + std::to_string(e) + " is not an edge of body.outline (0 to " + std::to_string(n - 1) + ")");
  Grasp_regions g;
  if (!only.empty()) g.asked = edges;
  g.mu = mu;
  g.edges = n;
  g.ccw = scene.body.outline_ccw;
  g.convex = scene.body.outline_convex;
  const int orientation = outline_orientation(V);
  // per edge: its first vertex, its vector, and its cone's edges R = n − μ·rot90 n, L = n + μ·rot90 n
  struct Edge {
    Vec2 a, d, R, L;
  };
  std::vector<Edge> E(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 nn = edge_inward_normal(V, k, orientation), t{-nn.y, nn.x};
    E[k] = {V[k], {V[(k + 1) % n].x - V[k].x, V[(k + 1) % n].y - V[k].y}, {nn.x - mu * t.x, nn.y - mu * t.y},
            {nn.x + mu * t.x, nn.y + mu * t.y}};
  }
  const std::vector<Corner> square{{Rational(0), Rational(0)}, {Rational(1), Rational(0)}, {Rational(1), Rational(1)},
                                   {Rational(0), Rational(1)}};
  for (std::size_t x = 0; x < edges.size(); ++x)
    for (std::size_t y = x + 1; y < edges.size(); ++y) {
      Pair_region r;
      r.i = std::min(edges[x], edges[y]), r.j = std::max(edges[x], edges[y]);
      if (r.i == r.j) continue;
      const Edge &ei = E[r.i], &ej = E[r.j];
      // v = p_j(t) − p_i(s) = (a_j − a_i) + t d_j − s d_i; finger i: cross(R_i, v) > 0, cross(v, L_i) > 0; finger j
      // with −v: cross(R_j, −v) > 0, cross(−v, L_j) > 0
      const Vec2 c0{ej.a.x - ei.a.x, ej.a.y - ei.a.y};
      const auto along = [&](const Vec2& e, int sign) {  // sign · cross(e, v) as a·s + b·t + c
        return Region_constraint{Rational(-sign * cross(e, ei.d)), Rational(sign * cross(e, ej.d)), Rational(sign * cross(e, c0))};
      };
      r.cones = {along(ei.R, 1), along(ei.L, -1), along(ej.R, -1), along(ej.L, 1)};
      bool possible = true;
      for (const Region_constraint& h : r.cones) possible = possible && !(h.a == 0 && h.b == 0 && sgn(h.c) <= 0);
      if (possible) {
        std::vector<Corner> P = square;
        for (const Region_constraint& h : r.cones)
          if (!P.empty()) P = clip(P, h);
        r.polygon = strict(std::move(P), r.area);
        if (!r.polygon.empty()) independent(r);
      }
      g.pairs.push_back(std::move(r));
    }
  return g;
}

}  // namespace wrenchkit
