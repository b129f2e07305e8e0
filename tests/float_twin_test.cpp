// [FL-1] [FL-2] [FL-3] The float twin against the exact engine: every bound contains the exact
// value; a certified float answer always equals the exact one; hybrid always answers exactly; the
// twin decides typical scenes by itself; naive floating point is measurably wrong where the twin
// abstains.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "exact/certificates/certificates.h"
#include "exact/statics/closure.h"
#include "exact/io/to_float.h"
#include "float/bounded.h"
#include "float/closure_twin.h"
#include "float/float_kernel.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

using fl::Bounded;

// |exact − v| ≤ e, checked in exact arithmetic.
::testing::AssertionResult contains(const Bounded& b, const Rational& exact) {
  if (!std::isfinite(b.v) || !(b.e == b.e)) return ::testing::AssertionSuccess();  // no claim made
  if (b.e == Bounded::kInf) return ::testing::AssertionSuccess();
  if (abs(exact - Rational(b.v)) <= Rational(b.e)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "v = " << b.v << ", e = " << b.e << ", exact = " << exact.get_d();
}

TEST(Bounded, ExactOperandsStayExactAndInexactOnesCarryTheirError) {
  const Bounded a = Bounded::exact(3), b = Bounded::exact(0.5);
  EXPECT_EQ((a * b - Bounded::exact(1.5)).e, 0.0);
  EXPECT_EQ((a * b - Bounded::exact(1.5)).sign(), Sign::zero);  // exact zero is certified
  const Bounded tenth = to_bounded(Rational(1, 10));
  EXPECT_GT(tenth.e, 0.0);
  EXPECT_TRUE(contains(tenth, Rational(1, 10)));
  // 10 · 0.1 − 1 is exactly 0 for the rational 1/10; the twin cannot certify it, and says so.
  EXPECT_EQ((Bounded::exact(10) * tenth - Bounded::exact(1)).sign(), Sign::uncertain);
  EXPECT_EQ(to_bounded(Rational(1, 2)).e, 0.0);
  EXPECT_EQ(to_bounded(Rational(Integer(1), Integer(1) << 2000)).e, Bounded::kInf);  // below doubles
  EXPECT_EQ(Bounded::exact(std::numeric_limits<double>::quiet_NaN()).sign(), Sign::uncertain);
  const Bounded huge = Bounded::exact(1e300);
  EXPECT_EQ((huge * huge).sign(), Sign::uncertain);  // overflow
  const Bounded tiny = Bounded::exact(1e-300);
  EXPECT_EQ((tiny * tiny).sign(), Sign::uncertain);  // underflow
  EXPECT_EQ((tiny * tiny - tiny * tiny).sign(), Sign::uncertain);
}

TEST(Bounded, EveryBoundContainsTheExactDeterminant) {
  std::mt19937_64 rng(test::seed(11));
  std::uniform_int_distribution<int> num(-1000, 1000), den(1, 1000), scale(-60, 60);
  int certified = 0;
  for (int t = 0; t < 20000; ++t) {
    Rational q[9];
    Bounded b[9];
    const int s = scale(rng);
    for (int i = 0; i < 9; ++i) {
      q[i] = Rational(num(rng), den(rng));
      if (s >= 0) q[i] *= Rational(Integer(1) << s);
      else q[i] /= Rational(Integer(1) << -s);
      b[i] = to_bounded(q[i]);
    }
    // Near-singular half the time: third row = first + second (exactly, in the rationals).
    if (t % 2) {
      for (int i = 0; i < 3; ++i) {
        q[6 + i] = q[i] + q[3 + i];
        b[6 + i] = to_bounded(q[6 + i]);
      }
    }
    const Rational exact = q[0] * (q[4] * q[8] - q[5] * q[7]) - q[1] * (q[3] * q[8] - q[5] * q[6]) +
                           q[2] * (q[3] * q[7] - q[4] * q[6]);
    const Bounded d = b[0] * (b[4] * b[8] - b[5] * b[7]) - b[1] * (b[3] * b[8] - b[5] * b[6]) +
                      b[2] * (b[3] * b[7] - b[4] * b[6]);
    ASSERT_TRUE(contains(d, exact)) << "case " << t;
    const Sign sg = d.sign();
    if (sg != Sign::uncertain) {
      ++certified;
      ASSERT_EQ(sg, sign_of(sgn(exact))) << "case " << t;
    }
  }
  EXPECT_GT(certified, 9000);  // the non-singular half is certified
}

// [FL-2] Stage 0: one bound per kernel (determinants and minors). Kernels of random generators at mixed scales (so the bound is
// coarse for the small ones), half of the triples nearly singular; every sign Stage 0 gives (|D̂| > bound)
// is the exact sign; magnitudes outside [2^-300, 2^300] make it decline for the whole kernel.
TEST(FloatKernel, SceneBoundSignsAreExactAndExtremeMagnitudesDecline) {
  std::mt19937_64 rng(test::seed(12));
  std::uniform_int_distribution<int> num(-1000, 1000), den(1, 1000), scale(-40, 40);
  int decided = 0;
  for (int t = 0; t < 2000; ++t) {
    std::vector<std::array<Rational, 3>> q(6);
    std::vector<fl::Bounded3> g(6);
    for (int r = 0; r < 6; ++r) {
      const int s = scale(rng);
      for (int c = 0; c < 3; ++c) {
        q[r][c] = Rational(num(rng), den(rng));
        if (s >= 0) q[r][c] *= Rational(Integer(1) << s);
        else q[r][c] /= Rational(Integer(1) << -s);
      }
    }
    if (t % 2)
      for (int c = 0; c < 3; ++c) q[5][c] = q[3][c] + q[4][c] * Rational(1, 3);  // det(3, 4, 5) = 0 exactly
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 3; ++c) g[r][c] = to_bounded(q[r][c]);
    const fl::Float_kernel k(g);
    ASSERT_LT(k.scene_bound(), Bounded::kInf);
    for (int i = 0; i < 6; ++i)
      for (int j = i + 1; j < 6; ++j)
        for (int p = 0; p < 3; ++p) {
          const int c1 = (p + 1) % 3, c2 = (p + 2) % 3;
          const double m = g[i][c1].v * g[j][c2].v - g[i][c2].v * g[j][c1].v;
          const Rational exact = q[i][c1] * q[j][c2] - q[i][c2] * q[j][c1];
          ASSERT_LE(abs(exact - Rational(m)), Rational(k.cross_bound(p))) << "case " << t;
          if (std::fabs(m) > k.cross_bound(p)) {
            ASSERT_NE(exact, 0) << "case " << t;
          }
        }
    for (int i = 0; i < 6; ++i)
      for (int j = i + 1; j < 6; ++j)
        for (int l = j + 1; l < 6; ++l) {
          const auto& a = g[i];
          const auto& b = g[j];
          const auto& c = g[l];
          const double d = a[0].v * (b[1].v * c[2].v - b[2].v * c[1].v) - a[1].v * (b[0].v * c[2].v - b[2].v * c[0].v) +
                           a[2].v * (b[0].v * c[1].v - b[1].v * c[0].v);
          const auto& x = q[i];
          const auto& y = q[j];
          const auto& z = q[l];
          const Rational exact = x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0]) +
                                 x[2] * (y[0] * z[1] - y[1] * z[0]);
          // The bound contains the error itself, not only the sign.
          ASSERT_LE(abs(exact - Rational(d)), Rational(k.scene_bound())) << "case " << t;
          if (std::fabs(d) > k.scene_bound()) {
            ++decided;
            ASSERT_EQ(k.det_sign(i, j, l), sign_of(sgn(exact))) << "case " << t;
          }
        }
  }
  EXPECT_GT(decided, 1000);
  for (double extreme : {0x1p-310, 0x1p310, std::numeric_limits<double>::infinity()}) {
    std::vector<fl::Bounded3> g = {{Bounded::exact(1), Bounded::exact(0), Bounded::exact(0)},
                                   {Bounded::exact(0), Bounded::exact(1), Bounded::exact(0)},
                                   {Bounded::exact(0), Bounded::exact(0), Bounded::exact(extreme)}};
    EXPECT_EQ(fl::Float_kernel(g).scene_bound(), Bounded::kInf) << extreme;
    EXPECT_EQ(fl::Float_kernel(g).cross_bound(0), Bounded::kInf) << extreme;
  }
}

