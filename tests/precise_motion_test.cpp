// [SL-6] Stick or slide within 10^-8 … 10^-40 of the limit surface: Newton's method in multiple precision
// proposes, exact rationals decide (proofs/notes/SL-6-precise-motion.md). Loads whose answer is known by
// construction (the stress report's families, a rotation whose speeds are all rational), every certificate
// re-checked by the independent checker; a load exactly on the surface stays undecided.
#include <gtest/gtest.h>

#include <string>

#include "exact/io/scene.h"
#include "exact/pipeline/hold_answer.h"
#include "exact/pipeline/support_answer.h"
#include "exact/sliding/precise_motion.h"
#include "exact/statics/equilibrium.h"
#include "exact/statics/generators.h"
#include "testing/stress_families.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

Rational q(const char* s) {
  Rational r(s);
  r.canonicalize();
  return r;
}

// The scene with its load written in (the family's exact JSON number texts).
std::string with_load(const stress::Family_scene& s) {
  const std::size_t end = s.text.rfind('}');
  return s.text.substr(0, end) + ", \"load\": {\"wrench\": [" + s.load_text[0] + ", " + s.load_text[1] + ", " +
         s.load_text[2] + "]}" + s.text.substr(end);
}

Vec3q load_of(const stress::Family_scene& s) {
  return load_wrench(read_scene(with_load(s), Input_limits{}));
}

// 3–6 support points ε off a line, the load p(q)·(1 ± ε) for a rotation q about a point of the line: slides iff
// above. The float search abstains from about 10^-10 (docs/stability.md) and the polygons from 10^-2.
TEST(PreciseMotion, CollinearSupportNearTheSurfaceIsDecidedWithCheckedCertificates) {
  int newton = 0;
  for (const double eps : {1e-20, 1e-40})  // each case first spends the float search's budget (~0.3 s)
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const stress::Family_scene s = stress::make_scene("collinear_support", eps, seed);
      const std::string tag = "precise_collinear_" + std::to_string(eps) + "_" + std::to_string(seed);
      Support_query query;
      query.load = load_of(s);
      query.polytopes = false;
      const Support_item r = answer_support(s.text, "test", Request{}, query);
      ASSERT_EQ(r.status, Status::answered) << r.message << test::dump_failure(s.text, tag);
      ASSERT_EQ(r.motion->motion, s.above ? Motion::slides : Motion::sticks)
          << r.motion->uncertified << test::dump_failure(s.text, tag);
      ASSERT_FALSE(r.certificate.empty()) << test::dump_failure(s.text, tag);
      EXPECT_TRUE(test::checker_accepts(s.text, r.certificate)) << test::dump_failure(s.text, tag);
      newton += r.motion->decided_by == Decided_by::newton;
    }
  EXPECT_EQ(newton, 8);  // at 10^-20 and 10^-40 only Newton decides
}

