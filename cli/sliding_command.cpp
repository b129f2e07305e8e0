// wrenchkit sliding: centre of friction and the frictional load of the scene's support for a twist
// (theory.md §10, §11.5) [LS-4]. Exact for translations; exact bounds for rotations.
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.h"
#include "cli/float_json.h"
#include "exact/io/input_error.h"
#include "exact/io/json.h"
#include "exact/pipeline/support_answer.h"
#include "exact/sliding/sliding.h"
#include "exact/io/streaming_scene_reader.h"
#include "exact/io/to_float.h"

namespace wrenchkit::cli {

// An unknown distribution (docs/theory-sliding.md §1–§2), for sliding and limit-surface alike.
std::string distribution_json(const std::vector<Rational>& f) {
  std::string s = "[";
  for (std::size_t i = 0; i < f.size(); ++i) s += (i ? ", " : "") + json::quote(to_string(f[i]));
  return s + "]";
}

std::string unknown_distribution_fields(const Support_item& r) {
  const Admissible& a = *r.admissible;
  std::string s = ", \"distribution\": \"unknown\", \"unknown_points\": [";
  for (std::size_t k = 0; k < a.unknown.size(); ++k) s += (k ? ", " : "") + std::to_string(a.unknown[k]);
  s += "], \"weight\": " + json::quote(to_string(*r.scene.support->weight)) + ", \"pressure_center\": [" +
       json::quote(to_string(r.pressure_center.x)) + ", " + json::quote(to_string(r.pressure_center.y)) +
       "], \"extreme_distributions\": ";
  if (a.unknown.size() > kMaxEnumeratedUnknowns) return s + "null";
  s += "[";
  for (std::size_t v = 0; v < r.vertices.size(); ++v) s += (v ? ", " : "") + distribution_json(r.vertices[v]);
  return s + "]";
}

std::string power_over_fields(const Support_item& r) {
  return ", \"power\": {\"lower\": " + json::quote(to_string(r.power->lower)) + ", \"upper\": " +
         json::quote(to_string(r.power->upper)) + ", \"min_distribution\": " +
         distribution_json(r.power->min_distribution) + ", \"max_distribution\": " +
         distribution_json(r.power->max_distribution) + "}";
}

namespace {

std::string jq(const Rational& q) { return json::quote(to_string(q)); }
std::string jv(const Vec3q& v) { return "[" + jq(v[0]) + ", " + jq(v[1]) + ", " + jq(v[2]) + "]"; }
std::string thv(const Vec3q& v) {
  return "(" + human_number(v[0]) + ", " + human_number(v[1]) + ", " + human_number(v[2]) + ")";
}
std::string face_json(const Ls_face& f) {
  std::string s = "{\"dimension\": " + std::to_string(f.dimension) + ", \"vertices\": [";
  for (std::size_t i = 0; i < f.vertices.size(); ++i) s += (i ? ", " : "") + jv(f.vertices[i]);
  return s + "]}";
}

// The options (validated where they were parsed): --twist (not zero) and --sides (default 64).
struct Sliding_options {
  std::optional<Vec3q> twist;
  int sides = 64;
  Mode mode = Mode::hybrid;
};

Sliding_options sliding_options(const Options& o) {
  Sliding_options so;
  so.sides = o.sides.value_or(64);
  so.twist = o.twist;
  so.mode = o.mode;
  return so;
}

// The scene's answer through the pipeline; a failure unwinds as the CLI's Failure.
Support_item compute(const Sliding_options& so, const Options& o, const std::string& text, const std::string& source) {
  Support_query q;
  q.question = Support_question::sliding;
  q.sides = so.sides;
  q.twist = so.twist;
  return answered(answer_support(text, source, request_of(o), q));
}

// The float twin's values for the twist (hybrid: added to the exact answer).
std::string true_fields(const Support_item& r) {
  if (!r.true_power) return "";
  return ", \"true_power\": " + float_value_json(*r.true_power) + ", \"true_load\": " + float_load_json(*r.true_load);
}

std::string sliding_float_json(const Sliding_options& so, const Support_item& r) {
  const fl::Point2& cof = r.twin_center_of_friction;
  const fl::Bounded& mu_f0 = r.twin_mu_f0;
  std::ostringstream s;
  s << "{\"command\": \"sliding\", \"name\": " << json::quote(r.scene.name) << ", \"mode\": \"float\""
    << ", \"center_of_friction\": [" << float_value_json(cof.x) << ", " << float_value_json(cof.y)
    << "], \"mu_f0\": " << float_value_json(mu_f0);
  if (so.twist)
    s << ", \"twist\": " << jv(*so.twist) << ", \"sides\": " << so.sides << ", \"lambda_squared\": "
      << float_value_json(r.twin_directions->lambda_sq) << ", \"power\": {\"inner\": "
      << float_value_json(*r.twin_power_inner) << ", \"outer\": " << float_value_json(*r.twin_power_outer) << "}"
      << true_fields(r);
  s << "}";
  return s.str();
}

std::string sliding_float_human(const Sliding_options& so, const Support_item& r, const std::string& source) {
  const fl::Point2& cof = r.twin_center_of_friction;
  std::ostringstream s;
  s << "scene: " << (r.scene.name.empty() ? source : r.scene.name) << "\n"
    << "centre of friction: (" << float_value_text(cof.x) << ", " << float_value_text(cof.y) << ")\n";
  if (so.twist)
    s << "twist (" << human_number((*so.twist)[0]) << ", " << human_number((*so.twist)[1]) << ", "
      << human_number((*so.twist)[2]) << "):\n"
      << "  true power h = " << float_value_text(*r.true_power) << "\n"
      << "  true load: " << float_load_text(*r.true_load) << "\n";
  s << "decided by: the float twin alone (values with certified bounds)\n";
  return s.str();
}

const char* kConvention =
    "loads: the wrench the slider applies to the support, parallel to the sliding velocity (theory.md 1.5); "
    "the friction wrench on the slider is its negative";

std::string sliding_unknown_json(const Sliding_options& so, const Support_item& r) {
  return "{\"command\": \"sliding\", \"name\": " + json::quote(r.scene.name) + ", \"mode\": \"" +
         mode_name(r.mode) + "\", \"convention\": " + json::quote(kConvention) + unknown_distribution_fields(r) +
         (so.twist ? ", \"twist\": " + jv(*so.twist) + power_over_fields(r) : std::string()) + "}";
}

std::string sliding_unknown_human(const Sliding_options& so, const Support_item& r, const std::string& source) {
  const Admissible& a = *r.admissible;
  const auto dist = [](const std::vector<Rational>& f) {
    std::string s = "(";
    for (std::size_t i = 0; i < f.size(); ++i) s += (i ? ", " : "") + human_number(f[i]);
    return s + ")";
  };
  std::ostringstream s;
  s << "scene: " << (r.scene.name.empty() ? source : r.scene.name) << "\n"
    << "support: " << r.scene.support->points.size() << " points, the forces of " << a.unknown.size()
    << " not given; weight " << human_number(*r.scene.support->weight) << ", centre of pressure ("
    << human_number(r.pressure_center.x) << ", " << human_number(r.pressure_center.y) << ")\n";
  if (a.unknown.size() <= kMaxEnumeratedUnknowns)
    s << "extreme admissible distributions: " << r.vertices.size() << "\n";
  if (so.twist)
    s << "twist " << thv(*so.twist) << ": the frictional power over every admissible distribution lies in ["
      << human_number(r.power->lower) << ", " << human_number(r.power->upper) << "]\n"
      << "  least at f = " << dist(r.power->min_distribution) << ", most at f = " << dist(r.power->max_distribution)
      << "\n";
  s << "convention: " << kConvention << "\n";
  return s.str();
}

std::string sliding_json(const Sliding_options& so, const Support_item& r) {
  const Sliding_answer& a = r.sliding;
  const char* kinds[] = {"facet", "vertex", "smooth"};
  std::ostringstream s;
  s << "{\"command\": \"sliding\", \"name\": " << json::quote(r.scene.name) << ", \"mode\": \"" << mode_name(so.mode)
    << "\", \"convention\": " << json::quote(kConvention)
    << ", \"center_of_friction\": [" << jq(a.center_of_friction.x) << ", " << jq(a.center_of_friction.y)
    << "], \"friction_centroid\": [" << jq(a.friction_centroid.x) << ", " << jq(a.friction_centroid.y)
    << "], \"mu_f0\": " << jq(a.mu_f0);
  if (a.has_twist) {
    s << ", \"twist\": " << jv(a.twist) << ", \"motion\": \"" << (a.translation ? "translation" : "rotation") << "\"";
    if (a.translation) {
      s << ", \"load_direction\": " << jv(a.load_direction) << ", \"speed_squared\": " << jq(a.speed_squared)
        << ", \"load\": " << (a.load ? jv(*a.load) : std::string("null"));
    } else {
      s << ", \"rotation_center\": [" << jq(a.rotation_center.x) << ", " << jq(a.rotation_center.y) << "]";
    }
    s << ", \"true_surface\": {\"kind\": \"" << kinds[static_cast<int>(a.cls.kind)] << "\", \"text\": "
      << json::quote(a.cls.text);
    if (a.cls.support_point >= 0) {
      const Ls_point& p = r.model->support().points[static_cast<std::size_t>(a.cls.support_point)];
      s << ", \"facet_disc\": {\"at\": [" << jq(p.at.x) << ", " << jq(p.at.y) << "], \"radius\": " << jq(p.rho) << "}";
    }
    s << "}, \"sides\": " << so.sides << ", \"lambda_squared\": " << jq(r.model->directions().lambda_sq)
      << ", \"power\": {\"inner\": " << jq(a.h_inner) << ", \"outer\": " << jq(a.h_outer) << ", \"lower\": "
      << jq(a.h_lo) << ", \"upper\": " << jq(a.h_hi) << "}, \"load_box\": {\"lower\": " << jv(a.load_lo)
      << ", \"upper\": " << jv(a.load_hi) << ", \"of\": \""
      << (a.cls.kind == Twist_kind::facet ? "the facet's centre" : "the load") << "\"}, \"inner_load\": "
      << face_json(a.inner_face) << ", \"outer_load\": " << face_json(a.outer_face) << true_fields(r);
  }
  s << "}";
  return s.str();
}

std::string sliding_human(const Sliding_options& so, const Support_item& r, const std::string& source) {
  const Sliding_answer& a = r.sliding;
  std::ostringstream s;
  s << "scene: " << (r.scene.name.empty() ? source : r.scene.name) << "\n"
    << "centre of friction: (" << human_number(a.center_of_friction.x) << ", " << human_number(a.center_of_friction.y) << ")\n"
    << "mu*f0 = " << human_number(a.mu_f0) << ", friction centroid (" << human_number(a.friction_centroid.x) << ", "
    << human_number(a.friction_centroid.y) << ")\n";
  if (a.has_twist) {
    s << "twist " << thv(a.twist) << ": " << a.cls.text << "\n";
    if (a.translation) {
      if (a.load) s << "load: " << thv(*a.load) << " (exact)\n";
      else
        s << "load: (mu*f0/|v|) * " << thv(a.load_direction) << " with |v|^2 = " << human_number(a.speed_squared)
          << " (exact)\n";
    } else {
      s << "power h between " << human_number(a.h_inner) << " and " << human_number(a.h_outer) << " (polygonal, "
        << so.sides << " sides)\n";
    }
    s << "load box: " << thv(a.load_lo) << " .. " << thv(a.load_hi)
      << (a.cls.kind == Twist_kind::facet ? " (the facet's centre)\n" : "\n");
    if (r.true_power)
      s << "true power h = " << float_value_text(*r.true_power) << ", true load " << float_load_text(*r.true_load)
        << " (float twin, certified bounds)\n";
  }
  s << "convention: " << kConvention << "\n";
  return s.str();
}

// The answer as JSON and as text, by what the pipeline answered (an unknown distribution, the twin alone,
// or the exact answer).
std::string answer_json(const Sliding_options& so, const Support_item& r) {
  if (r.admissible) return sliding_unknown_json(so, r);
  return so.mode == Mode::float_only ? sliding_float_json(so, r) : sliding_json(so, r);
}

std::string answer_text(const Sliding_options& so, const Support_item& r, const std::string& source) {
  if (r.admissible) return sliding_unknown_human(so, r, source);
  return so.mode == Mode::float_only ? sliding_float_human(so, r, source) : sliding_human(so, r, source);
}

}  // namespace

Scene_answer prepare_sliding_json(const Options& o) { return per_scene(o, sliding_options, compute, answer_json); }

int run_sliding(const Options& o, const std::string& text, const std::string& source) {
  return run_per_scene(o, text, source, sliding_options, compute, answer_json, answer_text);
}

}  // namespace wrenchkit::cli
