// [QL-1 §8] [FL-10] The float twin of ε (L1): see quality_twin.h and proofs/notes/QL-1-quality.md §8.
#include "float/quality_twin.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace wrenchkit::fl {

namespace {

struct B3 {
  Bounded x, y, z;
};

struct Face {
  int a, b, c;
  double nx, ny, nz, off;  // the plane n · p = off in doubles, n = (b − a) × (c − a) (outward)
};

Face face(const std::vector<std::array<double, 3>>& P, int a, int b, int c) {
  const auto& A = P[a];
  const double ux = P[b][0] - A[0], uy = P[b][1] - A[1], uz = P[b][2] - A[2];
  const double vx = P[c][0] - A[0], vy = P[c][1] - A[1], vz = P[c][2] - A[2];
  Face f{a, b, c, uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx, 0};
  f.off = f.nx * A[0] + f.ny * A[1] + f.nz * A[2];
  return f;
}

double height(const Face& f, const std::array<double, 3>& p) { return f.nx * p[0] + f.ny * p[1] + f.nz * p[2] - f.off; }

// The convex hull's triangles in doubles (incremental; a proposal only, certified by the caller). Empty when the
// points look flat (no tetrahedron well above rounding) or the construction goes astray.
void hull(const std::vector<std::array<double, 3>>& P, std::vector<Face>& F) {
  F.clear();
  const int n = static_cast<int>(P.size());
  if (n < 4) return;
  double scale = 0;
  for (const auto& p : P) scale = std::max({scale, std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])});
  if (!(scale > 0) || !std::isfinite(scale)) return;
  const double tol = 1e-12 * scale;  // "above a plane" for the proposal (distances scale with |n|: below)
  const auto d2 = [&](int i, int j) {
    const double x = P[i][0] - P[j][0], y = P[i][1] - P[j][1], z = P[i][2] - P[j][2];
    return x * x + y * y + z * z;
  };
  int i0 = 0;
  for (int i = 1; i < n; ++i)
    if (P[i][0] < P[i0][0]) i0 = i;
  int i1 = i0;
  for (int i = 0; i < n; ++i)
    if (d2(i, i0) > d2(i1, i0)) i1 = i;
  int i2 = -1;
  double best = 0;
  for (int i = 0; i < n; ++i) {  // farthest from the line i0 i1: the largest |(p − p0) × (p1 − p0)|
    const double ux = P[i1][0] - P[i0][0], uy = P[i1][1] - P[i0][1], uz = P[i1][2] - P[i0][2];
    const double vx = P[i][0] - P[i0][0], vy = P[i][1] - P[i0][1], vz = P[i][2] - P[i0][2];
    const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    const double a = cx * cx + cy * cy + cz * cz;
    if (a > best) best = a, i2 = i;
  }
  if (i2 < 0 || !(std::sqrt(best) > tol * scale)) return;
  Face base = face(P, i0, i1, i2);
  const double nlen = std::sqrt(base.nx * base.nx + base.ny * base.ny + base.nz * base.nz);
  int i3 = -1;
  best = 0;
  for (int i = 0; i < n; ++i)
    if (std::fabs(height(base, P[i])) > best) best = std::fabs(height(base, P[i])), i3 = i;
  if (i3 < 0 || !(best > tol * nlen)) return;
  if (height(base, P[i3]) > 0) std::swap(i1, i2);  // the fourth point below the base: the base faces outward
  F.assign({face(P, i0, i1, i2), face(P, i0, i3, i1), face(P, i1, i3, i2), face(P, i2, i3, i0)});
  thread_local std::vector<std::pair<int, int>> edges;
  thread_local std::vector<Face> kept;
  for (int p = 0; p < n; ++p) {
    if (p == i0 || p == i1 || p == i2 || p == i3) continue;
    edges.clear();
    kept.clear();
    for (const Face& f : F) {
      const double len = std::sqrt(f.nx * f.nx + f.ny * f.ny + f.nz * f.nz);
      if (height(f, P[p]) > tol * len) {
        edges.push_back({f.a, f.b}), edges.push_back({f.b, f.c}), edges.push_back({f.c, f.a});
      } else {
        kept.push_back(f);
      }
    }
    if (edges.empty()) continue;  // inside (or on) the hull so far
    for (const auto& [u, v] : edges)  // the horizon: visible edges whose reverse is not visible
      if (std::find(edges.begin(), edges.end(), std::make_pair(v, u)) == edges.end()) kept.push_back(face(P, u, v, p));
    F.swap(kept);
    if (F.size() > 4 * static_cast<std::size_t>(n)) return F.clear();  // astray
  }
}

}  // namespace

