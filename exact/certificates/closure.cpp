// proofs/certificate-format.md §3.1–§3.2: force and form closure — positive (a combination summing to zero, three
// independent generators), negative (a twist with power ≥ 0 against every generator, with its reading); and the
// parts the other sections borrow (a combination, a twist with its reading). The checker's side: proofs/checker/.
#include "exact/certificates/certificates.h"

namespace wrenchkit {

void write_combination(Json_writer& w, const std::vector<std::pair<Generator_ref, Rational>>& terms) {
  w.array();
  for (const auto& [ref, weight] : terms)
    w.object().member("contact", ref.contact).member("edge", edge_name(ref.edge)).member("weight", weight).end_object();
  w.end_array();
}

void write_twist(Json_writer& w, const Vec3q& t) {
  w.key("twist").rationals(t);
  const Twist_reading r = read_twist(t);
  w.key("reading").object();
  if (r.label == 'i') w.member("label", "infinity").key("direction");
  else w.member("label", std::string_view(&r.label, 1)).key("point");
  w.rationals(r.point).end_object();
}

void write_certificate(Json_writer& w, const Closure_certificate& c) {
  w.object().member("wrenchkit_certificate", 1).member("property", property_name(c.property)).member("holds", c.holds);
  if (!c.holds) {
    write_twist(w, c.twist);
  } else {
    write_combination(w.key("combination"), c.combination);
    w.key("independent").array();
    for (const Generator_ref& g : c.independent)
      w.object().member("contact", g.contact).member("edge", edge_name(g.edge)).end_object();
    w.end_array();
  }
  w.end_object();
}

std::string certificate_json(const Closure_certificate& c) { return json_text(write_certificate, c, 512); }

}  // namespace wrenchkit
