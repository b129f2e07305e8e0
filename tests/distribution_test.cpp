// [LP-1] the exact LP, [SL-1] admissible distributions (the scene format's unknown forces, the reason an F is
// empty, the vertices of F), [SL-2] the power of a twist over F (docs/theory-sliding.md §1–§2).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "exact/io/input_error.h"
#include "exact/io/scene.h"
#include "exact/io/scene_writer.h"
#include "exact/numbers/exact_lp.h"
#include "exact/pipeline/support_answer.h"
#include "exact/sliding/distribution.h"
#include "exact/sliding/motion.h"
#include "exact/sliding/strategies.h"
#include "fuzz/scene_checks.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

Rational rq(long p, long q = 1) {
  Rational r(p, q);
  r.canonicalize();
  return r;
}

TEST(ExactLp, OptimalWithItsDualInfeasibleUnboundedAndRedundantRows) {
  // max x0 + 2 x1 s.t. x0 + x1 + x2 = 4, x0 - x1 = 1 (and the sum of the two rows again: redundant).
  const std::vector<std::vector<Rational>> a = {{1, 1, 1}, {1, -1, 0}, {2, 0, 1}};
  const Lp_result r = maximise(a, {4, 1, 5}, {1, 2, 0});
  ASSERT_EQ(r.status, Lp_result::Status::optimal);
  EXPECT_EQ(r.value, rq(11, 2));  // x0 = 5/2, x1 = 3/2
  EXPECT_EQ(r.x[0], rq(5, 2));
  EXPECT_EQ(r.x[1], rq(3, 2));
  Rational by = 4 * r.y[0] + 1 * r.y[1] + 5 * r.y[2];
  EXPECT_EQ(by, r.value);
  // Inconsistent redundant row: infeasible. Negative right-hand sides are fine.
  EXPECT_EQ(maximise(a, {4, 1, 6}, {1, 2, 0}).status, Lp_result::Status::infeasible);
  EXPECT_EQ(maximise({{1, 1}}, {-1}, {1, 0}).status, Lp_result::Status::infeasible);
  EXPECT_EQ(maximise({{1, -1}}, {1}, {1, 0}).status, Lp_result::Status::unbounded);
  const Lp_result neg = maximise({{-1, -1}}, {-3}, {1, 0});
  ASSERT_EQ(neg.status, Lp_result::Status::optimal);
  EXPECT_EQ(neg.value, 3);
}

// Random LPs against brute force over every basis (m = 3 rows, n ≤ 7 columns, small integers): the optimum
// equals the best basic feasible solution, and the dual certifies it (maximise checks A^T y ≥ c itself).
TEST(ExactLp, RandomAgainstEveryBasis) {
  std::mt19937_64 rng(test::seed(20261124));
  std::uniform_int_distribution<int> d(-3, 3);
  int optimal = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = 3 + static_cast<std::size_t>(trial % 5);
    std::vector<std::vector<Rational>> a(3, std::vector<Rational>(n));
    std::vector<Rational> c(n);
    for (auto& row : a)
      for (auto& x : row) x = d(rng);
    for (auto& x : c) x = d(rng);
    // b from a nonnegative x, so the LP is feasible; a bounded objective when every column sums positive.
    std::vector<Rational> x0(n);
    for (auto& x : x0) x = std::abs(d(rng));
    std::vector<Rational> b(3);
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < n; ++j) b[i] += a[i][j] * x0[j];
    for (std::size_t j = 0; j < n; ++j) a[0][j] = 1 + std::abs(d(rng));  // row 0 positive: bounded
    b[0] = 0;
    for (std::size_t j = 0; j < n; ++j) b[0] += a[0][j] * x0[j];
    const Lp_result r = maximise(a, b, c);
    ASSERT_EQ(r.status, Lp_result::Status::optimal) << "seed trial " << trial;
    ++optimal;
    for (std::size_t i = 0; i < 3; ++i) {
      Rational s;
      for (std::size_t j = 0; j < n; ++j) s += a[i][j] * r.x[j];
      EXPECT_EQ(s, b[i]);
    }
    // Brute force: every feasible x0 of this construction has c·x0 ≤ the optimum.
    Rational cx0;
    for (std::size_t j = 0; j < n; ++j) cx0 += c[j] * x0[j];
    EXPECT_LE(cx0, r.value);
  }
  EXPECT_EQ(optimal, 400);
}

