// [CG-1] The CGAL face of the exact API (opt-in: include this header and link wrenchkit::cgal; docs/design.md
// "CGAL and Boost", docs/cmake-package.md). The engine itself never includes CGAL: this is the one public header
// that does, and no other public header includes it (tests/check_walls.cmake).
//
// Everything here converts the engine's exact answers into CGAL objects on CGAL's exact kernel Epeck (with
// CGAL_USE_GMPXX its exact number type is GMP's mpq_class, the engine's Rational), and back, without rounding:
// rationals in, rationals out (tests/cgal_face_test.cpp checks every conversion both ways).
//   * A planar region (moment labels R₊, R₋, the ± set, the force dual's sheets, Reuleaux's regions; theory.md
//     §5–§7) is a Region_2: its corners as a Polygon_2 (for a bounded region the region itself, counter-clockwise,
//     convex), its extreme recession directions, its boundary as CGAL segments, rays and lines in
//     counter-clockwise order (what Arrangement_2 with Arr_linear_traits_2 takes), and its H-representation as
//     closed half-planes (the region is the intersection of the positive sides of `half_planes`; what
//     Nef_polyhedron_2(line, INCLUDED) takes). Why not Nef_polyhedron_2 itself: docs/design.md.
//   * A polygonal limit surface LS_in/LS_out (theory.md §12) is a CGAL::Surface_mesh with exact points, one face
//     per facet (a convex polygon, counter-clockwise seen from outside).
//   * A support region [RG-1] (docs/regions.md) is a Polygon_with_holes_2 (outline counter-clockwise, holes
//     clockwise) with its pressure and coefficient beside it; back, it is validated and settled by the scene
//     reader's own settle_region (exact/io/region.h): a bad polygon is the same Input_error.
// Cost: conversions are linear in the size of the answer; the answers themselves are the engine's.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Surface_mesh.h>

#include "exact/io/scene.h"
#include "exact/sliding/limit_surface.h"
#include "exact/statics/force_dual.h"
#include "exact/statics/moment_labels.h"

