#include "exact/pipeline/push_answer.h"

#include "exact/certificates/certificates.h"
#include "exact/io/input_error.h"

namespace wrenchkit {

Push_item answer_push(std::string_view text, std::string_view source, const Request& request, const Push_query& query) {
  return answer_into_item<Push_item>(text, source, request.limits, [&](Push_item& r) {
    r.mode = request.mode;
    if (!r.scene.pusher)
      throw Input_error("pusher: missing (push needs \"pusher\": {\"at\": [x, y], \"normal\": [nx, ny], \"mu\": m, "
                        "\"velocity\": [vx, vy]}, a point contact on the body moving into it)");
    if (!r.scene.support)
      throw Input_error("support: missing (push needs the support the body slides on: its points or regions with "
                        "their friction, as limit-surface reads them)");
    const Support_model model(r.scene);
    if (query.region && !r.scene.pusher->line())
      throw Input_error("--region: the stable region is a line pusher's (\"segment\"); a point pusher's contact mode "
                        "is --contact");
    if (query.locus && r.scene.pusher->line())
      throw Input_error("--locus: the rotation centres are answered for a point pusher; a line pusher's are its stable "
                        "region (--region)");
    if (r.scene.pusher->line()) {  // a line contact (PU-3): is its motion stable — exact in every mode
      if (query.contact)
        throw Input_error("--contact: the contact mode is answered for a point pusher; a line pusher (\"segment\") "
                          "answers whether its motion is stable (drop --contact)");
      r.push = decide_line_push(model, *r.scene.pusher);
      if (query.region) r.push.region = stable_region(model, *r.scene.pusher);
      if (!request.certify || r.push.stable->verdict == Stability::undecided) return;
      r.certificate = push_certificate(r.push);
      check_into(r, text, {r.certificate}, request);
      return;
    }
    // float: the twin alone (no certificate: its signs are certified by their error bounds, FL-1); a certificate
    // needs the exact values; hybrid without one: the twin first
    const Mode mode = request.mode == Mode::float_only ? Mode::float_only : request.certify ? Mode::exact : request.mode;
    r.push = decide_push(model, *r.scene.pusher, mode);
    if (query.contact) r.push.contact = push_contact_mode(model, *r.scene.pusher, query.tolerance);
    if (query.locus) {  // the senses the (certified) rotation leaves; with a certain sense, a slow distribution
      const Rotation rot = r.push.rotation;
      r.push.locus = push_locus(model, *r.scene.pusher, senses_left(rot));
      if (r.push.locus->friction_centre && (rot == Rotation::ccw || rot == Rotation::cw))
        r.push.slowest = slowest_turn(model, *r.scene.pusher, query.tolerance, r.push.contact);
    }
    if (!request.certify || r.push.by_twin || r.push.rotation == Rotation::undecided) return;
    r.certificate = push_certificate(r.push);
    check_into(r, text, {r.certificate}, request);
  });
}

}  // namespace wrenchkit
