// The labels family through the pipeline (exact/pipeline/pipeline.h): moment labels [LB-3], the force dual
// [LB-4] and Reuleaux's method (the contacts read frictionless, per-contact modes of a motion), with the
// scene's load and the queries answered in the request's mode.
//
//   exact   the exact cone and constructions, no floating point;
//   hybrid  the cone's signs by the float twin first, exact where it is uncertain; constructions exact, so
//           the answer is the exact one (tested byte-equal);
//   float   the twin alone (float/labels_twin.h [FL-6]): corners with certified bounds; Status::undecided
//           when a sign, the cone's rank or a query is not certified.
// Every query (a resultant, the load's balance, a dual point, a contact's mode) is answered here, never
// while an answer is written, so a front end only serialises.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "exact/pipeline/pipeline.h"
#include "exact/statics/force_dual.h"
#include "exact/statics/moment_labels.h"
#include "float/labels_twin.h"

namespace wrenchkit {

enum class Labels_question { labels, dual, reuleaux };

struct Labels_query {
  Labels_question question = Labels_question::labels;
  std::optional<Vec3q> resultant;  // labels: is this wrench a possible resultant?
  std::optional<Vec3q> motion;     // reuleaux: the per-contact modes of this twist
};

struct Labels_item {
  Status status = Status::answered;
  std::string message;
  Scene scene;
  Mode mode = Mode::hybrid;
  Reading reading = Reading::friction;  // frictionless for reuleaux
  // The exact generators: for the force dual (every mode) and the exact constructions below; empty when
  // hybrid labels and Reuleaux, whose cone comes from moment_labels(scene, …) (integer rows first).
  std::vector<Generator> generators;
  // exact and hybrid: the exact constructions
  std::vector<Vec3q> wrenches;
  Moment_labels labels;
  std::optional<Force_dual> dual;
  // float: the twin's
  std::vector<fl::Bounded3> twin_generators;
  fl::Labels_twin twin;
  std::optional<fl::Dual_twin> twin_dual;
  std::vector<fl::Dual_point_twin> twin_dual_points;  // per generator
  std::optional<fl::Dual_point_twin> twin_antipode;   // of the load
  // the queries, in every mode
  std::optional<bool> resultant_possible;
  std::optional<Vec3q> load;            // the scene's load as a wrench
  std::optional<bool> load_balanced;   // −load ∈ W (theory.md §5.5)
  std::optional<Mode_answer> modes;    // reuleaux with a motion
  // Nothing labeled, infinity included: force closure (friction), form closure (frictionless).
  bool closed() const { return mode == Mode::float_only ? twin.nothing_labeled() : labels.cone.force_closure(); }
};

// Reads `text` (eagerly) and answers; never throws.
Labels_item answer_labels(std::string_view text, std::string_view source, const Request& request,
                          const Labels_query& query);
// The same for a scene already read.
Labels_item answer_labels(const Scene& scene, const Request& request, const Labels_query& query);

}  // namespace wrenchkit
