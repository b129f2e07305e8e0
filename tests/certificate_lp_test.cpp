// [FC-5] The integer certificates against the rational LP of FC-4 (kept as the oracle): the same
// pivots and weights, fixed width against GMP, and every certificate accepted by the independent
// checker — on the golden scenes (thresholds ± 10^-40, 40-digit rotations, scales 10^±20), 3 000
// degenerate-rich random scenes, user-like decimal scenes and random loads. Fixed seeds
// (WRENCHKIT_SEED overrides); a failing case prints its seed and dumps its scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <string>
#include <vector>

#include "exact/certificates/certificates.h"
#include "exact/statics/closure.h"
#include "exact/statics/cone_lp.h"
#include "exact/statics/equilibrium.h"
#include "exact/io/scene.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

// The kernel rows as rationals (columns of the oracle's tableau).
std::vector<Vec3q> rows_as_wrenches(const Exact_kernel& k, const std::vector<std::size_t>& which) {
  std::vector<Vec3q> out;
  for (std::size_t i : which) {
    const auto r = k.row(i);
    out.push_back({Rational(r[0]), Rational(r[1]), Rational(r[2])});
  }
  return out;
}

// The integer LP on kernel rows against the rational tableau on the same rows and target: FC-5 makes
// the pivots of FC-4, so membership, weights and twist are equal, in fixed width and in GMP alike.
::testing::AssertionResult same_as_rational_lp(const Exact_kernel& k, const std::vector<std::size_t>& columns,
                                               const std::vector<std::size_t>& negated) {
  Vec3q x{Rational(0), Rational(0), Rational(0)};
  for (const Vec3q& w : rows_as_wrenches(k, negated)) x = {x[0] - w[0], x[1] - w[1], x[2] - w[2]};
  const Cone_membership q = cone_membership(rows_as_wrenches(k, columns), x);
  for (bool fixed : {true, false}) {
    const Integer_cone_membership z = cone_membership(k, columns, negated, fixed);
    if (z.member != q.member) return ::testing::AssertionFailure() << "membership differs (fixed " << fixed << ")";
    if (q.member) {
      if (z.denominator <= 0) return ::testing::AssertionFailure() << "denominator not positive";
      for (std::size_t j = 0; j < columns.size(); ++j)
        if (Rational(z.numerators[j] * q.weights[j].get_den()) != Rational(z.denominator * q.weights[j].get_num()))
          return ::testing::AssertionFailure() << "weight " << j << " differs (fixed " << fixed << ")";
    } else {
      const Vec3q t = primitive_vec(q.twist);
      for (int r = 0; r < 3; ++r)
        if (Rational(z.twist[r]) != t[r]) return ::testing::AssertionFailure() << "twist differs (fixed " << fixed << ")";
    }
  }
  return ::testing::AssertionSuccess();
}

// The old certificate of equilibrium (FC-4 on the rational generators), as the oracle: the integer
// LP makes the same pivots on positive multiples of the same columns and target, so the certificate
// must be the same, weight for weight.
Equilibrium_certificate rational_lp_certificate(const Scene& s, const Vec3q& load) {
  const std::vector<Generator> gens = generators(s, Reading::friction);
  std::vector<Vec3q> ws;
  for (const Generator& g : gens) ws.push_back(g.w);
  const Cone_membership m = cone_membership(ws, Vec3q{-load[0], -load[1], -load[2]});
  Equilibrium_certificate c;
  c.holds = m.member;
  if (m.member) {
    for (std::size_t i = 0; i < gens.size(); ++i)
      if (m.weights[i] != 0) c.combination.push_back({{gens[i].contact, gens[i].edge}, m.weights[i]});
  } else {
    c.twist = primitive_vec(m.twist);
  }
  return c;
}

struct Tally {
  int cases = 0, closed = 0, gmp = 0;
};

