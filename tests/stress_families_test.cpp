// [ST-1] The scene families of the stress report (testing/stress_families.h, fuzz/families.h): every family
// is deterministic, lands on its stated side of the threshold, honours ε exactly where the scene is exact
// by construction, and its exact symmetries (rotation, translation, scaling) keep the answer. The stress
// tool's own failure path (a wrong certified answer ⇒ exit 1) is proven by the CTest stress_report_fault.
#include <gtest/gtest.h>

#include "exact/sliding/pushing.h"

#include "exact/pipeline/answer_json.h"
#include "exact/pipeline/hold_answer.h"
#include "exact/pipeline/labels_answer.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

#include "exact/pipeline/support_answer.h"
#include "exact/statics/closure.h"
#include "exact/statics/equilibrium.h"
#include "exact/statics/generators.h"
#include "exact/statics/moment_labels.h"
#include "exact/io/to_float.h"
#include "testing/stress_families.h"
#include "fuzz/families.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

std::vector<stress::Family> every_family() {
  std::vector<stress::Family> f = stress::families();
  for (const stress::Family& x : stress::report_only_families()) f.push_back(x);
  return f;
}

bool is(const stress::Family& f, std::initializer_list<const char*> names) {
  for (const char* n : names)
    if (std::string(f.name) == n) return true;
  return false;
}

Scene scene_of(const std::string& text) { return read_scene(text, Input_limits{}); }

bool closure(const std::string& text, Property p = Property::force_closure) {
  return decide_closure(scene_of(text), p, Mode::exact, false).holds;
}

bool brute_closure(const std::string& text, Reading r = Reading::friction) {
  std::vector<Vec3q> w;
  for (const Generator& g : generators(scene_of(text), r)) w.push_back(g.w);
  return test::brute_force_closure(w);
}

TEST(StressFamilies, EveryFamilyIsDeterministicAndReadable) {
  for (const stress::Family& f : every_family()) {
    if (is(f, {"many_contacts"})) continue;  // below, with fewer scenes (each holds up to 10^4 contacts)
    std::set<std::string> texts;
    for (std::uint64_t seed : {1, 2, 42}) {
      const auto a = stress::make_scene(f.name, 1e-10, seed), b = stress::make_scene(f.name, 1e-10, seed);
      EXPECT_EQ(a.text, b.text) << f.name;
      EXPECT_EQ(a.untransformed, b.untransformed) << f.name;
      EXPECT_EQ(a.load_text, b.load_text) << f.name;
      EXPECT_EQ(a.above, b.above) << f.name;
      EXPECT_EQ(a.known, f.known) << f.name;
      EXPECT_NO_THROW(scene_of(a.text)) << f.name << "\n" << a.text;
      if (!a.untransformed.empty()) {
        EXPECT_NO_THROW(scene_of(a.untransformed)) << f.name;
      }
      texts.insert(a.text);
    }
    if (!is(f, {"ladder_equilibrium"})) {  // the ladder is one scene per side
      EXPECT_EQ(texts.size(), 3u) << f.name << ": different seeds, different scenes";
    }
    // A running generator: the same stream gives the same scenes.
    stress::Rng r1(7), r2(7);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(stress::make_scene(f, 1e-3, r1).text, stress::make_scene(f, 1e-3, r2).text);
  }
  const auto a = stress::make_scene("many_contacts", 1e-10, 3), b = stress::make_scene("many_contacts", 1e-10, 3);
  EXPECT_EQ(a.text, b.text);
  const Scene s = scene_of(a.text);
  EXPECT_GE(s.contacts.size(), 1000u);
  EXPECT_LE(s.contacts.size(), 10000u);
}

