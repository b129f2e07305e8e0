// proofs/checker/regions.cpp - support regions, certificate-format.md §6.4 (proofs/notes/RG-1, RG-2): the scene's
// regions checked and settled by the checker's own exact geometry (no CGAL), and the certificates' region blocks
// (tiling, stick blocks, slide blocks).
#include "proofs/checker/regions.h"

#include <algorithm>

#include "proofs/checker/certificate.h"
#include "proofs/checker/scene.h"

namespace wrenchkit_checker::detail {

Q cross(const P2& a, const P2& b, const P2& c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }
int orient(const P2& a, const P2& b, const P2& c) { return sgn(cross(a, b, c)); }
// p on the closed segment ab, given the three are collinear.
bool on_segment(const P2& p, const P2& a, const P2& b) {
  return (p.x - a.x) * (p.x - b.x) <= 0 && (p.y - a.y) * (p.y - b.y) <= 0;
}
// Do the closed segments ab and cd share a point?
bool segments_meet(const P2& a, const P2& b, const P2& c, const P2& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on_segment(c, a, b)) || (o2 == 0 && on_segment(d, a, b)) || (o3 == 0 && on_segment(a, c, d)) ||
         (o4 == 0 && on_segment(b, c, d));
}
Q pressure(const Q (&c)[3], const P2& r) { return c[0] + c[1] * r.x + c[2] * r.y; }
Q twice_area(const std::vector<P2>& ring) {
  Q a = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const P2 &p = ring[i], &q = ring[(i + 1) % ring.size()];
    a += p.x * q.y - p.y * q.x;
  }
  return a;
}
// Strictly inside a simple ring, for a point on none of its edges: the parity of the crossings of the ray to +x.
bool inside(const std::vector<P2>& ring, const P2& p) {
  bool in = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const P2 &a = ring[i], &b = ring[(i + 1) % ring.size()];
    if (a.y <= p.y && p.y < b.y && orient(a, b, p) > 0) in = !in;  // upward, p to its left
    if (b.y <= p.y && p.y < a.y && orient(a, b, p) < 0) in = !in;  // downward, p to its right
  }
  return in;
}
// Every ring simple and the rings apart. Edges are swept in order of their smallest x, each compared with the
// edges that start before it ends (O(n log n) for ordinary polygons, O(n^2) at worst; n is at most
// max_region_vertices).
void check_rings(const Region& g) {
  struct Edge {
    std::size_t ring, i;
    Q lo, hi;
  };
  std::vector<Edge> edges;
  for (std::size_t k = 0; k < g.rings.size(); ++k) {
    const auto& r = g.rings[k];
    const std::string at = g.path + (k == 0 ? std::string(".outline") : ".holes[" + std::to_string(k - 1) + "]");
    if (r.size() < 3) throw Failure{at + ": has " + std::to_string(r.size()) + " vertices (a polygon needs at least 3)"};
    std::vector<const P2*> sorted;
    for (const P2& v : r) sorted.push_back(&v);
    std::sort(sorted.begin(), sorted.end(), [](const P2* a, const P2* b) { return a->x < b->x || (a->x == b->x && a->y < b->y); });
    for (std::size_t i = 1; i < sorted.size(); ++i)
      if (sorted[i]->x == sorted[i - 1]->x && sorted[i]->y == sorted[i - 1]->y)
        throw Failure{at + ": is not a simple polygon (a vertex is repeated)"};
    for (std::size_t i = 0; i < r.size(); ++i) {
      const P2 &a = r[i], &b = r[(i + 1) % r.size()];
      edges.push_back({k, i, a.x < b.x ? a.x : b.x, a.x < b.x ? b.x : a.x});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.lo < b.lo; });
  const auto ring_name = [&](std::size_t k) {
    return k == 0 ? std::string("the outline") : "holes[" + std::to_string(k - 1) + "]";
  };
  for (std::size_t u = 0; u < edges.size(); ++u)
    for (std::size_t w = u + 1; w < edges.size() && edges[w].lo <= edges[u].hi; ++w) {
      const Edge &e = edges[u], &f = edges[w];
      const auto& re = g.rings[e.ring];
      const auto& rf = g.rings[f.ring];
      const P2 &a = re[e.i], &b = re[(e.i + 1) % re.size()], &c = rf[f.i], &d = rf[(f.i + 1) % rf.size()];
      if (e.ring != f.ring) {
        if (segments_meet(a, b, c, d)) {
          const std::size_t hi = std::max(e.ring, f.ring), lo = std::min(e.ring, f.ring);
          throw Failure{g.path + ".holes[" + std::to_string(hi - 1) + "]: meets " + ring_name(lo) +
                        (lo == 0 ? " (a hole must lie strictly inside it)" : " (holes must be disjoint)")};
        }
        continue;
      }
      const std::size_t n = re.size();
      const std::string at = g.path + (e.ring == 0 ? std::string(".outline") : ".holes[" + std::to_string(e.ring - 1) + "]");
      const bool next = (e.i + 1) % n == f.i, prev = (f.i + 1) % n == e.i;
      if (next || prev) {  // adjacent: they meet at the shared vertex only (no fold back along one line)
        const P2& shared = next ? b : a;
        const P2& x = next ? a : b;            // e's other end
        const P2& y = next ? d : c;            // f's other end
        if (orient(x, shared, y) == 0 && (x.x - shared.x) * (y.x - shared.x) + (x.y - shared.y) * (y.y - shared.y) > 0)
          throw Failure{at + ": is not a simple polygon (two of its edges cross, touch or overlap)"};
        if (!(next && prev)) continue;  // a triangle: every pair is adjacent both ways; checked above
        continue;
      }
      if (segments_meet(a, b, c, d)) throw Failure{at + ": is not a simple polygon (two of its edges cross, touch or overlap)"};
    }
  for (std::size_t k = 1; k < g.rings.size(); ++k) {
    const std::string at = g.path + ".holes[" + std::to_string(k - 1) + "]";
    if (!inside(g.rings[0], g.rings[k][0])) throw Failure{at + ": is not inside the outline (a hole must lie strictly inside it)"};
    for (std::size_t j = 1; j < g.rings.size(); ++j)
      if (j != k && inside(g.rings[j], g.rings[k][0]))
        throw Failure{at + ": lies inside holes[" + std::to_string(j - 1) + "] (holes must be disjoint)"};
  }
}

