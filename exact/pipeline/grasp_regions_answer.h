// `grasp-regions` through the pipeline (exact/pipeline/pipeline.h): the two-finger force-closure regions of a
// polygon's edge pairs (exact/statics/grasp_regions.h, docs/grasp-regions.md), certified (proofs/certificate-format.md
// §3.6) and checked by the independent checker before the item is returned. Exact arithmetic in every mode (the
// regions are polygons cut by rational half-planes; there is nothing for a float twin to decide).
#pragma once

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
};

struct Grasp_regions_item {
  Status status = Status::answered;
  std::string message;
  Scene scene;
  Mode mode = Mode::hybrid;
  Grasp_regions regions;
  std::string certificate;  // accepted by the checker (request.certify)
};

// Reads `text` (eagerly) and answers; never throws. Input_error (exit 2) without a friction coefficient (neither
// --mu nor the scene's "mu"), without body.outline, or for an edge out of range.
Grasp_regions_item answer_grasp_regions(std::string_view text, std::string_view source, const Request& request,
                                        const Grasp_regions_query& query);

}  // namespace wrenchkit
