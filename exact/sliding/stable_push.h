// [PU-3] Stable pushing with a line contact (Lynch & Mason, IJRR 15(6) 1996; proofs/notes/PU-3-stable-pushing.md):
// does the body stay fixed to a pusher that touches it along a segment, for every pressure distribution?
//
// The pusher (scene "pusher" with "segment") touches the body along [e0, e1] with inward normal n and coefficient μ,
// and moves as a rigid body: velocity v at the segment's middle m and rotation rate ω — a rotation about
// q = m + rot90(v)/ω (sense σ = sign ω), or a translation (ω = 0). The body fixed to it has a frictional load; the
// push is **stable** when that load lies in the composite friction cone CF of the segment (forces inside the cone
// whose line crosses the segment: four facets) for every distribution of the support's friction on S — the support's
// points and regions with μ > 0 — whose centre is the centre of friction c (fixed: every force given, or one μ).
//
//   translation: the load is v through c, the same for every distribution: four exact signs decide (≥ 0 each:
//     stable; some facet 0 is the load on CF's boundary, still sticking; one < 0: unstable).
//   rotation: sufficient, distribution-free (PU-3 §2, §3, §5): both direction facets by S's extreme vertices, one end's
//     moment by the bisector of that end and c, the other's by the tip line with its correction E — four rational
//     inequalities (√ bracketed: R ≤ R_hi, d_lo ≤ |q − c|, α_hi ≥ |c − end|). Else a **witness**: one, two or three
//     points of S with weights whose mean is c, whose load is certainly beyond a facet (its sign from square roots
//     bracketed at `bits`): unstable. On a support of points (at most 48), a facet whose condition fails is decided by
//     the linear program over the distributions: a witness, or its dual proving the facet for all of them (§7).
//     Neither: undecided (the load on the cone's boundary, or a region's support where the conditions are sufficient,
//     not necessary).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "exact/sliding/motion.h"

