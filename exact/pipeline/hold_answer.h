// `hold` through the pipeline (exact/pipeline/pipeline.h): can the contacts, with the support's friction, hold the
// body against the scene's load (exact/fixture/hold.h, docs/theory-sliding.md §5)? Decided in the request's mode,
// certified (proofs/certificate-format.md §7) and checked by the independent checker before the item is returned.
//
//   exact   exact arithmetic only: the contacts' equilibrium by the exact LP, W*'s rays, the exact LP on
//           inscribed N-gons; undecided (an answer, with the reason) within their resolution;
//   hybrid  the float witnesses first (the smoothed support forces, candidate twists), each verified exactly as
//           its certificate is built, then the exact LPs; undecided only within the 256-gons' resolution;
//   float   the float witnesses alone: Status::undecided (exit 3) when they decide nothing.
#pragma once

#include <string>
#include <string_view>

#include "exact/fixture/hold.h"
#include "exact/pipeline/pipeline.h"

namespace wrenchkit {

struct Hold_item {
  Status status = Status::answered;
  std::string message;
  Scene scene;
  Mode mode = Mode::hybrid;
  Hold_answer answer;
  std::string certificate;  // decided: the certificate the independent checker accepted; undecided: empty
};

// Reads `text` (eagerly) and answers; never throws.
Hold_item answer_hold(std::string_view text, std::string_view source, const Request& request);
// The same for a scene already read; `text`: a text of it for the checker.
Hold_item answer_hold(const Scene& scene, std::string_view text, const Request& request);

}  // namespace wrenchkit
