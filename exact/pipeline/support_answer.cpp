#include "exact/pipeline/support_answer.h"

#include <algorithm>

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
    if (q.load) {
      r.motion = decide_motion(model, *q.load, Mode::float_only);
      if (r.motion.motion == Motion::undecided)
        throw Undecided_error("the float twin's search could not tell whether the load sticks (it is within the "
                              "search's resolution of the limit surface)");
    }
    return;
  }
  if (build) {
    r.in = model.build(Side::inner);
    r.out = model.build(Side::outer);
    r.polytopes_built = true;
  }
  r.sliding = compute_sliding(model, q.twist);
  if (!q.load) return;
  // Hybrid decides on the true surface first; the polytopes only when it cannot tell (decide_motion builds them
  // then, within kMaxCandidates).
  r.motion = decide_motion(model, *q.load, r.mode, build ? &r.in : nullptr, build ? &r.out : nullptr);
  if (!build) return;
  r.gauge_in = model.gauge(r.in, Side::inner, *q.load);
  r.gauge_out = model.gauge(r.out, Side::outer, *q.load);
  if (r.motion.motion != Motion::sticks) {
    r.cone_in = model.normal_cone(r.in, Side::inner, *q.load);
    r.cone_out = model.normal_cone(r.out, Side::outer, *q.load);
  }
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

// Stick or slide over F enumerates F's vertices: refused beyond kMaxEnumeratedUnknowns unknown forces.
Input_error too_many_unknowns(std::string_view source, std::size_t n) {
  return Input_error(std::string(source) + ": support: " + std::to_string(n) +
                     " forces are not given: stick or slide over every admissible distribution enumerates the "
                     "extreme ones, at most " + std::to_string(kMaxEnumeratedUnknowns) + " unknown forces");
}

// Some force not given: the admissible set, its vertices, and the power range of the twist over it.
void answer_unknown(std::string_view source, const Support_query& q, Support_item& r) {
  const Support& s = *r.scene.support;
  r.admissible = admissible_set(r.scene);
  r.pressure_center = *pressure_center_of(r.scene);
  if (r.mode == Mode::float_only)
    throw Undecided_error("the float twin has no LP over the admissible distributions (the forces of " +
                          std::to_string(r.admissible->unknown.size()) + " support point(s) are not given)");
  if (r.admissible->unknown.size() <= kMaxEnumeratedUnknowns) r.vertices = vertices(s, *r.admissible);
  if (q.twist) r.power = power_range(s, *r.admissible, *q.twist);
  if (q.question == Support_question::limit_surface && q.load) {
    if (r.admissible->unknown.size() > kMaxEnumeratedUnknowns) throw too_many_unknowns(source, r.admissible->unknown.size());
    r.motion_over = decide_motion_over(s, *r.admissible, *q.load, r.mode, q.sides);
  }
}

Vec3q rational_twist(const std::array<double, 3>& w) { return {Rational(w[0]), Rational(w[1]), Rational(w[2])}; }

// Twists that may prove "slides" for the distribution f: the certified search's witness, else the outward
// normals of LS_out at the load (its normal cone's generators).
std::vector<Vec3q> slide_candidates(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                    const Motion_decision& d, int sides, const Polygonal_ls::Normal_cone* cone) {
  std::vector<Vec3q> c;
  if (std::string(d.decided_by) == "float") c.push_back(rational_twist(d.witness));
  if (d.exact_witness) c.push_back(*d.exact_witness);
  std::optional<Polygonal_ls::Normal_cone> built;
  if (!cone && std::string(d.decided_by) != "float" && !d.exact_witness) {
    const Polygonal_ls model(merge_support(s, &f), make_directions(sides));
    if (model.candidate_count() > kMaxCandidates) return c;
    const Ls_polytope out = model.build(Side::outer);
    cone = &built.emplace(model.normal_cone(out, Side::outer, p));
  }
  if (cone)
    for (const Vec3z& g : cone->generators) c.push_back({Rational(g[0]), Rational(g[1]), Rational(g[2])});
  // A load far outside: q = p itself; a flat limit surface (friction at one point r, or none): the rotations
  // about r, which cost no friction.
  if (p[0] != 0 || p[1] != 0 || p[2] != 0) c.push_back(p);
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Support_point& pt = s.points[i];
    if (s.mu_of(pt) * f[i] == 0) continue;
    c.push_back({pt.at.y, -pt.at.x, Rational(1)});  // v(r) = (vx − w y, vy + w x) = 0
    c.push_back({-pt.at.y, pt.at.x, Rational(-1)});
    break;
  }
  c.push_back({Rational(1), Rational(0), Rational(0)});
  return c;
}