// The table of docs/theory-sliding.md §6: legs (±1, ±1), μ = 1, W = 1, c = 0, every force unknown.
const char* kTable = R"({"wrenchkit": 1, "support": {"mu": 1, "weight": 1, "pressure_center": [0, 0],
  "points": [{"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}]}})";

TEST(Distribution, TheTableHasTheTwoDiagonalBarbellsAsVertices) {
  const Scene s = read_scene(kTable, Input_limits{});
  ASSERT_TRUE(s.support && !s.support->known());
  const Admissible a = admissible_set(s);
  EXPECT_EQ(a.unknown.size(), 4u);
  const auto v = vertices(*s.support, a);
  ASSERT_EQ(v.size(), 2u);
  const std::vector<Rational> d1 = {rq(1, 2), 0, rq(1, 2), 0}, d2 = {0, rq(1, 2), 0, rq(1, 2)};
  EXPECT_TRUE((v[0] == d1 && v[1] == d2) || (v[0] == d2 && v[1] == d1));
  for (const auto& f : v) EXPECT_TRUE(a.contains(*s.support, f));
  EXPECT_FALSE(a.contains(*s.support, {rq(1, 4), rq(1, 4), rq(1, 4), rq(1, 2)}));
  EXPECT_TRUE(a.contains(*s.support, {rq(1, 4), rq(1, 4), rq(1, 4), rq(1, 4)}));
  // A pure rotation about the centre: every leg at distance √2, so every distribution has power √2.
  const Power_range p = power_range(*s.support, a, {0, 0, 1});
  EXPECT_LE(p.lower, p.upper);
  EXPECT_LT(p.lower * p.lower, 2);
  EXPECT_GT(p.upper * p.upper, 2);
  EXPECT_LT(p.upper - p.lower, Rational(1, 1000000));
  // A translation: exact, μW|v| = 5 for v = (3, 4), whatever the distribution.
  const Power_range t = power_range(*s.support, a, {3, 4, 0});
  EXPECT_EQ(t.lower, 5);
  EXPECT_EQ(t.upper, 5);
}

TEST(Distribution, ThePowerRangeIsAttainedAtVertices) {
  // Rotation about (1, 1), a leg: the barbell through it has power μ/2·|(−2,−2)| = √2, the other diagonal
  // μ/2·(2 + 2) = 2 → the range is [√2, 2], bracketed.
  const Scene s = read_scene(kTable, Input_limits{});
  const Admissible a = admissible_set(s);
  const Power_range p = power_range(*s.support, a, {1, -1, 1});  // centre (−vy/ω, vx/ω) = (1, 1)
  EXPECT_LT(p.lower * p.lower, 2);
  EXPECT_GT(p.lower * p.lower, Rational(19999, 10000));
  EXPECT_GE(p.upper, 2);
  EXPECT_LT(p.upper, Rational(20001, 10000));
  EXPECT_EQ(p.min_distribution, (std::vector<Rational>{rq(1, 2), 0, rq(1, 2), 0}));
  EXPECT_EQ(p.max_distribution, (std::vector<Rational>{0, rq(1, 2), 0, rq(1, 2)}));
}

// Random supports with some forces unknown: the vertices of F against brute force over every subset
// (every nonnegative basic solution), and the LP's maximum equals the best vertex.
TEST(Distribution, VerticesAndTheLpAgreeWithBruteForceOnRandomSupports) {
  std::mt19937_64 rng(test::seed(7711));
  std::uniform_int_distribution<int> coord(-3, 3), coin(0, 2);
  int with_unknown = 0;
  for (int trial = 0; trial < 800; ++trial) {
    std::string pts;
    const int k = 3 + trial % 5;
    for (int i = 0; i < k; ++i) {
      pts += std::string(i ? ", " : "") + "{\"at\": [" + std::to_string(coord(rng)) + ", " + std::to_string(coord(rng)) +
             "]" + (coin(rng) == 0 ? ", \"force\": \"1/4\"" : "") + "}";
    }
    const std::string text = "{\"wrenchkit\": 1, \"support\": {\"mu\": 1, \"weight\": 3, \"pressure_center\": [\"" +
                             std::to_string(coord(rng)) + "/3\", \"" + std::to_string(coord(rng)) + "/4\"], \"points\": [" +
                             pts + "]}}";
    Scene s;
    try {
      s = read_scene(text, Input_limits{});
    } catch (const Input_error&) {
      continue;  // an empty F (its reason is tested below)
    }
    if (s.support->known()) continue;
    ++with_unknown;
    const Admissible a = admissible_set(s);
    const auto v = vertices(*s.support, a);
    ASSERT_FALSE(v.empty()) << text;
    for (const auto& f : v) EXPECT_TRUE(a.contains(*s.support, f)) << text;
    std::vector<Rational> coef;
    for (int i = 0; i < k; ++i) coef.push_back(coord(rng));
    Rational best;
    bool first = true;
    for (const auto& f : v) {
      Rational val;
      for (int i = 0; i < k; ++i) val += coef[static_cast<std::size_t>(i)] * f[static_cast<std::size_t>(i)];
      if (first || val > best) best = val;
      first = false;
    }
    const F_optimum o = maximise_over(*s.support, a, coef);
    EXPECT_EQ(o.value, best) << text;
    EXPECT_TRUE(a.contains(*s.support, o.distribution)) << text;
    // The dual bounds the maximum: coef_i ≤ y0 + y·r_i on the unknown points.
    for (std::size_t i : a.unknown)
      EXPECT_LE(coef[i], o.dual[0] + o.dual[1] * s.support->points[i].at.x + o.dual[2] * s.support->points[i].at.y);
  }
  EXPECT_GT(with_unknown, 200);
}

Scene reused_eager, reused_lazy;
std::string error_of(const std::string& text) {
  EXPECT_EQ(readers_disagree(text, Input_limits{}, reused_eager, reused_lazy), "") << text;
  try {
    read_scene(text, Input_limits{});
  } catch (const Input_error& e) {
    return e.what();
  }
  return "(accepted)";
}

std::string table_with(const std::string& support_keys, const std::string& points) {
  return R"({"wrenchkit": 1, "support": {"mu": 1, )" + support_keys + R"("points": [)" + points + "]}}";
}

TEST(Distribution, EmptyAdmissibleSetsAreBadInputWithTheReason) {
  const std::string legs = R"({"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]})";
  EXPECT_EQ(error_of(table_with(R"("weight": 1, "pressure_center": [0, 0], )", legs)), "(accepted)");
  EXPECT_EQ(error_of(table_with(R"("weight": 1, "pressure_center": [1, 1], )", legs)), "(accepted)");  // a corner
  EXPECT_EQ(error_of(table_with(R"("weight": 1, "pressure_center": [2, 0], )", legs)),
            "support: no admissible distribution: the centre of pressure (2, 0) needs the unknown forces to act at "
            "(2, 0), outside the convex hull of the points whose force is not given (the body would tip over)");
  EXPECT_EQ(error_of(table_with(R"("pressure_center": [0, 0], )", legs)),
            "support.weight: missing (the total normal force is needed when a point's force is not given)");
  EXPECT_EQ(error_of(table_with(R"("weight": 1, )", legs)),
            "support.pressure_center: missing, and the body has no com (the centre of pressure is needed when a "
            "point's force is not given)");
  EXPECT_EQ(error_of(R"({"wrenchkit": 1, "body": {"com": [0, 0]}, "support": {"mu": 1, "weight": 1, "points": [)" + legs +
                     "]}}"),
            "(accepted)");  // c defaults to body.com
  EXPECT_EQ(error_of(table_with(R"("weight": 0, "pressure_center": [0, 0], )", legs)),
            "support.weight: 0 is not positive (a total normal force must be > 0)");
  EXPECT_EQ(error_of(table_with(R"("weight": 1, "pressure_center": [0, 0], )",
                                R"({"at": [1, 1], "force": 2}, {"at": [-1, -1]})")),
            "support.weight: 1 is less than the sum of the given forces, 2: no admissible distribution");
  EXPECT_EQ(error_of(table_with(R"("weight": 2, "pressure_center": [0, 0], )",
                                R"({"at": [1, 1], "force": 2}, {"at": [-1, -1]})")),
            "support: no admissible distribution: the given forces carry the whole weight, but their centre of "
            "pressure is (1, 1), not (0, 0)");
  // Every force given: weight and pressure_center, when written, must agree.
  const std::string barbell = R"({"at": [0, 1], "force": "1/2"}, {"at": [0, -1], "force": "1/2"})";
  EXPECT_EQ(error_of(table_with(R"("weight": 1, "pressure_center": [0, 0], )", barbell)), "(accepted)");
  EXPECT_EQ(error_of(table_with(R"("weight": 2, )", barbell)),
            "support.weight: 2 is not the sum of the given forces, 1: no admissible distribution");
  EXPECT_EQ(error_of(table_with(R"("pressure_center": [0, 1], )", barbell)),
            "support.pressure_center: (0, 1) is not the centre of pressure of the given forces, (0, 0): no admissible "
            "distribution");
  // Collinear unknown points: c on their segment is admissible, off it is not.
  const std::string line = R"({"at": [0, 0]}, {"at": [2, 0]}, {"at": [4, 0]})";
  EXPECT_EQ(error_of(table_with(R"("weight": 1, "pressure_center": [3, 0], )", line)), "(accepted)");
  EXPECT_NE(error_of(table_with(R"("weight": 1, "pressure_center": [3, "1/1000"], )", line)), "(accepted)");
  // The canonical text keeps the unknown forces, the weight and the centre.
  const Scene s = read_scene(table_with(R"("weight": 1, "pressure_center": [0, 0], )", legs), Input_limits{});
  EXPECT_EQ(write_scene(read_scene(write_scene(s), Input_limits{})), write_scene(s));
  EXPECT_NE(write_scene(s).find("\"weight\": \"1\", \"pressure_center\": [\"0\", \"0\"], \"points\": [{\"at\": [\"1\", \"1\"]}"),
            std::string::npos)
      << write_scene(s);
}

