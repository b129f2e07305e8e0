// CGAL as an independent oracle of the engine's constructions and verdicts (docs/design.md, "CGAL and Boost";
// issue 17). Every family runs on every golden scene it applies to and on ≥ 1 000 random scenes (seed:
// WRENCHKIT_SEED, else the fixed one below); a failure prints the seed and dumps the scene to failures/.
//   * [LB-3] [LB-4] moment labels and the force dual against CGAL's half-plane intersection on an exact kernel
//     (Nef_polyhedron_2 over Extended_homogeneous<Gmpz>: unbounded and lower-dimensional sets are ordinary values;
//     not the filtered variant: with CGAL 5.5.1 and g++ -O2 it crashed in an overlay on a golden scene, and g++
//     warns that its points' cached intervals may be used uninitialized): R₊, R₋, the ± set and the labeled directions from their definitions (theory.md §5:
//     M_c(g_i) ≥ 0, ≤ 0, the points at infinity), the dual's sheets from the H-representation of pos{D(g_i)}
//     (a generating set of its dual cone by brute force), each compared as a SET with the CGAL face's region
//     (exact/cgal/cgal.h: Region_2's half-planes); the dual polygon about the reference point against
//     CGAL::convex_hull_2.
//   * [LS-2] limit-surface polytopes against CGAL::convex_hull_3 on Epeck of the Minkowski sums of the summand
//     polygons (incrementally: hull, then its vertices ⊕ the next polygon): vertex sets and facet sets (the hull's
//     triangles grouped by plane) equal; CGAL::is_strongly_convex_3 of the face's Surface_mesh.
//   * [EQ-1] equilibrium verdicts (exact, hybrid, and float when it decides) against CGAL's exact LP solver
//     (CGAL/QP_functions.h on Gmpz): −w ∈ pos{g_i} ⇔ {λ ≥ 0 : Σ λ_i g_i = −w} is feasible.
// This translation unit parses CGAL's Nef, hull and QP headers once; its compile time is in docs/benchmarks.md ("Performance notes").
#include <CGAL/Extended_homogeneous.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Nef_polyhedron_2.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/convexity_check_3.h>

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "exact/cgal/cgal.h"
#include "exact/pipeline/answer_json.h"
#include "exact/statics/equilibrium.h"
#include "exact/statics/generators.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

using namespace cgal;
using Nef_kernel = CGAL::Extended_homogeneous<CGAL::Gmpz>;
using Nef = CGAL::Nef_polyhedron_2<Nef_kernel>;
using V3 = std::array<Rational, 3>;

constexpr int kRandomScenes = 1000;

// Prints the seconds a family took (the report's numbers) when it ends.
struct Timer {
  const char* what;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  ~Timer() {
    std::cout << "[ timing ] " << what << ": "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
  }
};

// On a failure, dumps the scene for replay and prints the path.
struct Dump_on_failure {
  const std::string& text;
  const std::string& tag;
  ~Dump_on_failure() {
    if (::testing::Test::HasFailure()) std::cerr << "failing scene: " << test::dump_failure(text, tag) << "\n";
  }
};

CGAL::Gmpz gmpz(const Integer& z) { return CGAL::Gmpz(z.get_mpz_t()); }

// {(x, y) : a x + b y + c ≥ 0} as a Nef polyhedron (a = b = 0: everything or nothing).
Nef half_plane(const Rational& a, const Rational& b, const Rational& c) {
  if (a == 0 && b == 0) return Nef(c >= 0 ? Nef::COMPLETE : Nef::EMPTY);
  Integer l = 1;
  for (const Rational* q : {&a, &b, &c}) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), q->get_den_mpz_t());
  const auto z = [&](const Rational& q) { return gmpz(Integer(q.get_num() * (l / q.get_den()))); };
  return Nef(Nef::Line(z(a), z(b), z(c)), Nef::INCLUDED);
}

