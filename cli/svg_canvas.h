// The SVG writer of every picture of `wrenchkit render` (and `limit-surface --svg`): one number
// format, one escaping, one document frame, and two layouts. Svg_canvas: a disc-shaped view of the
// plane whose rim is the circle at infinity (the two-sided plane seen from its front sheet, as in
// Stolfi's and Mason's drawings), world → screen mapping, clipping of exact regions to the view,
// arrows, legend. Svg_panels: a row of square plots, each in its own coordinates (the limit
// surfaces' slices and projections). Pictures are presentation only: coordinates are converted to
// double here, after every exact computation; nothing drawn feeds back into an answer.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "exact/statics/planar_region.h"

namespace wrenchkit::cli {

struct P2 {
  double x = 0, y = 0;
};
P2 to_p2(const Vec2& v);
P2 unit(P2 d);  // d / |d|; (1, 0) for the zero vector

// The number format of every picture: `decimals` places (2 for coordinates); non-finite as 0.
std::string svg_num(double v, int decimals = 2);

// The convex hull of pts, counter-clockwise from the lowest of the leftmost points, collinear points
// dropped (Andrew's monotone chain); fewer than three distinct points come back sorted, duplicates
// dropped. Double arithmetic: for drawing only.
std::vector<P2> convex_hull(std::vector<P2> pts);

class Svg_canvas {
 public:
  // The view: a disc of world radius `radius` about `centre`, drawn on a square canvas.
  Svg_canvas(P2 centre, double radius, std::string title, std::string subtitle = "");

  // World-space drawing (clipped to the view disc).
  void region(const Region& r, const std::string& fill, const std::string& stroke, const std::string& label);
  // Returns the clipped polygon (world coordinates).
  std::vector<P2> polygon(const std::vector<P2>& pts, const std::string& style);
  void line(P2 a, P2 b, const std::string& style);
  void full_line(P2 through, P2 direction, const std::string& style);  // the whole line, clipped
  void arrow(P2 from, P2 to, const std::string& colour, double width = 2);
  void dot(P2 p, double r_px, const std::string& style);
  // A label up right of p, or where it covers no label drawn before (a nearby free place).
  void text(P2 p, const std::string& s, const std::string& style = "");
  // The rim: the circle at infinity, and labeled arcs/directions on it (counter-clockwise arcs).
  void infinity_arc(P2 from, P2 to, bool full, const std::string& colour);
  void infinity_dot(P2 direction, const std::string& colour);
  void infinity_cone(const Cone2& c, const std::string& colour);
  // Legend entries (swatch style, text) and caption lines, drawn below the disc.
  void legend(const std::string& swatch_style, const std::string& text);
  void caption(const std::string& text);

  double world_radius() const { return radius_; }
  P2 centre() const { return centre_; }
  std::string finish() const;

 private:
  P2 screen(P2 w) const;
  std::vector<P2> clip(const std::vector<P2>& poly) const;  // to the square around the disc
  void arrowhead(P2 tip_world, P2 dir, const std::string& colour);

  P2 centre_;
  double radius_;
  std::string title_, subtitle_;
  struct Label_box {
    double x0, y0, x1, y1;  // page pixels
  };
  std::vector<Label_box> labels_;  // the texts drawn so far: a new one is placed off them
  std::string body_;   // clipped to the view disc
  std::string texts_;  // the labels, drawn over everything in the disc
  std::string rim_;   // on the circle at infinity
  std::vector<std::pair<std::string, std::string>> legend_;
  std::vector<std::string> captions_;
};

// A row of square panels under a heading and a subheading, with a legend row below. Each panel is
// a plot in its own coordinates: axes through its origin, scaled so that every shape drawn in it
// lies within 0.42 of the panel's width of the centre, the half-range written at both axes' ends.
class Svg_panels {
 public:
  Svg_panels(std::string title, std::string heading, std::string subheading);

  // A new panel right of the others; returns its index.
  int panel(std::string title, std::string xlabel, std::string ylabel);
  // In panel i's coordinates, drawn in call order: a polygon as given (one or two points too; none:
  // nothing), and a circle of radius r about the origin.
  void polygon(int i, std::vector<P2> pts, const std::string& style);
  void circle(int i, double r, const std::string& style);
  // Legend entries, x pixels right of the left margin: a small box or a short line in `style`.
  void legend_box(double x, const std::string& style, const std::string& text);
  void legend_line(double x, const std::string& style, const std::string& text);

  std::string finish() const;

 private:
  struct Shape {
    std::vector<P2> pts;  // a polygon; empty for a circle
    double r = 0;         // a circle's radius
    std::string style;
  };
  struct Panel {
    std::string title, xlabel, ylabel;
    std::vector<Shape> shapes;
  };
  std::string panel_svg(const Panel& p, double x0) const;

  std::string title_, heading_, subheading_;
  std::vector<Panel> panels_;
  std::string legend_;
};

// Escapes text for XML.
std::string xml_escape(const std::string& s);

}  // namespace wrenchkit::cli