namespace wrenchkit::cgal {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Kernel::FT;
using Point_2 = Kernel::Point_2;
using Vector_2 = Kernel::Vector_2;
using Segment_2 = Kernel::Segment_2;
using Ray_2 = Kernel::Ray_2;
using Line_2 = Kernel::Line_2;
using Polygon_2 = CGAL::Polygon_2<Kernel>;
using Polygon_with_holes_2 = CGAL::Polygon_with_holes_2<Kernel>;
using Point_3 = Kernel::Point_3;
using Surface_mesh = CGAL::Surface_mesh<Point_3>;

// Exact conversions between the engine's numbers and CGAL's (no rounding either way).
FT to_ft(const Rational& q);
Rational to_rational(const FT& x);
Point_2 to_point_2(const Vec2& p);
Vec2 to_vec2(const Point_2& p);
Vec2 to_vec2(const Vector_2& v);
Point_3 to_point_3(const Vec3q& p);
Vec3q to_vec3q(const Point_3& p);

// A piece of a region's boundary: a segment between two corners, a ray from a corner (CGAL rays start at their
// source: the incoming ray of an unbounded region points away from its corner too), or a whole line.
using Boundary_piece = std::variant<Segment_2, Ray_2, Line_2>;

// A closed convex region of the plane (exact/statics/planar_region.h: Region), as CGAL objects.
//   shape        the engine's classification (empty, point, segment, ray, line, strip, half_plane, wedge, polygon,
//                unbounded_polygon, plane)
//   corners      Region::vertices in order: for a bounded region the region itself (polygon: a convex, simple,
//                counter-clockwise Polygon_2; a point or a segment: 1 or 2 vertices); unbounded: the corners
//                between the incoming and the leaving ray; no corners: a point of each boundary line
//   directions   Region::directions: the extreme recession directions, counter-clockwise, primitive integers
//   boundary     the boundary counter-clockwise (the region on the left when walked): segments between corners;
//                for an unbounded region first the incoming ray (from corners[0] along directions.back()), last
//                the leaving ray (from the last corner along directions.front()); lines for lines, strips and
//                half-planes (oriented with the region on their positive side). A lower-dimensional region
//                (point, segment, ray, line) is its own boundary: {}, {segment}, {ray}, {line}.
//   half_planes  the region = ∩ of the closed positive (left) sides of these lines; none for the plane; the
//                empty region is two opposite disjoint half-planes.
struct Region_2 {
  Region::Shape shape = Region::Shape::empty;
  Polygon_2 corners;
  std::vector<Vector_2> directions;
  std::vector<Boundary_piece> boundary;
  std::vector<Line_2> half_planes;
  bool empty() const { return shape == Region::Shape::empty; }
  bool bounded() const { return directions.empty(); }
  // Is p in the closed region? Exact (the signs of p against `half_planes`).
  bool has_on(const Point_2& p) const;
};
Region_2 to_cgal(const Region& r);
Region to_region(const Region_2& r);  // the exact inverse of to_cgal: the same corners and directions

// A cone of directions (Cone2: the labeled points at infinity, the dual's arc at infinity), by its extreme
// directions counter-clockwise, and as the region of vectors it is (a region at the origin: zero → the point 0).
struct Cone_2 {
  Cone2::Shape shape = Cone2::Shape::zero;
  std::vector<Vector_2> extreme;
  Region_2 region;
};
Cone_2 to_cgal(const Cone2& c);

// Moment labels [LB-3] as CGAL objects: R₊ (counter-clockwise rotation centres), R₋ (clockwise), the ± set
// (none → empty, a point, a line, the plane) and the labeled directions at infinity (translations).
struct Labels_2 {
  Region_2 plus, minus, both;
  Cone_2 infinity;
  bool nothing_labeled = false;  // force closure (theory.md §5.5)
};
Labels_2 to_cgal(const Moment_labels& l);
Labels_2 moment_labels_2(const Scene& scene, Reading reading = Reading::friction, Mode mode = Mode::exact);
// Reuleaux's feasible rotation centres (theory.md §7): the labels of the frictionless reading.
Labels_2 reuleaux_regions_2(const Scene& scene, Mode mode = Mode::exact);

// The force dual [LB-4] as CGAL objects: its front and back sheets, its arc at infinity, the dual points of the
// generators (dual_point: sheet '+', '-', 'i' or '0'), and about a reference point inside R₊ (§6.2) the ordinary
// dual polygon.
struct Dual_point_2 {
  char sheet = '+';
  Point_2 at;  // a point ('+', '-'), a direction as a point ('i'), the origin ('0')
};
struct Force_dual_2 {
  bool covers_all = false;
  Region_2 plus_sheet, minus_sheet;
  Cone_2 infinity;
  std::vector<Dual_point_2> generators;
  bool has_reference = false;
  Point_2 reference;
  Region_2 about_reference;
};
Force_dual_2 to_cgal(const Force_dual& d);
Force_dual_2 force_dual_2(const Scene& scene, Reading reading = Reading::friction, Mode mode = Mode::exact);

// [LS-2] A polytope as a Surface_mesh with exact points: vertex i is P.vertices[i], face k is P.facets[k]'s vertex
// cycle (counter-clockwise seen from outside). A flat polytope (one support point) has its two sides as two
// faces with opposite orientations; the zero polytope one isolated vertex.
Surface_mesh to_surface_mesh(const Ls_polytope& P);
// Back, exactly: the vertices in index order and each face's vertex indices.
std::vector<Vec3q> mesh_vertices(const Surface_mesh& m);
std::vector<std::vector<int>> mesh_faces(const Surface_mesh& m);

// The certified limit-surface polytopes of the scene's support with N = sides directions [LS-1]–[LS-2]
// (every support force must be given: std::invalid_argument otherwise; sides even, 4 … kMaxSides).
struct Limit_surface_meshes {
  Surface_mesh inner, outer;
  Rational lambda_squared;  // λ·LS ⊆ LS_in ⊆ LS ⊆ LS_out ⊆ LS/λ
  int dimension = 3;
};
Limit_surface_meshes limit_surface_meshes(const Scene& scene, int sides);

// [RG-1] A support region (Support_region, exact/io/scene.h; docs/regions.md) as CGAL objects: the polygon with
// holes, and beside it its pressure and coefficient as written (nothing settled: back, settle_region recomputes
// area, W_R and the moments exactly).
//   polygon   the outer boundary counter-clockwise, each hole clockwise (what CGAL's polygon-with-holes functions
//             expect, e.g. the Boolean set operations); to_cgal gives the region's settled rings
//   uniform   true: the pressure is uniform, F/area, with F = force > 0; false: p(x, y) = a + b·x + c·y with
//             (a, b, c) = linear, ≥ 0 on the region
//   mu        its own coefficient, else the support's
struct Support_region_2 {
  Polygon_with_holes_2 polygon;
  bool uniform = true;
  FT force;
  std::array<FT, 3> linear;
  std::optional<FT> mu;
};
// Forward: a settled region (read_scene settles every region) gives its rings; one built in code and not settled
// yet is settled first (Input_error naming `path`, as below).
Support_region_2 to_cgal(const Support_region& r, const std::string& path = "region");
// Every region of the support, in order (none when the scene has no support).
std::vector<Support_region_2> support_regions_2(const Support& s);
std::vector<Support_region_2> support_regions_2(const Scene& scene);
// Back, exactly (rationals out): the region as input (outline = the outer boundary, holes = the holes, as the
// polygon has them; the pressure and mu), validated and settled by settle_region like a region of a scene, so a
// bad polygon (fewer than 3 vertices, not simple, a hole that meets the outline or another hole or lies outside,
// a negative pressure at a vertex, a force ≤ 0) throws the scene reader's Input_error, named by `path`
// (e.g. "region.holes[0]: is not inside the outline …"); a negative mu: "`path`.mu: … is negative". No input
// limits are applied (--max-region-vertices is the command's).
Support_region to_support_region(const Support_region_2& r, const std::string& path = "region");
// A whole support's regions, named "support.regions[i]" as the scene reader names them.
std::vector<Support_region> to_support_regions(const std::vector<Support_region_2>& r);

}  // namespace wrenchkit::cgal
