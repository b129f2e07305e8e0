// proofs/checker/grasp_regions.cpp - certificate-format.md §3.6 (format 5): two-finger force-closure regions on a
// polygon's edge pairs. The checker derives each pair's region itself from the scene — Nguyen's theorem
// (proofs/notes/GR-1-two-finger-regions.md): two frictional fingers close the grasp exactly when the segment between
// them lies strictly inside both friction cones, four strict linear inequalities in the edges' parameters (s, t) —,
// cuts the unit square by them, and accepts the certificate only when every pair asked is listed once, in order, with
// exactly that polygon (the same corners, counter-clockwise, from the same first corner) or with none when the region
// is empty. Exact rationals throughout.
#include <algorithm>

#include "proofs/checker/certificate.h"

namespace wrenchkit_checker::detail {

namespace {

using P = std::array<Q, 2>;

Q cross(const P& a, const P& b) { return a[0] * b[1] - a[1] * b[0]; }

// The closed half-plane a s + b t + c >= 0 of the polygon (Sutherland-Hodgman).
std::vector<P> cut(const std::vector<P>& in, const Q& a, const Q& b, const Q& c) {
  std::vector<P> out;
  for (std::size_t k = 0; k < in.size(); ++k) {
    const P &x = in[k], &y = in[(k + 1) % in.size()];
    const Q vx = a * x[0] + b * x[1] + c, vy = a * y[0] + b * y[1] + c;
    if (sgn(vx) >= 0) out.push_back(x);
    if (sgn(vx) * sgn(vy) < 0) {
      const Q r = vx / (vx - vy);
      out.push_back({x[0] + r * (y[0] - x[0]), x[1] + r * (y[1] - x[1])});
    }
  }
  return out;
}

using Half = std::array<Q, 3>;  // a s + b t + c > 0

// Nguyen's four strict inequalities of the pair, in the order finger i's R, L, then finger j's.
std::array<Half, 4> cones(const std::vector<P>& V, std::size_t i, std::size_t j, const Q& mu) {
  const std::size_t n = V.size();
  Q area2 = 0;
  for (std::size_t k = 0; k < n; ++k) area2 += cross(V[k], V[(k + 1) % n]);
  const auto edge = [&](std::size_t k) {  // first vertex, vector, cone edges n - mu rot90 n and n + mu rot90 n
    const P d{V[(k + 1) % n][0] - V[k][0], V[(k + 1) % n][1] - V[k][1]};
    const P nn = sgn(area2) > 0 ? P{-d[1], d[0]} : P{d[1], -d[0]}, t{-nn[1], nn[0]};
    return std::array<P, 4>{V[k], d, P{nn[0] - mu * t[0], nn[1] - mu * t[1]}, P{nn[0] + mu * t[0], nn[1] + mu * t[1]}};
  };
  const auto ei = edge(i), ej = edge(j);
  const P c0{ej[0][0] - ei[0][0], ej[0][1] - ei[0][1]};
  // sign * cross(e, v) with v = c0 + t d_j - s d_i: (-sign cross(e, d_i)) s + (sign cross(e, d_j)) t + sign cross(e, c0)
  const std::array<std::pair<const P*, int>, 4> sides{{{&ei[2], 1}, {&ei[3], -1}, {&ej[2], -1}, {&ej[3], 1}}};
  std::array<Half, 4> out;
  for (std::size_t k = 0; k < 4; ++k) {
    const auto& [e, sign] = sides[k];
    out[k] = {Q(-sign * cross(*e, ei[1])), Q(sign * cross(*e, ej[1])), Q(sign * cross(*e, c0))};
  }
  return out;
}

// The pair's closure polygon: corners counter-clockwise, none repeated or collinear, from the first the cutting
// leaves; empty when its area is 0 (then the strict inequalities hold nowhere on the square).
std::vector<P> region(const std::array<Half, 4>& H) {
  std::vector<P> poly{{Q(0), Q(0)}, {Q(1), Q(0)}, {Q(1), Q(1)}, {Q(0), Q(1)}};
  for (const auto& [a, b, c] : H) {
    if (sgn(a) == 0 && sgn(b) == 0 && sgn(c) <= 0) return {};
    if (!poly.empty()) poly = cut(poly, a, b, c);
  }
  for (bool again = true; again && poly.size() >= 3;) {  // collinear corners out
    again = false;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const P &a = poly[(k + poly.size() - 1) % poly.size()], &b = poly[k], &c = poly[(k + 1) % poly.size()];
      if (sgn(Q((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))) == 0) {
        poly.erase(poly.begin() + static_cast<long>(k));
        again = true;
        break;
      }
    }
  }
  Q area = 0;
  for (std::size_t k = 0; k < poly.size(); ++k) area += cross(poly[k], poly[(k + 1) % poly.size()]);
  if (poly.size() < 3 || sgn(area) <= 0) return {};
  return poly;
}

P read_point(Reader& r) {
  P p;
  read_fixed(r, 2, "an array of two rationals [s, t]", [&](std::size_t k) { p[k] = read_rational(r); });
  return p;
}

}  // namespace

