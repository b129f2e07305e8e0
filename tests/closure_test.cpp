// [FC-1] [FC-2] [FC-3] Force and form closure: named degenerate fixtures, the algorithm against the
// O(k³) brute force on thousands of random scenes, every certificate through the independent
// checker, and tampered certificates rejected.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/dual_cone.h"
#include "exact/certificates/certificates.h"
#include "exact/statics/closure.h"
#include "exact/statics/cone_lp.h"
#include "exact/io/scene.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

using test::Contact_spec;
using test::scene_json;

struct Both {
  Closure_answer force, form;
  std::string text;
};

Both closure_of(const std::string& text) {
  const Scene s = read_scene(text, Input_limits{});
  return {decide_closure(s, Property::force_closure), decide_closure(s, Property::form_closure), text};
}

Both closure_of(const std::vector<Contact_spec>& c) { return closure_of(scene_json(c)); }

void expect_certified(const Both& b) {
  EXPECT_TRUE(test::checker_accepts(b.text, certificate_json(b.force.certificate)));
  EXPECT_TRUE(test::checker_accepts(b.text, certificate_json(b.form.certificate)));
}

// theory.md §8.7: three normals concurrent at G = (1,1).
std::vector<Contact_spec> example3(const std::string& mu) {
  return {{"1", "0", "0", "1", mu}, {"0", "1", "1", "0", mu}, {"3", "3", "-1", "-1", mu}};
}

TEST(ClosureFixture, Example3FrictionlessIsRank2AndOpen) {
  const Both b = closure_of(example3("0"));
  EXPECT_FALSE(b.force.holds);
  EXPECT_EQ(b.force.rank, 2);
  EXPECT_EQ(b.force.shape, Dual_shape::lineality);
  // The only labeled point is G = (1,1), labeled ±: the certificate twist is a rotation about G.
  const Twist_reading r = read_twist(b.force.certificate.twist);
  ASSERT_NE(r.label, 'i');
  EXPECT_EQ(r.point[0], 1);
  EXPECT_EQ(r.point[1], 1);
  expect_certified(b);
}

TEST(ClosureFixture, Example3AnyFrictionCloses) {
  for (const char* mu : {"1/1000", "1/10", "1/5", "1/2", "1e-30"}) {
    SCOPED_TRACE(mu);
    const Both b = closure_of(example3(mu));
    EXPECT_TRUE(b.force.holds);
    EXPECT_FALSE(b.form.holds);
    EXPECT_EQ(b.form.rank, 2);
    expect_certified(b);
  }
}

TEST(ClosureFixture, VerticalWallsSqueezeIsNotForceClosure) {
  // theory.md §5.5: no finite labeled point, yet W is only the plane fy = 0.
  const Both b = closure_of(std::vector<Contact_spec>{
      {"-1", "1", "1", "0", ""}, {"-1", "-1", "1", "0", ""}, {"1", "1", "-1", "0", ""}, {"1", "-1", "-1", "0", ""}});
  EXPECT_FALSE(b.force.holds);
  EXPECT_EQ(b.force.rank, 2);
  // The escape is a vertical translation: a point at infinity, direction (±1, 0).
  const Twist_reading r = read_twist(b.force.certificate.twist);
  EXPECT_EQ(r.label, 'i');
  EXPECT_EQ(abs(r.point[0]), 1);
  EXPECT_EQ(r.point[1], 0);
  expect_certified(b);
}

