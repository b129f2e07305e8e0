// [QL-1] How good is the grasp: the Ferrari–Canny quality ε of the contacts with their friction, exact or in a
// certified bracket (docs/quality.md, proofs/notes/QL-1-quality.md, proofs/certificate-format.md §3.4).
//
// The grasp wrench space of the planar contacts is a convex polytope in (fx, fy, s·m) — m the moment about the
// point `about`, s the torque scale — built from each contact's friction-cone edges scaled so that a contact's
// force is at most one unit (the normalisation):
//   L1   conv{every scaled edge}             (the contacts' normal forces sum to at most 1);
//   L∞   Σ_i conv{0, contact i's scaled edges} (each contact's normal force at most 1; a Minkowski sum).
// ε is the radius of the largest ball about the origin inside it: 0 unless the contacts are in force closure.
//
// Exact: the edges of proofs/certificate-format.md §1 are rational; a normalisation multiplies contact i's edges by
// c_i = 1/√q_i (q_i = |n_i|² for unit-normal, |n_i|²(1 + μ_i²) for unit-force, 1 as given). When every c_i is
// rational, ε² is rational and given exactly. Otherwise c_i is replaced by a rational c̃_i within η_i of it, ε̃ of
// the rational polytope computed exactly, and ε bracketed by ε̃ ± δ (δ the generators' largest displacement, L1, or
// their sum over the contacts, L∞: ε is 1-Lipschitz in the support function) to the relative tolerance asked.
//
// L1: an exact incremental convex hull of the (at most a few hundred) scaled edges; its triangles are the
// certificate's closed, positively oriented boundary, and ε² = min over them of b²/|n|². L∞: the facets of a
// Minkowski sum of triangles have normals among the triangles' normals and the cross products of two contacts'
// edge directions; ε = min over those O(n²) candidates of the support function over |d|, O(n³) in all.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "core/mode.h"
#include "exact/io/scene.h"
#include "exact/numbers/vectors.h"
#include "exact/statics/closure.h"

