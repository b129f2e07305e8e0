#include "exact/pipeline/hold_answer.h"

#include "exact/io/streaming_scene_reader.h"

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
  std::string why = check_certificates(text, {r.certificate}, request);
  if (!why.empty()) {
    r.status = Status::check_failed;
    r.message = std::move(why);
  }
}

}  // namespace

Hold_item answer_hold(std::string_view text, std::string_view source, const Request& request) {
  Hold_item item;
  guarded(item, [&] {
    read_scene_into(item.scene, text, request.limits, source, false);
    decide(text, request, item);
  });
  return item;
}

Hold_item answer_hold(const Scene& scene, std::string_view text, const Request& request) {
  Hold_item item;
  guarded(item, [&] {
    item.scene = scene;
    decide(text, request, item);
  });
  return item;
}

}  // namespace wrenchkit
