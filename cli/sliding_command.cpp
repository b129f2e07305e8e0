// wrenchkit sliding: centre of friction and the frictional load of the scene's support for a twist
// (theory.md §10, §11.5) [LS-4]. Exact for translations; exact bounds for rotations.
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.h"
#include "cli/float_json.h"
#include "exact/numbers/decimal.h"
#include "exact/io/input_error.h"
#include "exact/io/json_writer.h"
#include "exact/pipeline/support_answer.h"
#include "exact/sliding/sliding.h"
#include "exact/io/streaming_scene_reader.h"
#include "exact/io/to_float.h"

namespace wrenchkit::cli {

// An unknown distribution (docs/theory-sliding.md §1–§2), for sliding and limit-surface alike.
std::string distribution_text(const std::vector<Rational>& f) { return vec_text(f); }

namespace {

void write_xy(Json_writer& w, const Vec2& p) { w.array().rational(p.x).rational(p.y).end_array(); }
// A point people read (a centre): "key": [x, y] exact and "key_approx": its decimals.
void write_centre(Json_writer& w, const std::string& key, const Vec2& p) {
  write_xy(w.key(key), p);
  write_approx(w, key, {p.x, p.y});
}


// "support": {"points": n, "regions": [{area, force, mu, centre of pressure, pressure, moments, triangles}, …]}.
void write_support_regions(Json_writer& w, const Support& s) {
  w.key("support").object().member("points", s.points.size()).key("regions").array();
  for (const Support_region& g : s.regions) {
    w.object().member("area", g.area).member("force", g.total).member("mu", s.mu_of(g));
    write_xy(w.key("center_of_pressure"), {g.moment.x / g.total, g.moment.y / g.total});
    w.member("pressure", g.uniform ? "uniform" : "linear").key("pressure_coefficients").rationals(g.pressure);
    w.key("second_moments").rationals(g.second).member("triangles", g.triangles.size()).end_object();
  }
  w.end_array().end_object();
}

// One line per region: "  region k: area …, force …, mu …, centre of pressure (…) (… pressure, n triangles)".
std::string region_lines(const Support& s) {
  std::ostringstream o;
  for (std::size_t k = 0; k < s.regions.size(); ++k) {
    const Support_region& g = s.regions[k];
    o << "  region " << k << ": area " << number_text(g.area) << ", force " << number_text(g.total) << ", mu "
      << number_text(s.mu_of(g)) << ", centre of pressure " << vec_text(Vec2{g.moment.x / g.total, g.moment.y / g.total})
      << " (" << (g.uniform ? "uniform" : "linear") << " pressure, " << g.triangles.size() << " triangles)\n";
  }
  return o.str();
}

}  // namespace

std::string unknown_support_text(const Support_item& r, const std::string& source) {
  const Admissible& a = *r.admissible;
  std::string s = scene_line(r.scene, source) + "support: " + std::to_string(r.scene.support->points.size()) +
                  " points, the forces of " + std::to_string(a.unknown.size()) + " not given; weight " +
                  number_text(r.weight) + ", centre of pressure " + vec_text(r.pressure_center);
  if (a.unknown.size() <= kMaxEnumeratedUnknowns)
    s += "; " + std::to_string(r.vertices.size()) + " extreme admissible distributions";
  s += "\n";
  if (r.regions)  // [RG-3] regions beside the points: their pressure is known, so they count as given in F
    s += "  and " + std::to_string(r.scene.support->regions.size()) + " region(s) with a known pressure (given in F):\n" +
         region_lines(*r.scene.support);
  return s;
}

void write_unknown_distribution(Json_writer& w, const Support_item& r) {
  const Admissible& a = *r.admissible;
  w.member("distribution", "unknown").key("unknown_points").array();
  for (const auto k : a.unknown) w.integer(k);
  w.end_array().member("weight", r.weight);
  w.key("pressure_center").array().rational(r.pressure_center.x).rational(r.pressure_center.y).end_array();
  w.key("extreme_distributions");
  if (a.unknown.size() > kMaxEnumeratedUnknowns) {
    w.null();
  } else {
    w.array();
    for (const std::vector<Rational>& f : r.vertices) w.rationals(f);
    w.end_array();
  }
  if (r.regions) write_support_regions(w, *r.scene.support);  // [RG-3] the regions, given in F
}

std::string regions_power_text(const Support_item& r) {
  if (!r.regions || !r.regions->has_twist) return "";
  const std::string lo = decimal_text(r.regions->h_lo, 10), hi = decimal_text(r.regions->h_hi, 10);
  return std::string("  of which the regions' power (every distribution alike) lies in [") + lo + ", " + hi +
         "] (certified: exact rational ends in --json)\n";
}

void write_power_over(Json_writer& w, const Support_item& r) {
  w.key("power").object().member("lower", r.power->lower).member("upper", r.power->upper);
  w.key("min_distribution").rationals(r.power->min_distribution);
  w.key("max_distribution").rationals(r.power->max_distribution);
  if (r.regions && r.regions->has_twist)  // [RG-3] the regions' certified bracket, included in lower and upper
    w.key("regions").object().member("lower", r.regions->h_lo).member("upper", r.regions->h_hi)
        .member("tolerance_met", r.regions->met).member("precision_bits", r.regions->bits).end_object();
  w.end_object();
}

namespace {

// "twist", "motion", and the translation's exact load or the rotation's centre (Sliding_answer and Region_sliding
// alike).
template <class Answer>
void write_twist_motion(Json_writer& w, const Answer& a) {
  w.key("twist").rationals(a.twist).member("motion", a.translation ? "translation" : "rotation");
  if (a.translation) {
    w.key("load_direction").rationals(a.load_direction).member("speed_squared", a.speed_squared).key("load");
    a.load ? w.rationals(*a.load) : w.null();
    if (a.load) write_approx(w, "load", {(*a.load)[0], (*a.load)[1], (*a.load)[2]});
  } else {
    write_centre(w, "rotation_center", a.rotation_center);
  }
}

}  // namespace

void write_region_statics(Json_writer& w, const Support_item& r) {
  const Region_sliding& a = *r.regions;
  write_support_regions(w, *r.scene.support);
  w.member("total_force", a.total_force);
  write_centre(w, "center_of_friction", a.center_of_pressure);
  write_centre(w, "friction_centroid", a.friction_centroid);
  w.member("mu_f0", a.mu_f0);
}

void write_region_twist(Json_writer& w, const Support_item& r, const Rational& tolerance) {
  const Region_sliding& a = *r.regions;
  if (!a.has_twist) return;
  write_twist_motion(w, a);
  if (!a.translation) w.member("rotation_about_a_support_point", a.center_on_point);
  w.key("power").object().member("lower", a.h_lo).member("upper", a.h_hi).member("tolerance", tolerance);
  w.member("tolerance_met", a.met).member("precision_bits", a.bits).end_object();
  w.key("load_box").object().key("lower").rationals(a.load_lo).key("upper").rationals(a.load_hi).end_object();
}

std::string region_statics_text(const Support_item& r, const std::string& source) {
  const Support& s = *r.scene.support;
  const Region_sliding& a = *r.regions;
  std::ostringstream o;
  o << scene_line(r.scene, source) << "support: " << s.points.size() << " point(s) and " << s.regions.size()
    << " region(s) with a continuous pressure\n" << region_lines(s);
  o << "total normal force " << number_text(a.total_force) << ", centre of friction " << vec_text(a.center_of_pressure)
    << " (exact)\nmu*f0 = " << number_text(a.mu_f0) << ", friction centroid " << vec_text(a.friction_centroid) << "\n";
  return o.str();
}

std::string region_twist_text(const Support_item& r) {
  const Region_sliding& a = *r.regions;
  if (!a.has_twist) return "";
  std::ostringstream o;
  o << "twist " << vec_text(a.twist) << ": ";
  if (a.translation) {
    o << "a translation: the load is the force mu*f0 along v through the friction centroid\n";
    if (a.load) o << "  load: " << vec_text(*a.load) << " (exact)\n";
    else
      o << "  load: (mu*f0/|v|) * " << vec_text(a.load_direction) << " with |v|^2 = " << number_text(a.speed_squared)
        << " (exact)\n";
  } else {
    o << "rotation about " << vec_text(a.rotation_center)
      << (a.center_on_point ? " (a support point: its disc is a facet, inside the load box)" : "") << "\n";
  }
  o << "  power h in [" << decimal_text(a.h_lo, 10) << ", " << decimal_text(a.h_hi, 10) << "] (certified: exact rational ends in --json"
    << (a.met ? "" : "; the tolerance was not met at the largest precision") << ")\n"
    << "  load box: " << vec_text(a.load_lo) << " .. " << vec_text(a.load_hi) << "\n";
  return o.str();
}

namespace {

void write_pair(Json_writer& w, const Rational& x, const Rational& y) { w.array().rational(x).rational(y).end_array(); }
void write_face(Json_writer& w, const Ls_face& f) {
  w.object().member("dimension", f.dimension).key("vertices").array();
  for (const Vec3q& v : f.vertices) w.rationals(v);
  w.end_array().end_object();
}

const char* kConvention =
    "loads: the wrench the slider applies to the support, parallel to the sliding velocity (theory.md 1.5); "
    "the friction wrench on the slider is its negative";

// The pipeline's query from the options (validated where they were parsed): --twist (not zero), --sides (default 64;
// refused for regions), --tolerance (the relative width of a region's power bracket, default 10^-6).
Support_query sliding_options(const Options& o) {
  Support_query q;
  q.question = Support_question::sliding;
  q.sides = o.sides.value_or(64);
  q.polytopes_asked = o.sides.has_value();
  q.twist = o.twist;
  q.tolerance = o.tolerance.value_or(Rational(1, 1000000));
  return q;
}

// The scene's answer through the pipeline; a failure unwinds as the CLI's Failure.
Support_item compute(const Support_query& q, const Options& o, const std::string& text, const std::string& source) {
  return answered(answer_support(text, source, request_of(o), q));
}

// A support with regions [RG-1]: the exact statics, and the twist's certified power and load.
void write_sliding_regions(Json_writer& w, const Support_query& q, const Support_item& r) {
  w.member("command", "sliding").member("name", r.scene.name).member("mode", mode_name(r.mode));
  w.member("convention", kConvention);
  write_region_statics(w, r);
  write_region_twist(w, r, *q.tolerance);
}

std::string sliding_regions_human(const Support_query&, const Support_item& r, const std::string& source) {
  return region_statics_text(r, source) + region_twist_text(r) + "convention: " + kConvention + "\n";
}

// The float twin's values for the twist (hybrid: added to the exact answer).
void write_true(Json_writer& w, const Support_item& r) {
  if (!r.true_power) return;
  write_float_value(w.key("true_power"), *r.true_power);
  write_float_load(w.key("true_load"), *r.true_load);
}

void write_sliding_float(Json_writer& w, const Support_query& q, const Support_item& r) {
  const fl::Point2& cof = r.twin_center_of_friction;
  w.member("command", "sliding").member("name", r.scene.name).member("mode", "float");
  write_float_value(w.key("center_of_friction").array(), cof.x);
  write_float_value(w, cof.y);
  write_float_value(w.end_array().key("mu_f0"), r.twin_mu_f0);
  if (q.twist) {
    w.key("twist").rationals(*q.twist).member("sides", q.sides);
    write_float_value(w.key("lambda_squared"), r.twin_directions->lambda_sq);
    write_float_value(w.key("power").object().key("inner"), *r.twin_power_inner);
    write_float_value(w.key("outer"), *r.twin_power_outer);
    w.end_object();
    write_true(w, r);
  }
}

std::string sliding_float_human(const Support_query& q, const Support_item& r, const std::string& source) {
  const fl::Point2& cof = r.twin_center_of_friction;
  std::ostringstream s;
  s << scene_line(r.scene, source)
    << "centre of friction: (" << float_value_text(cof.x) << ", " << float_value_text(cof.y) << ")\n";
  if (q.twist)
    s << "twist " << vec_text(*q.twist) << ":\n"
      << "  true power h = " << float_value_text(*r.true_power) << "\n"
      << "  true load: " << float_load_text(*r.true_load) << "\n";
  s << "decided by: the float twin alone (values with certified bounds)\n";
  return s.str();
}


void write_sliding_unknown(Json_writer& w, const Support_query& q, const Support_item& r) {
  w.member("command", "sliding").member("name", r.scene.name).member("mode", mode_name(r.mode));
  w.member("convention", kConvention);
  write_unknown_distribution(w, r);
  if (q.twist) {
    w.key("twist").rationals(*q.twist);
    write_power_over(w, r);
  }
}

std::string sliding_unknown_human(const Support_query& q, const Support_item& r, const std::string& source) {
  std::ostringstream s;
  s << unknown_support_text(r, source);
  if (q.twist)
    s << "twist " << vec_text(*q.twist) << ": the frictional power over every admissible distribution lies in ["
      << number_text(r.power->lower) << ", " << number_text(r.power->upper) << "]\n"
      << "  least at f = " << distribution_text(r.power->min_distribution)
      << ", most at f = " << distribution_text(r.power->max_distribution) << "\n" << regions_power_text(r);
  s << "convention: " << kConvention << "\n";
  return s.str();
}

void write_sliding(Json_writer& w, const Support_query& q, const Support_item& r) {
  const Sliding_answer& a = r.sliding;
  const char* kinds[] = {"facet", "vertex", "smooth"};
  w.member("command", "sliding").member("name", r.scene.name).member("mode", mode_name(r.mode));
  w.member("convention", kConvention);
  write_centre(w, "center_of_friction", a.center_of_friction);
  write_centre(w, "friction_centroid", a.friction_centroid);
  w.member("mu_f0", a.mu_f0);
  if (!a.has_twist) return;
  write_twist_motion(w, a);
  w.key("true_surface").object().member("kind", kinds[static_cast<int>(a.cls.kind)]).member("text", a.cls.text);
  if (a.cls.support_point >= 0) {
    const Ls_point& p = r.model->support().points[static_cast<std::size_t>(a.cls.support_point)];
    write_pair(w.key("facet_disc").object().key("at"), p.at.x, p.at.y);
    w.member("radius", p.rho).end_object();
  }
  w.end_object().member("sides", q.sides).member("lambda_squared", r.model->directions().lambda_sq);
  w.key("power").object().member("inner", a.h_inner).member("outer", a.h_outer).member("lower", a.h_lo);
  w.member("upper", a.h_hi).end_object();
  w.key("load_box").object().key("lower").rationals(a.load_lo).key("upper").rationals(a.load_hi);
  w.member("of", a.cls.kind == Twist_kind::facet ? "the facet's centre" : "the load").end_object();
  write_face(w.key("inner_load"), a.inner_face);
  write_face(w.key("outer_load"), a.outer_face);
  write_true(w, r);
}

std::string sliding_human(const Support_query& q, const Support_item& r, const std::string& source) {
  const Sliding_answer& a = r.sliding;
  std::ostringstream s;
  s << scene_line(r.scene, source)
    << "centre of friction: " << vec_text(a.center_of_friction) << "\n"
    << "mu*f0 = " << number_text(a.mu_f0) << ", friction centroid " << vec_text(a.friction_centroid) << "\n";
  if (a.has_twist) {
    s << "twist " << vec_text(a.twist) << ": " << a.cls.text << "\n";
    if (a.translation) {
      if (a.load) s << "load: " << vec_text(*a.load) << " (exact)\n";
      else
        s << "load: (mu*f0/|v|) * " << vec_text(a.load_direction) << " with |v|^2 = " << number_text(a.speed_squared)
          << " (exact)\n";
    } else {
      s << "power h between " << number_text(a.h_inner) << " and " << number_text(a.h_outer) << " (polygonal, "
        << q.sides << " sides)\n";
    }
    s << "load box: " << vec_text(a.load_lo) << " .. " << vec_text(a.load_hi)
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
void answer_json(Json_writer& w, const Support_query& q, const Support_item& r) {
  by_kind(r, &write_sliding, &write_sliding_float, &write_sliding_unknown, &write_sliding_regions)(w, q, r);
}

std::string answer_text(const Support_query& q, const Support_item& r, const std::string& source) {
  return by_kind(r, &sliding_human, &sliding_float_human, &sliding_unknown_human, &sliding_regions_human)(
             q, r, source) +
         (q.twist || q.load ? std::string() : ask_support_text());
}

}  // namespace

Scene_answer prepare_sliding_json(const Options& o) { return per_scene(o, sliding_options, compute, answer_json); }

int run_sliding(const Options& o, const std::string& text, const std::string& source) {
  return run_per_scene(o, text, source, sliding_options, compute, answer_json, answer_text);
}

}  // namespace wrenchkit::cli
