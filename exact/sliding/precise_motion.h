// [SL-6] Stick or slide for a load too close to the limit surface of a known discrete distribution for the
// float twin's search and the exact polygons (proofs/notes/SL-6-precise-motion.md).
//
// The gauge of the load p in the limit surface is 1/min{ h(q) : q·p = 1 }, h(q) = Σ_i ρ_i |v_i(q)| (ρ_i = μ_i f_i,
// v_i(q) = (q_x − ω y_i, q_y + ω x_i)). Newton's method with a backtracking line search, in MPFR at 128, 256 and
// 512 bits, proposes the minimiser q* and h* = h(q*); it only proposes — what is kept is checked in exact rationals:
//   h* > 1, p inside: rational weights w_i ≈ ρ_i/(h*·|v_i(q*)|), L solving Σ w_i A_i A_iᵀ L = p exactly (a 3×3
//           rational system; A_i g = (g, r_i × g)), g_i = w_i v_i(L): Σ A_i g_i = p exactly and |g_i|² < ρ_i²
//           checked exactly — a stick witness (the same as the smoothed witness's, so the same certificate);
//   h* < 1, p outside: q* rounded to a primitive integer twist q, u_i ≥ |v_i(q)| rational (u_i² ≥ |v_i|², an
//           integer square root), Σ ρ_i u_i < q·p checked exactly — a slide witness, strict (so also a motion
//           that breaks a hold).
// The working precision follows the margin |h* − 1| (the rationals get about 24 bits more than it asks, so short
// margins give short certificates); nothing when the margin is below 2^-480, when p is on the surface, or when
// Newton does not converge (the minimiser rotates about a support point: a facet of the surface, where h is not
// smooth). Hybrid mode only: its numbers are floating point, even though everything kept is exact.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "exact/sliding/limit_surface.h"

namespace wrenchkit {

struct Rho_point {
  Vec2 at;
  Rational rho;  // μ_i f_i ≥ 0
};

struct Precise_motion {
  Motion motion = Motion::undecided;
  std::vector<Vec2> forces;            // sticks: g_i, one per point, Σ (g_i, r_i × g_i) = p, |g_i| < ρ_i
  Vec3q twist{};                       // slides: a primitive integer twist …
  std::vector<Rational> speed_bounds;  // … with u_i ≥ |v_i(twist)|, one per point, and Σ ρ_i u_i < twist·p
  // undecided: Newton's last minimiser, when it ran (a load on the limit surface: close to its normal twist, which a
  // caller may make exact, rationalized, to certify the load on the surface).
  std::optional<std::array<double, 3>> proposal;
};

// At most this many points, and at most kMaxPreciseMotionWork point evaluations of h in all (each costs a few
// multiple-precision operations): bounded time on any input, about a second at worst.
constexpr std::size_t kMaxPreciseMotionPoints = 4096;
constexpr std::size_t kMaxPreciseMotionWork = 2000000;

// Precondition: friction (ρ > 0) at two distinct points at least, else nothing (a flat limit surface).
Precise_motion precise_motion(const std::vector<Rho_point>& points, const Vec3q& p);

}  // namespace wrenchkit