std::optional<Slide_witness> first_slide_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                                 const std::vector<Vec3q>& candidates) {
  for (const Vec3q& q : candidates)
    if (auto w = slide_witness(s, f, p, q)) return w;
  return std::nullopt;
}

// [SL-4] The certificate of a known distribution's motion.
void certify_known(const Support_query& q, Support_item& r) {
  const Support& s = *r.scene.support;
  const Admissible a = admissible_set(r.scene);
  const Vec3q& p = *q.load;
  if (r.motion.motion == Motion::sticks) {
    if (auto w = stick_witness_refined(s, a, p, std::max(q.sides, 8), a.given)) {
      r.certificate = sticks_certificate(p, *w);
    } else if (auto sw = first_slide_witness(s, a.given, p, slide_candidates(s, a.given, p, r.motion, q.sides, nullptr))) {
      // No interior at all (a flat limit surface: friction at fewer than two points): the load is on it and slides.
      r.certificate = slides_certificate(p, *sw);
      r.motion.motion = Motion::slides;
      r.motion.decided_by = "certificate";
    }
  } else if (r.motion.motion == Motion::slides) {
    const bool cone = r.polytopes_built && (!r.cone_out.generators.empty() || !r.cone_out.lineality.empty());
    const auto c = slide_candidates(s, a.given, p, r.motion, q.sides, cone ? &r.cone_out : nullptr);
    if (auto w = first_slide_witness(s, a.given, p, c)) r.certificate = slides_certificate(p, *w);
  }
  if (r.motion.motion == Motion::sticks && r.certificate.empty() &&
      s.points.size() * static_cast<std::size_t>(std::max(q.sides, 8)) > kMaxStickWitnessColumns) {
    // Too many support points for the stick witness LP: the certified search's verdict stands, unchecked.
    r.uncertified = "no certificate: the stick witness LP is run up to " + std::to_string(kMaxStickWitnessColumns) +
                    " columns (support points x sides); the verdict is the float twin's certified search's";
    return;
  }
  if (r.motion.motion != Motion::undecided && r.certificate.empty()) {
    r.uncertified = std::string("the certified search says ") + motion_name(r.motion.motion) +
                    ", but no rational witness was found (the load is too close to the limit surface for the witnesses: "
                    "the smoothed twist witness in double and the exact LP on inscribed 256-gons)";
    r.motion.motion = Motion::undecided;
  }
}

// [SL-4] The certificate of a motion over every admissible distribution.
void certify_over(const Support_query& q, Support_item& r) {
  const Support& s = *r.scene.support;
  const Admissible& a = *r.admissible;
  Motion_over_f& m = *r.motion_over;
  const Vec3q& p = *q.load;
  const int sides = std::max(q.sides, 8);
  if (m.motion == Motion_over::sticks) {
    std::vector<Stick_witness> ws;
    for (const auto& f : r.vertices) {
      auto w = stick_witness_refined(s, a, p, sides, f);
      if (!w) break;
      ws.push_back(std::move(*w));
    }
    if (ws.size() == r.vertices.size()) r.certificate = sticks_for_every_certificate(p, ws);
  } else if (m.motion == Motion_over::slides) {
    const Vec3q& t = *m.separating_twist;
    const std::vector<Rational> u = speed_bounds(s, t);
    std::vector<Rational> coef(s.points.size());
    for (std::size_t i = 0; i < coef.size(); ++i) {
      const Support_point& pt = s.points[i];
      coef[i] = s.mu_of(pt) * u[i];
    }
    const F_optimum o = maximise_over(s, a, coef);
    if (dot(t, p) >= o.value) r.certificate = slides_for_every_certificate(p, t, u, o.dual);
  } else if (m.motion == Motion_over::depends) {
    std::optional<Stick_witness> sticking = m.sticking;
    if (!sticking) sticking = stick_witness_refined(s, a, p, sides, r.vertices[*m.sticking_vertex]);
    const std::vector<Rational>& f = r.vertices[*m.sliding_vertex];
    const auto sliding = first_slide_witness(s, f, p, slide_candidates(s, f, p, m.decisions[*m.sliding_vertex], sides, nullptr));
    if (sticking && sliding) r.certificate = depends_certificate(p, *sticking, *sliding);
  }
  if (m.motion != Motion_over::undecided && r.certificate.empty()) {
    r.uncertified = std::string("the answer is ") + motion_over_name(m.motion) +
                    ", but no rational witness was found (the load is too close to the limit surface for the witnesses: "
                    "the smoothed twist witness in double and the exact LP on inscribed 256-gons)";
    m.motion = Motion_over::undecided;
  }
}

