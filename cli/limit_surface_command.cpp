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
#include "cli/render_limit_surface.h"
#include "exact/input_error.h"
#include "exact/json.h"
#include "exact/limit_surface.h"
#include "exact/sliding.h"

namespace wrenchkit::cli {

const char* kLimitSurfaceHelp =
    "usage: wrenchkit limit-surface [OPTIONS] SCENE.json\n"
    "\n"
    "Builds, exactly, the polygonal inner and outer limit surfaces of the scene's \"support\"\n"
    "(theory.md §12): every friction disc is replaced by the inscribed and the circumscribed N-gon of\n"
    "rational unit directions, and the Minkowski sums LS_in and LS_out are computed as exact polytopes\n"
    "(facets and vertices; coplanar facets merged). The certificate lambda^2 = (1 + min u_j.u_(j+1))/2\n"
    "guarantees  lambda*LS <= LS_in <= LS <= LS_out <= LS/lambda, i.e. for every twist q the true\n"
    "frictional power h(q) satisfies lambda*h <= h_in <= h <= h_out <= h/lambda.\n"
    "\n"
    "Sign convention (theory.md §1.5): every wrench here is the LOAD the slider applies to the support\n"
    "(parallel to the sliding velocity); the friction wrench on the slider is its negative. Wrenches are\n"
    "fx,fy,m with m about the origin; twists vx,vy,w with w counter-clockwise.\n"
    "\n"
    "options:\n"
    "  --sides N          polygon sides, even, 4..4096 (default 32)\n"
    "  --tolerance EPS    instead of --sides: the smallest N whose certified relative error\n"
    "                     1/lambda - 1 is <= EPS (EPS > 0, exact: 0.01, 1/100, 1e-3)\n"
    "  --twist vx,vy,w    also the load for this twist on LS_in and LS_out (a point, a segment or a\n"
    "                     facet), the bounds h_in <= h <= h_out, and what the twist is on the true LS\n"
    "  --load fx,fy,m     also \"motion\": sticks (certainly inside LS), slides (certainly not inside),\n"
    "                     or undecided (refine N); the gauge bounds, and the cones of twists of LS_out\n"
    "                     and LS_in at the load's direction\n"
    "  --list             list every facet (normal, offset, vertex indices) and vertex, exactly\n"
    "  --off FILE         write both polytopes as one coloured OFF mesh (inner blue, outer red)\n"
    "  --obj FILE         write both polytopes as a Wavefront OBJ with objects \"inner\" and \"outer\"\n"
    "  --json             machine-readable output (docs/limit-surface.md)\n"
    "  --max-digits N, --max-exponent N, --max-file-size BYTES, --max-contacts N  (as for closure)\n"
    "  --mode exact|hybrid|float  accepted; the limit surface is always computed exactly\n"
    "\n"
    "Exact rationals are printed in lowest terms; OFF/OBJ coordinates are doubles (for viewing).\n";

namespace {

struct Ls_options {
  int sides = 32;
  bool sides_given = false;
  std::optional<Rational> tolerance;
  std::string tolerance_text;
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

Vec3q parse_triple(const std::string& opt, const std::string& text, const Input_limits& limits, const char* names) {
  std::vector<std::string> parts;
  std::string cur;
  for (char c : text) {
    if (c == ',') {
      parts.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  parts.push_back(cur);
  if (parts.size() != 3)
    throw Usage_error(opt + ": \"" + text + "\" is not three numbers " + names + " separated by commas");
  Vec3q v;
  for (int i = 0; i < 3; ++i) {
    std::string why;
    const auto q = parse_rational(parts[static_cast<std::size_t>(i)], false, limits, why);
    if (!q) throw Usage_error(opt + ": \"" + parts[static_cast<std::size_t>(i)] + "\" " + why);
    v[static_cast<std::size_t>(i)] = *q;
  }
  return v;
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

}  // namespace

int run_limit_surface(int argc, char** argv) {
  Ls_options lo;
  std::vector<char*> rest = {argv[0], argv[1]};
  std::vector<std::string> twist_text(3);  // --tolerance, --twist, --load texts
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw Usage_error(a + " needs a value");
      return argv[++i];
    };
    if (a == "--sides") {
      const std::string v = value();
      if (v.empty() || v.size() > 6 || v.find_first_not_of("0123456789") != std::string::npos)
        throw Usage_error("--sides: \"" + v + "\" is not a positive integer");
      lo.sides = std::stoi(v);
      lo.sides_given = true;
      if (lo.sides < 4 || lo.sides % 2 != 0 || lo.sides > kMaxSides)
        throw Usage_error("--sides: " + v + " must be even and between 4 and " + std::to_string(kMaxSides));
    } else if (a == "--tolerance") {
      lo.tolerance_text = value();
      twist_text[0] = lo.tolerance_text;
    } else if (a == "--twist") {
      twist_text[1] = value();
      lo.twist = Vec3q{};
    } else if (a == "--load") {  // parsed below, once the number limits are known
      twist_text[2] = value();
      lo.load = Vec3q{};
    } else if (a == "--off") lo.off_file = value();
    else if (a == "--obj") lo.obj_file = value();
    else if (a == "--svg") lo.svg_file = value();
    else if (a == "--list") lo.list = true;
    else rest.push_back(argv[i]);
  }
  const Options o = parse_options(static_cast<int>(rest.size()), rest.data(), 2);
  if (o.help) return std::cout << kLimitSurfaceHelp, kAnswered;
  if (o.verdict_only) throw Usage_error("--verdict-only is for batch");
  if (!o.certificate_file.empty() || !o.form_certificate_file.empty())
    throw Usage_error("limit-surface writes no certificate file (its certificate is lambda_squared)");
  if (o.positional.size() != 1) throw Usage_error("limit-surface needs exactly one SCENE.json");
  if (!lo.tolerance_text.empty()) {
    if (lo.sides_given) throw Usage_error("--sides and --tolerance exclude each other");
    std::string why;
    const auto e = parse_rational(lo.tolerance_text, false, o.limits, why);
    if (!e) throw Usage_error("--tolerance: \"" + lo.tolerance_text + "\" " + why);
    if (*e <= 0) throw Usage_error("--tolerance: \"" + lo.tolerance_text + "\" must be > 0");
    lo.tolerance = *e;
  }
  if (lo.twist) {
    lo.twist = parse_triple("--twist", twist_text[1], o.limits, "vx,vy,w");
    if ((*lo.twist)[0] == 0 && (*lo.twist)[1] == 0 && (*lo.twist)[2] == 0)
      throw Usage_error("--twist: \"" + twist_text[1] + "\" is the zero twist (no motion, no load)");
  }
  if (lo.load) lo.load = parse_triple("--load", twist_text[2], o.limits, "fx,fy,m");

  const std::string& path = o.positional[0];
  const std::string source = path == "-" ? "<stdin>" : path;
  const Scene scene = read_scene(read_input(path, o.limits.max_file_bytes), o.limits, source);
  if (!scene.support) throw Input_error(source + ": support: the scene has no \"support\" (limit-surface needs one)");

  int sets_built = 0;
  if (lo.tolerance) {
    lo.sides = smallest_sides(*lo.tolerance, kMaxSides, &sets_built);
    if (lo.sides == 0)
      throw Usage_error("--tolerance: " + lo.tolerance_text + " needs more than " + std::to_string(kMaxSides) +
                        " sides (the largest certified ratio available is reached at --sides " +
                        std::to_string(kMaxSides) + ")");
  }
  const Polygonal_ls model(merge_support(*scene.support), make_directions(lo.sides));
  if (model.candidate_count() > kMaxCandidates)
    throw Usage_error("--sides " + std::to_string(lo.sides) + " with " + std::to_string(model.support().points.size()) +
                      " distinct support points needs " + std::to_string(model.candidate_count()) +
                      " candidate normals, more than the limit " + std::to_string(kMaxCandidates) +
                      "; use fewer sides (or a larger --tolerance)");
  const Ls_polytope in = model.build(Side::inner), out = model.build(Side::outer);
  const Directions& d = model.directions();
  const Sliding_answer sa = compute_sliding(model, lo.twist);

  if (!lo.off_file.empty()) write_file(lo.off_file, off_text(in, out));
  if (!lo.obj_file.empty()) write_file(lo.obj_file, obj_text(in, out));
  if (!lo.svg_file.empty()) write_file(lo.svg_file, render_limit_surface_svg(scene, lo.sides));

  std::optional<Rational> g_in, g_out;
  Motion motion = Motion::undecided;
  Polygonal_ls::Normal_cone cone_in, cone_out;
  if (lo.load) {
    g_in = model.gauge(in, Side::inner, *lo.load);
    g_out = model.gauge(out, Side::outer, *lo.load);
    motion = classify_load(g_in, g_out);
    if (motion != Motion::sticks) {
      cone_in = model.normal_cone(in, Side::inner, *lo.load);
      cone_out = model.normal_cone(out, Side::outer, *lo.load);
    }
  }
  const Ls_support& sup = model.support();
  const std::string convention =
      "loads: the wrench the slider applies to the support, parallel to the sliding velocity (theory.md 1.5); "
      "the friction wrench on the slider is its negative";
  char ratio_buf[32];
  std::snprintf(ratio_buf, sizeof ratio_buf, "%.6g", 1 / std::sqrt(d.lambda_sq.get_d()) - 1);
  const std::string ratio = ratio_buf;
  if (o.json) {
    std::ostringstream s;
    s << "{\"command\": \"limit-surface\", \"name\": " << json::quote(scene.name) << ", \"convention\": "
      << json::quote(convention) << ", \"sides\": " << lo.sides;
    if (lo.tolerance)
      s << ", \"tolerance\": " << jq(*lo.tolerance) << ", \"direction_sets_tried\": " << sets_built;
    s << ", \"lambda_squared\": " << jq(d.lambda_sq) << ", \"relative_error_bound_approx\": " << ratio
      << ", \"support\": {\"input_points\": " << scene.support->points.size()
      << ", \"points\": " << sup.points.size() << ", \"collinear\": " << (sup.collinear ? "true" : "false")
      << ", \"mu_f0\": " << jq(sa.mu_f0) << ", \"center_of_friction\": [" << jq(sa.center_of_friction.x) << ", "
      << jq(sa.center_of_friction.y) << "]}, \"dimension\": " << model.dimension()
      << ", \"inner\": " << polytope_json(in, lo.list) << ", \"outer\": " << polytope_json(out, lo.list);
    if (lo.twist) {
      s << ", \"twist\": " << jv(*lo.twist) << ", \"load_for_twist\": {\"inner\": " << face_json(sa.inner_face)
        << ", \"outer\": " << face_json(sa.outer_face) << ", \"power\": {\"inner\": " << jq(sa.h_inner)
        << ", \"outer\": " << jq(sa.h_outer) << "}, \"true_surface\": {\"kind\": \""
        << (sa.cls.kind == Twist_kind::facet ? "facet" : (sa.cls.kind == Twist_kind::vertex ? "vertex" : "smooth"))
        << "\", \"text\": " << json::quote(sa.cls.text) << "}}";
    }
    if (lo.load) {
      auto cone_json = [&](const Polygonal_ls::Normal_cone& c) {
        std::string r = "{\"generators\": [";
        for (std::size_t i = 0; i < c.generators.size(); ++i) r += (i ? ", " : "") + jz(c.generators[i]);
        r += "], \"lineality\": [";
        for (std::size_t i = 0; i < c.lineality.size(); ++i) r += (i ? ", " : "") + jz(c.lineality[i]);
        return r + "]}";
      };
      s << ", \"load\": " << jv(*lo.load) << ", \"motion\": \"" << motion_name(motion)
        << "\", \"gauge\": {\"outer\": " << gauge_json(g_out) << ", \"inner\": " << gauge_json(g_in) << "}";
      if (motion != Motion::sticks)
        s << ", \"twist_cone\": {\"outer\": " << cone_json(cone_out) << ", \"inner\": " << cone_json(cone_in) << "}";
    }
    s << "}\n";
    std::cout << s.str();
    return kAnswered;
  }
  std::ostringstream s;
  s << "scene: " << (scene.name.empty() ? source : scene.name) << "\n"
    << "support: " << sup.points.size() << " distinct point(s) with mu*f > 0 (of " << scene.support->points.size()
    << " given)" << (sup.collinear ? ", collinear" : "") << ", mu*f0 = " << to_string(sa.mu_f0)
    << ", centre of friction (" << to_string(sa.center_of_friction.x) << ", " << to_string(sa.center_of_friction.y)
    << ")\n"
    << "sides: " << lo.sides;
  if (lo.tolerance) s << " (the smallest meeting --tolerance " << to_string(*lo.tolerance) << ")";
  s << "\ncertificate: lambda^2 = " << to_string(d.lambda_sq) << "  (lambda*LS <= LS_in <= LS <= LS_out <= LS/lambda;"
    << " relative error 1/lambda - 1 ~ " << ratio << ")\n";
  if (model.dimension() == 2)
    s << "note: one support point: the limit surface is a flat disc in the plane of its rotation twist (dimension 2);"
         " 'facets' are its two sides\n";
  if (model.dimension() == 0) s << "note: no point has mu*f > 0: the limit surface is the single point 0\n";
  for (const auto& [name, P] : {std::pair<const char*, const Ls_polytope*>{"inner", &in}, {"outer", &out}})
    s << name << ": " << P->facets.size() << " facets, " << P->vertices.size() << " vertices, " << P->edges << " edges\n";
  s << "convention: " << convention << "\n";
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
  }
  if (lo.load) {
    s << "load " << tv(*lo.load) << ": " << motion_name(motion) << "  (gauge between " << gauge_text(g_out) << " and "
      << gauge_text(g_in) << "; sticks if < 1, slides if >= 1)\n";
    if (motion == Motion::undecided) s << "  undecided: refine with more --sides or a smaller --tolerance\n";
    if (motion != Motion::sticks) {
      s << "  twists (outward normals of LS_out at the load's direction):";
      for (const Vec3z& g : cone_out.generators) s << " " << tz(g);
      for (const Vec3z& g : cone_out.lineality) s << " +-" << tz(g);
      s << "\n";
    }
  }
  std::cout << s.str();
  return kAnswered;
}

}  // namespace wrenchkit::cli
