// The admissible distributions of a support (docs/theory-sliding.md §1): whether any exists, and why not.
//
//   F = { f ≥ 0 : f_i = the given force where given, Σ f_i + Σ_R W_R = W, Σ f_i r_i + Σ_R ∫_R r p dA = W c }
//
// (support regions, exact/io/region.h, have a known pressure: their force W_R and moment count as given ones.)
//
// W is support.weight and c support.pressure_center (default body.com) when a force is unknown; when every
// force is given they constrain only if written (and must agree). With W' = W − Σ_given f_i and
// M' = W c − Σ_given f_i r_i, F is nonempty iff W' = 0 and M' = 0, or W' > 0, some force is unknown and
// c' = M'/W' lies in the convex hull of the points with unknown force. The hull test is exact: c' is in
// conv(P) iff some p = c', or the vectors p − c' lie in no open half-plane (an incremental wedge, signs of
// 2×2 determinants of rationals only). O(k).
#pragma once

#include <optional>
#include <string>

#include "exact/io/scene.h"

namespace wrenchkit {

// "" when the scene's support (if any) has an admissible distribution; else the reason, "PATH: what",
// as read_scene reports it (both scene readers call it once the whole scene is read).
std::string support_inadmissible(const Scene& scene);

// The centre of pressure c a support with an unknown force is held to (pressure_center, else body.com);
// nothing when every force is given and no pressure_center is written.
std::optional<Vec2> pressure_center_of(const Scene& scene);

// The total normal force W: support.weight, else a gravity load's weight (gravity beside a support is the
// weight pressing the body on it, docs/scene-format.md "Gravity on a support"); nothing when neither is given.
std::optional<Rational> support_weight_of(const Scene& scene);

// Gravity beside a support acts across the support's plane: it presses the body on the support with its
// weight at body.com and pushes nothing in the plane. True when the scene's load is read that way.
bool gravity_across_support(const Scene& scene);

}  // namespace wrenchkit
