// Support regions [RG-1] [RG-2]: reading and validation, exact measures, the certified power and load brackets
// against closed forms (theory.md §14.1), an independent quadrature and invariances; stick/slide certificates
// accepted by the independent checker, and the table and plate as small regions converging to their point
// masses.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "exact/io/input_error.h"
#include "exact/io/region.h"
#include "exact/io/scene.h"
#include "exact/io/scene_writer.h"
#include "exact/io/streaming_scene_reader.h"
#include "exact/pipeline/support_answer.h"
#include "exact/sliding/distribution.h"
#include "exact/sliding/motion.h"
#include "exact/sliding/strategies.h"
#include "exact/sliding/region_sliding.h"
#include "exact/sliding/sliding.h"
#include "proofs/checker/checker.h"
#include "test_support.h"

namespace wrenchkit {
namespace {

const Input_limits kLimits{};

std::string num(const Rational& q) { return "\"" + to_string(q) + "\""; }
std::string pt(const Rational& x, const Rational& y) { return "[" + num(x) + ", " + num(y) + "]"; }
std::string ring(const std::vector<Vec2>& r) {
  std::string s = "[";
  for (std::size_t i = 0; i < r.size(); ++i) s += (i ? ", " : "") + pt(r[i].x, r[i].y);
  return s + "]";
}

// A scene with one uniform region (force W, μ) and no points.
std::string region_scene(const std::vector<Vec2>& outline, const Rational& force, const Rational& mu,
                         const std::vector<std::vector<Vec2>>& holes = {}) {
  std::string s = "{\"wrenchkit\": 1, \"support\": {\"mu\": " + num(mu) + ", \"regions\": [{\"outline\": " + ring(outline);
  if (!holes.empty()) {
    s += ", \"holes\": [";
    for (std::size_t j = 0; j < holes.size(); ++j) s += (j ? ", " : "") + ring(holes[j]);
    s += "]";
  }
  return s + ", \"pressure\": \"uniform\", \"force\": " + num(force) + "}]}}";
}

std::vector<Vec2> square(const Rational& h) { return {{-h, -h}, {h, -h}, {h, h}, {-h, h}}; }

// Rational points on the circle of radius R: u(t) = ((1 − t²)/(1 + t²), 2t/(1 + t²)), t = tan(φ/2) rounded to a
// rational with denominator 10^6 (exactly on the circle whatever the rounding).
std::vector<Vec2> inscribed(int n, const Rational& R) {
  std::vector<Vec2> v;
  for (int j = 0; j < n; ++j) {
    const double phi = 2 * M_PI * (j + 0.5) / n - M_PI;
    const Rational t(static_cast<long>(std::llround(std::tan(phi / 2) * 1e6)), 1000000);
    const Rational d = 1 + t * t;
    v.push_back({R * (1 - t * t) / d, R * 2 * t / d});
  }
  return v;
}
// The tangents at the inscribed polygon's vertices meet at R (u_j + u_{j+1})/(1 + u_j·u_{j+1}) (theory.md §12.2).
std::vector<Vec2> circumscribed(int n, const Rational& R) {
  const std::vector<Vec2> u = inscribed(n, 1);
  std::vector<Vec2> v;
  for (int j = 0; j < n; ++j) {
    const Vec2& a = u[static_cast<std::size_t>(j)];
    const Vec2& b = u[static_cast<std::size_t>((j + 1) % n)];
    const Rational d = 1 + a.x * b.x + a.y * b.y;
    v.push_back({R * (a.x + b.x) / d, R * (a.y + b.y) / d});
  }
  return v;
}

Scene read(const std::string& text) { return read_scene(text, kLimits); }

Region_sliding power(const std::string& text, const Vec3q& q, const Rational& tol = Rational(1, 1000000)) {
  const Scene s = read(text);
  return region_sliding(*s.support, q, tol);
}
Region_sliding statics(const std::string& text) { return region_sliding(*read(text).support, std::nullopt, 1); }

// ---------------------------------------------------------------------------------------------------------------
// Reading.

TEST(RegionReading, MeasuresOfASquareAndALinearPressure) {
  const Scene s = read(region_scene(square(1), 1, 1));
  const Support_region& r = s.support->regions.at(0);
  EXPECT_EQ(r.area, 4);
  EXPECT_EQ(r.total, 1);
  EXPECT_EQ(r.moment.x, 0);
  EXPECT_EQ(r.moment.y, 0);
  EXPECT_EQ(r.second[0], Rational(1, 3));  // ∫ x² (1/4) over [-1,1]² = 1/3
  EXPECT_EQ(r.second[1], 0);
  // p = x on [0,1]²: W = 1/2, ∫ x p = 1/3, ∫ y p = 1/4, ∫ x² p = 1/4, ∫ xy p = 1/6, ∫ y² p = 1/6.
  const Scene l = read(
      "{\"wrenchkit\": 1, \"support\": {\"mu\": 1, \"regions\": [{\"outline\": [[0,0],[1,0],[1,1],[0,1]], "
      "\"pressure\": {\"linear\": [0, 1, 0]}}]}}");
  const Support_region& q = l.support->regions.at(0);
  EXPECT_EQ(q.total, Rational(1, 2));
  EXPECT_EQ(q.moment.x, Rational(1, 3));
  EXPECT_EQ(q.moment.y, Rational(1, 4));
  EXPECT_EQ(q.second[0], Rational(1, 4));
  EXPECT_EQ(q.second[1], Rational(1, 6));
  EXPECT_EQ(q.second[2], Rational(1, 6));
}

TEST(RegionReading, OrientationIsNormalisedAndHolesSubtract) {
  std::vector<Vec2> cw = square(2);
  std::reverse(cw.begin(), cw.end());
  const Scene s = read(region_scene(cw, 3, 1, {square(1)}));  // a hole written counter-clockwise
  const Support_region& r = s.support->regions.at(0);
  EXPECT_EQ(r.area, 12);
  EXPECT_EQ(r.rings.size(), 2u);
  // The outline is counter-clockwise, the hole clockwise, and the triangles tile the ring.
  Rational sum;
  for (const Region_triangle& t : r.triangles) {
    const Rational a2 = (t.b.x - t.a.x) * (t.c.y - t.a.y) - (t.b.y - t.a.y) * (t.c.x - t.a.x);
    EXPECT_GT(a2, 0);
    sum += a2 / 2;
  }
  EXPECT_EQ(sum, 12);
  // As written, back: the canonical writer keeps the input's order and orientation.
  EXPECT_EQ(write_scene(read(write_scene(s))), write_scene(s));
}

struct Bad_region {
  std::string region, message;
};

TEST(RegionReading, BadRegionsNameTheRegionAndTheReason) {
  const std::vector<Bad_region> cases = {
      {"{\"outline\": [[0,0],[1,1],[1,0],[0,1]], \"pressure\": \"uniform\", \"force\": 1}",
       "support.regions[0].outline: is not a simple polygon"},
      {"{\"outline\": [[0,0],[1,0],[2,0]], \"pressure\": \"uniform\", \"force\": 1}",
       "support.regions[0].outline: is not a simple polygon"},
      {"{\"outline\": [[0,0],[1,0]], \"pressure\": \"uniform\", \"force\": 1}",
       "support.regions[0].outline: has 2 vertices"},
      {"{\"outline\": [[0,0],[1,0],[1,0],[0,1]], \"pressure\": \"uniform\", \"force\": 1}",
       "support.regions[0].outline: is not a simple polygon (a vertex is repeated)"},
      {"{\"outline\": [[0,0],[4,0],[4,4],[0,4]], \"holes\": [[[3,3],[5,3],[5,5],[3,5]]], \"pressure\": \"uniform\", "
       "\"force\": 1}",
       "support.regions[0].holes[0]: meets the outline"},
      {"{\"outline\": [[0,0],[4,0],[4,4],[0,4]], \"holes\": [[[5,5],[6,5],[6,6],[5,6]]], \"pressure\": \"uniform\", "
       "\"force\": 1}",
       "support.regions[0].holes[0]: is not inside the outline"},
      {"{\"outline\": [[0,0],[4,0],[4,4],[0,4]], \"holes\": [[[1,1],[3,1],[3,3],[1,3]], [[2,2],[\"5/2\",2],[\"5/2\",\"5/2\"]]], "
       "\"pressure\": \"uniform\", \"force\": 1}",
       "support.regions[0].holes[1]: lies inside holes[0]"},
      {"{\"outline\": [[0,0],[4,0],[4,4],[0,4]], \"holes\": [[[1,1],[3,1],[3,3],[1,3]], [[2,2],[\"7/2\",2],[\"7/2\",\"7/2\"]]], "
       "\"pressure\": \"uniform\", \"force\": 1}",
       "support.regions[0].holes[1]: meets holes[0]"},
      {"{\"outline\": [[0,0],[4,0],[4,4],[0,4]], \"holes\": [[[0,0],[1,1],[1,2]]], \"pressure\": \"uniform\", "
       "\"force\": 1}",
       "support.regions[0].holes[0]: meets the outline"},
      {"{\"outline\": [[0,0],[1,0],[1,1],[0,1]], \"pressure\": {\"linear\": [\"-1/2\", 1, 0]}}",
       "support.regions[0].pressure: p = -1/2 < 0 at outline[0] (0, 0)"},
      {"{\"outline\": [[0,0],[1,0],[1,1],[0,1]], \"pressure\": {\"linear\": [0, 0, 0]}}",
       "support.regions[0].pressure: the pressure is zero on the whole region"},
      {"{\"outline\": [[0,0],[1,0],[1,1],[0,1]], \"pressure\": \"uniform\", \"force\": 0}",
       "support.regions[0].force: 0 is not positive"},
      {"{\"outline\": [[0,0],[1,0],[1,1],[0,1]], \"pressure\": \"uniform\"}",
       "support.regions[0]: missing key \"force\""},
      {"{\"outline\": [[0,0],[1,0],[1,1],[0,1]], \"pressure\": {\"linear\": [1, 0, 0]}, \"force\": 1}",
       "support.regions[0].force: not allowed with a linear pressure"},
      {"{\"outline\": [[0,0],[1,0],[1,1],[0,1]], \"pressure\": \"even\", \"force\": 1}",
       "support.regions[0].pressure: \"even\" is not \"uniform\""},
      {"{\"outline\": [[0,0],[1,0],[1,1],[0,1]], \"pressure\": \"uniform\", \"force\": 1, \"colour\": 1}",
       "support.regions[0]: unknown key \"colour\""},
  };
  for (const Bad_region& c : cases) {
    const std::string text = "{\"wrenchkit\": 1, \"support\": {\"mu\": 1, \"regions\": [" + c.region + "]}}";
    try {
      read(text);
      ADD_FAILURE() << "accepted: " << c.region;
    } catch (const Input_error& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what() << "\nwanted: " << c.message;
    }
    // The independent checker refuses the scene too (its own reading, GMP only).
    const auto r = wrenchkit_checker::check(text, "{}");
    EXPECT_EQ(r.outcome, wrenchkit_checker::Outcome::bad_scene) << c.region << ": " << r.message;
  }
  // A region without mu, and none in the support.
  EXPECT_THROW(read("{\"wrenchkit\": 1, \"support\": {\"regions\": [{\"outline\": [[0,0],[1,0],[0,1]], \"pressure\": "
                    "\"uniform\", \"force\": 1}]}}"),
               Input_error);
}

TEST(RegionReading, CollinearVerticesAreFine) {
  // A vertex in the middle of an edge, and a hole touching nothing.
  const std::string text = region_scene({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, 1, 1, {{{1, 1}, {Rational(3, 2), 1}, {1, Rational(3, 2)}}});
  const Scene s = read(text);
  EXPECT_EQ(s.support->regions[0].area, Rational(4) - Rational(1, 8));
  // The checker reads the same regions as valid (a certificate of nothing is rejected, the scene is not bad), and
  // the one-pass reader reads them without deferring.
  for (const std::string& t : {text, region_scene(square(1), 1, 1, {square(Rational(1, 2))}),
                               std::string("{\"wrenchkit\": 1, \"support\": {\"mu\": 1, \"regions\": [{\"outline\": "
                                           "[[0,0],[3,0],[3,3],[2,3],[2,1],[1,1],[1,3],[0,3]], \"pressure\": {\"linear\": "
                                           "[1, 0, \"1/3\"]}}]}}")}) {
    EXPECT_EQ(wrenchkit_checker::check(t, "{}").outcome, wrenchkit_checker::Outcome::rejected) << t;
    Scene into;
    EXPECT_TRUE(read_scene_into(into, t, kLimits, "scene", false)) << t;
  }
}

// ---------------------------------------------------------------------------------------------------------------
// The power and the load against closed forms (theory.md §14.1).

TEST(RegionPower, UniformSquareAboutItsCentre) {
  const double truth = (std::sqrt(2.0) + std::asinh(1.0)) / 3;  // 0.7651957165…
  const Region_sliding a = power(region_scene(square(1), 1, 1), {0, 0, 1});
  EXPECT_EQ(a.center_of_pressure.x, 0);
  EXPECT_EQ(a.center_of_pressure.y, 0);
  EXPECT_TRUE(a.met);
  EXPECT_LE(a.h_lo.get_d(), truth * (1 + 1e-15));
  EXPECT_GE(a.h_hi.get_d(), truth * (1 - 1e-15));
  EXPECT_LE(Rational(a.h_hi - a.h_lo).get_d(), 1e-6 * truth);
  // About the centre, by symmetry, the force is zero and the moment is the power.
  EXPECT_LE(a.load_lo[0], 0);
  EXPECT_GE(a.load_hi[0], 0);
  EXPECT_NEAR(a.load_lo[2].get_d(), truth, 1e-6);
  // Clockwise: the same power, the opposite moment.
  const Region_sliding b = power(region_scene(square(1), 1, 1), {0, 0, -1});
  EXPECT_EQ(b.h_lo, a.h_lo);
  EXPECT_NEAR(b.load_hi[2].get_d(), -truth, 1e-6);
}

TEST(RegionPower, RectangleAndDiscAndRing) {
  // Rectangle [-2,2]x[-1,1]: 1.186466832 (μ f₀ = 1).
  const Region_sliding r = power(region_scene({{-2, -1}, {2, -1}, {2, 1}, {-2, 1}}, 1, 1), {0, 0, 1});
  EXPECT_NEAR(r.h_lo.get_d(), 1.186466832, 1e-8);
  // Uniform disc of radius 1: 2/3, between the inscribed and the circumscribed 64-gons.
  const Region_sliding in = power(region_scene(inscribed(64, 1), 1, 1), {0, 0, 1});
  const Region_sliding out = power(region_scene(circumscribed(64, 1), 1, 1), {0, 0, 1});
  EXPECT_LT(in.h_hi, Rational(2, 3));
  EXPECT_GT(out.h_lo, Rational(2, 3));
  EXPECT_LT(Rational(out.h_hi - in.h_lo).get_d(), 1e-3);
  // A thin ring 0.99 … 1.01 (the circumscribed outer 256-gon, the inscribed inner one as a hole): R = 1.
  const Region_sliding ring = power(region_scene(circumscribed(256, Rational(101, 100)), 1, 1, {inscribed(256, Rational(99, 100))}), {0, 0, 1});
  EXPECT_NEAR(ring.h_lo.get_d(), 1.0, 2e-4);
  // The disc with the rotation centre on its rim, (1, 0), ω > 0: the table's load (0, −0.84882636, 0.28294212).
  const Region_sliding rim = power(region_scene(inscribed(256, 1), 1, 1), {0, -1, 1});
  EXPECT_NEAR(rim.load_lo[1].get_d(), -0.84882636, 5e-4);
  EXPECT_NEAR(rim.load_lo[2].get_d(), 0.28294212, 5e-4);
  EXPECT_NEAR(rim.h_lo.get_d(), 32 / (9 * M_PI), 5e-4);  // the mean distance from a rim point
}

// An independent double quadrature of ∫ |r − c| p dA and ∫ (r − c)/|r − c| p dA over the region's triangles (each
// cut into n² pieces, a 7-point rule on each).
std::array<double, 3> quadrature(const Support_region& r, double cx, double cy, int n) {
  std::array<double, 3> out{0, 0, 0};
  const double p0 = r.pressure[0].get_d(), p1 = r.pressure[1].get_d(), p2 = r.pressure[2].get_d();
  const auto f = [&](double x, double y, double w) {
    const double d = std::hypot(x - cx, y - cy);
    const double p = p0 + p1 * x + p2 * y;
    out[0] += w * d * p;
    if (d > 0) out[1] += w * (x - cx) / d * p, out[2] += w * (y - cy) / d * p;
  };
  for (const Region_triangle& t : r.triangles) {
    const double ax = t.a.x.get_d(), ay = t.a.y.get_d(), ux = t.b.x.get_d() - ax, uy = t.b.y.get_d() - ay,
                 vx = t.c.x.get_d() - ax, vy = t.c.y.get_d() - ay;
    const double area = std::fabs(ux * vy - uy * vx) / 2 / (n * n);
    const auto tri = [&](double s0, double t0, double s1, double t1, double s2, double t2) {
      const double P[3][2] = {{ax + s0 * ux + t0 * vx, ay + s0 * uy + t0 * vy},
                              {ax + s1 * ux + t1 * vx, ay + s1 * uy + t1 * vy},
                              {ax + s2 * ux + t2 * vx, ay + s2 * uy + t2 * vy}};
      const double gx = (P[0][0] + P[1][0] + P[2][0]) / 3, gy = (P[0][1] + P[1][1] + P[2][1]) / 3;
      f(gx, gy, area * 27 / 60);
      for (int k = 0; k < 3; ++k) {
        f(P[k][0], P[k][1], area * 3 / 60);
        f((P[k][0] + P[(k + 1) % 3][0]) / 2, (P[k][1] + P[(k + 1) % 3][1]) / 2, area * 8 / 60);
      }
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        const double s = 1.0 / n;
        tri(i * s, j * s, (i + 1) * s, j * s, i * s, (j + 1) * s);
        if (i + j + 2 <= n) tri((i + 1) * s, j * s, (i + 1) * s, (j + 1) * s, i * s, (j + 1) * s);
      }
  }
  return out;
}

// A random simple polygon: a star-shaped one around the origin (random radii at sorted random angles), with an
// optional hole (a small triangle near the origin), integer-grid coordinates over 64.
std::vector<Vec2> random_star(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> radius(1, 3);
  std::vector<double> angle;
  for (int i = 0; i < n; ++i) angle.push_back(2 * M_PI * (i + 0.2 + 0.6 * std::uniform_real_distribution<double>(0, 1)(rng)) / n);
  std::vector<Vec2> v;
  for (double a : angle) {
    const double r = radius(rng);
    v.push_back({Rational(static_cast<long>(std::llround(64 * r * std::cos(a))), 64),
                 Rational(static_cast<long>(std::llround(64 * r * std::sin(a))), 64)});
  }
  return v;
}

TEST(RegionPower, RandomRegionsAgainstAnIndependentQuadrature) {
  std::mt19937_64 rng(test::seed(20261202));
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 3 + static_cast<int>(rng() % 12);
    const std::vector<Vec2> outline = random_star(rng, n);
    std::string text = region_scene(outline, Rational(1 + static_cast<long>(rng() % 5)), Rational(1, 2 + static_cast<long>(rng() % 3)),
                                    trial % 3 == 0 ? std::vector<std::vector<Vec2>>{{{Rational(-1, 4), Rational(-1, 4)}, {Rational(1, 4), Rational(-1, 4)}, {0, Rational(1, 4)}}} : std::vector<std::vector<Vec2>>{});
    if (trial % 2 == 1) {  // a linear pressure, positive on the polygon (radius ≤ 3)
      const std::string lin = "\"pressure\": {\"linear\": [4, \"" + std::to_string(static_cast<int>(rng() % 3)) + "/7\", \"-1/5\"]}";
      const auto at = text.find("\"pressure\": \"uniform\"");
      const auto end = text.find('}', at);
      text = text.substr(0, at) + lin + text.substr(end);
    }
    Scene s;
    try {
      s = read(text);
    } catch (const Input_error& e) {
      FAIL() << e.what() << "\n" << text;
    }
    const Support_region& r = s.support->regions[0];
    const Rational mu = s.support->mu_of(r);
    for (int k = 0; k < 4; ++k) {
      // Rotation centres inside, on a vertex, and outside.
      const Vec2 c = k == 0 ? Vec2{Rational(1, 3), Rational(-1, 5)} : k == 1 ? r.outline[0] : Vec2{Rational(7), Rational(5, 2)};
      const Vec3q q{c.y, -c.x, Rational(1)};  // rotation about c, ω = 1
      const Region_sliding a = region_sliding(*s.support, q, Rational(1, 1000000));
      const std::array<double, 3> quad = quadrature(r, c.x.get_d(), c.y.get_d(), k == 0 || k == 1 ? 64 : 16);
      const double h = mu.get_d() * quad[0];
      EXPECT_NEAR(a.h_lo.get_d(), h, 1e-5 * h) << text << " about " << to_string(c.x) << "," << to_string(c.y);
      EXPECT_LE(Rational(a.h_hi - a.h_lo).get_d(), 1e-6 * h);
      // The load: F = μ rot90(J), m = μ(K + c·J).
      const double fx = -mu.get_d() * quad[2], fy = mu.get_d() * quad[1];
      const double m = mu.get_d() * (quad[0] + c.x.get_d() * quad[1] + c.y.get_d() * quad[2]);
      // (r − c)/|r − c| jumps at c: the quadrature's error on J is larger than on K, and c·J carries it.
      const double tol = 3e-4 * (1 + std::fabs(c.x.get_d()) + std::fabs(c.y.get_d())) * (1 + h);
      EXPECT_NEAR(a.load_lo[0].get_d(), fx, tol) << "k " << k;
      EXPECT_NEAR(a.load_lo[1].get_d(), fy, tol) << "k " << k;
      EXPECT_NEAR(a.load_lo[2].get_d(), m, tol) << "k " << k;
      // The double evaluation of the same closed form (the search's) agrees with the certified bracket.
      const double hd = mu.get_d() * fan_power_double(r, c.x.get_d(), c.y.get_d());
      EXPECT_GE(hd, a.h_lo.get_d() * (1 - 1e-9));
      EXPECT_LE(hd, a.h_hi.get_d() * (1 + 1e-9));
    }
    if (HasFailure()) return;
  }
}

TEST(RegionPower, TranslationIsExact) {
  const Region_sliding a = power(region_scene(square(1), 2, Rational(1, 2)), {3, 4, 0});
  ASSERT_TRUE(a.load);
  EXPECT_EQ((*a.load)[0], Rational(3, 5));  // μW v̂ = (1)(3/5, 4/5)
  EXPECT_EQ((*a.load)[1], Rational(4, 5));
  EXPECT_EQ(a.h_lo, 5);
  EXPECT_EQ(a.h_hi, 5);
}

TEST(RegionPower, InvariantUnderRationalRotationsAndTranslations) {
  // Rotate by (3/5, 4/5) and move by (7/3, -2): the power about the moved centre is the same number.
  std::mt19937_64 rng(test::seed(7));
  for (int trial = 0; trial < 10; ++trial) {
    const std::vector<Vec2> v = random_star(rng, 5 + trial % 4);
    const Rational c(3, 5), s(4, 5), tx(7, 3), ty(-2);
    std::vector<Vec2> w;
    for (const Vec2& p : v) w.push_back({c * p.x - s * p.y + tx, s * p.x + c * p.y + ty});
    const Vec2 center{Rational(1, 7), Rational(2, 9)};
    const Vec2 moved{c * center.x - s * center.y + tx, s * center.x + c * center.y + ty};
    const Region_sliding a = power(region_scene(v, 1, 1), {center.y, -center.x, 1});
    const Region_sliding b = power(region_scene(w, 1, 1), {moved.y, -moved.x, 1});
    EXPECT_TRUE(a.h_lo <= b.h_hi && b.h_lo <= a.h_hi);
    const Region_sliding ca = statics(region_scene(v, 1, 1));
    const Region_sliding cb = statics(region_scene(w, 1, 1));
    EXPECT_EQ(cb.center_of_pressure.x, c * ca.center_of_pressure.x - s * ca.center_of_pressure.y + tx);
    EXPECT_EQ(cb.center_of_pressure.y, s * ca.center_of_pressure.x + c * ca.center_of_pressure.y + ty);
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Stick / slide with certificates, through the pipeline (every certificate checked by the independent checker).

Support_item motion_of(const std::string& text, const Vec3q& p, Mode mode = Mode::hybrid) {
  Request request;
  request.mode = mode;
  Support_query q;
  q.load = p;
  return answer_support(text, "scene", request, q);
}

// A small uniform square of half-size h at (x, y) with force f, as a region object.
std::string leg(const Rational& x, const Rational& y, const Rational& h, const Rational& f) {
  return "{\"outline\": " + ring({{x - h, y - h}, {x + h, y - h}, {x + h, y + h}, {x - h, y + h}}) +
         ", \"pressure\": \"uniform\", \"force\": " + num(f) + "}";
}

TEST(RegionMotion, SquareSticksInsideAndSlidesOutside) {
  const std::string sq = region_scene(square(1), 1, 1);
  const double h = (std::sqrt(2.0) + std::asinh(1.0)) / 3;
  struct Case {
    Vec3q load;
    Motion motion;
  };
  const std::vector<Case> cases = {
      {{0, 0, Rational(1, 2)}, Motion::sticks},         {{0, 0, Rational(4, 5)}, Motion::slides},
      {{Rational(99, 100), 0, 0}, Motion::sticks},      {{Rational(101, 100), 0, 0}, Motion::slides},
      {{Rational(3, 5), Rational(3, 10), Rational(2, 5)}, Motion::sticks},
      {{0, 0, Rational(static_cast<long>(std::floor(h * 0.999 * 1e6)), 1000000)}, Motion::sticks},
      {{0, 0, Rational(static_cast<long>(std::ceil(h * 1.001 * 1e6)), 1000000)}, Motion::slides},
      {{0, 0, 0}, Motion::sticks},
  };
  for (const Case& c : cases)
    for (Mode mode : {Mode::hybrid, Mode::exact}) {
      const Support_item r = motion_of(sq, c.load, mode);
      ASSERT_EQ(r.status, Status::answered) << r.message;
      EXPECT_EQ(r.motion->motion, c.motion) << to_string(c.load[0]) << "," << to_string(c.load[1]) << "," << to_string(c.load[2]);
      EXPECT_FALSE(r.certificate.empty());  // checked by the independent checker inside answer_support
    }
  // Float: no twin of regions.
  EXPECT_EQ(motion_of(sq, {0, 0, Rational(1, 2)}, Mode::float_only).status, Status::undecided);
}

TEST(RegionMotion, TableAndPlateAsSmallRegionsReachTheirPointMassLimits) {
  // The four-legged table with a known, even distribution (theory-sliding §6): legs at (±1, ±1), 1/4 each, μ = 1;
  // the pure moment that sticks tends to √2 as the legs shrink, the force to 1.
  const Rational e(1, 100);
  std::string legs;
  for (const auto& [x, y] : std::vector<std::pair<int, int>>{{1, 1}, {-1, 1}, {-1, -1}, {1, -1}})
    legs += (legs.empty() ? "" : ", ") + leg(x, y, e, Rational(1, 4));
  const std::string table = "{\"wrenchkit\": 1, \"support\": {\"mu\": 1, \"regions\": [" + legs + "]}}";
  const Region_sliding a = power(table, {0, 0, 1});
  EXPECT_NEAR(a.h_lo.get_d(), std::sqrt(2.0), 1e-4);
  EXPECT_EQ(motion_of(table, {0, 0, Rational(140, 100)}).motion->motion, Motion::sticks);
  EXPECT_EQ(motion_of(table, {0, 0, Rational(142, 100)}).motion->motion, Motion::slides);
  EXPECT_EQ(motion_of(table, {Rational(99, 100), 0, 0}).motion->motion, Motion::sticks);
  EXPECT_EQ(motion_of(table, {Rational(101, 100), 0, 0}).motion->motion, Motion::slides);
  // The dinner plate carried by its rim: eight small regions at radius 1 (rational points on the circle), 1/8 each;
  // the pure moment μWR = 1 is the threshold.
  std::string rim;
  for (const Vec2& v : inscribed(8, 1)) rim += (rim.empty() ? "" : ", ") + leg(v.x, v.y, e, Rational(1, 8));
  const std::string plate = "{\"wrenchkit\": 1, \"support\": {\"mu\": 1, \"regions\": [" + rim + "]}}";
  EXPECT_NEAR(power(plate, {0, 0, 1}).h_lo.get_d(), 1.0, 1e-4);
  EXPECT_EQ(motion_of(plate, {0, 0, Rational(99, 100)}).motion->motion, Motion::sticks);
  EXPECT_EQ(motion_of(plate, {0, 0, Rational(101, 100)}).motion->motion, Motion::slides);
}

TEST(RegionMotion, PointsWithRegionsAndLinearPressure) {
  // A point (3, 0) with force 1 and the square [-1,1]² pressed by p = 1 + x/2 (W = 4, centre of pressure (1/6, 0)).
  const std::string text =
      "{\"wrenchkit\": 1, \"support\": {\"mu\": \"1/2\", \"points\": [{\"at\": [3, 0], \"force\": 1}], \"regions\": "
      "[{\"outline\": [[-1,-1],[1,-1],[1,1],[-1,1]], \"pressure\": {\"linear\": [1, \"1/2\", 0]}, \"mu\": 1}]}}";
  const Scene s = read(text);
  EXPECT_EQ(s.support->regions[0].total, 4);
  const Region_sliding st = region_sliding(*s.support, std::nullopt, 1);
  EXPECT_EQ(st.total_force, 5);
  EXPECT_EQ(st.center_of_pressure.x, (3 + Rational(2, 3)) / 5);  // (1·3 + 4·(1/6))/5
  EXPECT_EQ(st.mu_f0, Rational(9, 2));
  for (const auto& [p, m] : std::vector<std::pair<Vec3q, Motion>>{{{4, 0, 0}, Motion::sticks},
                                                                  {{5, 0, 0}, Motion::slides},
                                                                  {{0, 1, 2}, Motion::sticks},
                                                                  {{0, 0, 6}, Motion::slides}}) {
    const Support_item r = motion_of(text, p);
    ASSERT_EQ(r.status, Status::answered) << r.message;
    EXPECT_EQ(r.motion->motion, m) << to_string(p[0]) << "," << to_string(p[1]) << "," << to_string(p[2]);
  }
}

TEST(RegionMotion, RandomRegionsNearTheirLimitSurfaceAreCertified) {
  // Random star regions (some with holes, some linear), random load directions scaled to 10^-2 inside and outside
  // the limit surface (by the search's gauge): the answer is the side, and every certificate is accepted.
  std::mt19937_64 rng(test::seed(1202));
  std::uniform_int_distribution<int> coord(-8, 8);
  int decided = 0;
  for (int trial = 0; trial < 16; ++trial) {
    const std::string text = region_scene(random_star(rng, 4 + trial % 6), 1 + trial % 3, Rational(1, 2));
    const Scene s = read(text);
    Vec3q dir{Rational(coord(rng)) / 4, Rational(coord(rng)) / 4, Rational(coord(rng)) / 4};
    if (dir[0] == 0 && dir[1] == 0 && dir[2] == 0) dir[2] = 1;
    const Motion_answer probe = decide_on_regions(*s.support, dir);
    const double g = probe.gauge_estimate;  // dir/g is on the limit surface
    ASSERT_TRUE(std::isfinite(g) && g > 0) << text;
    for (const double side : {0.99, 1.01}) {
      const Rational k(static_cast<long>(std::llround(side / g * 1e9)), 1000000000);
      const Vec3q p{dir[0] * k, dir[1] * k, dir[2] * k};
      const Support_item r = motion_of(text, p);
      ASSERT_EQ(r.status, Status::answered) << r.message << "\n" << text;
      EXPECT_EQ(r.motion->motion, side < 1 ? Motion::sticks : Motion::slides) << text << " side " << side;
      decided += r.motion->motion != Motion::undecided;
    }
  }
  EXPECT_EQ(decided, 32);
}

TEST(RegionMotion, TamperedCertificatesAreRejected) {
  const std::string sq = region_scene(square(1), 1, 1);
  const Support_item stick = motion_of(sq, {Rational(1, 2), 0, Rational(1, 4)});
  ASSERT_EQ(stick.motion->motion, Motion::sticks);
  const Support_item slide = motion_of(sq, {0, 0, Rational(4, 5)});
  ASSERT_EQ(slide.motion->motion, Motion::slides);
  using wrenchkit_checker::Outcome;
  EXPECT_EQ(wrenchkit_checker::check(sq, stick.certificate).outcome, Outcome::accepted);
  EXPECT_EQ(wrenchkit_checker::check(sq, slide.certificate).outcome, Outcome::accepted);
  // Another load, another region, a scaled force: rejected.
  const auto replace = [](std::string t, const std::string& a, const std::string& b) {
    const auto at = t.find(a);
    return at == std::string::npos ? std::string() : t.replace(at, a.size(), b);
  };
  EXPECT_EQ(wrenchkit_checker::check(sq, replace(stick.certificate, "\"load\": [\"1/2\"", "\"load\": [\"3/5\"")).outcome,
            Outcome::rejected);
  EXPECT_EQ(wrenchkit_checker::check(region_scene(square(1), 1, Rational(1, 2)), stick.certificate).outcome,
            Outcome::rejected);  // μ 1/2: the discs shrink
  EXPECT_EQ(wrenchkit_checker::check(region_scene(square(Rational(99, 100)), 1, 1), slide.certificate).outcome,
            Outcome::rejected);  // another square: the cells no longer tile it
  EXPECT_EQ(wrenchkit_checker::check(sq, replace(slide.certificate, "\"load\": [\"0\", \"0\", \"4/5\"]",
                                                 "\"load\": [\"0\", \"0\", \"3/4\"]")).outcome,
            Outcome::rejected);  // below the power
}

// ---------------------------------------------------------------------------------------------------------------
// [RG-3] Stick / slide over regions with points whose force is not given (format 2, certificate-format.md §6.5).

// The mat [-1/2, 1/2]² (uniform, force 1) and legs (-2, 0), (0, 0), (2, 0) without forces, W = 5 at the origin,
// μ = 1/2 (`mu`): W' = 4, F's vertices (0, 4, 0) and (2, 0, 2).
std::string mat_legs(const std::string& mu = "1/2") {
  return R"({"wrenchkit": 1, "support": {"mu": ")" + mu + R"(", "weight": 5, "pressure_center": [0, 0],
      "points": [{"at": [-2, 0]}, {"at": [0, 0]}, {"at": [2, 0]}], "regions": [{"outline": [["-1/2", "-1/2"],
      ["1/2", "-1/2"], ["1/2", "1/2"], ["-1/2", "1/2"]], "pressure": "uniform", "force": 1}]}})";
}

TEST(RegionMotionOver, MatAndLegsGolden) {
  // By hand: at both vertices the friction forces sum to at most μ(4 + 1) = 5/2 (a translation); the pure moment is
  // carried up to μ ∫|r| p ≈ 0.1913 by the mat alone under (0, 4, 0) (the middle leg sits at the centre) and up to
  // 4 + 0.1913 under (2, 0, 2).
  struct Case {
    Vec3q load;
    Motion motion;
  };
  const std::vector<Case> cases = {
      {{2, 0, 0}, Motion::sticks},                  // inside both
      {{3, 0, 0}, Motion::slides},                  // the translation (1, 0, 0): the dual bound 2 + the mat's 1/2
      {{Rational(5, 2), 0, 0}, Motion::impending},  // on every limit surface: the translation meets every bound
      {{0, 0, Rational(1, 10)}, Motion::sticks},    // below the mat's 0.1913
      {{0, 0, 1}, Motion::depends},                 // the barbell sticks, the middle leg slides
      {{0, 0, 5}, Motion::slides},                  // above 4.1913: the rotation about the centre
      {{1, Rational(1, 2), Rational(1, 2)}, Motion::depends},
  };
  const std::string scene = mat_legs();
  for (const Case& c : cases)
    for (const Mode mode : {Mode::hybrid, Mode::exact}) {
      const std::string where = mode_name(mode) + std::string(" load ") + to_string(c.load[0]) + "," +
                                to_string(c.load[1]) + "," + to_string(c.load[2]);
      const Support_item r = motion_of(scene, c.load, mode);
      ASSERT_EQ(r.status, Status::answered) << r.message << " " << where;
      ASSERT_TRUE(r.motion && r.admissible) << where;
      EXPECT_EQ(r.motion->motion, c.motion) << where << "\n" << r.motion->undecided_why;
      ASSERT_EQ(r.vertices.size(), 2u);
      EXPECT_EQ(r.vertices[0], (std::vector<Rational>{0, 4, 0}));
      EXPECT_EQ(r.vertices[1], (std::vector<Rational>{2, 0, 2}));
      // Checked inside answer_support; again here, and its header.
      EXPECT_EQ(r.certificate.rfind(R"({"wrenchkit_certificate": 3, "property": "motion")", 0), 0u) << r.certificate;
      EXPECT_TRUE(test::checker_accepts(scene, r.certificate)) << where;
      if (c.motion == Motion::depends) {
        EXPECT_EQ(r.motion->per_vertex, (std::vector<Motion>{Motion::slides, Motion::sticks})) << where;
      }
      // Format 1 has none; less friction (μ 1/4) breaks sticks, more (μ 1; 3 for depends, whose sticking witness
      // stays inside larger discs) breaks slides.
      std::string v1 = r.certificate;
      v1.replace(v1.find(": 3,"), 4, ": 1,");
      EXPECT_NE(wrenchkit_checker::check(scene, v1).message.find("no certificate in format 1"), std::string::npos);
      const std::string other = mat_legs(c.motion == Motion::sticks    ? "1/4"
                                         : c.motion == Motion::depends ? "3"
                                                                            : "1");
      EXPECT_EQ(wrenchkit_checker::check(other, r.certificate).outcome, wrenchkit_checker::Outcome::rejected) << where;
    }
  // The power of a twist over F: the points' range plus the regions' bracket (the rotation about the centre: the
  // legs give [0, 4] over F, the mat (√2 + asinh 1)/12 ≈ 0.1913).
  Request request;
  Support_query q;
  q.question = Support_question::sliding;
  q.twist = Vec3q{0, 0, 1};
  const Support_item p = answer_support(scene, "scene", request, q);
  ASSERT_EQ(p.status, Status::answered) << p.message;
  ASSERT_TRUE(p.power && p.regions);
  const double mat = (std::sqrt(2.0) + std::asinh(1.0)) / 12;
  EXPECT_NEAR(p.power->lower.get_d(), mat, 1e-6);
  EXPECT_NEAR(p.power->upper.get_d(), 4 + mat, 1e-6);
  EXPECT_LE(p.regions->h_lo.get_d(), mat * (1 + 1e-12));
  EXPECT_GE(p.regions->h_hi.get_d(), mat * (1 - 1e-12));
  // Float: no twin of regions.
  EXPECT_EQ(motion_of(scene, {2, 0, 0}, Mode::float_only).status, Status::undecided);
}

// U = ∪_F LS(f) is not convex: legs at (±2, 0) and (0, ±2) whose forces are not given (F's vertices the two barbells)
// beside a small mat. The load (3/2, 3/2, -2) slides under both barbells, yet the even mixture sticks: step 3 of RG-3
// §5 (the LP over F on the mat's cells as given points) finds it — depends, decided by "lp".
TEST(RegionMotionOver, AMixtureSticksWhereNoVertexDoes) {
  const std::string cross = R"({"wrenchkit": 1, "support": {"mu": "1/2", "weight": 5, "pressure_center": [0, 0],
      "points": [{"at": [-2, 0]}, {"at": [2, 0]}, {"at": [0, -2]}, {"at": [0, 2]}], "regions": [{"outline":
      [["-1/4", "-1/4"], ["1/4", "-1/4"], ["1/4", "1/4"], ["-1/4", "1/4"]], "pressure": "uniform", "force": "1/5"}]}})";
  for (const Mode mode : {Mode::hybrid, Mode::exact}) {
    const Support_item r = motion_of(cross, {Rational(3, 2), Rational(3, 2), -2}, mode);
    ASSERT_EQ(r.status, Status::answered) << r.message;
    ASSERT_TRUE(r.motion);
    EXPECT_EQ(r.motion->motion, Motion::depends) << r.motion->undecided_why;
    EXPECT_EQ(r.motion->decided_by, Decided_by::lp);
    EXPECT_EQ(r.motion->per_vertex, (std::vector<Motion>(r.vertices.size(), Motion::slides)));
    ASSERT_TRUE(r.motion->sticking);
    const Scene sc = read(cross);
    EXPECT_TRUE(admissible_set(sc).contains(*sc.support, r.motion->sticking->distribution));
    // The oracle: that distribution sticks by the known-forces decision, the vertices slide.
    Support t = *sc.support;
    for (std::size_t i = 0; i < t.points.size(); ++i) t.points[i].force = r.motion->sticking->distribution[i];
    EXPECT_EQ(decide_on_regions(t, {Rational(3, 2), Rational(3, 2), -2}).motion, Motion::sticks);
    EXPECT_TRUE(test::checker_accepts(cross, r.certificate));
  }
}

