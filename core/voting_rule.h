// [PU-1] Mason's voting rule (proofs/notes/PU-1-voting-theorem.md §4), shared by the exact engine and the float twin:
// the rotation sense of a pushed body from the votes of three directed lines through the pusher — the friction
// cone's left edge, its right edge, and the pusher's velocity — each +1 (ccw: the centre of friction on its left),
// −1 (cw) or 0 (through the centre). Returns +1 ccw, −1 cw, 0 none (a translation).
// Standard library only.
#pragma once

namespace wrenchkit {

inline constexpr int voting_rule_sense(int left, int right, int velocity) noexcept {
  if (left != 0 && left == right) return left;                          // the edges alike
  if (left != 0 && right != 0) return velocity;                         // apart: the velocity (0: a translation)
  if (left == 0 && right == 0) return 0;                                // every line of the cone through c
  return velocity == (left != 0 ? left : right) ? velocity : 0;         // one edge through c
}

// Does the rule's "none" rest on the translation's point of the limit surface being smooth (§4)? Every "none" but
// the one of edges voting strictly apart.
inline constexpr bool none_needs_smooth(int left, int right) noexcept {
  return !(left != 0 && right != 0 && left != right);
}

}  // namespace wrenchkit
