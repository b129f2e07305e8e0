// [EQ-1] Static equilibrium: can the contacts, with their friction, balance the scene's load?
//
// The load is an external wrench w_ext (theory.md §9: a force at a point, a wrench, or gravity at
// the centre of mass); it is balanced iff −w_ext ∈ W = pos{contact wrench generators} (friction
// reading). Decided by the exact cone LP [FC-4] (in integers [FC-5]), which returns the certificate either way
// (proofs/certificate-format.md §3.3):
//   balanced     — strictly positive weights on at most three generators with Σ λ_k g_k + w_ext = 0
//                  (the contact forces that hold the body, as multiples of the cone edges);
//   not balanced — a twist t with ⟨t, g⟩ ≥ 0 for every generator and ⟨t, w_ext⟩ > 0: a motion the
//                  contacts allow and the load drives (power > 0).
// Exact; every degenerate case (rank < 3, loads on the cone's boundary, the zero load) answered.
// Cost: O(n) per simplex pivot, a handful of pivots.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "exact/statics/closure.h"

namespace wrenchkit {

// The load as a wrench (m about the origin). Precondition: scene.load is set.
Vec3q load_wrench(const Scene& scene);

struct Equilibrium_certificate {
  bool holds = false;
  std::vector<std::pair<Generator_ref, Rational>> combination;  // holds: weights > 0
  std::array<Rational, 3> twist;                                // !holds: primitive integers
};

struct Equilibrium_answer {
  Mode mode = Mode::exact;
  bool decided = true;  // false only in Mode::float_only
  bool balanced = false;
  Vec3q load;
  std::size_t generators = 0;
  Equilibrium_certificate certificate;  // built exactly, in every mode (when certify)
  std::size_t predicates = 0, exact_predicates = 0;  // signs of the dual-cone path (hybrid, float)
  Arithmetic decided_by() const { return wrenchkit::decided_by(mode, predicates, exact_predicates); }
};

// Throws Input_error("load: …") if the scene has no load.
//   exact:       the exact cone LP [FC-4] decides and certifies;
//   hybrid/float [EQ-2]: the dual cone W* [FC-1] over the filtered kernel; when rank W = 3,
//                −w ∈ W ⇔ det[g_a; g_b; w] ≤ 0 at every extreme ray g_a × g_b of W* (and always when
//                W* = {0}). Rank < 3: hybrid decides by the exact LP, float says undecided.
// `certify` false skips the certificate (throughput).
Equilibrium_answer decide_equilibrium(const Scene& scene, Mode mode = Mode::exact, bool certify = true);

}  // namespace wrenchkit
