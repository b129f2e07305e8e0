// The float twin alone: this binary links wrenchkit_float and GoogleTest only — no GMP, no CGAL —
// proving that float/ builds and runs on its own (a robot-side library on plain doubles).
#include <gtest/gtest.h>

#include <stdexcept>

#include "float/closure_twin.h"
#include "float/labels_twin.h"
#include "float/limit_surface_twin.h"

namespace wrenchkit::fl {
namespace {

TEST(FloatOnly, TextbookVerdictsOnPlainDoubles) {
  // theory.md §8.7: concurrent normals; frictionless is exactly degenerate (integers: certified).
  std::vector<Point_contact> tri = {{1, 0, 0, 1, 0}, {0, 1, 1, 0, 0}, {3, 3, -1, -1, 0}};
  EXPECT_EQ(force_closure(tri), Verdict::open);
  for (auto& c : tri) c.mu = 0.125;
  EXPECT_EQ(force_closure(tri), Verdict::closed);
  EXPECT_EQ(form_closure(tri), Verdict::open);
  // theory.md §7: crossed couples close; the pinwheel does not.
  EXPECT_EQ(form_closure({{1.5, 0, 0, 1}, {0.5, 2, 0, -1}, {0, 1.5, 1, 0}, {2, 0.5, -1, 0}}), Verdict::closed);
  EXPECT_EQ(form_closure({{0.5, 0, 0, 1}, {1.5, 2, 0, -1}, {0, 1.5, 1, 0}, {2, 0.5, -1, 0}}), Verdict::open);
  // theory.md §5.5: the vertical-walls squeeze is not force closure.
  EXPECT_EQ(force_closure({{-1, 1, 1, 0}, {-1, -1, 1, 0}, {1, 1, -1, 0}, {1, -1, -1, 0}}), Verdict::open);
  // theory.md §8.5: two fingers; on the cone edge exactly (all inputs exact doubles).
  EXPECT_EQ(force_closure({{0, 0.5, 1, 0, 0.5}, {1, 0.9, -1, 0, 0.5}}), Verdict::closed);
  EXPECT_EQ(force_closure({{0, 0.5, 1, 0, 0.25}, {1, 0.9, -1, 0, 0.25}}), Verdict::open);
  EXPECT_EQ(force_closure({{0, 0.5, 1, 0, 0.5}, {1, 1, -1, 0, 0.5}}), Verdict::open);
  EXPECT_EQ(force_closure({}), Verdict::open);
}

TEST(FloatOnly, BadInputThrowsAndNonFiniteIsUndecided) {
  EXPECT_THROW(force_closure({{0, 0, 0, 0, 0}}), std::invalid_argument);
  EXPECT_THROW(force_closure({{0, 0, 1, 0, -1}}), std::invalid_argument);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(force_closure({{inf, 0, 1, 0}, {1, 0, -1, 0}, {0, 1, 0, -1}, {0, -1, 0, 1}}), Verdict::undecided);
}

TEST(FloatOnly, LabelsAndSlidingOnPlainDoubles) {
  // Two fingers with μ = 1/2 (theory.md §8.5): force closure, so nothing is labeled.
  const Labels_twin two = moment_labels(std::vector<Point_contact>{{0, 0.5, 1, 0, 0.5}, {1, 0.9, -1, 0, 0.5}});
  ASSERT_TRUE(two.decided());
  EXPECT_TRUE(two.nothing_labeled());
  // The barbell (theory.md §14.2): translation (1, 0, 0) gives the load (1, 0, 0); it slides at 1.01 of it.
  const auto bb = bounded_support({{0, -1, 1, 0.5}, {0, 1, 1, 0.5}});
  const Bounded3 tx = {Bounded::exact(1), Bounded::exact(0), Bounded::exact(0)};
  EXPECT_EQ(support_function(bb, tx).v, 1);
  EXPECT_EQ(classify_load(bb, {Bounded::exact(1.01), Bounded::exact(0), Bounded::exact(0)}).motion, Motion_twin::slides);
}

}  // namespace
}  // namespace wrenchkit::fl
