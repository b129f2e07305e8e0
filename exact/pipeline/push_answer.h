// `push` through the pipeline (exact/pipeline/pipeline.h): which way a pushed body turns (exact/sliding/pushing.h,
// docs/pushing.md), certified (proofs/certificate-format.md §8) and checked by the independent checker before the item
// is returned. Exact arithmetic in every mode (three signs of linear functions over F; nothing for a twin to guess).
#pragma once

#include <string>
#include <string_view>

#include "exact/pipeline/pipeline.h"
#include "exact/sliding/pushing.h"

namespace wrenchkit {

// What to answer besides the rotation: the contact mode (sticks, slides left or right) and the sticking motion's
// rotation rate, bracketed to `tolerance` (relative).
struct Push_query {
  bool contact = false;
  bool region = false;  // a line pusher's stable region (PU-3 §6)
  bool locus = false;   // a point pusher's rotation centres over every distribution and its slowest turn (PU-4)
  Rational tolerance = Rational(1, 1000000000000);
};

struct Push_item {
  Status status = Status::answered;
  std::string message;
  Scene scene;
  Mode mode = Mode::hybrid;
  Push_answer push;
  std::string certificate;  // accepted by the checker (request.certify; none when undecided)
};

// Reads `text` and answers; never throws. Input_error (exit 2) without "pusher" or "support", or when nothing under
// the body has friction.
Push_item answer_push(std::string_view text, std::string_view source, const Request& request,
                      const Push_query& query = {});

}  // namespace wrenchkit
