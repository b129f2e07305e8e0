// [EQ-1] Static equilibrium: the textbook scenes of theory.md §9 (tests/golden/equilibrium, verdicts
// re-derived by make_golden.py's own brute force), random scenes and loads against an O(k³)
// Carathéodory brute force, every certificate through the independent checker, tampering.
#include <gtest/gtest.h>

#include <random>

#include "exact/equilibrium.h"
#include "exact/input_error.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

using V = std::array<Rational, 3>;

// −w ∈ pos(g) by Carathéodory: some ≤ 3 generators with a non-negative exact solution.
bool brute_force_balanced(const std::vector<Wrench>& g, const Wrench& w) {
  const V x = {-w.fx, -w.fy, -w.m};
  if (x[0] == 0 && x[1] == 0 && x[2] == 0) return true;
  auto vec = [](const Wrench& a) { return V{a.fx, a.fy, a.m}; };
  auto det = [](const V& a, const V& b, const V& c) -> Rational {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  };
  auto cross = [](const V& a, const V& b) {
    return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  const std::size_t n = g.size();
  for (std::size_t i = 0; i < n; ++i) {  // x = λ g_i
    const V a = vec(g[i]);
    const V c = cross(a, x);
    if (c[0] == 0 && c[1] == 0 && c[2] == 0 && a[0] * x[0] + a[1] * x[1] + a[2] * x[2] > 0) return true;
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {  // x = λ g_i + μ g_j in their plane
      const V a = vec(g[i]), b = vec(g[j]), nrm = cross(a, b);
      if (nrm[0] == 0 && nrm[1] == 0 && nrm[2] == 0) continue;
      if (nrm[0] * x[0] + nrm[1] * x[1] + nrm[2] * x[2] != 0) continue;
      // λ = (x × b)·n / |n|², μ = (a × x)·n / |n|²: signs of the numerators decide.
      const V xb = cross(x, b), ax = cross(a, x);
      const Rational l = xb[0] * nrm[0] + xb[1] * nrm[1] + xb[2] * nrm[2];
      const Rational m = ax[0] * nrm[0] + ax[1] * nrm[1] + ax[2] * nrm[2];
      if (l >= 0 && m >= 0) return true;
    }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {  // Cramer
        const V a = vec(g[i]), b = vec(g[j]), c = vec(g[k]);
        const Rational d = det(a, b, c);
        if (d == 0) continue;
        const Rational l1 = det(x, b, c) / d, l2 = det(a, x, c) / d, l3 = det(a, b, x) / d;
        if (l1 >= 0 && l2 >= 0 && l3 >= 0) return true;
      }
  return false;
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
  EXPECT_EQ(a.load.fx, 0);
  EXPECT_EQ(a.load.fy, -1);
  EXPECT_EQ(a.load.m, Rational(-1, 2));
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
    std::vector<Wrench> ws;
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
