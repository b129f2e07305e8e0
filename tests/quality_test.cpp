// [QL-1] The grasp quality ε: golden cases worked by hand, and an independent brute force (the supporting planes
// through every triple of points of the wrench space, L∞'s points being every sum of one point per contact) on
// random grasps, for both norms; brackets against the exact value of the same grasp written with unit normals.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "exact/certificates/certificates.h"
#include "exact/io/input_error.h"
#include "exact/io/scene.h"
#include "exact/statics/generators.h"
#include "exact/statics/quality.h"
#include "proofs/checker/checker.h"
#include "testing/stress_families.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {
using namespace test;

Scene scene_of(const std::string& text) { return read_scene(text, Input_limits{}); }

// The independent checker's verdict on the answer's certificate: "" when accepted.
std::string rejected(const std::string& scene, const Quality_answer& a) {
  const wrenchkit_checker::Result r = wrenchkit_checker::check(scene, certificate_json(a), wrenchkit_checker::Limits{});
  return r.outcome == wrenchkit_checker::Outcome::accepted ? "" : r.message + "\n" + certificate_json(a);
}

// ε² of conv(S) by brute force: the minimum of off²/|n|² over the planes through three points of S with every point
// on one side (the facets' planes); 0 when the origin is not strictly inside (or S is flat).
Rational brute_epsilon_squared(const std::vector<Vec3q>& S) {
  bool any = false;
  Rational best;
  for (std::size_t a = 0; a < S.size(); ++a)
    for (std::size_t b = a + 1; b < S.size(); ++b)
      for (std::size_t c = b + 1; c < S.size(); ++c) {
        const Vec3q u{S[b][0] - S[a][0], S[b][1] - S[a][1], S[b][2] - S[a][2]};
        const Vec3q v{S[c][0] - S[a][0], S[c][1] - S[a][1], S[c][2] - S[a][2]};
        Vec3q n = cross(u, v);
        if (is_zero(n)) continue;
        Rational off = dot(n, S[a]);
        int above = 0, below = 0;
        for (const Vec3q& p : S) {
          const Rational s = dot(n, p) - off;
          above += s > 0, below += s < 0;
        }
        if (above && below) continue;  // not a supporting plane
        if (!above && !below) return 0;  // S is flat
        if (above) n = {-n[0], -n[1], -n[2]}, off = -off;
        if (off <= 0) return 0;  // the origin on the plane or beyond it
        const Rational d = off * off / dot(n, n);
        if (!any || d < best) best = d, any = true;
      }
  return any ? best : Rational(0);
}

// The points of the wrench space as the definition states them (not as the engine builds them): L1 every scaled
// edge; L∞ every sum of one point (0 or an edge) per contact.
std::vector<Vec3q> brute_points(const Scene& scene, Quality_norm norm, const Rational& s, const Vec2& about) {
  std::vector<std::vector<Vec3q>> per(scene.contacts.size());
  for (const Generator& g : generators(scene, Reading::friction)) {
    const Vec3q f{g.w[0], g.w[1], s * (g.w[2] - (about.x * g.w[1] - about.y * g.w[0]))};
    per[g.contact].push_back(f);
  }
  std::vector<Vec3q> out;
  if (norm == Quality_norm::l1) {
    for (const auto& p : per) out.insert(out.end(), p.begin(), p.end());
    return out;
  }
  out.push_back({0, 0, 0});
  for (const auto& p : per) {
    std::vector<Vec3q> next = out;
    for (const Vec3q& x : out)
      for (const Vec3q& e : p) next.push_back({x[0] + e[0], x[1] + e[1], x[2] + e[2]});
    out = std::move(next);
  }
  return out;
}

Quality_query query(Quality_norm norm, Force_normalization f = Force_normalization::as_given) {
  Quality_query q;
  q.norm = norm;
  q.normalize = f;
  return q;
}

// Two fingers at (∓1, 0) pressing inward with μ = 1: the edges are the alternate corners of the cube [−1, 1]³, a
// regular tetrahedron of inradius 1/√3.
const char* kTwoFingers = R"({"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0], "mu": 1},
                                           {"at": [1, 0], "normal": [-1, 0], "mu": 1}]})";

