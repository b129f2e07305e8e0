#include "exact/pipeline/quality_answer.h"

#include "exact/certificates/certificates.h"

namespace wrenchkit {

namespace {

void decide(std::string_view text, const Request& request, const Quality_query& query, Quality_item& r) {
  r.mode = request.mode;
  std::vector<std::string_view> certificates;
  r.epsilon = query.epsilon;
  if (query.critical_mu) check_critical_size(r.scene);  // (before ε's work, which would be thrown away)
  if (query.contact_margins) r.contact_margins = contact_margins(r.scene, query);  // (its bound refused first too)
  if (query.epsilon) {
    if (query.twin_first && request.certify) {  // (a certificate is written from the exact structures)
      Quality_query q = query;
      q.twin_first = false;
      decide_quality_into(r.scene, q, request.mode, r.answer);
    } else {
      decide_quality_into(r.scene, query, request.mode, r.answer);
    }
    if (!r.answer.closure.decided) throw Undecided_error("force closure is undecided by the float twin alone");
    if (request.mode == Mode::float_only && r.answer.closure.holds && !r.answer.twin)
      throw Undecided_error("the grasp is in force closure; its quality ε is exact arithmetic here (the float twin "
                            "certifies it only without a certificate, in general position)");
    if (request.certify) r.certificate = certificate_json(r.answer), certificates.push_back(r.certificate);
  }
  if (query.critical_mu) {
    if (request.mode == Mode::float_only)
      throw Undecided_error("the critical friction coefficient has no float twin (it is exact arithmetic)");
    r.critical = decide_critical_mu(r.scene, request.mode, query.tolerance);
    if (request.certify) {
      r.closure_mu_certificate = critical_mu_certificate(r.critical->closure, true);
      certificates.push_back(r.closure_mu_certificate);
      if (r.critical->equilibrium) {
        r.balance_mu_certificate = critical_mu_certificate(*r.critical->equilibrium, false);
        certificates.push_back(r.balance_mu_certificate);
      }
      if (r.critical->margin) {
        r.margin_certificate = critical_mu_certificate(*r.critical->margin, true);
        certificates.push_back(r.margin_certificate);
      }
    }
  }
  check_into(r, text, certificates, request);
}

}  // namespace

Quality_item answer_quality(std::string_view text, std::string_view source, const Request& request,
                            const Quality_query& query) {
  return answer_into_item<Quality_item>(text, source, request.limits,
                                        [&](Quality_item& r) { decide(text, request, query, r); });
}

Quality_item answer_quality(const Scene& scene, std::string_view text, const Request& request,
                            const Quality_query& query) {
  return answer_into_item<Quality_item>(scene, request.limits, [&](Quality_item& r) { decide(text, request, query, r); });
}

Quality_item answer_quality(Scene&& scene, std::string_view text, const Request& request, const Quality_query& query) {
  return answer_into_item<Quality_item>(std::move(scene), request.limits,
                                        [&](Quality_item& r) { decide(text, request, query, r); });
}

}  // namespace wrenchkit
