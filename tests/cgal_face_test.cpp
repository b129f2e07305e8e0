// The CGAL face of the exact API (exact/cgal/cgal.h [CG-1]) and the mesh files written through CGAL's IO
// (exact/cgal/mesh_io.h [CG-2]): exact round trips (rationals in, rationals out), and every mesh file read back by
// CGAL's own reader (CGAL::IO::read_polygon_mesh) with the same vertices, faces and properties. Support regions
// [RG-1] as Polygon_with_holes_2 and back, with CGAL's polygon area and Green's boundary integrals as the
// independent oracle of the engine's exact area, W and moments (which come from a triangulation).
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "exact/cgal/cgal.h"
#include "exact/cgal/mesh_io.h"
#include "exact/io/input_error.h"
#include "exact/io/region.h"
#include "exact/io/scene_writer.h"
#include "exact/pipeline/answer_json.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

using namespace cgal;
namespace fs = std::filesystem;

Scene golden(const std::string& name) {
  return read_scene(test::read_text(test::source_dir() + "/tests/golden/" + name + ".scene.json"), Input_limits{});
}

// Two cycles are the same up to where they start.
bool same_cycle(const std::vector<int>& a, const std::vector<int>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    bool ok = true;
    for (std::size_t i = 0; i < a.size() && ok; ++i) ok = a[(k + i) % a.size()] == b[i];
    if (ok) return true;
  }
  return a.empty();
}

Polygonal_ls model_of(const Scene& s, int sides) { return Polygonal_ls(merge_support(*s.support), make_directions(sides)); }

TEST(CgalFace, NumbersAndPointsConvertExactly) {
  for (const char* t : {"0", "-7", "1/3", "-22/7", "123456789012345678901234567890/7", "1/10000000000000000000000001"}) {
    const Rational q(t);
    EXPECT_EQ(to_rational(to_ft(q)), q) << t;
  }
  const Vec2 p{Rational("1/3"), Rational("-5/7")};
  const Vec2 b = to_vec2(to_point_2(p));
  EXPECT_TRUE(b.x == p.x && b.y == p.y);
  const Vec3q v{Rational("1/3"), Rational("10000000000000000000001"), Rational("-1/9")};
  EXPECT_EQ(to_vec3q(to_point_3(v)), v);
  // Exact constructions on the converted values stay exact: the midpoint of 1/3 and 1/6 is 1/4.
  EXPECT_EQ(to_rational(CGAL::midpoint(to_point_2({Rational(1, 3), 0}), to_point_2({Rational(1, 6), 0})).x()),
            Rational(1, 4));
}

// Every region shape: the face's corners, half-planes and boundary agree with the region; the round trip is exact.
TEST(CgalFace, EveryRegionShapeRoundTrips) {
  const auto V = [](const char* x, const char* y) { return Vec2{Rational(x), Rational(y)}; };
  std::vector<Region> shapes;
  shapes.push_back(Region{});
  shapes.push_back(region_of({V("1/3", "2")}, Cone2{}));
  shapes.push_back(region_of({V("0", "0"), V("1/2", "1/3")}, Cone2{}));
  shapes.push_back(region_of({V("0", "0"), V("1", "0"), V("0", "1"), V("1/3", "1/3")}, Cone2{}));
  for (const std::vector<Vec2>& d : std::vector<std::vector<Vec2>>{
           {V("1", "2")}, {V("1", "0"), V("-1", "0")}, {V("1", "0"), V("0", "1"), V("-1", "0")},
           {V("1", "0"), V("1", "1")}, {V("1", "0"), V("0", "1"), V("-1", "0"), V("0", "-1")}}) {
    const Cone2 c = cone_hull(d);
    shapes.push_back(region_of({V("1/2", "1/2")}, c));
    shapes.push_back(region_of({V("1/2", "1/2"), V("3", "-1"), V("-2", "5/3")}, c));
  }
  std::set<Region::Shape> seen;
  for (const Region& r : shapes) {
    SCOPED_TRACE(region_json(r));
    seen.insert(r.shape);
    const Region_2 c = to_cgal(r);
    EXPECT_EQ(region_json(to_region(c)), region_json(r));
    EXPECT_EQ(c.corners.size(), r.vertices.size());
    EXPECT_EQ(c.bounded(), r.bounded());
    if (r.shape == Region::Shape::plane) {
      EXPECT_TRUE(c.half_planes.empty());
    }
    if (r.empty()) {
      EXPECT_FALSE(c.has_on(Point_2(0, 0)) || c.has_on(Point_2(1, 0)) || c.has_on(Point_2(1, 2)));
      continue;
    }
    for (const Point_2& p : c.corners.vertices()) EXPECT_TRUE(c.has_on(p));
    // Boundary pieces lie in the region: segment ends, ray sources and a point along each ray, a line's point.
    for (const Boundary_piece& b : c.boundary) {
      if (const Segment_2* s = std::get_if<Segment_2>(&b)) {
        EXPECT_TRUE(c.has_on(s->source()) && c.has_on(s->target()));
      } else if (const Ray_2* y = std::get_if<Ray_2>(&b)) {
        EXPECT_TRUE(c.has_on(y->source()) && c.has_on(y->point(7)));
      } else {
        const Line_2& l = std::get<Line_2>(b);
        EXPECT_TRUE(c.has_on(l.point(0)) && c.has_on(l.point(-9)) && c.has_on(l.point(9)));
      }
    }
    // Points far along every recession direction stay inside; a point beyond the corners' box in a non-recession
    // direction does not (for bounded regions: any point far away).
    for (const Vector_2& d : c.directions) EXPECT_TRUE(c.has_on(c.corners[0] + 1000 * d));
    if (r.bounded()) {
      EXPECT_FALSE(c.has_on(Point_2(1000, 1001)));
    }
    if (r.shape == Region::Shape::polygon) {
      EXPECT_TRUE(c.corners.is_convex() && c.corners.is_simple());
      EXPECT_EQ(c.corners.orientation(), CGAL::COUNTERCLOCKWISE);
      // The interior: the centroid of the corners is strictly inside every half-plane.
      Vector_2 sum(0, 0);
      for (const Point_2& p : c.corners.vertices()) sum = sum + (p - CGAL::ORIGIN);
      const Point_2 g = CGAL::ORIGIN + sum / static_cast<int>(c.corners.size());
      for (const Line_2& l : c.half_planes) EXPECT_EQ(l.oriented_side(g), CGAL::ON_POSITIVE_SIDE);
    }
  }
  EXPECT_EQ(seen.size(), 11u);  // every Region::Shape
}