TEST(QualityGolden, TwoFingersTetrahedron) {
  const Quality_answer a = decide_quality(scene_of(kTwoFingers), query(Quality_norm::l1), Mode::exact);
  ASSERT_TRUE(a.closure.holds);
  EXPECT_TRUE(a.exact);
  EXPECT_EQ(a.squared, Rational(1, 3));
  EXPECT_EQ(a.boundary.size(), 4u);
  EXPECT_LE(a.lower * a.lower, Rational(1, 3));
  EXPECT_GE(a.upper * a.upper, Rational(1, 3));
  EXPECT_LE(a.upper - a.lower, a.query.tolerance * a.lower);
  EXPECT_EQ(rejected(kTwoFingers, a), "");
}

// Unit-force: every edge divided by √2, so ε = 1/√6, irrational: a bracket within the tolerance.
TEST(QualityGolden, TwoFingersUnitForceBracket) {
  const Quality_answer a = decide_quality(scene_of(kTwoFingers), query(Quality_norm::l1, Force_normalization::unit_force), Mode::exact);
  EXPECT_FALSE(a.exact);
  EXPECT_LT(a.lower * a.lower * 6, Rational(1));
  EXPECT_GT(a.upper * a.upper * 6, Rational(1));
  EXPECT_LE(a.upper - a.lower, a.query.tolerance * a.lower);
  EXPECT_EQ(rejected(kTwoFingers, a), "");
}

// Irrational scales (normals of length √2 on a hexagon, μ = 1/2: unit-force's 1/√(5/2) too): the scaled points at the
// default tolerance fit 2^61 (the hull in 256-bit integers), at 10⁻⁴⁰ they do not (GMP's integers) — each tier is
// taken 8 times here (measured when the test was written). The two brackets of the same ε must overlap, the finer inside the
// coarser's width, both certificates accepted, for both norms and both normalisations, in both modes.
TEST(QualityGolden, IrrationalScalesAgreeAcrossIntegerTiers) {
  const std::string t = R"({"wrenchkit": 1, "contacts": [{"at": [4, 0], "normal": [-1, 0], "mu": "1/2"},
    {"at": [2, 3], "normal": [-1, -1], "mu": "1/2"}, {"at": [-2, 3], "normal": [1, -1], "mu": "1/2"},
    {"at": [-4, 0], "normal": [1, 0], "mu": "1/2"}, {"at": [-2, -3], "normal": [1, 1], "mu": "1/2"},
    {"at": [2, -3], "normal": [-1, 1], "mu": "1/2"}]})";
  for (const Quality_norm norm : {Quality_norm::l1, Quality_norm::linf})
    for (const Force_normalization f : {Force_normalization::unit_normal, Force_normalization::unit_force})
      for (const Mode m : {Mode::exact, Mode::hybrid}) {
        Quality_query coarse = query(norm, f), fine = query(norm, f);
        fine.tolerance = Rational(1) / Rational(Integer(10) * Integer("1000000000000000000000000000000000000000"));
        const Quality_answer a = decide_quality(scene_of(t), coarse, m), b = decide_quality(scene_of(t), fine, m);
        ASSERT_TRUE(a.closure.holds && b.closure.holds);
        EXPECT_FALSE(a.exact);
        EXPECT_LE(a.lower, b.upper);
        EXPECT_LE(b.lower, a.upper);
        EXPECT_LE(b.upper - b.lower, fine.tolerance * b.lower);
        EXPECT_LE(a.upper - a.lower, coarse.tolerance * a.lower);
        EXPECT_EQ(rejected(t, a), "");
        EXPECT_EQ(rejected(t, b), "");
      }
}

