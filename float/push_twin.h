// [PU-1] [FL-8] The float twin of the voting theorem (exact/sliding/pushing.h) for a support of points with every force
// given: the friction under the body D = Σ w_i (w_i = μ_i f_i) and each line's vote numerator
// N_d = Σ w_i (p − r_i) × d in Bounded arithmetic (float/bounded.h) — certified signs or uncertain, never a guess —
// and the rule (core/voting_rule.h). Standard library only.
#pragma once

#include <vector>

#include "core/sign.h"
#include "float/bounded.h"

namespace wrenchkit::fl {

struct Push_twin_input {
  std::vector<Bounded> x, y, w;  // the support points and μ_i f_i
  Bounded px, py, nx, ny, mu, vx, vy;
};

struct Push_twin_answer {
  Sign friction = Sign::uncertain;  // D's sign
  Sign votes[3] = {Sign::uncertain, Sign::uncertain, Sign::uncertain};  // left edge, right edge, velocity
  bool certain = false;  // every sign certain, D > 0, and the rule's answer not a "none" that needs the support's shape
  int rotation = 0;      // (certain) +1 ccw, −1 cw, 0 none
};

Push_twin_answer push_twin(const Push_twin_input& in);

}  // namespace wrenchkit::fl
