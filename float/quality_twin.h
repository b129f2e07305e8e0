// [QL-1 §8] [FL-10] The float twin of the grasp's ε (L1; exact/statics/quality.h): the friction-cone edges as
// wrenches in Bounded arithmetic (float/bounded.h, FL-1), their convex hull proposed in doubles, and then certified —
// the hull's triangles form a closed oriented surface (every directed edge once, its reverse once) and every wrench is
// certainly on the inner side of every triangle's plane (strictly, or is one of its corners) — so the triangles'
// planes are exactly the hull's, and ε is the least distance from the origin to them, bracketed with the bounds
// carried (proofs/notes/QL-1-quality.md §8). Anything the doubles cannot certify (four wrenches on one plane, the
// origin on a facet, a flat wrench set) is "uncertain": the exact engine decides. Standard library only.
#pragma once

#include <vector>

#include "float/bounded.h"

namespace wrenchkit::fl {

struct Quality_twin_contact {
  Bounded px, py, nx, ny, mu;  // the point, the inward normal (any length), Coulomb μ ≥ 0
};

enum class Twin_normalization { unit_normal, unit_force, as_given };

struct Quality_twin_answer {
  bool certain = false;   // else: undecided here
  bool closed = false;    // (certain) force closure: the origin strictly inside the hull
  double lower = 0, upper = 0;  // (certain) ε ∈ [lower, upper]; 0 when not closed
};

// ε (L1) of the contacts' friction cones — each contact's two edges n ± μ rot90 n (one when μ is exactly 0), scaled as
// `normalization` says, as wrenches (fx, fy, s·((p − about) × f)) with the torque scale s. At most 64 contacts.
Quality_twin_answer epsilon_twin(const std::vector<Quality_twin_contact>& contacts, Twin_normalization normalization,
                                 const Bounded& torque_scale, const Bounded& about_x, const Bounded& about_y);

}  // namespace wrenchkit::fl