// Not in closure (two frictionless fingers): ε = 0, exactly.
TEST(QualityGolden, OpenGraspIsZero) {
  const Quality_answer a = decide_quality(
      scene_of(R"({"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0]}, {"at": [1, 0], "normal": [-1, 0]}]})"),
      query(Quality_norm::l1), Mode::exact);
  EXPECT_FALSE(a.closure.holds);
  EXPECT_TRUE(a.exact);
  EXPECT_EQ(a.upper, 0);
  // The L1 hull decides closure itself (QL-1 §2): flat (frictionless, above), the origin on a facet (two fingers whose
  // contact line makes tan 1/2 with the normals, at μ = 1/2 exactly: the hull's facet through the origin) and inside
  // (just above); an open answer carries the closure engine's twist, accepted by the checker, in both modes.
  const std::string at_half = R"({"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0], "mu": "1/2"}, {"at": [1, 1], "normal": [-1, 0], "mu": "1/2"}]})";
  const std::string above = R"({"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0], "mu": "0.5000000001"}, {"at": [1, 1], "normal": [-1, 0], "mu": "0.5000000001"}]})";
  for (const Mode m : {Mode::exact, Mode::hybrid}) {
    const Quality_answer b = decide_quality(scene_of(at_half), query(Quality_norm::l1), m);
    EXPECT_FALSE(b.closure.holds);
    EXPECT_EQ(b.upper, 0);
    EXPECT_TRUE(b.refs.empty() && b.boundary.empty());  // (nothing of the hull left in an open answer)
    EXPECT_EQ(rejected(at_half, b), "");
    const Quality_answer c = decide_quality(scene_of(above), query(Quality_norm::l1), m);
    EXPECT_TRUE(c.closure.holds);
    EXPECT_GT(c.lower, 0);
    EXPECT_EQ(rejected(above, c), "");
  }
}

// Normals of length 5 (3-4-5): unit-normal divides by 5 exactly, so ε² stays rational and is 1/25 of the as-given
// one for the same directions.
TEST(QualityGolden, RationalUnitNormalIsExact) {
  const char* scene = R"({"wrenchkit": 1, "contacts": [{"at": [0, -1], "normal": [3, 4], "mu": "1/2"}, {"at": [1, 1], "normal": [-4, -3], "mu": "1/2"},
                                       {"at": [-1, 1], "normal": [4, -3], "mu": "1/2"}]})";
  const Quality_answer given = decide_quality(scene_of(scene), query(Quality_norm::l1), Mode::exact);
  const Quality_answer unit = decide_quality(scene_of(scene), query(Quality_norm::l1, Force_normalization::unit_normal), Mode::exact);
  ASSERT_TRUE(given.closure.holds);
  ASSERT_TRUE(unit.exact);
  EXPECT_EQ(unit.squared * 25, given.squared);
}

// Random grasps likely to be closed: 2–5 contacts at small integer points, each normal pointing roughly at the
// origin, μ from a few fractions (and now and then a frictionless one).
std::string inward_grasp(std::mt19937_64& rng, int n) {
  const char* mus[] = {"", "1/4", "1/3", "1/2", "1", "2"};
  std::vector<Contact_spec> cs;
  for (int i = 0; i < n; ++i) {
    int x = 0, y = 0;
    while (x == 0 && y == 0) x = static_cast<int>(rng() % 7) - 3, y = static_cast<int>(rng() % 7) - 3;
    const int nx = -x + static_cast<int>(rng() % 3) - 1, ny = -y + static_cast<int>(rng() % 3) - 1;
    if (nx == 0 && ny == 0) continue;
    cs.push_back({std::to_string(x), std::to_string(y), std::to_string(nx), std::to_string(ny), mus[rng() % 6]});
  }
  return scene_json(cs);
}