// A stick witness proves what it says, exactly: f ∈ F, |g_i|² ≤ (μ_i f_i)², Σ (g_i, r_i × g_i) = p.
void expect_witness_holds(const Support& s, const Admissible& a, const Stick_witness& w, const Vec3q& p) {
  EXPECT_TRUE(a.contains(s, w.distribution));
  Vec3q sum{};
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Rational mu = s.mu_of(s.points[i]);
    const Vec2& g = w.forces[i];
    EXPECT_LE(g.x * g.x + g.y * g.y, mu * mu * w.distribution[i] * w.distribution[i]);
    sum[0] += g.x;
    sum[1] += g.y;
    sum[2] += s.points[i].at.x * g.y - s.points[i].at.y * g.x;
  }
  EXPECT_EQ(sum, p);
}

Vec3q load(const std::string& fx, const std::string& fy, const std::string& m) {
  return {Rational(fx), Rational(fy), Rational(m)};
}

// The one decision (exact/sliding/motion.h) at 32 sides.
Motion_answer decide(const Scene& s, const Vec3q& p, Mode mode) {
  Motion_options o;
  o.sides = 32;
  return decide_motion(Support_model(s), p, mode, o);
}

// The table (docs/theory-sliding.md §6): |f| < 1 sticks for every distribution, |f| > 1 slides for every one;
// a pure moment m < √2 sticks, m > √2 slides; (1/2, 1/2, 0.9) depends — on the two diagonals.
TEST(UnknownMotion, TheTableSticksSlidesAndDepends) {
  const Scene s = read_scene(kTable, Input_limits{});
  const Admissible a = admissible_set(s);
  for (const Mode mode : {Mode::hybrid, Mode::exact}) {
    SCOPED_TRACE(mode_name(mode));
    EXPECT_EQ(decide(s, load("1/2", "0", "0"), mode).motion, Motion::sticks);
    EXPECT_EQ(decide(s, load("0", "0", "13/10"), mode).motion, Motion::sticks);
    const Motion_answer d = decide(s, load("1/2", "1/2", "9/10"), mode);
    EXPECT_EQ(d.motion, Motion::depends);
    EXPECT_EQ(d.per_vertex.size(), 2u);
  }
  const Motion_answer sl = decide(s, load("3/2", "0", "0"), Mode::hybrid);
  ASSERT_EQ(sl.motion, Motion::slides);
  EXPECT_TRUE(slides_for_every(*s.support, a, load("3/2", "0", "0"), sl.sliding->twist));
  const Motion_answer m = decide(s, load("0", "0", "3/2"), Mode::hybrid);
  ASSERT_EQ(m.motion, Motion::slides);
  EXPECT_TRUE(slides_for_every(*s.support, a, load("0", "0", "3/2"), m.sliding->twist));
  // The LP finds a distribution that sticks for a load inside U, and its witness holds exactly.
  const auto w = stick_witness(*s.support, a, load("1/2", "1/2", "9/10"), 32);
  ASSERT_TRUE(w);
  expect_witness_holds(*s.support, a, *w, load("1/2", "1/2", "9/10"));
  EXPECT_FALSE(stick_witness(*s.support, a, load("3/2", "0", "0"), 64));
}

