// [GR-1] Two-finger force-closure regions: see grasp_regions.h and proofs/notes/GR-1-two-finger-regions.md.
#include "exact/statics/grasp_regions.h"

#include <algorithm>
#include <climits>
#include <cmath>
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

namespace {

// per edge: its first vertex, its vector, and its cone's edges R = n − μ·rot90 n, L = n + μ·rot90 n
struct Edge_cone {
  Vec2 a, d, R, L;
};

// The checks every question on the outline's edges makes, the edges asked (increasing) and each edge's cone.
std::vector<Edge_cone> prepare(const Scene& scene, const Rational& mu, const std::vector<std::size_t>& only, Grasp_regions& g,
                          std::vector<std::size_t>& edges) {
  const std::vector<Vec2>& V = scene.body.outline;
  if (V.empty()) throw Input_error("body.outline: missing (grasp regions are places on the outline's edges: give the part's polygon)");
  for (const std::string& w : scene.warnings)  // (--lenient: contacts off the outline are only warnings; unused here)
    if (w.rfind("body.outline", 0) == 0) throw Input_error(w + " (grasp regions need a valid outline; drop --lenient)");
  if (mu < 0) throw Input_error("--mu: " + to_string(mu) + " is negative");
  const std::size_t n = V.size();
  if (n > kGraspRegionsMaxEdges)
    throw Input_error("body.outline: " + std::to_string(n) + " edges, more than " + std::to_string(kGraspRegionsMaxEdges) +
                      " (the edge pairs grow as their square); ask for some with --edges");
  edges = only;
  if (edges.empty())
    for (std::size_t k = 0; k < n; ++k) edges.push_back(k);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const std::size_t e : edges)
    if (e >= n)
      throw Input_error("--edges: " + std::to_string(e) + " is not an edge of body.outline (0 to " + std::to_string(n - 1) + ")");
  if (!only.empty()) g.asked = edges;
  g.mu = mu;
  g.edges = n;
  g.ccw = scene.body.outline_ccw;
  g.convex = scene.body.outline_convex;
  const int orientation = outline_orientation(V);
  std::vector<Edge_cone> E(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 nn = edge_inward_normal(V, k, orientation), t{-nn.y, nn.x};
    E[k] = {V[k], {V[(k + 1) % n].x - V[k].x, V[(k + 1) % n].y - V[k].y}, {nn.x - mu * t.x, nn.y - mu * t.y},
            {nn.x + mu * t.x, nn.y + mu * t.y}};
  }
  return E;
}

}  // namespace