TEST(CgalFace, LabelsOfAGoldenScene) {
  // Example 3 of theory.md §5 (a golden scene): closure fails, R₊ is labeled.
  for (const std::string& f : test::scene_files("tests/golden")) {
    SCOPED_TRACE(f);
    const Scene s = read_scene(test::read_text(f), Input_limits{});
    const Moment_labels l = moment_labels(s, Reading::friction);
    const Labels_2 c = moment_labels_2(s);
    EXPECT_EQ(region_json(to_region(c.plus)), region_json(l.plus));
    EXPECT_EQ(region_json(to_region(c.minus)), region_json(l.minus));
    EXPECT_EQ(c.nothing_labeled, l.nothing_labeled());
    const Labels_2 r = reuleaux_regions_2(s);
    EXPECT_EQ(region_json(to_region(r.plus)), region_json(moment_labels(s, Reading::frictionless).plus));
    const Force_dual_2 d = force_dual_2(s);
    EXPECT_EQ(d.covers_all, l.nothing_labeled());
    EXPECT_EQ(d.generators.size(), generators(s, Reading::friction).size());
  }
}

TEST(CgalFace, PolytopesRoundTripAsSurfaceMeshes) {
  for (const char* name : {"barbell", "single_point", "zero_friction", "coincident_collinear", "ten_points"}) {
    SCOPED_TRACE(name);
    const Scene s = golden(std::string("limit_surface/") + name);
    const Polygonal_ls model = model_of(s, 8);
    for (Side side : {Side::inner, Side::outer}) {
      const Ls_polytope P = model.build(side);
      const Surface_mesh m = to_surface_mesh(P);
      EXPECT_TRUE(m.is_valid(false));
      EXPECT_EQ(mesh_vertices(m), P.vertices);
      const std::vector<std::vector<int>> f = mesh_faces(m);
      ASSERT_EQ(f.size(), P.facets.size());
      for (std::size_t k = 0; k < f.size(); ++k) EXPECT_TRUE(same_cycle(f[k], P.facets[k].vertices)) << k;
      if (P.dimension >= 2) {
        EXPECT_TRUE(CGAL::is_closed(m));
      }
      if (P.dimension == 3) {  // Euler: V − E + F = 2
        EXPECT_EQ(static_cast<long>(m.number_of_vertices()) - static_cast<long>(m.number_of_edges()) +
                      static_cast<long>(m.number_of_faces()),
                  2);
        EXPECT_EQ(m.number_of_edges(), P.edges);
      }
    }
  }
  const Limit_surface_meshes b = limit_surface_meshes(golden("limit_surface/barbell"), 6);
  EXPECT_EQ(b.dimension, 3);
  EXPECT_TRUE(b.lambda_squared > Rational(7, 10) && b.lambda_squared < 1);  // N = 6: 6561/8770
  EXPECT_THROW(limit_surface_meshes(golden("block_corner_mu_0"), 6), std::invalid_argument);
}

