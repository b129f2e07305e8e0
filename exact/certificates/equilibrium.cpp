// proofs/certificate-format.md §3.3: equilibrium of the load — a combination balancing it, or a twist the contacts
// allow and the load drives. The checker's side: proofs/checker/.
#include "exact/certificates/certificates.h"

namespace wrenchkit {

void write_certificate(Json_writer& w, const Equilibrium_certificate& c) {
  w.object().member("wrenchkit_certificate", 1).member("property", "equilibrium").member("holds", c.holds);
  if (c.holds) write_combination(w.key("combination"), c.combination);
  else write_twist(w, c.twist);
  w.end_object();
}

std::string certificate_json(const Equilibrium_certificate& c) { return json_text(write_certificate, c, 512); }

}  // namespace wrenchkit