Grasp_regions two_finger_regions(const Scene& scene, const Rational& mu, const std::vector<std::size_t>& only) {
  Grasp_regions g;
  std::vector<std::size_t> edges;
  const std::vector<Edge_cone> E = prepare(scene, mu, only, g, edges);
  const std::vector<Corner> square{{Rational(0), Rational(0)}, {Rational(1), Rational(0)}, {Rational(1), Rational(1)},
                                   {Rational(0), Rational(1)}};
  for (std::size_t x = 0; x < edges.size(); ++x)
    for (std::size_t y = x + 1; y < edges.size(); ++y) {
      Pair_region r;
      r.i = std::min(edges[x], edges[y]), r.j = std::max(edges[x], edges[y]);
      if (r.i == r.j) continue;
      const Edge_cone &ei = E[r.i], &ej = E[r.j];
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

// ---- [GR-2] three fingers -------------------------------------------------------------------------------------------

namespace wrenchkit {

std::string wrench_label(int w) { return std::string(w % 2 == 0 ? "R" : "L") + std::to_string(w / 2); }

std::size_t Grasp_regions::boxed_triples() const {
  std::size_t n = 0;
  for (const Triple_region& t : triples) n += t.box.has_value();
  return n;
}

std::size_t Grasp_regions::never_triples() const {
  std::size_t n = 0;
  for (const Triple_region& t : triples) n += t.never;
  return n;
}

namespace {

// The four-subsets of the six wrenches (increasing), the complements of the fifteen pairs.
const std::array<std::array<int, 4>, 15>& four_subsets() {
  static const std::array<std::array<int, 4>, 15> Q = [] {
    std::array<std::array<int, 4>, 15> out{};
    std::size_t at = 0;
    for (int x = 0; x < 6; ++x)
      for (int y = x + 1; y < 6; ++y) {
        std::size_t k = 0;
        for (int w = 0; w < 6; ++w)
          if (w != x && w != y) out[at][k++] = w;
        ++at;
      }
    return out;
  }();
  return Q;
}

// A wrench of the triple, affine in its finger's parameter s: (fx, fy, m0 + s·m1), the moment about the origin.
struct Wrench_q {
  Rational fx, fy, m0, m1;
};
struct Wrench_d {
  double fx, fy, m0, m1;
};

template <class T>
T det3(const T (&a)[3], const T (&b)[3], const T (&c)[3]) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - b[0] * (a[1] * c[2] - a[2] * c[1]) + c[0] * (a[1] * b[2] - a[2] * b[1]);
}

// The four signed cofactors (−1)^m det(w without w_m) of the subset q at the placement p (one parameter per finger).
template <class T, class W>
std::array<T, 4> cofactors(const W (&w)[6], const std::array<int, 4>& q, const T (&p)[3]) {
  T v[4][3];
  for (int k = 0; k < 4; ++k) {
    const W& x = w[q[k]];
    v[k][0] = x.fx, v[k][1] = x.fy, v[k][2] = x.m0 + p[q[k] / 2] * x.m1;
  }
  return {det3(v[1], v[2], v[3]), T(-det3(v[0], v[2], v[3])), det3(v[0], v[1], v[3]), T(-det3(v[0], v[1], v[2]))};
}

// Every corner of the cube of half-side h about c (inside the unit cube) has the subset's four cofactors of one strict
// sign, beyond `tol` (doubles: a proposal only).
bool valid_d(const Wrench_d (&w)[6], const std::array<int, 4>& q, const double (&c)[3], double h, double tol) {
  int sign = 0;
  for (int corner = 0; corner < (h > 0 ? 8 : 1); ++corner) {
    const double p[3] = {c[0] + (corner & 1 ? h : -h), c[1] + (corner & 2 ? h : -h), c[2] + (corner & 4 ? h : -h)};
    for (const double v : cofactors(w, q, p)) {
      const int sv = v > tol ? 1 : v < -tol ? -1 : 0;
      if (sv == 0 || (sign != 0 && sv != sign)) return false;
      sign = sv;
    }
  }
  return true;
}

// The exact check (what the checker also does): the 32 cofactors at the box's corners, one strict sign.
bool valid_q(const Wrench_q (&w)[6], const std::array<int, 4>& q, const std::array<std::array<Rational, 2>, 3>& box) {
  int sign = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Rational p[3] = {box[0][corner & 1 ? 1 : 0], box[1][corner & 2 ? 1 : 0], box[2][corner & 4 ? 1 : 0]};
    for (const Rational& v : cofactors(w, q, p)) {
      const int sv = sgn(v);
      if (sv == 0 || (sign != 0 && sv != sign)) return false;
      sign = sv;
    }
  }
  return true;
}

// The doubles' proposals in a scaled frame: the force rows and the moment row of the wrenches each divided by a power of
// two (2^-ef, 2^-em) so that their largest entry is near 1 — every 3×3 determinant scales by 2^-(2ef+em) > 0, so its
// sign, and a cube's validity, are the same — whatever the part's size (10^±3000 coordinates overflow a double).
long exponent_of(const Rational& q) {
  if (sgn(q) == 0) return LONG_MIN;
  long en = 0, ed = 0;
  mpz_get_d_2exp(&en, q.get_num_mpz_t());
  mpz_get_d_2exp(&ed, q.get_den_mpz_t());
  return en - ed;
}
double scaled(const Rational& q, long e) {  // q · 2^-e as a double (≈; a proposal only)
  if (sgn(q) == 0) return 0;
  long en = 0, ed = 0;
  const double dn = mpz_get_d_2exp(&en, q.get_num_mpz_t()), dd = mpz_get_d_2exp(&ed, q.get_den_mpz_t());
  return std::ldexp(dn / dd, static_cast<int>(std::max(-2000L, std::min(2000L, en - ed - e))));
}

// A direction u of the wrench space with u · w ≤ 0 for the twelve wrenches at the edges' ends, or none: proposed by
// the doubles among ±(w_x × w_y) (a facet's normal of their cone, when it is not everything), checked exactly.
std::optional<std::array<Rational, 3>> never_direction(const Wrench_q (&w)[6]) {
  Rational W[12][3];
  double D[12][3];
  for (int k = 0; k < 12; ++k) {
    const Wrench_q& x = w[k / 2];
    W[k][0] = x.fx, W[k][1] = x.fy, W[k][2] = k % 2 ? Rational(x.m0 + x.m1) : x.m0;
  }
  long ef = LONG_MIN, em = LONG_MIN;  // (the scaled frame: u's sign pattern on the wrenches is the same)
  for (const auto& w : W) ef = std::max({ef, exponent_of(w[0]), exponent_of(w[1])}), em = std::max(em, exponent_of(w[2]));
  if (ef == LONG_MIN) ef = 0;
  if (em == LONG_MIN) em = 0;
  for (int k = 0; k < 12; ++k) D[k][0] = scaled(W[k][0], ef), D[k][1] = scaled(W[k][1], ef), D[k][2] = scaled(W[k][2], em);
  double scale = 0;
  for (const auto& d : D)
    for (const double x : d) scale = std::max(scale, std::abs(x));
  for (int x = 0; x < 12; ++x)
    for (int y = x + 1; y < 12; ++y) {
      const double u[3] = {D[x][1] * D[y][2] - D[x][2] * D[y][1], D[x][2] * D[y][0] - D[x][0] * D[y][2],
                           D[x][0] * D[y][1] - D[x][1] * D[y][0]};
      const double un = std::abs(u[0]) + std::abs(u[1]) + std::abs(u[2]);
      if (!(un > 0)) continue;
      for (const double sign : {1.0, -1.0}) {
        bool below = true;
        for (int k = 0; k < 12 && below; ++k) below = sign * (u[0] * D[k][0] + u[1] * D[k][1] + u[2] * D[k][2]) <= 1e-9 * un * scale;
        if (!below) continue;
        std::array<Rational, 3> q{W[x][1] * W[y][2] - W[x][2] * W[y][1], W[x][2] * W[y][0] - W[x][0] * W[y][2],
                                  W[x][0] * W[y][1] - W[x][1] * W[y][0]};
        if (sign < 0)
          for (Rational& v : q) v = -v;
        if (sgn(q[0]) == 0 && sgn(q[1]) == 0 && sgn(q[2]) == 0) continue;
        bool exact = true;
        for (int k = 0; k < 12 && exact; ++k) exact = sgn(Rational(q[0] * W[k][0] + q[1] * W[k][1] + q[2] * W[k][2])) <= 0;
        if (exact) {  // as the primitive integer vector along it (small integers to read)
          const std::array<Integer, 3> z = primitive(q);
          return std::array<Rational, 3>{Rational(z[0]), Rational(z[1]), Rational(z[2])};
        }
      }
    }
  return std::nullopt;
}

// A dyadic rational near x (2^-24 steps): short certificates, exact.
Rational dyadic(double x, bool down) {
  const double k = down ? std::floor(x * 16777216.0) : std::nearbyint(x * 16777216.0);
  Rational q(static_cast<long>(k), 16777216L);
  q.canonicalize();
  return q;
}

// The search for the triple's largest cube (GR-2 §3): centres on a 4×4×4 grid and at the pairs' own boxes (the third
// finger at 1/2), each with every four-subset valid there and its largest half-side by bisection, then a local search
// moving the best centre by halving steps; doubles propose, and the best is rounded to dyadic rationals, shrunk by
// 2⁻¹⁰ and checked exactly (halved up to four times when the rounding lost it).
void search_box(Triple_region& t, const Wrench_q (&wq)[6], const std::vector<std::array<double, 3>>& seeds) {
  Wrench_d w[6];
  long ef = LONG_MIN, em = LONG_MIN;  // the scaled frame (never_direction's)
  for (const Wrench_q& x : wq) {
    ef = std::max({ef, exponent_of(x.fx), exponent_of(x.fy)});
    em = std::max({em, exponent_of(x.m0), exponent_of(Rational(x.m0 + x.m1))});
  }
  if (ef == LONG_MIN) ef = 0;
  if (em == LONG_MIN) em = 0;
  double scale = 0;
  for (int k = 0; k < 6; ++k) {
    w[k] = {scaled(wq[k].fx, ef), scaled(wq[k].fy, ef), scaled(wq[k].m0, em), scaled(wq[k].m1, em)};
    scale = std::max({scale, std::abs(w[k].fx), std::abs(w[k].fy), std::abs(w[k].m0), std::abs(w[k].m0 + w[k].m1)});
  }
  const double tol = 1e-12 * scale * scale * scale;
  const auto& Q = four_subsets();
  double best_h = 0, best_c[3] = {0.5, 0.5, 0.5};
  int best_q = -1;
  const auto try_centre = [&](const double (&c)[3]) {
    double hmax = 1;
    for (const double x : c) hmax = std::min({hmax, x, 1 - x});
    if (!(hmax > best_h * (1 + 1e-9))) return false;
    bool improved = false;
    for (int q = 0; q < 15; ++q) {
      if (!valid_d(w, Q[q], c, 0, tol)) continue;
      double h;
      if (valid_d(w, Q[q], c, hmax, tol)) {
        h = hmax;
      } else {
        double lo = best_h, hi = hmax;
        if (lo > 0 && !valid_d(w, Q[q], c, lo, tol)) continue;
        for (int it = 0; it < 22; ++it) {
          const double mid = (lo + hi) / 2;
          (valid_d(w, Q[q], c, mid, tol) ? lo : hi) = mid;
        }
        h = lo;
      }
      if (h > best_h * (1 + 1e-9)) {
        best_h = h, best_q = q, improved = true;
        std::copy(c, c + 3, best_c);
      }
    }
    return improved;
  };
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int e = 0; e < 4; ++e) {
        const double c[3] = {(2 * a + 1) / 8.0, (2 * b + 1) / 8.0, (2 * e + 1) / 8.0};
        try_centre(c);
      }
  for (const auto& s : seeds) {
    const double c[3] = {s[0], s[1], s[2]};
    try_centre(c);
  }
  if (best_q < 0) return;
  int moves = 0;
  for (double step = 1.0 / 16; step >= 1.0 / 1024 && moves < 200;) {
    bool improved = false;
    for (int axis = 0; axis < 3 && !improved; ++axis)
      for (const double dir : {1.0, -1.0}) {
        double c[3] = {best_c[0], best_c[1], best_c[2]};
        c[axis] += dir * step;
        ++moves;
        if (try_centre(c)) {
          improved = true;
          break;
        }
      }
    if (!improved) step /= 2;
  }
  // exact: the centre and the half-side as dyadic rationals, inside the unit cube, checked
  Rational c[3], h = dyadic(best_h * (1023.0 / 1024.0), true);
  for (int k = 0; k < 3; ++k) {
    c[k] = dyadic(best_c[k], false);
    h = std::min({h, c[k], Rational(1 - c[k])});
  }
  for (int attempt = 0; attempt < 5 && sgn(h) > 0; ++attempt, h /= 2) {
    std::array<std::array<Rational, 2>, 3> box;
    for (int k = 0; k < 3; ++k) box[k] = {c[k] - h, c[k] + h};
    for (int q = 0; q < 15; ++q) {
      const int tried = (best_q + q) % 15;  // the proposal's subset first
      if (!valid_q(wq, Q[tried], box)) continue;
      t.box = box;
      t.wrenches = Q[tried];
      t.side = 2 * h;
      return;
    }
  }
}

}  // namespace