// GraspIt!'s conventions: the square [-1, 1]² held at its side middles with μ = 1/10; every edge's moment about the
// centre is ±μ, and divided by the largest radius √2 the L1 space's nearest facets are the planes m = ±μ/√2: ε² = 1/200
// exactly, ε itself irrational — a bracket whose certificate carries the torque scale's error and moment bounds.
TEST(QualityGolden, GraspItPresetDividesMomentsByTheLargestRadius) {
  const std::string t = R"({"wrenchkit": 1, "body": {"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]], "com": [0, 0]},
    "contacts": [{"at": [0, -1], "normal": [0, 1], "mu": "1/10"}, {"at": [0, 1], "normal": [0, -1], "mu": "1/10"},
                 {"at": [-1, 0], "normal": [1, 0], "mu": "1/10"}, {"at": [1, 0], "normal": [-1, 0], "mu": "1/10"}]})";
  Quality_query q;
  q.preset = Quality_preset::graspit;
  const Quality_answer a = decide_quality(scene_of(t), q, Mode::hybrid);
  EXPECT_FALSE(a.exact);
  EXPECT_LE(a.lower * a.lower, Rational(1, 200));
  EXPECT_GE(a.upper * a.upper, Rational(1, 200));
  EXPECT_LE(a.upper - a.lower, a.query.tolerance * a.lower);
  EXPECT_EQ(*a.query.torque_radius_squared, 2);
  EXPECT_EQ(rejected(t, a), "");
  // Dex-Net's and GraspIt!'s presets take moments about the centre of mass: a scene without one is refused
  EXPECT_THROW(decide_quality(scene_of(kTwoFingers), q, Mode::hybrid), Input_error);
  // a rational radius (a 3-4-5 body) keeps ε² exact
  const std::string r = R"({"wrenchkit": 1, "body": {"outline": [[-3, -4], [3, -4], [3, 4], [-3, 4]], "com": [0, 0]},
    "contacts": [{"at": [0, -4], "normal": [0, 1], "mu": "1/2"}, {"at": [0, 4], "normal": [0, -1], "mu": "1/2"},
                 {"at": [-3, 0], "normal": [1, 0], "mu": "1/2"}, {"at": [3, 0], "normal": [-1, 0], "mu": "1/2"}]})";
  const Quality_answer b = decide_quality(scene_of(r), q, Mode::hybrid);
  EXPECT_TRUE(b.exact);
  EXPECT_EQ(b.query.torque_scale, Rational(1, 5));
  EXPECT_EQ(rejected(r, b), "");
}

// Both norms against the brute force on random grasps (the contacts' own μ, as given, moments about the origin).
TEST(QualityOracle, RandomGraspsAgainstBruteForce) {
  std::mt19937_64 rng(seed(20261128));
  int closed = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const int n = 2 + static_cast<int>(rng() % 4);
    const std::string text = trial % 3 == 0 ? scene_json(random_contacts(rng, n)) : inward_grasp(rng, n);
    const Scene scene = scene_of(text);
    if (scene.contacts.empty()) continue;
    for (Quality_norm norm : {Quality_norm::l1, Quality_norm::linf}) {
      if (norm == Quality_norm::linf && scene.contacts.size() > 3) continue;  // the brute force's 3^n points
      const Quality_answer a = decide_quality(scene, query(norm), Mode::exact);
      const Rational want = brute_epsilon_squared(brute_points(scene, norm, 1, {}));
      ASSERT_TRUE(a.exact);
      ASSERT_EQ(a.squared, want) << quality_norm_name(norm) << " " << dump_failure(text, "quality_oracle");
      ASSERT_EQ(a.closure.holds, want > 0) << dump_failure(text, "quality_oracle");
      // (L1 decides closure by its hull: the closure engine, the other way, must agree)
      ASSERT_EQ(a.closure.holds, decide_closure(scene, Property::force_closure, Mode::exact, false).holds)
          << dump_failure(text, "quality_oracle");
      ASSERT_EQ(rejected(text, a), "") << dump_failure(text, "quality_oracle");
      Quality_query uf = query(norm, Force_normalization::unit_force);
      const Quality_answer b = decide_quality(scene, uf, Mode::exact);
      ASSERT_EQ(rejected(text, b), "") << dump_failure(text, "quality_oracle");
      closed += a.closure.holds;
    }
  }
  EXPECT_GT(closed, 40);
}