// [RG-3] Regions together with a point force not given: the admissible set (the regions count as given), its
// vertices, the regions' own statics and bracket, the power over F (the points' range plus the regions' bracket), and
// the load's motion over F with its format-2 certificate (checked by check_motion).
void answer_regions_unknown(std::string_view source, const Support_query& q, Support_item& r) {
  const Support& s = *r.scene.support;
  r.admissible = admissible_set(r.scene);
  r.pressure_center = *pressure_center_of(r.scene);
  Support regions_only = s;
  regions_only.points.clear();
  r.regions = region_sliding(regions_only, q.twist, q.tolerance ? *q.tolerance : Rational(1, 1000000));
  const bool enumerable = r.admissible->unknown.size() <= kMaxEnumeratedUnknowns;
  if (enumerable) r.vertices = vertices(s, *r.admissible);
  if (q.twist) {
    r.power = power_range(s, *r.admissible, *q.twist);
    r.power->lower += r.regions->h_lo;
    r.power->upper += r.regions->h_hi;
  }
  if (q.question != Support_question::limit_surface || !q.load) return;
  if (!enumerable) throw too_many_unknowns(source, r.admissible->unknown.size());
  r.region_motion_over = decide_region_motion_over(s, *r.admissible, *q.load, r.vertices);
  r.motion_over = r.region_motion_over->over;
  r.certificate = r.region_motion_over->certificate;
}

// [RG-1] [RG-2] A support with regions: the statics exactly, the twist's power and load as certified brackets,
// the load's motion by a certificate (checked by check_motion).
void answer_regions(std::string_view source, const Support_query& q, Support_item& r) {
  const Support& s = *r.scene.support;
  if (q.polytopes_asked)
    throw Input_error(std::string(source) + ": support: it has regions, whose limit surface is strictly convex: no exact "
                                            "polytope to build or list (--sides, --list, --off, --obj need support points only)");
  if (r.mode == Mode::float_only)
    throw Undecided_error("the float twin has no model of support regions (their power and certificates are exact "
                          "and interval arithmetic): use --mode hybrid or exact");
  if (!s.known()) return answer_regions_unknown(source, q, r);
  r.regions = region_sliding(s, q.twist, q.tolerance ? *q.tolerance : Rational(1, 1000000));
  if (q.question != Support_question::limit_surface || !q.load) return;
  r.region_motion = decide_region_motion(s, *q.load);
  r.motion.motion = r.region_motion->motion;
  r.motion.decided_by = r.region_motion->motion == Motion::undecided ? "none" : "certificate";
  r.certificate = r.region_motion->certificate;
}

void answer(std::string_view source, const Request& request, const Support_query& q, Support_item& r) {
  r.mode = request.mode;
  const bool ls = q.question == Support_question::limit_surface;
  if (!r.scene.support)
    throw Input_error(std::string(source) + ": support: the scene has no \"support\" (" +
                      (ls ? "limit-surface" : "sliding") + " needs one)");
  if (!r.scene.support->regions.empty()) return answer_regions(source, q, r);
  if (!r.scene.support->known()) {
    answer_unknown(source, q, r);
    if (r.motion_over) certify_over(q, r);
  } else {
    if (ls) answer_limit_surface(q, r);
    else answer_sliding(q, r);
    if (ls && q.load) certify_known(q, r);
  }
}

// The independent checker on the motion's certificate (Status::check_failed if it ever rejects it).
void check_motion(std::string_view text, const Request& request, Support_item& r) {
  if (r.certificate.empty()) return;
  std::string why = check_certificates(text, {r.certificate}, request);
  if (!why.empty()) {
    r.status = Status::check_failed;
    r.message = std::move(why);
  }
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
  return answer_into_item<Support_item>(scene, [&](Support_item& item) {
    answer(source, request, query, item);
    check_motion(text, request, item);
  });
}

}  // namespace wrenchkit
