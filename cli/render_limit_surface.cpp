// SVG of the polygonal limit surfaces (see render_limit_surface.h).
#include "cli/render_limit_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "exact/io/input_error.h"
#include "exact/sliding/limit_surface.h"

namespace wrenchkit::cli {
namespace {

using P2 = std::array<double, 2>;

double cross(const P2& o, const P2& a, const P2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

std::vector<P2> hull(std::vector<P2> p) {  // Andrew's monotone chain, for drawing only
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<P2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

std::vector<std::array<double, 3>> to_double(const Ls_polytope& P) {
  std::vector<std::array<double, 3>> v;
  for (const Vec3q& x : P.vertices) v.push_back({x[0].get_d(), x[1].get_d(), x[2].get_d()});
  return v;
}

// Slice f_y = 0 of the polytope, as points (f_x, m): vertices on the plane and edge crossings.
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
  return hull(pts);
}

std::vector<P2> projection(const Ls_polytope& P, int c0, int c1) {
  std::vector<P2> pts;
  for (const auto& x : to_double(P)) pts.push_back({x[static_cast<std::size_t>(c0)], x[static_cast<std::size_t>(c1)]});
  return hull(pts);
}

std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", x);
  return b;
}

std::string esc(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '<') r += "&lt;";
    else if (c == '>') r += "&gt;";
    else if (c == '&') r += "&amp;";
    else r += c;
  }
  return r;
}

struct Panel {
  std::string title, xlabel, ylabel;
  std::vector<P2> inner, outer;
  double circle = 0;  // > 0: draw the true outline, a circle of this radius (dashed)
};

std::string draw(const Panel& p, double x0, double y0, double size) {
  double r = p.circle;
  for (const auto* poly : {&p.inner, &p.outer})
    for (const P2& q : *poly) r = std::max({r, std::fabs(q[0]), std::fabs(q[1])});
  if (r == 0) r = 1;
  const double s = 0.42 * size / r, cx = x0 + size / 2, cy = y0 + size / 2;
  auto X = [&](double x) { return num(cx + s * x); };
  auto Y = [&](double y) { return num(cy - s * y); };
  std::ostringstream o;
  o << "<g>\n<rect x=\"" << num(x0) << "\" y=\"" << num(y0) << "\" width=\"" << num(size) << "\" height=\"" << num(size)
    << "\" fill=\"#fcfcfc\" stroke=\"#999\"/>\n"
    << "<line x1=\"" << num(x0 + 8) << "\" y1=\"" << num(cy) << "\" x2=\"" << num(x0 + size - 8) << "\" y2=\"" << num(cy)
    << "\" stroke=\"#bbb\"/>\n<line x1=\"" << num(cx) << "\" y1=\"" << num(y0 + 8) << "\" x2=\"" << num(cx) << "\" y2=\""
    << num(y0 + size - 8) << "\" stroke=\"#bbb\"/>\n";
  o << "<text x=\"" << num(x0 + size - 10) << "\" y=\"" << num(cy - 6) << "\" text-anchor=\"end\" font-size=\"13\">"
    << esc(p.xlabel) << "</text>\n<text x=\"" << num(cx + 6) << "\" y=\"" << num(y0 + 20)
    << "\" font-size=\"13\">" << esc(p.ylabel) << "</text>\n";
  o << "<text x=\"" << num(x0 + size / 2) << "\" y=\"" << num(y0 - 8) << "\" text-anchor=\"middle\" font-size=\"14\">"
    << esc(p.title) << "</text>\n";
  // Tick at ±r (the plot's half-range) so the scale is readable.
  o << "<text x=\"" << num(cx + s * r) << "\" y=\"" << num(cy + 16) << "\" text-anchor=\"middle\" font-size=\"11\">"
    << num(r) << "</text>\n<text x=\"" << num(cx - 4) << "\" y=\"" << num(cy - s * r + 4)
    << "\" text-anchor=\"end\" font-size=\"11\">" << num(r) << "</text>\n";
  if (p.circle > 0)
    o << "<circle cx=\"" << num(cx) << "\" cy=\"" << num(cy) << "\" r=\"" << num(s * p.circle)
      << "\" fill=\"none\" stroke=\"#333\" stroke-dasharray=\"4 3\"/>\n";
  auto poly = [&](const std::vector<P2>& v, const char* style) {
    if (v.empty()) return;
    o << "<polygon points=\"";
    for (const P2& q : v) o << X(q[0]) << "," << Y(q[1]) << " ";
    o << "\" " << style << "/>\n";
  };
  poly(p.inner, "fill=\"#3366e6\" fill-opacity=\"0.35\" stroke=\"#3366e6\" stroke-width=\"1.5\"");
  poly(p.outer, "fill=\"none\" stroke=\"#e03030\" stroke-width=\"1.5\"");
  o << "</g>\n";
  return o.str();
}

}  // namespace

