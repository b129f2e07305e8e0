#include "cli/svg_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace wrenchkit::cli {

namespace {

constexpr double kWidth = 720, kDiscPx = 320, kCx = 360, kCy = 396;
constexpr double kPi = 3.14159265358979323846;
constexpr double kPanel = 300, kGap = 30, kTop = 70;  // Svg_panels: panel side, margins, heading height

std::string num(double v) { return svg_num(v); }
std::string xy(P2 p) { return num(p.x) + "," + num(p.y); }

// The elements, in page pixels (y runs down), one line each.
std::string line_el(P2 a, P2 b, const std::string& style) {
  return "<line x1=\"" + num(a.x) + "\" y1=\"" + num(a.y) + "\" x2=\"" + num(b.x) + "\" y2=\"" + num(b.y) + "\" " + style +
         "/>\n";
}
std::string polygon_el(const std::vector<P2>& px, const std::string& style) {
  std::string s = "<polygon points=\"";
  for (const P2& p : px) s += xy(p) + " ";
  return s + "\" " + style + "/>\n";
}
std::string circle_el(P2 c, double r, const std::string& style) {
  return "<circle cx=\"" + num(c.x) + "\" cy=\"" + num(c.y) + "\" r=\"" + num(r) + "\" " + style + "/>\n";
}
std::string text_el(P2 at, const std::string& text, const std::string& style) {
  return "<text x=\"" + num(at.x) + "\" y=\"" + num(at.y) + "\" " + style + ">" + xml_escape(text) + "</text>\n";
}
// The document's opening: size, title, white background (close with "</svg>\n").
std::string document_head(double width, double height, const std::string& title) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width) +
         "\" height=\"" + num(height) + "\" viewBox=\"0 0 " + num(width) + " " + num(height) +
         "\" font-family=\"sans-serif\">\n<title>" + xml_escape(title) +
         "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

// Liang–Barsky: the part of segment a→b inside the box; false if none.
bool clip_segment(P2& a, P2& b, double x0, double y0, double x1, double y1) {
  double t0 = 0, t1 = 1;
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy}, q[4] = {a.x - x0, x1 - a.x, a.y - y0, y1 - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  const P2 a0 = a;
  a = {a0.x + t0 * dx, a0.y + t0 * dy};
  b = {a0.x + t1 * dx, a0.y + t1 * dy};
  return true;
}

}  // namespace

P2 to_p2(const Vec2& v) { return {v.x.get_d(), v.y.get_d()}; }

P2 unit(P2 d) {
  const double n = std::hypot(d.x, d.y);
  return n > 0 ? P2{d.x / n, d.y / n} : P2{1, 0};
}

std::string svg_num(double v, int decimals) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", decimals, std::isfinite(v) ? v : 0.0);
  return b;
}