// The CGAL face's region as a set: the intersection of its half-planes.
Nef nef_of(const Region_2& r) {
  Nef n(Nef::COMPLETE);
  for (const Line_2& l : r.half_planes) n = n * half_plane(to_rational(l.a()), to_rational(l.b()), to_rational(l.c()));
  return n;
}

// Is the face's region the set `oracle`? The empty set and the plane are read off the oracle directly (each Nef
// overlay costs about a millisecond: most regions of random scenes are empty); any other region as a Nef.
bool same_set(const Region_2& r, const Nef& oracle) {
  if (r.shape == Region::Shape::empty || oracle.is_empty()) return r.shape == Region::Shape::empty && oracle.is_empty();
  if (r.shape == Region::Shape::plane || oracle.is_plane()) return r.shape == Region::Shape::plane && oracle.is_plane();
  return nef_of(r) == oracle;
}

// ∩_t {p : ⟨t, (p, z)⟩ ≥ 0} for the sheet z = 1 (front), −1 (back: ⟨t, −(p, 1)⟩ ≥ 0) or 0 (directions).
Nef slice(const std::vector<V3>& ts, int z) {
  Nef n(Nef::COMPLETE);
  const Rational s = z == 0 ? 1 : z;
  for (const V3& t : ts) n = n * half_plane(s * t[0], s * t[1], z == 0 ? Rational(0) : s * t[2]);
  return n;
}