// [FL-1 "Static generators"] The robot-side static generators: every coordinate's bound contains the exact
// generator of the doubles as given, the column bounds cover every coordinate, Stage 0 from those bounds
// contains every determinant's error and its signs are the exact ones — at mixed scales 2^-64 … 2^64 with
// exact zeros, cancelling normals and μ = 0; inputs outside the range are declined; and force/form closure
// through them equal the exact verdicts (exactly degenerate scenes decided by the running-error fallback).
TEST(StaticGenerators, BoundsContainTheExactGeneratorsAndSignsAreExactAtMixedScales) {
  std::mt19937_64 rng(test::seed(1919));
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> scale(-60, 60);
  auto value = [&](int k) {  // a random double of magnitude in [2^k, 2^(k+1)), sometimes exactly zero
    if (rng() % 10 == 0) return 0.0;
    const double u = unit(rng);
    return std::ldexp(u < 0 ? u - 1 : u + 1, k);
  };
  auto in_range = [](const fl::Point_contact& p) {  // the static generators' guard, as documented
    for (double x : {p.ax, p.ay, p.nx, p.ny, p.mu})
      if (x != 0 && !(std::fabs(x) >= 0x1p-64 && std::fabs(x) <= 0x1p64)) return false;
    return true;
  };
  int decided = 0, declined = 0;
  for (int t = 0; t < 3000; ++t) {
    const int s = t % 3 == 0 ? 0 : scale(rng);  // one scale for the scene, or each number its own
    std::vector<fl::Point_contact> c(2 + t % 5);
    for (auto& p : c) {
      const auto k = [&] { return t % 3 == 1 ? s : scale(rng) / 2; };
      p = {value(k()), value(k()), value(k()), value(k()), t % 4 == 0 ? 0.0 : std::fabs(value(k() / 2))};
      ASSERT_TRUE(in_range(p));
      if (p.nx == 0 && p.ny == 0) p.nx = 1;
      if (t % 7 == 0) p.ny = -p.mu * p.nx;  // edges close to cancelling
      if (p.nx == 0 && p.ny == 0) p.nx = 1;
      if (!in_range(p)) p.ny = 1;  // (a cancelling product may leave the range)
    }
    for (Reading reading : {Reading::friction, Reading::frictionless}) {
      std::vector<fl::Bounded3> g;
      fl::Float_kernel::Column_bounds columns;
      ASSERT_TRUE(fl::static_generators(c, reading, g, &columns)) << "case " << t;
      // The exact generators of the doubles, in the order of the engine.
      std::vector<std::array<Rational, 3>> q;
      for (const auto& p : c)
        point_contact_generators(Rational(p.ax), Rational(p.ay), Rational(p.nx), Rational(p.ny), Rational(p.mu),
                                 p.mu != 0, reading, [&](Edge, const Rational& fx, const Rational& fy, const Rational& m) {
                                   q.push_back({fx, fy, m});
                                 });
      ASSERT_EQ(q.size(), g.size());
      for (std::size_t i = 0; i < g.size(); ++i)
        for (int k = 0; k < 3; ++k) {
          ASSERT_TRUE(contains(g[i][k], q[i][k])) << "case " << t << " generator " << i << " coordinate " << k;
          ASSERT_LE(std::fabs(g[i][k].v), columns.M[k]);
          ASSERT_LE(g[i][k].e, columns.E[k]);
          ASSERT_LE(abs(q[i][k]), Rational(columns.Mu[k]));
        }
      const fl::Float_kernel kernel(g, columns);
      ASSERT_LT(kernel.scene_bound(), Bounded::kInf) << "case " << t;
      for (std::size_t i = 0; i < g.size(); ++i)
        for (std::size_t j = i + 1; j < g.size(); ++j)
          for (std::size_t l = j + 1; l < g.size(); ++l) {
            const auto &x = q[i], &y = q[j], &z = q[l];
            const Rational exact = x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0]) +
                                   x[2] * (y[0] * z[1] - y[1] * z[0]);
            const Sign sign = kernel.det_sign(i, j, l);
            if (sign == Sign::uncertain) continue;
            ++decided;
            ASSERT_EQ(sign, sign_of(sgn(exact))) << "case " << t << " triple " << i << " " << j << " " << l;
          }
    }
    fl::Point_contact out_of_range = c[0];
    out_of_range.ax = t % 2 ? 0x1p70 : 0x1p-70;
    std::vector<fl::Bounded3> none;
    EXPECT_FALSE(fl::static_generators({out_of_range}, Reading::friction, none));
    EXPECT_TRUE(none.empty());
    ++declined;
  }
  EXPECT_GT(decided, 10000);
}

