// The exact kernel's fixed-width integer arithmetic (exact/numbers/wide_int.h) and its integer rows
// (Exact_kernel from a scene), against GMP: random entries of every bit length and sign, the extreme
// magnitudes ±(2^62 − 1), exactly dependent rows, and random scenes whose numbers range from short
// decimals to 30-digit fractions. Seeds fixed, overridable by WRENCHKIT_SEED.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "exact/statics/generators.h"
#include "exact/numbers/wide_int.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

using wide::i128;

Integer big(i128 v) {
  const bool neg = v < 0;
  const wide::u128 u = neg ? 0 - static_cast<wide::u128>(v) : static_cast<wide::u128>(v);
  Integer r = Integer(static_cast<unsigned long>(u >> 64));
  r <<= 64;
  r += static_cast<unsigned long>(static_cast<std::uint64_t>(u));
  return neg ? Integer(-r) : r;
}

Integer big(const wide::Int192& x) {  // two's complement limbs → Integer
  Integer r = 0;
  for (int i = 2; i >= 0; --i) {
    r <<= 64;
    r += static_cast<unsigned long>(x.w[i]);
  }
  if (x.w[2] >> 63) r -= Integer(1) << 192;
  return r;
}

// A random value with a random bit length in [0, bits], random sign; now and then an extreme.
std::int64_t draw(std::mt19937_64& rng, int bits) {
  const std::uint64_t kind = rng() % 16;
  const std::int64_t max = bits >= 62 ? wide::kMax62 : (std::int64_t(1) << bits) - 1;
  if (kind == 0) return max;
  if (kind == 1) return -max;
  if (kind == 2) return 0;
  if (kind == 3) return (rng() & 1) ? 1 : -1;
  const int len = static_cast<int>(rng() % (bits + 1));
  const std::int64_t m = len == 0 ? 0 : static_cast<std::int64_t>(rng() & ((std::uint64_t(1) << len) - 1));
  const std::int64_t v = std::min(m, max);
  return (rng() & 1) ? -v : v;
}

int gmp_det_sign(const std::int64_t a[3], const std::int64_t b[3], const std::int64_t c[3]) {
  auto z = [](std::int64_t v) { return Integer(static_cast<long>(v)); };
  const Integer d = z(a[0]) * (z(b[1]) * z(c[2]) - z(b[2]) * z(c[1])) -
                    z(a[1]) * (z(b[0]) * z(c[2]) - z(b[2]) * z(c[0])) +
                    z(a[2]) * (z(b[0]) * z(c[1]) - z(b[1]) * z(c[0]));
  return sgn(d);
}

TEST(WideInt, ProductsAndSumsAgreeWithGmp) {
  std::mt19937_64 rng(test::seed(71));
  for (int t = 0; t < 20000; ++t) {
    const std::int64_t a = draw(rng, 63 - 1);
    const i128 b = static_cast<i128>(draw(rng, 62)) * draw(rng, 62) + draw(rng, 62);  // |b| < 2^125
    const wide::Int192 p = wide::mul(a, b);
    ASSERT_EQ(big(p), Integer(static_cast<long>(a)) * big(b)) << "a=" << a << " seed " << test::seed(71);
    const wide::Int192 q = wide::mul(draw(rng, 62), static_cast<i128>(draw(rng, 62)) * draw(rng, 62));
    ASSERT_EQ(big(wide::add(p, q)), big(p) + big(q));
    ASSERT_EQ(wide::sign(p), sgn(big(p)));
  }
  // The extremes: (2^62 − 1)·(2^125 − …) both signs.
  const i128 m = wide::minor2(wide::kMax62, -wide::kMax62, wide::kMax62, wide::kMax62);  // 2·(2^62−1)^2
  for (std::int64_t a : {wide::kMax62, -wide::kMax62})
    for (i128 b : {m, -m}) EXPECT_EQ(big(wide::mul(a, b)), Integer(static_cast<long>(a)) * big(b));
}

