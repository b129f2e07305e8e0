// [PU-1] [FL-8] The float twin of the voting theorem: see push_twin.h; the error bounds are float/bounded.h's
// (proofs/notes/FL-1-bounded-arithmetic.md), so each sign returned is the exact sign of the polynomial.
#include "float/push_twin.h"

#include "core/voting_rule.h"

namespace wrenchkit::fl {

Push_twin_answer push_twin(const Push_twin_input& in) {
  Push_twin_answer a;
  // the lines: n ± μ rot90 n (rot90 n = (−ny, nx)), and v — the contacts' construction (core/contact_generators.h)
  const Bounded mny = in.mu * in.ny, mnx = in.mu * in.nx;
  const Bounded d[3][2] = {{in.nx - mny, in.ny + mnx}, {in.nx + mny, in.ny - mnx}, {in.vx, in.vy}};
  Bounded D, N[3];
  for (std::size_t i = 0; i < in.x.size(); ++i) {
    D = D + in.w[i];
    const Bounded ax = in.px - in.x[i], ay = in.py - in.y[i];
    for (int k = 0; k < 3; ++k) N[k] = N[k] + in.w[i] * (ax * d[k][1] - ay * d[k][0]);
  }
  a.friction = D.sign();
  for (int k = 0; k < 3; ++k) a.votes[k] = N[k].sign();
  if (a.friction != Sign::positive) return a;
  for (const Sign s : a.votes)
    if (s == Sign::uncertain) return a;
  const int l = static_cast<int>(a.votes[0]), r = static_cast<int>(a.votes[1]), v = static_cast<int>(a.votes[2]);
  a.rotation = voting_rule_sense(l, r, v);
  a.certain = !(a.rotation == 0 && none_needs_smooth(l, r));
  return a;
}

}  // namespace wrenchkit::fl
