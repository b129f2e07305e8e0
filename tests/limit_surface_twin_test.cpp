// [FL-7] The float twin of sliding and the limit surface against the exact engine and the closed forms:
// the true h(q) lies in the exact polygonal bracket [h_in, h_out] and in the exact √-bracket; the true load
// lies in the exact box of compute_sliding; the barbell of theory.md §14.2 exactly; the float polygonal
// bounds bracket the true h with the certified λ; stick/slide on the true LS agrees with every certified
// polygonal answer of the exact engine, and is never "sticks" for a load outside LS.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "exact/sliding/limit_surface.h"
#include "exact/sliding/sliding.h"
#include "exact/sliding/strategies.h"
#include "exact/io/to_float.h"
#include "testing/twin_agreement.h"
#include "float/limit_surface_twin.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

using fl::Bounded;

Rational rq(long a, long b) {
  Rational r(a, b);
  r.canonicalize();
  return r;
}

// Both contain the true value, so the float interval and the exact [lo, hi] must meet.
::testing::AssertionResult meets(const Bounded& b, const Rational& lo, const Rational& hi) {
  if (!std::isfinite(b.e)) return ::testing::AssertionFailure() << "infinite bound";
  const Rational l = Rational(fl::lower(b)), h = Rational(fl::upper(b));
  if (h < lo || l > hi)
    return ::testing::AssertionFailure() << "[" << l.get_d() << ", " << h.get_d() << "] misses [" << lo.get_d() << ", "
                                         << hi.get_d() << "]";
  return ::testing::AssertionSuccess();
}

std::vector<fl::Support_point_twin> twin_of(const Ls_support& s) {
  std::vector<fl::Support_point_twin> out;
  for (const Ls_point& p : s.points) out.push_back({to_bounded(p.at.x), to_bounded(p.at.y), to_bounded(p.force), to_bounded(p.rho)});
  return out;
}
fl::Bounded3 twin_of(const Vec3q& q) { return {to_bounded(q[0]), to_bounded(q[1]), to_bounded(q[2])}; }

Support random_support(std::mt19937_64& rng, int k) {
  std::uniform_int_distribution<int> c(-40, 40), f(1, 20), mu(1, 9);
  Support s;
  s.mu = rq(mu(rng), 10);
  for (int i = 0; i < k; ++i) s.points.push_back({Vec2{rq(c(rng), 10), rq(c(rng), 10)}, rq(f(rng), 7), std::nullopt});
  return s;
}

Vec3q random_twist(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> c(-9, 9);
  Vec3q q;
  do q = {rq(c(rng), 3), rq(c(rng), 3), rq(c(rng), 4)};
  while (q[0] == 0 && q[1] == 0 && q[2] == 0);
  return q;
}

