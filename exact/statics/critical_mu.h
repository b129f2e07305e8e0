// [QL-2] How much friction does the grasp need: the critical friction coefficient μ*, common to every point contact,
// at which the contacts come into force closure, and at which they balance the scene's load (docs/quality.md,
// proofs/notes/QL-2-critical-friction.md, proofs/certificate-format.md §3.5).
//
// With μ common to the point contacts, contact i's edges are a_i ± μ·b_i (a_i = W(p_i, n_i), b_i = W(p_i, rot90 n_i));
// the cones grow with μ, so closure holds on an open half-line (μ*, ∞) and balance on a closed one [μ*, ∞). Between
// two consecutive roots of the minors of the edges (cubics in μ for 3×3 determinants) the edges' oriented matroid is
// constant, and so are both answers: μ* is a root of such a minor — an algebraic number of degree at most 3.
//
// Decision: μ = 0 decides "always"; the limit cone pos{a_i, ±b_i} decides "never" for closure (and for balance when
// the load is outside it; else balance beyond the minors' root bound); otherwise a binary search over the gaps between
// the minors' roots found in doubles (hints only), then bisection on rationals, each step an exact closure or
// equilibrium decision. μ* is exact when it is rational: the simplest rational of a narrow
// bracket that is a root of a minor and lies on the right side, proved by the minors' constant signs on a one-sided
// interval beside it (Descartes' rule); otherwise a bracket of the tolerance's width. Certificates on both sides.
#pragma once

#include <optional>
#include <string>

#include "core/mode.h"
#include "exact/io/scene.h"
#include "exact/statics/closure.h"
#include "exact/statics/equilibrium.h"

namespace wrenchkit {

enum class Critical_kind { value, always, never };
// common: one μ for every point contact (the scene's own set aside); proportional: every contact's own μ times one
// factor t (the friction margin: closed for every t above t*).
enum class Friction_scaling { common, proportional };
const char* critical_kind_name(Critical_kind k);  // "value", "always", "never"

// μ* of one property. value: μ* ∈ [lower, upper] (lower = upper: exact). The evidence: the property fails at
// `below_mu` (a twist) and holds at `above_mu` (a combination); `constant`: the minors keep their signs strictly
// between them and at the end that is not μ* (the exact case: μ* is below_mu, the property failing at μ* and holding
// just above it — closure, or balance when the cone at μ* holds a line —, or above_mu, holding at μ*). always: holds at μ = 0 (above). never: a twist with
// power ≥ 0 against every a_i, 0 against every b_i (and > 0 against the load) — `limit_twist` —, or, for the load, it
// fails at below_mu and the minors keep their signs on [below_mu, ∞) (`constant_beyond`).
struct Critical_mu {
  Friction_scaling scaling = Friction_scaling::common;  // (μ, or the factor t on the scene's μ)
  Critical_kind kind = Critical_kind::value;
  Rational lower, upper;
  bool exact() const { return kind == Critical_kind::value && lower == upper; }
  std::optional<Rational> below_mu, above_mu;
  Closure_certificate below_closure, above_closure;          // of force closure
  Equilibrium_certificate below_balance, above_balance;      // of equilibrium
  bool constant = false, constant_beyond = false;
  bool holds_at_critical = false;  // exact: the property holds at μ* itself (balance on [μ*, ∞)), or only above it
  std::optional<Vec3q> limit_twist;
  std::size_t decisions = 0;  // closure or equilibrium decisions made
};

struct Critical_answer {
  Critical_mu closure;                     // force closure, one μ for every point contact
  std::optional<Critical_mu> equilibrium;  // the scene's load, when it has one
  // The friction margin: the least factor t* on every contact's own μ at which the grasp is closed (t* < 1: the μs may
  // shrink to t* of theirs and it stays closed), when some contact has friction.
  std::optional<Critical_mu> margin;
};

// The scene with every point contact's μ set to `t` (common; a contact frictionless in the scene included) or
// multiplied by `t` (proportional).
Scene at_mu(const Scene& scene, const Rational& t, Friction_scaling scaling);
// The same in place: `s` is `scene` or a copy of it (contacts in the same order) that set_mu may have changed before;
// its μs are set from `scene`'s (a search reuses one scene's storage for every μ it decides).
void set_mu(Scene& s, const Scene& scene, const Rational& t, Friction_scaling scaling);
inline Scene at_common_mu(const Scene& scene, const Rational& mu) { return at_mu(scene, mu, Friction_scaling::common); }

// Throws Input_error for a scene without point contacts. `tolerance`: the bracket's width relative to its upper end
// when μ* is not found rational. Mode::float_only is not offered (the caller says undecided); hybrid and exact decide
// each step in that mode.
// Bounded work: refused (Input_error naming the bound) past 24 point contacts — the minors grow as the cube of their
// number (40 contacts take a second and 50 MB).
constexpr std::size_t kCriticalMaxPointContacts = 24;
void check_critical_size(const Scene& scene);  // the bound and the no-point-contact case, as decide_critical_mu refuses
Critical_answer decide_critical_mu(const Scene& scene, Mode mode, const Rational& tolerance);

}  // namespace wrenchkit
