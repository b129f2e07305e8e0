// [RF-1] How close a scene is to a degenerate boundary, for readers of a disagreement
// (docs/reference-format.md §4): is a floating-point implementation's different verdict a tolerance
// issue (the scene is within rounding of a scene where the verdict changes) or a real bug?
//
// Two measures, both computed from the exact scene:
//   * the smallest deciding predicate: over the determinants det[a; b; c] of contact wrench
//     generators that the exact decisions evaluate (force closure with friction, form closure
//     frictionless, and, with a load, the load against each extreme ray of W* [EQ-2]), the smallest
//     nonzero |det| / (|a|·|b|·|c|) — the volume spanned by the three unit generators, in [0, 1] —
//     and how many of them are exactly zero (exact degeneracies the verdict passes through). The
//     wrenches are taken in the scene's own frame (moments about the centroid of the contact points,
//     in units of their RMS distance from it), so the measure does not change when the scene is
//     moved or scaled;
//   * the friction scale: force closure and equilibrium are monotone in friction (W grows with every
//     μ), so there is one s* where the verdict flips when every μ is multiplied by s; an exact rational
//     bracket lo < s* ≤ hi is found by bisection (at most ~30 exact decisions), and
//     max(|lo − 1|, |hi − 1|) bounds the relative change of friction that flips the verdict.
// Exact decisions (hybrid kernel, exact answers); the reported sizes are doubles (approximate, for
// reading). Cost: one dual cone per reading with a GMP-integer kernel, plus ≤ ~30 closure or
// equilibrium decisions per friction scale.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "exact/statics/closure.h"

namespace wrenchkit {

struct Predicate_margin {
  std::size_t determinants = 0;        // determinants evaluated
  std::size_t exact_zeros = 0;         // of which exactly zero
  std::optional<double> min_relative;  // smallest nonzero |det|/(|a||b||c|); none if all zero or none
};

// The friction scale s* at which a verdict flips: verdict(s) false for s ≤ lo, true for s ≥ hi.
struct Friction_flip {
  Rational lo, hi;
  double distance = 0;  // max(|lo − 1|, |hi − 1|): an upper bound of |s* − 1|
};

struct Boundary_distance {
  Predicate_margin force, form, equilibrium;  // equilibrium: only when the scene has a load
  // nullopt: no friction in the scene, or the verdict does not flip for s in [0, 2^64] (e.g. closed
  // even frictionless, or open even with 2^64 times the friction).
  std::optional<Friction_flip> closure_flip, equilibrium_flip;
  // The smallest of the relative determinants and the flip distances (nullopt when none exists), and
  // which measure it is: "determinant" or "friction_scale".
  std::optional<double> distance;
  std::string nearest;
  std::size_t exact_zeros() const { return force.exact_zeros + form.exact_zeros + equilibrium.exact_zeros; }
};

Boundary_distance boundary_distance(const Scene& scene);

// The margin of one reading's dual-cone decision (and of the load against W* when `load` is given
// and rank W = 3).
Predicate_margin predicate_margin(const Scene& scene, Reading reading, const Vec3q* load = nullptr);

// (The scene with every contact's μ multiplied by s: at_mu(scene, s, Friction_scaling::proportional), critical_mu.h.)

}  // namespace wrenchkit
