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
#include "exact/cgal/mesh_io.h"
#include "exact/io/input_error.h"
#include "exact/io/json_writer.h"
#include "exact/numbers/vectors.h"
#include "exact/pipeline/support_answer.h"
#include "exact/sliding/limit_surface.h"
#include "exact/sliding/sliding.h"
#include "exact/io/streaming_scene_reader.h"
#include "exact/io/to_float.h"

namespace wrenchkit::cli {

namespace {

// The options, combined once (before any scene): the pipeline's query (--sides, or --tolerance resolved to N or a
// region's power width; --twist, --load; whether the polytopes are built or were asked for by name), and what only
// the command does with the answer (--list, the mesh and picture files).
struct Ls_options {
  Support_query query;
  Mode mode = Mode::hybrid;
  int sets_built = 0;  // direction sets tried to meet the tolerance
  std::string off_file, obj_file, ply_file, svg_file;
  bool exact_coordinates = false;  // --exact-coordinates: OFF exactly (exact/cgal/mesh_io.h)
  bool list = false;
  // The mesh files asked for, in option order: --off, --obj, --ply.
  std::vector<std::pair<Mesh_format, std::string>> meshes() const {
    std::vector<std::pair<Mesh_format, std::string>> m;
    if (!off_file.empty()) m.push_back({Mesh_format::off, off_file});
    if (!obj_file.empty()) m.push_back({Mesh_format::obj, obj_file});
    if (!ply_file.empty()) m.push_back({Mesh_format::ply, ply_file});
    return m;
  }
  bool exports() const { return !meshes().empty() || !svg_file.empty(); }
};

std::string tz(const Vec3z& v) { return "(" + v[0].get_str() + ", " + v[1].get_str() + ", " + v[2].get_str() + ")"; }

void write_face(Json_writer& w, const Ls_face& f) {
  w.object().member("dimension", f.dimension).key("vertices").array();
  for (const Vec3q& v : f.vertices) w.rationals(v);
  w.end_array().end_object();
}

void write_polytope(Json_writer& w, const Ls_polytope& P, bool list) {
  std::size_t rot = 0;
  for (const Ls_facet& f : P.facets) rot += f.support_point >= 0;
  w.object().member("dimension", P.dimension).member("facets", P.facets.size()).member("vertices", P.vertices.size());
  w.member("edges", P.edges).member("rotation_facets", rot);
  if (list) {
    w.key("facet_list").array();
    for (const Ls_facet& f : P.facets) {
      w.object().key("normal").rationals(f.normal);
      w.member("b", f.b).key("vertices").array();
      for (const int v : f.vertices) w.integer(v);
      w.end_array();
      if (f.support_point >= 0) w.member("rotation_about_support_point", f.support_point);
      w.end_object();
    }
    w.end_array().key("vertex_list").array();
    for (const Vec3q& v : P.vertices) w.rationals(v);
    w.end_array();
  }
  w.end_object();
}

std::string gauge_text(const std::optional<Rational>& g) { return g ? number_text(*g) : std::string("infinite"); }
void write_gauge(Json_writer& w, const std::optional<Rational>& g) { g ? w.rational(*g) : w.null(); }

// The options, combined once (before any scene): --sides or --tolerance (resolved to N here), --twist,
// --load, the exports and --list (each already validated where it was parsed).
Ls_options limit_surface_options(const Options& o) {
  Ls_options lo;
  Support_query& q = lo.query;
  if (o.sides) q.sides = *o.sides;
  q.tolerance = o.tolerance;  // for a support with regions: the power's relative width
  if (o.tolerance) {
    if (o.sides) throw Usage_error("--sides and --tolerance exclude each other");
    q.sides = smallest_sides(*o.tolerance, kMaxSides, &lo.sets_built);
    if (q.sides == 0)
      throw Usage_error("--tolerance: " + o.tolerance_text + " needs more than " + std::to_string(kMaxSides) +
                        " sides (the largest certified ratio available is reached at --sides " +
                        std::to_string(kMaxSides) + ")");
  }
  q.twist = o.twist;
  q.load = o.load;
  lo.off_file = o.off_file;
  lo.obj_file = o.obj_file;
  lo.ply_file = o.ply_file;
  lo.svg_file = o.svg_file;
  lo.exact_coordinates = o.exact_coordinates;
  lo.list = o.list;
  lo.mode = o.mode;
  if (lo.exact_coordinates && lo.meshes().empty())
    throw Usage_error("--exact-coordinates is about mesh files: give --off, --obj or --ply");
  // The polytopes are built when asked for (--sides, --tolerance, --list, the exports) or when nothing else is
  // asked; a --load or --twist query alone is answered on the true surface, building them only if needed.
  q.polytopes = o.sides || o.tolerance || lo.list || lo.exports() || (!q.load && !q.twist);
  q.polytopes_asked = o.sides || lo.list || !lo.meshes().empty();  // by name (refused for regions); --svg draws them too
  if (lo.mode == Mode::float_only && (lo.list || lo.exports()))
    throw Usage_error("--list, --off, --obj, --ply and --svg show the exact polytopes: not with --mode float");
  return lo;
}

std::string bounded_text(const fl::Bounded& b) { return float_value_text(b); }

// The true surface's members (hybrid and float): "true_power", "true_load".
void write_true(Json_writer& w, const Support_item& r) {
  if (!r.true_power) return;
  write_float_value(w.key("true_power"), *r.true_power);
  write_float_load(w.key("true_load"), *r.true_load);
}

// "certificate_checked": true, "certificate": {…} when the motion has a certificate (the independent checker
// accepted it); "uncertified": "…" when a verdict found no rational witness and is reported undecided.
void write_certificate_members(Json_writer& w, const Support_item& r) {
  if (!r.certificate.empty()) w.member("certificate_checked", true).key("certificate").raw(r.certificate);
  else if (!r.motion->uncertified.empty()) w.member("uncertified", r.motion->uncertified);
}

std::string certificate_line(const Support_item& r) {
  if (!r.certificate.empty()) return "  certificate accepted by the independent checker (exact arithmetic)\n";
  if (!r.motion->uncertified.empty()) return "  " + r.motion->uncertified + "\n";
  return "";
}

// The twist a load on the surface may slip with: the one distribution's, or (over F) the one for every distribution.
const Vec3q* impending_twist(const Motion_answer& m) {
  if (m.motion != Motion::impending) return nullptr;
  return m.impending ? &m.impending->twist.twist : &m.sliding->twist;
}

std::string slip_text(const Vec3q& q) { return "the twist " + twist_text(q) + ", " + motion_text(q); }

// The load's motion, whatever the support (exact/sliding/motion.h): "load", "motion", "motion_decided_by", and how it
// was decided — every force given: the float search's twists and its sliding twist (points), the certificate's cells,
// the gauge's estimate and the sliding twist (regions); some force not given: each extreme distribution's verdict,
// the witnesses' distributions, the separating twist, why undecided (and the regions' cells).
void write_motion(Json_writer& w, const Support_item& r, const Vec3q& load) {
  const Motion_answer& m = *r.motion;
  w.key("load").rationals(load);
  write_approx(w, "load", {load[0], load[1], load[2]});
  w.member("motion", motion_name(m.motion));
  w.member("motion_decided_by", decided_by_name(m.decided_by));
  if (const Vec3q* slip = impending_twist(m))  // on the surface: the slip it admits (every kind of support)
    w.key("impending_twist").rationals(primitive_vec(*slip)).member("impending_motion", motion_words(*slip));
  if (r.kind == Support_kind::unknown) {
    w.key("per_extreme_distribution").array();
    for (const Motion v : m.per_vertex) w.string(motion_name(v));
    w.end_array();
    if (m.motion == Motion::depends) {  // the forces too when the sticking distribution was found over F
      w.key("witnesses").object().key("sticks").object().member("motion", motion_name(m.held_as));
      w.key("distribution").rationals(m.sticking->distribution);
      if (m.decided_by != Decided_by::vertices) {
        w.key("support_forces").array();
        for (const Vec2& f : m.sticking->forces) w.array().rational(f.x).rational(f.y).end_array();
        w.end_array();
      }
      w.end_object().key("slides").object().member("motion", motion_name(m.moved_as));
      w.key("distribution").rationals(m.sliding->distribution);
      w.end_object().end_object();
    }
    if (m.motion == Motion::slides) w.key("separating_twist").rationals(primitive_vec(m.sliding->twist));
    if (!m.undecided_why.empty()) w.member("undecided_why", m.undecided_why);
    if (r.regions) w.member("certificate_cells", m.cells);  // [RG-3] the regions' blocks
  } else if (r.kind == Support_kind::regions) {
    w.member("certificate_cells", m.cells);
    w.key("gauge_estimate").raw(std::isfinite(m.gauge_estimate) ? float_number(m.gauge_estimate) : "null");
    if (m.motion == Motion::slides) w.key("slide_twist").rationals(primitive_vec(m.sliding->twist));
    if (!m.undecided_why.empty()) w.member("undecided_why", m.undecided_why);
  } else {
    if (m.search_twists) w.member("search_twists", m.search_twists);
    if (m.decided_by == Decided_by::float_search && m.motion == Motion::slides) {
      w.key("witness_twist").array();
      for (const double x : m.search_twist) w.raw(float_number(x));
      w.end_array();
    }
  }
}

// The same as text: the verdict's line(s) and the certificate's.
std::string load_motion_text(const Support_item& r, const Vec3q& load) {
  const Motion_answer& m = *r.motion;
  std::ostringstream s;
  s << "load " << vec_text(load) << ": ";
  const Vec3q* slip = impending_twist(m);
  if (r.kind == Support_kind::unknown) {
    switch (m.motion) {
      case Motion::sticks: s << "sticks for every admissible distribution (every extreme one sticks)\n"; break;
      case Motion::impending:
        s << "impending for every admissible distribution: on every one's limit surface (every extreme one can just "
             "hold it, and "
          << slip_text(*slip) << " meets every one's friction power)\n";
        break;
      case Motion::slides:
        s << "slides for every admissible distribution (the twist " << twist_text(m.sliding->twist)
          << " drives it past every one's limit surface)\n";
        break;
      case Motion::depends:
        s << "depends on the distribution: it " << (m.held_as == Motion::sticks ? "sticks" : "is on the limit surface")
          << " with f = " << distribution_text(m.sticking->distribution) << " and "
          << (m.moved_as == Motion::slides ? "slides" : "is on the limit surface") << " with f = "
          << distribution_text(m.sliding->distribution) << "\n";
        break;
      case Motion::undecided: s << "undecided: " << m.undecided_why << "\n"; break;
    }
  } else if (r.kind == Support_kind::regions) {
    s << motion_name(m.motion);
    if (m.motion == Motion::sticks)
      s << " (forces on " << m.cells << " cells of the regions, each strictly inside its friction disc)\n";
    else if (m.motion == Motion::impending)
      s << " (on the limit surface: forces on " << m.cells << " cells in their closed friction discs, and "
        << slip_text(*slip) << " meets the regions' friction power exactly)\n";
    else if (m.motion == Motion::slides)
      s << " (the twist " << twist_text(m.sliding->twist) << " with speed bounds at the vertices of " << m.cells
        << " cells: its power bound is below q.p)\n";
    else
      s << ": " << m.undecided_why << "\n";
  } else if (r.kind == Support_kind::points_twin) {
    s << motion_name(m.motion) << " (the float twin's certified search on the true surface, " << m.search_twists
      << " twists)\n";
    if (m.motion == Motion::slides)
      s << "  a twist with h(q) < q.p: (" << float_number(m.search_twist[0]) << ", " << float_number(m.search_twist[1])
        << ", " << float_number(m.search_twist[2]) << ")\n";
    if (slip)
      s << "  on the limit surface: friction can just hold it, and it may slip with " << slip_text(*slip)
        << " (its power meets the friction's exactly)\n";
  } else {
    s << motion_name(m.motion) << "  (";
    if (r.polytopes_built)
      s << "gauge between " << gauge_text(r.gauge_out) << " and " << gauge_text(r.gauge_in)
        << "; sticks if < 1, slides if > 1, on the surface if 1; ";
    s << "decided by " << decided_by_words(m.decided_by) << ")\n";
    if (slip)
      s << "  on the limit surface: friction can just hold it, and it may slip with " << slip_text(*slip)
        << " (its power meets the friction's exactly)\n";
    if (m.motion == Motion::undecided) s << "  undecided: " << m.undecided_why << "\n";
  }
  return s.str() + certificate_line(r);
}

// The scene's answer through the pipeline; a failure unwinds as the CLI's Failure.
Support_item compute_limit_surface(const Ls_options& lo, const Options& o, const std::string& text,
                                   const std::string& source) {
  return answered(answer_support(text, source, request_of(o), lo.query));
}

const char* kConvention =
    "loads: the wrench the slider applies to the support, parallel to the sliding velocity (theory.md 1.5); "
    "the friction wrench on the slider is its negative";

std::string ratio_text(const Directions& d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", 1 / std::sqrt(d.lambda_sq.get_d()) - 1);
  return buf;
}

void write_limit_surface(Json_writer& w, const Ls_options& lo, const Support_item& r) {
  const Polygonal_ls& model = *r.model;
  const Directions& d = model.directions();
  const Ls_support& sup = model.support();
  const Sliding_answer& sa = r.sliding;
  w.member("command", "limit-surface").member("name", r.scene.name).member("mode", mode_name(lo.mode));
  w.member("convention", kConvention).member("sides", lo.query.sides);
  if (lo.query.tolerance) w.member("tolerance", *lo.query.tolerance).member("direction_sets_tried", lo.sets_built);
  w.member("lambda_squared", d.lambda_sq).key("relative_error_bound_approx").raw(ratio_text(d));
  w.key("support").object().member("input_points", r.scene.support->points.size()).member("points", sup.points.size());
  w.member("collinear", sup.collinear).member("mu_f0", sa.mu_f0).key("center_of_friction").array();
  w.rational(sa.center_of_friction.x).rational(sa.center_of_friction.y).end_array();
  write_approx(w, "center_of_friction", {sa.center_of_friction.x, sa.center_of_friction.y});
  w.end_object();
  w.member("dimension", model.dimension());
  if (r.polytopes_built) {
    write_polytope(w.key("inner"), r.in, lo.list);
    write_polytope(w.key("outer"), r.out, lo.list);
  } else {
    w.member("polytopes", false);  // a query alone: answered without them (--sides or --list builds them)
  }
  if (lo.query.twist) {
    w.key("twist").rationals(*lo.query.twist);
    write_face(w.key("load_for_twist").object().key("inner"), sa.inner_face);
    write_face(w.key("outer"), sa.outer_face);
    w.key("power").object().member("inner", sa.h_inner).member("outer", sa.h_outer).end_object();
    w.key("true_surface").object();
    const char* kinds[] = {"facet", "vertex", "smooth"};
    w.member("kind", kinds[static_cast<int>(sa.cls.kind)]);
    w.member("text", sa.cls.text).end_object();
    write_true(w, r);
    w.end_object();
  }
  if (lo.query.load) {
    const auto cone = [&w](const char* key, const Polygonal_ls::Normal_cone& c) {
      w.key(key).object().key("generators").array();
      for (const Vec3z& g : c.generators) w.rationals(g);
      w.end_array().key("lineality").array();
      for (const Vec3z& g : c.lineality) w.rationals(g);
      w.end_array().end_object();
    };
    write_motion(w, r, *lo.query.load);
    if (r.polytopes_built) {
      write_gauge(w.key("gauge").object().key("outer"), r.gauge_out);
      write_gauge(w.key("inner"), r.gauge_in);
      w.end_object();
    }
    write_certificate_members(w, r);
    if (r.polytopes_built && r.motion->motion != Motion::sticks) {
      w.key("twist_cone").object();
      cone("outer", r.cone_out);
      cone("inner", r.cone_in);
      w.end_object();
    }
  }
}

std::string limit_surface_human(const Ls_options& lo, const Support_item& r, const std::string& source) {
  const Polygonal_ls& model = *r.model;
  const Directions& d = model.directions();
  const Ls_support& sup = model.support();
  const Sliding_answer& sa = r.sliding;
  std::ostringstream s;
  s << scene_line(r.scene, source)
    << "support: " << sup.points.size() << " distinct point(s) with mu*f > 0 (of " << r.scene.support->points.size()
    << " given)" << (sup.collinear ? ", collinear" : "") << ", mu*f0 = " << number_text(sa.mu_f0)
    << ", centre of friction " << vec_text(sa.center_of_friction) << "\n"
    << "sides: " << lo.query.sides;
  if (lo.query.tolerance) s << " (the smallest meeting --tolerance " << to_string(*lo.query.tolerance) << ")";
  s << "\ncertificate: lambda^2 = " << number_text(d.lambda_sq) << "  (lambda*LS <= LS_in <= LS <= LS_out <= LS/lambda;"
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
  if (lo.query.twist) {
    s << "twist " << vec_text(*lo.query.twist) << ": " << sa.cls.text << "\n";
    for (const auto& [name, f] : {std::pair<const char*, const Ls_face*>{"inner", &sa.inner_face}, {"outer", &sa.outer_face}}) {
      s << "  load on LS_" << name << ": ";
      if (f->dimension == 0) s << "the point " << vec_text(f->vertices[0]) << "\n";
      else {
        s << (f->dimension == 1 ? "the segment" : "the facet with vertices");
        for (const Vec3q& v : f->vertices) s << " " << vec_text(v);
        s << "\n";
      }
    }
    s << "  power: " << number_text(sa.h_inner) << " <= h <= " << number_text(sa.h_outer) << "\n";
    if (r.true_power) s << "  true power (float twin, certified): " << bounded_text(*r.true_power) << "\n";
  }
  if (lo.query.load) {
    s << load_motion_text(r, *lo.query.load);
    if (r.polytopes_built && r.motion->motion != Motion::sticks) {
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
void write_limit_surface_float(Json_writer& w, const Ls_options& lo, const Support_item& r) {
  const fl::Directions_twin& d = *r.twin_directions;
  const fl::Point2& cof = r.twin_center_of_friction;
  w.member("command", "limit-surface").member("name", r.scene.name).member("mode", "float");
  w.member("convention", kConvention).member("sides", lo.query.sides);
  if (lo.query.tolerance) w.member("tolerance", *lo.query.tolerance);
  write_float_value(w.key("lambda_squared"), d.lambda_sq);
  w.key("support").object().member("input_points", r.scene.support->points.size()).member("points", r.twin.size());
  write_float_value(w.key("mu_f0"), r.twin_mu_f0);
  write_float_value(w.key("center_of_friction").array(), cof.x);
  write_float_value(w, cof.y);
  w.end_array().end_object();
  if (lo.query.twist) {
    w.key("twist").rationals(*lo.query.twist);
    write_float_value(w.key("load_for_twist").object().key("power").object().key("inner"), *r.twin_power_inner);
    write_float_value(w.key("outer"), *r.twin_power_outer);
    w.end_object();
    write_true(w, r);
    w.end_object();
  }
  if (lo.query.load) {
    write_motion(w, r, *lo.query.load);
    write_certificate_members(w, r);
  }
}

std::string limit_surface_float_human(const Ls_options& lo, const Support_item& r, const std::string& source) {
  const fl::Directions_twin& d = *r.twin_directions;
  const fl::Point2& cof = r.twin_center_of_friction;
  std::ostringstream s;
  s << scene_line(r.scene, source)
    << "support: " << r.twin.size() << " point(s) with mu*f > 0 (of " << r.scene.support->points.size()
    << " given), centre of friction (" << bounded_text(cof.x) << ", " << bounded_text(cof.y) << ")\n"
    << "sides: " << lo.query.sides << ", lambda^2 = " << bounded_text(d.lambda_sq) << " (the float twin's direction set)\n"
    << "convention: " << kConvention << "\n";
  if (lo.query.twist) {
    s << "twist " << vec_text(*lo.query.twist) << ":\n"
      << "  polygonal power: " << bounded_text(*r.twin_power_inner) << " <= h <= " << bounded_text(*r.twin_power_outer)
      << "\n";
    if (r.true_power) s << "  true power: " << bounded_text(*r.true_power) << "\n";
    if (r.true_load) s << "  true load: " << float_load_text(*r.true_load) << "\n";
  }
  if (lo.query.load) s << load_motion_text(r, *lo.query.load);
  s << "decided by: the float twin alone (every sign certified; values with certified bounds)\n";
  return s.str();
}

// An unknown distribution (docs/theory-sliding.md §2): the admissible set, the power over it for --twist,
// and for --load whether it sticks for every distribution, slides for every one, or depends, with witnesses.
void write_limit_surface_unknown(Json_writer& w, const Ls_options& lo, const Support_item& r) {
  w.member("command", "limit-surface").member("name", r.scene.name).member("mode", mode_name(r.mode));
  w.member("convention", kConvention).member("sides", lo.query.sides);
  write_unknown_distribution(w, r);
  if (lo.query.twist) {
    w.key("twist").rationals(*lo.query.twist);
    write_power_over(w, r);
  }
  if (!lo.query.load) return;
  write_motion(w, r, *lo.query.load);
  write_certificate_members(w, r);
}

std::string limit_surface_unknown_human(const Ls_options& lo, const Support_item& r, const std::string& source) {
  std::ostringstream s;
  s << unknown_support_text(r, source);
  if (lo.query.twist)
    s << "twist " << vec_text(*lo.query.twist) << ": the frictional power over every admissible distribution lies in ["
      << number_text(r.power->lower) << ", " << number_text(r.power->upper) << "]\n" << regions_power_text(r);
  if (lo.query.load) s << load_motion_text(r, *lo.query.load);
  s << "convention: " << kConvention << "\n";
  return s.str();
}

// --exact-coordinates says how each mesh file holds its coordinates (exact/cgal/mesh_io.h): JSON "mesh_coordinates"
// {"off": "…", …} and a text line per file. Without the option the answer is as before (nearest doubles).
void write_mesh_coordinates(Json_writer& w, const Ls_options& lo) {
  if (!lo.exact_coordinates) return;
  w.key("mesh_coordinates").object();
  for (const auto& [format, file] : lo.meshes()) {
    std::string key = mesh_format_name(format);
    for (char& c : key) c = static_cast<char>(c - 'A' + 'a');
    w.member(key.c_str(), coordinates_note(format, true));
  }
  w.end_object();
}

std::string mesh_coordinates_text(const Ls_options& lo) {
  if (!lo.exact_coordinates) return "";
  std::string s;
  for (const auto& [format, file] : lo.meshes())
    s += std::string(mesh_format_name(format)) + " " + file + ": coordinates " + coordinates_note(format, true) + "\n";
  return s;
}

// A support with regions [RG-1]: the exact statics, the twist's certified power and load, the load's motion with
// its certificate; no polytope (the limit surface is strictly convex).
void write_limit_surface_regions(Json_writer& w, const Ls_options& lo, const Support_item& r) {
  w.member("command", "limit-surface").member("name", r.scene.name).member("mode", mode_name(lo.mode));
  w.member("convention", kConvention);
  write_region_statics(w, r);
  w.member("polytopes", false).member("strictly_convex", true);
  write_region_twist(w, r, lo.query.tolerance ? *lo.query.tolerance : Rational(1, 1000000));
  if (!lo.query.load) return;
  write_motion(w, r, *lo.query.load);
  write_certificate_members(w, r);
}

std::string limit_surface_regions_human(const Ls_options& lo, const Support_item& r, const std::string& source) {
  std::ostringstream s;
  s << region_statics_text(r, source)
    << "limit surface: strictly convex (a continuous pressure): no exact polytope; queries are certified\n"
    << region_twist_text(r);
  if (lo.query.load) s << load_motion_text(r, *lo.query.load);
  s << "convention: " << kConvention << "\n";
  return s.str();
}

// The answer as JSON and as text, by what the pipeline answered (an unknown distribution, the twin alone, or
// the exact answer).
void answer_json(Json_writer& w, const Ls_options& lo, const Support_item& r) {
  by_kind(r, &write_limit_surface, &write_limit_surface_float, &write_limit_surface_unknown,
            &write_limit_surface_regions)(w, lo, r);
}

std::string answer_text(const Ls_options& lo, const Support_item& r, const std::string& source) {
  return by_kind(r, &limit_surface_human, &limit_surface_float_human, &limit_surface_unknown_human,
                   &limit_surface_regions_human)(lo, r, source);
}

}  // namespace

Scene_answer prepare_limit_surface_json(const Options& o) {
  return per_scene(o, limit_surface_options, compute_limit_surface, answer_json);
}

int run_limit_surface(const Options& o, const std::string& text, const std::string& source) {
  const Ls_options lo = limit_surface_options(o);
  const Support_item r = compute_limit_surface(lo, o, text, source);
  if (r.kind == Support_kind::unknown && (lo.list || lo.exports()))
    throw Input_error(source + ": support: the forces of some points are not given, so there is no one limit surface "
                      "to list or draw (--list, --off, --obj, --ply, --svg need every force)");
  if (!o.certificate_file.empty()) {
    if (r.certificate.empty())
      throw Failure(Status::undecided, "the load's motion is undecided: no certificate to write" +
                                           (r.motion && !r.motion->undecided_why.empty() ? " (" + r.motion->undecided_why + ")"
                                                                                          : std::string()) +
                                           undecided_advice(o.mode));
    write_file(o.certificate_file, r.certificate + "\n");
  }
  // Every mesh is made before any file is written (a coordinate beyond the doubles is an error, nothing written).
  std::vector<std::string> mesh_bytes;
  for (const auto& [format, file] : lo.meshes()) mesh_bytes.push_back(polytopes_mesh(r.in, r.out, format, lo.exact_coordinates));
  for (std::size_t i = 0; i < mesh_bytes.size(); ++i) write_file(lo.meshes()[i].second, mesh_bytes[i]);
  if (!lo.svg_file.empty()) write_file(lo.svg_file, render_limit_surface_svg(r.scene, lo.query.sides));
  return write_answer(o, [&](Json_writer& w) {
    answer_json(w, lo, r);
    write_mesh_coordinates(w, lo);
  }, [&] {
    const bool asked = lo.query.twist || lo.query.load || lo.list || lo.exports() || o.sides || o.tolerance;
    return answer_text(lo, r, source) + mesh_coordinates_text(lo) + (asked ? std::string() : ask_support_text());
  },
                      r.motion && r.motion->motion == Motion::undecided);
}

}  // namespace wrenchkit::cli