TEST(ClosureFixture, ReuleauxSquares) {
  // theory.md §7, square [0,2]^2.
  const Both crossed = closure_of(std::vector<Contact_spec>{
      {"3/2", "0", "0", "1", ""}, {"1/2", "2", "0", "-1", ""}, {"0", "3/2", "1", "0", ""}, {"2", "1/2", "-1", "0", ""}});
  EXPECT_TRUE(crossed.form.holds);
  EXPECT_TRUE(crossed.force.holds);
  expect_certified(crossed);

  const Both pinwheel = closure_of(std::vector<Contact_spec>{
      {"1/2", "0", "0", "1", ""}, {"3/2", "2", "0", "-1", ""}, {"0", "3/2", "1", "0", ""}, {"2", "1/2", "-1", "0", ""}});
  EXPECT_FALSE(pinwheel.form.holds);
  EXPECT_EQ(pinwheel.form.rank, 3);
  // The feasible rotation centres are the '−' square (1/2,1/2)–(3/2,3/2): a clockwise rotation.
  const Twist_reading r = read_twist(pinwheel.form.certificate.twist);
  EXPECT_EQ(r.label, '-');
  EXPECT_GE(r.point[0], Rational(1, 2));
  EXPECT_LE(r.point[0], Rational(3, 2));
  EXPECT_GE(r.point[1], Rational(1, 2));
  EXPECT_LE(r.point[1], Rational(3, 2));
  expect_certified(pinwheel);

  const Both aligned = closure_of(std::vector<Contact_spec>{
      {"1/2", "0", "0", "1", ""}, {"1/2", "2", "0", "-1", ""}, {"0", "1", "1", "0", ""}, {"2", "1", "-1", "0", ""}});
  EXPECT_FALSE(aligned.form.holds);
  EXPECT_EQ(aligned.form.rank, 2);
  const Twist_reading a = read_twist(aligned.form.certificate.twist);
  EXPECT_EQ(a.point[0], Rational(1, 2));  // (1/2, 1) labeled ±
  EXPECT_EQ(a.point[1], 1);
  expect_certified(aligned);
}

TEST(ClosureFixture, TriangleFourContactsAndTheMarginalPoint) {
  const Both closed = closure_of(std::vector<Contact_spec>{
      {"1", "0", "0", "1", ""}, {"3", "0", "0", "1", ""}, {"0", "2", "1", "0", ""}, {"2", "2", "-1", "-1", ""}});
  EXPECT_TRUE(closed.form.holds);
  expect_certified(closed);
  // Moving the left contact to (0,1): R+ = {(1,1)}, a single marginal point; W* is one ray.
  const Both marginal = closure_of(std::vector<Contact_spec>{
      {"1", "0", "0", "1", ""}, {"3", "0", "0", "1", ""}, {"0", "1", "1", "0", ""}, {"2", "2", "-1", "-1", ""}});
  EXPECT_FALSE(marginal.form.holds);
  EXPECT_EQ(marginal.form.shape, Dual_shape::ray);
  const Twist_reading r = read_twist(marginal.form.certificate.twist);
  EXPECT_EQ(r.label, '+');
  EXPECT_EQ(r.point[0], 1);
  EXPECT_EQ(r.point[1], 1);
  expect_certified(marginal);
}

TEST(ClosureFixture, TwoFingerTable) {
  // theory.md §8.5 (Nguyen): finger 1 at (0,1/2) n=(1,0); finger 2 at (1,y2) n=(−1,0).
  struct Row { const char *y2, *mu; bool fc; };
  for (const Row& row : {Row{"1/2", "1/10", true}, Row{"9/10", "1/4", false}, Row{"9/10", "1/2", true},
                         Row{"1", "1/2", false}}) {
    SCOPED_TRACE(std::string(row.y2) + " " + row.mu);
    const Both b = closure_of(std::vector<Contact_spec>{{"0", "1/2", "1", "0", row.mu},
                                                        {"1", row.y2, "-1", "0", row.mu}});
    EXPECT_EQ(b.force.holds, row.fc);
    EXPECT_FALSE(b.form.holds);
    expect_certified(b);
  }
}