// Validates the region and settles it: rings oriented, pressure coefficients, W and M (fan triangles (0, a, b)
// of the oriented boundary, whose signed integrals sum to the region's; degree <= 2, so the edge-midpoint rule
// is exact on each).
void settle_region(Region& g) {
  check_rings(g);
  Q area2 = 0;
  for (std::size_t k = 0; k < g.rings.size(); ++k) {
    const Q a = twice_area(g.rings[k]);
    if (sgn(a) == 0) throw Failure{g.path + ".outline: has zero area"};  // not reached for a simple ring
    if ((sgn(a) > 0) != (k == 0)) std::reverse(g.rings[k].begin(), g.rings[k].end());
    area2 += k == 0 ? abs(a) : Q(-abs(a));
  }
  if (g.uniform) {
    if (sgn(g.force) <= 0) throw Failure{g.path + ".force: " + show(g.force) + " is not positive (a region's force must be > 0)"};
    g.c[0] = 2 * g.force / area2, g.c[1] = 0, g.c[2] = 0;
  } else {
    for (int k = 0; k < 3; ++k) g.c[k] = g.linear[k];
    for (std::size_t i = 0; i < g.rings[0].size(); ++i)
      if (sgn(pressure(g.c, g.rings[0][i])) < 0)
        throw Failure{g.path + ".pressure: p = " + show(pressure(g.c, g.rings[0][i])) + " < 0 at a vertex of the outline " +
                      show(g.rings[0][i].x, g.rings[0][i].y) + " (a pressure must be >= 0 on the region)"};
  }
  std::vector<Q> w, mx, my;
  for (const auto& ring : g.rings)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const P2 &a = ring[i], &b = ring[(i + 1) % ring.size()];
      const Q area = (a.x * b.y - a.y * b.x) / 2;  // signed
      if (sgn(area) == 0) continue;
      const P2 ma{a.x / 2, a.y / 2}, mb{b.x / 2, b.y / 2}, mab{(a.x + b.x) / 2, (a.y + b.y) / 2};
      const Q pa = pressure(g.c, ma), pb = pressure(g.c, mb), pab = pressure(g.c, mab);
      w.push_back(area * (pa + pb + pab) / 3);
      mx.push_back(area * (ma.x * pa + mb.x * pb + mab.x * pab) / 3);
      my.push_back(area * (ma.y * pa + mb.y * pb + mab.y * pab) / 3);
    }
  g.W = tree_sum(std::move(w));
  g.M[0] = tree_sum(std::move(mx));
  g.M[1] = tree_sum(std::move(my));
  if (sgn(g.W) <= 0)
    throw Failure{g.path + ".pressure: the pressure is zero on the whole region (a region's total force must be > 0)"};
}