V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Rational dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool zero(const V3& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

// A generating set of C* = {t : ⟨t, d⟩ ≥ 0 ∀ d ∈ D} for C = pos(D) in R³, by brute force: every candidate ±d,
// ±e_k, ±(a × b), ±((a × b) × c) over a, b, c ∈ D ∪ {e_1, e_2, e_3} that lies in C*, one per direction. It holds
// the extreme rays of C* (normals of C's facets: rank 3), the lineality ±n and the in-plane rays n × d (rank 2),
// d^⊥ and ±d (rank 1), ±e_k (C = {0}); so C = {x : ⟨t, x⟩ ≥ 0 for every t of the set}.
std::vector<V3> dual_generators(const std::vector<V3>& D) {
  std::vector<V3> base = D;
  base.push_back({1, 0, 0});
  base.push_back({0, 1, 0});
  base.push_back({0, 0, 1});
  std::vector<V3> cand = base;
  for (const V3& a : base)
    for (const V3& b : base) {
      const V3 ab = cross(a, b);
      if (zero(ab)) continue;
      cand.push_back(ab);
      for (const V3& c : base) cand.push_back(cross(ab, c));
    }
  // When C is full-dimensional (rank 3) C* is pointed and generated by its extreme rays alone: the t orthogonal to
  // two independent d (the normals of C's facets); the other candidates are redundant and only cost time.
  const auto rank = [](const std::vector<V3>& v) {
    for (const V3& a : v)
      for (const V3& b : v) {
        const V3 n = cross(a, b);
        if (zero(n)) continue;
        for (const V3& c : v)
          if (dot(n, c) != 0) return 3;
        return 2;
      }
    for (const V3& a : v)
      if (!zero(a)) return 1;
    return 0;
  };
  const bool full = rank(D) == 3;
  std::set<std::array<Integer, 3>> seen;
  std::vector<V3> out;
  for (const V3& c0 : cand)
    for (int s : {1, -1}) {
      if (zero(c0)) continue;
      const V3 c{s * c0[0], s * c0[1], s * c0[2]};
      bool in = true;
      std::vector<V3> tight;
      for (const V3& d : D) {
        in = in && dot(c, d) >= 0;
        if (dot(c, d) == 0) tight.push_back(d);
      }
      if (!in || (full && rank(tight) < 2) || !seen.insert(primitive(c)).second) continue;
      out.push_back(c);
    }
  return out;
}

// The distinct directions of D (a positive multiple of a half-plane's normal is the same half-plane).
std::vector<V3> distinct(const std::vector<V3>& D) {
  std::set<std::array<Integer, 3>> seen;
  std::vector<V3> out;
  for (const V3& d : D)
    if (!zero(d) && seen.insert(primitive(d)).second) out.push_back(d);
  return out;
}

V3 dual_of(const Vec3q& w) { return {-w[1], w[0], w[2]}; }  // D(w) = J w (theory.md §6)

std::vector<Vec3q> wrenches(const Scene& s, Reading r) {
  std::vector<Vec3q> w;
  for (const Generator& g : generators(s, r)) w.push_back(g.w);
  return w;
}

// The labels and the force dual of one scene and reading against Nef_polyhedron_2, and the face's round trip.
void check_labels_and_dual(const Scene& scene, Reading reading) {
  SCOPED_TRACE(reading == Reading::friction ? "friction" : "frictionless");
  const std::vector<Vec3q> g = wrenches(scene, reading);
  const Moment_labels l = moment_labels(g);
  const Force_dual fd = force_dual(l, g);
  const Labels_2 c = to_cgal(l);
  const Force_dual_2 cd = to_cgal(fd);
  std::vector<V3> D;
  for (const Vec3q& w : g) D.push_back(dual_of(w));
  D = distinct(D);

  // Labels: R₊ = {c : ⟨(c, 1), D_i⟩ ≥ 0}, R₋ = {… ≤ 0}, ± = R₊ ∩ R₋, R∞ = {d : ⟨(d, 0), D_i⟩ ≥ 0}.
  const Nef plus = slice(D, 1), minus = slice(D, -1);
  ASSERT_TRUE(same_set(c.plus, plus)) << "R+ " << region_json(l.plus);
  ASSERT_TRUE(same_set(c.minus, minus)) << "R- " << region_json(l.minus);
  ASSERT_TRUE(same_set(c.both, plus.is_empty() || minus.is_empty() ? Nef(Nef::EMPTY) : plus * minus)) << "both";
  ASSERT_TRUE(same_set(c.infinity.region, slice(D, 0))) << "infinity " << infinity_json(l.infinity);

  // The force dual: the slices of pos{D_i} = {x : ⟨t, x⟩ ≥ 0 for t in a generating set of its dual}.
  const std::vector<V3> T = dual_generators(D);
  ASSERT_TRUE(same_set(cd.plus_sheet, slice(T, 1))) << "dual + " << region_json(fd.plus_sheet);
  ASSERT_TRUE(same_set(cd.minus_sheet, slice(T, -1))) << "dual - " << region_json(fd.minus_sheet);
  ASSERT_TRUE(same_set(cd.infinity.region, slice(T, 0))) << "dual infinity " << infinity_json(fd.infinity);
  ASSERT_EQ(cd.covers_all, T.empty());  // C = R³ ⇔ C* = {0}: force closure, nothing labeled (theory.md §5.5)
  ASSERT_EQ(c.nothing_labeled, T.empty());
  if (cd.has_reference) {  // §6.2: the dual polygon about o is conv{(−fy, fx)/m_o}, by CGAL::convex_hull_2
    std::vector<Point_2> pts, hull;
    const Vec2 o = to_vec2(cd.reference);
    for (const Vec3q& w : g) {
      const Rational mo = w[2] - (o.x * w[1] - o.y * w[0]);
      ASSERT_GT(mo, 0);
      pts.push_back(to_point_2({-w[1] / mo, w[0] / mo}));
    }
    CGAL::convex_hull_2(pts.begin(), pts.end(), std::back_inserter(hull));
    const Polygon_2& ours = cd.about_reference.corners;
    ASSERT_EQ(hull.size(), ours.size()) << region_json(fd.about_reference);
    std::size_t k = 0;
    while (k < hull.size() && hull[k] != ours[0]) ++k;
    ASSERT_LT(k, hull.size());
    for (std::size_t i = 0; i < hull.size(); ++i) ASSERT_EQ(hull[(k + i) % hull.size()], ours[i]);
  }

  // The face: exact round trips, bounded regions as convex counter-clockwise Polygon_2, corners on the region.
  for (const auto& [r, r2] : {std::pair<const Region*, const Region_2*>{&l.plus, &c.plus}, {&l.minus, &c.minus},
                              {&fd.plus_sheet, &cd.plus_sheet}, {&fd.minus_sheet, &cd.minus_sheet},
                              {&fd.about_reference, &cd.about_reference}}) {
    const Region back = to_region(*r2);
    ASSERT_EQ(region_json(back), region_json(*r));
    ASSERT_EQ(back.vertices.size(), r->vertices.size());
    for (std::size_t i = 0; i < back.vertices.size(); ++i)
      ASSERT_TRUE(back.vertices[i].x == r->vertices[i].x && back.vertices[i].y == r->vertices[i].y);
    if (r->shape == Region::Shape::polygon) {
      ASSERT_TRUE(r2->corners.is_simple() && r2->corners.is_convex());
      ASSERT_EQ(r2->corners.orientation(), CGAL::COUNTERCLOCKWISE);
      ASSERT_GT(r2->corners.area(), 0);
    }
    for (const Point_2& p : r2->corners.vertices())
      if (r->shape != Region::Shape::empty) {
        ASSERT_TRUE(r2->has_on(p));
      }
  }
}

std::vector<std::string> golden_files() {
  std::vector<std::string> f = test::scene_files("tests/golden");
  for (const std::string& e : test::scene_files("tests/golden/equilibrium")) f.push_back(e);
  return f;
}

TEST(CgalOracle, LabelsAndDualOnEveryGolden) {
  const Timer t{"labels and dual, goldens"};
  int n = 0;
  for (const std::string& f : golden_files()) {
    SCOPED_TRACE(f);
    const Scene s = read_scene(test::read_text(f), Input_limits{});
    for (Reading r : {Reading::friction, Reading::frictionless}) {
      check_labels_and_dual(s, r);
      if (HasFatalFailure()) return;
    }
    ++n;
  }
  EXPECT_EQ(n, 64);
}

// 1 000 random scenes (degenerate-rich integer grids, ≤ 5 contacts), in four parts that CTest runs in parallel;
// each scene in one reading, friction and frictionless (Reuleaux) in turn.
class CgalOracleRandomLabels : public ::testing::TestWithParam<int> {};

TEST_P(CgalOracleRandomLabels, LabelsAndDualOnRandomScenes) {
  const int part = GetParam();
  const Timer t{"labels and dual, random scenes, one part of 4"};
  const int per_part = kRandomScenes / 4;
  const std::uint64_t seed = test::seed(20261117) + static_cast<std::uint64_t>(part);  // WRENCHKIT_SEED + part
  std::mt19937_64 rng(seed);
  for (int i = 0; i < per_part; ++i) {
    const std::string text = test::scene_json(test::random_contacts(rng, 5));
    const std::string tag = "cgal_labels_" + std::to_string(seed) + "_" + std::to_string(i);
    const Dump_on_failure dump{text, tag};
    SCOPED_TRACE(tag);
    check_labels_and_dual(read_scene(text, Input_limits{}), i % 2 ? Reading::frictionless : Reading::friction);
    if (HasFatalFailure()) return;
  }
}
INSTANTIATE_TEST_SUITE_P(Parts, CgalOracleRandomLabels, ::testing::Values(1, 2, 3, 4));

// ---- limit surfaces against convex_hull_3 ----------------------------------------------------------------------

using Epoint = Point_3;
struct Point_less {
  bool operator()(const Vec3q& a, const Vec3q& b) const { return a < b; }
};
using Point_set = std::set<Vec3q, Point_less>;

// The vertices of the hull of pts (three-dimensional), by convex_hull_3 on Epeck.
Point_set hull_vertices(const std::vector<Vec3q>& pts, Surface_mesh* out = nullptr) {
  std::vector<Epoint> e;
  for (const Vec3q& p : pts) e.push_back(to_point_3(p));
  Surface_mesh m;
  CGAL::convex_hull_3(e.begin(), e.end(), m);
  Point_set v;
  for (auto i : m.vertices()) v.insert(to_vec3q(m.point(i)));
  if (out) *out = std::move(m);
  return v;
}

// The summand polygons ρ_i A_{r_i}(P) (theory.md §12.3) from the direction set alone: inner P = conv{u_j}; outer P
// has the vertices (u_j + u_{j+1}) / (1 + u_j·u_{j+1}) where the tangents at u_j and u_{j+1} meet.
std::vector<std::vector<Vec3q>> summands(const Polygonal_ls& model, Side side) {
  const std::vector<Vec2>& u = model.directions().u;
  std::vector<Vec2> P;
  for (std::size_t j = 0; j < u.size(); ++j) {
    if (side == Side::inner) {
      P.push_back(u[j]);
    } else {
      const Vec2& a = u[j];
      const Vec2& b = u[(j + 1) % u.size()];
      const Rational s = 1 + a.x * b.x + a.y * b.y;
      P.push_back({(a.x + b.x) / s, (a.y + b.y) / s});
    }
  }
  std::vector<std::vector<Vec3q>> out;
  for (const Ls_point& q : model.support().points) {
    std::vector<Vec3q> poly;
    for (const Vec2& f : P) {
      const Rational fx = q.rho * f.x, fy = q.rho * f.y;
      poly.push_back({fx, fy, q.at.x * fy - q.at.y * fx});
    }
    out.push_back(std::move(poly));
  }
  return out;
}

void check_polytope(const Polygonal_ls& model, Side side) {
  SCOPED_TRACE(side_name(side));
  const Ls_polytope P = model.build(side);
  const Point_set ours(P.vertices.begin(), P.vertices.end());
  ASSERT_EQ(ours.size(), P.vertices.size());
  const std::vector<std::vector<Vec3q>> polys = summands(model, side);
  if (P.dimension == 0) {
    ASSERT_TRUE(polys.empty());
    ASSERT_EQ(ours, (Point_set{Vec3q{0, 0, 0}}));
    return;
  }
  if (P.dimension == 2) {  // one point: the polytope is its (flat) summand polygon
    ASSERT_EQ(polys.size(), 1u);
    ASSERT_EQ(ours, Point_set(polys[0].begin(), polys[0].end()));
    return;
  }
  // Minkowski sum by hulls: S_1 = P_1, S_{i+1} = vertices of hull(S_i ⊕ P_{i+1}).
  std::vector<Vec3q> S = polys[0];
  Surface_mesh hull;
  Point_set hv;
  for (std::size_t i = 1; i < polys.size(); ++i) {
    std::vector<Vec3q> sum;
    for (const Vec3q& a : S)
      for (const Vec3q& b : polys[i]) sum.push_back({a[0] + b[0], a[1] + b[1], a[2] + b[2]});
    hv = hull_vertices(sum, &hull);
    S.assign(hv.begin(), hv.end());
  }
  ASSERT_EQ(ours, hv) << "vertex sets differ: " << ours.size() << " ours, " << hv.size() << " convex_hull_3";
  // Facets: the hull's triangles grouped by their plane (primitive outward normal) → the vertices on that plane.
  std::map<std::array<Integer, 3>, Point_set> theirs;
  for (auto f : hull.faces()) {
    std::vector<Vec3q> t;
    for (auto v : CGAL::vertices_around_face(hull.halfedge(f), hull)) t.push_back(to_vec3q(hull.point(v)));
    const V3 e1{t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]};
    const V3 e2{t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2]};
    Point_set& s = theirs[primitive(cross(e1, e2))];
    s.insert(t.begin(), t.end());
  }
  std::map<std::array<Integer, 3>, Point_set> mine;
  for (const Ls_facet& f : P.facets) {
    Point_set& s = mine[f.normal];
    for (const int i : f.vertices) s.insert(P.vertices[static_cast<std::size_t>(i)]);
    for (const int i : f.vertices) ASSERT_EQ(dot(to_rational(f.normal), P.vertices[static_cast<std::size_t>(i)]), f.b);
  }
  ASSERT_EQ(mine.size(), theirs.size()) << "facet counts differ";
  ASSERT_TRUE(mine == theirs) << "facet sets differ";
  // The CGAL face's mesh is a strongly convex closed polytope with the same vertices and faces.
  const Surface_mesh m = to_surface_mesh(P);
  ASSERT_TRUE(CGAL::is_closed(m) && m.is_valid(false));
  ASSERT_TRUE(CGAL::is_strongly_convex_3(m));
  ASSERT_EQ(mesh_vertices(m), P.vertices);
}

