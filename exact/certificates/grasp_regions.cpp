// proofs/certificate-format.md §3.6 (format 5): the two-finger force-closure regions of a polygon — every edge pair
// asked, each with its closure set's polygon in (s, t) (counter-clockwise corners, exact), empty when no placement
// closes. The checker's side: proofs/checker/grasp_regions.cpp (it derives Nguyen's half-planes from the scene and
// accepts only the same polygons).
#include "exact/certificates/certificates.h"

namespace wrenchkit {

void write_region_pairs(Json_writer& w, const Grasp_regions& g) {
  w.key("pairs").array();
  for (const Pair_region& p : g.pairs) {
    w.object().key("edges").array().integer(p.i).integer(p.j).end_array().key("closed").array();
    if (!p.polygon.empty()) {
      w.array();
      for (const auto& c : p.polygon) w.rationals(c);
      w.end_array();
    }
    w.end_array();
    if (p.box) w.key("independent").array().rationals((*p.box)[0]).rationals((*p.box)[1]).end_array();
    w.end_object();
  }
  w.end_array();
}

std::string grasp_regions_certificate(const Grasp_regions& g) {
  Json_writer w(1024);
  w.object().member("wrenchkit_certificate", 5).member("property", "grasp_regions").member("fingers", 2);
  w.member("mu", g.mu);
  if (!g.asked.empty()) {
    w.key("edges").array();
    for (const std::size_t e : g.asked) w.integer(e);
    w.end_array();
  }
  write_region_pairs(w, g);
  return w.end_object().take();
}

}  // namespace wrenchkit
