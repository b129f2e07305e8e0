// [QL-2] The critical friction coefficient μ*: golden cases worked by hand (two fingers: the tangent of the contact
// line's angle; the ladder's 1/7 of theory.md §9 for its equilibrium and 4/3 for its closure; grasps no friction
// closes; a load only an infinite μ balances; form closure: "always"), and on random grasps the theorem's own
// statement: the property fails at μ* (closure) or just below it (balance) and holds just above it (closure) or at it
// (balance), μ*·(1 ± 10⁻⁹); brackets fail at their lower end and hold at their upper end; every certificate accepted
// by the independent checker.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "exact/certificates/certificates.h"
#include "exact/io/scene.h"
#include "exact/statics/critical_mu.h"
#include "proofs/checker/checker.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {
using namespace test;

Scene scene_of(const std::string& text) { return read_scene(text, Input_limits{}); }
const Rational kTol(1, 1000000000000ul);

std::string rejected(const std::string& scene, const std::string& cert) {
  const wrenchkit_checker::Result r = wrenchkit_checker::check(scene, cert, wrenchkit_checker::Limits{});
  return r.outcome == wrenchkit_checker::Outcome::accepted ? "" : r.message + "\n" + cert;
}
bool closed(const Scene& s, const Rational& mu) {
  return decide_closure(at_common_mu(s, mu), Property::force_closure, Mode::exact, false).holds;
}
bool balanced(const Scene& s, const Rational& mu) { return decide_equilibrium(at_common_mu(s, mu), Mode::exact, false).balanced; }

Critical_answer answer(const std::string& text) { return decide_critical_mu(scene_of(text), Mode::hybrid, kTol); }

TEST(CriticalMuGolden, TwoFingersTangentOfTheContactLine) {
  // the contact line from (-1, 0) to (1, 1) makes tan = 1/2 with both normals
  const char* t = R"({"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0]}, {"at": [1, 1], "normal": [-1, 0]}]})";
  const Critical_answer a = answer(t);
  EXPECT_TRUE(a.closure.exact());
  EXPECT_EQ(a.closure.lower, Rational(1, 2));
  EXPECT_FALSE(a.equilibrium);
  EXPECT_EQ(rejected(t, critical_mu_certificate(a.closure, true)), "");
  // different angles: the larger tangent (3/4 at one finger, 1/3 at the other... here 4/3 and 3/4)
  const char* l = R"({"wrenchkit": 1, "body": {"com": ["-1/2", "7/2"]},
    "contacts": [{"at": [0, 0], "normal": [0, 1]}, {"at": [-4, 3], "normal": [1, 0]}], "load": {"gravity": 1}})";
  const Critical_answer b = answer(l);
  EXPECT_EQ(b.closure.lower, Rational(4, 3));
  EXPECT_TRUE(b.closure.exact());
  ASSERT_TRUE(b.equilibrium);  // theory.md §9: the ladder stands iff mu >= 1/7
  EXPECT_TRUE(b.equilibrium->exact());
  EXPECT_EQ(b.equilibrium->lower, Rational(1, 7));
  EXPECT_EQ(rejected(l, critical_mu_certificate(b.closure, true)), "");
  EXPECT_EQ(rejected(l, critical_mu_certificate(*b.equilibrium, false)), "");
}

// Closure's "constant" is the chirotope's (QL-2 §2): the 3×3 minors keep their signs on (μ*, above], while a smaller
// minor may change sign there. Contact 0 at (-4, -3) with normal (-5, 4): a = (-5, 4, -31), b = W(p, (-4, -5)) =
// (-4, -5, 8), so its left edge's moment -31 + 8μ vanishes at 31/8, inside the certified (7/2, above]. Every minor
// constant would not hold there: the checker accepts the engine's interval by the 3×3 minors alone.
TEST(CriticalMuGolden, ClosureIsConstantWhereTheChirotopeIs) {
  const char* t = R"({"wrenchkit": 1, "contacts": [{"at": [-4, -3], "normal": [-5, 4]}, {"at": [-2, 4], "normal": [-4, 0]},
    {"at": [-4, -3], "normal": [-2, 4]}]})";
  const Critical_answer a = answer(t);
  ASSERT_TRUE(a.closure.exact());
  EXPECT_EQ(a.closure.lower, Rational(7) / 2);
  EXPECT_FALSE(closed(scene_of(t), Rational(7) / 2));
  EXPECT_TRUE(closed(scene_of(t), Rational(7) / 2 + Rational(1) / 1000000000));
  ASSERT_TRUE(a.closure.constant && a.closure.above_mu);
  EXPECT_GE(*a.closure.above_mu, Rational(31) / 8);  // (the smaller minor's root is inside the interval)
  EXPECT_EQ(rejected(t, critical_mu_certificate(a.closure, true)), "");
}