std::string render_limit_surface_svg(const Scene& scene, int sides) {
  if (!scene.support) throw Input_error("support: the scene has no \"support\" (nothing to draw)");
  const Polygonal_ls model(merge_support(*scene.support), make_directions(sides));
  if (model.candidate_count() > kMaxCandidates)
    throw Input_error("support: too many points for a picture with " + std::to_string(sides) + " sides");
  const Ls_polytope in = model.build(Side::inner), out = model.build(Side::outer);
  Rational muf0 = 0;
  for (const Ls_point& p : model.support().points) muf0 += p.rho;
  const std::vector<Panel> panels = {
      {"slice f_y = 0", "f_x", "m", slice(in), slice(out), 0},
      {"projection onto (f_x, m)", "f_x", "m", projection(in, 0, 2), projection(out, 0, 2), 0},
      {"projection onto (f_x, f_y)", "f_x", "f_y", projection(in, 0, 1), projection(out, 0, 1), muf0.get_d()}};
  char lambda_text[32];
  std::snprintf(lambda_text, sizeof lambda_text, "%.6f", std::sqrt(model.directions().lambda_sq.get_d()));
  const double size = 300, gap = 30, top = 70;
  const double width = gap + 3 * (size + gap), height = top + size + 70;
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\"" << num(height)
    << "\" viewBox=\"0 0 " << num(width) << " " << num(height) << "\" font-family=\"sans-serif\">\n"
    << "<title>wrenchkit limit surface</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << num(gap) << "\" y=\"26\" font-size=\"16\">Limit surface of " << esc(scene.name.empty() ? "the support" : scene.name)
    << ": " << sides << " sides, lambda^2 = " << esc(to_string(model.directions().lambda_sq).substr(0, 40))
    << " (lambda ~ " << lambda_text << ")</text>\n"
    << "<text x=\"" << num(gap) << "\" y=\"46\" font-size=\"12\">loads (f_x, f_y, m): the wrench the slider applies "
       "to the support (theory.md 1.5); m about the origin</text>\n";
  for (int i = 0; i < 3; ++i) o << draw(panels[static_cast<std::size_t>(i)], gap + i * (size + gap), top, size);
  const double ly = top + size + 30;
  o << "<rect x=\"" << num(gap) << "\" y=\"" << num(ly - 10) << "\" width=\"14\" height=\"10\" fill=\"#3366e6\" fill-opacity=\"0.35\" stroke=\"#3366e6\"/>\n"
    << "<text x=\"" << num(gap + 20) << "\" y=\"" << num(ly) << "\" font-size=\"12\">LS_in (inner, inscribed polygons)</text>\n"
    << "<rect x=\"" << num(gap + 250) << "\" y=\"" << num(ly - 10) << "\" width=\"14\" height=\"10\" fill=\"none\" stroke=\"#e03030\"/>\n"
    << "<text x=\"" << num(gap + 270) << "\" y=\"" << num(ly) << "\" font-size=\"12\">LS_out (outer, circumscribed polygons)</text>\n"
    << "<line x1=\"" << num(gap + 540) << "\" y1=\"" << num(ly - 4) << "\" x2=\"" << num(gap + 560) << "\" y2=\"" << num(ly - 4)
    << "\" stroke=\"#333\" stroke-dasharray=\"4 3\"/>\n"
    << "<text x=\"" << num(gap + 566) << "\" y=\"" << num(ly) << "\" font-size=\"12\">true LS projection: disc of radius mu*f0</text>\n"
    << "</svg>\n";
  return o.str();
}

}  // namespace wrenchkit::cli