TEST(WideInt, DeterminantSignsAgreeWithGmpAtEveryMagnitude) {
  const std::uint64_t seed = test::seed(72);
  std::mt19937_64 rng(seed);
  for (int t = 0; t < 60000; ++t) {
    const int bits = 1 + static_cast<int>(rng() % 62);
    std::int64_t a[3], b[3], c[3];
    for (int i = 0; i < 3; ++i) a[i] = draw(rng, bits), b[i] = draw(rng, bits), c[i] = draw(rng, bits);
    const int expected = gmp_det_sign(a, b, c);
    ASSERT_EQ(wide::det3_sign(a, b, c), expected) << "bits " << bits << " seed " << seed << " case " << t;
    if (bits <= 40) {
      ASSERT_EQ(wide::det3_sign_small(a, b, c), expected) << "seed " << seed << " case " << t;
    }
  }
}

TEST(WideInt, ExactlyDependentRowsHaveDeterminantZero) {
  const std::uint64_t seed = test::seed(73);
  std::mt19937_64 rng(seed);
  for (int t = 0; t < 20000; ++t) {
    std::int64_t a[3], b[3], c[3];
    const std::int64_t al = draw(rng, 3), be = draw(rng, 3);  // |α|, |β| ≤ 7
    for (int i = 0; i < 3; ++i) {
      a[i] = draw(rng, 58);
      b[i] = draw(rng, 58);
      c[i] = al * a[i] + be * b[i];  // |c| < 2^62
    }
    ASSERT_EQ(wide::det3_sign(a, b, c), 0) << "seed " << seed << " case " << t;
    ASSERT_EQ(wide::det3_sign(c, a, b), 0) << "seed " << seed << " case " << t;
    // One unit off the dependence: the sign is that of GMP's determinant.
    c[t % 3] += (t & 1) ? 1 : -1;
    ASSERT_EQ(wide::det3_sign(a, b, c), gmp_det_sign(a, b, c)) << "seed " << seed << " case " << t;
  }
  const std::int64_t M = wide::kMax62;
  const std::int64_t e1[3] = {M, -M, M}, e2[3] = {-M, M, M}, e3[3] = {M, M, -M};
  EXPECT_EQ(wide::det3_sign(e1, e2, e3), gmp_det_sign(e1, e2, e3));
  EXPECT_EQ(wide::det3_sign(e1, e1, e3), 0);
}

// A random number as a user may write it (scene_json quotes it): short decimals, long decimals, exponents, fractions.
std::string number(std::mt19937_64& rng) {
  auto digits = [&](int n) {
    std::string s(1, static_cast<char>('1' + rng() % 9));
    for (int i = 1; i < n; ++i) s += static_cast<char>('0' + rng() % 10);
    return s;
  };
  const std::string sign = (rng() & 1) ? "-" : "";
  switch (rng() % 6) {
    case 0: return sign + std::to_string(rng() % 5);                                          // small integers
    case 1: return sign + digits(1) + "." + digits(1 + static_cast<int>(rng() % 6));          // 6 decimals
    case 2: return sign + "0." + digits(12 + static_cast<int>(rng() % 8));                    // ~2^60 denominators
    case 3: return sign + digits(2) + "." + digits(25);                                       // long
    case 4: return sign + digits(1 + static_cast<int>(rng() % 30)) + "/" + digits(1 + static_cast<int>(rng() % 30));
    default: return sign + digits(1) + "e" + std::to_string(static_cast<int>(rng() % 21) - 10);
  }
}

Vec3q rationals(const Vec3q& w) { return {w[0], w[1], w[2]}; }

int mpq_det_sign(const Vec3q& a, const Vec3q& b, const Vec3q& c) {
  return sgn(a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]));
}

