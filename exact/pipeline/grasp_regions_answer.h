// `grasp-regions` through the pipeline (exact/pipeline/pipeline.h): the two-finger force-closure regions of a
// polygon's edge pairs (exact/statics/grasp_regions.h, docs/grasp-regions.md), certified (proofs/certificate-format.md
// §3.6) and checked by the independent checker before the item is returned. Exact arithmetic in every mode (the
// regions are polygons cut by rational half-planes; there is nothing for a float twin to decide).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "exact/pipeline/pipeline.h"
#include "exact/statics/grasp_regions.h"

namespace wrenchkit {

struct Grasp_regions_query {
  std::optional<Rational> mu;       // else the scene's "mu"
  std::vector<std::size_t> edges;   // empty: every edge
  int fingers = 2;                  // 2: Nguyen's regions; 3: independent boxes per edge triple (GR-2)
  // The ranking of the placements a designer would pick: each closed pair's (triple's) independent box's centre,
  // by the box's side (default) or by the grasp's ε there (`rank_epsilon`: L1, unit-normal, moments about body.com
  // else the outline's area centroid, certified), only boxes with side ≥ min_side.
  bool rank_epsilon = false;
  Rational min_side = 0;
  bool rank_asked = false;  // --rank or --min-side given: the text shows the ranking (JSON always has it)
};

// One ranked placement: the edges, the box's centre (one parameter per finger) and side, and with rank_epsilon the
// grasp's ε bracket there.
struct Ranked_placement {
  std::vector<std::size_t> edges;
  std::vector<Rational> at;
  Rational side;
  std::optional<std::array<Rational, 2>> epsilon;  // [lower, upper]
};

struct Grasp_regions_item {
  Status status = Status::answered;
  std::string message;
  Scene scene;
  Mode mode = Mode::hybrid;
  Grasp_regions regions;
  std::string certificate;  // accepted by the checker (request.certify)
  std::vector<Ranked_placement> ranked;  // best first
  bool rank_asked = false;
  // rank_epsilon: the best placement as a scene (its fingers as placed contacts) and its ε certificate (§3.4),
  // accepted by the checker on that scene
  std::string best_scene, best_certificate;
};

// Reads `text` (eagerly) and answers; never throws. Input_error (exit 2) without a friction coefficient (neither
// --mu nor the scene's "mu"), without body.outline, or for an edge out of range.
Grasp_regions_item answer_grasp_regions(std::string_view text, std::string_view source, const Request& request,
                                        const Grasp_regions_query& query);

}  // namespace wrenchkit