TEST(CriticalMuGolden, CollinearFingersNeedAnyFriction) {
  const char* t = R"({"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0]}, {"at": [1, 0], "normal": [-1, 0]}]})";
  const Critical_answer a = answer(t);
  EXPECT_TRUE(a.closure.exact());
  EXPECT_EQ(a.closure.lower, 0);
  EXPECT_EQ(rejected(t, critical_mu_certificate(a.closure, true)), "");
}

TEST(CriticalMuGolden, NeverAndAlways) {
  // both fingers push +x: no friction closes the grasp, nor balances a push along +x
  const char* t = R"({"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0]}, {"at": [1, 1], "normal": [1, 0]}],
                     "load": {"force": [1, 0], "at": [0, 0]}})";
  const Critical_answer a = answer(t);
  EXPECT_EQ(a.closure.kind, Critical_kind::never);
  EXPECT_EQ(a.equilibrium->kind, Critical_kind::never);
  EXPECT_TRUE(a.closure.limit_twist);
  EXPECT_EQ(rejected(t, critical_mu_certificate(a.closure, true)), "");
  EXPECT_EQ(rejected(t, critical_mu_certificate(*a.equilibrium, false)), "");
  // a sideways push on one contact: balanced only in the limit of infinite friction
  const char* s = R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [0, 1]}], "load": {"force": [1, 0], "at": [0, 0]}})";
  const Critical_answer b = answer(s);
  EXPECT_EQ(b.equilibrium->kind, Critical_kind::never);
  EXPECT_TRUE(b.equilibrium->constant_beyond);
  EXPECT_EQ(rejected(s, critical_mu_certificate(*b.equilibrium, false)), "");
  // form closure (square_crossed_couples): closed without friction
  const std::string f = read_text(source_dir() + "/tests/golden/square_crossed_couples.scene.json");
  const Critical_answer c = answer(f);
  EXPECT_EQ(c.closure.kind, Critical_kind::always);
  EXPECT_EQ(rejected(f, critical_mu_certificate(c.closure, true)), "");
}

// The friction margin: μ = 1 and 3/4 on the offset fingers (each needs 1/2): closed for every factor above 2/3 on
// the scene's own μ; the larger one has room to spare, the smaller one sets it.
TEST(CriticalMuGolden, FrictionMargin) {
  const char* t = R"({"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0], "mu": 1}, {"at": [1, 1], "normal": [-1, 0], "mu": "3/4"}]})";
  const Critical_answer a = answer(t);
  ASSERT_TRUE(a.margin);
  EXPECT_EQ(a.margin->scaling, Friction_scaling::proportional);
  EXPECT_TRUE(a.margin->exact());
  EXPECT_EQ(a.margin->lower, Rational(2, 3));
  EXPECT_EQ(rejected(t, critical_mu_certificate(*a.margin, true)), "");
  const Scene s = scene_of(t);
  EXPECT_FALSE(decide_closure(at_mu(s, Rational(2, 3), Friction_scaling::proportional), Property::force_closure, Mode::exact, false).holds);
  EXPECT_TRUE(decide_closure(at_mu(s, Rational(2, 3) + Rational(1, 1000000), Friction_scaling::proportional), Property::force_closure,
                             Mode::exact, false).holds);
  // every contact with the same μ0: the margin is the common μ* over μ0 (here μ0 = 1: both 1/2)
  const char* same = R"({"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0], "mu": 1}, {"at": [1, 1], "normal": [-1, 0], "mu": 1}]})";
  const Critical_answer b = answer(same);
  ASSERT_TRUE(b.margin);
  EXPECT_EQ(b.margin->lower, b.closure.lower);
  EXPECT_EQ(b.margin->lower, Rational(1, 2));
  // frictionless contacts only: no margin to give
  EXPECT_FALSE(answer(R"({"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0]}, {"at": [1, 1], "normal": [-1, 0]}]})").margin);
}