TEST(StaticGenerators, RobotSideVerdictsEqualExactOnesIncludingDegenerateScenes) {
  std::mt19937_64 rng(test::seed(2019));
  int checked = 0;
  for (int t = 0; t < 1500; ++t) {
    // Half: random decimals-as-doubles at a random scale; half: small integers (exactly degenerate
    // configurations are common, and only the running-error fallback certifies their zeros).
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 41) - 20);
    std::vector<fl::Point_contact> c(3 + t % 4);
    for (auto& p : c) {
      auto v = [&] {
        return t % 2 ? static_cast<double>(static_cast<int>(rng() % 5) - 2)
                     : scale * (static_cast<double>(rng() % 2000001) / 1e6 - 1);
      };
      p = {v(), v(), v(), v(), t % 2 ? static_cast<double>(rng() % 3) / 2 : static_cast<double>(rng() % 600) / 1000};
      if (p.nx == 0 && p.ny == 0) p.nx = 1;
    }
    Scene scene;
    for (const auto& p : c) {
      Contact x;
      x.at = {Rational(p.ax), Rational(p.ay)};
      x.normal = {Rational(p.nx), Rational(p.ny)};
      x.mu = Rational(p.mu);
      scene.contacts.push_back(x);
    }
    const fl::Verdict force = fl::force_closure(c), form = fl::form_closure(c);
    const bool exact_force = decide_closure(scene, Property::force_closure, Mode::exact, false).holds;
    const bool exact_form = decide_closure(scene, Property::form_closure, Mode::exact, false).holds;
    if (force != fl::Verdict::undecided) {
      ASSERT_EQ(force == fl::Verdict::closed, exact_force) << "case " << t;
      ++checked;
    }
    if (form != fl::Verdict::undecided) {
      ASSERT_EQ(form == fl::Verdict::closed, exact_form) << "case " << t;
      ++checked;
    }
  }
  EXPECT_GT(checked, 2800);
}

