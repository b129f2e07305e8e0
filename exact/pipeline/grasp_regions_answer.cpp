#include "exact/pipeline/grasp_regions_answer.h"

#include "exact/certificates/certificates.h"
#include "exact/io/input_error.h"

namespace wrenchkit {


Grasp_regions_item answer_grasp_regions(std::string_view text, std::string_view source, const Request& request,
                                        const Grasp_regions_query& query) {
  return answer_into_item<Grasp_regions_item>(text, source, request.limits, [&](Grasp_regions_item& r) {
    r.mode = request.mode;
    const std::optional<Rational> mu = query.mu ? query.mu : r.scene.mu;
    if (!mu) throw Input_error("--mu: missing (the fingers' friction coefficient: give --mu M, or \"mu\" in the scene)");
    r.regions = query.fingers == 3 ? three_finger_regions(r.scene, *mu, query.edges)
                                    : two_finger_regions(r.scene, *mu, query.edges);
    if (!request.certify) return;
    r.certificate = grasp_regions_certificate(r.regions);
    check_into(r, text, {r.certificate}, request);
  });
}

}  // namespace wrenchkit