// The dinner plate (§6): 8 rim points at radius 1 and the centre, c = the centre, μ = W = 1: a pure moment
// 0 < m < 1 depends (the rim resists it, the centre alone does not), m > 1 slides for every distribution.
TEST(UnknownMotion, TheDinnerPlateDepends) {
  const Scene s = read_scene(R"({"wrenchkit": 1, "body": {"com": [0, 0]}, "support": {"mu": 1, "weight": 1,
      "points": [{"at": [1, 0]}, {"at": ["3/5", "4/5"]}, {"at": [0, 1]}, {"at": ["-3/5", "4/5"]}, {"at": [-1, 0]},
                 {"at": ["-3/5", "-4/5"]}, {"at": [0, -1]}, {"at": ["3/5", "-4/5"]}, {"at": [0, 0]}]}})",
                             Input_limits{});
  const Admissible a = admissible_set(s);
  EXPECT_EQ(vertices(*s.support, a).size(), 13u);  // the centre, 4 diameters, 8 triangles about it
  for (const char* m : {"1/100", "1/2", "99/100"})
    EXPECT_EQ(decide(s, load("0", "0", m), Mode::hybrid).motion, Motion::depends) << m;
  for (const char* m : {"101/100", "2"})
    EXPECT_EQ(decide(s, load("0", "0", m), Mode::hybrid).motion, Motion::slides) << m;
  const auto w = stick_witness(*s.support, a, load("0", "0", "1/2"), 32);
  ASSERT_TRUE(w);
  expect_witness_holds(*s.support, a, *w, load("0", "0", "1/2"));
}

