// A small SVG writer for the pictures of `wrenchkit render`: a disc-shaped view of the plane whose
// rim is the circle at infinity (the two-sided plane seen from its front sheet, as in Stolfi's and
// Mason's drawings), world → screen mapping, clipping of exact regions to the view, arrows, legend.
// Pictures are presentation only: coordinates are converted to double here, after every exact
// computation; nothing drawn feeds back into an answer.
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
  std::string body_;  // clipped to the view disc
  std::string rim_;   // on the circle at infinity
  std::vector<std::pair<std::string, std::string>> legend_;
  std::vector<std::string> captions_;
};

// Escapes text for XML.
std::string xml_escape(const std::string& s);

}  // namespace wrenchkit::cli
