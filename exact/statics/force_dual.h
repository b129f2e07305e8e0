// [LB-4] The force dual (theory.md §6): each wrench w = (fx, fy, m) is the point D(w) = (−fy, fx, m)
// of the two-sided plane (front sheet when m > 0, back sheet when m < 0, at infinity in direction
// (−fy, fx) when m = 0), and the wrench cone W = pos{g_i} is the convex spherical polygon
// pos{D(g_i)}: a front-sheet piece, a back-sheet piece and an arc at infinity. It covers all of T²
// iff W = R³ (force closure). Read from the same exact W as the labels (exact/statics/wrench_cone.h).
//
// The reference-point trick (§6.2): about a point o strictly inside R₊ every generator has moment
// m_o > 0, so all dual points are finite on the front sheet and the dual is the ordinary convex
// polygon conv{(−fy/m_o, fx/m_o)}; reported when R₊ has interior points.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "exact/statics/moment_labels.h"

namespace wrenchkit {

struct Dual_point {
  char sheet = '+';  // '+', '-', 'i' (at infinity: `at` is a primitive direction), '0' (the zero wrench)
  Vec2 at;
};
Dual_point dual_point(const Vec3q& w);

struct Force_dual {
  bool covers_all = false;   // W = R³: force closure
  Region plus_sheet, minus_sheet;
  Cone2 infinity;
  std::vector<Dual_point> generators;  // D(g_i) of every generator, in order
  // §6.2: o strictly inside R₊ and the dual polygon about o (all on the front sheet).
  std::optional<Vec2> reference;
  Region about_reference;
};

// From the labels (which hold the cone), so that both are computed once.
Force_dual force_dual(const Moment_labels& labels, const std::vector<Vec3q>& generators);

}  // namespace wrenchkit
