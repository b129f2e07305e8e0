#include "exact/pipeline/hold_answer.h"

#include "exact/certificates/certificates.h"

namespace wrenchkit {

namespace {

void decide(std::string_view text, const Request& request, Hold_item& r) {
  r.mode = request.mode;
  r.answer = decide_hold(r.scene, request.mode);
  if (r.answer.verdict == Hold_verdict::undecided) {
    if (request.mode == Mode::float_only) throw Undecided_error(r.answer.undecided_why);
    return;
  }
  r.certificate = hold_certificate(r.answer);
  check_into(r, text, {r.certificate}, request);
}

}  // namespace

Hold_item answer_hold(std::string_view text, std::string_view source, const Request& request) {
  return answer_into_item<Hold_item>(text, source, request.limits, [&](Hold_item& r) { decide(text, request, r); });
}

Hold_item answer_hold(const Scene& scene, std::string_view text, const Request& request) {
  return answer_into_item<Hold_item>(scene, request.limits, [&](Hold_item& r) { decide(text, request, r); });
}

}  // namespace wrenchkit