// The oracle: the known-forces decision over regions at distributions spread over F (its vertices and random convex
// combinations of them, exact). Sticks for every ⇒ none of them slides; slides for every ⇒ none sticks; a stick and
// a slide among them ⇒ depends (or undecided). Two supports: the mat and legs, and a linear-pressure triangle beside
// four legs (one with its own μ) around an off-centre centre of pressure.
TEST(RegionMotionOver, AgainstTheKnownForcesDecisionOverF) {
  const std::string tri = R"({"wrenchkit": 1, "support": {"mu": "1/2", "weight": 4, "pressure_center": ["1/10", "1/5"],
      "points": [{"at": [-2, -1]}, {"at": [2, -1]}, {"at": [1, 2]}, {"at": [-1, "3/2"], "mu": "3/4"}],
      "regions": [{"outline": [[-1, -1], [1, -1], [0, 1]], "pressure": {"linear": [1, "1/4", "1/4"]}}]}})";
  std::mt19937_64 rng(20261127);
  std::map<Motion, int> seen;
  for (const std::string& scene : {mat_legs(), tri}) {
    const Scene sc = read(scene);
    const Support& s = *sc.support;
    const Admissible a = admissible_set(sc);
    const std::vector<std::vector<Rational>> v = vertices(s, a);
    ASSERT_GE(v.size(), 2u);
    std::vector<std::vector<Rational>> spread = v;
    for (int k = 0; k < 6; ++k) {
      std::vector<Rational> f(s.points.size()), w(v.size());
      Rational total;
      for (Rational& x : w) total += (x = Rational(static_cast<long>(rng() % 8)));
      if (total == 0) continue;
      for (std::size_t j = 0; j < v.size(); ++j)
        for (std::size_t i = 0; i < f.size(); ++i) f[i] += w[j] / total * v[j][i];
      ASSERT_TRUE(a.contains(s, f));
      spread.push_back(f);
    }
    for (int k = 0; k < 40; ++k) {
      const Vec3q dir{Rational(static_cast<long>(rng() % 9) - 4, 4), Rational(static_cast<long>(rng() % 9) - 4, 4),
                      Rational(static_cast<long>(rng() % 9) - 4, 8)};
      if (dir[0] == 0 && dir[1] == 0 && dir[2] == 0) continue;
      const Rational scale(static_cast<long>(1 + rng() % 12), 4);
      const Vec3q p{dir[0] * scale, dir[1] * scale, dir[2] * scale};
      const std::string where = "seed 20261127 case " + std::to_string(k) + " load " + to_string(p[0]) + "," +
                                to_string(p[1]) + "," + to_string(p[2]) + "\n" + scene;
      const Support_item r = motion_of(scene, p);
      ASSERT_EQ(r.status, Status::answered) << r.message << "\n" << where;
      const Motion m = r.motion->motion;
      ++seen[m];
      bool stick = false, slide = false;
      for (const std::vector<Rational>& f : spread) {
        Support t = s;
        for (std::size_t i = 0; i < f.size(); ++i) t.points[i].force = f[i];
        const Motion g = decide_on_regions(t, p).motion;
        stick |= g == Motion::sticks;
        slide |= g == Motion::slides;
      }
      EXPECT_FALSE(m == Motion::sticks && slide) << where;
      EXPECT_FALSE(m == Motion::slides && stick) << where;
      EXPECT_TRUE(!(stick && slide) || m == Motion::depends || m == Motion::undecided) << where;
      EXPECT_TRUE(m == Motion::undecided || !r.certificate.empty()) << where;
    }
  }
  for (const Motion m : {Motion::sticks, Motion::slides, Motion::depends})
    EXPECT_GT(seen[m], 0) << motion_name(m);
}

}  // namespace
}  // namespace wrenchkit