// ---- support regions as Polygon_with_holes_2 [RG-1] ------------------------------------------------------------

Vec2 V(const char* x, const char* y) { return {Rational(x), Rational(y)}; }

bool same_ring(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
  return true;
}

bool same_polygon(const Polygon_with_holes_2& a, const Polygon_with_holes_2& b) {
  if (a.outer_boundary() != b.outer_boundary() || a.number_of_holes() != b.number_of_holes()) return false;
  return std::equal(a.holes_begin(), a.holes_end(), b.holes_begin());
}

// Everything a region is, as written and as settled, compared exactly.
void expect_same_region(const Support_region& a, const Support_region& b) {
  ASSERT_EQ(a.rings.size(), b.rings.size());
  for (std::size_t k = 0; k < a.rings.size(); ++k) EXPECT_TRUE(same_ring(a.rings[k], b.rings[k])) << "ring " << k;
  EXPECT_EQ(a.uniform, b.uniform);
  if (a.uniform) {
    EXPECT_EQ(a.force, b.force);
  } else {
    EXPECT_EQ(a.linear, b.linear);
  }
  EXPECT_EQ(a.mu, b.mu);
  EXPECT_EQ(a.pressure, b.pressure);
  EXPECT_EQ(a.area, b.area);
  EXPECT_EQ(a.total, b.total);
  EXPECT_TRUE(a.moment.x == b.moment.x && a.moment.y == b.moment.y);
  EXPECT_EQ(a.second, b.second);
  EXPECT_EQ(a.triangles.size(), b.triangles.size());
}

// The oracle: CGAL's signed polygon area, and Green's theorem on the boundary (outline counter-clockwise, holes
// clockwise: their integrals subtract) for ∫ {1, x, y, x², xy, y²} dA, in CGAL's exact numbers. Independent of the
// engine's triangulation and quadrature rules.
struct Green {
  FT area, x, y, xx, xy, yy;
};
Green green(const Polygon_with_holes_2& p) {
  Green g{CGAL::polygon_area_2(p.outer_boundary().vertices_begin(), p.outer_boundary().vertices_end(), Kernel()),
          0, 0, 0, 0, 0};
  for (const Polygon_2& h : p.holes()) g.area += CGAL::polygon_area_2(h.vertices_begin(), h.vertices_end(), Kernel());
  const auto add = [&g](const Polygon_2& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point_2 &a = ring[i], &b = ring[(i + 1) % ring.size()];
      const FT c = a.x() * b.y() - b.x() * a.y();
      g.x += (a.x() + b.x()) * c / 6;
      g.y += (a.y() + b.y()) * c / 6;
      g.xx += (a.x() * a.x() + a.x() * b.x() + b.x() * b.x()) * c / 12;
      g.yy += (a.y() * a.y() + a.y() * b.y() + b.y() * b.y()) * c / 12;
      g.xy += (a.x() * b.y() + 2 * a.x() * a.y() + 2 * b.x() * b.y() + b.x() * a.y()) * c / 24;
    }
  };
  add(p.outer_boundary());
  for (const Polygon_2& h : p.holes()) add(h);
  return g;
}

// The region's area, W and first moment against the oracle; uniform: the centroid is the polygon's own.
void expect_oracle(const Support_region& r) {
  const Support_region_2 c = to_cgal(r);
  const Green g = green(c.polygon);
  EXPECT_EQ(to_rational(g.area), r.area);
  FT by_polygons = c.polygon.outer_boundary().area();  // Polygon_2::area, the holes' negative (clockwise)
  for (const Polygon_2& h : c.polygon.holes()) by_polygons += h.area();
  EXPECT_EQ(to_rational(by_polygons), r.area);
  FT a, b, cc;
  if (r.uniform) {
    a = to_ft(r.force) / g.area;
    EXPECT_EQ(to_rational(g.x / g.area), r.moment.x / r.total);  // the centre of pressure is the centroid
    EXPECT_EQ(to_rational(g.y / g.area), r.moment.y / r.total);
  } else {
    a = c.linear[0], b = c.linear[1], cc = c.linear[2];
  }
  EXPECT_EQ(to_rational(a * g.area + b * g.x + cc * g.y), r.total);
  EXPECT_EQ(to_rational(a * g.x + b * g.xx + cc * g.xy), r.moment.x);
  EXPECT_EQ(to_rational(a * g.y + b * g.xy + cc * g.yy), r.moment.y);
}