TEST(StressFamilies, CorpusAndReportLists) {
  // The corpus keeps its first eight families in place (their seeds depend on the position); the
  // report-only families are not in the corpus; the benchmark's six are unchanged.
  const char* first[] = {"friction_threshold", "cone_edge",          "nearly_concurrent", "nearly_parallel",
                         "huge_offset",        "ladder_equilibrium", "random_generic",    "random_grid"};
  for (std::size_t i = 0; i < 8; ++i) EXPECT_STREQ(stress::families()[i].name, first[i]);
  for (const stress::Family& f : stress::report_only_families())
    for (const stress::Family& g : stress::families()) EXPECT_STRNE(f.name, g.name);
  ASSERT_EQ(families::all().size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_STREQ(families::all()[i].name, first[i]);
  std::size_t with_eps = 0;
  for (const stress::Family& f : every_family()) with_eps += f.uses_epsilon;
  EXPECT_EQ(families::report().size(), with_eps);
  EXPECT_NE(stress::find_family("collinear_support"), nullptr);
  EXPECT_THROW(stress::make_scene("collinear_support", 0, 1), std::invalid_argument);
}

// fixture_pin (hold): holds iff below, for every ε, through the pipeline (certificates checked) in hybrid and exact.
TEST(StressFamilies, FixturePinHoldsIffBelow) {
  std::set<bool> sides;
  for (double eps : {1e-2, 1e-13, 1e-40})
    for (int seed = 1; seed <= 6; ++seed) {
      const auto s = stress::make_scene("fixture_pin", eps, static_cast<std::uint64_t>(seed));
      ASSERT_TRUE(s.known);
      sides.insert(s.above);
      for (const Mode m : {Mode::hybrid, Mode::exact}) {
        Request r;
        r.mode = m;
        const Hold_item h = answer_hold(s.text, "fixture_pin", r);
        ASSERT_EQ(h.status, Status::answered) << h.message << "\n" << s.text;
        EXPECT_EQ(h.answer.verdict, s.above ? Hold_verdict::fails : Hold_verdict::holds)
            << eps << " " << mode_name(m) << " " << h.answer.undecided_why << "\n" << s.text;
      }
    }
  EXPECT_EQ(sides.size(), 2u);
}

// region_legs (regions with legs whose force is not given, RG-3): every admissible distribution has the same
// translation boundary load, so the answer is sticks for every one below and slides for every one above —
// through the pipeline (format-2 certificates, checked there and here) in hybrid and exact; and each extreme
// distribution alone (the known-forces region decision) lands on the same side, as the construction says.
TEST(StressFamilies, RegionLegsStickOrSlideForEveryDistributionBySide) {
  std::set<bool> sides;
  for (double eps : {1e-2, 1e-6})
    for (int seed = 1; seed <= 6; ++seed) {
      const auto s = stress::make_scene("region_legs", eps, static_cast<std::uint64_t>(seed));
      ASSERT_TRUE(s.known);
      sides.insert(s.above);
      const families::Case k = families::make_case(*families::find("region_legs"), eps, static_cast<std::uint64_t>(seed));
      ASSERT_EQ(k.text, s.text);
      Support_query q;
      q.question = Support_question::limit_surface;
      q.load = k.motion_load;
      q.polytopes = false;
      for (const Mode m : {Mode::hybrid, Mode::exact}) {
        Request r;
        r.mode = m;
        const Support_item item = answer_support(s.text, "region_legs", r, q);
        ASSERT_EQ(item.status, Status::answered) << item.message << test::dump_failure(s.text, "region_legs");
        ASSERT_TRUE(item.motion.has_value());
        EXPECT_EQ(item.motion->motion, s.above ? Motion::slides : Motion::sticks)
            << eps << " " << mode_name(m) << " " << item.motion->undecided_why << test::dump_failure(s.text, "region_legs");
        EXPECT_TRUE(test::checker_accepts(s.text, item.certificate)) << test::dump_failure(s.text, "region_legs");
        for (const Motion v : item.motion->per_vertex)
          EXPECT_EQ(v, s.above ? Motion::slides : Motion::sticks) << test::dump_failure(s.text, "region_legs");
      }
    }
  EXPECT_EQ(sides.size(), 2u);
}

// The exact families: the answer is the side for EVERY ε, through the dual cone and through the O(k³)
// brute force (which shares no code with it).
TEST(StressFamilies, KnownFamiliesLandOnTheirSideForEveryEpsilon) {
  for (const stress::Family& f : every_family()) {
    if (!f.known || f.question == stress::Question::stick_slide || f.question == stress::Question::stick_slide_over ||
        f.question == stress::Question::hold || f.question == stress::Question::stick_slide_region)
      continue;
    const bool large = is(f, {"many_contacts"});
    std::set<bool> sides;
    for (double eps : {1e-2, 1e-13, 1e-17, 1e-40})
      for (int seed = 1; seed <= (large ? 4 : 12); ++seed) {
        if (large && (eps == 1e-13 || eps == 1e-17)) continue;
        const auto s = stress::make_scene(f.name, eps, static_cast<std::uint64_t>(seed));
        ASSERT_TRUE(s.known);
        sides.insert(s.above);
        if (f.question == stress::Question::equilibrium) {
          EXPECT_EQ(decide_equilibrium(scene_of(s.text)).balanced, s.above) << f.name << " " << eps << "\n" << s.text;
          continue;
        }
        if (f.question == stress::Question::push_contact) {  // slides left iff above, else sticks (PU-2 §5)
          const Scene sc = scene_of(s.text);
          const Push_contact c = push_contact_mode(Support_model(sc), *sc.pusher, Rational(1, 1000000000000));
          EXPECT_EQ(c.mode, s.above ? Push_mode::slides_left : Push_mode::sticks) << f.name << " " << eps << "\n" << s.text;
          continue;
        }
        if (f.question == stress::Question::push_stable) {  // stable iff below (PU-3 §8: the load is v through c)
          const Scene sc = scene_of(s.text);
          const Stable_push st = decide_stable_push(Support_model(sc), *sc.pusher);
          EXPECT_EQ(st.verdict, s.above ? Stability::unstable : Stability::stable) << f.name << " " << eps << "\n" << s.text;
          if (s.above) {
            EXPECT_EQ(st.facet, Cone_facet::left_edge) << f.name << " " << eps << "\n" << s.text;
          }
          continue;
        }
        if (f.question == stress::Question::push) {  // ccw iff above, by the velocity's vote (PU-1)
          const Scene sc = scene_of(s.text);
          const Rotation r = decide_push(Support_model(sc), *sc.pusher).rotation;
          EXPECT_EQ(r, s.above ? Rotation::ccw : Rotation::cw) << f.name << " " << eps << "\n" << s.text;
          continue;
        }
        EXPECT_EQ(closure(s.text), s.above) << f.name << " " << eps << "\n" << s.text;
        if (!is(f, {"many_contacts"})) {
          EXPECT_EQ(brute_closure(s.text), s.above) << f.name << " " << eps << "\n" << s.text;
        }
      }
    EXPECT_EQ(sides.size(), 2u) << f.name << ": both sides occur";
  }
}

// The nominal families print doubles (17 digits), so ε holds only up to rounding: at ε = 10^-6 the
// verdict must follow the side (cone_edge: the segment ε outside the cone above, so closure iff below;
// nearly_parallel never closes: its verdict does not flip).
TEST(StressFamilies, NominalFamiliesFollowTheirSideWhereEpsilonSurvivesRounding) {
  for (const stress::Family& f : stress::families()) {
    if (f.known || !f.uses_epsilon) continue;
    std::set<bool> verdicts;
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
      const auto s = stress::make_scene(f.name, 1e-6, seed);
      const Property p =
          f.question == stress::Question::form_closure ? Property::form_closure : Property::force_closure;
      const bool holds = closure(s.text, p);
      verdicts.insert(holds);
      if (is(f, {"nearly_parallel"})) {
        EXPECT_FALSE(holds) << s.text;
      } else {
        EXPECT_EQ(holds, is(f, {"cone_edge"}) ? !s.above : s.above) << f.name << "\n" << s.text;
      }
    }
    EXPECT_EQ(verdicts.size(), is(f, {"nearly_parallel"}) ? 1u : 2u) << f.name;
  }
}

