// The CGAL face of the installed wrenchkit (wrenchkit::cgal, exact/cgal/cgal.h): computes the moment labels of a
// golden scene, a support region and the limit surface of the barbell, receives them as CGAL objects and checks
// them with CGAL's own functions. Exit 0 on success. Argument: the golden scene tests/golden/two_finger_y9_10_mu1_4.scene.json.
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/convexity_check_3.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "exact/cgal/cgal.h"

namespace PMP = CGAL::Polygon_mesh_processing;
using namespace wrenchkit;

int fail(const char* what) {
  std::printf("cgal consumer: FAILED: %s\n", what);
  return 1;
}

int main(int argc, char** argv) {
  if (argc < 2) return fail("usage: consumer_cgal GOLDEN.scene.json");
  std::ifstream in(argv[1]);
  std::stringstream text;
  text << in.rdbuf();
  const Scene golden = read_scene(text.str(), Input_limits{});

  // Two fingers at (0, 1/2) and (1, 9/10) pushing along ±x with mu = 1/4 (theory.md §8): R+ is the quadrilateral
  // of the fingers and the two meeting points of their friction-cone edge lines (slopes ±1/4):
  // (−3/10, 23/40) and (13/10, 33/40); by the shoelace formula its area is 39/200.
  const cgal::Labels_2 labels = cgal::moment_labels_2(golden);
  const cgal::Polygon_2& plus = labels.plus.corners;
  if (labels.plus.shape != Region::Shape::polygon || !labels.plus.bounded()) return fail("R+ is not a bounded polygon");
  if (!plus.is_simple() || !plus.is_convex() || plus.orientation() != CGAL::COUNTERCLOCKWISE)
    return fail("R+ is not a convex counter-clockwise Polygon_2");
  if (plus.area() != cgal::FT(Rational(39, 200))) return fail("area of R+ is not 39/200");
  if (plus.bounded_side(cgal::Point_2(cgal::FT(Rational(1, 2)), cgal::FT(Rational(7, 10)))) != CGAL::ON_BOUNDED_SIDE)
    return fail("(1/2, 7/10) is not inside R+");
  if (!labels.minus.empty()) return fail("R- is not empty");
  if (!labels.plus.has_on(cgal::Point_2(0, cgal::FT(Rational(1, 2))))) return fail("the finger (0, 1/2) is not in R+");

  // A support region, a 4 × 4 square with a 1 × 2 hole, as a CGAL::Polygon_with_holes_2: CGAL's own areas (the
  // hole clockwise, so negative) give the engine's exact area 14, and the polygon comes back as the same region.
  const Scene foot = read_scene(
      R"({"wrenchkit": 1, "support": {"mu": "1/2", "regions": [{"outline": [[0, 0], [4, 0], [4, 4], [0, 4]],
          "holes": [[[1, 1], [2, 1], [2, 3], [1, 3]]], "pressure": "uniform", "force": 7}]}})",
      Input_limits{});
  const cgal::Support_region_2 region = cgal::support_regions_2(foot).at(0);
  if (region.polygon.outer_boundary().orientation() != CGAL::COUNTERCLOCKWISE ||
      region.polygon.holes_begin()->orientation() != CGAL::CLOCKWISE)
    return fail("the region's outline is not counter-clockwise with a clockwise hole");
  if (region.polygon.outer_boundary().area() + region.polygon.holes_begin()->area() != cgal::FT(14) ||
      foot.support->regions[0].area != 14)
    return fail("the region's area is not 14");
  if (cgal::to_support_region(region).moment.x != foot.support->regions[0].moment.x)
    return fail("the region does not come back from CGAL as itself");

  // The barbell (theory.md §14.2), N = 8: both polytopes as exact Surface_meshes, strongly convex, and the inner
  // one's volume equal to that of CGAL's own hull of every sum of the two summand polygons' vertices.
  const Scene barbell = read_scene(
      R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0, -1], "force": "1/2"}, {"at": [0, 1], "force": "1/2"}]}})",
      Input_limits{});
  const cgal::Limit_surface_meshes ls = cgal::limit_surface_meshes(barbell, 8);
  if (!CGAL::is_closed(ls.inner) || !CGAL::is_strongly_convex_3(ls.inner)) return fail("LS_in is not strongly convex");
  if (!CGAL::is_closed(ls.outer) || !CGAL::is_strongly_convex_3(ls.outer)) return fail("LS_out is not strongly convex");
  cgal::Surface_mesh tin = ls.inner, tout = ls.outer;
  PMP::triangulate_faces(tin);
  PMP::triangulate_faces(tout);
  const cgal::FT vin = PMP::volume(tin), vout = PMP::volume(tout);
  // LS_in = A_1(ρ P_in) ⊕ A_2(ρ P_in) with P_in = conv{u_j} (the N unit directions), ρ = μ f = 1/2 and
  // A_r(f) = (f_x, f_y, r_x f_y − r_y f_x): for r = (0, −1), (0, 1) the sum of u_j and u_k is
  // ρ (u_j + u_k) in force and ρ (u_j,x − u_k,x) in moment. CGAL's hull of all N² sums is LS_in again.
  std::vector<cgal::Point_3> sums;
  const Rational rho(1, 2);
  for (const Vec2& a : make_directions(8).u)
    for (const Vec2& b : make_directions(8).u)
      sums.push_back(cgal::to_point_3({rho * (a.x + b.x), rho * (a.y + b.y), rho * (a.x - b.x)}));
  cgal::Surface_mesh hull;
  CGAL::convex_hull_3(sums.begin(), sums.end(), hull);
  if (PMP::volume(hull) != vin) return fail("volume of LS_in differs from CGAL's hull of the vertex sums");
  const cgal::FT l2 = cgal::to_ft(ls.lambda_squared);
  if (!(vin < vout) || !(l2 * l2 * l2 * vout <= vin)) return fail("volumes break lambda^6 vol(LS_out) <= vol(LS_in) < vol(LS_out)");
  std::printf("cgal consumer: R+ area %s, LS_in volume %s, LS_out volume %s (exact)\n",
              to_string(cgal::to_rational(plus.area())).c_str(), to_string(cgal::to_rational(vin)).c_str(),
              to_string(cgal::to_rational(vout)).c_str());
  return 0;
}