Grasp_regions three_finger_regions(const Scene& scene, const Rational& mu, const std::vector<std::size_t>& only) {
  Grasp_regions g;
  g.fingers = 3;
  std::vector<std::size_t> edges;
  const std::vector<Edge_cone> E = prepare(scene, mu, only, g, edges);
  const std::size_t m = edges.size();
  if (m >= 3 && m * (m - 1) * (m - 2) / 6 > kGraspRegionsMaxTriples)
    throw Input_error("body.outline: " + std::to_string(m) + " edges make " + std::to_string(m * (m - 1) * (m - 2) / 6) +
                      " triples for three fingers, more than " + std::to_string(kGraspRegionsMaxTriples) +
                      "; ask for some edges with --edges");
  // the pairs' own independent squares seed the search (a closed pair closes whatever the third finger does)
  std::vector<std::array<double, 4>> pair_box;  // per pair index: centre (s, t) and whether there is one
  const Grasp_regions pairs = two_finger_regions(scene, mu, only);
  const auto pair_at = [&](std::size_t x, std::size_t y) -> const Pair_region& {  // x < y indices into edges
    return pairs.pairs[x * m - x * (x + 1) / 2 + (y - x - 1)];
  };
  for (std::size_t x = 0; x < m; ++x)
    for (std::size_t y = x + 1; y < m; ++y)
      for (std::size_t z = y + 1; z < m; ++z) {
        Triple_region t;
        t.edges = {edges[x], edges[y], edges[z]};
        Wrench_q w[6];
        for (int f = 0; f < 3; ++f) {
          const Edge_cone& e = E[t.edges[f]];
          for (int side = 0; side < 2; ++side) {
            const Vec2& F = side == 0 ? e.R : e.L;
            w[2 * f + side] = {F.x, F.y, cross(e.a, F), cross(e.d, F)};
          }
        }
        if (sgn(mu) == 0) {
          t.never = true;
        } else if ((t.never_direction = never_direction(w))) {
          t.never = true;
        } else {
          std::vector<std::array<double, 3>> seeds;
          const std::size_t idx[3] = {x, y, z};
          for (int a = 0; a < 3; ++a)
            for (int b = a + 1; b < 3; ++b) {
              const Pair_region& p = pair_at(idx[a], idx[b]);
              if (!p.box) continue;
              std::array<double, 3> c{0.5, 0.5, 0.5};
              c[a] = Rational((*p.box)[0][0] + (*p.box)[0][1]).get_d() / 2;
              c[b] = Rational((*p.box)[1][0] + (*p.box)[1][1]).get_d() / 2;
              seeds.push_back(c);
            }
          search_box(t, w, seeds);
        }
        g.triples.push_back(std::move(t));
      }
  return g;
}

}  // namespace wrenchkit
