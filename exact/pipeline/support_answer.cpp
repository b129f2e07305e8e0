#include "exact/pipeline/support_answer.h"

#include <algorithm>

#include "exact/certificates/certificates.h"
#include "exact/io/support_check.h"
#include "exact/io/to_float.h"

namespace wrenchkit {

namespace {

fl::Bounded3 twin_of(const Vec3q& q) { return {to_bounded(q[0]), to_bounded(q[1]), to_bounded(q[2])}; }

// The true surface's values for the twist (hybrid and float).
void true_surface(const Support_query& q, Support_item& r) {
  r.twin = twin_support(merge_support(*r.scene.support));
  if (!q.twist) return;
  const fl::Bounded3 t = twin_of(*q.twist);
  r.true_power = fl::support_function(r.twin, t);
  r.true_load = fl::load_for_twist(r.twin, t);
}

// --mode float: the twin's own direction set, centre of friction and polygonal powers.
void twin_polygons(const Support_query& q, Support_item& r) {
  r.twin_directions = fl::make_directions(q.sides);
  r.twin_center_of_friction = fl::center_of_friction(r.twin);
  for (const fl::Support_point_twin& p : r.twin) r.twin_mu_f0 = r.twin_mu_f0 + p.rho;
  if (!q.twist) return;
  const fl::Bounded3 t = twin_of(*q.twist);
  r.twin_power_inner = fl::polygonal_support(r.twin, *r.twin_directions, false, t);
  r.twin_power_outer = fl::polygonal_support(r.twin, *r.twin_directions, true, t);
}

// A twist's polygonal values (compute_sliding) need the polygons' tables: refused beyond kMaxTableEntries.
void require_tables(const Polygonal_ls& model) {
  const std::string why = model.tables_problem();
  if (!why.empty()) throw Input_error(why);
}

void answer_limit_surface(const Support_query& q, Support_item& r) {
  const Polygonal_ls& model = r.model.emplace(merge_support(*r.scene.support), make_directions(q.sides));
  const bool build = q.polytopes && r.mode != Mode::float_only;
  if (q.twist && r.mode != Mode::float_only) require_tables(model);
  if (build && model.candidate_count() > kMaxCandidates)
    throw Input_error("sides " + std::to_string(q.sides) + " with " + std::to_string(model.support().points.size()) +
                      " distinct support points needs " + std::to_string(model.candidate_count()) +
                      " candidate normals, more than the limit " + std::to_string(kMaxCandidates) +
                      "; use fewer sides (or a larger tolerance)");
  if (r.mode != Mode::exact) true_surface(q, r);
  if (r.mode == Mode::float_only) {
    twin_polygons(q, r);
    return;
  }
  if (build) {
    r.in = model.build(Side::inner);
    r.out = model.build(Side::outer);
    r.polytopes_built = true;
  }
  r.sliding = compute_sliding(model, q.twist);
}

void answer_sliding(const Support_query& q, Support_item& r) {
  if (r.mode != Mode::exact) true_surface(q, r);
  if (r.mode == Mode::float_only) {
    twin_polygons(q, r);
    return;
  }
  const Polygonal_ls& model = r.model.emplace(merge_support(*r.scene.support), make_directions(q.sides));
  if (q.twist) require_tables(model);
  r.sliding = compute_sliding(model, q.twist);
}

// Some force not given: the admissible set, its vertices, and the power range of the twist over it.
void answer_unknown(const Support_model& m, const Support_query& q, Support_item& r) {
  const Support& s = *r.scene.support;
  r.admissible = m.admissible();
  r.pressure_center = *pressure_center_of(r.scene);
  r.weight = *support_weight_of(r.scene);
  if (r.mode == Mode::float_only)
    throw Undecided_error("the float twin has no LP over the admissible distributions (the forces of " +
                          std::to_string(r.admissible->unknown.size()) + " support point(s) are not given)");
  if (r.admissible->unknown.size() <= kMaxEnumeratedUnknowns) r.vertices = m.extreme();
  if (q.twist) r.power = power_range(s, *r.admissible, *q.twist);
}

// [RG-3] Regions together with a point force not given: the admissible set (the regions count as given), its
// vertices, the regions' own statics and bracket, and the power over F (the points' range plus the regions' bracket).
void answer_regions_unknown(const Support_model& m, const Support_query& q, Support_item& r) {
  const Support& s = *r.scene.support;
  r.admissible = m.admissible();
  r.pressure_center = *pressure_center_of(r.scene);
  r.weight = *support_weight_of(r.scene);
  Support regions_only = s;
  regions_only.points.clear();
  r.regions = region_sliding(regions_only, q.twist, q.tolerance ? *q.tolerance : Rational(1, 1000000));
  if (r.admissible->unknown.size() <= kMaxEnumeratedUnknowns) r.vertices = m.extreme();
  if (q.twist) {
    r.power = power_range(s, *r.admissible, *q.twist);
    r.power->lower += r.regions->h_lo;
    r.power->upper += r.regions->h_hi;
  }
}

// [RG-1] [RG-2] A support with regions: the statics exactly, the twist's power and load as certified brackets.
void answer_regions(std::string_view source, const Support_model& m, const Support_query& q, Support_item& r) {
  const Support& s = *r.scene.support;
  if (q.polytopes_asked)
    throw Input_error(std::string(source) + ": support: it has regions, whose limit surface is strictly convex: no exact "
                                            "polytope to build or list (--sides, --list, --off, --obj need support points only)");
  if (r.mode == Mode::float_only)
    throw Undecided_error("the float twin has no model of support regions (their power and certificates are exact "
                          "and interval arithmetic): use --mode hybrid or exact");
  if (!s.known()) return answer_regions_unknown(m, q, r);
  r.regions = region_sliding(s, q.twist, q.tolerance ? *q.tolerance : Rational(1, 1000000));
}

// [SL-1] The load's motion (exact/sliding/motion.h): one decision whatever the support is made of, and the certificate
// of its witnesses (exact/certificates/certificates.h).
void answer_motion(std::string_view source, const Support_model& m, const Support_query& q, Support_item& r) {
  if (m.admissible().unknown.size() > kMaxEnumeratedUnknowns)  // the vertices of F are enumerated
    throw Input_error(std::string(source) + ": support: " + std::to_string(m.admissible().unknown.size()) +
                      " forces are not given: stick or slide over every admissible distribution enumerates the "
                      "extreme ones, at most " + std::to_string(kMaxEnumeratedUnknowns) + " unknown forces");
  Motion_options o;
  o.sides = q.sides;
  if (r.model) o.polygons = {&*r.model, r.polytopes_built ? &r.in : nullptr, r.polytopes_built ? &r.out : nullptr};
  const Motion_answer& a = r.motion.emplace(decide_motion(m, *q.load, r.mode, o));
  if (r.mode == Mode::float_only && a.motion == Motion::undecided && a.uncertified.empty())
    throw Undecided_error("the float twin's search could not tell whether the load sticks (it is within the "
                          "search's resolution of the limit surface)");
  if (a.motion != Motion::undecided && a.uncertified.empty()) r.certificate = motion_certificate(m, *q.load, a);
  if (!r.polytopes_built) return;  // the polygons' own view of the load, for the answer
  r.gauge_in = r.model->gauge(r.in, Side::inner, *q.load);
  r.gauge_out = r.model->gauge(r.out, Side::outer, *q.load);
  if (a.motion != Motion::sticks) {
    r.cone_in = r.model->normal_cone(r.in, Side::inner, *q.load);
    r.cone_out = r.model->normal_cone(r.out, Side::outer, *q.load);
  }
}

void answer(std::string_view source, const Request& request, const Support_query& q, Support_item& r) {
  r.mode = request.mode;
  const bool ls = q.question == Support_question::limit_surface;
  if (!r.scene.support)
    throw Input_error(std::string(source) + ": support: the scene has no \"support\" (" +
                      (ls ? "limit-surface" : "sliding") + " needs one)");
  const Support_model m(r.scene);
  r.kind = !m.known()                   ? Support_kind::unknown
           : m.has_regions()            ? Support_kind::regions
           : r.mode == Mode::float_only ? Support_kind::points_twin
                                        : Support_kind::points;
  if (m.has_regions()) answer_regions(source, m, q, r);
  else if (!m.known()) answer_unknown(m, q, r);
  else if (ls) answer_limit_surface(q, r);
  else answer_sliding(q, r);
  if (ls && q.load) answer_motion(source, m, q, r);
}

// The independent checker on the motion's certificate (Status::check_failed if it ever rejects it).
void check_motion(std::string_view text, const Request& request, Support_item& r) {
  if (r.certificate.empty()) return;
  check_into(r, text, {r.certificate}, request);
}

}  // namespace

Support_item answer_support(std::string_view text, std::string_view source, const Request& request,
                            const Support_query& query) {
  return answer_into_item<Support_item>(text, source, request.limits, [&](Support_item& item) {
    answer(source, request, query, item);
    check_motion(text, request, item);
  });
}

Support_item answer_support(const Scene& scene, std::string_view text, std::string_view source, const Request& request,
                            const Support_query& query) {
  return answer_into_item<Support_item>(scene, request.limits, [&](Support_item& item) {
    answer(source, request, query, item);
    check_motion(text, request, item);
  });
}

}  // namespace wrenchkit