// [FL-5] Quotients and square roots: the bound contains the exact value (checked exactly: for √,
// the exact root r of the exact square s satisfies (v − e)² ≤ s ≤ (v + e)² when v − e ≥ 0).
TEST(Bounded, QuotientsAndSquareRootsContainTheExactValue) {
  std::mt19937_64 rng(test::seed(12));
  std::uniform_int_distribution<int> num(-1000, 1000), den(1, 1000), scale(-60, 60);
  int exact_quotients = 0;
  for (int t = 0; t < 20000; ++t) {
    const int s = scale(rng);
    Rational a(num(rng), den(rng)), b(num(rng), den(rng));
    if (t % 3 == 0) {  // exact dyadic quotients
      a = Rational(num(rng));
      b = Rational(1 << (t % 7));
    }
    if (s >= 0) a *= Rational(Integer(1) << s);
    else a /= Rational(Integer(1) << -s);
    // Divisors far from 1 as well (|b| up to 2^±900: a bound written with |b|² overflowed there).
    if (t % 5 == 1) b *= Rational(Integer(1) << (100 + t % 800));
    if (t % 5 == 2) b /= Rational(Integer(1) << (100 + t % 800));
    const Bounded ba = to_bounded(a), bb = to_bounded(b);
    const Bounded qt = ba / bb;
    if (b == 0) {
      EXPECT_EQ(qt.sign(), Sign::uncertain);
      continue;
    }
    ASSERT_TRUE(contains(qt, a / b)) << "case " << t;
    exact_quotients += qt.e == 0;
    if (qt.sign() != Sign::uncertain) { ASSERT_EQ(qt.sign(), sign_of(sgn(a / b))); }
    if (t % 5 == 1 || t % 5 == 2) continue;  // (b² may overflow)
    // √ of a square computed with errors: x² + y² for inexact x, y.
    const Rational sq = a * a + b * b;
    const Bounded bs = fl::sqrt(ba * ba + bb * bb);
    ASSERT_TRUE(std::isfinite(bs.e)) << "case " << t;
    const Rational lo = Rational(fl::lower(bs)), hi = Rational(fl::upper(bs));
    ASSERT_LE(lo < 0 ? Rational(0) : lo * lo, sq) << "case " << t;
    ASSERT_GE(hi * hi, sq) << "case " << t;
  }
  EXPECT_GT(exact_quotients, 3000);  // exact data stays exact
  EXPECT_EQ(fl::sqrt(Bounded::exact(2.25)).e, 0.0);  // √ of an exact square is exact
  EXPECT_GT(fl::sqrt(Bounded::exact(2)).e, 0.0);
  EXPECT_EQ((Bounded::exact(1) / Bounded{1e-3, 2e-3}).sign(), Sign::uncertain);  // divisor not certified ≠ 0
  EXPECT_EQ(fl::sqrt(Bounded{-1, 0.5}).sign(), Sign::uncertain);                 // certified negative
  EXPECT_EQ((Bounded::exact(1e300) / Bounded::exact(1e-300)).sign(), Sign::uncertain);  // overflow
  // A product with an unbounded factor is unbounded — never 0·∞ = NaN (found by fuzz_scene_parser:
  // an underflowed zero times an exact value gave a NaN bound to a labels corner).
  const Bounded lost{0.0, Bounded::kInf};
  EXPECT_EQ((lost * Bounded::exact(3)).e, Bounded::kInf);
  EXPECT_EQ((Bounded::exact(3) * lost).e, Bounded::kInf);
  EXPECT_EQ((lost * Bounded{2, 0.5}).e, Bounded::kInf);
}