// {"outline": ring, "holes"?: [ring, ...], "pressure": "uniform" | {"linear": [a, b, c]}, "force"?: F, "mu"?: mu}
Region read_region(Reader& r, const Limits& lim, std::size_t& vertices) {
  Region g;
  g.path = r.path();
  begin_object(r, "expected an object {\"outline\", \"holes\"?, \"pressure\", \"force\"?, \"mu\"?}");
  const auto ring = [&](std::vector<P2>& out) {
    begin_array(r, "expected an array of points");
    while (r.next_item()) {
      if (++vertices > lim.max_region_vertices)
        r.fail("the support's regions have more than " + std::to_string(lim.max_region_vertices) + " vertices in all", true);
      Q v[2];
      read_fixed(r, 2, numbers_text(2), [&](std::size_t k) { v[k] = read_number(r, lim); });
      out.push_back({v[0], v[1]});
    }
  };
  bool has_outline = false, has_pressure = false, has_force = false;
  std::string_view key;
  g.rings.emplace_back();
  while (r.next_key(key)) {
    if (key == "outline") {
      ring(g.rings[0]);
      has_outline = true;
    } else if (key == "holes") {
      begin_array(r, "expected an array of rings");
      while (r.next_item()) {
        g.rings.emplace_back();
        ring(g.rings.back());
      }
    } else if (key == "pressure") {
      has_pressure = true;
      if (r.peek() == Kind::string) {
        if (r.string_view() != "uniform") r.fail("expected \"uniform\" or {\"linear\": [a, b, c]}");
        g.uniform = true;
      } else {
        begin_object(r, "expected \"uniform\" or {\"linear\": [a, b, c]}");
        bool has_linear = false;
        std::string_view k;
        while (r.next_key(k)) {
          if (k != "linear") r.fail("unknown key " + quote(k), true);
          read_fixed(r, 3, numbers_text(3), [&](std::size_t j) { g.linear[j] = read_number(r, lim); });
          has_linear = true;
        }
        if (!has_linear) r.fail("missing required key \"linear\"");
        g.uniform = false;
      }
    } else if (key == "force") {
      g.force = read_number(r, lim);
      has_force = true;
    } else if (key == "mu") {
      std::string text;
      g.mu = read_number(r, lim, &text);
      if (sgn(g.mu) < 0) r.fail(quote(text) + " is negative");
      g.has_mu = true;
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  if (!has_outline) r.fail("missing required key \"outline\"");
  if (!has_pressure) r.fail("missing required key \"pressure\"");
  if (g.uniform && !has_force) r.fail("missing key \"force\" (a uniform pressure needs the region's force)");
  if (!g.uniform && has_force) throw Failure{g.path + ".force: not allowed with a linear pressure"};
  if (g.rings.size() > 1) g.rings.shrink_to_fit();
  return g;
}

// ---------------------------------------------------------------------------------------------
// Region blocks (certificate-format.md §6.4, proofs/notes/RG-1): the shared checks of a region's part of a stick or
// slide witness.

// The cells of b tile g: every cell counter-clockwise with positive area, and the sum of the cells' oriented
// boundaries equals the region's oriented boundary as 1-chains (on each supporting line, the multiplicity of
// every piece between endpoints is zero; collinear overlapping segments cancel). Then the cells' indicators
// sum to the region's almost everywhere (RG-1 §2).
void check_tiling(const Region& g, const Block& b) {
  struct Event {
    int vertical;
    Q a, b, t;  // the line (y = a x + b, or x = a) and the parameter (x, or y)
    int delta;
  };
  std::vector<Event> events;
  const auto segment = [&](const P2& p, const P2& q, int w) {
    if (p.x != q.x) {
      const Q slope = (q.y - p.y) / (q.x - p.x), icpt = p.y - slope * p.x;
      const int dir = q.x > p.x ? w : -w;
      const Q& lo = q.x > p.x ? p.x : q.x;
      const Q& hi = q.x > p.x ? q.x : p.x;
      events.push_back({0, slope, icpt, lo, dir});
      events.push_back({0, slope, icpt, hi, -dir});
    } else {
      const int dir = q.y > p.y ? w : -w;
      const Q& lo = q.y > p.y ? p.y : q.y;
      const Q& hi = q.y > p.y ? q.y : p.y;
      events.push_back({1, p.x, Q(0), lo, dir});
      events.push_back({1, p.x, Q(0), hi, -dir});
    }
  };
  for (std::size_t k = 0; k < b.triangles.size(); ++k) {
    const auto& t = b.triangles[k];
    const std::string at = b.path + ".triangles[" + std::to_string(k) + "]";
    for (const std::size_t v : t)
      if (v >= b.vertices.size())
        throw Failure{at + ": vertex index " + (v == SIZE_MAX ? std::string("(huge)") : std::to_string(v)) +
                      " out of range (" + std::to_string(b.vertices.size()) + " vertices)"};
    const P2 &p = b.vertices[t[0]], &q = b.vertices[t[1]], &r = b.vertices[t[2]];
    if (orient(p, q, r) <= 0) throw Failure{at + ": not counter-clockwise with a positive area"};
    segment(p, q, 1), segment(q, r, 1), segment(r, p, 1);
  }
  for (const auto& ring : g.rings)
    for (std::size_t i = 0; i < ring.size(); ++i) segment(ring[i], ring[(i + 1) % ring.size()], -1);
  std::sort(events.begin(), events.end(), [](const Event& x, const Event& y) {
    if (x.vertical != y.vertical) return x.vertical < y.vertical;
    if (x.a != y.a) return x.a < y.a;
    if (x.b != y.b) return x.b < y.b;
    return x.t < y.t;
  });
  int sum = 0;
  for (std::size_t i = 0; i < events.size(); ++i) {
    sum += events[i].delta;
    const bool last_at_t = i + 1 == events.size() || events[i + 1].vertical != events[i].vertical ||
                           events[i + 1].a != events[i].a || events[i + 1].b != events[i].b || events[i + 1].t != events[i].t;
    if (last_at_t && sum != 0)
      throw Failure{b.path + ": the cells do not tile " + g.path + " (their boundaries do not add up to the region's "
                    "boundary: a cell outside it, a gap, an overlap or a hole covered)"};
  }
}

// The block's `key` has one entry (`n` of `what`) per cell or vertex, and its cells tile g.
void check_block(const Region& g, const Block& b, const char* key, std::size_t have, const char* items, std::size_t n,
                 const char* what) {
  if (have != n)
    throw Failure{b.path + "." + key + ": " + std::to_string(have) + " " + items + " for " + std::to_string(n) + " " + what};
  check_tiling(g, b);
}

bool in_disc(const Q& gx, const Q& gy, const Q& rho, bool strict, const std::string& path, std::size_t i,
             const char* mu_f) {
  const Q lhs = gx * gx + gy * gy;
  const bool open = sgn(rho) == 0 ? sgn(lhs) == 0 : lhs < rho * rho;
  if (open || (!strict && lhs <= rho * rho)) return open;
  throw Failure{path + "[" + std::to_string(i) + "]: |g|^2 = " + show(lhs) + " is not " + (strict ? "less than" : "at most") +
                " (" + mu_f + ")^2 = " + show(Q(rho * rho)) + (sgn(rho) == 0 ? " (no friction there: g must be 0)" : "")};
}

void speed_bound(const Q& u, const Q (&q)[3], const Q& x, const Q& y, const std::string& path, std::size_t i,
                 const char* v) {
  const auto at = [&] { return path + "[" + std::to_string(i) + "]: "; };
  if (sgn(u) < 0) throw Failure{at() + show(u) + " is negative"};
  const Q vx = q[0] - q[2] * y, vy = q[1] + q[2] * x, speed2 = vx * vx + vy * vy;
  if (u * u < speed2) throw Failure{at() + "u^2 = " + show(Q(u * u)) + " is less than |" + v + "|^2 = " + show(speed2)};
}

// A stick block: |g_k|^2 < (mu F_k)^2 (g_k = 0 where mu F_k = 0; closed without `strict`, then returning whether every
// force is strictly inside all the same), F_k = area p(centroid); adds sum_k (g_k, c_k x g_k)
// to `sum` (c_k = M_k / F_k the cell's pressure centroid, M_k its integral of r p by the edge-midpoint rule) and
// calls friction(c_k) for every cell with mu F_k > 0.
// `strict` as support_sum's: a stick (|g_k|^2 < (mu F_k)^2) or a hold (|g_k|^2 <= (mu F_k)^2, closed discs).
bool add_stick_block(const Region& g, const Block& b, std::array<Q, 3>& sum,
                     const std::function<void(const Q&, const Q&)>& friction, bool strict) {
  check_block(g, b, "forces", b.forces.size(), "forces", b.triangles.size(), "cells");
  bool open = true;
  for (std::size_t k = 0; k < b.triangles.size(); ++k) {
    const auto& t = b.triangles[k];
    const P2 &p = b.vertices[t[0]], &q = b.vertices[t[1]], &r = b.vertices[t[2]];
    const Q area = cross(p, q, r) / 2;
    const P2 m[3] = {{(p.x + q.x) / 2, (p.y + q.y) / 2}, {(q.x + r.x) / 2, (q.y + r.y) / 2}, {(r.x + p.x) / 2, (r.y + p.y) / 2}};
    Q F = 0, M[2] = {0, 0};
    for (const P2& x : m) {
      const Q pm = pressure(g.c, x);
      F += pm, M[0] += x.x * pm, M[1] += x.y * pm;
    }
    F *= area / 3, M[0] *= area / 3, M[1] *= area / 3;
    const Pair& f = b.forces[k];
    const Q rho = g.mu * F;
    open = in_disc(f[0], f[1], rho, strict, b.path + ".forces", k, "mu F") && open;
    if (sgn(rho) == 0) continue;
    sum[0] += f[0], sum[1] += f[1], sum[2] += (M[0] * f[1] - M[1] * f[0]) / F;
    friction(Q(M[0] / F), Q(M[1] / F));
  }
  return open;
}

// A slide block: u_j >= 0 and u_j^2 >= |v_j(q)|^2 at every vertex; returns mu sum_cells sum_j w_j u_j with
// w_j = area (p_j + p_a + p_b + p_c)/12, the integral of the barycentric coordinate j times p (|v| is convex and
// p >= 0, so the integral of |v| p over the region is at most this).
Q slide_block_bound(const Region& g, const Block& b, const Q (&q)[3]) {
  check_block(g, b, "speed_bounds", b.speeds.size(), "bounds", b.vertices.size(), "vertices");
  const std::string path = b.path + ".speed_bounds";
  for (std::size_t j = 0; j < b.vertices.size(); ++j) speed_bound(b.speeds[j], q, b.vertices[j].x, b.vertices[j].y, path, j, "v(q)");
  std::vector<Q> terms;
  terms.reserve(b.triangles.size());
  for (const auto& t : b.triangles) {
    const P2 &p = b.vertices[t[0]], &q2 = b.vertices[t[1]], &r = b.vertices[t[2]];
    const Q area = cross(p, q2, r) / 2;
    const Q pv[3] = {pressure(g.c, p), pressure(g.c, q2), pressure(g.c, r)};
    const Q all = pv[0] + pv[1] + pv[2];
    Q cell = 0;
    for (int j = 0; j < 3; ++j) cell += (pv[j] + all) * b.speeds[t[static_cast<std::size_t>(j)]];
    terms.push_back(cell * area / 12);
  }
  return g.mu * tree_sum(std::move(terms));
}
}  // namespace wrenchkit_checker::detail
