// Polygonal limit surfaces and sliding [LS-1]–[LS-4] (theory.md §10–§12, §14.1, §14.2).
// Proof notes: proofs/notes/LS-1-directions.md, LS-2-polytopes.md, LS-3-queries.md.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <sstream>

#include "exact/sliding/limit_surface.h"
#include "exact/sliding/sliding.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

// A canonical rational (GMP requires canonical operands).
Rational rq(long a, long b) {
  Rational r(a, b);
  r.canonicalize();
  return r;
}

Support support_of(const std::vector<std::array<Rational, 3>>& pts, const Rational& mu = 1) {
  Support s;
  s.mu = mu;
  for (const auto& p : pts) s.points.push_back({Vec2{p[0], p[1]}, p[2], std::nullopt});
  return s;
}

std::string describe(const Support& s) {
  std::ostringstream o;
  o << "{\"wrenchkit\": 1, \"support\": {\"mu\": \"" << to_string(*s.mu) << "\", \"points\": [";
  for (std::size_t i = 0; i < s.points.size(); ++i)
    o << (i ? ", " : "") << "{\"at\": [\"" << to_string(s.points[i].at.x) << "\", \"" << to_string(s.points[i].at.y)
      << "\"], \"force\": \"" << to_string(*s.points[i].force) << "\"}";
  o << "]}}";
  return o.str();
}

Support barbell() { return support_of({{0, -1, rq(1, 2)}, {0, 1, rq(1, 2)}}); }

Rational dot(const Vec3z& q, const Vec3q& x) { return q[0] * x[0] + q[1] * x[1] + q[2] * x[2]; }
using wrenchkit::dot;  // and the vocabulary's dot of two rational vectors

// The V-rep and H-rep agree: every vertex satisfies every facet, with equality exactly on the facet's
// own vertices (at least 3, not collinear); normals are distinct; facets come in ± pairs (central symmetry).
void expect_consistent(const Ls_polytope& P) {
  std::set<std::array<std::string, 3>> normals;
  for (const Ls_facet& f : P.facets) {
    ASSERT_TRUE(normals.insert({f.normal[0].get_str(), f.normal[1].get_str(), f.normal[2].get_str()}).second);
    std::set<int> on(f.vertices.begin(), f.vertices.end());
    ASSERT_GE(on.size(), 3u);
    for (std::size_t v = 0; v < P.vertices.size(); ++v) {
      const Rational val = dot(f.normal, P.vertices[v]);
      ASSERT_LE(val, f.b);
      ASSERT_EQ(val == f.b, on.count(static_cast<int>(v)) == 1) << "vertex " << v;
    }
  }
  for (const Ls_facet& f : P.facets)
    EXPECT_EQ(normals.count({Integer(-f.normal[0]).get_str(), Integer(-f.normal[1]).get_str(), Integer(-f.normal[2]).get_str()}), 1u);
  std::set<std::array<std::string, 3>> verts;
  for (const Vec3q& x : P.vertices) verts.insert({x[0].get_str(), x[1].get_str(), x[2].get_str()});
  for (const Vec3q& x : P.vertices) EXPECT_EQ(verts.count({Rational(-x[0]).get_str(), Rational(-x[1]).get_str(), Rational(-x[2]).get_str()}), 1u);
  EXPECT_EQ(P.vertices.size() + P.facets.size(), P.edges + 2);  // Euler
}

