// proofs/checker/grasp_regions.cpp - certificate-format.md §3.6 (format 5): two-finger force-closure regions on a
// polygon's edge pairs. The checker derives each pair's region itself from the scene — Nguyen's theorem
// (proofs/notes/GR-1-two-finger-regions.md): two frictional fingers close the grasp exactly when the segment between
// them lies strictly inside both friction cones, four strict linear inequalities in the edges' parameters (s, t) —,
// cuts the unit square by them, and accepts the certificate only when every pair asked is listed once, in order, with
// exactly that polygon (the same corners, counter-clockwise, from the same first corner) or with none when the region
// is empty. Three fingers ("triples", proofs/notes/GR-2-three-finger-boxes.md): a cube is accepted when the four
// wrenches it names have signed cofactors of one strict sign at its eight corners (they are multilinear in the
// parameters), "never" when mu = 0 or no wrench at either end of the three edges is beyond the direction given.
// Exact rationals throughout.
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

// Edge k's first vertex, its vector, and its friction cone's edges R = n - mu rot90 n and L = n + mu rot90 n (n the
// inward normal: rot90 of the edge vector on a counter-clockwise outline, its opposite on a clockwise one).
// `ccw`: the outline's signed area is positive (counter_clockwise(V), computed once per certificate).
bool counter_clockwise(const std::vector<P>& V) {
  Q area2 = 0;
  for (std::size_t x = 0; x < V.size(); ++x) area2 += cross(V[x], V[(x + 1) % V.size()]);
  return sgn(area2) > 0;
}

std::array<P, 4> edge_cone(const std::vector<P>& V, std::size_t k, const Q& mu, bool ccw) {
  const std::size_t n = V.size();
  const P d{V[(k + 1) % n][0] - V[k][0], V[(k + 1) % n][1] - V[k][1]};
  const P nn = ccw ? P{-d[1], d[0]} : P{d[1], -d[0]}, t{-nn[1], nn[0]};
  return std::array<P, 4>{V[k], d, P{nn[0] - mu * t[0], nn[1] - mu * t[1]}, P{nn[0] + mu * t[0], nn[1] + mu * t[1]}};
}

