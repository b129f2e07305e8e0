// Planar sliding quantities of a support (theory.md §10, §11.5) [LS-4].
//
// Sign convention (theory.md §1.5): a "load" is the wrench the slider applies to the support,
// parallel to the sliding velocity; the friction wrench acting on the slider is its negative.
//
// * Centre of friction r₀ = Σ f_i r_i / Σ f_i (pressure centroid; exact).
// * Translation (ω = 0, v ≠ 0): load = (Σρ_i / |v|)·(v_x, v_y, c × v), c = Σ ρ_i r_i / Σ ρ_i (= r₀ when
//   μ is uniform): exact as a rational vector times 1/|v|, and exact outright when |v| is rational.
// * Rotation (ω ≠ 0) about c: the load is a point of LS, or a FACET (a translated copy of the disc
//   A_{r_i}(D_{ρ_i})) when c is a support point i. Exact bounds: the power h(q) ∈ [h_in(q), h_out(q)]
//   from the polygonal surfaces (§12.3), their exact faces ∂h_in/out(q), and an exact rational box
//   containing the true load (or the facet's centre), from rational brackets of each |v_i| (§11.5).
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>

#include "exact/sliding/limit_surface.h"
#include "core/mode.h"
#include "float/limit_surface_twin.h"

namespace wrenchkit {

// Bracket of √s for a rational s ≥ 0: lo ≤ √s ≤ hi, hi − lo ≤ 2^-bits·max(1, √s) (exact rationals).
std::pair<Rational, Rational> sqrt_bracket(const Rational& s, int bits = 80);

// The twist minimising a convex, positively homogeneous power h (in double) on the plane q·p = 1: min h < 1 iff p
// lies outside the set whose support function is h, and the minimiser is then the twist with the largest margin
// (min h = 1/gauge(p)). A compass search in two variables (eight directions, turned a little at every halving of
// the step) from `start` scaled onto the plane (else p/|p|²), stopped once h < stop_below. Proposes twists only:
// every caller checks what it keeps exactly. found = false when p = 0 or the doubles overflow.
struct Plane_minimum {
  bool found = false;
  std::array<double, 3> q{};
  double h = 0;
};
Plane_minimum minimise_on_load_plane(const Vec3q& p, const std::function<double(const double*)>& h,
                                     const Vec3q* start = nullptr, double stop_below = 0);

// The bracket of one support point's power ρ|v(q)| and of its load ρ(v̂, r × v̂) (theory.md §11.5), added to
// h_lo/h_hi and to the box lo/hi (sqrt brackets of |v|² at `bits`); a point with v = 0 (the rotation centre) adds
// its whole facet: every load ρ(g, r × g), |g| ≤ 1, inside the box when `facet_box`, nothing otherwise.
void add_point_bracket(const Vec2& at, const Rational& rho, const Vec3q& q, int bits, Rational& h_lo, Rational& h_hi,
                       Vec3q& lo, Vec3q& hi, bool facet_box);

// What a twist is on the TRUE limit surface (theory.md §11.4): the load is a facet (rotation about a
// support point), a non-smooth point (collinear support, rotation centre on its line, or a
// translation perpendicular to it), or a smooth point.
enum class Twist_kind { facet, vertex, smooth };
struct Twist_class {
  Twist_kind kind = Twist_kind::smooth;
  int support_point = -1;  // facet: index in the merged support
  std::string text;        // one line for people
};
Twist_class classify_twist(const Ls_support& s, const Vec3q& q);

struct Sliding_answer {
  Vec2 center_of_friction;
  Vec2 friction_centroid;  // where the translation load acts
  Rational mu_f0;          // Σ ρ_i
  bool has_twist = false;
  Vec3q twist;
  bool translation = false;
  Vec2 rotation_center;    // rotation only
  Twist_class cls;
  // translation
  Vec3q load_direction;     // load = (mu_f0/|v|)·load_direction
  Rational speed_squared;   // |v|²
  std::optional<Vec3q> load;  // exact when |v| is rational
  // rotation (and translation, for uniformity)
  Rational h_inner, h_outer;  // polygonal bounds of the power h(q)
  Rational h_lo, h_hi;        // rational bracket of the true h(q)
  Vec3q load_lo, load_hi;     // box containing the true load (facet: its centre)
  Ls_face inner_face, outer_face;
};

// Precondition: q ≠ 0 when given (throws std::invalid_argument).
Sliding_answer compute_sliding(const Polygonal_ls& model, const std::optional<Vec3q>& q);

// The merged support as the float twin's points (each value with its conversion bound) [FL-4].
std::vector<fl::Support_point_twin> twin_support(const Ls_support& s);

}  // namespace wrenchkit
