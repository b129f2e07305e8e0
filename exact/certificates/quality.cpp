// proofs/certificate-format.md §3.4: the grasp quality ε — the wrench space's definition (norm, normalisation, torque
// scale, moment point), each contact's scale, the bracket, and its evidence: a twist (ε = 0), the closed boundary and
// its nearest triangle (L1), or the nearest facet's normal (L∞). The checker's side: proofs/checker/quality.cpp.
#include "exact/certificates/certificates.h"

namespace wrenchkit {

void write_certificate(Json_writer& w, const Quality_answer& a) {
  w.object().member("wrenchkit_certificate", 4).member("property", "quality");
  w.member("norm", quality_norm_name(a.query.norm)).member("normalize", normalization_name(a.query.normalize));
  w.member("torque_scale", a.query.torque_scale);
  const bool radius = a.closure.holds && a.torque_scale_error != 0;  // s = 1/√r2, irrational: within its error
  if (radius)
    w.member("torque_radius_squared", *a.query.torque_radius_squared).member("torque_scale_error", a.torque_scale_error);
  w.key("about").rationals(std::array<Rational, 2>{a.about.x, a.about.y});
  w.key("epsilon").object().member("lower", a.lower).member("upper", a.upper);
  if (a.exact) w.member("squared", a.squared);
  w.end_object();
  if (!a.closure.holds) {
    write_twist(w, a.closure.certificate.twist);
    w.end_object();
    return;
  }
  w.key("scales").array();
  for (const Quality_scale& s : a.scales) {
    w.object().member("scale", s.scale).member("error", s.error).member("bound", s.bound);
    if (radius) w.member("moment_bound", s.moment_bound);
    w.end_object();
  }
  w.end_array();
  const auto triple = [&w](const std::array<std::size_t, 3>& t) {
    w.array().integer(t[0]).integer(t[1]).integer(t[2]).end_array();
  };
  if (a.query.norm == Quality_norm::l1) {
    w.key("boundary").array();
    for (const auto& t : a.boundary) triple(t);
    w.end_array();
    w.key("nearest");
    triple(a.nearest);
  } else {
    w.key("normal").rationals(a.normal);
  }
  w.end_object();
}

std::string certificate_json(const Quality_answer& a) { return json_text(write_certificate, a, 1024); }

}  // namespace wrenchkit