// The forward form is what CGAL expects and holds the settled rings exactly; back it is the same region; the
// polygon given back is the same polygon.
void expect_round_trip(const Support_region& r) {
  const Support_region_2 c = to_cgal(r);
  const Polygon_2& outer = c.polygon.outer_boundary();
  EXPECT_TRUE(outer.is_simple());
  EXPECT_EQ(outer.orientation(), CGAL::COUNTERCLOCKWISE);
  std::vector<Vec2> outline;
  for (const Point_2& p : outer.vertices()) outline.push_back(to_vec2(p));
  EXPECT_TRUE(same_ring(outline, r.rings[0]));
  ASSERT_EQ(c.polygon.number_of_holes() + 1, r.rings.size());
  std::size_t k = 1;
  for (const Polygon_2& h : c.polygon.holes()) {
    EXPECT_TRUE(h.is_simple());
    EXPECT_EQ(h.orientation(), CGAL::CLOCKWISE);
    ASSERT_EQ(h.size(), r.rings[k].size());
    std::vector<Vec2> hole;
    for (const Point_2& p : h.vertices()) hole.push_back(to_vec2(p));
    EXPECT_TRUE(same_ring(hole, r.rings[k])) << "hole " << k - 1;
    ++k;
  }
  EXPECT_EQ(c.uniform, r.uniform);
  const Support_region back = to_support_region(c);
  expect_same_region(back, r);
  EXPECT_TRUE(same_polygon(to_cgal(back).polygon, c.polygon));
}

Scene region_scene(const std::string& regions) {
  return read_scene(R"({"wrenchkit": 1, "support": {"mu": "1/2", "regions": [)" + regions + "]}}", Input_limits{});
}

TEST(CgalSupportRegions, SquareWithAHole) {
  // A 4 × 4 square, written clockwise, with a 1 × 2 hole written counter-clockwise: CGAL gets them the other way.
  const Scene s = region_scene(R"({"outline": [[0, 0], [0, 4], [4, 4], [4, 0]],
                                   "holes": [[[1, 1], [2, 1], [2, 3], [1, 3]]], "pressure": "uniform", "force": 7})");
  const Support_region& r = s.support->regions[0];
  const std::vector<Support_region_2> c = support_regions_2(s);
  ASSERT_EQ(c.size(), 1u);
  const Polygon_with_holes_2& p = c[0].polygon;
  EXPECT_EQ(p.outer_boundary().orientation(), CGAL::COUNTERCLOCKWISE);
  ASSERT_EQ(p.number_of_holes(), 1u);
  EXPECT_EQ(p.holes_begin()->orientation(), CGAL::CLOCKWISE);
  EXPECT_EQ(p.outer_boundary().area(), FT(16));
  EXPECT_EQ(p.holes_begin()->area(), FT(-2));
  EXPECT_TRUE(c[0].uniform);
  EXPECT_EQ(c[0].force, FT(7));
  EXPECT_FALSE(c[0].mu);  // the support's 1/2 applies
  EXPECT_EQ(r.area, 14);
  // The centroid, by hand: (16·(2, 2) − 2·(3/2, 2)) / 14 = (29/14, 2).
  EXPECT_EQ(r.moment.x / r.total, Rational(29, 14));
  EXPECT_EQ(r.moment.y / r.total, 2);
  expect_round_trip(r);
  expect_oracle(r);
  // The whole support back, named as the reader names it; CGAL's polygon (its orientation) is the input back.
  const std::vector<Support_region> back = to_support_regions(c);
  ASSERT_EQ(back.size(), 1u);
  expect_same_region(back[0], r);
  EXPECT_TRUE(same_ring(back[0].outline, r.rings[0]));  // the clockwise outline as written, reversed
  EXPECT_EQ(to_cgal(back[0]).polygon.outer_boundary(), p.outer_boundary());
  // A region built in code and not settled: to_cgal settles a copy.
  Support_region raw;
  raw.outline = r.outline;
  raw.holes = r.holes;
  raw.force = 7;
  EXPECT_TRUE(same_polygon(to_cgal(raw).polygon, p));
}