TEST(LimitSurface, DirectionsAreRationalUnitVectorsWithTheCertificate) {
  for (int n : {4, 6, 8, 10, 64, 4096}) {
    const Directions d = make_directions(n);
    ASSERT_EQ(static_cast<int>(d.u.size()), n);
    Rational cmin = 2;
    for (int j = 0; j < n; ++j) {
      const Vec2& a = d.u[j];
      const Vec2& b = d.u[(j + 1) % n];
      EXPECT_EQ(a.x * a.x + a.y * a.y, 1);
      EXPECT_GT(a.x * b.y - a.y * b.x, 0);  // strictly CCW
      EXPECT_EQ(d.u[(j + n / 2) % n].x, -a.x);
      cmin = std::min(cmin, Rational(a.x * b.x + a.y * b.y));
    }
    EXPECT_EQ(d.lambda_sq, (1 + cmin) / 2);
    // No set of n directions beats the regular n-gon: λ ≤ cos(π/n); ours is close to it.
    const double ideal = std::cos(3.14159265358979323846 / n);
    EXPECT_LE(d.lambda_sq.get_d(), ideal * ideal + 1e-15);
    EXPECT_GT(1 - d.lambda_sq.get_d(), 0.9 * (1 - ideal * ideal));
    EXPECT_LT(1 - d.lambda_sq.get_d(), 1.2 * (1 - ideal * ideal));
  }
  EXPECT_THROW(make_directions(3), std::invalid_argument);
  EXPECT_THROW(make_directions(7), std::invalid_argument);
  EXPECT_THROW(make_directions(kMaxSides + 2), std::invalid_argument);
}

// [LS-1] The shared rule (core/limit_surface_directions.h): for every even n ≤ kMaxSides the first
// denominator 32n separates the directions (1 ≤ a_0 < … < a_{q−1} < den), and t_j = a_j/den is tan(φ_j/2)
// to within half a step.
TEST(LimitSurface, DirectionRuleNeedsNoFinerDenominator) {
  for (int n = 4; n <= kMaxSides; n += 2) {
    const Direction_parameters p = direction_parameters(n);
    ASSERT_EQ(p.den, 32 * n) << n;
    ASSERT_EQ(static_cast<int>(p.a.size()), n / 4) << n;
    ASSERT_EQ(p.middle, n / 2 % 2 == 1) << n;
    for (std::size_t j = 0; j < p.a.size(); ++j) {
      ASSERT_TRUE(j == 0 ? p.a[0] >= 1 : p.a[j - 1] < p.a[j]) << n << " " << j;
      const double t = std::tan(3.14159265358979323846 * (j + 0.5) / n);
      ASSERT_LE(std::fabs(static_cast<double>(p.a[j]) - t * static_cast<double>(p.den)), 0.5 + 1e-9) << n << " " << j;
    }
    ASSERT_LT(p.a.back(), p.den) << n;
  }
  EXPECT_THROW(direction_parameters(2), std::invalid_argument);
  EXPECT_THROW(direction_parameters(kMaxSides + 2), std::invalid_argument);
}

TEST(LimitSurface, ToleranceGivesTheSmallestQualifyingN) {
  for (const Rational& eps : {rq(1, 2), rq(1, 10), rq(1, 100), rq(1, 1000)}) {
    int built = 0;
    const int n = smallest_sides(eps, kMaxSides, &built);
    ASSERT_GT(n, 0);
    const Rational target = 1 / ((1 + eps) * (1 + eps));
    EXPECT_GE(make_directions(n).lambda_sq, target);
    for (int m = 4; m < n; m += 2) EXPECT_LT(make_directions(m).lambda_sq, target) << m;  // none smaller works
    EXPECT_LE(built, 8) << "built more direction sets than needed";
  }
  EXPECT_EQ(smallest_sides(rq(1, 100000000), kMaxSides), 0);
}