// [QL-1 §3] The L1 hull decides closure: on the stress families' degenerate grasps — random_grid (small integer grids,
// axis and diagonal normals: parallel, concurrent and cone-edge configurations, flat wrench sets), cone_edge,
// nearly_concurrent and friction_threshold at 10⁻⁶ (17-digit decimals, both sides) — its verdict is the closure
// engine's, in exact and hybrid modes, and every answer's certificate (ε > 0 with the hull, ε = 0 with the twist) is
// accepted.
TEST(QualityOracle, TheHullsClosureIsTheClosureEnginesOnDegenerateGrasps) {
  int closed = 0, open = 0;
  for (const char* family : {"random_grid", "cone_edge", "nearly_concurrent", "friction_threshold"})
    for (std::uint64_t seed = 1; seed <= 120; ++seed) {
      const stress::Family_scene f = stress::make_scene(family, 1e-6, seed);
      const Scene scene = scene_of(f.text);
      if (scene.contacts.empty()) continue;
      const bool truth = decide_closure(scene, Property::force_closure, Mode::exact, false).holds;
      for (const Mode m : {Mode::exact, Mode::hybrid}) {
        Quality_query q = query(Quality_norm::l1, Force_normalization::unit_force);
        q.critical_mu = false;
        const Quality_answer a = decide_quality(scene, q, m);
        ASSERT_EQ(a.closure.holds, truth) << family << " " << seed << "\n" << dump_failure(f.text, "quality_hull_closure");
        ASSERT_EQ(rejected(f.text, a), "") << dump_failure(f.text, "quality_hull_closure");
      }
      (truth ? closed : open) += 1;
    }
  EXPECT_GT(closed, 40);
  EXPECT_GT(open, 40);
}

// The fast path (small numbers, rational scales: integers only) and the general one (rationals; taken when the query
// keeps the planes) give the same ε², the same nearest distance and accepted certificates, for every normalisation and
// both norms, on grasps whose normals have rational length (3-4-5, 5-12-13, axes), about body.com or the origin.
TEST(QualityOracle, FastPathAgreesWithTheGeneralOne) {
  std::mt19937_64 rng(seed(20261130));
  const int normals[][2] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}, {3, 4}, {-4, 3}, {-3, -4}, {4, -3}, {5, 12}, {-12, 5}, {12, -5}};
  const char* mus[] = {"", "1/2", "3/4", "1/3", "2"};
  int fast_closed = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<Contact_spec> cs;
    const int n = 2 + static_cast<int>(rng() % 4);
    for (int i = 0; i < n; ++i) {
      const auto& nn = normals[rng() % 11];
      cs.push_back({std::to_string(static_cast<int>(rng() % 7) - 3) + "/" + std::to_string(1 + rng() % 3),
                    std::to_string(static_cast<int>(rng() % 7) - 3), std::to_string(nn[0]), std::to_string(nn[1]),
                    mus[rng() % 5]});
    }
    const std::string text = scene_json(cs);
    const Scene scene = scene_of(text);
    for (Quality_norm norm : {Quality_norm::l1, Quality_norm::linf})
      for (Force_normalization f : {Force_normalization::unit_normal, Force_normalization::unit_force, Force_normalization::as_given}) {
        Quality_query q = query(norm, f);
        if (trial % 2) q.torque_scale = Rational(1, 3), q.about = Vec2{Rational(1, 2), Rational(-1)};
        const Quality_answer fast = decide_quality(scene, q, Mode::hybrid);
        q.keep_planes = true;
        const Quality_answer general = decide_quality(scene, q, Mode::exact);
        ASSERT_EQ(fast.closure.holds, general.closure.holds) << dump_failure(text, "quality_fast");
        ASSERT_EQ(fast.exact, general.exact) << dump_failure(text, "quality_fast");
        ASSERT_EQ(fast.squared, general.squared) << quality_norm_name(norm) << " " << normalization_name(f) << " "
                                                 << dump_failure(text, "quality_fast");
        ASSERT_EQ(rejected(text, fast), "") << dump_failure(text, "quality_fast");
        fast_closed += fast.closure.holds;
      }
  }
  EXPECT_GT(fast_closed, 60);
}


