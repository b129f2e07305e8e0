// Signs of predicates, shared by the exact engine and the floating-point twin.
//
// A predicate of the exact kernel always returns negative, zero or positive. A predicate of a
// filtered floating-point kernel may also return `uncertain` when its error bound cannot decide;
// generic algorithms then stop and report that they could not decide (they never guess).
#pragma once

namespace wrenchkit {

enum class Sign : int { negative = -1, zero = 0, positive = 1, uncertain = 2 };

inline constexpr Sign sign_of(int s) noexcept {
  return s < 0 ? Sign::negative : (s > 0 ? Sign::positive : Sign::zero);
}

inline constexpr Sign negate(Sign s) noexcept {
  return s == Sign::negative ? Sign::positive : (s == Sign::positive ? Sign::negative : s);
}

}  // namespace wrenchkit
