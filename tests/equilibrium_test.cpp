// [EQ-1] Static equilibrium: the textbook scenes of theory.md §9 (tests/golden/equilibrium, verdicts
// re-derived by make_golden.py's own brute force), random scenes and loads against an O(k³)
// Carathéodory brute force, every certificate through the independent checker, tampering.
#include <gtest/gtest.h>

#include <random>

#include "exact/certificates/certificates.h"
#include "exact/statics/equilibrium.h"
#include "exact/io/input_error.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

using V = std::array<Rational, 3>;

// −w ∈ pos(g) by Carathéodory (test_support).
bool brute_force_balanced(const std::vector<Vec3q>& g, const Vec3q& w) {
  return test::brute_force_in_cone(g, {-w[0], -w[1], -w[2]});
}

TEST(EquilibriumGolden, TextbookScenesOfTheory9) {
  int n = 0;
  for (const std::string& f : test::scene_files("tests/golden/equilibrium")) {
    SCOPED_TRACE(f);
    const std::string text = test::read_text(f);
    const bool want = test::expected_of(f).find("\"balanced\": true") != std::string::npos;
    const Scene s = read_scene(text, Input_limits{});
    const Equilibrium_answer a = decide_equilibrium(s);
    EXPECT_EQ(a.balanced, want);
    EXPECT_TRUE(test::checker_accepts(text, certificate_json(a.certificate)));
    for (Mode m : {Mode::hybrid, Mode::float_only}) {
      const Equilibrium_answer b = decide_equilibrium(s, m);
      EXPECT_TRUE(b.decided || m == Mode::float_only);
      if (!b.decided) continue;
      EXPECT_EQ(b.balanced, want) << mode_name(m);
      EXPECT_TRUE(test::checker_accepts(text, certificate_json(b.certificate))) << mode_name(m);
    }
    ++n;
  }
  EXPECT_GE(n, 28);
}

TEST(Equilibrium, GravityOnTheBlockInACornerIsHeldByTheFloor) {
  const std::string text = test::read_text(test::source_dir() +
                                           "/tests/golden/equilibrium/block_corner_mu_0_gravity.scene.json");
  const Equilibrium_answer a = decide_equilibrium(read_scene(text, Input_limits{}));
  ASSERT_TRUE(a.balanced);
  EXPECT_EQ(a.load[0], 0);
  EXPECT_EQ(a.load[1], -1);
  EXPECT_EQ(a.load[2], Rational(-1, 2));
  // Frictionless: only the floor normals (contacts 0 and 1) can push up; walls carry nothing.
  Rational total = 0;
  for (const auto& [ref, w] : a.certificate.combination) {
    EXPECT_LT(ref.contact, 2u);
    total += w;
  }
  EXPECT_EQ(total, 1);  // the floor carries the whole weight
}

TEST(Equilibrium, NoLoadIsBadInput) {
  EXPECT_THROW(decide_equilibrium(read_scene(R"({"wrenchkit": 1})", Input_limits{})), Input_error);
}

TEST(Equilibrium, AgreesWithBruteForceOnRandomScenesAndLoads) {
  const std::uint64_t seed = test::seed(777);
  std::mt19937_64 rng(seed);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  int balanced = 0;
  const int cases = 2000;
  for (int i = 0; i < cases; ++i) {
    std::string text = test::scene_json(test::random_contacts(rng, 6));
    text.pop_back();  // add a load: a force at a grid point, or a wrench
    text += uni(0, 2) ? ", \"load\": {\"force\": [" + std::to_string(uni(-2, 2)) + ", " + std::to_string(uni(-2, 2)) +
                            "], \"at\": [" + std::to_string(uni(-3, 3)) + ", " + std::to_string(uni(-3, 3)) + "]}}"
                      : ", \"load\": {\"wrench\": [" + std::to_string(uni(-1, 1)) + ", " + std::to_string(uni(-1, 1)) +
                            ", " + std::to_string(uni(-2, 2)) + "]}}";
    const Scene s = read_scene(text, Input_limits{});
    std::vector<Vec3q> ws;
    for (const Generator& g : generators(s, Reading::friction)) ws.push_back(g.w);
    const Equilibrium_answer a = decide_equilibrium(s);
    const bool brute = brute_force_balanced(ws, a.load);
    const auto cert = test::checker_accepts(text, certificate_json(a.certificate));
    if (a.balanced != brute || !cert) {
      ADD_FAILURE() << "seed " << seed << " case " << i << ": " << a.balanced << " vs brute force " << brute << "\n"
                    << cert.message() << "\nscene dumped to "
                    << test::dump_failure(text, "equilibrium_" + std::to_string(seed) + "_" + std::to_string(i));
      return;
    }
    balanced += a.balanced;
    // [EQ-2] The dual-cone path agrees: hybrid always, float whenever it decides.
    for (Mode m : {Mode::hybrid, Mode::float_only}) {
      const Equilibrium_answer b = decide_equilibrium(s, m);
      if (m == Mode::hybrid) {
        ASSERT_TRUE(b.decided);
      }
      if (!b.decided) continue;
      const auto ok = test::checker_accepts(text, certificate_json(b.certificate));
      if (b.balanced != brute || !ok) {
        ADD_FAILURE() << "seed " << seed << " case " << i << " " << mode_name(m) << ": " << b.balanced
                      << " vs brute force " << brute << "\n" << ok.message() << "\nscene dumped to "
                      << test::dump_failure(text, "equilibrium_mode_" + std::to_string(seed) + "_" + std::to_string(i));
        return;
      }
    }
    // Tampering: a doubled weight no longer cancels the load; a negated twist has negative power
    // against the load.
    Equilibrium_certificate t = a.certificate;
    if (t.holds && !t.combination.empty()) {
      t.combination[0].second *= 2;
      EXPECT_FALSE(test::checker_accepts(text, certificate_json(t)));
    } else if (!t.holds) {
      for (Rational& x : t.twist) x = -x;
      EXPECT_FALSE(test::checker_accepts(text, certificate_json(t)));  // power against the load < 0
    }
  }
  EXPECT_GT(balanced, cases / 20);
  EXPECT_LT(balanced, cases - cases / 20);
}

}  // namespace
}  // namespace wrenchkit