namespace wrenchkit {

enum class Stability { stable, unstable, undecided };
const char* stability_name(Stability s);  // "stable", "unstable", "undecided"

// The composite cone's facets: the load's force left of the cone's left edge n + μ·rot90 n, right of its right
// edge, and its line past either end of the segment (its moment about that end of the wrong sign). Ends by their index
// in the scene's "segment".
enum class Cone_facet { left_edge, right_edge, end0, end1 };
const char* cone_facet_name(Cone_facet f);  // "left edge", "right edge", "end 0", "end 1"

struct Stable_push {
  Stability verdict = Stability::undecided;
  std::string why;
  int sense = 0;                   // +1 ccw, −1 cw (the pusher's rotation), 0 a translation
  std::optional<Vec2> centre;      // q, rotating
  std::optional<Vec2> friction_centre;  // c (none: it moves with the distribution — undecided)
  Rational R2;                     // max |x − c|² over S's vertices
  // stable, rotating (PU-3 §5): R ≤ R_hi, d_lo ≤ |q − c| with d_lo > R_hi, α_hi ≥ |c − tip end|; the tip line bounds
  // end `tip`'s moment, the bisector the other's
  Rational R_hi, d_lo, alpha_hi;
  std::size_t tip = 0;
  bool tip_line = false;  // the tip facet proven by the corrected tip line (else by a dual)
  // stable, rotating on a support of points (PU-3 §7): a facet whose condition fails may be proven by the dual
  // (y0 < 0, yx, yy) of the LP over the distributions: g_i ≤ y0 + y·(x_i − c) at every point, √ at `bits`
  std::vector<std::pair<Cone_facet, std::array<Rational, 3>>> duals;
  // translating: each facet's value, ≥ 0 when it holds (left edge v × e₊, right edge e₋ × v, the ends' moments
  // signed so); the facets at 0 are the load on CF's boundary
  std::array<Rational, 4> values;
  // unstable: the facet the load leaves CF by; rotating, the distribution (points of S, weights > 0 with mean c) and
  // the bits its square roots were bracketed at
  Cone_facet facet = Cone_facet::left_edge;
  std::vector<Vec2> points;
  std::vector<Rational> weights;
  int bits = 64;
  // the voting theorem's corners (PU-1 with a line contact): +1 when both cone edges' lines through both ends pass c
  // on its left ((e_k − c) × e > 0: every force the pusher can apply turns the body ccw), −1 on its right, else 0
  int corners = 0;
};

// Precondition: pusher.line(). Throws Input_error when nothing under the body has friction.
Stable_push decide_stable_push(const Support_model& model, const Pusher& pusher);

// [PU-3 §6] The stable region: the rotation centres q of each sense certified stable for every distribution by PU-3's
// four conditions — four half-planes a·q ≤ b each (left edge, right edge, the bisector's end, the tip end) — and the
// translations' directions. The tip line's half-plane is (c − e_t)·(q − c) ≥ T with T/α_hi > R_hi and T ≥ R² +
// E(T/α_hi, α_hi, R_hi): every q in it has |q − c| ≥ T/α > R and E(|q − c|) ≤ E(T/α_hi) (E falls with d), so §5 holds
// there. An inner region: a centre outside may be stable too (the query decides it). `polygon` is the intersection
// clipped to `box` (counter-clockwise, empty when it misses the box).
struct Halfplane {
  Vec2 a;
  Rational b;  // a·q ≤ b
};
struct Stable_region_side {
  bool possible = false;           // false: the tip end is the centre of friction (no tip line), nothing certified
  std::array<Halfplane, 4> halfplanes;  // left edge, right edge, end 0, end 1
  std::size_t tip = 0;             // the end the tip line bounds (the other: the bisector)
  Rational T, alpha_hi;
  std::vector<Vec2> polygon;
};
struct Stable_region {
  std::optional<Vec2> friction_centre;  // none: it moves with the distribution (no region)
  std::string why;                      // no region: the reason
  Rational R2, R_hi;
  std::array<Stable_region_side, 2> side;  // [0] ccw (ω > 0), [1] cw
  std::array<Vec2, 2> box;                 // [lower-left, upper-right]: the scene's box widened by 10 sizes
  // translating: the directions v with the four facets ≥ 0 — the cone from `translations[0]` counter-clockwise to
  // `translations[1]` (equal: one direction), none when empty
  std::optional<std::array<Vec2, 2>> translations;
};
Stable_region stable_region(const Support_model& model, const Pusher& pusher);

// What PU-3's bounds need of the support, shared with a point pusher's locus (push_locus.h): S's vertices (the support
// points and region rings with μ > 0), the centre of friction c when it is one point for every distribution (every
// force given, or one μ: else `why`), and R² = max |x − c|² over S's vertices. Throws Input_error when nothing under
// the body has friction.
struct Friction_disc {
  std::vector<Vec2> vertices;
  std::optional<Vec2> c;
  std::string why;
  Rational R2;
};
Friction_disc friction_disc(const Support_model& model);

// [PU-3 §5–6] The corrected tip line's offset: the least short decimal T with T/α_hi > R_hi and T ≥ R² +
// E(T/α_hi, α_hi, R_hi). For a point y with |c − y| ≤ α_hi, every rotation centre q with (c − y)·(q − c) > T has the
// load's moment about y strictly of the sense's opposite sign (§5) — the load's line misses y — for every distribution
// with centre c on B(c, R), R ≤ R_hi. None when no T is found (then nothing is certified).
std::optional<Rational> tip_line_T(const Rational& R2, const Rational& R_hi, const Rational& alpha_hi);

// x rounded outward to `digits` decimals (up or down): short numbers for a certificate a person reads.
Rational outward(const Rational& x, int digits, bool up);

// The convex polygon `poly` (counter-clockwise) cut by h (Sutherland–Hodgman, exact).
std::vector<Vec2> clip(const std::vector<Vec2>& poly, const Halfplane& h);

}  // namespace wrenchkit