TEST(ClosureFixture, OnTheConeEdgeTheArcCollapses) {
  // y2 = 1, mu = 1/2: the segment between the fingers lies exactly on both cone edges: W* is the
  // ray (or arc) of twists that roll the fingers along that line; not force closure.
  const Both b = closure_of(std::vector<Contact_spec>{{"0", "1/2", "1", "0", "1/2"}, {"1", "1", "-1", "0", "1/2"}});
  EXPECT_FALSE(b.force.holds);
  EXPECT_EQ(b.force.rank, 3);
  EXPECT_NE(b.force.shape, Dual_shape::polygon);
  expect_certified(b);
}

TEST(ClosureFixture, EmptyAndTinySets) {
  const Both none = closure_of(std::vector<Contact_spec>{});
  EXPECT_EQ(none.force.rank, 0);
  EXPECT_FALSE(none.force.holds);
  expect_certified(none);
  const Both one = closure_of(std::vector<Contact_spec>{{"0", "0", "1", "0", ""}});
  EXPECT_EQ(one.force.rank, 1);
  expect_certified(one);
  const Both opposite = closure_of(std::vector<Contact_spec>{{"0", "0", "1", "0", ""}, {"3", "0", "-1", "0", ""}});
  EXPECT_EQ(opposite.force.rank, 1);
  expect_certified(opposite);
  const Both same_point = closure_of(std::vector<Contact_spec>{{"1", "1", "1", "0", ""}, {"1", "1", "1", "0", ""},
                                                               {"1", "1", "2", "0", ""}});
  EXPECT_EQ(same_point.force.rank, 1);
  expect_certified(same_point);
}

TEST(ClosureFixture, PureMomentsOfBothSigns) {
  std::vector<Contact_spec> c = {{"", "", "", "", "", "[1, 0, 0]"},  {"", "", "", "", "", "[-1, 0, 0]"},
                                 {"", "", "", "", "", "[0, 1, 0]"},  {"", "", "", "", "", "[0, 0, 1]"},
                                 {"", "", "", "", "", "[0, 0, -1]"}};
  const Both open = closure_of(c);
  EXPECT_FALSE(open.force.holds);  // only R∞ remains: the translation that moves up is free
  const Twist_reading r = read_twist(open.force.certificate.twist);
  EXPECT_EQ(r.label, 'i');
  expect_certified(open);
  c.push_back({"", "", "", "", "", "[0, -1, 0]"});
  const Both closed = closure_of(c);
  EXPECT_TRUE(closed.force.holds);
  expect_certified(closed);
}

TEST(ClosureFixture, DuplicatesAndParallelsAreHarmless) {
  // The same frictional contact three times, and normals of different lengths.
  std::vector<Contact_spec> c = example3("1/2");
  c.push_back({"1", "0", "0", "7", "1/2"});
  c.push_back({"1", "0", "0", "1", "1/2"});
  const Both b = closure_of(c);
  EXPECT_TRUE(b.force.holds);
  expect_certified(b);
}

TEST(ClosureFixture, PositiveCertificateIsSmall) {
  // Steinitz: at most 6 generators are ever needed in R³; ours uses ≤ 3 + 3.
  const Both b = closure_of(example3("1/2"));
  ASSERT_TRUE(b.force.holds);
  EXPECT_LE(b.force.certificate.combination.size(), 6u);
  for (const auto& [ref, w] : b.force.certificate.combination) EXPECT_GT(w, 0);
}

// ---- Differential: the incremental dual cone against the O(k³) brute force and the exact LP. ----

