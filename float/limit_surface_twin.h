// [FL-7] The float twin of planar sliding and the limit surface (theory.md §10–§12). Standard library only.
//
// What only floating point can give, with certified bounds: the TRUE limit surface's support function
//   h(q) = Σ_i ρ_i |v_i(q)|,   v_i(q) = (v_x − ω y_i, v_y + ω x_i)             (theory.md §11.3)
// and the true load for a twist, p(q) = Σ_{v_i ≠ 0} ρ_i (v̂_i, r_i × v̂_i) (a facet when some v_i = 0, §11.5),
// with square roots and quotients in Bounded arithmetic [FL-1, FL-5]; the polygonal bounds h_in ≤ h ≤ h_out
// of §12 over the exact engine's direction sets (the same integer parameters, core/limit_surface_directions.h,
// so the same polygons, each u(t_j) an exact rational point of the unit circle held as a Bounded pair, and λ
// certified); and whether a load sticks or slides on the TRUE limit surface,
// certified by a search over the twists (proofs/notes/FL-7-limit-surface-twin.md):
//   slides  — a twist q with h(q) ≤ q·p (certified): p is not in the interior of LS; q is a witness;
//   sticks  — h(q) − q·p > 0 certified on every cell of a subdivision of the cube's surface, using the
//             Lipschitz bound |f(q) − f(c)| ≤ (Σ ρ_i √(1 + |r_i|²) + |p|)·|q − c|;
//   undecided — the cell budget ran out (p within the search's resolution of the limit surface).
// Sign convention (theory.md §1.5): a load is the wrench the slider applies to the support.
//
// Exactness: certified-or-undecided for signs and for h, loads and polygonal values (each a Bounded);
// the witness twist is reported in doubles. Inputs: support points with ρ_i = μ_i f_{n,i} ≥ 0 and
// f_{n,i} ≥ 0 (Bounded: exact doubles from the robot side, or the exact engine's values with their
// conversion errors).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "float/bounded.h"
#include "float/labels_twin.h"

namespace wrenchkit::fl {

struct Support_point_twin {
  Bounded x, y;    // position
  Bounded force;   // normal force f_n ≥ 0
  Bounded rho;     // μ·f_n ≥ 0
};

// Centre of friction r₀ = Σ f_i r_i / Σ f_i (theory.md §10); uncertain when Σ f_i is not certified > 0.
Point2 center_of_friction(const std::vector<Support_point_twin>& s);

// h(q) for a twist q = (v_x, v_y, ω). O(k).
Bounded support_function(const std::vector<Support_point_twin>& s, const Bounded3& q);

// The load for a twist (theory.md §11.5): `load` is the sum over the points that move; the points with
// v_i certified zero (the rotation centre is a support point) make the load a facet: each adds its
// disc A_{r_i}(D_{ρ_i}) around `load`. `decided` false when some |v_i| is not certified zero or nonzero.
struct Load_twin {
  bool decided = false;
  Bounded3 load;
  std::vector<std::size_t> facet_points;  // indices with v_i = 0
};
Load_twin load_for_twist(const std::vector<Support_point_twin>& s, const Bounded3& q);

// [LS-1] in floating point: the exact engine's n (even, 4 ≤ n ≤ kMaxSides) unit vectors u(t_j), from the
// same integers t_j = a_j/den (core/limit_surface_directions.h; u(t) = ((1 − t²)/(1 + t²), 2t/(1 + t²))),
// each coordinate a Bounded containing the exact rational of make_directions in exact/sliding/limit_surface.h;
// counter-clockwise (certified) and centrally symmetric, and λ² = (1 + min_j u_j·u_{j+1})/2 as a Bounded
// containing the exact λ² (its lower end is a certified λ²).
struct Directions_twin {
  int n = 0;
  std::vector<Point2> u;
  Bounded lambda_sq;
};
Directions_twin make_directions(int n);  // throws std::invalid_argument for a bad n

// h_in(q) = Σ ρ_i max_j u_j·v_i(q) and h_out(q) = Σ ρ_i max_j w_j·v_i(q) (w_j the outer polygon's
// vertices, theory.md §12.2): certified brackets h_in ≤ h ≤ h_out ≤ h_in/λ². O(k·n).
Bounded polygonal_support(const std::vector<Support_point_twin>& s, const Directions_twin& d, bool outer,
                          const Bounded3& q);

// Does the load p stick (interior of the true LS; relative interior when LS is flat) or slide?
enum class Motion_twin { sticks, slides, undecided };
const char* motion_name(Motion_twin m);
struct Motion_answer {
  Motion_twin motion = Motion_twin::undecided;
  std::array<double, 3> witness{};  // slides: a twist with h(q) ≤ q·p (approximately, in the input frame)
  std::size_t cells = 0;            // twists evaluated
};
Motion_answer classify_load(const std::vector<Support_point_twin>& s, const Bounded3& p,
                            std::size_t max_cells = 200000);

// Robot-side: support points (x, y, normal force, μ) as plain doubles. Throws std::invalid_argument for a
// negative or non-finite force or μ.
struct Support_contact {
  double x = 0, y = 0, force = 0, mu = 0;
};
std::vector<Support_point_twin> bounded_support(const std::vector<Support_contact>& points);

}  // namespace wrenchkit::fl