namespace wrenchkit {

enum class Quality_norm { l1, linf };
// The peers' conventions in one word: GraspIt! (unit-normal edges, moments about the body's centre of mass divided by
// its largest radius — the largest distance from body.com to a vertex of body.outline; L1 or L∞ as asked) and Dex-Net
// (unit-normal edges, moments about the centre of mass, its `torque_scaling` as the torque scale; its metric is L1).
enum class Quality_preset { none, graspit, dexnet };
enum class Force_normalization { unit_normal, unit_force, as_given };
const char* quality_norm_name(Quality_norm n);            // "L1", "Linf"
const char* normalization_name(Force_normalization n);    // "unit-normal", "unit-force", "as-given"

struct Quality_query {
  Quality_norm norm = Quality_norm::l1;
  Force_normalization normalize = Force_normalization::unit_normal;
  Rational torque_scale = 1;       // s > 0: the moment's weight against a force
  // s = 1/√r2 instead (GraspIt!'s 1/maxRadius): exact when r2 is a rational square, else certified within an error
  std::optional<Rational> torque_radius_squared;
  Quality_preset preset = Quality_preset::none;  // resolved against the scene by decide_quality
  std::optional<Vec2> about;       // the moments' point; default body.com when the scene has one, else the origin
  Rational tolerance{1ul, 1000000000000ul};  // the bracket's width relative to its lower end (ε not rational)
  // What to answer (the quality command): ε, and the critical friction coefficient μ* (critical_mu.h)
  bool epsilon = true, critical_mu = true;
  bool keep_planes = false;  // keep the wrench space's supporting planes in the answer (pictures)
  // Not Mode::exact: ε (L1) from the float twin when it certifies it (float/quality_twin.h), else as without. For
  // callers that need no certificate (the array API without certificates; the pipeline drops it when certifying):
  // the answer then has the bracket, closure's verdict and `twin` set, and none of the exact structures (points,
  // boundary, nearest, the closure certificate).
  bool twin_first = false;
  bool contact_margins = false;  // also each contact's distance to a degenerate configuration (contact_margins)
};

// One contact's scale: its edges are multiplied by `scale` (c̃_i); the true c_i = 1/√q_i lies within `error` of it
// (0: exact); `bound` ≥ |u| for each of its unscaled edges u (as wrenches about `about` with the torque scale).
struct Quality_scale {
  Rational q, scale, error, bound;
  Rational moment_bound;  // (an irrational torque scale) ≥ |m − about × f| for its edges
};

struct Quality_answer {
  Quality_query query;  // (the preset resolved: norm, normalize, about, torque scale or radius)
  Rational torque_scale_error;  // with query.torque_radius_squared: |s − query.torque_scale| ≤ it (0: exact)
  Vec2 about;                   // resolved
  Closure_answer closure;       // force closure of the contacts: ε > 0 exactly when it holds
  bool exact = false;           // ε² is rational and `squared` is it
  Rational squared;             // ε² (exact) or ε̃² (of the rational polytope)
  Rational lower, upper;        // ε ∈ [lower, upper]; lower = upper = ε when ε is rational
  std::vector<Quality_scale> scales;  // per contact
  std::vector<Generator_ref> refs;    // the generators (friction reading) in §1 order
  std::vector<Vec3q> points;          // their scaled wrenches (fx, fy, s·m about `about`), c̃ applied
  // ε > 0, L1: the boundary of conv(points), triangles of point indices, each positively oriented (det > 0), and
  // the one nearest the origin.
  std::vector<std::array<std::size_t, 3>> boundary;
  std::array<std::size_t, 3> nearest{};
  // ε > 0: the outward normal of a nearest facet (L1: of `nearest`; L∞: the candidate attaining the minimum)
  Vec3q normal;
  std::size_t hull_points = 0;  // L1: points on the hull (for the text)
  // ε > 0: supporting planes n·x ≤ b whose intersection is the (rational) wrench space — L1 its facets' planes, L∞ the
  // candidate normals with their support — for pictures (render --what quality), when the query keeps them.
  std::vector<std::pair<Vec3q, Rational>> planes;
  bool twin = false;  // decided by the float twin: lower and upper are its certified doubles, nothing exact above
};

// The quality of the scene's contacts (the friction reading, each contact with its own μ). Closure is decided in
// `mode` (Mode::float_only may leave it undecided: closure.decided false and nothing else set); ε itself is exact
// arithmetic, or (L1, query.twin_first, not Mode::exact) the float twin's certified bracket (`twin`); a closed
// grasp's ε is left unset in Mode::float_only otherwise. Throws Input_error for a scene without contacts or a question that does not apply (torque scale ≤ 0).
//
// Bounded work: ε of a closed grasp is refused (Input_error naming the bound) past 1024 friction-cone edges for L1
// (the hull grows as their square: 1 000 contacts take seconds) and past 48 contacts for L∞ (its candidates grow as
// the cube). Closure, and ε = 0 of an open grasp, have no such bound.
constexpr std::size_t kQualityMaxL1Edges = 1024, kQualityMaxLinfContacts = 48;
Quality_answer decide_quality(const Scene& scene, const Quality_query& query, Mode mode);
// The same into `out` (a default-constructed answer): the pipeline's item holds it, no second answer built.
void decide_quality_into(const Scene& scene, const Quality_query& query, Mode mode, Quality_answer& out);

// [QL-1 §6] How near each contact is to a degenerate configuration — the per-contact form of `compare`'s smallest
// deciding determinant (boundary_distance.h), over every triple of friction-cone edges rather than those one decision
// happens to evaluate. The edges as wrenches (fx, fy, s·m about `about`, the query's torque scale s and point, as ε
// takes them; no normalisation: the measure is invariant under each edge's scale); for three of them the relative
// volume |det(u, v, w)| / (|u||v||w|) ∈ [0, 1] (1: orthogonal, 0: coplanar); where two of them are one contact's
// edges, its normal and tangent wrenches W(p, n), W(p, rot90 n) stand for them (the same plane: the measure does not
// shrink with the cone's width; 0 when the third edge's line passes through the contact point). A verdict of closure (with friction) can
// change only where some such determinant passes through zero, so a contact whose every triple stays away from 0 is
// away from any change of the grasp's combinatorics. Per contact: the least relative volume, squared — rational,
// exact —, over the triples that hold one of its edges, the triple attaining it, and how many of its triples are
// exactly zero (it is in a degenerate configuration now). With an irrational torque scale (GraspIt!'s 1/√r2) the
// scale is a rational within 2^-64 of it and `exact` is false. Bounded work: refused (Input_error) past 96 edges
// (C(96, 3) = 142 880 determinants).
struct Contact_margin {
  std::size_t contact = 0;
  std::optional<Rational> squared;  // none: fewer than three edges in the scene
  std::array<Generator_ref, 3> nearest{};
  std::size_t zeros = 0, triples = 0;
};
struct Contact_margins {
  bool exact = true;
  Rational torque_scale;
  Vec2 about;
  std::vector<Contact_margin> contacts;
};
constexpr std::size_t kContactMarginsMaxEdges = 96;
Contact_margins contact_margins(const Scene& scene, const Quality_query& query);

// The scaled wrench of a §1 generator g of a contact with scale c: c·(fx, fy, s·(m − about × f)).
Vec3q quality_wrench(const Vec3q& g, const Rational& c, const Rational& s, const Vec2& about);

}  // namespace wrenchkit
