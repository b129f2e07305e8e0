// Sliding over support regions with a continuous pressure [RG-1] [RG-2] (docs/regions.md; theory-sliding §4;
// proofs/notes/RG-1-regions.md, RG-2-fan-integrals.md). A support is any number of points (every force given)
// and regions (exact/io/scene.h: polygons with holes, linear pressure p ≥ 0, settled when read).
//
// * Exact: the total normal force W, the centre of pressure, μ·W and the friction centroid (points and regions
//   by their exact moments), and translation loads (μW/|v|)·(v, c × v) as for points.
// * Rotation about c (ω ≠ 0): the power h(q) = Σ ρ_i |v_i| + Σ_R μ_R |ω| ∫_R |r − c| p dA and the load, from
//   the closed form of ∫|r − c| p dA and ∫ (r − c)/|r − c| p dA over each fan triangle (c, a, b) of a boundary
//   edge a → b [RG-2] (square roots and asinh), evaluated in MPFR interval arithmetic with directed rounding
//   and summed with the edges' signs; the precision doubles until the power's relative width meets the
//   tolerance. Certified brackets, exact rational ends.
// * Stick / slide (every mode but float, which has no twin of regions; decide_on_regions of exact/sliding/strategies.h,
//   behind decide_motion): answered only with witnesses a certificate carries (proofs/certificate-format.md §6.4): sticks — rational forces on the cells of
//   a triangulation of each region (the cells tile it), strictly inside their discs μ F_k, acting at the cells'
//   pressure centroids, with the points' forces summing to the load; slides — a twist and rational speed
//   bounds at the points and at the cells' vertices, whose power bound Σ_points μ f u + Σ_cells Σ_j μ w_j u_j
//   the load's power reaches (|v| is convex and p ≥ 0 linear, so ∫_T |v| p ≤ Σ_j w_j u_j). Doubles only
//   propose the witnesses: a search for the twist minimising h on the plane q·p = 1 (the closed form in
//   double), the smoothed Newton witness on the cells as support points; everything kept is exact.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "exact/io/region.h"
#include "exact/sliding/limit_surface.h"

namespace wrenchkit {

// [RG-2] Certified brackets of K = ∫_R |r − c| p dA and J = ∫_R (r − c)/|r − c| p dA at `bits` of MPFR
// precision (outward rounding throughout); exact rational ends.
struct Fan_bracket {
  Rational k_lo, k_hi;
  Vec2 j_lo, j_hi;
};
Fan_bracket fan_integrals(const Support_region& r, const Vec2& c, long bits);
// K in plain double (the same closed form; a proposal, not certified).
double fan_power_double(const Support_region& r, double cx, double cy);
// ∫_R |v(r)| p dA for the twist q in plain double (the closed form near the region, a quadrature far from it, where
// the closed form cancels): the searches' proposal, not certified.
double region_power_double(const Support_region& r, const double* q);

// The support's exact statics and, with a twist, its power and load (certified brackets).
struct Region_sliding {
  Rational total_force;     // W: the points' forces and the regions' W_R
  Vec2 center_of_pressure;  // Σ f_i r_i + Σ ∫ r p, over W
  Rational mu_f0;           // Σ μ_i f_i + Σ μ_R W_R
  Vec2 friction_centroid;   // where a translation's load acts (= the centre of pressure when μ is uniform)
  bool has_twist = false;
  Vec3q twist;
  bool translation = false;
  Vec2 rotation_center;     // rotation
  bool center_on_point = false;  // rotation about a support point: its disc is a facet (in the load box)
  Vec3q load_direction;     // translation: load = (mu_f0/|v|)·load_direction
  Rational speed_squared;
  std::optional<Vec3q> load;  // translation with |v| rational: exact
  Rational h_lo, h_hi;        // the power, certified
  Vec3q load_lo, load_hi;     // a box holding the load (every load of the facet when center_on_point)
  long bits = 0;              // MPFR precision that met the tolerance (0: no interval arithmetic needed)
  bool met = true;            // the tolerance was met (else: the best bracket at the largest precision)
};
// Precondition: every point force given; q ≠ 0 when given; tolerance > 0 (relative width of the power).
Region_sliding region_sliding(const Support& s, const std::optional<Vec3q>& q, const Rational& tolerance);

// --- Certificate blocks (proofs/certificate-format.md §6.4), shared by every claim that carries a region's
// friction (stick/slide, and fixtures on a support): a stick witness's block is a force per cell, a slide
// witness's block rational speed bounds at the cells' vertices with the bound they give.
struct Region_stick_block {
  Region_cells cells;
  std::vector<Vec2> forces;  // one per cell, |g_k| < μ F_k (g_k = 0 when μ F_k = 0)
};
struct Region_slide_block {
  Region_cells cells;
  std::vector<Rational> speed_bounds;  // one per vertex, u ≥ |v(vertex)|
  Rational bound;                      // μ Σ_cells Σ_j w_j u_j ≥ μ ∫_R |v| p dA
};
// The wrench Σ_k (g_k, c_k × g_k) of a stick block (c_k the cells' pressure centroids).
Vec3q region_stick_wrench(const Support_region& r, const Region_stick_block& b);
// A slide block for the twist q: the cells refined where the bound exceeds Jensen's lower bound most, until the
// bound is at most `target` (when given) or the cells reach max_cells. Exact.
Region_slide_block region_slide_block(const Support_region& r, const Rational& mu, const Vec3q& q,
                                      const std::optional<Rational>& target, std::size_t max_cells);
// [RG-1] The cells of a region as support points: each at its pressure centroid, carrying its force F_k with the
// region's μ. Their limit surface is inside the region's (a cell force spread ∝ p has moment c_k × g_k).
std::vector<Support_point> cell_points(const Support_region& r, const Rational& mu, const Region_cells& cells);
// Slide blocks for every region of s at the twist q whose bounds add up to at most `slack`, each region's target
// its share of it ∝ its power estimated in double (max_cells shared among the regions). `ok` false (no blocks) when
// that estimate already exceeds the slack: no bound can fit.
struct Region_slide_blocks {
  bool ok = false;
  std::vector<Region_slide_block> blocks;
  Rational bound;          // Σ_R the blocks' bounds
  std::size_t cells = 0;
  double estimate = 0;     // Σ_R μ_R ∫_R |v| p in double
};
Region_slide_blocks region_slide_blocks(const Support& s, const Vec3q& q, const Rational& slack, std::size_t max_cells);

}  // namespace wrenchkit