// Nguyen's four strict inequalities of the pair, in the order finger i's R, L, then finger j's.
std::array<Half, 4> cones(const std::vector<P>& V, std::size_t i, std::size_t j, const Q& mu, bool ccw) {
  const auto ei = edge_cone(V, i, mu, ccw), ej = edge_cone(V, j, mu, ccw);
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

// Three fingers (proofs/notes/GR-2-three-finger-boxes.md). The wrench of a cone edge f at the point p: (f, p x f).
using W = std::array<Q, 3>;
W wrench(const P& p, const P& f) { return {f[0], f[1], Q(cross(p, f))}; }
Q det(const W& a, const W& b, const W& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - b[0] * (a[1] * c[2] - a[2] * c[1]) + c[0] * (a[1] * b[2] - a[2] * b[1]);
}

// One triple's claims: an independent box (each of its eight corners: the four wrenches named, at that placement,
// have the four signed cofactors (-1)^m det(the others, in order) of one strict sign, the same at every corner), and
// "never" (mu = 0, or u . w <= 0 for every wrench at both ends of the three edges).
void check_triple(const std::vector<P>& V, const Q& mu, bool ccw, const Regions_part::Triple& t, const std::string& at) {
  std::array<std::array<P, 4>, 3> E;
  for (int f = 0; f < 3; ++f) E[f] = edge_cone(V, t.e[f], mu, ccw);
  const auto point = [&](int f, const Q& s) { return P{E[f][0][0] + s * E[f][1][0], E[f][0][1] + s * E[f][1][1]}; };
  if (t.has_box) {
    for (int f = 0; f < 3; ++f)
      if (!(sgn(t.box[f][0]) >= 0 && t.box[f][0] < t.box[f][1] && t.box[f][1] <= 1))
        throw Failure{at + ".independent: not a box [[a0, b0], [a1, b1], [a2, b2]] with 0 <= a < b <= 1"};
    for (int k = 0; k < 4; ++k)
      if (t.wrench[k] < 0 || t.wrench[k] > 5 || (k > 0 && t.wrench[k] <= t.wrench[k - 1]))
        throw Failure{at + ".wrenches: expected four different labels of R0, L0, R1, L1, R2, L2 in that order"};
    int sign = 0;
    for (int corner = 0; corner < 8; ++corner) {
      const Q s[3] = {t.box[0][corner & 1], t.box[1][(corner >> 1) & 1], t.box[2][(corner >> 2) & 1]};
      W w[4];
      for (int k = 0; k < 4; ++k) {
        const int f = t.wrench[k] / 2;
        w[k] = wrench(point(f, s[f]), E[f][2 + t.wrench[k] % 2]);
      }
      const Q c[4] = {det(w[1], w[2], w[3]), Q(-det(w[0], w[2], w[3])), det(w[0], w[1], w[3]), Q(-det(w[0], w[1], w[2]))};
      for (const Q& v : c) {
        if (sgn(v) == 0 || (sign != 0 && sgn(v) != sign))
          throw Failure{at + ".independent: at the corner " + show(s[0], s[1]) + ", " + show(s[2]) +
                        " the four wrenches' cofactors do not have one strict sign (no positive spanning certified)"};
        sign = sgn(v);
      }
    }
  }
  if (t.never == 1 && sgn(mu) != 0) throw Failure{at + ".never: \"frictionless\" but mu is " + show(mu)};
  if (t.never == 2) {
    if (sgn(t.direction[0]) == 0 && sgn(t.direction[1]) == 0 && sgn(t.direction[2]) == 0)
      throw Failure{at + ".never: the direction is 0"};
    for (int f = 0; f < 3; ++f)
      for (int side = 2; side < 4; ++side)
        for (const Q& s : {Q(0), Q(1)}) {
          const W w = wrench(point(f, s), E[f][side]);
          if (sgn(Q(t.direction[0] * w[0] + t.direction[1] * w[1] + t.direction[2] * w[2])) > 0)
            throw Failure{at + ".never: the wrench " + std::string(side == 2 ? "R" : "L") + std::to_string(f) + " at s = " +
                          show(s) + " is beyond the direction (some placement may close)"};
        }
  }
  if (t.has_box && t.never) throw Failure{at + ": both an independent box and \"never\""};
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
  } else if (key == "triples") {
    begin_array(r, "expected an array of {\"edges\": [i, j, k], ...}");
    while (r.next_item()) {
      Regions_part::Triple& t = g.triples.emplace_back();
      begin_object(r, "expected an object {\"edges\": [i, j, k], ...}");
      std::string_view k;
      unsigned seen = 0;
      while (r.next_key(k)) {
        if (k == "edges") {
          seen |= 1;
          read_fixed(r, 3, "an array of three edge indices [i, j, k]", [&](std::size_t m) { t.e[m] = read_index(r, "edge index"); });
        } else if (k == "independent") {
          t.has_box = true;
          read_fixed(r, 3, "[[a0, b0], [a1, b1], [a2, b2]]", [&](std::size_t m) {
            read_fixed(r, 2, "an interval [lower, upper]", [&](std::size_t e) { t.box[m][e] = read_rational(r); });
          });
        } else if (k == "wrenches") {
          seen |= 2;
          read_fixed(r, 4, "an array of four wrench labels", [&](std::size_t m) {
            const std::string_view v = r.peek() == Kind::string ? r.string_view() : "";
            if (v.size() != 2 || (v[0] != 'R' && v[0] != 'L') || v[1] < '0' || v[1] > '2')
              r.fail("expected a wrench label R0, L0, R1, L1, R2 or L2");
            t.wrench[m] = 2 * (v[1] - '0') + (v[0] == 'L');
          });
        } else if (k == "never") {
          if (r.peek() == Kind::string) {
            if (r.string_view() != "frictionless") r.fail("expected \"frictionless\" or a direction [ux, uy, um]");
            t.never = 1;
          } else {
            t.never = 2;
            read_fixed(r, 3, "a direction [ux, uy, um]", [&](std::size_t m) { t.direction[m] = read_rational(r); });
          }
        } else {
          r.fail("unknown key " + quote(k), true);
        }
      }
      if (!(seen & 1)) r.fail("a triple needs \"edges\"");
      if (t.has_box != ((seen & 2) != 0)) r.fail("\"independent\" and \"wrenches\" go together");
    }
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
  if (g.fingers != 2 && g.fingers != 3) throw Failure{"fingers: 2 (Nguyen's regions) or 3 (independent boxes) only"};
  if ((g.fingers == 3) != c.keys.count("triples"))
    throw Failure{g.fingers == 3 ? "fingers: 3 answers \"triples\"" : "fingers: 2 answers \"pairs\""};
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
  const bool ccw = counter_clockwise(V);
  if (g.fingers == 3) {
    for (std::size_t x = 0; x < edges.size(); ++x)
      for (std::size_t y = x + 1; y < edges.size(); ++y)
        for (std::size_t z = y + 1; z < edges.size(); ++z, ++at) {
          const std::string name = "triples[" + std::to_string(at) + "]";
          if (at >= g.triples.size()) throw Failure{name + ": missing (every triple i < j < k of the edges, in order)"};
          const Regions_part::Triple& t = g.triples[at];
          if (t.e[0] != edges[x] || t.e[1] != edges[y] || t.e[2] != edges[z])
            throw Failure{name + ": expected edges [" + std::to_string(edges[x]) + ", " + std::to_string(edges[y]) + ", " +
                          std::to_string(edges[z]) + "]"};
          check_triple(V, g.mu, ccw, t, name);
        }
    if (at != g.triples.size()) throw Failure{"triples: more than the edge triples asked"};
    return;
  }
  for (std::size_t x = 0; x < edges.size(); ++x)
    for (std::size_t y = x + 1; y < edges.size(); ++y, ++at) {
      const std::string pair = "pairs[" + std::to_string(at) + "]";
      if (at >= g.pairs.size()) throw Failure{pair + ": missing (every pair i < j of the edges, in order)"};
      const Regions_part::Pair& p = g.pairs[at];
      if (p.i != edges[x] || p.j != edges[y])
        throw Failure{pair + ": expected edges [" + std::to_string(edges[x]) + ", " + std::to_string(edges[y]) + "]"};
      const std::array<Half, 4> H = cones(V, p.i, p.j, g.mu, ccw);
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
