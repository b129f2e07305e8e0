#include "float/pressure.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace wrenchkit::fl {

namespace {

Bounded ex(double x) { return Bounded::exact(x); }

struct P2 {
  Bounded x, y;
};

Sign orient(const P2& a, const P2& b, const P2& c) {
  return ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)).sign();
}
bool certain(Sign s) { return s != Sign::uncertain; }

// Do the closed segments ab and cd meet? Uncertain signs count as meeting (the polygon is then refused).
bool segments_meet(const P2& a, const P2& b, const P2& c, const P2& d) {
  const Sign o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (!certain(o1) || !certain(o2) || !certain(o3) || !certain(o4)) return true;
  if (o1 != o2 && o3 != o4 && o1 != Sign::zero && o2 != Sign::zero && o3 != Sign::zero && o4 != Sign::zero)
    return true;  // proper crossing
  // Touching or collinear overlap: a point of one segment on the other.
  const auto on = [](const P2& p, const P2& q, const P2& r) {  // r on segment pq, given collinear
    const Sign sx = ((r.x - p.x) * (r.x - q.x)).sign(), sy = ((r.y - p.y) * (r.y - q.y)).sign();
    return sx != Sign::positive && sy != Sign::positive;
  };
  return (o1 == Sign::zero && on(a, b, c)) || (o2 == Sign::zero && on(a, b, d)) || (o3 == Sign::zero && on(c, d, a)) ||
         (o4 == Sign::zero && on(c, d, b));
}

std::vector<std::array<P2, 3>> triangulate(std::vector<P2> v) {
  // Orientation: counter-clockwise (signed area certified positive after reversing if needed).
  Bounded area2;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const P2& a = v[i];
    const P2& b = v[(i + 1) % v.size()];
    area2 = area2 + (a.x * b.y - a.y * b.x);
  }
  const Sign s = area2.sign();
  if (s == Sign::zero || s == Sign::uncertain)
    throw std::invalid_argument("support region: the outline has zero (or uncertain) area");
  if (s == Sign::negative) std::reverse(v.begin(), v.end());
  // Simplicity: no two non-adjacent edges meet, adjacent ones only at their common vertex.
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) {
        const std::size_t shared = j == i + 1 ? j : i;
        const P2& p = v[shared];
        const P2& q = v[j == i + 1 ? i : j];      // the other end of the earlier edge
        const P2& r = v[(shared + 1) % n];         // the other end of the later edge
        if (orient(q, p, r) == Sign::zero && ((q.x - p.x) * (r.x - p.x) + (q.y - p.y) * (r.y - p.y)).sign() != Sign::negative)
          throw std::invalid_argument("support region: the outline folds back on itself at vertex " + std::to_string(shared));
        continue;
      }
      if (segments_meet(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n]))
        throw std::invalid_argument("support region: the outline is not a simple polygon (edges " + std::to_string(i) +
                                    " and " + std::to_string(j) + " meet)");
    }
  // Ear clipping: an ear is a certified left turn with no other vertex in the closed triangle.
  std::vector<std::array<P2, 3>> tris;
  std::vector<P2> w = v;
  while (w.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < w.size() && !clipped; ++i) {
      const P2& a = w[(i + w.size() - 1) % w.size()];
      const P2& b = w[i];
      const P2& c = w[(i + 1) % w.size()];
      const Sign t = orient(a, b, c);
      if (t == Sign::zero) {  // a straight vertex: drop it (no area)
        w.erase(w.begin() + static_cast<std::ptrdiff_t>(i));
        clipped = true;
        break;
      }
      if (t != Sign::positive) continue;
      bool empty = true;
      for (std::size_t k = 0; k < w.size() && empty; ++k) {
        if (k == i || k == (i + 1) % w.size() || k == (i + w.size() - 1) % w.size()) continue;
        const Sign s1 = orient(a, b, w[k]), s2 = orient(b, c, w[k]), s3 = orient(c, a, w[k]);
        empty = s1 == Sign::negative || s2 == Sign::negative || s3 == Sign::negative;
      }
      if (!empty) continue;
      tris.push_back({a, b, c});
      w.erase(w.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) throw std::invalid_argument("support region: the outline could not be triangulated (degenerate)");
  }
  if (orient(w[0], w[1], w[2]) == Sign::positive) tris.push_back({w[0], w[1], w[2]});
  return tris;
}

}  // namespace

