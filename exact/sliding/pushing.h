// [PU-1] Pushing (Mason ch. 7; docs/pushing.md): which way a pushed body turns, whatever its pressure distribution —
// Mason's voting theorem, exact, over the support's admissible distributions F (exact/sliding/motion.h's one model).
//
// A pusher (scene "pusher": a point contact p with inward normal n, coefficient μ, moving with velocity v, v·n > 0)
// pushes a body sliding quasi-statically on its support. Three directed lines through p vote: the friction cone's
// edges n + μ·rot90 n ("left") and n − μ·rot90 n ("right"), and v. A line along d votes by the side of the centre
// of friction c it passes — counter-clockwise when (p − c) × d > 0, clockwise when < 0, "through" c when 0 — where
//
//   c(f) = (Σ_i μ_i f_i r_i + Σ_R μ_R ∫_R r p) / D(f),   D(f) = Σ_i μ_i f_i + Σ_R μ_R W_R  (> 0: friction under the body)
//
// so each vote is the sign of N_d(f) = Σ_i μ_i f_i (p − r_i) × d + Σ_R μ_R (W_R p − M_R) × d, linear in f: constant
// on a known distribution, bracketed over F by the exact LP (distribution.h maximise_over, its dual the proof).
//
// The rule (proofs/notes/PU-1-voting-theorem.md proves it, with every tie):
//   the edges vote alike (both ccw or both cw)     → that sense;
//   the edges vote apart (one ccw, one cw)         → the velocity's vote; "none" (a translation) when v passes c;
//   one edge through c, the other votes s         → s when the velocity votes s, else "none" (a translation along pc);
//   both edges through c (μ = 0 along pc, or c = p) → "none".
// "none" holds for every distribution whose friction does not lie on one line through c (then the translation's
// limit-surface point is smooth); where F admits such a distribution, "undecided" with that reason. When a vote's
// sign changes over F (the coefficients μ differ and some forces are not given), the rule at the LP's extreme
// distributions may find two that turn opposite ways: "depends", with both as witnesses; else "undecided".
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/mode.h"
#include "exact/sliding/motion.h"
#include "exact/sliding/precise_motion.h"
#include "exact/sliding/push_locus.h"
#include "exact/sliding/stable_push.h"

