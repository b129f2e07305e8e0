// [CG-1] The CGAL face of the exact API (exact/cgal/cgal.h). The only translation unit of wrenchkit::cgal: CGAL's
// headers are parsed once for the whole face (docs/benchmarks.md, "Performance notes": compile cost).
#include "exact/cgal/cgal.h"

#include <stdexcept>

#include "exact/io/input_error.h"
#include "exact/io/region.h"
#include "exact/statics/generators.h"

namespace wrenchkit::cgal {

FT to_ft(const Rational& q) { return FT(q); }
Rational to_rational(const FT& x) { return CGAL::exact(x); }
Point_2 to_point_2(const Vec2& p) { return Point_2(to_ft(p.x), to_ft(p.y)); }
Vec2 to_vec2(const Point_2& p) { return {to_rational(p.x()), to_rational(p.y())}; }
Vec2 to_vec2(const Vector_2& v) { return {to_rational(v.x()), to_rational(v.y())}; }
Point_3 to_point_3(const Vec3q& p) { return Point_3(to_ft(p[0]), to_ft(p[1]), to_ft(p[2])); }
Vec3q to_vec3q(const Point_3& p) { return {to_rational(p.x()), to_rational(p.y()), to_rational(p.z())}; }

namespace {

Vector_2 to_vector_2(const Vec2& v) { return Vector_2(to_ft(v.x), to_ft(v.y)); }

// The closed half-plane {x : u·x ≥ u·p} (u ≠ 0) as the positive side of a line.
Line_2 at_least(const Vector_2& u, const Point_2& p) {
  return Line_2(u.x(), u.y(), -(u.x() * p.x() + u.y() * p.y()));
}

}  // namespace

bool Region_2::has_on(const Point_2& p) const {
  for (const Line_2& l : half_planes)
    if (l.oriented_side(p) == CGAL::ON_NEGATIVE_SIDE) return false;
  return true;
}

Region_2 to_cgal(const Region& r) {
  using S = Region::Shape;
  Region_2 c;
  c.shape = r.shape;
  std::vector<Point_2> v;
  for (const Vec2& p : r.vertices) v.push_back(to_point_2(p));
  c.corners = Polygon_2(v.begin(), v.end());
  for (const Vec2& d : r.directions) c.directions.push_back(to_vector_2(d));
  const std::vector<Vector_2>& d = c.directions;
  auto& h = c.half_planes;
  auto& b = c.boundary;
  switch (r.shape) {
    case S::empty:  // x ≥ 1 and x ≤ 0
      h = {Line_2(1, 0, -1), Line_2(-1, 0, 0)};
      break;
    case S::plane:
      break;
    case S::point:
      h = {at_least(Vector_2(1, 0), v[0]), at_least(Vector_2(-1, 0), v[0]), at_least(Vector_2(0, 1), v[0]),
           at_least(Vector_2(0, -1), v[0])};
      break;
    case S::segment:
      h = {Line_2(v[0], v[1]), Line_2(v[1], v[0]), at_least(v[1] - v[0], v[0]), at_least(v[0] - v[1], v[1])};
      b = {Segment_2(v[0], v[1])};
      break;
    case S::ray:
      h = {Line_2(v[0], d[0]), Line_2(v[0], -d[0]), at_least(d[0], v[0])};
      b = {Ray_2(v[0], d[0])};
      break;
    case S::line:
      h = {Line_2(v[0], d[0]), Line_2(v[0], -d[0])};
      b = {Line_2(v[0], d[0])};
      break;
    case S::strip:  // v[0] on the side of −rot90(d), v[1] on the side of rot90(d) (planar_region.cpp)
      h = {Line_2(v[0], d[0]), Line_2(v[1], -d[0])};
      b = {h[0], h[1]};
      break;
    case S::half_plane:  // directions [d, rot90 d, −d]: the side of rot90(d)
      h = {Line_2(v[0], d[0])};
      b = {h[0]};
      break;
    case S::wedge:  // apex v[0], directions [lo, hi] with lo × hi > 0
      h = {Line_2(v[0], d[0]), Line_2(v[0], -d.back())};
      b = {Ray_2(v[0], d.back()), Ray_2(v[0], d[0])};
      break;
    case S::polygon:
      for (std::size_t i = 0; i < v.size(); ++i) {
        const Point_2& p = v[i];
        const Point_2& q = v[(i + 1) % v.size()];
        h.push_back(Line_2(p, q));
        b.push_back(Segment_2(p, q));
      }
      break;
    case S::unbounded_polygon:  // in along directions.back() to v[0], the chain, out along directions.front()
      h.push_back(Line_2(v[0], -d.back()));
      b.push_back(Ray_2(v[0], d.back()));
      for (std::size_t i = 0; i + 1 < v.size(); ++i) {
        h.push_back(Line_2(v[i], v[i + 1]));
        b.push_back(Segment_2(v[i], v[i + 1]));
      }
      h.push_back(Line_2(v.back(), d.front()));
      b.push_back(Ray_2(v.back(), d.front()));
      break;
  }
  return c;
}

Region to_region(const Region_2& c) {
  Region r;
  r.shape = c.shape;
  for (const Point_2& p : c.corners.vertices()) r.vertices.push_back(to_vec2(p));
  for (const Vector_2& d : c.directions) r.directions.push_back(to_vec2(d));
  return r;
}

Cone_2 to_cgal(const Cone2& k) {
  Cone_2 c;
  c.shape = k.shape;
  for (const Vec2& d : k.extreme) c.extreme.push_back(to_vector_2(d));
  c.region = to_cgal(region_of({Vec2{0, 0}}, k));
  return c;
}

namespace {

Region both_region(const Both_set& b) {
  Region r;
  switch (b.kind) {
    case Both_set::Kind::none: break;
    case Both_set::Kind::point:
      r.shape = Region::Shape::point;
      r.vertices = {b.point};
      break;
    case Both_set::Kind::line: {
      const Vec2 d = primitive2(b.direction.x, b.direction.y);
      r.shape = Region::Shape::line;
      r.vertices = {b.point};
      r.directions = {d, Vec2{-d.x, -d.y}};
      break;
    }
    case Both_set::Kind::plane:
      r = region_of({Vec2{0, 0}}, cone_hull({Vec2{1, 0}, Vec2{0, 1}, Vec2{-1, 0}, Vec2{0, -1}}));
      break;
  }
  return r;
}

std::vector<Vec3q> wrenches(const Scene& scene, Reading reading) {
  std::vector<Vec3q> w;
  for (const Generator& g : generators(scene, reading)) w.push_back(g.w);
  return w;
}

}  // namespace

Labels_2 to_cgal(const Moment_labels& l) {
  Labels_2 c;
  c.plus = to_cgal(l.plus);
  c.minus = to_cgal(l.minus);
  c.both = to_cgal(both_region(l.both));
  c.infinity = to_cgal(l.infinity);
  c.nothing_labeled = l.nothing_labeled();
  return c;
}

Labels_2 moment_labels_2(const Scene& scene, Reading reading, Mode mode) {
  return to_cgal(moment_labels(scene, reading, mode));
}

Labels_2 reuleaux_regions_2(const Scene& scene, Mode mode) { return moment_labels_2(scene, Reading::frictionless, mode); }

Force_dual_2 to_cgal(const Force_dual& d) {
  Force_dual_2 c;
  c.covers_all = d.covers_all;
  c.plus_sheet = to_cgal(d.plus_sheet);
  c.minus_sheet = to_cgal(d.minus_sheet);
  c.infinity = to_cgal(d.infinity);
  for (const Dual_point& p : d.generators) c.generators.push_back({p.sheet, to_point_2(p.at)});
  c.has_reference = d.reference.has_value();
  if (d.reference) c.reference = to_point_2(*d.reference);
  c.about_reference = to_cgal(d.about_reference);
  return c;
}

Force_dual_2 force_dual_2(const Scene& scene, Reading reading, Mode mode) {
  const std::vector<Vec3q> g = wrenches(scene, reading);
  return to_cgal(force_dual(moment_labels(g, mode), g));
}

Surface_mesh to_surface_mesh(const Ls_polytope& P) {
  Surface_mesh m;
  std::vector<Surface_mesh::Vertex_index> v;
  v.reserve(P.vertices.size());
  for (const Vec3q& p : P.vertices) v.push_back(m.add_vertex(to_point_3(p)));
  std::vector<Surface_mesh::Vertex_index> cycle;
  for (const Ls_facet& f : P.facets) {
    cycle.clear();
    for (const int i : f.vertices) cycle.push_back(v.at(static_cast<std::size_t>(i)));
    if (m.add_face(cycle) == Surface_mesh::null_face())
      throw std::logic_error("to_surface_mesh: a facet does not fit the mesh (not a closed oriented polytope)");
  }
  return m;
}

std::vector<Vec3q> mesh_vertices(const Surface_mesh& m) {
  std::vector<Vec3q> v;
  v.reserve(m.number_of_vertices());
  for (const Surface_mesh::Vertex_index i : m.vertices()) v.push_back(to_vec3q(m.point(i)));
  return v;
}

std::vector<std::vector<int>> mesh_faces(const Surface_mesh& m) {
  std::vector<std::vector<int>> f;
  f.reserve(m.number_of_faces());
  for (const Surface_mesh::Face_index k : m.faces()) {
    std::vector<int> cycle;
    for (const Surface_mesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(k), m))
      cycle.push_back(static_cast<int>(v.idx()));
    f.push_back(std::move(cycle));
  }
  return f;
}