TEST(CgalSupportRegions, TriangleWithLinearPressureKeepsThePressure) {
  // p = 1 + 2x on the triangle (0, 0), (3, 0), (0, 3): area 9/2, centroid (1, 1), W = 9/2 · p(centroid) = 27/2.
  const Scene s = region_scene(R"({"outline": [[0, 0], [3, 0], [0, 3]], "pressure": {"linear": [1, 2, 0]},
                                   "mu": "1/3"})");
  const Support_region& r = s.support->regions[0];
  const Support_region_2 c = to_cgal(r);
  EXPECT_FALSE(c.uniform);
  EXPECT_EQ(c.linear, (std::array<FT, 3>{FT(1), FT(2), FT(0)}));
  ASSERT_TRUE(c.mu);
  EXPECT_EQ(to_rational(*c.mu), Rational(1, 3));
  EXPECT_EQ(r.total, Rational(27, 2));
  // ∫ x (1 + 2x) dA = A·x̄ + 2 ∫ x² = 9/2 + 2·27/4 = 18: the centre of pressure is at x = 18 / (27/2) = 4/3.
  EXPECT_EQ(r.moment.x / r.total, Rational(4, 3));
  expect_round_trip(r);
  expect_oracle(r);
  const Support_region back = to_support_region(c);
  EXPECT_FALSE(back.uniform);
  EXPECT_EQ(back.linear, (std::array<Rational, 3>{1, 2, 0}));
  EXPECT_EQ(back.total, Rational(27, 2));
}

TEST(CgalSupportRegions, NonDyadicRationalsRoundTripExactly) {
  // Coordinates and pressure in thirds and sevenths (no double holds them), a hole, a linear pressure.
  const Scene s = region_scene(R"({"outline": [["1/3", "2/7"], ["13/3", "2/7"], ["13/3", "30/7"], ["1/3", "30/7"]],
                                   "holes": [[["4/3", "9/7"], ["4/3", "16/7"], ["7/3", "16/7"]]],
                                   "pressure": {"linear": ["2/7", "1/3", "1/21"]}, "mu": "2/7"})");
  const Support_region& r = s.support->regions[0];
  const Support_region_2 c = to_cgal(r);
  bool thirds = false, sevenths = false;
  for (const Point_2& p : c.polygon.outer_boundary().vertices()) {
    thirds = thirds || CGAL::exact(p.x()).get_den() == 3;
    sevenths = sevenths || CGAL::exact(p.y()).get_den() == 7;
  }
  EXPECT_TRUE(thirds && sevenths);
  EXPECT_EQ(to_rational(c.linear[2]), Rational(1, 21));
  // Outline 4 × 4 = 16, the hole a right triangle with legs 1: area 31/2.
  EXPECT_EQ(r.area, Rational(31, 2));
  expect_round_trip(r);
  expect_oracle(r);
  // The CGAL polygon, built by a CGAL user from exact numbers, comes in as the same region.
  Polygon_2 outer;
  for (const Vec2& v : {V("1/3", "2/7"), V("13/3", "2/7"), V("13/3", "30/7"), V("1/3", "30/7")}) outer.push_back(to_point_2(v));
  Polygon_2 hole;
  for (const Vec2& v : {V("7/3", "16/7"), V("4/3", "16/7"), V("4/3", "9/7")}) hole.push_back(to_point_2(v));
  Polygon_with_holes_2 q(outer);
  q.add_hole(hole);
  Support_region_2 in{q, false, FT(0), {to_ft(Rational(2, 7)), to_ft(Rational(1, 3)), to_ft(Rational(1, 21))}, to_ft(Rational(2, 7))};
  expect_same_region(to_support_region(in), r);
}

// The same polygon is the same error through the CGAL face as through the scene reader.
TEST(CgalSupportRegions, BadPolygonsGiveTheReadersError) {
  struct Bad {
    const char* json;  // the region in a scene
    Support_region_2 cgal;
  };
  const auto ring = [](std::initializer_list<std::pair<int, int>> v) {
    Polygon_2 p;
    for (const auto& [x, y] : v) p.push_back(Point_2(x, y));
    return p;
  };
  const auto with_holes = [](Polygon_2 outer, std::vector<Polygon_2> holes) {
    Polygon_with_holes_2 p(outer);
    for (Polygon_2& h : holes) p.add_hole(h);
    return p;
  };
  const Polygon_2 square = ring({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  const std::vector<Bad> bad = {
      {R"({"outline": [[0, 0], [4, 4], [4, 0], [0, 4]], "pressure": "uniform", "force": 1})",
       {with_holes(ring({{0, 0}, {4, 4}, {4, 0}, {0, 4}}), {}), true, FT(1), {}, {}}},
      {R"({"outline": [[0, 0], [4, 0]], "pressure": "uniform", "force": 1})",
       {with_holes(ring({{0, 0}, {4, 0}}), {}), true, FT(1), {}, {}}},
      {R"({"outline": [[0, 0], [4, 0], [4, 4], [0, 4]], "holes": [[[5, 5], [6, 5], [6, 6]]], "pressure": "uniform", "force": 1})",
       {with_holes(square, {ring({{5, 5}, {6, 5}, {6, 6}})}), true, FT(1), {}, {}}},
      {R"({"outline": [[0, 0], [4, 0], [4, 4], [0, 4]], "holes": [[[0, 0], [1, 1], [1, 2]]], "pressure": "uniform", "force": 1})",
       {with_holes(square, {ring({{0, 0}, {1, 1}, {1, 2}})}), true, FT(1), {}, {}}},
      {R"({"outline": [[0, 0], [4, 0], [4, 4], [0, 4]], "holes": [[[1, 1], [3, 1], [3, 3]], [[2, 1], [3, 2], [2, 3]]],
           "pressure": "uniform", "force": 1})",
       {with_holes(square, {ring({{1, 1}, {3, 1}, {3, 3}}), ring({{2, 1}, {3, 2}, {2, 3}})}), true, FT(1), {}, {}}},
      {R"({"outline": [[0, 0], [4, 0], [4, 4], [0, 4]], "pressure": {"linear": [1, -1, 0]}})",
       {with_holes(square, {}), false, FT(0), {FT(1), FT(-1), FT(0)}, {}}},
      {R"({"outline": [[0, 0], [4, 0], [4, 4], [0, 4]], "pressure": "uniform", "force": 0})",
       {with_holes(square, {}), true, FT(0), {}, {}}},
      {R"({"outline": [[0, 0], [4, 0], [4, 4], [0, 4]], "pressure": "uniform", "force": 1, "mu": -1})",
       {with_holes(square, {}), true, FT(1), {}, FT(-1)}},
  };
  for (const Bad& b : bad) {
    SCOPED_TRACE(b.json);
    std::string reader, face;
    try {
      region_scene(b.json);
    } catch (const Input_error& e) {
      reader = e.what();
    }
    try {
      to_support_regions({b.cgal});
    } catch (const Input_error& e) {
      face = e.what();
    }
    EXPECT_NE(reader.find("support.regions[0]"), std::string::npos) << reader;
    EXPECT_EQ(face, reader);
  }
}