// Three points whose distances to c = (3, 4) are 5, 4, 3: the rotation about c has rational unit velocities, so
// its boundary load p = Σ ρ_i (v̂_i, r_i × v̂_i) = (9/5, −8/5, 0) is exact. (1 + 10^-30)·p slides, (1 − 10^-30)·p
// sticks; p itself is on the surface, where no witness in rationals need exist: Newton proposes nothing.
TEST(PreciseMotion, RationalRotationLoadNearAndOnTheSurface) {
  const std::vector<Rho_point> pts = {{{q("0"), q("0")}, q("1")}, {{q("3"), q("0")}, q("1")}, {{q("0"), q("4")}, q("1")}};
  const Vec3q p{q("9/5"), q("-8/5"), q("0")};
  const Rational up = 1 + q("1/1000000000000000000000000000000"), down = 1 - q("1/1000000000000000000000000000000");
  const Precise_motion out = precise_motion(pts, {p[0] * up, p[1] * up, p[2] * up});
  ASSERT_EQ(out.motion, Motion::slides);
  Rational bound, power;
  for (std::size_t i = 0; i < pts.size(); ++i) {  // the witness's own claim, re-derived
    const Rational vx = out.twist[0] - out.twist[2] * pts[i].at.y, vy = out.twist[1] + out.twist[2] * pts[i].at.x;
    EXPECT_GE(out.speed_bounds[i] * out.speed_bounds[i], vx * vx + vy * vy);
    EXPECT_GE(out.speed_bounds[i], 0);
    bound += pts[i].rho * out.speed_bounds[i];
  }
  for (int c = 0; c < 3; ++c) power += out.twist[c] * p[c] * up;
  EXPECT_LT(bound, power);
  const Precise_motion in = precise_motion(pts, {p[0] * down, p[1] * down, p[2] * down});
  ASSERT_EQ(in.motion, Motion::sticks);
  Vec3q sum{};
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec2& g = in.forces[i];
    EXPECT_LT(g.x * g.x + g.y * g.y, pts[i].rho * pts[i].rho);
    sum[0] += g.x;
    sum[1] += g.y;
    sum[2] += pts[i].at.x * g.y - pts[i].at.y * g.x;
  }
  for (int c = 0; c < 3; ++c) EXPECT_EQ(sum[c], p[c] * down);
  EXPECT_EQ(precise_motion(pts, p).motion, Motion::undecided);
  // Fewer than two points with friction: a flat surface, not Newton's to decide.
  EXPECT_EQ(precise_motion({pts[0], {pts[1].at, q("0")}}, p).motion, Motion::undecided);

  // Through the pipeline, with the independent checker: limit-surface and hold (no contacts) agree.
  const std::string support = R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [0, 0], "force": 1},
      {"at": [3, 0], "force": 1}, {"at": [0, 4], "force": 1}]})";
  for (const bool above : {true, false}) {
    const Rational s = above ? up : down;
    const Vec3q load{p[0] * s, p[1] * s, p[2] * s};
    const std::string text = support + R"(, "load": {"wrench": [")" + to_string(load[0]) + R"(", ")" +
                             to_string(load[1]) + R"(", 0]}})";
    Support_query query;
    query.load = load;
    const Support_item r = answer_support(text, "test", Request{}, query);
    ASSERT_EQ(r.status, Status::answered) << r.message;
    EXPECT_EQ(r.motion->motion, above ? Motion::slides : Motion::sticks);
    EXPECT_EQ(r.motion->decided_by, Decided_by::newton);
    EXPECT_TRUE(test::checker_accepts(text, r.certificate));
    const Hold_item h = answer_hold(text, "test", Request{});
    ASSERT_EQ(h.status, Status::answered) << h.message;
    EXPECT_EQ(h.answer.verdict, above ? Hold_verdict::fails : Hold_verdict::holds);
    EXPECT_TRUE(test::checker_accepts(text, h.certificate));
  }
}

// The distribution unknown, 10^-20 and 10^-40 from a vertex distribution's limit surface: hold (no contacts) answers
// what the construction allows, with a certificate the checker accepts (it used to spend seconds in exact LP rounds
// and say undecided).
TEST(PreciseMotion, HoldOverUnknownDistributionsNearTheSurface) {
  int decided = 0, cases = 0;
  for (const double eps : {1e-20, 1e-40})
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      const stress::Family_scene s = stress::make_scene("unknown_support", eps, seed);
      const std::string text = with_load(s);
      const std::string tag = "precise_unknown_" + std::to_string(eps) + "_" + std::to_string(seed);
      const Hold_item h = answer_hold(text, "test", Request{});
      ASSERT_EQ(h.status, Status::answered) << h.message << test::dump_failure(text, tag);
      ++cases;
      if (h.answer.verdict == Hold_verdict::undecided) continue;
      ++decided;
      const unsigned bit = h.answer.verdict == Hold_verdict::holds   ? stress::answer_sticks
                           : h.answer.verdict == Hold_verdict::fails ? stress::answer_slides
                                                                     : stress::answer_depends;
      EXPECT_TRUE(s.allowed & bit) << test::dump_failure(text, tag);
      EXPECT_TRUE(test::checker_accepts(text, h.certificate)) << test::dump_failure(text, tag);
    }
  EXPECT_GE(decided, cases * 3 / 4);
}