// ε exactly: the two-finger exact families write μ = μ*·(10^k ± 1)/10^k where μ* = |d × n|/(d·n) is the
// tangent of the angle between the segment AB and A's inward normal, whatever the rotation and scale.
TEST(StressFamilies, ExactTwoFingerFamiliesWriteMuAtExactlyTenToMinusKFromTheThreshold) {
  for (const char* name : {"long_rational", "rational_rotation", "huge_scale", "tiny_scale", "beyond_double"})
    for (int k : {2, 13, 40})
      for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        const auto s = stress::make_scene(name, std::pow(10.0, -k), seed);
        const Scene sc = scene_of(s.text);
        ASSERT_EQ(sc.contacts.size(), 2u);
        const Contact &a = sc.contacts[0], &b = sc.contacts[1];
        const Rational dx = b.at.x - a.at.x, dy = b.at.y - a.at.y;
        const Rational cross = abs(Rational(dx * a.normal.y - dy * a.normal.x)),
                       dot = dx * a.normal.x + dy * a.normal.y;
        ASSERT_GT(dot, 0) << s.text;
        const Rational mu_star = cross / dot;
        Integer p;
        mpz_ui_pow_ui(p.get_mpz_t(), 10, static_cast<unsigned long>(k));
        EXPECT_EQ(a.mu, b.mu);
        EXPECT_EQ(a.mu, mu_star * Rational(p + (s.above ? 1 : -1), p)) << name << " k=" << k << "\n" << s.text;
      }
}