Pressure_polygon uniform_pressure(std::vector<std::array<double, 2>> outline, double mu, double f0) {
  Pressure_polygon r;
  r.outline = std::move(outline);
  r.mu = mu;
  // c0 = f0 / area, computed here in doubles: the cells' forces are then certified for this c0, whose
  // total force (reported by discretize) is f0 up to its bound.
  double a2 = 0;
  for (std::size_t i = 0; i < r.outline.size(); ++i) {
    const auto& p = r.outline[i];
    const auto& q = r.outline[(i + 1) % r.outline.size()];
    a2 += p[0] * q[1] - p[1] * q[0];
  }
  r.c0 = f0 / (std::fabs(a2) / 2);
  return r;
}

Pressure_cells discretize(const Pressure_polygon& g, int m) {
  if (g.outline.size() < 3) throw std::invalid_argument("support region: the outline needs at least 3 vertices");
  if (g.outline.size() > 10000) throw std::invalid_argument("support region: more than 10000 outline vertices");
  if (m < 1 || m > 4096) throw std::invalid_argument("support region: cells per edge must be 1 … 4096");
  if (!(g.mu >= 0) || !std::isfinite(g.mu)) throw std::invalid_argument("support region: mu must be finite and >= 0");
  if (!std::isfinite(g.c0) || !std::isfinite(g.cx) || !std::isfinite(g.cy))
    throw std::invalid_argument("support region: pressure coefficients must be finite");
  std::vector<P2> v;
  for (std::size_t i = 0; i < g.outline.size(); ++i) {
    if (!std::isfinite(g.outline[i][0]) || !std::isfinite(g.outline[i][1]))
      throw std::invalid_argument("support region: outline[" + std::to_string(i) + "] is not finite");
    v.push_back({ex(g.outline[i][0]), ex(g.outline[i][1])});
  }
  const Bounded c0 = ex(g.c0), cx = ex(g.cx), cy = ex(g.cy);
  const auto pressure = [&](const Bounded& x, const Bounded& y) { return c0 + cx * x + cy * y; };
  // Linear ⇒ its minimum over the polygon is at a vertex.
  for (std::size_t i = 0; i < v.size(); ++i)
    if (pressure(v[i].x, v[i].y).sign() == Sign::negative || pressure(v[i].x, v[i].y).sign() == Sign::uncertain)
      throw std::invalid_argument("support region: the pressure is negative (or not certified >= 0) at outline[" +
                                  std::to_string(i) + "]");
  Pressure_cells out;
  Bounded eps;
  const Bounded mu = ex(g.mu), third = ex(1) / ex(3), half = ex(0.5), bm = ex(m);
  for (const auto& t : triangulate(v)) {
    const P2 &A = t[0], &B = t[1], &C = t[2];
    const auto at = [&](int i, int j) {  // A + (i/m)(B − A) + (j/m)(C − A)
      const Bounded s = ex(i) / bm, r = ex(j) / bm;
      return P2{A.x + s * (B.x - A.x) + r * (C.x - A.x), A.y + s * (B.y - A.y) + r * (C.y - A.y)};
    };
    const auto cell = [&](const P2& a, const P2& b, const P2& c) {
      const P2 s{(a.x + b.x + c.x) * third, (a.y + b.y + c.y) * third};
      const Bounded area = abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) * half;
      const Bounded F = area * pressure(s.x, s.y);
      Bounded delta;
      for (const P2* p : {&a, &b, &c}) delta = max(delta, fl::sqrt((p->x - s.x) * (p->x - s.x) + (p->y - s.y) * (p->y - s.y)));
      out.points.push_back({s.x, s.y, F, mu * F});
      out.total_force = out.total_force + F;
      eps = eps + F * delta;
    };
    for (int i = 0; i < m; ++i)
      for (int j = 0; i + j < m; ++j) {
        cell(at(i, j), at(i + 1, j), at(i, j + 1));
        if (i + j + 2 <= m) cell(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      }
  }
  // δ_k is an upper bound of the true radius only up to its own bound: use the upper ends.
  out.epsilon = {upper(mu * eps), 0.0};
  return out;
}

Bounded support_function(const Pressure_cells& cells, const Bounded3& q) {
  const Bounded h = support_function(cells.points, q);
  const double widen = cells.epsilon.v * upper(abs(q[2]));
  return {h.v, (h.e + widen) * (1 + 0x1p-50)};
}

}  // namespace wrenchkit::fl
