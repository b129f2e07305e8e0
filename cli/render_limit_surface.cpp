// SVG of the polygonal limit surfaces (see render_limit_surface.h), drawn through Svg_panels.
#include "cli/render_limit_surface.h"

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "cli/svg_canvas.h"
#include "exact/io/input_error.h"
#include "exact/io/region.h"
#include "exact/sliding/limit_surface.h"
#include "exact/sliding/region_sliding.h"

namespace wrenchkit::cli {
namespace {

std::vector<std::array<double, 3>> to_double(const Ls_polytope& P) {
  std::vector<std::array<double, 3>> v;
  for (const Vec3q& x : P.vertices) v.push_back({x[0].get_d(), x[1].get_d(), x[2].get_d()});
  return v;
}

// Slice f_y = 0 of the polytope, as the hull of points (f_x, m): vertices on the plane and edge crossings.
std::vector<P2> slice(const Ls_polytope& P) {
  const auto v = to_double(P);
  std::vector<P2> pts;
  for (const auto& x : v)
    if (x[1] == 0) pts.push_back({x[0], x[2]});
  for (const Ls_facet& f : P.facets)
    for (std::size_t i = 0; i < f.vertices.size(); ++i) {
      const auto& a = v[static_cast<std::size_t>(f.vertices[i])];
      const auto& b = v[static_cast<std::size_t>(f.vertices[(i + 1) % f.vertices.size()])];
      if ((a[1] < 0 && b[1] > 0) || (a[1] > 0 && b[1] < 0)) {
        const double s = a[1] / (a[1] - b[1]);
        pts.push_back({a[0] + s * (b[0] - a[0]), a[2] + s * (b[2] - a[2])});
      }
    }
  return convex_hull(pts);
}

// Projection of the polytope onto coordinates (c0, c1), as a hull.
std::vector<P2> projection(const Ls_polytope& P, int c0, int c1) {
  std::vector<P2> pts;
  for (const auto& x : to_double(P)) pts.push_back({x[static_cast<std::size_t>(c0)], x[static_cast<std::size_t>(c1)]});
  return convex_hull(pts);
}

// A support with regions [RG-1]: its limit surface is strictly convex (no polytope). Three panels: the support
// itself (each region's cells shaded by the pressure, darker where it is higher; the points; the centre of
// friction), the loads of the twists (cos t, 0, sin t) in (f_x, m) — points of the true limit surface, each the
// middle of its certified box — and the (f_x, f_y) projection, the disc of radius mu*f0.
std::string render_regions_svg(const Scene& scene) {
  const Support& s = *scene.support;
  const Region_sliding st = region_sliding(s, std::nullopt, 1);
  Svg_panels pic("wrenchkit limit surface",
                 "Limit surface of " + (scene.name.empty() ? std::string("the support") : scene.name),
                 std::to_string(s.points.size()) + " point(s), " + std::to_string(s.regions.size()) +
                     " region(s): strictly convex, no polytope; loads: what the slider applies to the support (theory.md 1.5)");
  const int sup = pic.panel("the support: pressure and centre of friction", "x", "y");
  double pmax = 0;
  for (const Support_region& g : s.regions)
    for (const auto& ring : g.rings)
      for (const Vec2& v : ring) pmax = std::max(pmax, pressure_at(g.pressure, v).get_d());
  for (const Support_region& g : s.regions) {
    const Region_cells cells = region_cells(g, 4);
    for (const auto& t : cells.triangles) {
      std::vector<P2> tri;
      double p = 0;
      for (const std::size_t i : t) {
        tri.push_back({cells.vertices[i].x.get_d(), cells.vertices[i].y.get_d()});
        p += pressure_at(g.pressure, cells.vertices[i]).get_d() / 3;
      }
      const double shade = pmax > 0 ? 0.15 + 0.7 * p / pmax : 0.5;
      pic.polygon(sup, std::move(tri), "fill=\"#3366e6\" fill-opacity=\"" + svg_num(shade, 3) + "\" stroke=\"none\"");
    }
    for (std::size_t k = 0; k < g.rings.size(); ++k) {
      std::vector<P2> ring;
      for (const Vec2& v : g.rings[k]) ring.push_back({v.x.get_d(), v.y.get_d()});
      pic.polygon(sup, std::move(ring), std::string("fill=\"") + (k == 0 ? "none" : "#fcfcfc") + "\" stroke=\"#1f3f8f\"");
    }
  }
  double span = 0;  // a marker size: 2% of the support's extent
  for (const Support_region& g : s.regions)
    for (const Vec2& v : g.rings[0]) span = std::max({span, std::fabs(v.x.get_d()), std::fabs(v.y.get_d())});
  for (const Support_point& p : s.points) span = std::max({span, std::fabs(p.at.x.get_d()), std::fabs(p.at.y.get_d())});
  const double d = 0.03 * (span > 0 ? span : 1);
  for (const Support_point& p : s.points) {
    const double x = p.at.x.get_d(), y = p.at.y.get_d();
    pic.polygon(sup, {{x - d, y - d}, {x + d, y - d}, {x + d, y + d}, {x - d, y + d}}, "fill=\"#333\" stroke=\"none\"");
  }
  const double cx = st.center_of_pressure.x.get_d(), cy = st.center_of_pressure.y.get_d();
  pic.polygon(sup, {{cx - 1.5 * d, cy}, {cx, cy - 1.5 * d}, {cx + 1.5 * d, cy}, {cx, cy + 1.5 * d}},
              "fill=\"#e03030\" stroke=\"#800\"");
  const int fm = pic.panel("loads of the twists (cos t, 0, sin t), (f_x, m)", "f_x", "m");
  std::vector<P2> curve;
  for (int j = 0; j < 96; ++j) {
    const double t = 2 * M_PI * (j + 0.5) / 96;
    const Vec3q q{Rational(std::cos(t)), Rational(0), Rational(std::sin(t))};
    const Region_sliding a = region_sliding(s, q, Rational(1, 1000));
    curve.push_back({Rational((a.load_lo[0] + a.load_hi[0]) / 2).get_d(), Rational((a.load_lo[2] + a.load_hi[2]) / 2).get_d()});
  }
  pic.polygon(fm, std::move(curve), "fill=\"#3366e6\" fill-opacity=\"0.25\" stroke=\"#3366e6\" stroke-width=\"1.5\"");
  const int ff = pic.panel("projection onto (f_x, f_y)", "f_x", "f_y");
  const std::string dashed = "stroke=\"#333\" stroke-dasharray=\"4 3\"";
  if (st.mu_f0 > 0) pic.circle(ff, st.mu_f0.get_d(), "fill=\"#3366e6\" fill-opacity=\"0.25\" " + dashed);
  pic.legend_box(0, "fill=\"#3366e6\" fill-opacity=\"0.6\"", "region: darker = higher pressure");
  pic.legend_box(250, "fill=\"#e03030\" stroke=\"#800\"", "centre of friction (exact: " + to_string(st.center_of_pressure.x).substr(0, 12) +
                                                                 ", " + to_string(st.center_of_pressure.y).substr(0, 12) + ")");
  pic.legend_line(560, dashed, "the disc of radius mu*f0");
  return pic.finish();
}

}  // namespace

std::string render_limit_surface_svg(const Scene& scene, int sides) {
  if (!scene.support) throw Input_error("support: the scene has no \"support\" (nothing to draw)");
  // Some point's force not given (regions beside them or not): a limit surface per distribution, none to draw.
  if (!scene.support->known())
    throw Input_error("support: the forces of some points are not given, so there is no one limit surface to draw");
  if (!scene.support->regions.empty()) return render_regions_svg(scene);
  const Polygonal_ls model(merge_support(*scene.support), make_directions(sides));
  if (model.candidate_count() > kMaxCandidates)
    throw Input_error("support: too many points for a picture with " + std::to_string(sides) + " sides");
  const Ls_polytope in = model.build(Side::inner), out = model.build(Side::outer);
  Rational muf0 = 0;
  for (const Ls_point& p : model.support().points) muf0 += p.rho;
  const std::string inner = "fill=\"#3366e6\" fill-opacity=\"0.35\" stroke=\"#3366e6\"";
  const std::string outer = "fill=\"none\" stroke=\"#e03030\"";
  const std::string dashed = "stroke=\"#333\" stroke-dasharray=\"4 3\"";
  Svg_panels pic("wrenchkit limit surface",
                 "Limit surface of " + (scene.name.empty() ? std::string("the support") : scene.name) + ": " +
                     std::to_string(sides) + " sides, lambda^2 = " + to_string(model.directions().lambda_sq).substr(0, 40) +
                     " (lambda ~ " + svg_num(std::sqrt(model.directions().lambda_sq.get_d()), 6) + ")",
                 "loads (f_x, f_y, m): the wrench the slider applies to the support (theory.md 1.5); m about the origin");
  const int sl = pic.panel("slice f_y = 0", "f_x", "m"), fm = pic.panel("projection onto (f_x, m)", "f_x", "m"),
            ff = pic.panel("projection onto (f_x, f_y)", "f_x", "f_y");
  // The true projection onto (f_x, f_y): the disc of radius mu*f0.
  if (muf0 > 0) pic.circle(ff, muf0.get_d(), "fill=\"none\" " + dashed);
  const auto draw = [&](int i, std::vector<P2> inner_polygon, std::vector<P2> outer_polygon) {
    pic.polygon(i, std::move(inner_polygon), inner + " stroke-width=\"1.5\"");
    pic.polygon(i, std::move(outer_polygon), outer + " stroke-width=\"1.5\"");
  };
  draw(sl, slice(in), slice(out));
  draw(fm, projection(in, 0, 2), projection(out, 0, 2));
  draw(ff, projection(in, 0, 1), projection(out, 0, 1));
  pic.legend_box(0, inner, "LS_in (inner, inscribed polygons)");
  pic.legend_box(250, outer, "LS_out (outer, circumscribed polygons)");
  pic.legend_line(540, dashed, "true LS projection: disc of radius mu*f0");
  return pic.finish();
}

}  // namespace wrenchkit::cli