// Random simple polygons with holes (fixed seed; WRENCHKIT_SEED to vary): star-shaped rings about a centre, with
// directions of every quadrant and rational radii of unrelated denominators; up to four holes, each inside its
// own box well inside the outline; uniform or linear pressure. Round trips exact, and the oracle agrees.
struct Random_region {
  std::mt19937_64& rng;
  int below(int n) { return static_cast<int>(rng() % static_cast<std::uint64_t>(n)); }
  static Rational frac(int n, int d) {
    Rational q(n, d);
    q.canonicalize();
    return q;
  }
  Rational between(int lo, int hi) {  // a rational in [lo, hi] with a denominator of 1 … 29
    const int den = 1 + below(29);
    return Rational(lo) + frac(below((hi - lo) * den + 1), den);
  }
  // Counter-clockwise directions of a star about `centre` at Chebyshev radii in [lo, hi]; every gap < π.
  std::vector<Vec2> star(const Vec2& centre, const Rational& lo, const Rational& hi, int extra) {
    std::vector<std::pair<int, int>> d = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    for (int i = 0; i < extra; ++i) {
      const int x = below(15) - 7, y = below(15) - 7;
      if (x != 0 || y != 0) d.push_back({x, y});
    }
    const auto half = [](const std::pair<int, int>& v) { return v.second > 0 || (v.second == 0 && v.first > 0) ? 0 : 1; };
    std::sort(d.begin(), d.end(), [&half](const auto& a, const auto& b) {
      if (half(a) != half(b)) return half(a) < half(b);
      return a.first * b.second - a.second * b.first > 0;
    });
    d.erase(std::unique(d.begin(), d.end(), [&half](const auto& a, const auto& b) {
              return half(a) == half(b) && a.first * b.second - a.second * b.first == 0;
            }),
            d.end());
    std::vector<Vec2> out;
    for (const auto& [x, y] : d) {
      const Rational s = (lo + (hi - lo) * frac(below(1000), 999)) / std::max(std::abs(x), std::abs(y));
      out.push_back({centre.x + s * x, centre.y + s * y});
    }
    if (below(2)) std::reverse(out.begin(), out.end());  // written either way
    return out;
  }
  Support_region make() {
    Support_region r;
    // Outline: Euclidean radius ≥ 6 at every vertex, gaps ≤ π/2, so it holds the disc of radius 6·cos(π/4) > 4.
    r.outline = star({0, 0}, between(6, 7), between(8, 10), below(10));
    const Vec2 centres[4] = {{2, 0}, {0, 2}, {-2, 0}, {0, -2}};
    for (int k = 0; k < 4; ++k)
      if (below(2)) {
        const Vec2 c{centres[k].x + frac(below(7) - 3, 29), centres[k].y + frac(below(7) - 3, 23)};
        r.holes.push_back(star(c, Rational(1, 4), Rational(1, 2), below(6)));  // inside c ± 1/2: disjoint, within 3
      }
    r.uniform = below(2) == 0;
    if (r.uniform) {
      r.force = between(1, 50);
    } else {  // |b x + c y| ≤ 20·(1/20) = 1 < a on the outline
      r.linear = {between(1, 3), between(-1, 1) / 20, between(-1, 1) / 20};
    }
    if (below(2)) r.mu = between(0, 1);
    return r;
  }
};