TEST(ExactKernelRows, SceneRowsArePositiveMultiplesOfTheGeneratorsAndSignsAgreeWithRationals) {
  const std::uint64_t seed = test::seed(74);
  std::mt19937_64 rng(seed);
  int tiers[3] = {0, 0, 0}, scenes = 0;  // rows below 2^40, below 2^62, larger: every tier is exercised
  for (int t = 0; t < 300; ++t) {
    std::vector<test::Contact_spec> cs;
    const int n = 1 + static_cast<int>(rng() % 5);
    for (int i = 0; i < n; ++i) {
      std::string mu = (rng() % 4 == 0) ? "0" : number(rng);
      if (mu[0] == '-') mu = mu.substr(1);
      std::string nx = number(rng), ny = number(rng);
      if (rng() % 8 == 0) nx = "1", ny = "0";  // parallel normals now and then
      cs.push_back({number(rng), number(rng), nx, ny, mu});
      if (rng() % 6 == 0) cs.push_back(cs.back());  // a duplicate contact: parallel rows
    }
    const std::string text = test::scene_json(cs);
    Scene scene;
    try {
      scene = read_scene(text, Input_limits{});
    } catch (const std::exception&) {
      continue;  // a zero normal drawn: not a scene
    }
    ++scenes;
    for (Reading reading : {Reading::friction, Reading::frictionless}) {
      const std::vector<Generator> gens = generators(scene, reading);
      std::vector<Vec3q> ws;
      for (const Generator& g : gens) ws.push_back(g.w);
      const Exact_kernel from_scene(scene, reading), from_wrenches(ws);
      ASSERT_EQ(from_scene.size(), gens.size());
      for (std::size_t i = 0; i < gens.size(); ++i) {
        const std::array<Integer, 3> r = from_scene.row(i);
        const Vec3q g = rationals(gens[i].w);
        const Vec3q x = cross(g, {Rational(r[0]), Rational(r[1]), Rational(r[2])});
        ASSERT_TRUE(x[0] == 0 && x[1] == 0 && x[2] == 0) << test::dump_failure(text, "kernel_rows");
        ASSERT_GT(g[0] * r[0] + g[1] * r[1] + g[2] * r[2], 0) << test::dump_failure(text, "kernel_rows");
        const Integer top = std::max({abs(r[0]), abs(r[1]), abs(r[2])});
        ++tiers[top < (Integer(1) << 40) ? 0 : (top < (Integer(1) << 62) ? 1 : 2)];
      }
      const std::size_t m = gens.size();
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < m; ++j) {
          const Vec3q x = cross(rationals(gens[i].w), rationals(gens[j].w));
          const Sign parallel = (x[0] == 0 && x[1] == 0 && x[2] == 0) ? Sign::zero : Sign::positive;
          ASSERT_EQ(from_scene.cross_sign(i, j), parallel) << test::dump_failure(text, "kernel_rows");
          ASSERT_EQ(from_wrenches.cross_sign(i, j), parallel) << test::dump_failure(text, "kernel_rows");
          for (std::size_t k = 0; k < m; ++k) {
            const Sign expected =
                sign_of(mpq_det_sign(rationals(gens[i].w), rationals(gens[j].w), rationals(gens[k].w)));
            ASSERT_EQ(from_scene.det_sign(i, j, k), expected) << "seed " << seed << " " << test::dump_failure(text, "kernel_rows");
            ASSERT_EQ(from_wrenches.det_sign(i, j, k), expected) << "seed " << seed << " " << test::dump_failure(text, "kernel_rows");
          }
        }
    }
  }
  EXPECT_GT(scenes, 250);
  for (int tier : tiers) EXPECT_GT(tier, 50);
}

TEST(ExactKernelRows, ParallelRowsOfDifferentTiersAreParallel) {
  // The same contact written with a small and with a 31-digit normal: rows of tier 0 and tier 2
  // (not reduced), parallel all the same; and a third contact that is not.
  const std::string big = "1" + std::string(30, '0');
  const std::string text = test::scene_json({{"1/3", "2", "1", "0", "1/2"},
                                             {"1/3", "2", big, "0", "1/2"},
                                             {"1/3", "2", big, "1", "1/2"}});
  const Scene scene = read_scene(text, Input_limits{});
  const Exact_kernel k(scene, Reading::friction);
  ASSERT_EQ(k.size(), 6u);
  EXPECT_EQ(k.cross_sign(0, 2), Sign::zero);
  EXPECT_EQ(k.cross_sign(1, 3), Sign::zero);
  EXPECT_EQ(k.cross_sign(2, 0), Sign::zero);
  EXPECT_EQ(k.cross_sign(0, 1), Sign::positive);
  EXPECT_EQ(k.cross_sign(0, 4), Sign::positive);
  EXPECT_EQ(k.det_sign(0, 2, 1), Sign::zero);
  EXPECT_EQ(k.det_sign(0, 1, 4), sign_of(mpq_det_sign(rationals(generators(scene, Reading::friction)[0].w),
                                                      rationals(generators(scene, Reading::friction)[1].w),
                                                      rationals(generators(scene, Reading::friction)[4].w))));
}

}  // namespace
}  // namespace wrenchkit
