// wrenchkit limit-surface: certified polygonal inner and outer limit surfaces of the scene's support,
// and queries on them (docs/limit-surface.md, theory.md §11–§12) [LS-1]–[LS-3].
#include <cmath>
#include <cstdio>
#include <optional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.h"
#include "cli/float_json.h"
#include "cli/render_limit_surface.h"
#include "exact/io/input_error.h"
#include "exact/io/json.h"
#include "exact/pipeline/support_answer.h"
#include "exact/sliding/limit_surface.h"
#include "exact/sliding/sliding.h"
#include "exact/io/streaming_scene_reader.h"
#include "exact/io/to_float.h"

namespace wrenchkit::cli {

namespace {

struct Ls_options {
  Mode mode = Mode::hybrid;
  bool polytopes = true;
  int sides = 32;
  std::optional<Rational> tolerance;
  int sets_built = 0;  // direction sets tried to meet the tolerance
  std::optional<Vec3q> twist, load;
  std::string off_file, obj_file, svg_file;
  bool list = false;
};

std::string jq(const Rational& q) { return json::quote(to_string(q)); }
std::string jv(const Vec3q& v) { return "[" + jq(v[0]) + ", " + jq(v[1]) + ", " + jq(v[2]) + "]"; }
std::string jz(const Vec3z& v) {
  return "[" + json::quote(v[0].get_str()) + ", " + json::quote(v[1].get_str()) + ", " + json::quote(v[2].get_str()) + "]";
}
std::string tv(const Vec3q& v) { return "(" + to_string(v[0]) + ", " + to_string(v[1]) + ", " + to_string(v[2]) + ")"; }
std::string tz(const Vec3z& v) { return "(" + v[0].get_str() + ", " + v[1].get_str() + ", " + v[2].get_str() + ")"; }

std::string face_json(const Ls_face& f) {
  std::string s = "{\"dimension\": " + std::to_string(f.dimension) + ", \"vertices\": [";
  for (std::size_t i = 0; i < f.vertices.size(); ++i) s += (i ? ", " : "") + jv(f.vertices[i]);
  return s + "]}";
}

std::string polytope_json(const Ls_polytope& P, bool list) {
  std::size_t rot = 0;
  for (const Ls_facet& f : P.facets) rot += f.support_point >= 0;
  std::string s = "{\"dimension\": " + std::to_string(P.dimension) + ", \"facets\": " + std::to_string(P.facets.size()) +
                  ", \"vertices\": " + std::to_string(P.vertices.size()) + ", \"edges\": " + std::to_string(P.edges) +
                  ", \"rotation_facets\": " + std::to_string(rot);
  if (list) {
    s += ", \"facet_list\": [";
    for (std::size_t i = 0; i < P.facets.size(); ++i) {
      const Ls_facet& f = P.facets[i];
      s += (i ? ", " : "") + std::string("{\"normal\": ") + jz(f.normal) + ", \"b\": " + jq(f.b) + ", \"vertices\": [";
      for (std::size_t j = 0; j < f.vertices.size(); ++j) s += (j ? ", " : "") + std::to_string(f.vertices[j]);
      s += "]";
      if (f.support_point >= 0) s += ", \"rotation_about_support_point\": " + std::to_string(f.support_point);
      s += "}";
    }
    s += "], \"vertex_list\": [";
    for (std::size_t i = 0; i < P.vertices.size(); ++i) s += (i ? ", " : "") + jv(P.vertices[i]);
    s += "]";
  }
  return s + "}";
}

std::string off_text(const Ls_polytope& in, const Ls_polytope& out) {
  std::ostringstream s;
  s.precision(17);
  s << "OFF\n# wrenchkit limit-surface: inner (blue) and outer (red) polygonal limit surfaces, coordinates\n"
    << "# (fx, fy, m) of loads (theory.md §1.5) as doubles; exact values: wrenchkit limit-surface --list\n";
  std::size_t faces = 0;
  for (const Ls_polytope* P : {&in, &out}) faces += P->facets.size();
  s << in.vertices.size() + out.vertices.size() << " " << faces << " " << in.edges + out.edges << "\n";
  for (const Ls_polytope* P : {&in, &out})
    for (const Vec3q& v : P->vertices) s << v[0].get_d() << " " << v[1].get_d() << " " << v[2].get_d() << "\n";
  for (int k = 0; k < 2; ++k) {
    const Ls_polytope& P = k == 0 ? in : out;
    const std::size_t base = k == 0 ? 0 : in.vertices.size();
    for (const Ls_facet& f : P.facets) {
      s << f.vertices.size();
      for (int v : f.vertices) s << " " << base + static_cast<std::size_t>(v);
      s << (k == 0 ? " 0.2 0.4 0.9 1.0\n" : " 0.9 0.2 0.2 0.35\n");
    }
  }
  return s.str();
}

std::string obj_text(const Ls_polytope& in, const Ls_polytope& out) {
  std::ostringstream s;
  s.precision(17);
  s << "# wrenchkit limit-surface: inner and outer polygonal limit surfaces; vertices (fx, fy, m) of loads\n"
    << "# (theory.md §1.5) as doubles; exact values: wrenchkit limit-surface --list\n";
  std::size_t base = 1;
  for (int k = 0; k < 2; ++k) {
    const Ls_polytope& P = k == 0 ? in : out;
    s << "o " << (k == 0 ? "inner" : "outer") << "\n";
    for (const Vec3q& v : P.vertices) s << "v " << v[0].get_d() << " " << v[1].get_d() << " " << v[2].get_d() << "\n";
    for (const Ls_facet& f : P.facets) {
      s << "f";
      for (int v : f.vertices) s << " " << base + static_cast<std::size_t>(v);
      s << "\n";
    }
    base += P.vertices.size();
  }
  return s.str();
}

std::string gauge_text(const std::optional<Rational>& g) { return g ? human_number(*g) : std::string("infinite"); }
std::string gauge_json(const std::optional<Rational>& g) { return g ? jq(*g) : std::string("null"); }

// The options, combined once (before any scene): --sides or --tolerance (resolved to N here), --twist,
// --load, the exports and --list (each already validated where it was parsed).
Ls_options limit_surface_options(const Options& o) {
  Ls_options lo;
  if (o.sides) lo.sides = *o.sides;
  if (o.tolerance) {
    if (o.sides) throw Usage_error("--sides and --tolerance exclude each other");
    lo.tolerance = o.tolerance;
    lo.sides = smallest_sides(*lo.tolerance, kMaxSides, &lo.sets_built);
    if (lo.sides == 0)
      throw Usage_error("--tolerance: " + o.tolerance_text + " needs more than " + std::to_string(kMaxSides) +
                        " sides (the largest certified ratio available is reached at --sides " +
                        std::to_string(kMaxSides) + ")");
  }
  lo.twist = o.twist;
  lo.load = o.load;
  lo.off_file = o.off_file;
  lo.obj_file = o.obj_file;
  lo.svg_file = o.svg_file;
  lo.list = o.list;
  lo.mode = o.mode;
  // The polytopes are built when asked for (--sides, --tolerance, --list, the exports) or when nothing else is
  // asked; a --load or --twist query alone is answered on the true surface, building them only if needed.
  lo.polytopes = o.sides || o.tolerance || lo.list || !lo.off_file.empty() || !lo.obj_file.empty() ||
                 !lo.svg_file.empty() || (!lo.load && !lo.twist);
  if (lo.mode == Mode::float_only && (lo.list || !lo.off_file.empty() || !lo.obj_file.empty() || !lo.svg_file.empty()))
    throw Usage_error("--list, --off, --obj and --svg show the exact polytopes: not with --mode float");
  return lo;
}

std::string bounded_json(const fl::Bounded& b) { return float_value_json(b); }
std::string bounded_text(const fl::Bounded& b) { return float_value_text(b); }

// The true surface's fields (hybrid and float): ', "true_power": …, "true_load": …'.
std::string true_json(const Support_item& r) {
  if (!r.true_power) return "";
  return ", \"true_power\": " + bounded_json(*r.true_power) + ", \"true_load\": " + float_load_json(*r.true_load);
}

// ', "certificate_checked": true, "certificate": {…}' when the motion has a certificate (the independent checker
// accepted it); ', "uncertified": "…"' when a verdict found no rational witness and is reported undecided.
std::string certificate_fields(const Support_item& r) {
  if (!r.certificate.empty()) return ", \"certificate_checked\": true, \"certificate\": " + r.certificate;
  if (!r.uncertified.empty()) return ", \"uncertified\": " + json::quote(r.uncertified);
  return "";
}

std::string certificate_line(const Support_item& r) {
  if (!r.certificate.empty()) return "  certificate accepted by the independent checker (exact arithmetic)\n";
  if (!r.uncertified.empty()) return "  " + r.uncertified + "\n";
  return "";
}

std::string motion_fields(const Support_item& r) {
  std::string s = std::string(", \"motion_decided_by\": \"") + r.motion.decided_by + "\"";
  if (r.motion.cells) s += ", \"search_twists\": " + std::to_string(r.motion.cells);
  if (std::string(r.motion.decided_by) == "float" && r.motion.motion == Motion::slides)
    s += ", \"witness_twist\": [" + float_number(r.motion.witness[0]) + ", " + float_number(r.motion.witness[1]) + ", " +
         float_number(r.motion.witness[2]) + "]";
  return s;
}

// The scene's answer through the pipeline; a failure unwinds as the CLI's Failure.
Support_item compute_limit_surface(const Ls_options& lo, const Options& o, const std::string& text,
                                   const std::string& source) {
  Support_query q;
  q.sides = lo.sides;
  q.twist = lo.twist;
  q.load = lo.load;
  q.polytopes = lo.polytopes;
  return answered(answer_support(text, source, request_of(o), q));
}

const char* kConvention =
    "loads: the wrench the slider applies to the support, parallel to the sliding velocity (theory.md 1.5); "
    "the friction wrench on the slider is its negative";

std::string ratio_text(const Directions& d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", 1 / std::sqrt(d.lambda_sq.get_d()) - 1);
  return buf;
}

std::string limit_surface_json(const Ls_options& lo, const Support_item& r) {
  const Polygonal_ls& model = *r.model;
  const Directions& d = model.directions();
  const Ls_support& sup = model.support();
  const Sliding_answer& sa = r.sliding;
  std::ostringstream s;
  s << "{\"command\": \"limit-surface\", \"name\": " << json::quote(r.scene.name) << ", \"mode\": \""
    << mode_name(lo.mode) << "\", \"convention\": " << json::quote(kConvention) << ", \"sides\": " << lo.sides;
  if (lo.tolerance) s << ", \"tolerance\": " << jq(*lo.tolerance) << ", \"direction_sets_tried\": " << lo.sets_built;
  s << ", \"lambda_squared\": " << jq(d.lambda_sq) << ", \"relative_error_bound_approx\": " << ratio_text(d)
    << ", \"support\": {\"input_points\": " << r.scene.support->points.size() << ", \"points\": " << sup.points.size()
    << ", \"collinear\": " << (sup.collinear ? "true" : "false") << ", \"mu_f0\": " << jq(sa.mu_f0)
    << ", \"center_of_friction\": [" << jq(sa.center_of_friction.x) << ", " << jq(sa.center_of_friction.y)
    << "]}, \"dimension\": " << model.dimension();
  if (r.polytopes_built)
    s << ", \"inner\": " << polytope_json(r.in, lo.list) << ", \"outer\": " << polytope_json(r.out, lo.list);
  else
    s << ", \"polytopes\": false";  // a query alone: answered without them (--sides or --list builds them)
  if (lo.twist) {
    s << ", \"twist\": " << jv(*lo.twist) << ", \"load_for_twist\": {\"inner\": " << face_json(sa.inner_face)
      << ", \"outer\": " << face_json(sa.outer_face) << ", \"power\": {\"inner\": " << jq(sa.h_inner)
      << ", \"outer\": " << jq(sa.h_outer) << "}, \"true_surface\": {\"kind\": \""
      << (sa.cls.kind == Twist_kind::facet ? "facet" : (sa.cls.kind == Twist_kind::vertex ? "vertex" : "smooth"))
      << "\", \"text\": " << json::quote(sa.cls.text) << "}" << true_json(r) << "}";
  }
  if (lo.load) {
    auto cone_json = [&](const Polygonal_ls::Normal_cone& c) {
      std::string t = "{\"generators\": [";
      for (std::size_t i = 0; i < c.generators.size(); ++i) t += (i ? ", " : "") + jz(c.generators[i]);
      t += "], \"lineality\": [";
      for (std::size_t i = 0; i < c.lineality.size(); ++i) t += (i ? ", " : "") + jz(c.lineality[i]);
      return t + "]}";
    };
    s << ", \"load\": " << jv(*lo.load) << ", \"motion\": \"" << motion_name(r.motion.motion) << "\"" << motion_fields(r);
    if (r.polytopes_built)
      s << ", \"gauge\": {\"outer\": " << gauge_json(r.gauge_out) << ", \"inner\": " << gauge_json(r.gauge_in) << "}";
    s << certificate_fields(r);
    if (r.polytopes_built && r.motion.motion != Motion::sticks)
      s << ", \"twist_cone\": {\"outer\": " << cone_json(r.cone_out) << ", \"inner\": " << cone_json(r.cone_in) << "}";
  }
  s << "}";
  return s.str();
}

std::string limit_surface_human(const Ls_options& lo, const Support_item& r, const std::string& source) {
  const Polygonal_ls& model = *r.model;
  const Directions& d = model.directions();
  const Ls_support& sup = model.support();
  const Sliding_answer& sa = r.sliding;
  std::ostringstream s;
  s << "scene: " << (r.scene.name.empty() ? source : r.scene.name) << "\n"
    << "support: " << sup.points.size() << " distinct point(s) with mu*f > 0 (of " << r.scene.support->points.size()
    << " given)" << (sup.collinear ? ", collinear" : "") << ", mu*f0 = " << to_string(sa.mu_f0)
    << ", centre of friction (" << to_string(sa.center_of_friction.x) << ", " << to_string(sa.center_of_friction.y)
    << ")\n"
    << "sides: " << lo.sides;
  if (lo.tolerance) s << " (the smallest meeting --tolerance " << to_string(*lo.tolerance) << ")";
  s << "\ncertificate: lambda^2 = " << to_string(d.lambda_sq) << "  (lambda*LS <= LS_in <= LS <= LS_out <= LS/lambda;"
    << " relative error 1/lambda - 1 ~ " << ratio_text(d) << ")\n";
  if (model.dimension() == 2)
    s << "note: one support point: the limit surface is a flat disc in the plane of its rotation twist (dimension 2);"
         " 'facets' are its two sides\n";
  if (model.dimension() == 0) s << "note: no point has mu*f > 0: the limit surface is the single point 0\n";
  if (r.polytopes_built)
    for (const auto& [name, P] : {std::pair<const char*, const Ls_polytope*>{"inner", &r.in}, {"outer", &r.out}})
      s << name << ": " << P->facets.size() << " facets, " << P->vertices.size() << " vertices, " << P->edges
        << " edges\n";
  else
    s << "polytopes: not built (the query is answered on the true surface; --sides or --list builds them)\n";
  s << "convention: " << kConvention << "\n";
  if (lo.twist) {
    s << "twist " << tv(*lo.twist) << ": " << sa.cls.text << "\n";
    for (const auto& [name, f] : {std::pair<const char*, const Ls_face*>{"inner", &sa.inner_face}, {"outer", &sa.outer_face}}) {
      s << "  load on LS_" << name << ": ";
      if (f->dimension == 0) s << "the point " << tv(f->vertices[0]) << "\n";
      else {
        s << (f->dimension == 1 ? "the segment" : "the facet with vertices");
        for (const Vec3q& v : f->vertices) s << " " << tv(v);
        s << "\n";
      }
    }
    s << "  power: " << to_string(sa.h_inner) << " <= h <= " << to_string(sa.h_outer) << "\n";
    if (r.true_power) s << "  true power (float twin, certified): " << bounded_text(*r.true_power) << "\n";
  }
  if (lo.load) {
    s << "load " << tv(*lo.load) << ": " << motion_name(r.motion.motion) << "  (";
    if (r.polytopes_built)
      s << "gauge between " << gauge_text(r.gauge_out) << " and " << gauge_text(r.gauge_in)
        << "; sticks if < 1, slides if >= 1; ";
    s << "decided by "
      << (std::string(r.motion.decided_by) == "float" ? "the float twin's certified search on the true surface"
                                                       : std::string(r.motion.decided_by) == "polygons" ? "the polygons"
                                                                                                         : "nothing")
      << ")\n";
    if (r.motion.motion == Motion::undecided) s << "  undecided: refine with more --sides or a smaller --tolerance\n";
    s << certificate_line(r);
    if (r.polytopes_built && r.motion.motion != Motion::sticks) {
      s << "  twists (outward normals of LS_out at the load's direction):";
      for (const Vec3z& g : r.cone_out.generators) s << " " << tz(g);
      for (const Vec3z& g : r.cone_out.lineality) s << " +-" << tz(g);
      s << "\n";
    }
  }
  return s.str();
}

// --mode float: the twin alone (no exact polytopes). Its direction set is the exact engine's (the same
// integer parameters, core/limit_surface_directions.h), so its λ² and polygonal powers bracket the exact ones.
std::string limit_surface_float_json(const Ls_options& lo, const Support_item& r) {
  const fl::Directions_twin& d = *r.twin_directions;
  const fl::Point2& cof = r.twin_center_of_friction;
  const fl::Bounded& mu_f0 = r.twin_mu_f0;
  std::ostringstream s;
  s << "{\"command\": \"limit-surface\", \"name\": " << json::quote(r.scene.name) << ", \"mode\": \"float\""
    << ", \"convention\": " << json::quote(kConvention) << ", \"sides\": " << lo.sides;
  if (lo.tolerance) s << ", \"tolerance\": " << jq(*lo.tolerance);
  s << ", \"lambda_squared\": " << bounded_json(d.lambda_sq) << ", \"support\": {\"input_points\": "
    << r.scene.support->points.size() << ", \"points\": " << r.twin.size() << ", \"mu_f0\": " << bounded_json(mu_f0)
    << ", \"center_of_friction\": [" << bounded_json(cof.x) << ", " << bounded_json(cof.y) << "]}";
  if (lo.twist)
    s << ", \"twist\": " << jv(*lo.twist) << ", \"load_for_twist\": {\"power\": {\"inner\": "
      << bounded_json(*r.twin_power_inner) << ", \"outer\": " << bounded_json(*r.twin_power_outer) << "}"
      << true_json(r) << "}";
  if (lo.load)
    s << ", \"load\": " << jv(*lo.load) << ", \"motion\": \"" << motion_name(r.motion.motion) << "\"" << motion_fields(r)
      << certificate_fields(r);
  s << "}";
  return s.str();
}

std::string limit_surface_float_human(const Ls_options& lo, const Support_item& r, const std::string& source) {
  const fl::Directions_twin& d = *r.twin_directions;
  const fl::Point2& cof = r.twin_center_of_friction;
  std::ostringstream s;
  s << "scene: " << (r.scene.name.empty() ? source : r.scene.name) << "\n"
    << "support: " << r.twin.size() << " point(s) with mu*f > 0 (of " << r.scene.support->points.size()
    << " given), centre of friction (" << bounded_text(cof.x) << ", " << bounded_text(cof.y) << ")\n"
    << "sides: " << lo.sides << ", lambda^2 = " << bounded_text(d.lambda_sq) << " (the float twin's direction set)\n"
    << "convention: " << kConvention << "\n";
  if (lo.twist) {
    s << "twist " << tv(*lo.twist) << ":\n"
      << "  polygonal power: " << bounded_text(*r.twin_power_inner) << " <= h <= " << bounded_text(*r.twin_power_outer)
      << "\n";
    if (r.true_power) s << "  true power: " << bounded_text(*r.true_power) << "\n";
    if (r.true_load) s << "  true load: " << float_load_text(*r.true_load) << "\n";
  }
  if (lo.load) {
    s << "load " << tv(*lo.load) << ": " << motion_name(r.motion.motion)
      << " (the float twin's certified search on the true surface, " << r.motion.cells << " twists)\n";
    if (r.motion.motion == Motion::slides)
      s << "  a twist with h(q) <= q.p: (" << float_number(r.motion.witness[0]) << ", " << float_number(r.motion.witness[1])
        << ", " << float_number(r.motion.witness[2]) << ")\n";
    s << certificate_line(r);
  }
  s << "decided by: the float twin alone (every sign certified; values with certified bounds)\n";
  return s.str();
}

// An unknown distribution (docs/theory-sliding.md §2): the admissible set, the power over it for --twist,
// and for --load whether it sticks for every distribution, slides for every one, or depends, with witnesses.
std::string limit_surface_unknown_json(const Ls_options& lo, const Support_item& r) {
  std::ostringstream s;
  s << "{\"command\": \"limit-surface\", \"name\": " << json::quote(r.scene.name) << ", \"mode\": \""
    << mode_name(r.mode) << "\", \"convention\": " << json::quote(kConvention) << ", \"sides\": " << lo.sides
    << unknown_distribution_fields(r);
  if (lo.twist) s << ", \"twist\": " << jv(*lo.twist) << power_over_fields(r);
  if (lo.load) {
    const Motion_over_f& m = *r.motion_over;
    s << ", \"load\": " << jv(*lo.load) << ", \"motion\": \"" << motion_over_name(m.motion)
      << "\", \"motion_decided_by\": \"" << m.decided_by << "\", \"per_extreme_distribution\": [";
    for (std::size_t i = 0; i < m.per_vertex.size(); ++i) s << (i ? ", " : "") << "\"" << motion_name(m.per_vertex[i]) << "\"";
    s << "]";
    if (m.motion == Motion_over::depends) {
      s << ", \"witnesses\": {\"sticks\": ";
      if (m.sticking) {
        s << "{\"distribution\": " << distribution_json(m.sticking->distribution) << ", \"support_forces\": [";
        for (std::size_t i = 0; i < m.sticking->forces.size(); ++i)
          s << (i ? ", " : "") << "[" << jq(m.sticking->forces[i].x) << ", " << jq(m.sticking->forces[i].y) << "]";
        s << "]}";
      } else {
        s << "{\"distribution\": " << distribution_json(r.vertices[*m.sticking_vertex]) << "}";
      }
      s << ", \"slides\": {\"distribution\": " << distribution_json(r.vertices[*m.sliding_vertex]) << "}}";
    }
    if (m.separating_twist) s << ", \"separating_twist\": " << jv(*m.separating_twist);
    s << certificate_fields(r);
  }
  s << "}";
  return s.str();
}

std::string limit_surface_unknown_human(const Ls_options& lo, const Support_item& r, const std::string& source) {
  const Admissible& a = *r.admissible;
  const auto dist = [](const std::vector<Rational>& f) {
    std::string s = "(";
    for (std::size_t i = 0; i < f.size(); ++i) s += (i ? ", " : "") + human_number(f[i]);
    return s + ")";
  };
  std::ostringstream s;
  s << scene_line(r.scene.name, source) << "support: " << r.scene.support->points.size() << " points, the forces of "
    << a.unknown.size() << " not given; weight " << human_number(*r.scene.support->weight) << ", centre of pressure ("
    << human_number(r.pressure_center.x) << ", " << human_number(r.pressure_center.y) << "); "
    << r.vertices.size() << " extreme admissible distributions\n";
  if (lo.twist)
    s << "twist " << tv(*lo.twist) << ": the frictional power over every admissible distribution lies in ["
      << human_number(r.power->lower) << ", " << human_number(r.power->upper) << "]\n";
  if (lo.load) {
    const Motion_over_f& m = *r.motion_over;
    s << "load " << tv(*lo.load) << ": ";
    switch (m.motion) {
      case Motion_over::sticks: s << "sticks for every admissible distribution (every extreme one sticks)\n"; break;
      case Motion_over::slides:
        s << "slides for every admissible distribution (the twist " << tv(*m.separating_twist)
          << " drives it past every one's limit surface)\n";
        break;
      case Motion_over::depends:
        s << "depends on the distribution: it sticks with f = "
          << dist(m.sticking ? m.sticking->distribution : r.vertices[*m.sticking_vertex]) << " and slides with f = "
          << dist(r.vertices[*m.sliding_vertex]) << "\n";
        break;
      case Motion_over::undecided:
        s << "undecided (within the resolution of the limit surfaces; refine --sides)\n";
        break;
    }
    s << certificate_line(r);
  }
  s << "convention: " << kConvention << "\n";
  return s.str();
}

// The answer as JSON and as text, by what the pipeline answered (an unknown distribution, the twin alone, or
// the exact answer).
std::string answer_json(const Ls_options& lo, const Support_item& r) {
  if (r.admissible) return limit_surface_unknown_json(lo, r);
  return lo.mode == Mode::float_only ? limit_surface_float_json(lo, r) : limit_surface_json(lo, r);
}

std::string answer_text(const Ls_options& lo, const Support_item& r, const std::string& source) {
  if (r.admissible) return limit_surface_unknown_human(lo, r, source);
  return lo.mode == Mode::float_only ? limit_surface_float_human(lo, r, source) : limit_surface_human(lo, r, source);
}

}  // namespace

Scene_answer prepare_limit_surface_json(const Options& o) {
  return per_scene(o, limit_surface_options, compute_limit_surface, answer_json);
}

int run_limit_surface(const Options& o, const std::string& text, const std::string& source) {
  const Ls_options lo = limit_surface_options(o);
  const Support_item r = compute_limit_surface(lo, o, text, source);
  if (r.admissible && (lo.list || !lo.off_file.empty() || !lo.obj_file.empty() || !lo.svg_file.empty()))
    throw Input_error(source + ": support: the forces of some points are not given, so there is no one limit surface "
                      "to list or draw (--list, --off, --obj, --svg need every force)");
  if (!o.certificate_file.empty()) {
    if (r.certificate.empty())
      throw Failure(Status::undecided, cli_message(Status::undecided, "the load's motion is undecided: no certificate to "
                                                                      "write"));
    write_file(o.certificate_file, r.certificate + "\n");
  }
  if (!lo.off_file.empty()) write_file(lo.off_file, off_text(r.in, r.out));
  if (!lo.obj_file.empty()) write_file(lo.obj_file, obj_text(r.in, r.out));
  if (!lo.svg_file.empty()) write_file(lo.svg_file, render_limit_surface_svg(r.scene, lo.sides));
  return write_answer(o, [&] { return answer_json(lo, r); }, [&] { return answer_text(lo, r, source); });
}

}  // namespace wrenchkit::cli