// Random supports with unknown forces and random loads: every answer is consistent with its witnesses —
// sticks: every vertex has a stick witness at N = 32 or 128; slides: the twist separates p from all of U
// exactly; depends: one vertex (or the LP's distribution) sticks and one slides.
TEST(UnknownMotion, RandomAnswersAgreeWithTheirWitnesses) {
  std::mt19937_64 rng(test::seed(424242));
  std::uniform_int_distribution<int> coord(-4, 4), small(-12, 12);
  int decided = 0, counts[5] = {0, 0, 0, 0, 0};
  for (int trial = 0; trial < 120; ++trial) {
    std::string pts;
    const int k = 4 + trial % 3;
    for (int i = 0; i < k; ++i)
      pts += std::string(i ? ", " : "") + "{\"at\": [" + std::to_string(coord(rng)) + ", " + std::to_string(coord(rng)) +
             "]" + (i == 0 ? ", \"force\": \"1/4\"" : "") + "}";
    const std::string text = R"({"wrenchkit": 1, "support": {"mu": "1/2", "weight": 2, "pressure_center": [0, 0], "points": [)" +
                             pts + "]}}";
    Scene s;
    try {
      s = read_scene(text, Input_limits{});
    } catch (const Input_error&) {
      continue;
    }
    const Admissible a = admissible_set(s);
    const auto eighth = [&] {
      Rational q(small(rng), 8);
      q.canonicalize();
      return q;
    };
    const Vec3q p = {eighth(), eighth(), eighth()};
    const Motion_answer m = decide(s, p, Mode::hybrid);
    ++counts[static_cast<int>(m.motion)];
    if (m.motion == Motion::undecided) continue;
    ++decided;
    const auto v = vertices(*s.support, a);
    if (m.motion == Motion::sticks) {
      for (const auto& f : v) {
        std::optional<Stick_witness> w;
        for (int n : {32, 128})
          if ((w = stick_witness(*s.support, a, p, n, &f))) break;
        ASSERT_TRUE(w) << text;
        expect_witness_holds(*s.support, a, *w, p);
      }
    } else if (m.motion == Motion::slides) {
      EXPECT_TRUE(slides_for_every(*s.support, a, p, m.sliding->twist, true)) << text;
    } else if (m.motion == Motion::impending) {  // every vertex held in its closed set, one twist meeting every bound
      EXPECT_TRUE(slides_for_every(*s.support, a, p, m.sliding->twist, false)) << text;
      EXPECT_FALSE(slides_for_every(*s.support, a, p, m.sliding->twist, true)) << text;
      EXPECT_EQ(m.vertices.size(), v.size()) << text;
    } else {
      ASSERT_TRUE(m.sticking && m.sliding) << text;
      EXPECT_TRUE(m.held_as == Motion::sticks || m.moved_as == Motion::slides) << text;  // one of them strictly
      if (m.held_as == Motion::sticks) expect_witness_holds(*s.support, a, *m.sticking, p);
      EXPECT_TRUE(a.contains(*s.support, m.sliding->distribution)) << text;
      EXPECT_TRUE(slide_witness(*s.support, m.sliding->distribution, p, m.sliding->twist, m.moved_as == Motion::slides))
          << text;
    }
  }
  EXPECT_GT(decided, 40);
  EXPECT_GT(counts[static_cast<int>(Motion::sticks)], 0);  // some stick, some slide, some depend
  EXPECT_GT(counts[static_cast<int>(Motion::slides)], 0);
  EXPECT_GT(counts[static_cast<int>(Motion::depends)], 0);
}