TEST(LimitSurfaceTwin, BarbellTheory14_2) {
  // a = (0, −1), b = (0, 1), ρ = 1/2 each: h(q) = ½|(v_x + ω, v_y)| + ½|(v_x − ω, v_y)|.
  const auto bb = fl::bounded_support({{0, -1, 1, 0.5}, {0, 1, 1, 0.5}});
  const auto B = [](double a, double b, double c) { return fl::Bounded3{Bounded::exact(a), Bounded::exact(b), Bounded::exact(c)}; };
  const Bounded h = fl::support_function(bb, B(1, 1, 2));
  EXPECT_NEAR(h.v, 0.5 * std::hypot(3, 1) + 0.5 * std::hypot(-1, 1), 1e-15);
  // IC (0, 2) CCW → (1, 0, 0); IC (0, 1/2) CCW → (0, 0, 1); IC (0, −3) CCW → (−1, 0, 0);
  // twist (1, 0, 0) → (1, 0, 0); (0, 0, 1) → (0, 0, 1). A rotation centre (cx, cy) CCW is q = (cy, −cx, 1).
  const std::pair<fl::Bounded3, std::array<double, 3>> cases[] = {
      {B(2, 0, 1), {1, 0, 0}}, {B(0.5, 0, 1), {0, 0, 1}}, {B(-3, 0, 1), {-1, 0, 0}}, {B(1, 0, 0), {1, 0, 0}}, {B(0, 0, 1), {0, 0, 1}}};
  for (const auto& [q, want] : cases) {
    const fl::Load_twin l = fl::load_for_twist(bb, q);
    ASSERT_TRUE(l.decided);
    EXPECT_TRUE(l.facet_points.empty());
    for (int c = 0; c < 3; ++c) EXPECT_LE(std::fabs(l.load[c].v - want[c]), l.load[c].e + 1e-300) << c;
  }
  // Twist (−1, 0, 1), rotation about a: the facet {(f_x − ½, f_y, f_x + ½) : |f| ≤ ½}, centre (−½, 0, ½).
  const fl::Load_twin facet = fl::load_for_twist(bb, B(-1, 0, 1));
  ASSERT_TRUE(facet.decided);
  ASSERT_EQ(facet.facet_points, std::vector<std::size_t>{0});
  EXPECT_EQ(facet.load[0].v, -0.5);
  EXPECT_EQ(facet.load[1].v, 0);
  EXPECT_EQ(facet.load[2].v, 0.5);
  // Stick/slide: the non-smooth point (1, 0, 0) is on LS: 0.99 of it sticks, 1.01 slides.
  EXPECT_EQ(fl::classify_load(bb, B(0.99, 0, 0)).motion, fl::Motion_twin::sticks);
  EXPECT_EQ(fl::classify_load(bb, B(1.01, 0, 0)).motion, fl::Motion_twin::slides);
  EXPECT_EQ(fl::classify_load(bb, B(0, 0, 0)).motion, fl::Motion_twin::sticks);
  EXPECT_EQ(fl::classify_load(bb, B(0.3, -0.2, 0.4)).motion, fl::Motion_twin::sticks);
  const fl::Motion_answer far = fl::classify_load(bb, B(0, 3, 1));
  ASSERT_EQ(far.motion, fl::Motion_twin::slides);
  // The witness twist really has h(q) ≤ q·p.
  const fl::Bounded3 w = B(far.witness[0], far.witness[1], far.witness[2]);
  EXPECT_LE(fl::support_function(bb, w).v, 3 * far.witness[1] + far.witness[2] + 1e-12);
}

TEST(LimitSurfaceTwin, SinglePointFlatDiscAndZeroSurface) {
  const auto one = fl::bounded_support({{1, 2, 2, 0.5}});  // ρ = 1 at (1, 2): ν = (2, −1, 1)
  const auto B = [](double a, double b, double c) { return fl::Bounded3{Bounded::exact(a), Bounded::exact(b), Bounded::exact(c)}; };
  // A flat limit surface has no interior (proofs/notes/SL-1): even a load in the disc's relative interior,
  // (f, r × f) with r × f = 1·f_y − 2·f_x and |f| < ρ, slides (about the point, at no frictional cost).
  EXPECT_EQ(fl::classify_load(one, B(0.5, 0.25, 0.25 - 1.0)).motion, fl::Motion_twin::slides);
  EXPECT_EQ(fl::classify_load(one, B(1, 0, -2)).motion, fl::Motion_twin::slides);  // on the rim
  EXPECT_EQ(fl::classify_load(one, B(0.5, 0.25, 0)).motion, fl::Motion_twin::slides);  // off the plane
  const auto none = fl::bounded_support({{1, 2, 2, 0}});
  EXPECT_EQ(fl::classify_load(none, B(0, 0, 0)).motion, fl::Motion_twin::slides);  // LS = {0}: no interior
  EXPECT_EQ(fl::classify_load(none, B(0, 0, 1)).motion, fl::Motion_twin::slides);
  EXPECT_THROW(fl::bounded_support({{0, 0, -1, 0.5}}), std::invalid_argument);
  // Coordinates near the top of the double range: bounds overflow; the search abstains rather than guess.
  const auto huge = fl::bounded_support({{1e300, 0, 1, 1}, {-1e300, 0, 1, 1}});
  EXPECT_NE(fl::classify_load(huge, B(0.5, 0, 0)).motion, fl::Motion_twin::slides);
  EXPECT_NE(fl::classify_load(huge, B(5, 0, 0)).motion, fl::Motion_twin::sticks);
}