TEST(StressFamilies, UntransformedSceneIsAnExactSymmetry) {
  for (const char* name : {"rational_rotation", "huge_scale", "tiny_scale", "beyond_double"})
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      const auto s = stress::make_scene(name, 1e-30, seed);
      ASSERT_FALSE(s.untransformed.empty()) << name;
      EXPECT_NE(s.untransformed, s.text);
      EXPECT_EQ(closure(s.untransformed), closure(s.text)) << name << "\n" << s.text;
      EXPECT_EQ(closure(s.untransformed), s.above);
    }
  // The scale families really leave (or keep to) the double range.
  const auto huge = scene_of(stress::make_scene("huge_scale", 1e-3, 5).text);
  EXPECT_GT(abs(huge.contacts[0].at.x), Rational(Integer("1" + std::string(250, '0'))));
  EXPECT_TRUE(std::isfinite(huge.contacts[0].at.x.get_d()));
  int beyond = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed)
    for (const stress::Contact_spec& c : stress::make_scene("beyond_double", 1e-3, seed).contacts)
      beyond += (std::isinf(c.ax) || c.ax == 0) && (std::isinf(c.ay) || c.ay == 0);
  EXPECT_EQ(beyond, 16) << "every beyond_double coordinate is ±inf or 0 as a double";
}

TEST(StressFamilies, NaiveDoubleReadsAsNaiveCodeDoes) {
  EXPECT_EQ(stress::naive_double("0.25"), 0.25);
  EXPECT_EQ(stress::naive_double("\"1/3\""), 1.0 / 3.0);
  EXPECT_EQ(stress::naive_double("-2/8"), -0.25);
  EXPECT_TRUE(std::isinf(stress::naive_double("1e400")));
  EXPECT_EQ(stress::naive_double("1e-400"), 0.0);
}

// The stick/slide family: far enough from the limit surface every certified route decides the side
// (hybrid: the search; exact: the polygons with N = 32, 1/λ − 1 ≈ 4.8e-3); the naive search too.
TEST(StressFamilies, CollinearSupportSticksBelowAndSlidesAbove) {
  const families::Family& f = *families::find("collinear_support");
  std::set<bool> sides;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const families::Case c = families::make_case(f, 1e-2, seed);
    ASSERT_TRUE(c.known);
    EXPECT_EQ(c.expected, c.above);
    sides.insert(c.above);
    const Scene s = scene_of(c.text);
    const families::Verdict h = families::decide_motion(c, s, Mode::hybrid, 16);
    EXPECT_TRUE(h.decided) << c.text;
    EXPECT_EQ(h.holds, c.above) << c.text;
    const families::Verdict e = families::decide_motion(c, s, Mode::exact, 32);
    EXPECT_TRUE(e.decided) << c.text;
    EXPECT_EQ(e.holds, c.above) << c.text;
    EXPECT_EQ(families::naive_slides(c), c.above) << c.text;
  }
  EXPECT_EQ(sides.size(), 2u);
  // The points are ε off a line: at ε = 10^-12 every point is within 10^-11 of the line through the
  // first two (relative to their distance).
  const auto sc = stress::make_scene("collinear_support", 1e-12, 3);
  ASSERT_GE(sc.support.size(), 3u);
  const auto& p = sc.support;
  const double ux = p[1].x - p[0].x, uy = p[1].y - p[0].y, len = std::sqrt(ux * ux + uy * uy);
  for (const auto& q : p) EXPECT_LT(std::fabs(((q.x - p[0].x) * uy - (q.y - p[0].y) * ux) / len), 1e-10);
}

TEST(StressFamilies, MeasurementLayerTruth) {
  // Known families: the truth is the side; nominal ones: the exact engine's verdict.
  const families::Case k = families::make_case(*families::find("long_rational"), 1e-40, 9);
  EXPECT_TRUE(k.known);
  EXPECT_EQ(k.expected, k.above);
  EXPECT_EQ(k.contacts.size(), 2u);
  const families::Case n = families::make_case(*families::find("cone_edge"), 1e-40, 9);
  EXPECT_FALSE(n.known);
  EXPECT_EQ(n.expected, closure(n.text));
  // The naive reading of a long fraction is strtod(p)/strtod(q) of its text.
  EXPECT_TRUE(std::isfinite(k.contacts[0].mu));
  EXPECT_NEAR(k.contacts[0].mu, scene_of(k.text).contacts[0].mu.get_d(), 1e-15 * std::fabs(k.contacts[0].mu));
}


