// [PU-4] Where a pushed body may turn about, for every pressure distribution (Peshkin & Sanderson's locus of rotation
// centres, IEEE J. Robotics and Automation 4(6) 1988; proofs/notes/PU-4-rotation-centres.md): an outer bound of the
// rotation centres of a body pushed by a point pusher, over every distribution on its support with the centre of
// friction c (fixed: every force given, or one μ), and the slowest it can turn.
//
// The body turns about q (sense σ, +1 ccw) as the pusher at p (inward normal n, friction cone edges e₊ = n + μ·rot90 n,
// e₋ = n − μ·rot90 n, velocity v) pushes it. Whatever the distribution, q satisfies (PU-4 §2–§4):
//   - the bisector (PU-3 §3): |q − p| ≥ |q − c| — else the load's moment about p is not 0;
//   - the tip line (PU-3 §5): (c − p)·(q − c) ≤ T, T from tip_line_T (R² the support's largest squared distance
//     from c, α = |c − p|) — else the moment about p is strictly negative;
//   - the contact advances: σ (p − q) × n ≥ 0 (the body's velocity at p has the pusher's normal component v·n > 0);
//   - and by the contact mode: sticks — q on the line through p perpendicular to v, the load inside the cone (some
//     place x of the support with σ(x − q)·e₊ ≤ 0, some with σ(x − q)·e₋ ≥ 0); slides left — the load along e₊
//     (min_S x·e₊ ≤ q·e₊ ≤ max_S x·e₊) and the body slipping along −rot90 n (σ (p − q)·v ≤ 0); slides right — along
//     e₋ and σ (p − q)·v ≥ 0.
// Each piece is an intersection of rational half-planes. Only the senses the voting theorem allows (`rotation`) are
// answered. When every piece is bounded, the rotation centre is within `arm_hi` of the pusher's normal line: the body
// turns by at least s/arm_hi radians while the pusher advances s along n (Peshkin's rate bound, instantaneous).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "exact/sliding/stable_push.h"

namespace wrenchkit {

// Why a half-plane holds the rotation centres: its words in the answer.
enum class Locus_bound { bisector, tip_line, advance, left_edge, right_edge, line, along_left, along_right, slip };
const char* locus_bound_name(Locus_bound b);

struct Locus_halfplane {
  Locus_bound why;
  Halfplane h;  // a·q ≤ b
};

// The contact mode a piece holds the centres of (PU-2's words: "sticks", "slides left", "slides right").
enum class Locus_mode { sticks, slides_left, slides_right };
const char* locus_mode_name(Locus_mode m);

struct Locus_piece {
  Locus_mode mode = Locus_mode::sticks;
  std::vector<Locus_halfplane> halfplanes;
  bool bounded = false;  // the intersection is bounded (its polygon exact) — else `polygon` is its part in the box
  std::vector<Vec2> polygon;  // counter-clockwise; 1 or 2 vertices when a point or a segment; empty when none
};

struct Locus_side {
  bool possible = false;  // the voting theorem allows this sense
  std::array<Locus_piece, 3> pieces;  // sticks, slides left, slides right
};

struct Push_locus {
  std::optional<Vec2> friction_centre;  // none: it moves with the distribution (no locus: `why`)
  std::string why;
  Rational R2, R_hi, alpha_hi;  // R² = max |x − c|², R ≤ R_hi, |c − p| ≤ alpha_hi
  std::optional<Rational> T;    // the tip line's offset (none: p = c or not found, no tip line)
  std::array<Locus_side, 2> side;  // [0] ccw, [1] cw
  std::array<Vec2, 2> box;         // the unbounded pieces drawn within it: [lower-left, upper-right]
  std::optional<Rational> arm_hi;  // every piece bounded: the centre's distance from the normal line ≤ arm_hi
  std::string arm_why;             // no arm: the reason
};

// Precondition: !pusher.line(). `allowed` the senses (ccw, cw) the push's certified rotation leaves (decide_push: ccw or
// cw that sense, none neither — the body translates —, undecided both). Throws Input_error when nothing under the body
// has friction.
Push_locus push_locus(const Support_model& model, const Pusher& pusher, const std::array<bool, 2>& allowed);

}  // namespace wrenchkit