TEST(ClosureDifferential, AgreesWithBruteForceAndLpOnRandomScenes) {
  const std::uint64_t seed = test::seed(20261121);
  std::mt19937_64 rng(seed);
  int closed = 0;
  const int cases = 3000;
  for (int i = 0; i < cases; ++i) {
    const std::string text = scene_json(test::random_contacts(rng, 7));
    const Scene s = read_scene(text, Input_limits{});
    for (Property p : {Property::force_closure, Property::form_closure}) {
      std::vector<Vec3q> ws;
      for (const Generator& g : generators(s, reading_of(p))) ws.push_back(g.w);
      const Closure_answer a = decide_closure(s, p);
      const bool brute = test::brute_force_closure(ws);
      // Third opinion: force closure ⇔ rank 3 and −Σ basis ∈ W (exact LP [FC-4]).
      bool lp = false;
      if (test::brute_force_rank(ws) == 3) {
        const Dual_cone dc = compute_dual_cone(Exact_kernel(ws));
        const auto& b = dc.basis;
        lp = cone_membership(ws, {-(ws[b[0]][0] + ws[b[1]][0] + ws[b[2]][0]),
                                  -(ws[b[0]][1] + ws[b[1]][1] + ws[b[2]][1]),
                                  -(ws[b[0]][2] + ws[b[1]][2] + ws[b[2]][2])})
                 .member;
      }
      const bool rank_ok = a.rank == test::brute_force_rank(ws);
      const auto cert = test::checker_accepts(text, certificate_json(a.certificate));
      if (a.holds != brute || lp != brute || !rank_ok || !cert) {
        ADD_FAILURE() << "seed " << seed << " case " << i << " " << property_name(p) << ": algorithm "
                      << a.holds << ", brute force " << brute << ", LP " << lp << ", rank " << a.rank
                      << " vs " << test::brute_force_rank(ws) << "\n"
                      << cert.message() << "\nscene dumped to "
                      << test::dump_failure(text, "closure_differential_" + std::to_string(seed) + "_" +
                                                      std::to_string(i));
        return;
      }
      closed += a.holds;
    }
  }
  // The generator must produce both verdicts in quantity, or this test proves little.
  EXPECT_GT(closed, cases / 20);
  EXPECT_LT(closed, 2 * cases - cases / 20);
}

// ---- Tampering: a changed certificate is rejected exactly when it no longer proves its claim. ----

TEST(ClosureCertificates, TamperedCertificatesAreRejected) {
  std::mt19937_64 rng(test::seed(7));
  int positives = 0, negatives = 0;
  for (int i = 0; i < 400; ++i) {
    const std::string text = scene_json(test::random_contacts(rng, 6));
    const Scene s = read_scene(text, Input_limits{});
    for (Property p : {Property::force_closure, Property::form_closure}) {
      const Closure_answer a = decide_closure(s, p);
      Closure_certificate c = a.certificate;
      ASSERT_TRUE(test::checker_accepts(text, certificate_json(c)));
      if (c.holds) {
        ++positives;
        Closure_certificate t = c;
        t.combination[0].second *= 2;  // Σ λ g becomes λ_0 g_0 ≠ 0
        EXPECT_FALSE(test::checker_accepts(text, certificate_json(t)));
        t = c;
        t.combination.pop_back();  // drop a generator: no longer sums to zero
        EXPECT_FALSE(test::checker_accepts(text, certificate_json(t)));
        t = c;
        t.combination[0].first.contact = s.contacts.size();  // out of range
        EXPECT_FALSE(test::checker_accepts(text, certificate_json(t)));
        t = c;
        t.holds = false;  // claim the opposite with the twist (0,0,0)
        t.twist = {0, 0, 0};
        EXPECT_FALSE(test::checker_accepts(text, certificate_json(t)));
      } else {
        ++negatives;
        // −t is still a certificate iff every power is zero (W ⊆ t^⊥).
        const auto gens = generators(s, reading_of(p));
        bool some_positive = false;
        for (const Generator& g : gens)
          some_positive |= c.twist[0] * g.w[0] + c.twist[1] * g.w[1] + c.twist[2] * g.w[2] > 0;
        Closure_certificate t = c;
        for (Rational& x : t.twist) x = -x;
        EXPECT_EQ(bool(test::checker_accepts(text, certificate_json(t))), !some_positive);
        t = c;
        t.holds = true;  // claim closure with no combination
        EXPECT_FALSE(test::checker_accepts(text, certificate_json(t)));
      }
    }
  }
  EXPECT_GT(positives, 20);
  EXPECT_GT(negatives, 20);
}