Limit_surface_meshes limit_surface_meshes(const Scene& scene, int sides) {
  if (!scene.support) throw std::invalid_argument("limit_surface_meshes: the scene has no support");
  const Polygonal_ls model(merge_support(*scene.support), make_directions(sides));
  Limit_surface_meshes r;
  r.inner = to_surface_mesh(model.build(Side::inner));
  r.outer = to_surface_mesh(model.build(Side::outer));
  r.lambda_squared = model.directions().lambda_sq;
  r.dimension = model.dimension();
  return r;
}

namespace {

Polygon_2 ring_2(const std::vector<Vec2>& ring) {
  Polygon_2 p;
  for (const Vec2& v : ring) p.push_back(to_point_2(v));
  return p;
}

std::vector<Vec2> ring_of(const Polygon_2& p) {
  std::vector<Vec2> r;
  r.reserve(p.size());
  for (const Point_2& v : p.vertices()) r.push_back(to_vec2(v));
  return r;
}

}  // namespace

Support_region_2 to_cgal(const Support_region& region, const std::string& path) {
  const Support_region* r = &region;
  Support_region settled;
  if (region.rings.empty()) {  // built in code: settle a copy (the rings are oriented there)
    settled = region;
    settle_region(settled, path);
    r = &settled;
  }
  Support_region_2 c;
  c.polygon = Polygon_with_holes_2(ring_2(r->rings.front()));
  for (std::size_t k = 1; k < r->rings.size(); ++k) c.polygon.add_hole(ring_2(r->rings[k]));
  c.uniform = r->uniform;
  if (r->uniform) {
    c.force = to_ft(r->force);
  } else {
    for (int k = 0; k < 3; ++k) c.linear[static_cast<std::size_t>(k)] = to_ft(r->linear[static_cast<std::size_t>(k)]);
  }
  if (r->mu) c.mu = to_ft(*r->mu);
  return c;
}