TEST(CgalSupportRegions, RandomPolygonsWithHolesRoundTripAndMatchTheOracle) {
  const std::uint64_t seed = test::seed(17017);
  std::mt19937_64 rng(seed);
  Random_region gen{rng};
  int holes = 0, linear = 0;
  for (int i = 0; i < 300; ++i) {
    Support_region r = gen.make();
    Scene scene;
    scene.support = Support{};
    scene.support->mu = Rational(1, 2);
    scene.support->regions.push_back(r);
    const std::string text = write_scene(scene);
    const std::string tag = "cgal_support_region_" + std::to_string(seed) + "_" + std::to_string(i);
    SCOPED_TRACE(tag + " (WRENCHKIT_SEED=" + std::to_string(seed) + ")");
    ASSERT_NO_THROW(settle_region(r, "region")) << test::dump_failure(text, tag);
    holes += static_cast<int>(r.holes.size());
    linear += r.uniform ? 0 : 1;
    expect_round_trip(r);
    expect_oracle(r);
    // The scene reader's region is the same region, and so is the one the face reads back from CGAL.
    const Scene read = read_scene(text, Input_limits{});
    expect_same_region(read.support->regions[0], r);
    expect_same_region(to_support_regions(support_regions_2(read))[0], r);
    if (HasFailure()) {
      ADD_FAILURE() << "scene dumped to " << test::dump_failure(text, tag);
      return;
    }
  }
  EXPECT_GT(holes, 300);  // the families are all there
  EXPECT_GT(linear, 100);
}

// ---- mesh files through CGAL's IO ------------------------------------------------------------------------------

using Dpoint = CGAL::Simple_cartesian<double>::Point_3;
using Dmesh = CGAL::Surface_mesh<Dpoint>;

fs::path scratch() {
  const fs::path d = test::scratch_dir("cgal_face_test");
  fs::create_directories(d);
  return d;
}

// Writes the mesh bytes to a file named by the format's extension and reads it back with CGAL's reader.
Dmesh read_back(const std::string& bytes, Mesh_format f, const std::string& stem) {
  const std::string ext = f == Mesh_format::off ? ".off" : f == Mesh_format::obj ? ".obj" : ".ply";
  const fs::path p = scratch() / (stem + ext);
  std::ofstream(p, std::ios::binary) << bytes;
  Dmesh m;
  EXPECT_TRUE(CGAL::IO::read_polygon_mesh(p.string(), m)) << p;
  return m;
}

// The mesh read back holds both polytopes: the nearest doubles of every exact coordinate, bit for bit, and every
// facet's cycle, the inner polytope first.
void expect_same_mesh(const Dmesh& m, const Ls_polytope& in, const Ls_polytope& out) {
  ASSERT_EQ(m.number_of_vertices(), in.vertices.size() + out.vertices.size());
  ASSERT_EQ(m.number_of_faces(), in.facets.size() + out.facets.size());
  std::vector<Dpoint> pts;
  for (auto v : m.vertices()) pts.push_back(m.point(v));
  std::size_t i = 0;
  for (const Ls_polytope* P : {&in, &out})
    for (const Vec3q& v : P->vertices) {
      for (int k = 0; k < 3; ++k) ASSERT_EQ(pts[i][k], *nearest_double(v[k])) << "vertex " << i << " " << to_string(v[k]);
      ++i;
    }
  std::vector<std::vector<int>> faces;
  for (auto f : m.faces()) {
    std::vector<int> c;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) c.push_back(static_cast<int>(v.idx()));
    faces.push_back(c);
  }
  std::size_t k = 0;
  const int base = static_cast<int>(in.vertices.size());
  for (const Ls_polytope* P : {&in, &out})
    for (const Ls_facet& f : P->facets) {
      std::vector<int> want = f.vertices;
      if (P == &out)
        for (int& x : want) x += base;
      ASSERT_TRUE(same_cycle(faces[k], want)) << "face " << k;
      ++k;
    }
}