// ---- Closure: twin and hybrid against exact. ----

struct Tally {
  int cases = 0, float_decided = 0;
};

void compare_modes(const std::string& text, Tally& tally, const std::string& tag) {
  const Scene s = read_scene(text, Input_limits{});
  for (Property p : {Property::force_closure, Property::form_closure}) {
    const Closure_answer exact = decide_closure(s, p, Mode::exact);
    const Closure_answer twin = decide_closure(s, p, Mode::float_only);
    const Closure_answer hybrid = decide_closure(s, p, Mode::hybrid);
    ++tally.cases;
    tally.float_decided += twin.decided;
    const bool ok = (!twin.decided || twin.holds == exact.holds) && hybrid.decided && hybrid.holds == exact.holds &&
                    hybrid.rank == exact.rank && test::checker_accepts(text, certificate_json(hybrid.certificate));
    if (!ok) {
      FAIL() << property_name(p) << ": exact " << exact.holds << ", twin " << (twin.decided ? twin.holds : -1)
             << ", hybrid " << hybrid.holds << "; scene dumped to " << test::dump_failure(text, tag);
    }
  }
}

TEST(FloatTwin, CertifiedAnswersEqualExactOnDegenerateRichRandomScenes) {
  Tally t;
  test::for_random_scenes(20261121, 2000, "twin_grid", [](std::mt19937_64& rng, int) { return test::random_contacts(rng, 7); },
                          [&](const std::string& text, const std::string& tag) { compare_modes(text, t, tag); });
  if (HasFatalFailure()) return;
  // Grid scenes are exact in binary (small integers, halves, quarters… and 1/3): many exact zeros
  // are still certified, since exact operations carry no error.
  std::printf("[ stats    ] grid scenes: the twin decided %d of %d queries alone\n", t.float_decided, t.cases);
  EXPECT_GT(t.float_decided, t.cases / 2);
}

