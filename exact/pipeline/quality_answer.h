// `quality` through the pipeline (exact/pipeline/pipeline.h): the grasp quality ε of the scene's contacts
// (exact/statics/quality.h, docs/quality.md), certified (proofs/certificate-format.md §3.4) and checked by the
// independent checker before the item is returned.
//
//   exact, hybrid  force closure in the mode (closure.h), then ε in exact arithmetic: exact, or a certified bracket;
//   float          force closure by the twin; ε = 0 when it is not closed (certified by its twist), else undecided
//                  (Status::undecided, exit 3): ε has no float twin; nor has μ*, undecided whenever asked.
// The critical friction coefficient μ* (exact/statics/critical_mu.h, §3.5) of closure and, with a load, of
// equilibrium, when the query asks (the default). Request::certify false (the array API's default) writes and checks
// no certificate: the same answers, for throughput.
#pragma once

#include <string>
#include <string_view>

#include "exact/pipeline/pipeline.h"
#include "exact/statics/critical_mu.h"
#include "exact/statics/quality.h"

namespace wrenchkit {

struct Quality_item {
  Status status = Status::answered;
  std::string message;
  Scene scene;
  Mode mode = Mode::hybrid;
  bool epsilon = false;      // ε was asked (query.epsilon): `answer` holds it
  Quality_answer answer;
  std::string certificate;  // the certificate the independent checker accepted
  std::optional<Critical_answer> critical;                // query.critical_mu
  std::string closure_mu_certificate, balance_mu_certificate, margin_certificate;  // accepted by the checker
  std::optional<Contact_margins> contact_margins;  // query.contact_margins: a measurement, exact (no certificate)
};

// Reads `text` (eagerly) and answers; never throws.
Quality_item answer_quality(std::string_view text, std::string_view source, const Request& request,
                            const Quality_query& query);
// The same for a scene already read; `text`: a text of it for the checker.
Quality_item answer_quality(const Scene& scene, std::string_view text, const Request& request,
                            const Quality_query& query);
// The same, the scene moved into the item (its `scene`; the array API moves it back for the next row).
Quality_item answer_quality(Scene&& scene, std::string_view text, const Request& request, const Quality_query& query);

}  // namespace wrenchkit
