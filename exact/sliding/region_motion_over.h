// [RG-3] Does a load stick or slide over a support with regions when some point's force is not given
// (docs/regions.md; proofs/notes/RG-3-regions-unknown-forces.md)?
//
// F counts the regions as given (their pressure is known): W' = W − Σ_given f_i − Σ_R W_R, M' likewise. The limit
// surface LS(f) = LS_regions ⊕ Σ_i μ_i f_i D_i is Minkowski-linear in the points' forces f, so
//
//   sticks  for every f ∈ F  ⇔  p ∈ int LS(f_v) at every vertex f_v of F;
//   depends                  ⇔  some f ∈ F sticks and another slides (a vertex of each, or a stick witness over F);
//   slides  for every f ∈ F  ⇔  some twist t has t·p ≥ Σ_R B_R(t) + max_F Σ μ_i f_i u_i(t), the regions' certified
//                               slide-block bounds plus the LP over F (its dual certifies the maximum).
//
// Decided as follows, every step certified (the certificate, format 2 of proofs/certificate-format.md §6.5, is
// checked by the independent checker in the pipeline):
//   1. each vertex: the known-forces decision over regions (decide_region_motion with that vertex's forces) — all
//      stick: sticks (one stick witness per vertex); a stick and a slide: depends;
//   2. every vertex slides: twists that may separate p from all of U = ∪_F LS(f) — the vertices' slide twists,
//      their sum, and the minimum of max_v h_v on the plane q·p = 1 (in double; a proposal) — each certified by the
//      LP over F (dual) and the regions' slide blocks;
//   3. else a distribution of F that sticks on the regions' coarse cells as support points with their forces given
//      (an inner approximation of the regions' friction with the same F): the exact LP over F × inscribed N-gons,
//      then a strict witness with that distribution fixed — found: depends;
//   4. else undecided, with the reason.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "exact/sliding/distribution.h"
#include "exact/sliding/region_sliding.h"
#include "exact/sliding/unknown_motion.h"

namespace wrenchkit {

struct Region_motion_over {
  // The verdict in the points' shape (per vertex, the witnesses' vertices, the separating twist, decided_by, why):
  // `decisions` stays empty (each vertex's decision is in `per_vertex` below).
  Motion_over_f over;
  std::vector<Region_motion> per_vertex;  // each vertex's known-forces decision over the regions, with its witness
  // depends found by the LP over F (step 3): the distribution and its witness (support forces, stick blocks).
  std::optional<std::vector<Rational>> sticking_distribution;
  std::optional<Region_motion> sticking;
  // slides for every distribution (step 2): the points' speed bounds at the twist, the LP's dual, the regions' blocks.
  std::vector<Rational> speed_bounds;
  std::array<Rational, 3> dual;
  std::vector<Region_slide_block> slide_blocks;
  std::size_t cells = 0;    // cells in the certificate's blocks
  std::string certificate;  // format 2 (§6.5); empty when undecided
};

// Precondition: s has regions and some point force not given; `v` the vertices of F (vertices(s, a)).
Region_motion_over decide_region_motion_over(const Support& s, const Admissible& a, const Vec3q& p,
                                             const std::vector<std::vector<Rational>>& v);

}  // namespace wrenchkit