void read_region_member(Reader& r, std::string_view key, Certificate& c) {
  Regions_part& g = c.g();
  if (key == "fingers") {
    g.fingers = read_index(r, "number of fingers");
  } else if (key == "mu") {
    g.mu = read_rational(r);
  } else if (key == "edges") {
    g.has_edges = true;
    begin_array(r, "expected an array of edge indices");
    while (r.next_item()) g.edges.push_back(read_index(r, "edge index"));
  } else {  // pairs
    begin_array(r, "expected an array of {\"edges\": [i, j], \"closed\": [polygons]}");
    while (r.next_item()) {
      Regions_part::Pair& p = g.pairs.emplace_back();
      begin_object(r, "expected an object {\"edges\": [i, j], \"closed\": [polygons]}");
      std::string_view k;
      unsigned seen = 0;
      while (r.next_key(k)) {
        if (k == "edges") {
          seen |= 1;
          std::size_t e[2];
          read_fixed(r, 2, "an array of two edge indices [i, j]", [&](std::size_t m) { e[m] = read_index(r, "edge index"); });
          p.i = e[0], p.j = e[1];
        } else if (k == "independent") {
          p.has_box = true;
          read_fixed(r, 2, "[[s0, s1], [t0, t1]]", [&](std::size_t m) {
            read_fixed(r, 2, "an interval [lower, upper]", [&](std::size_t e) { p.box[m][e] = read_rational(r); });
          });
        } else if (k == "closed") {
          seen |= 2;
          begin_array(r, "expected an array of polygons");
          while (r.next_item()) {
            auto& poly = p.closed.emplace_back();
            begin_array(r, "expected a polygon: an array of [s, t]");
            while (r.next_item()) poly.push_back(read_point(r));
          }
        } else {
          r.fail("unknown key " + quote(k), true);
        }
      }
      if (seen != 3) r.fail("a pair needs \"edges\" and \"closed\"");
    }
  }
}

void check_grasp_regions(const Certificate& c, const Scene& scene, const Limits&) {
  const Regions_part& g = *c.regions_members;
  if (g.fingers != 2) throw Failure{"fingers: only 2 (Nguyen's regions) is a claim of format 5"};
  if (sgn(g.mu) < 0) throw Failure{"mu: " + show(g.mu) + " is negative"};
  const std::vector<P>& V = scene.outline;
  if (!scene.outline_valid || V.size() < 3) throw Failure{"grasp_regions: the scene has no body.outline of points"};
  std::vector<std::size_t> edges = g.edges;
  if (!g.has_edges)
    for (std::size_t k = 0; k < V.size(); ++k) edges.push_back(k);
  for (std::size_t k = 0; k < edges.size(); ++k)
    if (edges[k] >= V.size() || (k > 0 && edges[k] <= edges[k - 1]))
      throw Failure{"edges: expected increasing edge indices of body.outline (0 to " + std::to_string(V.size() - 1) + ")"};
  std::size_t at = 0;
  for (std::size_t x = 0; x < edges.size(); ++x)
    for (std::size_t y = x + 1; y < edges.size(); ++y, ++at) {
      const std::string pair = "pairs[" + std::to_string(at) + "]";
      if (at >= g.pairs.size()) throw Failure{pair + ": missing (every pair i < j of the edges, in order)"};
      const Regions_part::Pair& p = g.pairs[at];
      if (p.i != edges[x] || p.j != edges[y])
        throw Failure{pair + ": expected edges [" + std::to_string(edges[x]) + ", " + std::to_string(edges[y]) + "]"};
      const std::array<Half, 4> H = cones(V, p.i, p.j, g.mu);
      const std::vector<P> want = region(H);
      const bool same = want.empty() ? p.closed.empty() : p.closed.size() == 1 && p.closed[0] == want;
      if (!same)
        throw Failure{pair + ".closed: not the force-closure region of edges " + std::to_string(p.i) + " and " +
                      std::to_string(p.j) + (want.empty() ? " (no placement closes: expected [])" : " (expected " +
                      std::to_string(want.size()) + " corners from " + show(want[0][0], want[0][1]) + ")")};
      // an independent box: inside the square, and each corner strictly inside the four half-planes (the region is
      // convex, so the whole box is)
      if (p.has_box) {
        const Q(&b)[2][2] = p.box;
        if (!(sgn(b[0][0]) >= 0 && b[0][0] < b[0][1] && b[0][1] <= 1 && sgn(b[1][0]) >= 0 && b[1][0] < b[1][1] && b[1][1] <= 1))
          throw Failure{pair + ".independent: not a box [[s0, s1], [t0, t1]] with 0 <= s0 < s1 <= 1, 0 <= t0 < t1 <= 1"};
        for (const Q& s : b[0])
          for (const Q& t : b[1])
            for (const auto& [a, bb, c] : H)
              if (sgn(Q(a * s + bb * t + c)) <= 0)
                throw Failure{pair + ".independent: the corner " + show(s, t) + " does not close the grasp"};
      }
    }
  if (at != g.pairs.size()) throw Failure{"pairs: more than the edge pairs asked"};
}

}  // namespace wrenchkit_checker::detail
