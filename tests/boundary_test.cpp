// The boundary is an answer (issue 29, docs/theory-sliding.md §3): a load on the limit surface is "impending" —
// friction can just hold it, and quasi-static slip with a twist in its normal cone is admitted — decided exactly with
// a certificate (forces in the closed discs; a twist with exact rational speeds whose power meets the friction's),
// in every mode, and hold and limit-surface --load answer every support-only load alike.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "exact/fixture/hold.h"
#include "exact/io/scene.h"
#include "exact/pipeline/hold_answer.h"
#include "exact/pipeline/support_answer.h"
#include "exact/io/scene_writer.h"
#include "exact/sliding/motion.h"
#include "exact/sliding/region_sliding.h"
#include "testing/stress_families.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

// The barbell of Mason's Fig. 6.14/6.15: support points (0, ±1) with force 1/2 each, μ = 1.
const char* kBarbell =
    R"({"wrenchkit": 1, "name": "barbell", "support": {"mu": 1, "points": [{"at": [0, -1], "force": "1/2"},
        {"at": [0, 1], "force": "1/2"}]})";

Support_item motion_of(const std::string& text, const Vec3q& p, Mode mode) {
  Request request;
  request.mode = mode;
  Support_query q;
  q.load = p;
  return answer_support(text, "scene", request, q);
}

Hold_item hold_of(const Vec3q& body_load, Mode mode) {
  Request request;
  request.mode = mode;
  const std::string text = std::string(kBarbell) + R"(, "load": {"wrench": [")" + to_string(body_load[0]) + "\", \"" +
                           to_string(body_load[1]) + "\", \"" + to_string(body_load[2]) + "\"]}}";
  return answer_hold(text, "scene", request);
}

Vec3q q3(long a, long b, long c, long d = 1) {
  Vec3q v{Rational(a, d), Rational(b, d), Rational(c, d)};
  for (Rational& x : v) x.canonicalize();
  return v;
}

struct Golden {
  const char* what;
  Vec3q load;   // the load the slider applies to the support
  Vec3q twist;  // the twist of the certificate (none given: any in the normal cone)
  bool unique;  // the normal cone is one ray (a facet's interior, a translation at μW)
};

// Each load: impending in hybrid, exact and float mode, the certificate (format 3) accepted by the independent
// checker, the twist the normal's (where the normal cone is a ray) with small integers; hold on the body load −p says
// "impending" too, with the motion −q.
void expect_impending(const Golden& g) {
  const std::string text = std::string(kBarbell) + "}";
  for (const Mode mode : {Mode::hybrid, Mode::exact, Mode::float_only}) {
    const Support_item r = motion_of(text, g.load, mode);
    ASSERT_EQ(r.status, Status::answered) << g.what << " " << mode_name(mode) << ": " << r.message;
    ASSERT_TRUE(r.motion) << g.what;
    EXPECT_EQ(r.motion->motion, Motion::impending) << g.what << " " << mode_name(mode) << " " << r.motion->undecided_why;
    ASSERT_TRUE(r.motion->impending) << g.what;
    const Vec3q& q = r.motion->impending->twist.twist;
    if (g.unique) {
      EXPECT_EQ(q, g.twist) << g.what << " " << mode_name(mode);
    }
    EXPECT_EQ(dot(q, g.load), [&] {  // its power meets the friction's: h(q) = Σ ρ_i u_i with exact speeds
      Rational h;
      for (const Rational& u : r.motion->impending->twist.speed_bounds) h += u / 2;  // ρ_i = μ f_i = 1/2
      return h;
    }()) << g.what;
    EXPECT_EQ(r.certificate.rfind(R"({"wrenchkit_certificate": 3, "property": "motion")", 0), 0u) << r.certificate;
    EXPECT_TRUE(test::checker_accepts(text, r.certificate)) << g.what;
    const Hold_item h = hold_of({-g.load[0], -g.load[1], -g.load[2]}, mode);
    ASSERT_EQ(h.status, Status::answered) << g.what << ": " << h.message;
    EXPECT_EQ(h.answer.verdict, Hold_verdict::impending) << g.what << " " << mode_name(mode);
    ASSERT_TRUE(h.answer.impending) << g.what;
    EXPECT_EQ(h.answer.impending->twist.twist, (Vec3q{-q[0], -q[1], -q[2]})) << g.what;
  }
}

