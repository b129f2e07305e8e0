// The float twin alone: this binary links wrenchkit_float and GoogleTest only — no GMP, no CGAL —
// proving that float/ builds and runs on its own (a robot-side library on plain doubles).
#include <gtest/gtest.h>

#include <stdexcept>

#include "float/closure_twin.h"

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

}  // namespace
}  // namespace wrenchkit::fl