// [LS-1] [FL-7] One direction rule: for every N the twin's u_j and λ² are the exact engine's rationals
// (each coordinate within its bound of the exact one), so the twin's polygons ARE the exact polygons.
TEST(LimitSurfaceTwin, DirectionSetsAreTheExactOnes) {
  std::vector<int> sizes = {600, 1000, 1024, 1366, 2048, 3000, 4094, 4096};
  for (int n = 4; n <= 512; n += 2) sizes.push_back(n);
  for (int n : sizes) {
    const Directions d = make_directions(n);
    const fl::Directions_twin f = fl::make_directions(n);
    ASSERT_EQ(f.n, n);
    ASSERT_EQ(f.u.size(), d.u.size());
    for (int j = 0; j < n; ++j)
      ASSERT_TRUE(within(f.u[j].x, d.u[j].x) && within(f.u[j].y, d.u[j].y))
          << "N = " << n << ", u_" << j << ": twin (" << f.u[j].x.v << " ± " << f.u[j].x.e << ", " << f.u[j].y.v
          << " ± " << f.u[j].y.e << "), exact (" << d.u[j].x << ", " << d.u[j].y << ")";
    ASSERT_TRUE(within(f.lambda_sq, d.lambda_sq)) << "N = " << n << ": twin λ² " << f.lambda_sq.v << " ± "
                                                  << f.lambda_sq.e << ", exact " << d.lambda_sq.get_d();
  }
}

TEST(LimitSurfaceTwin, TrueValuesLieInTheExactBrackets) {
  const std::uint64_t seed = test::seed(31);
  std::mt19937_64 rng(seed);
  const Directions d16 = make_directions(16);
  const fl::Directions_twin f16 = fl::make_directions(16);
  EXPECT_TRUE(within(f16.lambda_sq, d16.lambda_sq));  // the exact 16-gon's λ² (one direction rule)
  for (int t = 0; t < 150; ++t) {
    const Support s = random_support(rng, 1 + t % 6);
    const Ls_support ls = merge_support(s);
    const Polygonal_ls model(ls, d16);
    const auto tw = twin_of(ls);
    const fl::Point2 cof = fl::center_of_friction(tw);
    const Sliding_answer none = compute_sliding(model, std::nullopt);
    ASSERT_TRUE(meets(cof.x, none.center_of_friction.x, none.center_of_friction.x));
    ASSERT_TRUE(meets(cof.y, none.center_of_friction.y, none.center_of_friction.y));
    for (int k = 0; k < 6; ++k) {
      Vec3q q = random_twist(rng);
      if (k == 0) q = {-ls.points[0].at.y, ls.points[0].at.x, 1};  // rotation about a support point: a facet
      const Sliding_answer a = compute_sliding(model, q);
      const fl::Bounded3 bq = twin_of(q);
      const Bounded h = fl::support_function(tw, bq);
      const std::string why = "seed " + std::to_string(seed) + " case " + std::to_string(t) + "." + std::to_string(k);
      ASSERT_TRUE(meets(h, a.h_inner, a.h_outer)) << why;
      ASSERT_TRUE(meets(h, a.h_lo, a.h_hi)) << why;
      const fl::Load_twin l = fl::load_for_twist(tw, bq);
      if (l.decided) {
        for (int c = 0; c < 3; ++c) ASSERT_TRUE(meets(l.load[c], a.load_lo[c], a.load_hi[c])) << why << " coordinate " << c;
        ASSERT_EQ(l.facet_points.empty(), a.cls.kind != Twist_kind::facet) << why;
      }
      // The float polygons are the exact ones: their values contain h_in and h_out, and bracket the true h
      // within the certified λ².
      const Bounded hin = fl::polygonal_support(tw, f16, false, bq), hout = fl::polygonal_support(tw, f16, true, bq);
      ASSERT_TRUE(within(hin, a.h_inner)) << why << ": twin h_in " << hin.v << " ± " << hin.e << ", exact " << a.h_inner.get_d();
      ASSERT_TRUE(within(hout, a.h_outer)) << why << ": twin h_out " << hout.v << " ± " << hout.e << ", exact " << a.h_outer.get_d();
      ASSERT_LE(Rational(fl::lower(hin)), a.h_hi) << why;
      ASSERT_GE(Rational(fl::upper(hout)), a.h_lo) << why;
      ASSERT_LE(fl::lower(hout) * fl::lower(f16.lambda_sq), fl::upper(hin) * (1 + 1e-12)) << why;
    }
  }
}

