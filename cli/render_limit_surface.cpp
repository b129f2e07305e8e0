// SVG of the polygonal limit surfaces (see render_limit_surface.h), drawn through Svg_panels.
#include "cli/render_limit_surface.h"

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "cli/svg_canvas.h"
#include "exact/io/input_error.h"
#include "exact/sliding/limit_surface.h"

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

}  // namespace

std::string render_limit_surface_svg(const Scene& scene, int sides) {
  if (!scene.support) throw Input_error("support: the scene has no \"support\" (nothing to draw)");
  if (!scene.support->known())
    throw Input_error("support: the forces of some points are not given, so there is no one limit surface to draw");
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
