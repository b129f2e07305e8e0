// wrenchkit grasp-regions: where two frictional fingers may go on a polygon — every edge pair's force-closure
// region in the edges' parameters, exact, with a checked certificate (docs/grasp-regions.md,
// exact/statics/grasp_regions.h).
#include <sstream>
#include <string>

#include "cli/common.h"
#include "cli/float_json.h"
#include "exact/certificates/certificates.h"
#include "exact/numbers/decimal.h"

namespace wrenchkit::cli {

void write_grasp_regions(Json_writer& w, const Grasp_regions_item& r) {
  const Grasp_regions& g = r.regions;
  w.member("command", "grasp-regions").member("name", r.scene.name).member("fingers", 2).member("mu", g.mu);
  w.key("outline").object().member("vertices", g.edges).member("orientation", g.ccw ? "counter-clockwise" : "clockwise")
      .member("convex", g.convex).end_object();
  write_region_pairs(w, g);  // (the certificate's own "pairs")
  w.member("closed_pairs", g.closed_pairs());
  // each region's area (of the unit square of (s, t)) and the largest
  w.key("areas").array();
  const Pair_region *best = nullptr, *robust = nullptr;
  for (const Pair_region& p : g.pairs) {
    if (p.polygon.empty()) continue;
    w.object().key("edges").array().integer(p.i).integer(p.j).end_array().member("area", p.area);
    w.key("area_approx").raw(float_number(p.area.get_d())).member("independent_side", p.side);
    w.key("independent_side_approx").raw(float_number(p.side.get_d())).end_object();
    if (!best || p.area > best->area) best = &p;
    if (!robust || p.side > robust->side) robust = &p;
  }
  w.end_array();
  if (best) w.key("largest").object().key("edges").array().integer(best->i).integer(best->j).end_array()
                 .member("area", best->area).end_object();
  if (robust) w.key("most_independent").object().key("edges").array().integer(robust->i).integer(robust->j).end_array()
                   .member("independent_side", robust->side).end_object();
  if (!r.certificate.empty()) w.member("certificate_checked", true).key("certificate").raw(r.certificate);
}

namespace {

std::string edge_text(const Scene& s, std::size_t k) {
  const std::vector<Vec2>& V = s.body.outline;
  return "edge " + std::to_string(k) + " " + vec_text(V[k]) + "–" + vec_text(V[(k + 1) % V.size()]);
}

std::string regions_human(const Grasp_regions_item& r, const std::string& source) {
  const Grasp_regions& g = r.regions;
  std::ostringstream s;
  s << scene_line(r.scene, source) << "outline: " << g.edges << " edges, " << (g.ccw ? "counter-clockwise" : "clockwise")
    << ", " << (g.convex ? "convex" : "not convex") << "\n";
  s << "two fingers, mu = " << number_text(g.mu) << ", each pushing along its edge's inward normal; a finger on edge i at "
       "v_i + s (v_{i+1} - v_i), the other on edge j at t, s and t in [0, 1]\n";
  s << "force closure (Nguyen: the segment between the fingers inside both friction cones) for "
    << g.closed_pairs() << " of " << g.pairs.size() << " edge pairs:\n";
  for (const Pair_region& p : g.pairs) {
    if (p.polygon.empty()) continue;
    s << "  " << edge_text(r.scene, p.i) << " and " << edge_text(r.scene, p.j) << ": (s, t) inside the polygon ";
    for (std::size_t k = 0; k < p.polygon.size(); ++k) s << (k ? " " : "") << vec_text(Vec2{p.polygon[k][0], p.polygon[k][1]});
    s << " (its sides on the cones' lines excluded), area " << number_text(p.area) << " of the unit square\n";
    if (p.box) {
      const auto& b = *p.box;
      s << "    independent: every s in [" << decimal_text(b[0][0], 4) << ", " << decimal_text(b[0][1], 4) << "] with every t in ["
        << decimal_text(b[1][0], 4) << ", " << decimal_text(b[1][1], 4) << "] closes (the largest such square has side "
        << number_text(p.side) << ", not attained; the box's exact corners are in --json)\n";
    }
  }
  if (g.closed_pairs() == 0) s << "  none: no two placements of the fingers close the grasp with this mu\n";
  s << "certificate accepted by the independent checker (exact arithmetic)\n";
  return s.str();
}

}  // namespace

Scene_answer prepare_grasp_regions_json(const Options& o) {
  return [request = request_of(o), query = o.regions](Json_writer& w, const std::string& text, const std::string& source) {
    write_grasp_regions(w, answered(answer_grasp_regions(text, source, request, query)));
  };
}

int run_grasp_regions(const Options& o, const std::string& scene_text, const std::string& source) {
  const Grasp_regions_item r = answered(answer_grasp_regions(scene_text, source, request_of(o), o.regions));
  if (!o.certificate_file.empty()) write_file(o.certificate_file, r.certificate + "\n");
  return write_answer(o, [&](Json_writer& w) { write_grasp_regions(w, r); }, [&] { return regions_human(r, source); });
}

}  // namespace wrenchkit::cli