// [SL-3] step 4: every extreme distribution of the dinner plate (eight rim points and its centre, every force
// unknown) slides under these loads, and no twist of the vertices separates the load from the union U of their
// limit surfaces. The union's minimax (a log barrier in double on min_{q·p=1} max_v h_v(q)) proposes both ways:
// its minimiser q* (slides for every distribution, checked with the LP over F), or its dual distribution f*, a
// convex combination of vertices, which holds the load strictly (depends). The depends load was undecided before
// (the exact LP over F × inscribed 64-gons resolves only 1.2·10^-3 of U's boundary; its margin is 2·10^-6).
TEST(PreciseMotion, UnionMinimaxDecidesTheDinnerPlate) {
  const std::string plate =
      R"({"wrenchkit": 1, "contacts": [], "support": {"mu": 1, "weight": 1, "pressure_center": [0, 0], "points": [)"
      R"({"at": [1, 0]}, {"at": [0.6, 0.8]}, {"at": [0, 1]}, {"at": [-0.6, 0.8]}, {"at": [-1, 0]}, )"
      R"({"at": [-0.6, -0.8]}, {"at": [0, -1]}, {"at": [0.6, -0.8]}, {"at": [0, 0]}]}})";
  struct Load {
    const char *x, *y, *m;
    Motion expected;
  };
  for (const Load& l : {Load{"-4147752156737/60000000000000", "-1482864524071/20000000000000",
                             "59732690199553/60000000000000", Motion::slides},
                        Load{"-181775483315155714974009/50000000000000000000000000",
                             "-121725790733016995157591/25000000000000000000000000",
                             "-24999481381234365212395539/25000000000000000000000000", Motion::depends}}) {
    Support_query query;
    query.question = Support_question::limit_surface;
    query.sides = 16;
    query.load = Vec3q{q(l.x), q(l.y), q(l.m)};
    query.polytopes = false;
    const std::string tag = std::string("union_minimax_") + motion_name(l.expected);
    const Support_item item = answer_support(plate, "test", Request{}, query);
    ASSERT_EQ(item.status, Status::answered) << item.message << test::dump_failure(plate, tag);
    ASSERT_TRUE(item.motion.has_value());
    const Motion_answer& m = *item.motion;
    for (const Motion v : m.per_vertex) EXPECT_EQ(v, Motion::slides) << test::dump_failure(plate, tag);
    EXPECT_EQ(m.motion, l.expected) << m.undecided_why << test::dump_failure(plate, tag);
    EXPECT_EQ(m.decided_by, Decided_by::minimax);
    EXPECT_TRUE(test::checker_accepts(plate, item.certificate)) << item.certificate;
    if (l.expected == Motion::depends) {
      // The holding distribution is no vertex: the centre carries none of the weight and the rim all of it, spread.
      ASSERT_TRUE(m.sticking.has_value());
      int loaded = 0;
      for (const Rational& f : m.sticking->distribution) loaded += f > 0;
      EXPECT_GT(loaded, 3);
    }
    // Exact mode has no minimax (doubles only propose in hybrid): it may abstain, never contradict.
    Request exact;
    exact.mode = Mode::exact;
    const Support_item e = answer_support(plate, "test", exact, query);
    ASSERT_TRUE(e.status == Status::answered || e.status == Status::undecided) << e.message;
    if (e.motion && e.motion->motion != Motion::undecided) {
      EXPECT_EQ(e.motion->motion, l.expected);
    }
  }
}

}  // namespace
}  // namespace wrenchkit