void check_support(const Scene& s, int sides) {
  SCOPED_TRACE("N = " + std::to_string(sides));
  const Polygonal_ls model(merge_support(*s.support), make_directions(sides));
  for (Side side : {Side::inner, Side::outer}) {
    check_polytope(model, side);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

TEST(CgalOracle, LimitSurfacesOnEveryGolden) {
  const Timer t{"limit surfaces, goldens"};
  int n = 0;
  for (const std::string& f : test::scene_files("tests/golden/limit_surface")) {
    SCOPED_TRACE(f);
    const Scene s = read_scene(test::read_text(f), Input_limits{});
    bool known = true;
    for (const Support_point& p : s.support->points) known = known && p.force.has_value();
    if (!known) continue;  // an unknown distribution has no one limit surface
    for (int sides : {4, 6, 8}) {
      check_support(s, sides);
      if (HasFatalFailure()) return;
    }
    ++n;
  }
  EXPECT_EQ(n, 5);
}

// Random supports: 1–4 points on a small grid (some coincident: merged), decimal or fractional forces, μ per point
// or shared, N = 4, 6 or 8.
std::string random_support(std::mt19937_64& rng, int* sides) {
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const int k = uni(1, 4);
  *sides = 2 * uni(2, 4);
  std::string t = "{\"wrenchkit\": 1, \"support\": {\"mu\": \"" + std::to_string(uni(1, 9)) + "/10\", \"points\": [";
  for (int i = 0; i < k; ++i) {
    t += std::string(i ? ", " : "") + "{\"at\": [\"" + std::to_string(uni(-6, 6)) + "/" + std::to_string(uni(1, 4)) +
         "\", \"" + std::to_string(uni(-6, 6)) + "/" + std::to_string(uni(1, 3)) + "\"], \"force\": \"" +
         std::to_string(uni(1, 9)) + "/" + std::to_string(uni(1, 5)) + "\"";
    if (uni(0, 3) == 0) t += ", \"mu\": \"0." + std::to_string(uni(0, 9)) + "\"";
    t += "}";
  }
  return t + "]}}";
}

TEST(CgalOracle, LimitSurfacesOnRandomSupports) {
  const Timer t{"limit surfaces, random supports"};
  const std::uint64_t seed = test::seed(20261118);
  std::mt19937_64 rng(seed);
  for (int i = 0; i < kRandomScenes; ++i) {
    int sides = 4;
    const std::string text = random_support(rng, &sides);
    const std::string tag = "cgal_limit_surface_" + std::to_string(seed) + "_" + std::to_string(i);
    const Dump_on_failure dump{text, tag};
    SCOPED_TRACE(tag + " " + text);
    check_support(read_scene(text, Input_limits{}), sides);
    if (HasFatalFailure()) return;
  }
}

// ---- equilibrium against CGAL's exact LP ----------------------------------------------------------------------

// −w ∈ pos{g_i}: is {λ ≥ 0 : Σ λ_i g_i = −w} feasible? Columns and the right-hand side scaled to integers (a
// positive scaling of a column or of −w leaves the answer unchanged); solved exactly in Gmpz.
int lps_solved = 0;  // LPs handed to CGAL's solver (scenes with generators), for the count below
bool lp_balanced(const std::vector<Vec3q>& g, const Vec3q& w) {
  const auto integers = [](const V3& v) {
    Integer l = 1;
    for (const Rational& q : v) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), q.get_den_mpz_t());
    std::array<CGAL::Gmpz, 3> z;
    for (int i = 0; i < 3; ++i) z[i] = gmpz(Integer(v[i].get_num() * (l / v[i].get_den())));
    return z;
  };
  if (g.empty()) return w[0] == 0 && w[1] == 0 && w[2] == 0;
  CGAL::Quadratic_program<CGAL::Gmpz> lp(CGAL::EQUAL, true, 0, false, 0);
  for (std::size_t j = 0; j < g.size(); ++j) {
    const auto c = integers({g[j][0], g[j][1], g[j][2]});
    for (int i = 0; i < 3; ++i) lp.set_a(static_cast<int>(j), i, c[i]);
  }
  const auto b = integers({-w[0], -w[1], -w[2]});
  for (int i = 0; i < 3; ++i) lp.set_b(i, b[i]);
  ++lps_solved;
  return !CGAL::solve_linear_program(lp, CGAL::Gmpz()).is_infeasible();
}