// ---- Thresholds: random two-finger grasps at μ* and μ* ± 10^-40 against Nguyen's test. ----
//
// Two frictional contacts with the same μ are in force closure iff d = p2 − p1 is strictly inside
// the friction cone at p1 and −d strictly inside the one at p2 (theory.md §8.5): n_i·(±d) > 0 and
// |rot90(n_i)·(±d)| < μ n_i·(±d). With both n·d conditions true, the threshold is
// μ* = max(|rot90(n1)·d| / n1·d, |rot90(n2)·d| / −n2·d): closure iff μ > μ*.
TEST(ClosureThresholds, TwoFingerGraspsAtAndAroundNguyensThreshold) {
  const std::uint64_t seed = test::seed(42);
  std::mt19937_64 rng(seed);
  auto r = [&](int lo, int hi) {
    return Rational(std::uniform_int_distribution<int>(lo, hi)(rng), std::uniform_int_distribution<int>(1, 97)(rng));
  };
  const Rational eps(Integer(1), Integer("1" + std::string(40, '0')));
  int tested = 0;
  for (int i = 0; tested < 300 && i < 5000; ++i) {
    const Rational p1x = r(-50, 50), p1y = r(-50, 50), p2x = r(-50, 50), p2y = r(-50, 50);
    const Rational dx = p2x - p1x, dy = p2y - p1y;
    const Rational n1x = r(-20, 20), n1y = r(-20, 20), n2x = r(-20, 20), n2y = r(-20, 20);
    const Rational a1 = n1x * dx + n1y * dy, a2 = -(n2x * dx + n2y * dy);  // n1·d, n2·(−d)
    if (a1 <= 0 || a2 <= 0) continue;
    const Rational t1 = -n1y * dx + n1x * dy, t2 = -(-n2y * dx + n2x * dy);  // rot90(n)·(±d)
    const Rational mu_star = std::max(abs(t1) / a1, abs(t2) / a2);
    ++tested;
    for (int k = -1; k <= 1; ++k) {
      const Rational mu = mu_star + k * eps;
      if (mu < 0) continue;
      const std::string text = scene_json({{to_string(p1x), to_string(p1y), to_string(n1x), to_string(n1y), to_string(mu)},
                                           {to_string(p2x), to_string(p2y), to_string(n2x), to_string(n2y), to_string(mu)}});
      const Closure_answer a = decide_closure(read_scene(text, Input_limits{}), Property::force_closure);
      const auto cert = test::checker_accepts(text, certificate_json(a.certificate));
      if (a.holds != (k > 0) || !cert) {
        ADD_FAILURE() << "seed " << seed << " case " << i << " mu = mu* " << (k < 0 ? "- 1e-40" : k > 0 ? "+ 1e-40" : "")
                      << ": closure " << a.holds << "\n" << cert.message() << "\nscene dumped to "
                      << test::dump_failure(text, "threshold_" + std::to_string(seed) + "_" + std::to_string(i));
        return;
      }
    }
  }
  EXPECT_EQ(tested, 300);
}


