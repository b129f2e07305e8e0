// [LB-3] Moment labeling (theory.md §5) and Reuleaux's method (§7), exactly, from the one exact
// representation of W* (exact/statics/wrench_cone.h [LB-2]).
//
// Under P(t) = (−v_y, v_x, ω) the labeled set is W* on the two-sided plane: R₊ = its front sheet
// (the centres c with M_c(w) ≥ 0 for every w ∈ W: counter-clockwise rotation centres), R₋ = its back
// sheet (clockwise centres), R∞ = its points at infinity (translations), and the ± set = R₊ ∩ R₋ =
// the lineality of W* on the front sheet (every line of force passes through it). The regions are
// slices of W*'s generators (exact/statics/planar_region.h [LB-1]): exact rational vertices in
// counter-clockwise order and primitive integer recession directions, every degenerate shape an
// ordinary answer. For frictionless contacts the same labels are Reuleaux's feasible rotation
// centres (§7), and per-contact modes of a twist follow from the sign of v(p)·n.
#pragma once

#include <string>
#include <vector>

#include "exact/statics/planar_region.h"
#include "exact/statics/wrench_cone.h"

namespace wrenchkit {

// The ± set: nothing, one point, one line (through `point` along `direction`), or the whole plane.
struct Both_set {
  enum class Kind { none, point, line, plane };
  Kind kind = Kind::none;
  Vec2 point, direction;
};

struct Moment_labels {
  Wrench_cone cone;
  Region plus, minus;
  Both_set both;
  Cone2 infinity;
  // Force closure ⇔ nothing is labeled, infinity included (theory.md §5.5).
  bool nothing_labeled() const {
    return plus.empty() && minus.empty() && both.kind == Both_set::Kind::none && infinity.shape == Cone2::Shape::zero;
  }
};

// `mode` exact or hybrid (the same answer; see wrench_cone).
Moment_labels moment_labels(const std::vector<Vec3q>& generators, Mode mode = Mode::exact,
                            const std::vector<fl::Bounded3>* twin = nullptr);
Moment_labels moment_labels(const Scene& scene, Reading reading, Mode mode = Mode::exact);

// Reuleaux's per-contact modes for a twist t (theory.md §7): v(p)·n > 0 break, = 0 with v(p) ≠ 0
// slide, v(p) = 0 stick (the rotation centre is the contact point), < 0 penetrate. A pure wrench
// generator has no point and no mode ("none"; its power sign is reported instead).
enum class Contact_mode { breaks, slides, sticks, penetrates, none };
const char* mode_name(Contact_mode m);
struct Mode_answer {
  std::vector<Contact_mode> modes;  // per contact
  bool feasible = true;             // no contact penetrates (and no wrench generator has power < 0)
  bool marginal = false;            // feasible and some contact is kept (slides or sticks)
};
Mode_answer contact_modes(const Scene& scene, const Vec3q& twist);

// The twist of a rotation about c (sense +1 counter-clockwise, −1 clockwise) and of a translation
// that reaches the point at infinity d: P(t) is then (c, 1), −(c, 1) resp. (d, 0).
Vec3q rotation_twist(const Vec2& c, int sense);
Vec3q translation_twist(const Vec2& d);

}  // namespace wrenchkit