void check_equilibrium(const Scene& s) {
  const std::vector<Vec3q> g = wrenches(s, Reading::friction);
  const Equilibrium_answer a = decide_equilibrium(s, Mode::exact);
  const bool lp = lp_balanced(g, a.load);
  ASSERT_EQ(a.balanced, lp) << "exact";
  const Equilibrium_answer h = decide_equilibrium(s, Mode::hybrid);
  ASSERT_EQ(h.balanced, lp) << "hybrid";
  const Equilibrium_answer f = decide_equilibrium(s, Mode::float_only);
  if (f.decided) {
    ASSERT_EQ(f.balanced, lp) << "float";
  }
}

TEST(CgalOracle, EquilibriumOnEveryGolden) {
  const Timer t{"equilibrium, goldens"};
  int n = 0;
  for (const std::string& f : golden_files()) {
    SCOPED_TRACE(f);
    const Scene s = read_scene(test::read_text(f), Input_limits{});
    if (!s.load) continue;
    check_equilibrium(s);
    if (HasFatalFailure()) return;
    ++n;
  }
  EXPECT_GE(n, 28);
}

TEST(CgalOracle, EquilibriumOnRandomScenes) {
  const Timer t{"equilibrium, random scenes"};
  const std::uint64_t seed = test::seed(20261119);
  std::mt19937_64 rng(seed);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  int balanced = 0;
  lps_solved = 0;
  for (int i = 0; i < kRandomScenes; ++i) {
    std::string text = test::scene_json(test::random_contacts(rng, 6));
    text.pop_back();
    text += uni(0, 2) ? ", \"load\": {\"force\": [" + std::to_string(uni(-2, 2)) + ", " + std::to_string(uni(-2, 2)) +
                            "], \"at\": [" + std::to_string(uni(-3, 3)) + ", " + std::to_string(uni(-3, 3)) + "]}}"
                      : ", \"load\": {\"wrench\": [" + std::to_string(uni(-1, 1)) + ", " + std::to_string(uni(-1, 1)) +
                            ", " + std::to_string(uni(-2, 2)) + "]}}";
    const std::string tag = "cgal_equilibrium_" + std::to_string(seed) + "_" + std::to_string(i);
    const Dump_on_failure dump{text, tag};
    SCOPED_TRACE(tag);
    const Scene s = read_scene(text, Input_limits{});
    check_equilibrium(s);
    if (HasFatalFailure()) return;
    balanced += decide_equilibrium(s).balanced;
  }
  // Most scenes have contacts (the LP is solved), and both answers occur often enough to mean something.
  std::cout << "[ counts ] " << lps_solved << " LPs solved, " << balanced << " of " << kRandomScenes << " balanced\n";
  EXPECT_GT(lps_solved, kRandomScenes * 3 / 4);
  EXPECT_GT(balanced, kRandomScenes / 10);
  EXPECT_LT(balanced, kRandomScenes * 9 / 10);
}

}  // namespace
}  // namespace wrenchkit