// [FC-1] The randomized construction with conflict lists against the plain reference clipping:
// same decision, same shape, and (for polygons, arcs, rays) the same cone — every extreme ray of
// one is an extreme ray of the other.
TEST(ClosureDifferential, RandomizedConstructionMatchesTheReference) {
  const std::uint64_t seed = test::seed(99);
  std::mt19937_64 rng(seed);
  for (int i = 0; i < 3000; ++i) {
    const std::string text = scene_json(test::random_contacts(rng, 12));
    const Scene s = read_scene(text, Input_limits{});
    for (Property p : {Property::force_closure, Property::form_closure}) {
      std::vector<Vec3q> ws;
      for (const Generator& g : generators(s, reading_of(p))) ws.push_back(g.w);
      const Exact_kernel k(ws);
      const Dual_cone fast = compute_dual_cone_randomized(k), ref = compute_dual_cone_reference(k);
      bool same = fast.shape == ref.shape && fast.rank == ref.rank;
      if (same && (fast.shape == Dual_shape::polygon || fast.shape == Dual_shape::arc)) {
        // Same set of extreme rays: each ray of one is a positive multiple of a ray of the other.
        auto rays = [&](const Dual_cone& d) {
          std::vector<std::array<Integer, 3>> out;
          for (std::size_t j = 0; j < d.edges.size(); ++j) {
            const Vec3q& a = ws[d.edges[j]];
            const Vec3q& b = ws[d.edges[(j + 1) % d.edges.size()]];
            out.push_back(primitive(cross(a, b)));
          }
          std::sort(out.begin(), out.end());
          out.erase(std::unique(out.begin(), out.end()), out.end());
          return out;
        };
        same = rays(fast) == rays(ref);
      }
      if (!same) {
        ADD_FAILURE() << "seed " << seed << " case " << i << " " << property_name(p) << ": shapes "
                      << int(fast.shape) << " vs " << int(ref.shape) << "; scene dumped to "
                      << test::dump_failure(text, "randomized_" + std::to_string(seed) + "_" + std::to_string(i));
        return;
      }
    }
  }
}


// Above kSmallDualCone generators decide_closure uses the randomized construction: its verdicts
// (against the reference clipping) and its certificates (through the checker), in every mode.
TEST(ClosureDifferential, LargeScenesUseTheRandomizedPathWithValidCertificates) {
  const std::uint64_t seed = test::seed(1234);
  std::mt19937_64 rng(seed);
  int large = 0;
  for (int i = 0; i < 150; ++i) {
    const std::string text = scene_json(test::random_contacts(rng, 70));
    const Scene s = read_scene(text, Input_limits{});
    for (Property p : {Property::force_closure, Property::form_closure}) {
      std::vector<Vec3q> ws;
      for (const Generator& g : generators(s, reading_of(p))) ws.push_back(g.w);
      large += ws.size() > kSmallDualCone;
      const bool ref = compute_dual_cone_reference(Exact_kernel(ws)).force_closure();
      for (Mode m : {Mode::exact, Mode::hybrid}) {
        const Closure_answer a = decide_closure(s, p, m);
        const auto cert = test::checker_accepts(text, certificate_json(a.certificate));
        if (a.holds != ref || !cert) {
          ADD_FAILURE() << "seed " << seed << " case " << i << " " << property_name(p) << " " << mode_name(m)
                        << ": " << a.holds << " vs reference " << ref << "\n" << cert.message() << "\nscene dumped to "
                        << test::dump_failure(text, "large_" + std::to_string(seed) + "_" + std::to_string(i));
          return;
        }
      }
    }
  }
  EXPECT_GT(large, 100);
}


// Lazily read scenes (batch) give the same answers and valid certificates in every mode.
TEST(ClosureDifferential, LazySceneReadingGivesTheSameAnswers) {
  std::mt19937_64 rng(test::seed(4242));
  for (int i = 0; i < 500; ++i) {
    const std::string text = scene_json(test::random_contacts(rng, 8));
    const Scene eager = read_scene(text, Input_limits{});
    const Scene lazy = read_scene(text, Input_limits{}, "scene", true);
    for (Property p : {Property::force_closure, Property::form_closure})
      for (Mode m : {Mode::exact, Mode::hybrid, Mode::float_only}) {
        const Closure_answer a = decide_closure(eager, p, m), b = decide_closure(lazy, p, m);
        ASSERT_EQ(a.decided, b.decided) << text;
        if (!a.decided) continue;
        ASSERT_EQ(a.holds, b.holds) << text;
        ASSERT_EQ(a.rank, b.rank) << text;
        ASSERT_TRUE(test::checker_accepts(text, certificate_json(b.certificate)));
      }
  }
}

}  // namespace
}  // namespace wrenchkit