TEST(LimitSurface, BarbellExactFacetsTheory14_2) {
  const Ls_support s = merge_support(barbell());
  EXPECT_TRUE(s.collinear);
  Polygonal_ls m4(s, make_directions(4));
  const Ls_polytope p4 = m4.build(Side::inner);
  EXPECT_EQ(p4.facets.size(), 6u);  // a parallelepiped (theory.md §12.4)
  EXPECT_EQ(p4.vertices.size(), 8u);
  expect_consistent(p4);
  Polygonal_ls m8(s, make_directions(8));
  const Ls_polytope p8 = m8.build(Side::inner);
  EXPECT_EQ(p8.facets.size(), 22u);  // octagons: 22 facets (theory.md §12.4)
  expect_consistent(p8);
  for (int n : {4, 6, 8, 16}) {
    Polygonal_ls m(s, make_directions(n));
    for (Side side : {Side::inner, Side::outer}) {
      const Ls_polytope P = m.build(side);
      expect_consistent(P);
      // The four rotation facets of theory.md §14.2: normals (∓1, 0, ±1), i.e. rotations about a and b.
      int rot = 0;
      for (const Ls_facet& f : P.facets)
        if (f.support_point >= 0) {
          ++rot;
          EXPECT_TRUE(abs(f.normal[0]) == 1 && f.normal[1] == 0 && abs(f.normal[2]) == 1);
          // Its face is the full n-gon of the rotation point, translated.
          EXPECT_EQ(f.vertices.size(), static_cast<std::size_t>(n));
        }
      EXPECT_EQ(rot, 4);
    }
  }
  // The facet example of §14.2: twist (−1,0,1) about a = (0,−1): the true facet's centre is (−1/2, 0, 1/2).
  const Sliding_answer a = compute_sliding(Polygonal_ls(s, make_directions(8)), Vec3q{-1, 0, 1});
  EXPECT_EQ(a.cls.kind, Twist_kind::facet);
  EXPECT_EQ(a.cls.support_point, 0);
  EXPECT_EQ(a.load_lo, (Vec3q{rq(-1, 2), 0, rq(1, 2)}));
  EXPECT_EQ(a.load_hi, a.load_lo);
  EXPECT_EQ(a.inner_face.dimension, 2);
  // Non-smooth points (§14.2): IC (0,2), (0,1/2), (0,−3) and the translation along x are vertices of LS.
  for (const Vec3q& q : {Vec3q{2, 0, 1}, Vec3q{rq(1, 2), 0, 1}, Vec3q{-3, 0, 1}, Vec3q{1, 0, 0}})
    EXPECT_EQ(classify_twist(s, q).kind, Twist_kind::vertex) << to_string(q[0]);
  EXPECT_EQ(classify_twist(s, Vec3q{0, 1, 0}).kind, Twist_kind::smooth);
  // The true loads there (theory.md §14.2), bracketed exactly by the box: IC (0,2) CCW → (1,0,0).
  const Sliding_answer b = compute_sliding(Polygonal_ls(s, make_directions(8)), Vec3q{2, 0, 1});
  EXPECT_EQ(b.load_lo, (Vec3q{1, 0, 0}));
  EXPECT_EQ(b.load_hi, (Vec3q{1, 0, 0}));
  const Sliding_answer c = compute_sliding(Polygonal_ls(s, make_directions(8)), Vec3q{rq(1, 2), 0, 1});
  EXPECT_EQ(c.load_lo, (Vec3q{0, 0, 1}));
}

TEST(LimitSurface, SinglePointIsAFlatPolygonInnerNgonOuterTangentNgon) {
  const Rational x(3, 2), y(-2), rho(2);
  const Ls_support s = merge_support(support_of({{x, y, 4}}, rq(1, 2)));
  for (int n : {4, 6, 12, 32}) {
    Polygonal_ls m(s, make_directions(n));
    EXPECT_EQ(m.dimension(), 2);
    const Directions& d = m.directions();
    const Ls_polytope in = m.build(Side::inner), out = m.build(Side::outer);
    ASSERT_EQ(in.vertices.size(), static_cast<std::size_t>(n));
    ASSERT_EQ(out.vertices.size(), static_cast<std::size_t>(n));
    EXPECT_EQ(in.facets.size(), 2u);
    for (int j = 0; j < n; ++j) {
      const Vec2& u = d.u[j];
      EXPECT_EQ(in.vertices[j], (Vec3q{rho * u.x, rho * u.y, x * rho * u.y - y * rho * u.x}));
      // Outer edge j is tangent to the circle of radius ρ at ρ u_{j+1}: both ends on the tangent.
      const Vec2& t = d.u[(j + 1) % n];
      for (int e : {j, (j + 1) % n}) {
        const Vec3q& w = out.vertices[e];
        EXPECT_EQ(w[0] * t.x + w[1] * t.y, rho);
        EXPECT_EQ(w[2], x * w[1] - y * w[0]);  // in the plane of the point
      }
    }
    // Loads off the plane are outside (the slider pivots about the point).
    EXPECT_FALSE(m.gauge(in, Side::inner, Vec3q{1, 0, 0}).has_value());
    EXPECT_EQ(classify_load(m.gauge(in, Side::inner, Vec3q{1, 0, 0}), m.gauge(out, Side::outer, Vec3q{1, 0, 0})),
              Motion::slides);
    const Vec3q inside = {rq(1, 2), 0, -y * rq(1, 2)};  // A_r(1/2, 0)
    EXPECT_EQ(classify_load(m.gauge(in, Side::inner, inside), m.gauge(out, Side::outer, inside)), Motion::sticks);
  }
}