// [QL-1 §8] The float twin of ε against the exact engine: on random grasps written with 17-digit decimals (general
// position: the twin must decide most) and on integer grasps (symmetries and coplanar facets: it must abstain there,
// never guess), for each normalisation, about the origin and about a point with a torque scale: when it is certain
// its closure verdict is the exact one and its bracket meets the exact bracket (which is within 10⁻¹² of ε); its
// bracket is narrow (10⁻⁹ relative). A failing case prints its seed and dumps its scene.
TEST(QualityTwin, CertainAnswersAgreeWithTheExactEngineAndDegenerateOnesAbstain) {
  std::mt19937_64 rng(seed(20261129));
  std::uniform_real_distribution<double> U(-1, 1);
  int certain = 0, decimal_rows = 0, integer_certain_closed = 0, closed = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const bool decimal = trial % 4 != 0;
    const int n = 2 + static_cast<int>(rng() % 5);
    std::vector<Contact_spec> cs;
    char buf[64];
    const auto num = [&](double x) {
      std::snprintf(buf, sizeof buf, "%.17g", x);
      return std::string(buf);
    };
    for (int i = 0; i < n; ++i) {
      if (decimal) {
        const double th = 6.283185307179586 * (i + 0.5 * U(rng)) / n;
        const double ph = th + 3.141592653589793 + 0.4 * U(rng);
        cs.push_back({num(3 * std::cos(th)), num(2 * std::sin(th)), num(std::cos(ph)), num(std::sin(ph)), num(0.6 * (U(rng) + 1))});
      } else {
        const int axes[4][2] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};
        const auto& a = axes[rng() % 4];
        cs.push_back({std::to_string(static_cast<int>(rng() % 5) - 2), std::to_string(static_cast<int>(rng() % 5) - 2),
                      std::to_string(a[0]), std::to_string(a[1]), rng() % 3 ? "1/2" : ""});
      }
    }
    const std::string text = scene_json(cs);
    const Scene scene = scene_of(text);
    decimal_rows += decimal;
    for (Force_normalization f : {Force_normalization::unit_normal, Force_normalization::unit_force, Force_normalization::as_given}) {
      Quality_query q = query(Quality_norm::l1, f);
      if (trial % 2) q.torque_scale = Rational(2, 3), q.about = Vec2{Rational(1, 4), Rational(-1, 3)};
      q.twin_first = true;
      const Quality_answer t = decide_quality(scene, q, Mode::float_only);
      q.twin_first = false;
      const Quality_answer e = decide_quality(scene, q, Mode::exact);
      if (!t.twin) continue;
      ++certain;
      closed += t.closure.holds;
      if (!decimal && t.closure.holds) ++integer_certain_closed;
      ASSERT_EQ(t.closure.holds, e.closure.holds) << "seed " << trial << " " << dump_failure(text, "quality_twin");
      ASSERT_LE(t.lower, e.upper) << normalization_name(f) << " " << dump_failure(text, "quality_twin");
      ASSERT_LE(e.lower, t.upper) << normalization_name(f) << " " << dump_failure(text, "quality_twin");
      if (t.closure.holds) ASSERT_LE(t.upper - t.lower, Rational(1, 1000000000) * t.upper) << dump_failure(text, "quality_twin");
      else ASSERT_EQ(t.upper, 0);
    }
  }
  EXPECT_GT(certain, 3 * decimal_rows / 2);  // most decimal grasps decided by the twin, in each normalisation
  EXPECT_GT(closed, 100);
  std::printf("quality twin: %d certain answers (%d closed); integer grasps certain and closed: %d\n", certain, closed,
              integer_certain_closed);
}