// Near the thresholds, through the pipeline with certificates (every one re-checked by the independent checker
// inside answer_support, Status::check_failed otherwise): random known supports of 4–8 points under loads
// 1 ∓ 10⁻³ times a boundary load ∂h(q) of a random twist (computed in double: its error is far below 10⁻³), and the
// table's and the dinner plate's thresholds (docs/theory-sliding.md §6). Right answers, nothing undecided.
TEST(UnknownMotion, NearTheThresholdsWithCertificates) {
  std::mt19937_64 rng(test::seed(9090));
  std::uniform_int_distribution<int> c(-20, 20), force(1, 5), coin(0, 2);
  std::uniform_real_distribution<double> u(-1, 1);
  const char* mus[] = {"1/2", "1/4", "1"};
  int right = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const int k = 4 + trial % 5;
    std::string pts;
    std::vector<std::array<double, 4>> raw;  // x, y, f, μ
    for (int i = 0; i < k; ++i) {
      const int x = c(rng), y = c(rng), f = force(rng), m = coin(rng);
      raw.push_back({x / 10.0, y / 10.0, double(f), m == 0 ? 0.5 : m == 1 ? 0.25 : 1.0});
      pts += std::string(i ? ", " : "") + "{\"at\": [\"" + std::to_string(x) + "/10\", \"" + std::to_string(y) +
             "/10\"], \"force\": " + std::to_string(f) + ", \"mu\": \"" + mus[m] + "\"}";
    }
    const std::string text = "{\"wrenchkit\": 1, \"support\": {\"points\": [" + pts + "]}}";
    const Scene scene = read_scene(text, Input_limits{});
    const double q[3] = {u(rng), u(rng), u(rng)};
    double b[3] = {0, 0, 0};
    for (const auto& [x, y, f, mu] : raw) {
      const double vx = q[0] - q[2] * y, vy = q[1] + q[2] * x, n = std::hypot(vx, vy);
      if (n == 0) continue;
      const double gx = f * mu * vx / n, gy = f * mu * vy / n;
      b[0] += gx, b[1] += gy, b[2] += x * gy - y * gx;
    }
    for (const double s : {1 - 1e-3, 1 + 1e-3}) {
      Support_query query;
      query.load = Vec3q{Rational(s * b[0]), Rational(s * b[1]), Rational(s * b[2])};
      query.polytopes = false;
      const Support_item r = answer_support(scene, text, "near", Request{}, query);
      ASSERT_EQ(r.status, Status::answered) << r.message << "\n" << text;
      EXPECT_EQ(r.motion->motion, s < 1 ? Motion::sticks : Motion::slides) << text;
      EXPECT_FALSE(r.certificate.empty()) << r.motion->uncertified << "\n" << text;
      right += r.motion->motion == (s < 1 ? Motion::sticks : Motion::slides);
    }
  }
  EXPECT_EQ(right, 80);
  // The table: |f| = 1 and m = √2 are the thresholds for every distribution; the plate: m = 1 separates depends
  // from slides.
  const std::string plate = R"({"wrenchkit": 1, "body": {"com": [0, 0]}, "support": {"mu": 1, "weight": 1,
      "points": [{"at": [1, 0]}, {"at": ["3/5", "4/5"]}, {"at": [0, 1]}, {"at": ["-3/5", "4/5"]}, {"at": [-1, 0]},
                 {"at": ["-3/5", "-4/5"]}, {"at": [0, -1]}, {"at": ["3/5", "-4/5"]}, {"at": [0, 0]}]}})";
  const struct {
    const char* scene;
    Vec3q load;
    Motion want;
  } cases[] = {
      {kTable, {Rational("999/1000"), 0, 0}, Motion::sticks},
      {kTable, {Rational("1001/1000"), 0, 0}, Motion::slides},
      {kTable, {0, 0, Rational("1413/1000")}, Motion::sticks},   // √2 = 1.41421…
      {kTable, {0, 0, Rational("1415/1000")}, Motion::slides},
      {kTable, {Rational("1/2"), Rational("1/2"), Rational("9/10")}, Motion::depends},
      {plate.c_str(), {0, 0, Rational("999/1000")}, Motion::depends},
      {plate.c_str(), {0, 0, Rational("1001/1000")}, Motion::slides},
  };
  for (const auto& x : cases) {
    const Scene scene = read_scene(x.scene, Input_limits{});
    Support_query query;
    query.load = x.load;
    query.polytopes = false;
    const Support_item r = answer_support(scene, x.scene, "near", Request{}, query);
    ASSERT_EQ(r.status, Status::answered) << r.message;
    ASSERT_TRUE(r.motion);
    EXPECT_EQ(r.motion->motion, x.want) << to_string(x.load[0]) << " " << to_string(x.load[2]);
    EXPECT_FALSE(r.certificate.empty()) << r.motion->uncertified;
  }
}

}  // namespace
}  // namespace wrenchkit