Quality_twin_answer epsilon_twin(const std::vector<Quality_twin_contact>& contacts, Twin_normalization normalization,
                                 const Bounded& s, const Bounded& ax, const Bounded& ay) {
  Quality_twin_answer out;
  if (contacts.empty() || contacts.size() > 64) return out;
  // the generators: each contact's cone edges as scaled wrenches about (ax, ay)
  thread_local std::vector<B3> W;
  thread_local std::vector<std::array<double, 3>> P, X;  // P: the values; X: each coordinate's bound
  thread_local std::vector<Face> F;
  thread_local std::vector<unsigned char> edge;  // edge[u·m + v]: the directed edge u → v seen
  W.clear();
  for (const Quality_twin_contact& k : contacts) {
    const Bounded tx = -k.ny, ty = k.nx;
    const bool frictionless = k.mu.v == 0 && k.mu.e == 0;
    for (int side = frictionless ? 0 : -1; side <= (frictionless ? 0 : 1); side += 2) {
      const Bounded m = side < 0 ? -k.mu : k.mu;
      Bounded ex = k.nx + m * tx, ey = k.ny + m * ty;
      if (frictionless) ex = k.nx, ey = k.ny;
      Bounded c = Bounded::exact(1);
      if (normalization == Twin_normalization::unit_normal) c = Bounded::exact(1) / sqrt(k.nx * k.nx + k.ny * k.ny);
      else if (normalization == Twin_normalization::unit_force) c = Bounded::exact(1) / sqrt(ex * ex + ey * ey);
      const Bounded fx = c * ex, fy = c * ey;
      W.push_back({fx, fy, s * ((k.px - ax) * fy - (k.py - ay) * fx)});
    }
  }
  const int m = static_cast<int>(W.size());
  P.resize(W.size());
  X.resize(W.size());
  for (int i = 0; i < m; ++i) {
    const B3& w = W[static_cast<std::size_t>(i)];
    if (!(w.x.e < Bounded::kInf) || !(w.y.e < Bounded::kInf) || !(w.z.e < Bounded::kInf)) return out;
    P[static_cast<std::size_t>(i)] = {w.x.v, w.y.v, w.z.v};
    X[static_cast<std::size_t>(i)] = {w.x.e, w.y.e, w.z.e};
  }
  hull(P, F);
  if (F.empty()) return out;
  // (1) a closed oriented surface: every directed edge once, and its reverse once
  edge.assign(static_cast<std::size_t>(m) * static_cast<std::size_t>(m), 0);
  const auto at = [&](int u, int v) -> unsigned char& { return edge[static_cast<std::size_t>(u * m + v)]; };
  for (const Face& f : F)
    for (const auto& [u, v] : {std::make_pair(f.a, f.b), std::make_pair(f.b, f.c), std::make_pair(f.c, f.a)})
      if (at(u, v)++) return out;
  for (const Face& f : F)
    for (const auto& [u, v] : {std::make_pair(f.a, f.b), std::make_pair(f.b, f.c), std::make_pair(f.c, f.a)})
      if (!at(v, u)) return out;
  // (2) every triangle's normal certified nonzero, every wrench certified strictly below its plane (or a corner of
  // it) — by a static bound on the doubles' dot product (QL-1 §8) —; (3) the origin's side of each plane, and its
  // distance
  constexpr double u = 0x1p-53, kUp = 1 + 0x1p-40;
  bool closed = true, uncertain = false;
  double lo = Bounded::kInf, hi = Bounded::kInf;
  for (const Face& f : F) {
    const B3 &A = W[static_cast<std::size_t>(f.a)], &Bp = W[static_cast<std::size_t>(f.b)], &C = W[static_cast<std::size_t>(f.c)];
    const Bounded ux = Bp.x - A.x, uy = Bp.y - A.y, uz = Bp.z - A.z, vx = C.x - A.x, vy = C.y - A.y, vz = C.z - A.z;
    const Bounded nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const Bounded len2 = nx * nx + ny * ny + nz * nz;
    if (len2.sign() != Sign::positive) return out;
    const double n[3] = {nx.v, ny.v, nz.v}, nu[3] = {nx.e, ny.e, nz.e};
    const double a[3] = {A.x.v, A.y.v, A.z.v}, ae[3] = {A.x.e, A.y.e, A.z.e};
    for (int i = 0; i < m; ++i) {
      if (i == f.a || i == f.b || i == f.c) continue;
      const auto& x = P[static_cast<std::size_t>(i)];
      const auto& xe = X[static_cast<std::size_t>(i)];
      const double d0 = x[0] - a[0], d1 = x[1] - a[1], d2 = x[2] - a[2];
      const double h = n[0] * d0 + n[1] * d1 + n[2] * d2;
      // |h_exact − h| ≤ 4u Σ|n_k d_k| + Σ |n_k| (ξ_k + α_k) + Σ ν_k (|d_k| (1 + 2u) + ξ_k + α_k), inflated
      const double ad0 = std::fabs(d0), ad1 = std::fabs(d1), ad2 = std::fabs(d2);
      const double e0 = xe[0] + ae[0], e1 = xe[1] + ae[1], e2 = xe[2] + ae[2];
      const double err = (4 * u * (std::fabs(n[0]) * ad0 + std::fabs(n[1]) * ad1 + std::fabs(n[2]) * ad2) +
                          std::fabs(n[0]) * e0 + std::fabs(n[1]) * e1 + std::fabs(n[2]) * e2 +
                          nu[0] * (ad0 * (1 + 2 * u) + e0) + nu[1] * (ad1 * (1 + 2 * u) + e1) +
                          nu[2] * (ad2 * (1 + 2 * u) + e2)) * kUp + 0x1p-1000;
      if (!(h < -err)) return out;  // on the plane, above it, not certain, or not finite: the exact engine decides
    }
    const Bounded h0 = nx * A.x + ny * A.y + nz * A.z;  // n · a = −(n · (0 − a)): > 0 iff the origin is strictly below
    const Sign s0 = h0.sign();
    if (s0 == Sign::uncertain) {
      uncertain = true;
      continue;
    }
    if (s0 != Sign::positive) {  // the origin on or above a facet's plane: outside the interior, not closed
      closed = false;
      continue;
    }
    const Bounded d = h0 / sqrt(len2);
    if (!(d.e < Bounded::kInf)) {
      uncertain = true;
      continue;
    }
    lo = std::min(lo, std::max(0.0, lower(d)));
    hi = std::min(hi, upper(d));
  }
  if (!closed) {  // certain whatever the uncertain planes: one certified supporting plane has the origin outside
    out.certain = true;
    return out;
  }
  if (uncertain) return out;
  out.certain = true;
  out.closed = true;
  out.lower = lo, out.upper = hi;
  return out;
}

}  // namespace wrenchkit::fl