std::vector<P2> convex_hull(std::vector<P2> p) {
  const auto less = [](P2 a, P2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  const auto same = [](P2 a, P2 b) { return a.x == b.x && a.y == b.y; };
  const auto cross = [](P2 o, P2 a, P2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::sort(p.begin(), p.end(), less);
  p.erase(std::unique(p.begin(), p.end(), same), p.end());
  if (p.size() < 3) return p;
  std::vector<P2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower chain
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {  // upper chain
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

std::string xml_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default:
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\n' || c == '\t') o += c;
    }
  }
  return o;
}

Svg_canvas::Svg_canvas(P2 centre, double radius, std::string title, std::string subtitle)
    : centre_(centre),
      radius_(radius > 0 && std::isfinite(radius) ? radius : 1),
      title_(std::move(title)),
      subtitle_(std::move(subtitle)) {}

P2 Svg_canvas::screen(P2 w) const {
  const double s = kDiscPx / radius_;
  return {kCx + (w.x - centre_.x) * s, kCy - (w.y - centre_.y) * s};
}

std::vector<P2> Svg_canvas::clip(const std::vector<P2>& poly) const {
  const double r = 1.05 * radius_;
  const double lo[2] = {centre_.x - r, centre_.y - r}, hi[2] = {centre_.x + r, centre_.y + r};
  std::vector<P2> out = poly;
  for (int axis = 0; axis < 2; ++axis)
    for (int side = 0; side < 2; ++side) {
      const auto inside = [&](P2 p) {
        const double v = axis == 0 ? p.x : p.y;
        return side == 0 ? v >= lo[axis] : v <= hi[axis];
      };
      const auto cut = [&](P2 a, P2 b) {
        const double bound = side == 0 ? lo[axis] : hi[axis];
        const double va = axis == 0 ? a.x : a.y, vb = axis == 0 ? b.x : b.y;
        const double t = (bound - va) / (vb - va);
        return P2{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
      };
      std::vector<P2> in;
      in.swap(out);
      for (std::size_t i = 0; i < in.size(); ++i) {
        const P2 a = in[i], b = in[(i + 1) % in.size()];
        if (inside(a)) {
          out.push_back(a);
          if (!inside(b)) out.push_back(cut(a, b));
        } else if (inside(b)) {
          out.push_back(cut(a, b));
        }
      }
    }
  return out;
}

std::vector<P2> Svg_canvas::polygon(const std::vector<P2>& pts, const std::string& style) {
  const std::vector<P2> c = clip(pts);
  if (c.size() < 3) return c;
  std::vector<P2> px;
  for (const P2& p : c) px.push_back(screen(p));
  body_ += polygon_el(px, style);
  return c;
}

void Svg_canvas::line(P2 a, P2 b, const std::string& style) {
  const double r = 1.05 * radius_;
  if (!clip_segment(a, b, centre_.x - r, centre_.y - r, centre_.x + r, centre_.y + r)) return;
  body_ += line_el(screen(a), screen(b), style);
}

void Svg_canvas::full_line(P2 p, P2 d, const std::string& style) {
  const P2 u = unit(d);
  const double far = 4 * (radius_ + std::hypot(p.x - centre_.x, p.y - centre_.y));
  line({p.x - far * u.x, p.y - far * u.y}, {p.x + far * u.x, p.y + far * u.y}, style);
}

void Svg_canvas::arrowhead(P2 tip, P2 dir, const std::string& colour) {
  const P2 s = screen(tip);
  P2 d = unit(dir);
  d.y = -d.y;  // screen y runs down
  const P2 n{-d.y, d.x};
  const double L = 11, W = 5;
  const P2 a{s.x - L * d.x + W * n.x, s.y - L * d.y + W * n.y}, b{s.x - L * d.x - W * n.x, s.y - L * d.y - W * n.y};
  body_ += "<polygon points=\"" + xy(s) + " " + xy(a) + " " + xy(b) + "\" fill=\"" + colour + "\"/>\n";
}

void Svg_canvas::arrow(P2 from, P2 to, const std::string& colour, double width) {
  line(from, to, "stroke=\"" + colour + "\" stroke-width=\"" + num(width) + "\"");
  arrowhead(to, {to.x - from.x, to.y - from.y}, colour);
}

void Svg_canvas::dot(P2 p, double r_px, const std::string& style) {
  if (std::hypot(p.x - centre_.x, p.y - centre_.y) > 1.05 * radius_) return;
  body_ += circle_el(screen(p), r_px, style);
}

void Svg_canvas::text(P2 p, const std::string& s, const std::string& style) {
  if (std::hypot(p.x - centre_.x, p.y - centre_.y) > radius_) return;
  const P2 q = screen(p);
  const std::size_t sized = style.find("font-size=\"");
  const double size = sized == std::string::npos ? 13 : std::atof(style.c_str() + sized + 11);
  // The text's extent, estimated: 0.62 of the font size per character (UTF-8 continuation bytes not counted).
  double chars = 0;
  for (const char c : s) chars += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  const double w = 0.62 * size * chars, h = size;
  // Up right of the point, as always; where that covers a text already placed (names at a shared or a nearby
  // point, two captions at one centroid), the first free place of: down right, up left, down left, then further
  // up and down.
  const double gap = 6;
  std::vector<P2> at = {{q.x + gap, q.y - gap}, {q.x + gap, q.y + gap + h}, {q.x - gap - w, q.y - gap},
                        {q.x - gap - w, q.y + gap + h}};
  for (int k = 1; k <= 4; ++k) {
    at.push_back({q.x + gap, q.y - gap - k * (h + 2)});
    at.push_back({q.x + gap, q.y + gap + h + k * (h + 2)});
  }
  const auto free = [&](P2 a) {
    for (const Label_box& b : labels_)
      if (a.x < b.x1 && a.x + w > b.x0 && a.y - h < b.y1 && a.y > b.y0) return false;
    return true;
  };
  P2 chosen = at[0];
  for (const P2& a : at)
    if (free(a)) {
      chosen = a;
      break;
    }
  labels_.push_back({chosen.x, chosen.y - h, chosen.x + w, chosen.y});
  texts_ += text_el(chosen, s, (sized == std::string::npos ? "font-size=\"13\" " : "") + style);
}

void Svg_canvas::region(const Region& r, const std::string& fill, const std::string& stroke, const std::string& label) {
  using S = Region::Shape;
  if (r.empty()) return;
  std::vector<P2> v;
  for (const Vec2& x : r.vertices) v.push_back(to_p2(x));
  std::vector<P2> d;
  for (const Vec2& x : r.directions) d.push_back(unit(to_p2(x)));
  const std::string line_style = "stroke=\"" + stroke + "\" stroke-width=\"5\" stroke-linecap=\"round\" opacity=\"0.8\"";
  const std::string area_style = "fill=\"" + fill + "\" fill-opacity=\"0.45\" stroke=\"" + stroke + "\" stroke-width=\"1.5\"";
  P2 anchor = v.empty() ? centre_ : v[0];
  double far = 4 * radius_;
  for (const P2& p : v) far = std::max(far, 4 * (radius_ + std::hypot(p.x - centre_.x, p.y - centre_.y)));
  const auto away = [&](P2 p, P2 u) { return P2{p.x + far * u.x, p.y + far * u.y}; };
  const auto centroid = [&](const std::vector<P2>& c) {
    if (c.empty()) return;
    P2 m{0, 0};
    for (const P2& p : c) m.x += p.x / static_cast<double>(c.size()), m.y += p.y / static_cast<double>(c.size());
    anchor = m;
  };
  // Arrowheads where the region runs off to infinity: on its boundary rays, just inside the rim.
  const auto run_off = [&](P2 from, P2 u) {
    const double t = 0.9 * radius_;
    // The point of the ray from + s·u at distance 0.9·radius from the centre (if the ray gets there).
    const double bx = from.x - centre_.x, by = from.y - centre_.y;
    const double b = bx * u.x + by * u.y, c = bx * bx + by * by - t * t;
    const double disc = b * b - c;
    if (disc < 0) return;
    const double s = -b + std::sqrt(disc);
    if (s <= 0) return;
    arrowhead({from.x + s * u.x, from.y + s * u.y}, u, stroke);
  };
  switch (r.shape) {
    case S::empty: return;
    case S::point: dot(v[0], 6, "fill=\"" + fill + "\" stroke=\"" + stroke + "\" stroke-width=\"2\""); break;
    case S::segment: line(v[0], v[1], line_style); break;
    case S::ray:
      line(v[0], away(v[0], d[0]), line_style);
      run_off(v[0], d[0]);
      break;
    case S::line:
      full_line(v[0], d[0], line_style);
      run_off(v[0], d[0]);
      run_off(v[0], d[1]);
      break;
    case S::strip:
      centroid(polygon({away(v[0], d[1]), away(v[0], d[0]), away(v[1], d[0]), away(v[1], d[1])}, area_style));
      run_off(v[0], d[0]);
      run_off(v[1], d[1]);
      break;
    case S::polygon: centroid(polygon(v, area_style)); break;
    case S::plane:
      polygon({{centre_.x - 2 * radius_, centre_.y - 2 * radius_}, {centre_.x + 2 * radius_, centre_.y - 2 * radius_},
               {centre_.x + 2 * radius_, centre_.y + 2 * radius_}, {centre_.x - 2 * radius_, centre_.y + 2 * radius_}},
              area_style);
      break;
    case S::half_plane:
    case S::wedge:
    case S::unbounded_polygon: {
      // Corners, then far points sweeping counter-clockwise from the outgoing direction d_1 to the
      // incoming direction d_k (theory of the REGION format: docs/cli.md).
      std::vector<P2> poly = v;
      const double a1 = std::atan2(d.front().y, d.front().x);
      double ak = std::atan2(d.back().y, d.back().x);
      while (ak < a1) ak += 2 * kPi;
      if (r.shape == S::half_plane) ak = a1 + kPi;
      const P2 last = v.back(), first = v.front();
      const int steps = std::max(2, static_cast<int>((ak - a1) / (kPi / 18)) + 1);
      for (int i = 0; i <= steps; ++i) {
        const double a = a1 + (ak - a1) * i / steps;
        const P2 from = i == 0 ? last : (i == steps ? first : P2{(last.x + first.x) / 2, (last.y + first.y) / 2});
        poly.push_back(away(from, {std::cos(a), std::sin(a)}));
      }
      centroid(polygon(poly, area_style));
      run_off(last, d.front());
      run_off(first, d.back());
      if (r.shape == S::half_plane) run_off(first, d[1]);
      break;
    }
  }
  if (!label.empty()) text(anchor, label, "font-size=\"20\" font-weight=\"bold\" fill=\"" + stroke + "\"");
}

void Svg_canvas::infinity_arc(P2 from, P2 to, bool full, const std::string& colour) {
  const double a0 = std::atan2(from.y, from.x);
  double a1 = std::atan2(to.y, to.x);
  while (a1 <= a0) a1 += 2 * kPi;
  if (full) a1 = a0 + 2 * kPi;
  const double R = kDiscPx + 6;
  std::string path = "<path d=\"";
  const int steps = std::max(2, static_cast<int>((a1 - a0) / (kPi / 90)));
  for (int i = 0; i <= steps; ++i) {
    const double a = a0 + (a1 - a0) * i / steps;
    path += (i ? " L " : "M ") + num(kCx + R * std::cos(a)) + " " + num(kCy - R * std::sin(a));
  }
  rim_ += path + "\" fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"7\" stroke-linecap=\"round\"/>\n";
}

void Svg_canvas::infinity_dot(P2 d, const std::string& colour) {
  const P2 u = unit(d);
  const double R = kDiscPx + 6;
  rim_ += "<circle cx=\"" + num(kCx + R * u.x) + "\" cy=\"" + num(kCy - R * u.y) + "\" r=\"6\" fill=\"" + colour +
           "\"/>\n";
}

void Svg_canvas::infinity_cone(const Cone2& c, const std::string& colour) {
  using S = Cone2::Shape;
  switch (c.shape) {
    case S::zero: break;
    case S::ray: infinity_dot(to_p2(c.extreme[0]), colour); break;
    case S::line:
      infinity_dot(to_p2(c.extreme[0]), colour);
      infinity_dot(to_p2(c.extreme[1]), colour);
      break;
    case S::wedge: infinity_arc(to_p2(c.extreme[0]), to_p2(c.extreme[1]), false, colour); break;
    case S::half_plane: infinity_arc(to_p2(c.extreme[0]), to_p2(c.extreme[2]), false, colour); break;
    case S::plane: infinity_arc({1, 0}, {1, 0}, true, colour); break;
  }
}

void Svg_canvas::legend(const std::string& swatch_style, const std::string& text) { legend_.push_back({swatch_style, text}); }
void Svg_canvas::caption(const std::string& text) { captions_.push_back(text); }

std::string Svg_canvas::finish() const {
  const double top = kCy + kDiscPx + 30;
  const double height = top + 22.0 * static_cast<double>(legend_.size() + captions_.size()) + 16;
  std::string s = document_head(kWidth, height, title_ + " \u2014 " + subtitle_);
  s += "<defs><clipPath id=\"view\"><circle cx=\"" + num(kCx) + "\" cy=\"" + num(kCy) + "\" r=\"" + num(kDiscPx) +
       "\"/></clipPath></defs>\n";
  s += "<text x=\"" + num(kCx) + "\" y=\"28\" font-size=\"16\" text-anchor=\"middle\">" + xml_escape(title_) + "</text>\n";
  s += "<text x=\"" + num(kCx) + "\" y=\"50\" font-size=\"14\" fill=\"#555\" text-anchor=\"middle\">" +
       xml_escape(subtitle_) + "</text>\n";
  s += circle_el({kCx, kCy}, kDiscPx + 6, "fill=\"none\" stroke=\"#bbb\" stroke-width=\"1\" stroke-dasharray=\"4 4\"");
  s += "<g clip-path=\"url(#view)\">\n" + body_ + texts_ + "</g>\n" + rim_;
  double y = top;
  for (const auto& [style, text] : legend_) {
    s += "<rect x=\"40\" y=\"" + num(y - 12) + "\" width=\"26\" height=\"14\" " + style + "/>\n";
    s += "<text x=\"76\" y=\"" + num(y) + "\" font-size=\"13\">" + xml_escape(text) + "</text>\n";
    y += 22;
  }
  for (const std::string& c : captions_) {
    s += "<text x=\"40\" y=\"" + num(y) + "\" font-size=\"13\">" + xml_escape(c) + "</text>\n";
    y += 22;
  }
  return s + "</svg>\n";
}

Svg_panels::Svg_panels(std::string title, std::string heading, std::string subheading)
    : title_(std::move(title)), heading_(std::move(heading)), subheading_(std::move(subheading)) {}

int Svg_panels::panel(std::string title, std::string xlabel, std::string ylabel) {
  panels_.push_back({std::move(title), std::move(xlabel), std::move(ylabel), {}});
  return static_cast<int>(panels_.size()) - 1;
}

void Svg_panels::polygon(int i, std::vector<P2> pts, const std::string& style) {
  if (!pts.empty()) panels_.at(static_cast<std::size_t>(i)).shapes.push_back({std::move(pts), 0, style});
}

void Svg_panels::circle(int i, double r, const std::string& style) {
  panels_.at(static_cast<std::size_t>(i)).shapes.push_back({{}, r, style});
}

void Svg_panels::legend_box(double x, const std::string& style, const std::string& text) {
  const double ly = kTop + kPanel + 30;
  legend_ += "<rect x=\"" + num(kGap + x) + "\" y=\"" + num(ly - 10) + "\" width=\"14\" height=\"10\" " + style + "/>\n";
  legend_ += text_el({kGap + x + 20, ly}, text, "font-size=\"12\"");
}

void Svg_panels::legend_line(double x, const std::string& style, const std::string& text) {
  const double ly = kTop + kPanel + 30;
  legend_ += line_el({kGap + x, ly - 4}, {kGap + x + 20, ly - 4}, style);
  legend_ += text_el({kGap + x + 26, ly}, text, "font-size=\"12\"");
}

std::string Svg_panels::panel_svg(const Panel& p, double x0) const {
  const double size = kPanel, y0 = kTop;
  double r = 0;  // the half-range: every shape fits
  for (const Shape& sh : p.shapes) {
    r = std::max(r, sh.r);
    for (const P2& q : sh.pts) r = std::max({r, std::fabs(q.x), std::fabs(q.y)});
  }
  if (r == 0) r = 1;
  const double s = 0.42 * size / r, cx = x0 + size / 2, cy = y0 + size / 2;
  std::string o = "<g>\n<rect x=\"" + num(x0) + "\" y=\"" + num(y0) + "\" width=\"" + num(size) + "\" height=\"" + num(size) +
                  "\" fill=\"#fcfcfc\" stroke=\"#999\"/>\n";
  o += line_el({x0 + 8, cy}, {x0 + size - 8, cy}, "stroke=\"#bbb\"");
  o += line_el({cx, y0 + 8}, {cx, y0 + size - 8}, "stroke=\"#bbb\"");
  o += text_el({x0 + size - 10, cy - 6}, p.xlabel, "text-anchor=\"end\" font-size=\"13\"");
  o += text_el({cx + 6, y0 + 20}, p.ylabel, "font-size=\"13\"");
  o += text_el({x0 + size / 2, y0 - 8}, p.title, "text-anchor=\"middle\" font-size=\"14\"");
  // Ticks at ±r, so the scale is readable.
  o += text_el({cx + s * r, cy + 16}, num(r), "text-anchor=\"middle\" font-size=\"11\"");
  o += text_el({cx - 4, cy - s * r + 4}, num(r), "text-anchor=\"end\" font-size=\"11\"");
  for (const Shape& sh : p.shapes) {
    if (sh.pts.empty()) {
      o += circle_el({cx, cy}, s * sh.r, sh.style);
      continue;
    }
    std::vector<P2> px;
    for (const P2& q : sh.pts) px.push_back({cx + s * q.x, cy - s * q.y});
    o += polygon_el(px, sh.style);
  }
  return o + "</g>\n";
}

std::string Svg_panels::finish() const {
  const double n = static_cast<double>(panels_.size());
  std::string s = document_head(kGap + n * (kPanel + kGap), kTop + kPanel + 70, title_);
  s += "<text x=\"" + num(kGap) + "\" y=\"26\" font-size=\"16\">" + xml_escape(heading_) + "</text>\n";
  s += "<text x=\"" + num(kGap) + "\" y=\"46\" font-size=\"12\">" + xml_escape(subheading_) + "</text>\n";
  for (std::size_t i = 0; i < panels_.size(); ++i) s += panel_svg(panels_[i], kGap + static_cast<double>(i) * (kPanel + kGap));
  return s + legend_ + "</svg>\n";
}

}  // namespace wrenchkit::cli
