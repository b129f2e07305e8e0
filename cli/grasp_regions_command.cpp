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

namespace {

void write_ranked(Json_writer& w, const Grasp_regions_item& r) {
  w.key("ranked").array();
  for (const Ranked_placement& p : r.ranked) {
    w.object().key("edges").array();
    for (const std::size_t e : p.edges) w.integer(e);
    w.end_array().key("at").rationals(p.at).member("box_side", p.side);
    if (p.epsilon) {
      w.key("epsilon").object().member("lower", (*p.epsilon)[0]).member("upper", (*p.epsilon)[1]);
      w.key("lower_approx").raw(float_number((*p.epsilon)[0].get_d())).end_object();
    }
    w.end_object();
  }
  w.end_array();
  if (!r.best_certificate.empty())
    w.key("best_by_epsilon").object().key("scene").raw(r.best_scene).key("certificate").raw(r.best_certificate).end_object();
}

// The first five ranked placements, in words.
std::string ranked_human(const Grasp_regions_item& r, bool by_epsilon) {
  if (!r.rank_asked) return "";
  if (r.ranked.empty()) return "no independent box to rank (with --min-side, none that large)\n";
  std::ostringstream s;
  s << "best placements by " << (by_epsilon ? "the grasp's epsilon (L1, unit-normal edges, moments about " : "the independent box's side")
    << (by_epsilon ? (r.scene.body.com ? "body.com)" : "the outline's centroid)") : "") << " at each box's centre:\n";
  for (std::size_t k = 0; k < r.ranked.size() && k < 5; ++k) {
    const Ranked_placement& p = r.ranked[k];
    s << "  " << k + 1 << ". edges";
    for (std::size_t f = 0; f < p.edges.size(); ++f) s << (f ? ", " : " ") << p.edges[f];
    s << " at s = (";
    for (std::size_t f = 0; f < p.at.size(); ++f) s << (f ? ", " : "") << decimal_text(p.at[f], 4);
    s << "), box side " << decimal_text(p.side, 4);
    if (p.epsilon) s << ", epsilon " << decimal_text((*p.epsilon)[0], 6);
    s << "\n";
  }
  if (r.ranked.size() > 5) s << "  (" << r.ranked.size() << " ranked; all in --json)\n";
  if (!r.best_certificate.empty()) s << "  the best one's epsilon certified on its own scene (--json: best_by_epsilon)\n";
  return s.str();
}

}  // namespace

void write_grasp_regions(Json_writer& w, const Grasp_regions_item& r) {
  const Grasp_regions& g = r.regions;
  w.member("command", "grasp-regions").member("name", r.scene.name).member("fingers", g.fingers).member("mu", g.mu);
  w.key("outline").object().member("vertices", g.edges).member("orientation", g.ccw ? "counter-clockwise" : "clockwise")
      .member("convex", g.convex).end_object();
  if (g.fingers == 3) {
    write_region_triples(w, g);  // (the certificate's own "triples")
    w.member("boxed_triples", g.boxed_triples()).member("never_triples", g.never_triples());
    const Triple_region* robust = nullptr;
    for (const Triple_region& t : g.triples)
      if (t.box && (!robust || t.side > robust->side)) robust = &t;
    if (robust)
      w.key("most_independent").object().key("edges").array().integer(robust->edges[0]).integer(robust->edges[1])
          .integer(robust->edges[2]).end_array().member("independent_side", robust->side).key("independent_side_approx")
          .raw(float_number(robust->side.get_d())).end_object();
    write_ranked(w, r);
    if (!r.certificate.empty()) w.member("certificate_checked", true).key("certificate").raw(r.certificate);
    return;
  }
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
  write_ranked(w, r);
  if (!r.certificate.empty()) w.member("certificate_checked", true).key("certificate").raw(r.certificate);
}

namespace {

std::string edge_text(const Scene& s, std::size_t k) {
  const std::vector<Vec2>& V = s.body.outline;
  return "edge " + std::to_string(k) + " " + vec_text(V[k]) + "–" + vec_text(V[(k + 1) % V.size()]);
}

std::string triples_human(const Grasp_regions_item& r) {
  const Grasp_regions& g = r.regions;
  std::ostringstream s;
  s << "three fingers, mu = " << number_text(g.mu) << ", each pushing along its edge's inward normal; finger f on the "
       "triple's edge f at parameter s_f in [0, 1] (v_i + s (v_{i+1} - v_i))\n";
  s << "independent cubes (every placement inside closes; the largest cube the search found, certified) for "
    << g.boxed_triples() << " of " << g.triples.size() << " edge triples; no placement closes for " << g.never_triples()
    << (g.never_triples() == 1 ? " triple" : " triples") << (sgn(g.mu) == 0 ? " (frictionless: three wrenches cannot "
                                                                               "positively span the wrench space)" : "")
    << ":\n";
  for (const Triple_region& t : g.triples) {
    if (!t.box) continue;
    const auto& b = *t.box;
    s << "  edges " << t.edges[0] << ", " << t.edges[1] << ", " << t.edges[2] << ": side " << decimal_text(t.side, 4)
      << ", s in [" << decimal_text(b[0][0], 4) << ", " << decimal_text(b[0][1], 4) << "] x [" << decimal_text(b[1][0], 4)
      << ", " << decimal_text(b[1][1], 4) << "] x [" << decimal_text(b[2][0], 4) << ", " << decimal_text(b[2][1], 4)
      << "] (certified by wrenches";
    for (const int x : t.wrenches) s << " " << wrench_label(x);
    s << ")\n";
  }
  for (const Triple_region& t : g.triples) {
    if (!t.never_direction) continue;
    const auto& u = *t.never_direction;
    s << "  edges " << t.edges[0] << ", " << t.edges[1] << ", " << t.edges[2] << ": no placement closes (every wrench w "
      << "of the three fingers has u . w <= 0 for u = (" << number_text(u[0]) << ", " << number_text(u[1]) << ", "
      << number_text(u[2]) << ")" << (sgn(u[2]) == 0 ? ": the forces lie in a closed half-plane" : "") << ")\n";
  }
  std::size_t open = 0;
  for (const Triple_region& t : g.triples) open += !t.box && !t.never;
  if (open) s << "  " << open << " other triple(s): no cube found by the search (not a proof that none closes)\n";
  s << "(exact corners in --json) certificate accepted by the independent checker (exact arithmetic)\n";
  return s.str();
}

std::string regions_human(const Grasp_regions_item& r, const std::string& source) {
  const Grasp_regions& g = r.regions;
  std::ostringstream s;
  s << scene_line(r.scene, source) << "outline: " << g.edges << " edges, " << (g.ccw ? "counter-clockwise" : "clockwise")
    << ", " << (g.convex ? "convex" : "not convex") << "\n";
  const bool by_epsilon = !r.ranked.empty() && r.ranked.front().epsilon.has_value();
  if (g.fingers == 3) return s.str() + triples_human(r) + ranked_human(r, by_epsilon);
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
  s << ranked_human(r, by_epsilon);
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
