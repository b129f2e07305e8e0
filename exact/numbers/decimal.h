// Exact rationals as decimals for people: the one routine that writes the "≈ 0.142857" beside an exact value.
#pragma once

#include <string>

#include "exact/numbers/rational.h"

namespace wrenchkit {

// q as a decimal with `digits` significant digits (1..40), correctly rounded from the exact value (ties to even) in
// integer arithmetic, so that no size of q overflows (no double on the way): printf's %g layout (fixed when the
// decimal exponent is in [-4, digits), else "d.ddde±XX"; trailing zeros dropped): decimal_text(1/7) = "0.142857",
// decimal_text(10^400/3) = "3.33333e+399". Text for people reading an answer beside its exact value, never a predicate.
std::string decimal_text(const Rational& q, int digits = 6);

}  // namespace wrenchkit