TEST(LimitSurface, DegenerateSupports) {
  // Coincident points merge (radii add); ρ = 0 points are dropped but count in f₀ and the COF.
  Support s = support_of({{0, 0, 1}, {1, 1, 2}, {0, 0, 1}, {3, 3, rq(3, 2)}}, rq(1, 3));
  s.points.push_back({Vec2{5, 1}, 7, Rational(0)});
  const Ls_support m = merge_support(s);
  ASSERT_EQ(m.points.size(), 3u);
  EXPECT_EQ(m.points[0].rho, rq(2, 3));
  EXPECT_TRUE(m.collinear);
  EXPECT_EQ(m.total_force, rq(25, 2));
  const Sliding_answer a = compute_sliding(Polygonal_ls(m, make_directions(8)), std::nullopt);
  EXPECT_EQ(a.center_of_friction.x, (Rational(2) + rq(9, 2) + 35) / rq(25, 2));
  for (int n : {4, 8, 12}) {
    Polygonal_ls p(m, make_directions(n));
    for (Side side : {Side::inner, Side::outer}) expect_consistent(p.build(side));
  }
  // All radii zero: the limit surface is the point 0.
  const Ls_support z = merge_support(support_of({{0, 0, 1}, {1, 0, 1}}, 0));
  Polygonal_ls pz(z, make_directions(4));
  const Ls_polytope P = pz.build(Side::inner);
  EXPECT_EQ(P.dimension, 0);
  EXPECT_EQ(classify_load(pz.gauge(P, Side::inner, Vec3q{0, 0, 0}), std::nullopt), Motion::sticks);
  EXPECT_EQ(pz.support_value(Side::outer, Vec3q{1, 2, 3}), 0);
}

// Brute force: conv of all n^k vertex sums equals the polytope (every sum satisfies every facet
// inequality, every polytope vertex is such a sum); with expect_consistent this pins the facet count.
TEST(LimitSurface, FacetsMatchBruteForceHullOfAllVertexSums) {
  std::mt19937_64 rng(test::seed(4242));
  const std::uint64_t seed = test::seed(4242);
  std::uniform_int_distribution<int> c(-6, 6), f(1, 4);
  for (int trial = 0; trial < 6; ++trial) {
    std::vector<std::array<Rational, 3>> pts;
    for (int i = 0; i < 3; ++i) pts.push_back({rq(c(rng), 3), rq(c(rng), 2), Rational(f(rng))});
    const Support sup = support_of(pts, rq(1, 2));
    const Ls_support s = merge_support(sup);
    if (s.points.size() < 2) continue;
    for (int n : {4, 6, 8}) {
      Polygonal_ls m(s, make_directions(n));
      for (Side side : {Side::inner, Side::outer}) {
        const Ls_polytope P = m.build(side);
        SCOPED_TRACE("seed " + std::to_string(seed) + " n " + std::to_string(n) + " " + side_name(side) +
                     " scene " + describe(sup));
        expect_consistent(P);
        const auto& poly = m.unit_vertices(side);
        std::set<std::array<std::string, 3>> sums;
        std::vector<int> idx(s.points.size(), 0);
        for (;;) {
          Vec3q x = {0, 0, 0};
          for (std::size_t i = 0; i < idx.size(); ++i) {
            const Ls_point& p = s.points[i];
            const Rational fx = p.rho * poly[idx[i]].x, fy = p.rho * poly[idx[i]].y;
            x[0] += fx;
            x[1] += fy;
            x[2] += p.at.x * fy - p.at.y * fx;
          }
          for (const Ls_facet& fc : P.facets) ASSERT_LE(dot(fc.normal, x), fc.b);
          sums.insert({x[0].get_str(), x[1].get_str(), x[2].get_str()});
          std::size_t i = 0;
          while (i < idx.size() && ++idx[i] == n) idx[i++] = 0;
          if (i == idx.size()) break;
        }
        for (const Vec3q& v : P.vertices) EXPECT_EQ(sums.count({v[0].get_str(), v[1].get_str(), v[2].get_str()}), 1u);
      }
    }
  }
}