// The distribution unknown, loads 10^-3 relative from the thresholds (random supports of 4–8 points, the table,
// the dinner plate; testing/stress_families.h "unknown_support"): in hybrid, every answer is one the construction
// leaves possible, comes with a certificate the independent checker accepts (in the pipeline: a rejection is
// Status::check_failed), and at most 1 % are undecided. The construction's two sides and all three answers occur.
TEST(StressFamilies, UnknownSupportNearTheThresholds) {
  const stress::Family* f = stress::find_family("unknown_support");
  ASSERT_NE(f, nullptr);
  const int n = 400;
  int undecided = 0;
  std::set<std::string> answers;
  for (int seed = 1; seed <= n; ++seed) {
    const stress::Family_scene s = stress::make_scene(f->name, 1e-3, static_cast<std::uint64_t>(seed));
    const families::Case c = families::make_case(*f, 1e-3, static_cast<std::uint64_t>(seed));
    Support_query q;
    q.question = Support_question::limit_surface;
    q.load = c.motion_load;
    q.polytopes = false;
    const Support_item item = answer_support(s.text, "near-threshold", Request{}, q);
    const std::string where = "seed " + std::to_string(seed) + (s.above ? " above" : " below") + " allowed " +
                              std::to_string(s.allowed) + "\n" + s.text + "\nload " + s.load_text[0] + ", " +
                              s.load_text[1] + ", " + s.load_text[2];
    if (item.status == Status::undecided || (item.motion && item.motion->motion == Motion::undecided)) {
      ++undecided;
      EXPECT_TRUE(item.motion && (!item.motion->uncertified.empty() || !item.motion->undecided_why.empty()))
          << "an undecided answer says why, with its distance\n" << where;
      if (std::getenv("WRENCHKIT_TEST_VERBOSE")) {
        std::string per;
        if (item.motion)
          for (const Motion v : item.motion->per_vertex) per += std::string(" ") + motion_name(v);
        std::fprintf(stderr, "undecided: %s %s (%s)%s\n%s\n", item.message.c_str(),
                     item.motion ? item.motion->uncertified.c_str() : "",
                     item.motion ? decided_by_name(item.motion->decided_by) : "", per.c_str(), where.c_str());
      }
      continue;
    }
    ASSERT_EQ(item.status, Status::answered) << item.message << "\n" << where;
    ASSERT_TRUE(item.motion) << where;
    const Motion m = item.motion->motion;
    const unsigned bit = m == Motion::sticks   ? stress::answer_sticks
                         : m == Motion::slides ? stress::answer_slides
                                               : stress::answer_depends;
    EXPECT_TRUE(s.allowed & bit) << motion_name(m) << " is ruled out by the construction\n" << where;
    EXPECT_FALSE(item.certificate.empty()) << where;
    answers.insert(motion_name(m));
  }
  EXPECT_LE(undecided * 100, n) << undecided << " of " << n << " undecided";
  EXPECT_EQ(answers.size(), 3u);
}

