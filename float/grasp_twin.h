// [GR-1] [FL-9] The float twin of Nguyen's two-finger test (exact/statics/grasp_regions.h): two frictional fingers at
// p_a, p_b with inward normals n_a, n_b and friction μ close the grasp iff, with d = p_b − p_a, both
// μ (n_a · d) ∓ cross(n_a, d) > 0 and μ (n_b · −d) ∓ cross(n_b, −d) > 0 — four strict signs (GR-1 §3: the segment
// strictly inside both cones; μ = 0 closes nothing). Computed in Bounded arithmetic (float/bounded.h, FL-1): each
// sign certified or uncertain, so the answer is closed, open, or uncertain — never a guess (the naive double test in
// bench/ guesses, to show how often that fails). Standard library only.
#pragma once

#include "core/sign.h"
#include "float/bounded.h"

namespace wrenchkit::fl {

struct Finger_twin {
  Bounded px, py, nx, ny;  // the finger's point and inward normal (any length)
};

// Sign::positive: closed; negative: open (some condition is certainly ≤ 0, a boundary included); uncertain.
Sign nguyen_twin(const Finger_twin& a, const Finger_twin& b, const Bounded& mu);

}  // namespace wrenchkit::fl
