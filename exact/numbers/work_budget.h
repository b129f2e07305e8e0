// [WORK] The work budget of one request (docs/scene-format.md "Limits"): what a question may cost,
// counted in the engine's own units, never in wall time, so that an answer is the same on every machine and every run.
//
// A unit is one elementary step on numbers of one 64-bit limb: the steps the engine charges are those whose count
// grows with the scene beyond the digit budgets' reach —
//   * a candidate vertex of the admissible set F (one exact 3×3 solve):              1 × size
//   * an extreme distribution decided (its witness search and certificate):          kPerDistribution × points × size
//     (a support region's edge counting as kPerRegionEdge points)
//   * a support region's cell made (its exact moments and pressure):                 kPerCell × size
// — where `size` is 1 + (the limbs of the longest number the step handles)/8 (a 10 000-digit coordinate: 520 limbs,
// size 66), so a scene at scale 10^9990 is charged what its big numbers cost. A step that would take the request past its budget
// is refused before it starts: the question ends undecided (exit 3) with what it would have cost and the option that
// raises the budget (--max-work; Python: limits={"max_work": …}). Without a budget installed (the library's own
// functions called directly, the tests' oracles) nothing is counted.
//
// The budget belongs to the thread that answers the request (the pipeline installs it around each question,
// exact/pipeline/pipeline.h `guarded`), so batch lines and Python threads each have their own.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "exact/numbers/rational.h"

namespace wrenchkit {

// The budget ran out: the pipeline answers "undecided" (exit 3) with this message, which starts with kWorkBudget (so
// that a front end tells it from a float-mode undecided, whose advice differs).
constexpr const char* kWorkBudget = "the work budget of ";
struct Work_exhausted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

constexpr std::size_t kPerDistribution = 40;  // units per point of one extreme distribution decided
constexpr std::size_t kPerRegionEdge = 50;    // a region's edge counts as this many points there (its power's closed
                                              // form, evaluated by every search step)
constexpr std::size_t kPerCell = 40;          // units per region cell made

// Installs a budget of `limit` units for this thread while it lives (the previous one, if any, is restored after).
class Work_scope {
 public:
  explicit Work_scope(std::size_t limit);
  ~Work_scope();
  Work_scope(const Work_scope&) = delete;
  Work_scope& operator=(const Work_scope&) = delete;

 private:
  std::size_t limit_, used_;
  Work_scope* outer_;
  friend struct Work;
};

constexpr std::size_t kLimbsPerSize = 8;

struct Work {
  // Charges `units` for the step `what` (a phrase: "deciding 8150 extreme distributions of 60 points"); throws
  // Work_exhausted, charging nothing, when the request would go over its budget. Free without a scope.
  static void charge(std::size_t units, const std::string& what);
  // The units the last budget that ended on this thread used (its request's cost: measurements and tests).
  static std::size_t last();
  // 1 + (the limbs of x's numerator and, when not 1, denominator) / kLimbsPerSize: the size factor of steps on numbers
  // like x. Measured on cells and bases: a step's fixed costs dominate up to a few limbs, and at 519 limbs (10^9990) a
  // step costs about 60 times one on one-limb numbers, not 519 (GMP's products are subquadratic, and much of a step
  // is not multiplication).
  static std::size_t size(const Rational& x);
  // a·b, saturating.
  static std::size_t times(std::size_t a, std::size_t b);
};

}  // namespace wrenchkit