// The four facets (a rotation about one support point: the other point's force saturated along its velocity, the
// still point's force anywhere in its disc): at their centres and off-centre.
TEST(BoundaryBarbell, FourFacets) {
  const std::vector<Golden> facets = {
      {"rotation about (0, 1), counter-clockwise", q3(1, 0, 1, 2), q3(1, 0, 1), true},
      {"rotation about (0, 1), clockwise", q3(-1, 0, -1, 2), q3(-1, 0, -1), true},
      {"rotation about (0, -1), clockwise", q3(1, 0, -1, 2), q3(1, 0, -1), true},
      {"rotation about (0, -1), counter-clockwise", q3(-1, 0, 1, 2), q3(-1, 0, 1), true},
      // off-centre on the first facet: the still point (0, 1) carries g = (1/4, 1/4): (1/2 + 1/4, 1/4, 1/2 − 1/4)
      {"rotation about (0, 1), the still point's force (1/4, 1/4)", q3(3, 1, 1, 4), q3(1, 0, 1), true},
  };
  for (const Golden& g : facets) expect_impending(g);
}

// The four vertices (non-smooth points, Fig. 6.15): translations along ±x (both forces along x) and pure moments
// (both forces along x, opposite): their normal cones are wedges between the facets' normals; any twist of it.
TEST(BoundaryBarbell, FourVertices) {
  const std::vector<Golden> vertices = {
      {"translation along +x", q3(1, 0, 0), {}, false},
      {"translation along -x", q3(-1, 0, 0), {}, false},
      {"pure moment +1", q3(0, 0, 1), {}, false},
      {"pure moment -1", q3(0, 0, -1), {}, false},
  };
  for (const Golden& g : vertices) expect_impending(g);
}

// Translations at exactly μW in rational directions (Pythagorean: exact unit velocities): impending, the twist the
// translation itself; 10^-3 inside sticks and 10^-3 outside slides.
TEST(BoundaryBarbell, TranslationsAtMuW) {
  for (const auto& [a, b, c] : std::vector<std::array<long, 3>>{{3, 4, 5}, {5, 12, 13}, {-8, 15, 17}, {0, -1, 1}}) {
    expect_impending({"translation at muW", q3(a, b, 0, c), q3(a, b, 0), true});
    const std::string text = std::string(kBarbell) + "}";
    for (const auto& [scale, want] : std::vector<std::pair<Rational, Motion>>{{Rational(999, 1000), Motion::sticks},
                                                                              {Rational(1001, 1000), Motion::slides}}) {
      const Vec3q p{Rational(scale * a / c), Rational(scale * b / c), Rational(0)};
      const Support_item r = motion_of(text, p, Mode::hybrid);
      ASSERT_EQ(r.status, Status::answered) << r.message;
      EXPECT_EQ(r.motion->motion, want) << a << "," << b;
      EXPECT_TRUE(test::checker_accepts(text, r.certificate));
    }
  }
}

// A flat limit surface (friction at one place) is all surface: a load in its relative interior is impending, one
// off its plane slides.
TEST(BoundaryFlat, OnePointIsAllSurface) {
  const std::string one = R"({"wrenchkit": 1, "support": {"mu": "1/2", "points": [{"at": [1, 0], "force": 2}]}})";
  for (const Mode mode : {Mode::hybrid, Mode::exact}) {
    const Support_item in = motion_of(one, {Rational(1, 2), 0, 0}, mode);  // (g, r × g) with g = (1/2, 0): m = 0
    ASSERT_EQ(in.status, Status::answered) << in.message;
    EXPECT_EQ(in.motion->motion, Motion::impending) << mode_name(mode);
    EXPECT_TRUE(test::checker_accepts(one, in.certificate));
    const Support_item off = motion_of(one, {Rational(1, 2), 0, 1}, mode);  // m ≠ 1 × 0 − 0 × 1/2
    EXPECT_EQ(off.motion->motion, Motion::slides) << mode_name(mode);
    EXPECT_TRUE(test::checker_accepts(one, off.certificate));
  }
}