TEST(FloatTwin, DecidesTypicalScenesByItself) {
  Tally t;
  test::for_random_scenes(5, 1000, "twin_decimal", [](std::mt19937_64& rng, int i) { return test::decimal_contacts(rng, 3 + i % 6); },
                          [&](const std::string& text, const std::string& tag) { compare_modes(text, t, tag); });
  if (HasFatalFailure()) return;
  // Form closure of frictionless contacts with generic decimals is generic too: ≥ 99 % overall.
  std::printf("[ stats    ] decimal scenes: the twin decided %d of %d queries alone\n", t.float_decided, t.cases);
  EXPECT_GE(t.float_decided * 100, t.cases * 99) << t.float_decided << " of " << t.cases;
}

TEST(FloatTwin, NearThresholdNeverWrongAndNaiveFloatIs) {
  // Two fingers with the segment between them 10^-k away from the friction-cone edge (theory.md
  // §8.5, y2 = 1 ± 10^-k, μ = 1/2): closure iff y2 < 1. For small k the twin certifies; for large
  // k it abstains; it is never wrong. The naive kernel guesses and is wrong for some k.
  int naive_wrong = 0, twin_undecided = 0;
  for (const test::Near_edge_grasp& g : test::near_edge_grasps()) {
    const Scene s = read_scene(g.text, Input_limits{});
    ASSERT_EQ(decide_closure(s, Property::force_closure, Mode::exact).holds, g.closed) << g.y2;
    const Closure_answer twin = decide_closure(s, Property::force_closure, Mode::float_only);
    if (twin.decided) EXPECT_EQ(twin.holds, g.closed) << g.y2;
    else ++twin_undecided;
    EXPECT_EQ(decide_closure(s, Property::force_closure, Mode::hybrid).holds, g.closed) << g.y2;
    // Naive: the decimal text parsed to the nearest double (strtod), raw signs.
    std::vector<fl::Bounded_contact> cs(2);
    for (int c = 0; c < 2; ++c) {
      const double* x = g.contacts[c];
      cs[c].ax = Bounded::exact(x[0]);
      cs[c].ay = Bounded::exact(x[1]);
      cs[c].nx = Bounded::exact(x[2]);
      cs[c].ny = Bounded::exact(x[3]);
      cs[c].mu = Bounded::exact(x[4]);
      cs[c].frictional = true;
    }
    const fl::Naive_kernel naive(fl::generators(cs, Reading::friction));
    naive_wrong += compute_dual_cone(naive).force_closure() != g.closed;
  }
  std::printf("[ stats    ] 80 near-edge grasps: twin undecided %d (never wrong), naive wrong %d\n", twin_undecided,
              naive_wrong);
  EXPECT_GT(twin_undecided, 0);
  EXPECT_GT(naive_wrong, 0);  // guessing is wrong near the boundary
}

}  // namespace
}  // namespace wrenchkit
