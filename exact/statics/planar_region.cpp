#include "exact/statics/planar_region.h"

#include <algorithm>
#include <stdexcept>


namespace wrenchkit {

namespace {

bool same(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }
Vec2 neg(const Vec2& v) { return {-v.x, -v.y}; }

// Upper half-plane first (y > 0, or y = 0 and x > 0), then by counter-clockwise angle.
int half_of(const Vec2& v) { return (v.y > 0 || (v.y == 0 && v.x > 0)) ? 0 : 1; }
bool angle_less(const Vec2& a, const Vec2& b) {
  const int ha = half_of(a), hb = half_of(b);
  if (ha != hb) return ha < hb;
  return cross(a, b) > 0;
}

// Andrew's monotone chain on points sorted by (x, y): the strictly convex lower chain.
template <class Key>
std::vector<std::size_t> lower_chain(const std::vector<Vec2>& pts, const std::vector<std::size_t>& order, Key key) {
  std::vector<std::size_t> h;
  for (std::size_t i : order) {
    while (h.size() >= 2) {
      const Vec2 a = key(pts[h[h.size() - 2]]), b = key(pts[h.back()]), c = key(pts[i]);
      const Vec2 ab{b.x - a.x, b.y - a.y}, ac{c.x - a.x, c.y - a.y};
      if (cross(ab, ac) > 0) break;  // strict left turn: keep b
      h.pop_back();
    }
    h.push_back(i);
  }
  return h;
}

std::vector<Vec2> dedup(std::vector<Vec2> pts) {
  std::sort(pts.begin(), pts.end(), [](const Vec2& a, const Vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  pts.erase(std::unique(pts.begin(), pts.end(), same), pts.end());
  return pts;
}

// The convex hull of points, counter-clockwise, collinear points dropped.
Region bounded_hull(std::vector<Vec2> pts) {
  Region r;
  pts = dedup(std::move(pts));
  if (pts.empty()) return r;
  if (pts.size() == 1) {
    r.shape = Region::Shape::point;
    r.vertices = pts;
    return r;
  }
  std::vector<std::size_t> up, down;
  for (std::size_t i = 0; i < pts.size(); ++i) up.push_back(i);
  down.assign(up.rbegin(), up.rend());
  const auto id = [](const Vec2& v) { return v; };
  const std::vector<std::size_t> lo = lower_chain(pts, up, id), hi = lower_chain(pts, down, id);
  std::vector<Vec2> v;
  for (std::size_t k = 0; k + 1 < lo.size(); ++k) v.push_back(pts[lo[k]]);
  for (std::size_t k = 0; k + 1 < hi.size(); ++k) v.push_back(pts[hi[k]]);
  if (v.size() == 2) {
    r.shape = Region::Shape::segment;
  } else {
    r.shape = Region::Shape::polygon;
  }
  r.vertices = std::move(v);
  return r;
}

// The corners of conv(pts) + pos(dirs) for a pointed recession cone: in coordinates (x', y') of an
// orientation-preserving linear map that sends the cone into the closed upper half-plane (ray) or
// the positive quadrant (wedge), the corners are the lower chain from the leftmost point (lowest
// among equals) to the lowest point (leftmost among equals; the rightmost lowest for a ray).
std::vector<Vec2> pointed_corners(const std::vector<Vec2>& pts, const Cone2& cone) {
  const bool wedge = cone.shape == Cone2::Shape::wedge;
  const Vec2 lo = cone.extreme.front(), hi = cone.extreme.back();
  // Ray d: x' = e·p with e = (d_y, −d_x), y' = d·p. Wedge: x' = p × hi, y' = lo × p.
  const auto key = [&](const Vec2& p) -> Vec2 {
    if (wedge) return {cross(p, hi), cross(lo, p)};
    return {lo.y * p.x - lo.x * p.y, dot(lo, p)};
  };
  std::vector<std::size_t> order(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) order[i] = i;
  std::vector<Vec2> keys;
  keys.reserve(pts.size());
  for (const Vec2& p : pts) keys.push_back(key(p));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return keys[a].x < keys[b].x || (keys[a].x == keys[b].x && keys[a].y < keys[b].y);
  });
  // Keep the lowest point of each x'; for a wedge only points strictly below all points to their left.
  std::vector<std::size_t> kept;
  for (std::size_t i : order) {
    if (!kept.empty() && keys[kept.back()].x == keys[i].x) continue;
    if (wedge && !kept.empty() && !(keys[i].y < keys[kept.back()].y)) continue;
    kept.push_back(i);
  }
  const std::vector<std::size_t> chain = lower_chain(keys, kept, [](const Vec2& v) { return v; });
  std::vector<Vec2> out;
  for (std::size_t i : chain) out.push_back(pts[i]);
  return out;
}

}  // namespace

const char* shape_name(Cone2::Shape s) {
  switch (s) {
    case Cone2::Shape::zero: return "none";
    case Cone2::Shape::ray: return "direction";
    case Cone2::Shape::wedge: return "arc";
    case Cone2::Shape::half_plane: return "half-circle";
    case Cone2::Shape::line: return "antipodal pair";
    case Cone2::Shape::plane: return "whole circle";
  }
  return "?";
}

const char* shape_name(Region::Shape s) {
  switch (s) {
    case Region::Shape::empty: return "empty";
    case Region::Shape::point: return "point";
    case Region::Shape::segment: return "segment";
    case Region::Shape::ray: return "ray";
    case Region::Shape::line: return "line";
    case Region::Shape::strip: return "strip";
    case Region::Shape::half_plane: return "half-plane";
    case Region::Shape::wedge: return "wedge";
    case Region::Shape::polygon: return "polygon";
    case Region::Shape::unbounded_polygon: return "unbounded polygon";
    case Region::Shape::plane: return "plane";
  }
  return "?";
}

bool Region::full_dimensional() const {
  switch (shape) {
    case Shape::strip: case Shape::half_plane: case Shape::wedge: case Shape::polygon:
    case Shape::unbounded_polygon: case Shape::plane:
      return true;
    default:
      return false;
  }
}

Vec2 primitive2(const Rational& x, const Rational& y) {
  const std::array<Integer, 2> d = primitive(x, y);
  return {Rational(d[0]), Rational(d[1])};
}

Cone2 cone_hull(const std::vector<Vec2>& dirs) {
  std::vector<Vec2> u;
  for (const Vec2& d : dirs)
    if (!is_zero(d)) u.push_back(primitive2(d.x, d.y));
  Cone2 c;
  if (u.empty()) return c;
  std::sort(u.begin(), u.end(), angle_less);
  u.erase(std::unique(u.begin(), u.end(), same), u.end());
  const std::size_t m = u.size();
  if (m == 1) {
    c.shape = Cone2::Shape::ray;
    c.extreme = u;
    return c;
  }
  // Gaps between angularly consecutive directions: > 180° (cross < 0), = 180° (opposite), < 180°.
  std::size_t halves = 0, half_at = 0;
  for (std::size_t j = 0; j < m; ++j) {
    const Vec2& a = u[j];
    const Vec2& b = u[(j + 1) % m];
    const int s = sgn(cross(a, b));
    if (s < 0) {  // the one gap wider than a half-turn: the cone is the rest, from b round to a
      c.shape = Cone2::Shape::wedge;
      c.extreme = {b, a};
      return c;
    }
    if (s == 0) {  // distinct primitive directions: opposite
      ++halves;
      half_at = j;
    }
  }
  if (halves >= 2) {
    c.shape = Cone2::Shape::line;
    c.extreme = {u[0], u[1]};
  } else if (halves == 1) {
    const Vec2 d = u[(half_at + 1) % m];  // the cone runs from d counter-clockwise to −d
    c.shape = Cone2::Shape::half_plane;
    c.extreme = {d, rot90(d), neg(d)};
  } else {
    c.shape = Cone2::Shape::plane;
  }
  return c;
}

bool contains(const Cone2& c, const Vec2& d) {
  switch (c.shape) {
    case Cone2::Shape::zero: return false;
    case Cone2::Shape::plane: return true;
    case Cone2::Shape::ray: return cross(c.extreme[0], d) == 0 && dot(c.extreme[0], d) > 0;
    case Cone2::Shape::line: return cross(c.extreme[0], d) == 0;
    case Cone2::Shape::half_plane: return cross(c.extreme[0], d) >= 0;
    case Cone2::Shape::wedge: return cross(c.extreme[0], d) >= 0 && cross(d, c.extreme[1]) >= 0;
  }
  return false;
}

Region region_of(std::vector<Vec2> points, const Cone2& cone) {
  Region r;
  if (points.empty()) return r;
  switch (cone.shape) {
    case Cone2::Shape::zero:
      return bounded_hull(std::move(points));
    case Cone2::Shape::plane:
      r.shape = Region::Shape::plane;
      r.vertices = {Vec2{0, 0}};
      r.directions = {Vec2{1, 0}, Vec2{0, 1}, Vec2{-1, 0}, Vec2{0, -1}};
      return r;
    case Cone2::Shape::line: {
      // The strip between the extreme points across d (a line when they coincide).
      const Vec2 d = cone.extreme[0], e = rot90(d);
      std::size_t lo = 0, hi = 0;
      for (std::size_t i = 1; i < points.size(); ++i) {
        if (dot(e, points[i]) < dot(e, points[lo])) lo = i;
        if (dot(e, points[i]) > dot(e, points[hi])) hi = i;
      }
      r.directions = cone.extreme;
      if (dot(e, points[lo]) == dot(e, points[hi])) {
        r.shape = Region::Shape::line;
        r.vertices = {points[lo]};
      } else {
        r.shape = Region::Shape::strip;
        r.vertices = {points[lo], points[hi]};
      }
      return r;
    }
    case Cone2::Shape::half_plane: {
      const Vec2 n = cone.extreme[1];
      std::size_t lo = 0;
      for (std::size_t i = 1; i < points.size(); ++i)
        if (dot(n, points[i]) < dot(n, points[lo])) lo = i;
      r.shape = Region::Shape::half_plane;
      r.vertices = {points[lo]};
      r.directions = cone.extreme;
      return r;
    }
    case Cone2::Shape::ray:
    case Cone2::Shape::wedge: {
      points = dedup(std::move(points));
      r.vertices = pointed_corners(points, cone);
      r.directions = cone.extreme;
      const bool one = r.vertices.size() == 1;
      r.shape = cone.shape == Cone2::Shape::ray ? (one ? Region::Shape::ray : Region::Shape::unbounded_polygon)
                                                : (one ? Region::Shape::wedge : Region::Shape::unbounded_polygon);
      return r;
    }
  }
  return r;
}

namespace {

// D of the file comment: (X, Y) parts of the generators on Z = 0 and of the Z = 0 combinations.
std::vector<Vec2> crossings(const std::vector<Vec3q>& g, bool cyclic_pointed) {
  std::vector<Vec2> d;
  const auto combine = [&](const Vec3q& a, const Vec3q& b) {  // Z_a > 0 > Z_b
    d.push_back({-b[2] * a[0] + a[2] * b[0], -b[2] * a[1] + a[2] * b[1]});
  };
  const std::size_t K = g.size();
  for (std::size_t i = 0; i < K; ++i)
    if (g[i][2] == 0) d.push_back({g[i][0], g[i][1]});
  if (cyclic_pointed) {
    for (std::size_t i = 0; i < K && K >= 2; ++i) {
      const Vec3q& a = g[i];
      const Vec3q& b = g[(i + 1) % K];
      if (a[2] > 0 && b[2] < 0) combine(a, b);
      if (a[2] < 0 && b[2] > 0) combine(b, a);
    }
  } else {
    for (const Vec3q& a : g)
      if (a[2] > 0)
        for (const Vec3q& b : g)
          if (b[2] < 0) combine(a, b);
  }
  return d;
}

}  // namespace

Region slice_front(const std::vector<Vec3q>& gens, bool cyclic_pointed) {
  std::vector<Vec2> pts;
  for (const Vec3q& g : gens)
    if (g[2] > 0) pts.push_back({g[0] / g[2], g[1] / g[2]});
  if (pts.empty()) return Region{};
  return region_of(std::move(pts), cone_hull(crossings(gens, cyclic_pointed)));
}

Cone2 slice_infinity(const std::vector<Vec3q>& gens, bool cyclic_pointed) {
  return cone_hull(crossings(gens, cyclic_pointed));
}

std::vector<Vec3q> negated(std::vector<Vec3q> gens) {
  for (Vec3q& g : gens)
    for (Rational& c : g) c = -c;
  return gens;
}

}  // namespace wrenchkit