TEST(CgalMeshFiles, EveryFormatReadsBackWithCgal) {
  for (const char* name : {"barbell", "single_point", "zero_friction", "ten_points"}) {
    SCOPED_TRACE(name);
    const Polygonal_ls model = model_of(golden(std::string("limit_surface/") + name), 6);
    const Ls_polytope in = model.build(Side::inner), out = model.build(Side::outer);
    for (Mesh_format f : {Mesh_format::off, Mesh_format::obj, Mesh_format::ply}) {
      SCOPED_TRACE(mesh_format_name(f));
      if (f == Mesh_format::obj && in.facets.empty()) {  // CGAL's OBJ reader refuses a file without faces
        const std::string t = polytopes_mesh(in, out, f, false);
        EXPECT_NE(t.find("\nv 0 0 0\nv 0 0 0\n"), std::string::npos) << t;
        continue;
      }
      const Dmesh m = read_back(polytopes_mesh(in, out, f, false), f, name);
      expect_same_mesh(m, in, out);
      if (HasFatalFailure()) return;
      // Exact coordinates change only OFF (homogeneous integers); OBJ and PLY are the same bytes.
      if (!exact_coordinates_possible(f)) {
        EXPECT_EQ(polytopes_mesh(in, out, f, true), polytopes_mesh(in, out, f, false));
      }
    }
    // PLY: the face property `polytope` and the colours come back through CGAL's PLY reader.
    {
      std::istringstream bytes(polytopes_mesh(in, out, Mesh_format::ply, false));
      Dmesh m;
      std::string comments;
      ASSERT_TRUE(CGAL::IO::read_PLY(bytes, m, comments));
      EXPECT_NE(comments.find("polytope 0 = inner"), std::string::npos) << comments;
      const auto [which, has] = m.property_map<Dmesh::Face_index, std::uint8_t>("f:polytope");
      ASSERT_TRUE(has);
      const auto [color, has_color] = m.property_map<Dmesh::Face_index, CGAL::IO::Color>("f:color");
      ASSERT_TRUE(has_color);
      std::size_t k = 0;
      for (auto f : m.faces()) {
        const bool inner = k++ < in.facets.size();
        EXPECT_EQ(which[f], inner ? 0 : 1);
        EXPECT_EQ(color[f].blue(), inner ? 230 : 51);
      }
    }
  }
}

TEST(CgalMeshFiles, ExactOffHoldsTheRationalsAndCgalReadsIt) {
  const Polygonal_ls model = model_of(golden("limit_surface/barbell"), 8);
  const Ls_polytope in = model.build(Side::inner), out = model.build(Side::outer);
  const std::string text = polytopes_mesh(in, out, Mesh_format::off, true);
  ASSERT_EQ(text.rfind("4OFF\n", 0), 0u);
  // Our own reading of the text: every vertex X Y Z W is exactly the polytope's rational vertex.
  std::istringstream s(text);
  std::string line;
  std::getline(s, line);
  do std::getline(s, line);
  while (!line.empty() && line[0] == '#');
  std::size_t nv = 0, nf = 0;
  std::istringstream(line) >> nv >> nf;
  ASSERT_EQ(nv, in.vertices.size() + out.vertices.size());
  bool some_not_dyadic = false;
  for (const Ls_polytope* P : {&in, &out})
    for (const Vec3q& v : P->vertices) {
      std::string X, Y, Z, W;
      s >> X >> Y >> Z >> W;
      const Integer w(W);
      ASSERT_GT(w, 0);
      const auto q = [&w](const std::string& n) {
        Rational r(Integer(n), w);
        r.canonicalize();
        return r;
      };
      EXPECT_EQ(q(X), v[0]);
      EXPECT_EQ(q(Y), v[1]);
      EXPECT_EQ(q(Z), v[2]);
      for (const Rational& c : v) some_not_dyadic = some_not_dyadic || (c.get_den() & (c.get_den() - 1)) != 0;
    }
  EXPECT_TRUE(some_not_dyadic);  // the exact file says more than doubles can
  // CGAL's reader reads the homogeneous coordinates (dividing in double: the nearest doubles here).
  const Dmesh m = read_back(text, Mesh_format::off, "barbell_exact");
  expect_same_mesh(m, in, out);
}

TEST(CgalMeshFiles, CoordinatesBeyondDoublesAreAnErrorUnlessExact) {
  const std::string text = R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0, 0], "force": "1e400"},
                              {"at": [1, 0], "force": 1}]}})";
  const Polygonal_ls model = model_of(read_scene(text, Input_limits{}), 4);
  const Ls_polytope in = model.build(Side::inner), out = model.build(Side::outer);
  for (Mesh_format f : {Mesh_format::off, Mesh_format::obj, Mesh_format::ply})
    EXPECT_THROW(polytopes_mesh(in, out, f, false), Input_error);
  EXPECT_NO_THROW(polytopes_mesh(in, out, Mesh_format::off, true));
  EXPECT_EQ(coordinates_note(Mesh_format::ply, true), "nearest doubles (PLY has no exact numbers)");
}

}  // namespace
}  // namespace wrenchkit
