// The CGAL face of the exact API (exact/cgal/cgal.h [CG-1]) and the mesh files written through CGAL's IO
// (exact/cgal/mesh_io.h [CG-2]): exact round trips (rationals in, rationals out), and every mesh file read back by
// CGAL's own reader (CGAL::IO::read_polygon_mesh) with the same vertices, faces and properties.
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "exact/cgal/cgal.h"
#include "exact/cgal/mesh_io.h"
#include "exact/io/input_error.h"
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
