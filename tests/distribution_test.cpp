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
#include "exact/sliding/distribution.h"
#include "fuzz/scene_checks.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

Rational rq(long p, long q = 1) { return Rational(p, q); }

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

}  // namespace
}  // namespace wrenchkit
