// [FL-4] Handing an exact scene to the float twin: every rational becomes a double with a
// certified bound on its conversion error (0 when the rational is exactly a double, as 1/2 is and
// 0.1 is not). So a certified float answer is the exact answer for the scene as written.
#pragma once

#include <vector>

#include "exact/scene.h"
#include "float/closure_twin.h"

namespace wrenchkit {

// |q − v| ≤ e: v is q rounded toward zero; e = 0 if exact, 2^-51·|v| otherwise (one ulp of a
// normal double is at most 2^-52·|v|), +∞ if q is outside the normal range of doubles.
fl::Bounded to_bounded(const Rational& q);

std::vector<fl::Bounded_contact> to_bounded(const Scene& scene);

}  // namespace wrenchkit