// Hybrid labels with the cone from the scene's integer rows (wrench_cone_of_rows) against the exact
// construction: the same cone member by member, the same labels byte for byte (an eagerly and a lazily read
// scene), and the same pipeline answers (labels with a resultant and the load, Reuleaux with a motion) but
// for mode, decided_by and the predicate counts. Returns whether the rows served; a failure names the case
// and dumps the scene.
bool hybrid_labels_match_exact(const std::string& text, const std::string& tag) {
  const Scene s = read_scene(text, Input_limits{}), lazy = read_scene(text, Input_limits{}, "scene", true);
  bool from_rows = false;
  for (Reading r : {Reading::friction, Reading::frictionless}) {
    const std::optional<Wrench_cone> rows = wrench_cone_of_rows(s, r, fl::generators(to_bounded(s), r));
    const Moment_labels e = moment_labels(s, r, Mode::exact), h = moment_labels(s, r, Mode::hybrid),
                        hl = moment_labels(lazy, r, Mode::hybrid);
    const std::string where = tag + (r == Reading::friction ? " friction" : " frictionless") + ", dumped to ";
    EXPECT_EQ(labels_json(h), labels_json(e)) << where << test::dump_failure(text, tag);
    EXPECT_EQ(labels_json(hl), labels_json(e)) << where << test::dump_failure(text, tag);
    if (rows) {
      from_rows = true;
      EXPECT_EQ(rows->rank, e.cone.rank) << where << test::dump_failure(text, tag);
      EXPECT_TRUE(rows->shape == e.cone.shape && rows->dual == e.cone.dual && rows->primal == e.cone.primal &&
                  rows->dual_pointed == e.cone.dual_pointed && rows->primal_pointed == e.cone.primal_pointed &&
                  rows->lineality == e.cone.lineality)
          << where << test::dump_failure(text, tag);
    }
  }
  for (Labels_question question : {Labels_question::labels, Labels_question::reuleaux}) {
    Labels_query q;
    q.question = question;
    if (question == Labels_question::labels) q.resultant = Vec3q{1, -2, Rational(3, 7)};
    else q.motion = rotation_twist({Rational(1, 3), Rational(-2)}, 1);
    Request exact, hybrid;
    exact.mode = Mode::exact;
    hybrid.mode = Mode::hybrid;
    const Labels_item a = answer_labels(text, "scene", exact, q), b = answer_labels(text, "scene", hybrid, q);
    EXPECT_EQ(a.status, b.status) << tag << ": " << a.message << " / " << b.message;
    if (a.status != Status::answered || b.status != Status::answered) continue;
    EXPECT_EQ(labels_json(b.labels), labels_json(a.labels)) << tag << ", dumped to " << test::dump_failure(text, tag);
    EXPECT_EQ(b.labels.cone.rank, a.labels.cone.rank) << tag;
    EXPECT_EQ(b.resultant_possible, a.resultant_possible) << tag;
    EXPECT_EQ(b.load_balanced, a.load_balanced) << tag;
    EXPECT_EQ(b.closed(), a.closed()) << tag;
    if (a.modes) {
      EXPECT_TRUE(b.modes && b.modes->modes == a.modes->modes && b.modes->feasible == a.modes->feasible &&
                  b.modes->marginal == a.modes->marginal)
          << tag;
    }
  }
  return from_rows;
}

// Every family of the stress report at every ε of the report (three seeds each), and random grasps as a
// grasp planner writes them (random_grasp_text, 2–12 contacts); seeds fixed (WRENCHKIT_SEED moves the random
// ones), printed with each failure.
TEST(StressFamilies, HybridLabelsFromIntegerRowsAreTheExactOnes) {
  const double epsilons[] = {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-13, 1e-14, 1e-15, 1e-16, 1e-20, 1e-30, 1e-40};
  int cases = 0, from_rows = 0;
  for (const families::Family& f : families::report()) {
    if (is(f, {"many_contacts"})) continue;  // 10^3–10^4 contacts: the exact labels take seconds each
    for (double eps : epsilons)
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const families::Case c = families::make_case(f, eps, seed);
        char tag[96];
        std::snprintf(tag, sizeof tag, "labels_rows_%s_%g_%llu", f.name, eps, static_cast<unsigned long long>(seed));
        from_rows += hybrid_labels_match_exact(c.text, tag);
        ++cases;
        if (HasFailure()) return;
      }
  }
  const std::uint64_t seed = test::seed(19);
  stress::Rng rng(seed);
  int random_rows = 0;
  const int random_cases = 400;
  for (int i = 0; i < random_cases; ++i) {
    const std::string text = families::random_grasp_text(2 + i % 11, rng);
    random_rows += hybrid_labels_match_exact(text, "labels_rows_random_" + std::to_string(seed) + "_" + std::to_string(i));
    if (HasFailure()) return;
  }
  std::printf("[ stats    ] hybrid labels from integer rows: %d of %d family scenes, %d of %d random grasps\n", from_rows,
              cases, random_rows, random_cases);
  // Both paths are exercised: the rows serve every random grasp and some family scenes; the rest (rows beyond
  // 62 bits: 17-digit decimals, long fractions, huge scales) take the rational construction.
  EXPECT_GT(random_rows * 10, random_cases * 9);
  EXPECT_GT(from_rows, 0);
  EXPECT_LT(from_rows, cases);
}

}  // namespace
}  // namespace wrenchkit