namespace wrenchkit {

enum class Rotation { ccw, cw, none, depends, undecided };
const char* rotation_name(Rotation r);  // "ccw", "cw", "none", "depends", "undecided"

// A linear function of the distribution over F, Σ_i coef_i f_i + constant: its range [lower, upper], exact (equal
// when F is one distribution), and, some force not given, each bound with the distribution attaining it and the LP's
// dual (y0, yx, yy): coef_i ≤ y0 + yx x_i + yy y_i for every unknown i proves upper; (−coef) the same proves lower.
struct F_range {
  Rational lower, upper;
  std::vector<Rational> argmin, argmax;
  std::optional<std::array<Rational, 3>> dual_lower, dual_upper;
  int lower_sign() const { return sgn(lower); }
  int upper_sign() const { return sgn(upper); }
};

enum class Push_line { left, right, velocity };
const char* push_line_name(Push_line l);  // "left edge", "right edge", "velocity"

struct Push_vote {
  Push_line line;
  Vec2 direction;  // d
  F_range value;   // N_d over F
  // The vote over F: +1 ccw, −1 cw, 0 through c (the same for every distribution), or nullopt (it changes over F).
  std::optional<int> sign() const;
};

// [PU-2] The contact mode for a support of points with every force given (proofs/notes/PU-2-contact-mode.md): the
// sticking candidate — the twist whose velocity at p is the pusher's, v_p + ω·rot90(r − p) at r, and whose frictional
// load passes through p — has ω* the root of g(ω) = Σ ρ_i ((r_i − p) × v_i(ω)) / |v_i(ω)| (ρ_i = μ_i f_i), which is
// nondecreasing (the derivative of the convex power along the rotation about p). ω* is bracketed by exact signs of g
// at rationals (square roots bracketed by rationals, `bits` of them), and the bracket narrowed until the load's
// force F(ω*) is certified strictly inside the pusher's friction cone (sticks) or strictly beyond one edge (the
// sticking motion would need more friction than the contact has: it slides, its force on the edge F passed within
// the half-plane of forces whose normals push — "slides left" on n + μ·rot90 n, "slides right" on n − μ·rot90 n).
// ω* = 0 exactly when v_p passes through the centre of friction (a translation, F along v_p: exact), and when v_p is
// perpendicular to r_j − p for a support point j whose facet holds the root (a sticking pivot, §7: the rotation about
// r_j, sticking when its facet has a force strictly inside the cone, sliding when all its forces through p are beyond
// one edge, §8). Undecided: F (or a pivot's forces) within the resolution of a cone edge after narrowing, regions,
// forces not given. `push --contact` (certificate §8.2).
// impending: F exactly on a cone edge (only when exact: ω* = 0, a translation along v_p on the cone's edge).
// depends (forces not given): two extreme distributions of F whose modes differ, each certified (`witnesses`).
enum class Push_mode { sticks, impending, slides_left, slides_right, depends, undecided };
const char* push_mode_name(Push_mode m);  // "sticks", "impending", "slides left", "slides right", "depends", "undecided"

struct Push_contact {
  Push_mode mode = Push_mode::undecided;
  Rational omega_lo, omega_hi;  // the sticking candidate's rotation rate: g(lo) < 0 < g(hi), or lo = hi = ω* exactly
  // slides: the candidate of the tangent velocity t = rot90 n (its force F(t) bounds the pushing half-plane)
  bool has_tangent = false;
  Rational tangent_lo, tangent_hi;
  // …or the rotation about this support point (PU-2 §8: t ⟂ r_k − p, tangent_lo = tangent_hi its rate): F(t) is its
  // facet's chord, every force of which is on the left of the edge slid on
  std::optional<std::size_t> tangent_pivot;
  int bits = 64;                // the square roots' precision every sign was certified at
  std::string why;              // undecided: the reason
  // slides (PU-2 §5): the body's motion. Its velocity at p is v + τ·rot90(n) (the pusher's, plus the slip τ along the
  // tangent) with τ* in [slip_lo, slip_hi]; the rate ω* of its twist in [motion_lo, motion_hi] for every τ there; at
  // each end of the slip bracket the candidate's own bracket (slip_omega), whose force is on either side of the edge.
  // Exact (slip_lo = slip_hi, ω* = 0) when the edge's line through p passes through the centre of friction.
  bool has_motion = false;
  Rational slip_lo, slip_hi, motion_lo, motion_hi;
  std::array<std::array<Rational, 2>, 2> slip_omega;
  // the sticking motion is the rotation about this support point (PU-2 §7–8): the rate ω* exact (omega_lo = omega_hi);
  // sticks with `force` the direction of a force of its facet strictly inside the cone, or slides (§8) with every
  // force of its facet through p beyond the edge it slides on
  std::optional<std::size_t> pivot;
  std::optional<Vec2> force;
  std::optional<std::size_t> motion_pivot;  // slides as a rotation about this support point (§6): slip, rate exact
  std::string motion_why;       // slides, but the motion not bracketed: the reason
  // depends: two distributions of F (`forces`, one per support point) and each one's certified mode
  std::vector<Rational> forces;
  std::vector<Push_contact> witnesses;
};
// The contact mode over forces not given is sought at F's extreme distributions: at most this many unknown forces,
// and this many distributions tried.
constexpr std::size_t kMaxContactUnknowns = 12;
constexpr std::size_t kMaxContactCorners = 64;
constexpr std::size_t kMaxSlowestCorners = 16;

// [PU-4 §5] A distribution of F that turns the body slowly: among the given forces (or up to 16 extreme distributions
// of F), the one whose certified rotation rate ω (PU-2: sticking or sliding, its sense certain) has the smallest
// |ω|_hi — its `contact`, with `forces` set — and `arm_lo`, a short decimal at most v·n/(|ω|_hi |n|): its rotation
// centre is at least that far from the pusher's normal line. `given`: the contact mode already found for the given
// forces (push --contact), reused rather than searched again. None for regions, or when no distribution tried has
// such a rate.
struct Slowest_turn {
  Push_contact contact;
  Rational arm_lo;
};
std::optional<Slowest_turn> slowest_turn(const Support_model& model, const Pusher& pusher, const Rational& tolerance,
                                         const std::optional<Push_contact>& given = std::nullopt);

// The senses (ccw, cw) a push's rotation leaves for its rotation centres (push_locus): ccw or cw that one, none
// neither (a translation), undecided both.
inline std::array<bool, 2> senses_left(Rotation r) {
  return {r == Rotation::ccw || r == Rotation::undecided, r == Rotation::cw || r == Rotation::undecided};
}
Push_contact push_contact_mode(const Support_model& model, const Pusher& pusher, const Rational& tolerance);

// The centre of the body's rotation with velocity u at the point p and rate ω ≠ 0: p + rot90(u)/ω, the point x where
// u + ω·rot90(x − p) = 0 (the text and the picture of push --contact).
Vec2 rotation_centre(const Vec2& p, const Vec2& u, const Rational& omega);

struct Push_answer {
  Vec2 at, normal, velocity;
  Rational mu;
  bool known = true;               // F is one distribution
  F_range friction;                // D over F: its lower bound > 0 (the minimum only: upper = lower)
  std::optional<Vec2> center;      // c, when every distribution of F has the same (always when known)
  std::array<Push_vote, 3> votes;  // left edge, right edge, velocity
  Rotation rotation = Rotation::undecided;
  std::string why;                 // the rule that decided, in words; undecided: the reason
  // depends: two distributions of F and the senses they turn (ccw, cw)
  std::vector<Rational> turns_ccw, turns_cw;
  // "none": whether a distribution of F may put all its friction on one line through c (then not "none" but undecided)
  bool line_friction_possible = false;
  bool by_twin = false;  // decided by the float twin's certified signs (no exact values: no certificate from it)
  std::optional<Push_contact> contact;  // the contact mode, when asked (PU-2)
  bool votes_known = true;  // false: the float twin could not decide, or a line pusher (no votes), `votes` is empty
  std::optional<Stable_push> stable;  // a line pusher (PU-3): is its motion stable
  std::optional<Stable_region> region;  // a line pusher's stable region, when asked (PU-3 §6)
  std::optional<Push_locus> locus;  // a point pusher's rotation centres over every distribution, when asked (PU-4)
  // with the locus: a distribution that turns the body slowly and arm_lo ≤ its centre's distance from the pusher's normal
  // line (slowest_turn) — the slowest turn's arm is in [arm_lo, locus->arm_hi]
  std::optional<Slowest_turn> slowest;
};

// The rotation sense of the body pushed by `pusher` on `model`'s support. Throws Input_error when some distribution
// of F has no friction (D = 0: nothing resists the push, the motion is not quasi-static).
// The mode: exact (everything in rationals, what a certificate is written from); float_only — the float twin
// (float/push_twin.h) on a support of points with every force given: its certified signs, or `undecided` (regions,
// forces not given, or a sign its bounds cannot decide); hybrid — the twin first, the exact decision when it cannot
// tell. An answer of the twin has `by_twin` set and its votes' ranges hold only their signs (−1, 0, 1).
Push_answer decide_push(const Support_model& model, const Pusher& pusher, Mode mode = Mode::exact);

// A line pusher (pusher.line(), PU-3): `stable` decided (stable_push.h), exact in every mode; the rotation is the
// pusher's own when stable (the body moves with it), else undecided (a line contact's sliding is not answered).
Push_answer decide_line_push(const Support_model& model, const Pusher& pusher);



// The centre of friction of the distribution f (one force per support point; the regions' pressure is known):
// (Σ μ_i f_i r_i + Σ_R μ_R M_R) / D. Precondition: D > 0.
Vec2 friction_center(const Support& s, const std::vector<Rational>& f);

// The voting rule (core/voting_rule.h) on one distribution's three votes (left edge, right edge, velocity; +1, −1,
// 0), for a support whose friction does not lie on one line through c: ccw, cw or none.
Rotation voting_rule(int left, int right, int velocity);

}  // namespace wrenchkit