// Shared direction sets and points in general position: the generic count of theory.md §12.4,
// 2k + k(k−1)n²/4, minus the merges of the n/2 translation facets (every pair of points with the same
// edge direction e gives the same normal (rot90 e-ish, 0)): −(n/2)(k(k−1) − 2).
TEST(LimitSurface, FacetCountsForGenericPoints) {
  const Ls_support s3 = merge_support(support_of({{0, 0, 1}, {rq(7, 5), rq(1, 3), 2}, {rq(-2, 7), rq(11, 10), 1}}));
  for (int n : {4, 6, 8, 16}) {
    Polygonal_ls m(s3, make_directions(n));
    const std::size_t k = 3, expected = 2 * k + k * (k - 1) * n * n / 4 - (n / 2) * (k * (k - 1) - 2);
    for (Side side : {Side::inner, Side::outer}) EXPECT_EQ(m.build(side).facets.size(), expected) << n;
  }
}

TEST(LimitSurface, ProjectionOntoForcesIsThePolygonalDiscOfRadiusMuF0) {
  const Ls_support s = merge_support(support_of({{0, 0, 1}, {1, 2, 3}, {-1, 1, 2}, {2, -1, 1}}, rq(1, 4)));
  Rational total = 0;
  for (const auto& p : s.points) total += p.rho;
  Polygonal_ls m(s, make_directions(8));
  for (Side side : {Side::inner, Side::outer}) {
    const Ls_polytope P = m.build(side);
    const auto& poly = m.unit_vertices(side);
    for (const Vec2& u : poly) {  // every corner of μf₀·P is the projection of a vertex …
      bool found = false;
      for (const Vec3q& x : P.vertices) found |= x[0] == total * u.x && x[1] == total * u.y;
      EXPECT_TRUE(found);
    }
    for (std::size_t j = 0; j < poly.size(); ++j) {  // … and every vertex projects into μf₀·P
      const Vec2& a = poly[j];
      const Vec2& b = poly[(j + 1) % poly.size()];
      for (const Vec3q& x : P.vertices)
        EXPECT_GE((b.x - a.x) * (x[1] - total * a.y) - (b.y - a.y) * (x[0] - total * a.x), 0);
    }
  }
}