// A pure moment on the offset fingers: at mu = 1/2 their edges lie on one line (the cone holds it) and the moment is
// not balanced; above 1/2 the grasp is closed. mu* = 1/2, balanced only above it.
TEST(CriticalMuGolden, BalancedOnlyAboveTheCritical) {
  const char* t = R"({"wrenchkit": 1, "contacts": [{"at": [-1, 0], "normal": [1, 0]}, {"at": [1, 1], "normal": [-1, 0]}],
                     "load": {"wrench": [0, 0, 1]}})";
  const Critical_answer a = answer(t);
  ASSERT_TRUE(a.equilibrium);
  EXPECT_TRUE(a.equilibrium->exact());
  EXPECT_EQ(a.equilibrium->lower, Rational(1, 2));
  EXPECT_FALSE(a.equilibrium->holds_at_critical);
  EXPECT_FALSE(balanced(scene_of(t), Rational(1, 2)));
  EXPECT_EQ(rejected(t, critical_mu_certificate(*a.equilibrium, false)), "");
}

// 2–4 contacts at small integer points pressing roughly inward; each with a μ drawn from `mus` when given.
std::string random_contacts_text(std::mt19937_64& rng, const std::vector<const char*>& mus) {
  std::string text = R"({"wrenchkit": 1, "contacts": [)";
  const int n = 2 + static_cast<int>(rng() % 3);
  for (int i = 0; i < n; ++i) {
    int x = 0, y = 0;
    while (x == 0 && y == 0) x = static_cast<int>(rng() % 7) - 3, y = static_cast<int>(rng() % 7) - 3;
    int nx = -x + static_cast<int>(rng() % 5) - 2, ny = -y + static_cast<int>(rng() % 5) - 2;
    if (nx == 0 && ny == 0) nx = 1;
    text += (i ? ", " : "") + std::string("{\"at\": [") + std::to_string(x) + ", " + std::to_string(y) + "], \"normal\": [" +
            std::to_string(nx) + ", " + std::to_string(ny) + "]" +
            (mus.empty() ? std::string() : std::string(", \"mu\": \"") + mus[rng() % mus.size()] + "\"") + "}";
  }
  return text + "]";
}

// Random grasps (2–4 contacts pressing roughly inward, a load now and then): the theorem's own statement at μ* and
// 10⁻⁹ beside it, and the checker.
TEST(CriticalMuProperty, RandomGraspsMeetTheirThreshold) {
  std::mt19937_64 rng(seed(20261129));
  int values = 0, exact = 0, brackets = 0;
  for (int trial = 0; trial < 80; ++trial) {
    std::string text = random_contacts_text(rng, {});
    if (trial % 2) text += R"(, "load": {"force": [)" + std::to_string(static_cast<int>(rng() % 5) - 2) + ", -3], \"at\": [" +
                           std::to_string(static_cast<int>(rng() % 3) - 1) + ", 0]}";
    text += "}";
    const Scene s = scene_of(text);
    const Critical_answer a = decide_critical_mu(s, Mode::hybrid, kTol);
    ASSERT_EQ(rejected(text, critical_mu_certificate(a.closure, true)), "") << dump_failure(text, "critical_mu");
    ASSERT_TRUE(a.margin.has_value() == false);  // (these contacts have no μ of their own: no margin)
    const Rational step(1, 1000000000);
    if (a.closure.kind == Critical_kind::value) {
      ++values;
      const Critical_mu& c = a.closure;
      ASSERT_FALSE(closed(s, c.lower)) << dump_failure(text, "critical_mu");
      ASSERT_TRUE(closed(s, c.upper * (1 + step) + step)) << dump_failure(text, "critical_mu");
      if (c.exact()) {
        ++exact;
        ASSERT_TRUE(closed(s, c.upper + step * step)) << dump_failure(text, "critical_mu");
        if (c.lower > 0) {
          ASSERT_FALSE(closed(s, c.lower * (1 - step))) << dump_failure(text, "critical_mu");
        }
      } else {
        ++brackets;
        ASSERT_TRUE(closed(s, c.upper)) << dump_failure(text, "critical_mu");
        ASSERT_LE(c.upper - c.lower, kTol * c.upper + kTol) << dump_failure(text, "critical_mu");
      }
    } else if (a.closure.kind == Critical_kind::always) {
      ASSERT_TRUE(closed(s, 0));
    } else {
      ASSERT_FALSE(closed(s, 1000000));
    }
    if (!a.equilibrium) continue;
    const Critical_mu& e = *a.equilibrium;
    ASSERT_EQ(rejected(text, critical_mu_certificate(e, false)), "") << dump_failure(text, "critical_mu");
    if (e.kind == Critical_kind::value) {
      ASSERT_EQ(balanced(s, e.upper), !e.exact() || e.holds_at_critical) << dump_failure(text, "critical_mu");
      ASSERT_TRUE(balanced(s, e.upper * (1 + step) + step)) << dump_failure(text, "critical_mu");
      ASSERT_FALSE(balanced(s, e.lower * (1 - step))) << dump_failure(text, "critical_mu");
      if (!e.exact()) {
        ASSERT_FALSE(balanced(s, e.lower)) << dump_failure(text, "critical_mu");
      }
    } else if (e.kind == Critical_kind::always) {
      ASSERT_TRUE(balanced(s, 0));
    } else {
      ASSERT_FALSE(balanced(s, 1000000));
    }
  }
  EXPECT_GT(values, 20);
  EXPECT_GT(exact, 5);
  RecordProperty("brackets", brackets);
}

