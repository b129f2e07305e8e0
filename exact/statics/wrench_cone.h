// [LB-2] The one exact representation of a contact wrench cone W = pos{g_i} and of its dual cone
// W* = {t : ⟨t, g⟩ ≥ 0 ∀ g ∈ W} (theory.md §3, §5.4 step 4), from which closure, moment labels and
// the force dual are all read, so that they can never disagree.
//
// Both cones are given by generators (a V-representation): the extreme rays of the cone's pointed
// part, in cyclic order when the cone itself is pointed, followed by ± a basis of its lineality
// space. They come from core/dual_cone.h [FC-1] with the exact kernel (the same computation that
// decides closure):
//   rank W = 3  W* = polygon / arc / ray / {0}: its extreme rays are g_a × g_b at the vertices;
//               W is then pos{edge generators} (cyclic, pointed) / pos{the arc's four edges} /
//               the half-space {w : ⟨r, w⟩ ≥ 0} / R³.
//   rank W = 2  n = g_a × g_b spans the lineality of W*; W* ∩ {⟨t, n⟩ ≥ 0} is computed by the same
//               algorithm with n appended as a generator, and W* = that + pos{−n}. W, a planar cone,
//               is classified in exact integer coordinates of its plane.
//   rank W ≤ 1  explicit: half-space or plane (rank 1), R³ (rank 0).
// Exact; O(n log n) expected predicates (rank 3) plus O(K) exact constructions.
#pragma once

#include <optional>
#include <vector>

#include "core/dual_cone.h"
#include "exact/statics/generators.h"
#include "core/mode.h"
#include "float/float_kernel.h"

namespace wrenchkit {

struct Wrench_cone {
  int rank = 0;                          // rank of the generators
  Dual_shape shape = Dual_shape::lineality;  // of W* (rank 3), as closure reports it
  std::vector<Vec3q> dual;                // generators of W*, twists (vx, vy, ω)
  bool dual_pointed = true;              // `dual` = extreme rays of a pointed W*, in cyclic order
  std::vector<Vec3q> primal;              // generators of W, wrenches (fx, fy, m)
  bool primal_pointed = true;            // `primal` = extreme rays of a pointed W, in cyclic order
  std::vector<Vec3q> lineality;           // a basis of W* ∩ −W* = (span W)^⊥ (3 − rank vectors)
  // How the dual cone's signs were decided (hybrid: the float twin first, exact where it was
  // uncertain; the constructions above are exact in every mode).
  std::size_t predicates = 0, exact_predicates = 0;
  bool force_closure() const { return rank == 3 && shape == Dual_shape::zero; }
};

// Zero wrenches are ignored. `mode` exact or hybrid (float_only is the float twin's business:
// float/labels_twin.h); in hybrid mode `twin` holds the same generators as certified doubles (for a
// scene: fl::generators(to_bounded(scene), reading)), else they are converted from the rationals.
// The answer is the same in both modes; hybrid decides most signs in floating point.
Wrench_cone wrench_cone(const std::vector<Vec3q>& generators, Mode mode = Mode::exact,
                        const std::vector<fl::Bounded3>* twin = nullptr);

// [LB-2] The same cone in hybrid mode from the scene's integer rows (Exact_kernel(scene, reading): positive
// integer multiples of generators(scene, reading), read from the contacts' numerators and denominators, no
// rational generators): the signs are the twin's (`twin` = fl::generators(to_bounded(scene), reading)), exact
// where uncertain, so the combinatorics (edges, shape) are the exact ones; the rays g_a × g_b and their
// primitive forms are built in 128-bit integers (|rows| ≤ 2^62 − 1, so |g_a × g_b| < 2^125), and only the
// answer's coordinates become rationals; rank < 3 and a single-ray W* are built from the rational generators
// with the same combinatorics (no second sign computation). Equal, member by member, to
// wrench_cone(generators, Mode::hybrid) (tests/stress_families_test.cpp). std::nullopt — the caller takes
// the rational construction — when a row is zero or beyond 62 bits (before any sign is computed).
std::optional<Wrench_cone> wrench_cone_of_rows(const Scene& scene, Reading reading,
                                               const std::vector<fl::Bounded3>& twin);

// w ∈ W ⇔ ⟨t, w⟩ ≥ 0 for every generator t of W* (W = W**). Exact.
bool in_cone(const Wrench_cone& c, const Vec3q& w);

// J(u) = (−u_2, u_1, u_3) (theory.md §2.2): a twist as its rotation centre P(t), a wrench as its
// force-dual point D(w). Orthogonal, det 1.
Vec3q J(const Vec3q& u);

}  // namespace wrenchkit