// λ h ≤ h_in ≤ h ≤ h_out ≤ h/λ on random rational twists; h to long-double precision (test only).
TEST(LimitSurface, InclusionChainOnRandomTwists) {
  const std::uint64_t seed = test::seed(20261121);
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> c(-40, 40), f(1, 9);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<std::array<Rational, 3>> pts;
    const int k = 1 + trial % 5;
    for (int i = 0; i < k; ++i) pts.push_back({rq(c(rng), 7), rq(c(rng), 11), rq(f(rng), 3)});
    const Support sup = support_of(pts, rq(2, 5));
    const Ls_support s = merge_support(sup);
    const int n = 4 + 2 * (trial % 8);
    Polygonal_ls m(s, make_directions(n));
    const long double lam = std::sqrt(static_cast<long double>(m.directions().lambda_sq.get_d()));
    const Ls_polytope in = m.build(Side::inner), out = m.build(Side::outer);
    for (int r = 0; r < 30; ++r) {
      const Vec3q q = {rq(c(rng), 5), rq(c(rng), 3), rq(c(rng) / 4, 2)};
      if (q[0] == 0 && q[1] == 0 && q[2] == 0) continue;
      long double h = 0;
      for (const Ls_point& p : s.points) {
        const long double vx = Rational(q[0] - q[2] * p.at.y).get_d(), vy = Rational(q[1] + q[2] * p.at.x).get_d();
        h += static_cast<long double>(p.rho.get_d()) * std::sqrt(vx * vx + vy * vy);
      }
      const Rational hi = m.support_value(Side::inner, q), ho = m.support_value(Side::outer, q);
      const long double tol = 1e-12L * (1 + h);
      SCOPED_TRACE("seed " + std::to_string(seed) + " scene " + describe(sup) + " n " + std::to_string(n));
      EXPECT_LE(lam * h - tol, hi.get_d());
      EXPECT_LE(hi.get_d(), h + tol);
      EXPECT_LE(h - tol, ho.get_d());
      EXPECT_LE(ho.get_d(), h / lam + tol);
      // The faces attain the support values, and the H-rep agrees (3-D polytopes).
      for (Side side : {Side::inner, Side::outer}) {
        const Ls_face fc = m.face(side, q);
        for (const Vec3q& x : fc.vertices) EXPECT_EQ(dot(q, x), side == Side::inner ? hi : ho);
      }
      if (in.dimension == 3) {
        Rational best = 0;
        for (const Vec3q& x : in.vertices) best = std::max(best, dot(q, x));
        EXPECT_EQ(best, hi);
      }
      // The sqrt bracket of the true power brackets h too.
      const Sliding_answer a = compute_sliding(m, q);
      EXPECT_LE(a.h_lo.get_d(), static_cast<double>(h) + 1e-9);
      EXPECT_GE(a.h_hi.get_d(), static_cast<double>(h) - 1e-9);
      EXPECT_LE(a.h_inner, a.h_hi);
      EXPECT_GE(a.h_outer, a.h_lo);
    }
    if (in.dimension == 3) {
      expect_consistent(in);
      expect_consistent(out);
    }
  }
}

TEST(LimitSurface, StickSlideUndecidedAndTheNormalCone) {
  const Ls_support s = merge_support(barbell());
  Polygonal_ls m(s, make_directions(16));
  const Ls_polytope in = m.build(Side::inner), out = m.build(Side::outer);
  auto motion = [&](const Vec3q& p) { return classify_load(m.gauge(in, Side::inner, p), m.gauge(out, Side::outer, p)); };
  EXPECT_EQ(motion(Vec3q{0, 0, rq(1, 2)}), Motion::sticks);
  EXPECT_EQ(motion(Vec3q{0, 0, 2}), Motion::slides);
  EXPECT_EQ(motion(Vec3q{0, 0, 1}), Motion::undecided);  // on the true LS (pure-moment intercept 1)
  EXPECT_EQ(motion(Vec3q{rq(1, 3), rq(1, 3), rq(1, 3)}), Motion::sticks);
  // A point of the true facet is on neither polygonal facet: undecided. The centroid of the outer
  // polytope's facet for (−1, 0, 1) has gauge 1 and the single twist (−1, 0, 1) as its normal cone.
  EXPECT_EQ(motion(Vec3q{rq(-1, 2), 0, rq(1, 2)}), Motion::undecided);
  const Ls_face fc = m.face(Side::outer, Vec3q{-1, 0, 1});
  ASSERT_EQ(fc.dimension, 2);
  Vec3q p = {0, 0, 0};
  for (const Vec3q& x : fc.vertices)
    for (int i = 0; i < 3; ++i) p[i] += x[i] / static_cast<long>(fc.vertices.size());
  EXPECT_EQ(*m.gauge(out, Side::outer, p), 1);
  EXPECT_EQ(motion(p), Motion::slides);
  const auto cone = m.normal_cone(out, Side::outer, p);
  ASSERT_EQ(cone.generators.size(), 1u);
  EXPECT_EQ(cone.generators[0], (Vec3z{-1, 0, 1}));
}

