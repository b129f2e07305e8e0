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

void write_region_triples(Json_writer& w, const Grasp_regions& g) {
  w.key("triples").array();
  for (const Triple_region& t : g.triples) {
    w.object().key("edges").array().integer(t.edges[0]).integer(t.edges[1]).integer(t.edges[2]).end_array();
    if (t.box) {
      w.key("independent").array();
      for (const auto& iv : *t.box) w.rationals(iv);
      w.end_array().key("wrenches").array();
      for (const int x : t.wrenches) w.string(wrench_label(x));
      w.end_array();
    }
    if (t.never) {
      if (t.never_direction) w.key("never").rationals(*t.never_direction);
      else w.member("never", "frictionless");
    }
    w.end_object();
  }
  w.end_array();
}

std::string grasp_regions_certificate(const Grasp_regions& g) {
  Json_writer w(1024);
  w.object().member("wrenchkit_certificate", 5).member("property", "grasp_regions").member("fingers", g.fingers);
  w.member("mu", g.mu);
  if (!g.asked.empty()) {
    w.key("edges").array();
    for (const std::size_t e : g.asked) w.integer(e);
    w.end_array();
  }
  if (g.fingers == 3) write_region_triples(w, g);
  else write_region_pairs(w, g);
  return w.end_object().take();
}

}  // namespace wrenchkit