// A region (uniform square, μ = 1, W = 1) and a point: the load of the translation along (3, 4) is p* = (3/5, 4/5, m*)
// (m* from the region's centre of pressure and the point); p*·(1 ± 10^-30) are decided by their scale alone — sticks
// and slides, with forces or speeds exact on the translation's ray — and p* itself is impending, in hybrid and exact
// mode, the certificates accepted by the independent checker.
TEST(BoundaryRegions, TheRayOfATranslationAtAnyDistance) {
  const std::string scene = R"({"wrenchkit": 1, "support": {"mu": 1, "points": [{"at": [2, 1], "force": "1/2"}],
      "regions": [{"outline": [[-1, -1], [1, -1], [1, 1], [-1, 1]], "pressure": "uniform", "force": "1/2"}]}})";
  // p* = Σ μ f v̂ at each point of force: the point (2, 1) carries 1/2, the square 1/2 at its centre (0, 0).
  const Vec2 v{Rational(3, 5), Rational(4, 5)};
  const Vec3q star{v.x, v.y, Rational(1, 2) * cross(Vec2{Rational(2), Rational(1)}, v)};
  Rational tiny(1);
  for (int i = 0; i < 30; ++i) tiny /= 10;
  const auto scaled = [&](const Rational& k) { return Vec3q{star[0] * k, star[1] * k, star[2] * k}; };
  for (const Mode mode : {Mode::hybrid, Mode::exact}) {
    const struct {
      Vec3q load;
      Motion want;
    } cases[] = {{star, Motion::impending}, {scaled(1 - tiny), Motion::sticks}, {scaled(1 + tiny), Motion::slides}};
    for (const auto& c : cases) {
      const Support_item r = motion_of(scene, c.load, mode);
      ASSERT_EQ(r.status, Status::answered) << r.message;
      EXPECT_EQ(r.motion->motion, c.want) << mode_name(mode) << " " << to_string(c.load[2]) << ": " << r.motion->undecided_why;
      EXPECT_TRUE(test::checker_accepts(scene, r.certificate)) << mode_name(mode);
    }
  }
  // A triangle alone is one coarse cell: the stick witness cuts it once more (friction at two places at least).
  const std::string tri = R"({"wrenchkit": 1, "support": {"mu": 1, "regions": [{"outline": [[0, 0], [3, 0], [0, 3]],
      "pressure": "uniform", "force": 1}]}})";
  const Vec3q below{Rational(1) - tiny, Rational(0), Rational(0)};  // the centre (1, 1): m = −1·fx for fy = 0
  const Support_item r = motion_of(tri, {below[0], 0, -below[0]}, Mode::hybrid);
  ASSERT_EQ(r.status, Status::answered) << r.message;
  EXPECT_EQ(r.motion->motion, Motion::sticks) << r.motion->undecided_why;
  EXPECT_TRUE(test::checker_accepts(tri, r.certificate));
}

// Float mode, no support (hold is equilibrium): the twin decides a margin by balancing the load pushed toward the
// cone's interior (HD-1 §10), so a load held with margin is "holds" in float mode as in hybrid; the frictionless block
// in a corner, whose load only its floor carries (it may slide along the floor), is impending in hybrid and float
// mode does not guess.
TEST(BoundaryFloat, NoSupportHoldsWithMarginByTheTwin) {
  Request request;
  for (const Mode mode : {Mode::float_only, Mode::hybrid}) {
    request.mode = mode;
    const std::string gravity = test::read_text(test::source_dir() + "/proofs/examples/block_corner_mu_1_2_gravity.scene.json");
    const Hold_item h = answer_hold(gravity, "scene", request);
    ASSERT_EQ(h.status, Status::answered) << h.message;
    EXPECT_EQ(h.answer.verdict, Hold_verdict::holds) << mode_name(mode);
    EXPECT_TRUE(test::checker_accepts(gravity, h.certificate));
    const std::string mu0 = test::read_text(test::source_dir() + "/proofs/examples/block_corner_mu0.scene.json");
    const Hold_item b = answer_hold(mu0, "scene", request);
    if (mode == Mode::hybrid) {
      ASSERT_EQ(b.status, Status::answered) << b.message;
      EXPECT_EQ(b.answer.verdict, Hold_verdict::impending);
    } else {
      EXPECT_NE(b.status == Status::answered && b.answer.verdict == Hold_verdict::holds, true);
    }
  }
}