// Closure of one scene text, both properties, exact and hybrid: verdict against the rational LP's
// (rank 3 and −Σ basis ∈ W), certificate accepted, the closing LP equal to the rational one.
::testing::AssertionResult closure_case(const std::string& text, Tally& t) {
  const Scene s = read_scene(text, Input_limits{});
  for (Property p : {Property::force_closure, Property::form_closure}) {
    const Exact_kernel k(s, reading_of(p), {}, Exact_kernel::With_provenance{});
    std::vector<std::size_t> all(k.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    // The oracle's verdict: rank 3 (a basis) and −(r_a + r_b + r_c) ∈ pos(rows), by the rational LP.
    bool oracle = false;
    if (!all.empty()) {
      const Dual_cone dc = compute_dual_cone_reference(k);
      if (dc.rank == 3) {
        const std::vector<std::size_t> b = {dc.basis[0], dc.basis[1], dc.basis[2]};
        Vec3q x{Rational(0), Rational(0), Rational(0)};
        for (const Vec3q& w : rows_as_wrenches(k, b)) x = {x[0] - w[0], x[1] - w[1], x[2] - w[2]};
        oracle = cone_membership(rows_as_wrenches(k, all), x).member;
        auto same = same_as_rational_lp(k, all, b);
        if (!same) return same << " (" << property_name(p) << ", all generators)";
        std::int64_t probe[3];
        for (std::size_t i : all) t.gmp += !k.small_row(i, probe);
      }
    }
    for (Mode m : {Mode::exact, Mode::hybrid}) {
      const Closure_answer a = decide_closure(s, p, m);
      if (a.holds != oracle)
        return ::testing::AssertionFailure() << property_name(p) << " " << mode_name(m) << ": " << a.holds
                                             << " but the rational LP says " << oracle;
      auto ok = test::checker_accepts(text, certificate_json(a.certificate));
      if (!ok) return ok << " (" << property_name(p) << ", " << mode_name(m) << ")";
      if (a.holds && (a.certificate.combination.size() > 6 || a.certificate.combination.size() < 3))
        return ::testing::AssertionFailure() << "combination of " << a.certificate.combination.size() << " generators";
      t.closed += a.holds && m == Mode::exact;
    }
  }
  ++t.cases;
  return ::testing::AssertionSuccess();
}

TEST(IntegerCertificates, GoldenScenesIncludingNearDegenerateOnes) {
  Tally t;
  for (const std::string& file : test::scene_files("tests/golden")) {
    const auto r = closure_case(test::read_text(file), t);
    EXPECT_TRUE(r) << file;
  }
  EXPECT_GE(t.cases, 36);
  EXPECT_GT(t.gmp, 0) << "no golden scene exercised the GMP path (40-digit rotations, 10^±20 scales)";
}

TEST(IntegerCertificates, DegenerateRichRandomScenes) {
  const std::uint64_t seed = test::seed(5150);
  std::mt19937_64 rng(seed);
  Tally t;
  for (int i = 0; i < 3000; ++i) {
    const std::string text = test::scene_json(test::random_contacts(rng, 7));
    const auto r = closure_case(text, t);
    if (!r) {
      ADD_FAILURE() << "seed " << seed << " case " << i << ": " << r.message() << "\nscene dumped to "
                    << test::dump_failure(text, "integer_certificates_" + std::to_string(seed) + "_" + std::to_string(i));
      return;
    }
  }
  EXPECT_GT(t.closed, 150);        // both verdicts in quantity, or this proves little
  EXPECT_LT(t.closed, 2 * 3000 - 150);
}

TEST(IntegerCertificates, DecimalScenesAsUsersWriteThem) {
  const std::uint64_t seed = test::seed(6021);
  std::mt19937_64 rng(seed);
  Tally t;
  for (int i = 0; i < 400; ++i) {
    const std::string text = test::scene_json(test::decimal_contacts(rng, 3 + i % 6));
    const auto r = closure_case(text, t);
    if (!r) {
      ADD_FAILURE() << "seed " << seed << " case " << i << ": " << r.message() << "\nscene dumped to "
                    << test::dump_failure(text, "integer_certificates_decimal_" + std::to_string(seed) + "_" +
                                                    std::to_string(i));
      return;
    }
  }
  EXPECT_GT(t.closed, 20);
}

// [FC-2] Four rows: four_spanning_weights (cofactors, no LP) succeeds exactly when the rows positively
// span R³ (the rational LP's verdict on −(r_b1 + r_b2 + r_b3) with b an independent triple), and then its
// weights are the LP's λ = μ + 1_b up to a positive factor — so positive_certificate's coprime weights
// are the same either way.
TEST(IntegerCertificates, FourGeneratorsNeedNoLp) {
  const std::uint64_t seed = test::seed(4444);
  std::mt19937_64 rng(seed);
  int spanning = 0, not_spanning = 0;
  for (int i = 0; i < 400; ++i) {
    const std::string text =
        test::scene_json(i % 2 ? test::random_contacts(rng, 3 + i % 4) : test::decimal_contacts(rng, 3 + i % 4));
    const Scene s = read_scene(text, Input_limits{});
    const Exact_kernel k(s, Reading::friction, {}, Exact_kernel::With_provenance{});
    if (k.size() < 4) continue;
    for (int trial = 0; trial < 10; ++trial) {
      std::vector<std::size_t> pick(k.size());
      for (std::size_t j = 0; j < pick.size(); ++j) pick[j] = j;
      std::shuffle(pick.begin(), pick.end(), rng);
      const std::size_t rows[4] = {pick[0], pick[1], pick[2], pick[3]};
      const std::vector<std::size_t> cols(rows, rows + 4);
      std::vector<std::size_t> b;  // an independent triple of the four, if any
      for (int x = 0; x < 4 && b.empty(); ++x)
        for (int y = x + 1; y < 4 && b.empty(); ++y)
          for (int z = y + 1; z < 4 && b.empty(); ++z)
            if (k.det_sign(rows[x], rows[y], rows[z]) != Sign::zero) b = {rows[x], rows[y], rows[z]};
      bool member = false;
      Cone_membership q;
      if (!b.empty()) {
        Vec3q target{Rational(0), Rational(0), Rational(0)};
        for (const Vec3q& w : rows_as_wrenches(k, b)) target = {target[0] - w[0], target[1] - w[1], target[2] - w[2]};
        q = cone_membership(rows_as_wrenches(k, cols), target);
        member = q.member;
      }
      std::array<Integer, 4> lambda;
      const bool four = four_spanning_weights(k, rows, lambda);
      std::int64_t probe[3];
      bool small = true;
      for (std::size_t r : rows) small = small && k.small_row(r, probe);
      const std::string where = "seed " + std::to_string(seed) + " case " + std::to_string(i) + ": " + text;
      if (!small) continue;
      ASSERT_EQ(four, member) << where;
      if (!four) {
        ++not_spanning;
        continue;
      }
      ++spanning;
      // λ_j ∝ μ_j + [j ∈ b]: the ratios to the first are equal
      auto oracle = [&](std::size_t j) {
        Rational v = q.weights[j];
        if (std::find(b.begin(), b.end(), rows[j]) != b.end()) v += 1;
        return v;
      };
      for (std::size_t j = 0; j < 4; ++j) {
        ASSERT_GT(lambda[j], 0) << where;
        ASSERT_EQ(Rational(lambda[j]) * oracle(0), Rational(lambda[0]) * oracle(j)) << where;
      }
    }
  }
  EXPECT_GT(spanning, 100);
  EXPECT_GT(not_spanning, 100);
}

// Equilibrium: the certificate is the rational LP's, weight for weight, in exact mode; every mode's
// is accepted.
::testing::AssertionResult equilibrium_case(const std::string& text, int& balanced) {
  const Scene s = read_scene(text, Input_limits{});
  const Equilibrium_answer a = decide_equilibrium(s, Mode::exact);
  const Equilibrium_certificate want = rational_lp_certificate(s, a.load);
  if (certificate_json(a.certificate) != certificate_json(want))
    return ::testing::AssertionFailure() << "certificate " << certificate_json(a.certificate)
                                         << "\nrational LP's " << certificate_json(want);
  const Exact_kernel k(s, Reading::friction, {a.load}, Exact_kernel::With_provenance{});
  std::vector<std::size_t> all(k.size() - 1);
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  const auto same = same_as_rational_lp(k, all, {all.size()});
  if (!same) return same;
  for (Mode m : {Mode::exact, Mode::hybrid}) {
    const Equilibrium_answer b = decide_equilibrium(s, m);
    if (b.balanced != a.balanced) return ::testing::AssertionFailure() << mode_name(m) << " disagrees";
    auto ok = test::checker_accepts(text, certificate_json(b.certificate));
    if (!ok) return ok << " (" << mode_name(m) << ")";
  }
  balanced += a.balanced;
  return ::testing::AssertionSuccess();
}

TEST(IntegerCertificates, EquilibriumGoldenScenes) {
  int balanced = 0, n = 0;
  for (const std::string& f : test::scene_files("tests/golden/equilibrium")) {
    EXPECT_TRUE(equilibrium_case(test::read_text(f), balanced)) << f;
    ++n;
  }
  EXPECT_GE(n, 10);
  EXPECT_GT(balanced, 0);
}

TEST(IntegerCertificates, EquilibriumRandomScenesAndLoads) {
  const std::uint64_t seed = test::seed(4242);
  std::mt19937_64 rng(seed);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  int balanced = 0;
  const int cases = 1500;
  for (int i = 0; i < cases; ++i) {
    std::string text = i % 3 ? test::scene_json(test::random_contacts(rng, 6))
                             : test::scene_json(test::decimal_contacts(rng, 2 + i % 5));
    text.pop_back();
    text += uni(0, 2) ? ", \"load\": {\"force\": [" + std::to_string(uni(-2, 2)) + ", " + std::to_string(uni(-2, 2)) +
                            "], \"at\": [" + std::to_string(uni(-3, 3)) + ".5, " + std::to_string(uni(-3, 3)) + "]}}"
                      : ", \"load\": {\"wrench\": [" + std::to_string(uni(-1, 1)) + ", " + std::to_string(uni(-1, 1)) +
                            ", \"" + std::to_string(uni(-2, 2)) + "/3\"]}}";
    const auto r = equilibrium_case(text, balanced);
    if (!r) {
      ADD_FAILURE() << "seed " << seed << " case " << i << ": " << r.message() << "\nscene dumped to "
                    << test::dump_failure(text, "integer_equilibrium_" + std::to_string(seed) + "_" + std::to_string(i));
      return;
    }
  }
  EXPECT_GT(balanced, cases / 20);
  EXPECT_LT(balanced, cases - cases / 20);
}

}  // namespace
}  // namespace wrenchkit