// Grasps read from doubles (17 significant digits, as the array API and float tools give them): μ* is irrational or of
// great height, bracketed by one minor's sign between the roots' hints — the theorem's statement at the bracket's ends
// (fails at lower, holds at upper), its width, the checker; and the search's cost: one exact decision per halving of
// the gaps between the hints and a few to prove the ends, not one per bit (it took 261 before the hints).
TEST(CriticalMuProperty, DoubleGraspsBracketedFromTheHints) {
  std::mt19937_64 rng(seed(20261201));
  std::uniform_real_distribution<double> u(-1, 1);
  int brackets = 0;
  for (int trial = 0; trial < 30; ++trial) {
    std::string text = R"({"wrenchkit": 1, "mu": "1/2", "contacts": [)";
    const int n = 3 + static_cast<int>(rng() % 3);
    char b[256];
    for (int i = 0; i < n; ++i) {
      const double x = u(rng), y = u(rng);
      std::snprintf(b, sizeof b, R"(%s{"at": ["%.17g", "%.17g"], "normal": ["%.17g", "%.17g"]})", i ? ", " : "", x, y,
                    -x + 0.4 * u(rng), -y + 0.4 * u(rng));
      text += b;
    }
    text += "]}";
    const Scene s = scene_of(text);
    const Critical_answer a = decide_critical_mu(s, Mode::hybrid, kTol);
    ASSERT_EQ(rejected(text, critical_mu_certificate(a.closure, true)), "") << dump_failure(text, "critical_mu_doubles");
    const Critical_mu& c = a.closure;
    if (c.kind != Critical_kind::value || c.exact()) continue;
    ++brackets;
    ASSERT_FALSE(closed(s, c.lower)) << dump_failure(text, "critical_mu_doubles");
    ASSERT_TRUE(closed(s, c.upper)) << dump_failure(text, "critical_mu_doubles");
    ASSERT_LE(c.upper - c.lower, kTol * c.upper + kTol) << dump_failure(text, "critical_mu_doubles");
    EXPECT_LE(c.decisions, 24u) << dump_failure(text, "critical_mu_doubles");
  }
  EXPECT_GT(brackets, 10);
}

// The margin on random grasps with their own μ: fails at t* (or below the bracket), holds just above, and the checker.
TEST(CriticalMuProperty, RandomMarginsMeetTheirThreshold) {
  std::mt19937_64 rng(seed(20261201));
  int values = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const std::string text = random_contacts_text(rng, {"1/4", "1/2", "3/4", "1", "2", "1/3"}) + "}";
    const Scene s = scene_of(text);
    const Critical_answer a = decide_critical_mu(s, Mode::hybrid, kTol);
    ASSERT_TRUE(a.margin) << dump_failure(text, "margin");
    const Critical_mu& m = *a.margin;
    ASSERT_EQ(rejected(text, critical_mu_certificate(m, true)), "") << dump_failure(text, "margin");
    const auto closed_at = [&](const Rational& t) {
      return decide_closure(at_mu(s, t, Friction_scaling::proportional), Property::force_closure, Mode::exact, false).holds;
    };
    const Rational step(1, 1000000000);
    if (m.kind != Critical_kind::value) continue;
    ++values;
    ASSERT_FALSE(closed_at(m.lower)) << dump_failure(text, "margin");
    ASSERT_TRUE(closed_at(m.upper * (1 + step) + step)) << dump_failure(text, "margin");
  }
  EXPECT_GT(values, 20);
}

}  // namespace
}  // namespace wrenchkit
