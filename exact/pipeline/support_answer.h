// A support's sliding questions through the pipeline (exact/pipeline/pipeline.h): the polygonal limit
// surfaces [LS-1]–[LS-3] (`limit-surface`), the frictional load of a twist [LS-4] (`sliding`), and whether a
// load sticks or slides, in the request's mode:
//
//   exact   the exact polytopes and sliding bounds, no floating point; the motion from the polygons
//           (undecided within their resolution);
//   hybrid  the same exact answers, plus the TRUE surface's power and load from the float twin with
//           certified bounds [FL-7], and the motion by the twin's certified search on the true surface
//           first, the polygons only when it cannot tell;
//   float   the twin alone: no exact polygons; centre of friction, polygonal and true powers and loads with
//           certified bounds; Status::undecided when the search cannot tell.
// Everything is computed here; a front end only serialises the item.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "exact/pipeline/pipeline.h"
#include "exact/sliding/distribution.h"
#include "exact/sliding/limit_surface.h"
#include "exact/sliding/motion.h"
#include "exact/sliding/region_sliding.h"
#include "exact/sliding/sliding.h"
#include "float/limit_surface_twin.h"

namespace wrenchkit {

enum class Support_question { limit_surface, sliding };

struct Support_query {
  Support_question question = Support_question::limit_surface;
  int sides = 32;                // polygon sides N (even, 4..kMaxSides)
  std::optional<Vec3q> twist;    // the load for this twist (not zero)
  std::optional<Vec3q> load;     // limit-surface: does it stick or slide?
  bool polytopes = true;         // limit-surface: build the exact polytopes (else only if nothing else decides)
  // The polytopes, or their listing or pictures, were asked for by name (--sides, --list, the exports): a support
  // with regions has no exact polytope (its limit surface is strictly convex) and refuses them.
  bool polytopes_asked = false;
  // Support regions: the relative width the power's bracket must meet (default 10^-6).
  std::optional<Rational> tolerance;
};

// What the support is made of, which decides what its answer holds: points with every force given (the polygonal
// model; `points_twin` in float mode, the twin's values), some point force not given (the admissible set F, with or
// without regions), or regions with every point force given (their certified brackets).
enum class Support_kind { points, points_twin, unknown, regions };

struct Support_item {
  Status status = Status::answered;
  std::string message;
  Scene scene;
  Mode mode = Mode::hybrid;
  Support_kind kind = Support_kind::points;
  // exact and hybrid (and limit-surface's model in float, for the search)
  std::optional<Polygonal_ls> model;
  Ls_polytope in, out;          // limit-surface, exact and hybrid, when built
  bool polytopes_built = false;
  Sliding_answer sliding;       // exact and hybrid
  std::optional<Rational> gauge_in, gauge_out;  // with a load, the polytopes built
  Polygonal_ls::Normal_cone cone_in, cone_out;  // with a load that does not stick, the polytopes built
  // hybrid and float: the true surface by the twin
  std::vector<fl::Support_point_twin> twin;
  std::optional<fl::Bounded> true_power;    // with a twist
  std::optional<fl::Load_twin> true_load;   // with a twist
  // float: the twin's own polygonal values
  std::optional<fl::Directions_twin> twin_directions;
  fl::Point2 twin_center_of_friction;
  fl::Bounded twin_mu_f0;
  std::optional<fl::Bounded> twin_power_inner, twin_power_outer;  // with a twist
  // An unknown distribution (a point's force not given; docs/theory-sliding.md §1–§2): the admissible set,
  // its extreme distributions and, with a twist, the range of the power over it (exact, every mode but
  // float, which has no twin of the LP over F and answers undecided).
  std::optional<Admissible> admissible;
  std::vector<std::vector<Rational>> vertices;
  std::optional<Power_range> power;
  Vec2 pressure_center;
  Rational weight;  // W: support.weight, or the weight of gravity beside the support
  // A support with regions [RG-1] [RG-2] (exact/sliding/region_sliding.h), every mode but float (which has no twin
  // of regions and answers undecided): the exact statics and the power and load of --twist as certified brackets;
  // with a point force not given [RG-3], the regions' own (the points' range over F is in `power`, their bracket added).
  std::optional<Region_sliding> regions;
  // limit-surface with a load: the load's motion, whatever the support is made of (exact/sliding/motion.h), and the
  // certificate written from its witnesses (proofs/certificate-format.md §6), checked by the independent checker;
  // empty when undecided (or a verdict stands uncertified: `motion->uncertified` says why).
  std::optional<Motion_answer> motion;
  std::string certificate;
};

// Reads `text` (eagerly) and answers; never throws. A scene without a support is bad input; so is a
// limit surface whose candidate normals exceed kMaxCandidates (the polytopes are not built then).
// An unknown distribution: `sliding` (and `limit-surface --twist`) answers the power range over F and the
// extreme distributions; `limit-surface --load` whether the load sticks for every admissible distribution,
// slides for every one, or depends (exact/sliding/motion.h), with its witnesses. The polytopes
// depend on the distribution and are not built.
Support_item answer_support(std::string_view text, std::string_view source, const Request& request,
                            const Support_query& query);
// A support with regions: answered by exact/sliding/region_sliding.h in exact and hybrid alike (the doubles there only
// propose witnesses), undecided in float; refused (bad input) with the polytopes asked for by name. With points whose
// force is not given: the unknown distribution's answer over the regions.
// The same for a scene already read.
// `text`: a text of the scene for the checker (its own text, or write_scene(scene)).
Support_item answer_support(const Scene& scene, std::string_view text, std::string_view source, const Request& request,
                            const Support_query& query);

}  // namespace wrenchkit
