// [OL-1] The body's outline as geometry (docs/scene-format.md, "The outline"): when a scene gives body.outline, the
// outline must be a simple polygon (CGAL's exact test, the one the support regions use: exact/io/region.h), and every
// point contact must lie on it with its normal pointing into the body — on an edge's interior, n · (the edge's inward
// normal) > 0; at a vertex, n in the cone of the two adjacent edges' inward normals. A contact may name its place as
// {"edge": i, "s": t} (edge i from vertex i to i + 1, the point v_i + t·(v_{i+1} − v_i), 0 ≤ t ≤ 1), its normal the
// edge's inward normal unless it gives one. Exact: signs of cross and dot products of the rationals, no square root.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "exact/io/scene.h"

namespace wrenchkit {

// The outline's orientation: its signed area's sign (> 0 counter-clockwise, < 0 clockwise, 0 for none).
int outline_orientation(const std::vector<Vec2>& outline);
// Edge i's point at parameter t, and its inward normal (rot90 of the edge vector when the outline turns
// counter-clockwise, the opposite when clockwise; not unit: exact), given the orientation.
Vec2 edge_point(const std::vector<Vec2>& outline, std::size_t i, const Rational& t);
Vec2 edge_inward_normal(const std::vector<Vec2>& outline, std::size_t i, int orientation);

// The part with frictional fingers placed on its outline instead of its contacts: finger f on edge edges[f] at
// v_i + at[f] (v_{i+1} − v_i), pushing along the edge's inward normal, with Coulomb μ (named "finger 1", …). The load,
// support and pusher are dropped (a grasp of the part alone). The one construction of a placement: grasp-regions'
// ranking, compare's sampled placements and the fuzzer's oracle build it here.
Scene with_fingers(const Scene& part, const Rational& mu, const std::vector<std::size_t>& edges,
                   const std::vector<Rational>& at);

// Checks body.outline and every point contact against it, and states the outline's orientation and convexity in
// scene.body. A violation throws Input_error naming the field, the value and the likely fix — or, `lenient`, is kept
// as a warning in scene.warnings (the scene is analysed as given). No outline: nothing to check.
void check_outline(Scene& scene, bool lenient);

}  // namespace wrenchkit
