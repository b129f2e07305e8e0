#include "exact/pipeline/support_answer.h"

#include "exact/io/streaming_scene_reader.h"
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

void answer_limit_surface(const Support_query& q, Support_item& r) {
  const Polygonal_ls& model = r.model.emplace(merge_support(*r.scene.support), make_directions(q.sides));
  if (model.candidate_count() > kMaxCandidates)
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
  r.in = model.build(Side::inner);
  r.out = model.build(Side::outer);
  r.sliding = compute_sliding(model, q.twist);
  if (!q.load) return;
  r.gauge_in = model.gauge(r.in, Side::inner, *q.load);
  r.gauge_out = model.gauge(r.out, Side::outer, *q.load);
  r.motion = decide_motion(model, *q.load, r.mode, &r.in, &r.out);
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
  r.sliding = compute_sliding(r.model.emplace(merge_support(*r.scene.support), make_directions(q.sides)), q.twist);
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
    if (r.admissible->unknown.size() > kMaxEnumeratedUnknowns)
      throw Input_error(std::string(source) + ": support: " + std::to_string(r.admissible->unknown.size()) +
                        " forces are not given: stick or slide over every admissible distribution enumerates the "
                        "extreme ones, at most " + std::to_string(kMaxEnumeratedUnknowns) + " unknown forces");
    r.motion_over = decide_motion_over(s, *r.admissible, *q.load, r.mode, q.sides);
  }
}

void answer(std::string_view source, const Request& request, const Support_query& q, Support_item& r) {
  r.mode = request.mode;
  const bool ls = q.question == Support_question::limit_surface;
  if (!r.scene.support)
    throw Input_error(std::string(source) + ": support: the scene has no \"support\" (" +
                      (ls ? "limit-surface" : "sliding") + " needs one)");
  if (!r.scene.support->known()) return answer_unknown(source, q, r);
  if (ls) answer_limit_surface(q, r);
  else answer_sliding(q, r);
}

}  // namespace

Support_item answer_support(std::string_view text, std::string_view source, const Request& request,
                            const Support_query& query) {
  Support_item item;
  guarded(item, [&] {
    read_scene_into(item.scene, text, request.limits, source, false);
    answer(source, request, query, item);
  });
  return item;
}

Support_item answer_support(const Scene& scene, std::string_view source, const Request& request,
                            const Support_query& query) {
  Support_item item;
  guarded(item, [&] {
    item.scene = scene;
    answer(source, request, query, item);
  });
  return item;
}

}  // namespace wrenchkit