// [QL-1 §6] Contact margins: against a brute force in doubles written from the definition (every triple of edges, a
// contact's two edges replaced by its normal and tangent wrenches), and invariant — exactly — under a rigid motion of
// the scene that carries the moments' point along (the rotation by (3/5, 4/5) and a translation) and under scaling
// every normal.
TEST(QualityOracle, ContactMarginsAgainstTheirDefinition) {
  std::mt19937_64 rng(seed(20261129));
  const auto moved = [](const Scene& s) {
    Scene t = s;
    const Rational c(3, 5), d(4, 5);
    for (Contact& k : t.contacts) {
      k = exact_contact(k);
      k.at = {c * k.at.x - d * k.at.y + 7, d * k.at.x + c * k.at.y - 2};
      k.normal = {3 * (c * k.normal.x - d * k.normal.y), 3 * (d * k.normal.x + c * k.normal.y)};
      k.has_twin = false;
    }
    return t;
  };
  int zeros = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 2 + static_cast<int>(rng() % 4);
    const std::string text = inward_grasp(rng, n);
    const Scene scene = scene_of(text);
    if (scene.contacts.empty()) continue;
    Quality_query q;
    q.about = Vec2{0, 0};
    const Contact_margins m = contact_margins(scene, q);
    Quality_query q2;
    q2.about = Vec2{7, -2};
    const Contact_margins m2 = contact_margins(moved(scene), q2);
    ASSERT_TRUE(m.exact);
    // the brute force
    struct D { double x, y, z; };
    const auto w = [](double px, double py, double fx, double fy) { return D{fx, fy, px * fy - py * fx}; };
    const auto vol2 = [](D a, D b, D c) {
      const double det = a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
      const auto n2 = [](D v) { return v.x * v.x + v.y * v.y + v.z * v.z; };
      return det * det / (n2(a) * n2(b) * n2(c));
    };
    std::vector<std::pair<std::size_t, D>> edges;
    std::vector<std::array<D, 2>> plane;
    for (std::size_t i = 0; i < scene.contacts.size(); ++i) {
      const Contact& k = exact_contact(scene.contacts[i]);
      const double px = k.at.x.get_d(), py = k.at.y.get_d(), nx = k.normal.x.get_d(), ny = k.normal.y.get_d(), mu = k.mu.get_d();
      plane.push_back({w(px, py, nx, ny), w(px, py, -ny, nx)});
      if (mu == 0) edges.push_back({i, w(px, py, nx, ny)});
      else edges.push_back({i, w(px, py, nx - mu * ny, ny + mu * nx)}), edges.push_back({i, w(px, py, nx + mu * ny, ny - mu * nx)});
    }
    std::vector<double> best(scene.contacts.size(), 2.0);
    for (std::size_t a = 0; a < edges.size(); ++a)
      for (std::size_t b = a + 1; b < edges.size(); ++b)
        for (std::size_t c = b + 1; c < edges.size(); ++c) {
          const std::size_t ca = edges[a].first, cb = edges[b].first, cc = edges[c].first;
          const double v = ca == cb   ? vol2(plane[ca][0], plane[ca][1], edges[c].second)
                           : cb == cc ? vol2(edges[a].second, plane[cb][0], plane[cb][1])
                                      : vol2(edges[a].second, edges[b].second, edges[c].second);
          for (std::size_t k : {ca, cb, cc}) best[k] = std::min(best[k], v);
        }
    for (std::size_t i = 0; i < scene.contacts.size(); ++i) {
      ASSERT_EQ(m.contacts[i].squared.has_value(), best[i] <= 1.0) << dump_failure(text, "contact_margins");
      if (!m.contacts[i].squared) continue;
      EXPECT_NEAR(m.contacts[i].squared->get_d(), best[i], 1e-12) << i << " " << dump_failure(text, "contact_margins");
      ASSERT_EQ(*m.contacts[i].squared, *m2.contacts[i].squared) << i << " " << dump_failure(text, "contact_margins");
      zeros += *m.contacts[i].squared == 0;
      ASSERT_EQ(*m.contacts[i].squared == 0, m.contacts[i].zeros > 0) << dump_failure(text, "contact_margins");
    }
  }
  EXPECT_GT(zeros, 0);  // (the small integer grid meets degenerate triples)
}

}  // namespace
}  // namespace wrenchkit