// §14.1 closed forms bracketed with the certified discretisation of §12.6: a cell of half-size δ
// moves the power by at most ε|ω|, ε = μ Σ F_k δ_k.
TEST(LimitSurface, ClosedFormsBracketedSegmentAndRectangle) {
  // Uniform segment of length 2a on the x-axis, μf₀ = 1, rotation about (x_c, 0), ω = 1:
  // h = (a² + x_c²)/(2a) exactly (theory.md §14.1: load (0, −x_c/a, (a² − x_c²)/(2a))).
  const Rational a = 1;
  const int cells = 40;
  Support seg;
  seg.mu = 1;
  for (int i = 0; i < cells; ++i)
    seg.points.push_back({Vec2{-a + (2 * i + 1) * a / cells, 0}, rq(1, cells), std::nullopt});
  const Rational eps = a / cells;  // δ = half a cell, Σ F = 1
  Polygonal_ls m(merge_support(seg), make_directions(64));
  for (const Rational& xc : {Rational(0), rq(1, 4), rq(-3, 5), Rational(1)}) {
    const Vec3q q = {0, -xc, 1};
    const Rational h = (a * a + xc * xc) / (2 * a);
    EXPECT_LE(m.support_value(Side::inner, q) - eps, h);
    EXPECT_GE(m.support_value(Side::outer, q) + eps, h);
  }
  // Uniform rectangle [−2,2]×[−1,1], μf₀ = 1: max moment 1.186466832 (rotation about the centre).
  Support rect;
  rect.mu = 1;
  const int nx = 40, ny = 20;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      rect.points.push_back({Vec2{Rational(-2) + rq(2 * i + 1, 20), Rational(-1) + rq(2 * j + 1, 20)},
                             rq(1, nx * ny), std::nullopt});
  // Cells 1/10 × 1/10: δ = 1415/20000 ≥ √2/20.
  const Rational eps2(1415, 20000);
  Polygonal_ls mr(merge_support(rect), make_directions(64));
  const Vec3q q = {0, 0, 1};
  EXPECT_LE(Rational(mr.support_value(Side::inner, q) - eps2).get_d(), 1.186466832);
  EXPECT_GE(Rational(mr.support_value(Side::outer, q) + eps2).get_d(), 1.186466832);
  // … and the bracket is informative (a few percent).
  EXPECT_LT(Rational(mr.support_value(Side::outer, q) - mr.support_value(Side::inner, q) + 2 * eps2).get_d(), 0.15);
}

TEST(Sliding, TranslationIsExactAndRotationIsBracketed) {
  // Weights 2,1,1 at (0,0),(1,0),(0,1), μ = 1 (theory.md §11.4 item 7).
  const Ls_support s = merge_support(support_of({{0, 0, 2}, {1, 0, 1}, {0, 1, 1}}));
  Polygonal_ls m(s, make_directions(32));
  const Sliding_answer t = compute_sliding(m, Vec3q{3, 4, 0});
  EXPECT_EQ(t.center_of_friction.x, rq(1, 4));
  EXPECT_EQ(t.center_of_friction.y, rq(1, 4));
  ASSERT_TRUE(t.load.has_value());  // |v| = 5: exact
  EXPECT_EQ(*t.load, (Vec3q{rq(12, 5), rq(16, 5), rq(1, 4) * rq(16, 5) - rq(1, 4) * rq(12, 5)}));
  const Sliding_answer u = compute_sliding(m, Vec3q{1, 1, 0});
  EXPECT_FALSE(u.load.has_value());  // |v| = √2: given as (μf₀/|v|)·direction
  EXPECT_EQ(u.load_direction, (Vec3q{1, 1, 0}));
  // Rotation about (0,0) (a support point): a facet; the pure-moment intercept is 2 = Σ ρ|r − c|.
  const Sliding_answer r = compute_sliding(m, Vec3q{0, 0, 1});
  EXPECT_EQ(r.cls.kind, Twist_kind::facet);
  EXPECT_LE(r.h_inner, 2);
  EXPECT_GE(r.h_outer, 2);
  EXPECT_EQ(r.h_lo, 2);
  EXPECT_EQ(r.h_hi, 2);
  EXPECT_THROW(compute_sliding(m, Vec3q{0, 0, 0}), std::invalid_argument);
  // sqrt brackets
  const auto [lo, hi] = sqrt_bracket(Rational(2));
  EXPECT_LE(lo * lo, 2);
  EXPECT_GE(hi * hi, 2);
  EXPECT_LT(Rational(hi - lo).get_d(), 1e-20);
}

}  // namespace
}  // namespace wrenchkit