// On a support alone, `hold` with the body load w and `limit-surface --load −w` are one decision (issue 29): the same
// outcome (holds ⇔ sticks, impending ⇔ impending, fails ⇔ slides, depends ⇔ depends), both certificates accepted, in
// hybrid and exact mode — on every support-only scene of the stress families and the reference corpus' families
// (their loads: a family's own stick/slide load, else the scene's, and on the surface, the exact load of the
// translation along (3, 4) where every force is given), five seeds and two distances each (exact mode: one scene).
TEST(BoundaryAgreement, HoldAndLimitSurfaceOnEverySupportOnlyScene) {
  std::vector<const stress::Family*> all;
  for (const stress::Family& f : stress::families()) all.push_back(&f);
  for (const stress::Family& f : stress::report_only_families()) all.push_back(&f);
  int compared = 0, impending = 0;
  for (const stress::Family* family : all)
    for (const double eps : {1e-2, 1e-6})
      for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        if (!family->uses_epsilon && eps != 1e-2) continue;
        const stress::Family_scene fs = stress::make_scene(family->name, eps, seed);
        Scene scene;
        try {
          scene = read_scene(fs.text, Input_limits{});
        } catch (const Input_error&) {
          continue;  // (a family scene beyond the default limits: not this test's question)
        }
        if (!scene.support || !scene.contacts.empty()) continue;
        Vec3q p;
        if (!fs.load_text[0].empty()) {
          for (std::size_t k = 0; k < 3; ++k) p[k] = Rational(read_scene(R"({"wrenchkit": 1, "load": {"wrench": [)" +
                                                                         fs.load_text[0] + ", " + fs.load_text[1] + ", " +
                                                                         fs.load_text[2] + "]}}", Input_limits{})
                                                                  .load->wrench[k]);
        } else if (scene.load && scene.load->kind != Load::Kind::gravity) {
          const Vec3q w = load_wrench(scene);
          p = {-w[0], -w[1], -w[2]};
        } else {
          continue;
        }
        if (is_zero(p)) continue;
        std::vector<Vec3q> loads = {p};
        if (scene.support->known()) {  // and on the surface: the translation along (3, 4)'s exact load
          const Region_sliding t = region_sliding(*scene.support, Vec3q{3, 4, 0}, Rational(1, 1000000));
          if (t.load) loads.push_back(*t.load);
        }
        for (const Vec3q& load : loads) {
          Scene with_load = scene;
          with_load.load = Load{};
          with_load.load->kind = Load::Kind::wrench;
          with_load.load->wrench = {-load[0], -load[1], -load[2]};
          Scene bare = scene;
          bare.load.reset();
          const std::string hold_text = write_scene(with_load), bare_text = write_scene(bare);
          for (const Mode mode : {Mode::hybrid, Mode::exact}) {
            if (mode == Mode::exact && (seed > 1 || eps != 1e-2)) continue;  // (exact mode: the first scene only)
            Request request;
            request.mode = mode;
            Support_query q;
            q.load = load;
            const Support_item m = answer_support(bare, bare_text, "scene", request, q);
            const Hold_item h = answer_hold(with_load, hold_text, request);
            const std::string where = std::string(family->name) + " seed " + std::to_string(seed) + " " + mode_name(mode);
            ASSERT_EQ(m.status, h.status) << where << ": " << m.message << " / " << h.message;
            if (m.status != Status::answered) continue;
            const Motion mm = m.motion->motion;
            const Hold_verdict want = mm == Motion::sticks      ? Hold_verdict::holds
                                      : mm == Motion::impending ? Hold_verdict::impending
                                      : mm == Motion::slides    ? Hold_verdict::fails
                                      : mm == Motion::depends   ? Hold_verdict::depends
                                                                : Hold_verdict::undecided;
            EXPECT_EQ(h.answer.verdict, want) << where << "\n" << test::dump_failure(hold_text, "agreement");
            if (want != Hold_verdict::undecided) {
              EXPECT_TRUE(test::checker_accepts(bare_text, m.certificate)) << where;
              EXPECT_TRUE(test::checker_accepts(hold_text, h.certificate)) << where;
            }
            ++compared;
            impending += mm == Motion::impending;
          }
        }
      }
  EXPECT_GE(compared, 60);
  EXPECT_GE(impending, 10);
  std::printf("compared %d answers, %d impending\n", compared, impending);
}

}  // namespace
}  // namespace wrenchkit