TEST(LimitSurfaceTwin, StickSlideAgreesWithTheExactPolygons) {
  const std::uint64_t seed = test::seed(32);
  std::mt19937_64 rng(seed);
  const Directions d = make_directions(16);
  int float_decided = 0, both = 0, cases = 0, near_decided = 0, near = 0;
  const Rational scales[] = {rq(1, 2), rq(9, 10), rq(999, 1000), 1, rq(1001, 1000), rq(11, 10), rq(3, 2)};
  for (int t = 0; t < 30; ++t) {
    const Support s = random_support(rng, 2 + t % 4);
    const Ls_support ls = merge_support(s);
    const Polygonal_ls model(ls, d);
    const Ls_polytope in = model.build(Side::inner), out = model.build(Side::outer);
    const auto tw = twin_of(ls);
    for (int k = 0; k < 7; ++k) {
      // A load on the true LS (the load of a twist: the midpoint of the exact box, 2^-80 from it) scaled.
      const Sliding_answer a = compute_sliding(model, random_twist(rng));
      const Rational& scale = scales[k];
      Vec3q p;
      for (int c = 0; c < 3; ++c) p[c] = scale * (a.load_lo[c] + a.load_hi[c]) / 2;
      const Motion exact = classify_load(model.gauge(in, Side::inner, p), model.gauge(out, Side::outer, p));
      const fl::Motion_answer f = fl::classify_load(tw, twin_of(p), 20000);
      ++cases;
      const bool decided = f.motion != fl::Motion_twin::undecided;
      float_decided += decided;
      if (scale != 1 && abs(scale - 1) < rq(1, 100)) near += 1, near_decided += decided;
      const std::string why = "seed " + std::to_string(seed) + " case " + std::to_string(t) + "." + std::to_string(k);
      if (exact != Motion::undecided && decided) {
        ++both;
        ASSERT_EQ(std::string(fl::motion_name(f.motion)), motion_name(exact)) << why;
      }
      // Strictly outside LS never sticks; strictly inside never slides.
      if (scale > 1) { ASSERT_NE(f.motion, fl::Motion_twin::sticks) << why; }
      if (scale < 1) { ASSERT_NE(f.motion, fl::Motion_twin::slides) << why; }
    }
  }
  std::printf("[ stats    ] stick/slide: float decided %d of %d loads (%d also decided by the N = 16 polygons); "
              "%d of %d within 1/1000 of LS\n", float_decided, cases, both, near_decided, near);
  EXPECT_GT(float_decided * 10, cases * 7);
  EXPECT_GT(both, cases / 2);
  EXPECT_GT(near_decided * 2, near);  // where the N = 16 polygons (λ ≈ 0.98) cannot tell
}

// The points' verdict (exact/sliding/strategies.h): hybrid answers whatever exact answers, the same way, and more (no N
// to refine).
TEST(LimitSurfaceTwin, HybridMotionNeverContradictsExact) {
  std::mt19937_64 rng(test::seed(33));
  const Directions d = make_directions(8);
  int exact_decided = 0, hybrid_decided = 0, by_float = 0;
  for (int t = 0; t < 20; ++t) {
    const Polygonal_ls model(merge_support(random_support(rng, 2 + t % 3)), d);
    const Ls_polytope in = model.build(Side::inner), out = model.build(Side::outer);
    for (const Rational& scale : {rq(1, 2), rq(97, 100), rq(103, 100), rq(2, 1)}) {
      const Sliding_answer a = compute_sliding(model, random_twist(rng));
      Vec3q p;
      for (int c = 0; c < 3; ++c) p[c] = scale * (a.load_lo[c] + a.load_hi[c]) / 2;
      const Points_verdict e = points_verdict(model, p, Mode::exact, &in, &out);
      const Points_verdict h = points_verdict(model, p, Mode::hybrid, &in, &out);
      const Points_verdict f = points_verdict(model, p, Mode::float_only);
      exact_decided += e.motion != Motion::undecided;
      hybrid_decided += h.motion != Motion::undecided;
      by_float += h.decided_by == Decided_by::float_search;
      if (e.motion != Motion::undecided) { ASSERT_EQ(h.motion, e.motion) << "case " << t; }
      if (f.motion != Motion::undecided) { ASSERT_EQ(f.motion, h.motion) << "case " << t; }
      ASSERT_EQ(e.decided_by, e.motion == Motion::undecided ? Decided_by::none : Decided_by::polygons);
      ASSERT_EQ(h.motion, scale < 1 ? Motion::sticks : Motion::slides) << "case " << t;  // ±3 % of LS
    }
  }
  std::printf("[ stats    ] motion: exact (N = 8) decided %d of 80, hybrid %d (%d by the float search)\n", exact_decided,
              hybrid_decided, by_float);
  EXPECT_GT(hybrid_decided, exact_decided);
}

}  // namespace
}  // namespace wrenchkit