std::vector<Support_region_2> support_regions_2(const Support& s) {
  std::vector<Support_region_2> c;
  c.reserve(s.regions.size());
  for (std::size_t i = 0; i < s.regions.size(); ++i)
    c.push_back(to_cgal(s.regions[i], "support.regions[" + std::to_string(i) + "]"));
  return c;
}

std::vector<Support_region_2> support_regions_2(const Scene& scene) {
  return scene.support ? support_regions_2(*scene.support) : std::vector<Support_region_2>{};
}

Support_region to_support_region(const Support_region_2& c, const std::string& path) {
  Support_region r;
  r.outline = ring_of(c.polygon.outer_boundary());
  for (const Polygon_2& h : c.polygon.holes()) r.holes.push_back(ring_of(h));
  r.uniform = c.uniform;
  if (c.uniform) {
    r.force = to_rational(c.force);
  } else {
    for (std::size_t k = 0; k < 3; ++k) r.linear[k] = to_rational(c.linear[k]);
  }
  if (c.mu) {
    r.mu = to_rational(*c.mu);
    if (*r.mu < 0) throw Input_error(path + ".mu: " + to_string(*r.mu) + " is negative (must be >= 0)");
  }
  settle_region(r, path);
  return r;
}

std::vector<Support_region> to_support_regions(const std::vector<Support_region_2>& c) {
  std::vector<Support_region> r;
  r.reserve(c.size());
  for (std::size_t i = 0; i < c.size(); ++i)
    r.push_back(to_support_region(c[i], "support.regions[" + std::to_string(i) + "]"));
  return r;
}

}  // namespace wrenchkit::cgal
