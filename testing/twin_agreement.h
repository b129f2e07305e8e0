// Does the float twin's answer agree with the exact engine's, within the twin's stated bounds?
// [FL-6] Shared by the tests and the fuzz targets (tests/labels_twin_test.cpp, fuzz/scene_checks.h):
// each function returns "" when the twin's answer is consistent with the exact one — same shapes and
// counts, every constructed coordinate within its bound of the exact coordinate (checked in exact
// rational arithmetic), or an honest abstention — and otherwise a description of the first difference.
#pragma once

#include <string>

#include "exact/statics/force_dual.h"
#include "float/labels_twin.h"

namespace wrenchkit {

// |x − v| ≤ e for the exact x (an infinite bound fails: a decided twin owes finite bounds).
bool within(const fl::Bounded& b, const Rational& x);
bool same_point(const fl::Point2& f, const Vec2& exact);
// Some positive multiple of the exact direction lies in the float direction's box.
bool same_direction(const fl::Point2& f, const Vec2& exact);

// Bounded regions may start at any corner; unbounded ones must start where the exact normal form does.
std::string region_disagreement(const fl::Region2& f, const Region& exact);
std::string arc_disagreement(const fl::Arc2& f, const Cone2& exact);
// The whole label set; an undecided twin agrees when its reason is true (rank_deficient ⇔ rank < 3).
std::string labels_disagreement(const fl::Labels_twin& f, const Moment_labels& exact);
std::string dual_disagreement(const fl::Dual_twin& f, const Force_dual& exact);

}  // namespace wrenchkit
