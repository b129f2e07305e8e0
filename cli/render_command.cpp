// wrenchkit render SCENE --what labels|dual|reuleaux [-o FILE.svg]: the figure a reader of Mason's
// book expects — body, contacts with friction cones or normals, lines of force, the shaded + / −
// regions clipped to a disc whose rim is the circle at infinity (labeled directions drawn on it),
// arrows where regions run off to infinity, the load, a legend. Computed exactly, drawn in double.
#include <cmath>
#include <cstdio>
#include <optional>
#include <iostream>
#include <sstream>
#include <string>

#include "cli/common.h"
#include "exact/io/outline.h"
#include "cli/render_limit_surface.h"
#include "cli/svg_canvas.h"
#include "exact/numbers/decimal.h"
#include "exact/statics/force_dual.h"

namespace wrenchkit::cli {

namespace {

const char* kPlus = "#2f6fd0";
const char* kMinus = "#d0453f";
const char* kBoth = "#111111";
const char* kInfinity = "#8a3fbf";
const char* kLoad = "#1e8c3a";
const char* kCone = "#f0a030";

std::string swatch(const std::string& colour, double opacity = 0.45) {
  return "fill=\"" + colour + "\" fill-opacity=\"" + svg_num(opacity) + "\" stroke=\"" + colour + "\"";
}

// The view: every finite point the picture shows, with a margin.
struct Bounds {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  void add(P2 p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  }
  void add(const Region& r) {
    for (const Vec2& v : r.vertices) add(to_p2(v));
  }
  Svg_canvas canvas(const std::string& title, const std::string& subtitle) const {
    if (x0 > x1) return Svg_canvas({0, 0}, 1, title, subtitle);
    const P2 c{(x0 + x1) / 2, (y0 + y1) / 2};
    double r = 0.5 * std::hypot(x1 - x0, y1 - y0) * 1.35;
    if (!(r > 0)) r = std::max(1.0, std::hypot(c.x, c.y));
    return Svg_canvas(c, r, title, subtitle);
  }
};

Vec2 load_point(const Scene& s) {
  const Load& l = *s.load;
  if (l.kind == Load::Kind::force) return l.at;
  if (l.kind == Load::Kind::gravity && s.body.com) return *s.body.com;
  return {0, 0};
}

void add_scene_bounds(Bounds& b, const Scene& s) {
  for (const Vec2& v : s.body.outline) b.add(to_p2(v));
  if (s.body.com) b.add(to_p2(*s.body.com));
  for (const Contact& stored : s.contacts) {
    if (stored.kind != Contact::Kind::point) continue;
    b.add(to_p2(exact_contact(stored).at));
  }
  if (s.load && s.load->kind != Load::Kind::wrench) b.add(to_p2(load_point(s)));
}

// Body, lines of force, contacts (friction cones or directed normals), load.
void draw_scene(Svg_canvas& c, const Scene& s, const std::vector<Generator>& gens, bool frictionless) {
  const double L = 0.13 * c.world_radius();
  if (s.body.outline.size() >= 2) {
    std::vector<P2> o;
    for (const Vec2& v : s.body.outline) o.push_back(to_p2(v));
    c.polygon(o, "fill=\"#d8d8d8\" fill-opacity=\"0.55\" stroke=\"#333\" stroke-width=\"2\"");
  }
  for (const Generator& g : gens) {
    const P2 f = unit({g.w[0].get_d(), g.w[1].get_d()});
    if (g.w[0] == 0 && g.w[1] == 0) continue;
    // A point of the line of action: p with p × f = m, p = m (f_y, −f_x) / |f|².
    const Rational n2 = g.w[0] * g.w[0] + g.w[1] * g.w[1];
    const P2 p{Rational(g.w[2] * g.w[1] / n2).get_d(), Rational(-g.w[2] * g.w[0] / n2).get_d()};
    c.full_line(p, f, "stroke=\"#777\" stroke-width=\"1\" stroke-dasharray=\"6 4\"");
  }
  for (std::size_t i = 0; i < s.contacts.size(); ++i) {
    const Contact ct = exact_contact(s.contacts[i]);
    if (ct.kind != Contact::Kind::point) continue;
    const P2 p = to_p2(ct.at), n = unit(to_p2(ct.normal));
    const double mu = frictionless ? 0 : ct.mu.get_d();
    if (mu > 0) {
      const P2 t{-n.y, n.x};
      const P2 eL = unit({n.x + mu * t.x, n.y + mu * t.y}), eR = unit({n.x - mu * t.x, n.y - mu * t.y});
      c.polygon({p, {p.x + 1.6 * L * eL.x, p.y + 1.6 * L * eL.y}, {p.x + 1.6 * L * eR.x, p.y + 1.6 * L * eR.y}},
                "fill=\"" + std::string(kCone) + "\" fill-opacity=\"0.55\" stroke=\"" + kCone + "\"");
    }
    c.arrow(p, {p.x + L * n.x, p.y + L * n.y}, "#222", 2.5);
    c.dot(p, 3.5, "fill=\"#222\"");
    c.text(p, "c" + std::to_string(i), "fill=\"#222\"");
  }
  if (s.body.com) {
    c.dot(to_p2(*s.body.com), 5, "fill=\"white\" stroke=\"#222\" stroke-width=\"1.5\"");
  }
  if (s.load) {
    const Vec3q w = load_wrench(s);
    if (w[0] == 0 && w[1] == 0) {
      c.caption("load: a pure moment " + to_string(w[2]));
    } else {
      P2 at = to_p2(load_point(s));
      if (s.load->kind == Load::Kind::wrench) {
        const Rational n2 = w[0] * w[0] + w[1] * w[1];
        at = {Rational(w[2] * w[1] / n2).get_d(), Rational(-w[2] * w[0] / n2).get_d()};
      }
      const P2 f = unit({w[0].get_d(), w[1].get_d()});
      c.arrow(at, {at.x + 1.4 * L * f.x, at.y + 1.4 * L * f.y}, kLoad, 3);
      c.text({at.x + 1.4 * L * f.x, at.y + 1.4 * L * f.y}, "load", "fill=\"" + std::string(kLoad) + "\"");
    }
  }
}

// A + or − region that is only the ± point (concurrent lines of force) is drawn as that point.
bool only_both_point(const Region& r, const Both_set& b) {
  return r.shape == Region::Shape::point && b.kind == Both_set::Kind::point && r.vertices[0].x == b.point.x &&
         r.vertices[0].y == b.point.y;
}

void draw_labels(Svg_canvas& c, const Moment_labels& l) {
  if (!only_both_point(l.plus, l.both)) c.region(l.plus, kPlus, kPlus, "+");
  if (!only_both_point(l.minus, l.both)) c.region(l.minus, kMinus, kMinus, "\u2212");
  switch (l.both.kind) {
    case Both_set::Kind::point:
      c.dot(to_p2(l.both.point), 7, "fill=\"white\" stroke=\"" + std::string(kBoth) + "\" stroke-width=\"3\"");
      c.text(to_p2(l.both.point), "\u00b1", "font-weight=\"bold\"");
      break;
    case Both_set::Kind::line:
      c.full_line(to_p2(l.both.point), to_p2(l.both.direction), "stroke=\"" + std::string(kBoth) + "\" stroke-width=\"3\"");
      break;
    case Both_set::Kind::plane:
    case Both_set::Kind::none:
      break;
  }
  c.infinity_cone(l.infinity, kInfinity);
}

void labels_legend(Svg_canvas& c, const Moment_labels& l, const Scene& s, bool frictionless) {
  if (!l.plus.empty() && !only_both_point(l.plus, l.both)) c.legend(swatch(kPlus), "+ : counter-clockwise rotation centres (every moment >= 0)");
  if (!l.minus.empty() && !only_both_point(l.minus, l.both)) c.legend(swatch(kMinus), "\u2212 : clockwise rotation centres (every moment <= 0)");
  if (l.both.kind == Both_set::Kind::point || l.both.kind == Both_set::Kind::line)
    c.legend(swatch(kBoth, 1), "\u00b1 : every line of force passes through (all moments zero)");
  if (l.infinity.shape != Cone2::Shape::zero)
    c.legend(swatch(kInfinity, 1), "labeled points at infinity (translations), on the rim");
  if (!frictionless) c.legend(swatch(kCone, 0.55), "friction cones; arrows: contact normals");
  else c.legend(swatch("#222", 1), "contact normals (frictionless reading)");
  c.legend("fill=\"none\" stroke=\"#777\" stroke-dasharray=\"6 4\"", "lines of force of the cone's generators");
  if (s.load) c.legend(swatch(kLoad, 1), "load");
}

std::string title_of(const Scene& s, const std::string& source) { return s.name.empty() ? source : s.name; }

const char* kSupport = "#5a5a5a";
const char* kMotion = "#c0392b";

// --what hold: the contacts, the support (each point a disc of radius ∝ its friction μf, hollow where the force is
// unknown), the load, and when the load does not hold, the motion of the certificate's twist: its rotation centre
// (with the sense) or its translation direction.
std::string render_hold(const Scene& s, const Hold_item& h, const std::string& source) {
  const Hold_answer& a = h.answer;
  // The motion of the certificate: the one that breaks the hold, or on the boundary the one the load may slip with.
  const std::optional<Vec3q> motion = a.impending ? std::optional<Vec3q>(a.impending->twist.twist)
                                      : a.failing ? std::optional<Vec3q>(a.failing->twist)
                                                  : std::nullopt;
  Bounds b;
  add_scene_bounds(b, s);
  if (s.support)
    for (const Support_point& p : s.support->points) b.add(to_p2(p.at));
  if (motion && (*motion)[2] != 0)
    b.add({Rational(-(*motion)[1] / (*motion)[2]).get_d(), Rational((*motion)[0] / (*motion)[2]).get_d()});
  const std::string verdict = a.verdict == Hold_verdict::holds       ? "holds (with margin)"
                              : a.verdict == Hold_verdict::impending ? "impending (just held: it may slip)"
                              : a.verdict == Hold_verdict::fails     ? "does not hold"
                              : a.verdict == Hold_verdict::depends   ? "depends on the distribution"
                                                                     : "undecided";
  Svg_canvas c = b.canvas(title_of(s, source), "hold: the contacts and the support's friction against the load");
  const std::vector<Generator> gens = generators(s, Reading::friction);
  draw_scene(c, s, gens, false);
  if (s.support) {
    Rational most;
    for (const Support_point& p : s.support->points) {
      const Rational mu = s.support->mu_of(p);
      if (p.force && mu * *p.force > most) most = mu * *p.force;
    }
    for (std::size_t i = 0; i < s.support->points.size(); ++i) {
      const Support_point& p = s.support->points[i];
      const Rational mu = s.support->mu_of(p);
      const double r = p.force && most > 0 ? 4 + 8 * std::sqrt(Rational(mu * *p.force / most).get_d()) : 6;
      c.dot(to_p2(p.at), r, p.force ? "fill=\"" + std::string(kSupport) + "\" fill-opacity=\"0.5\" stroke=\"#222\""
                                    : "fill=\"none\" stroke=\"" + std::string(kSupport) + "\" stroke-width=\"2\"");
    }
  }
  if (motion) {
    const std::array<Rational, 3>& t = *motion;
    if (t[2] != 0) {
      const P2 ctr{Rational(-t[1] / t[2]).get_d(), Rational(t[0] / t[2]).get_d()};
      c.dot(ctr, 7, "fill=\"white\" stroke=\"" + std::string(kMotion) + "\" stroke-width=\"3\"");
      c.text(ctr, t[2] > 0 ? "\u21ba rotation centre" : "\u21bb rotation centre", "fill=\"" + std::string(kMotion) + "\"");
    } else {
      const P2 d = unit({t[0].get_d(), t[1].get_d()});
      const P2 from = c.centre();
      const double L = 0.3 * c.world_radius();
      c.arrow(from, {from.x + L * d.x, from.y + L * d.y}, kMotion, 4);
      c.text({from.x + L * d.x, from.y + L * d.y}, "translation", "fill=\"" + std::string(kMotion) + "\"");
    }
  }
  c.legend(swatch(kCone, 0.55), "contacts: friction cones; arrows: contact normals");
  if (s.support) c.legend(swatch(kSupport, 0.5), "support points: discs grow with mu*f (hollow: force unknown)");
  if (s.load) c.legend(swatch(kLoad, 1), "load");
  if (motion)
    c.legend(swatch(kMotion, 1), std::string(a.verdict == Hold_verdict::impending ? "the slip the load may start: "
                                                                                  : "the motion of the certificate's twist: ") +
                                     motion_words(*motion));
  c.caption("hold: " + verdict + " (decided by " + decided_by_text(a) + ")");
  if (a.verdict == Hold_verdict::depends)
    c.caption(std::string(a.held_as == Hold_verdict::holds ? "holds" : "just held") + " with f = " +
              distribution_text(a.holding->support.distribution) + "; the motion drawn is the one with f = " +
              distribution_text(a.failing->distribution));
  return c.finish();
}

// The grasp wrench space (render --what quality): three slices through the origin, each the polygon cut from the
// space's supporting planes, with the disc of radius ε — the picture of docs/quality.md.
std::vector<P2> slice(const Quality_answer& a, int fixed, double half) {
  const int i = fixed == 0 ? 1 : 0, j = fixed == 2 ? 1 : 2;
  std::vector<P2> poly = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
  for (const auto& [n, b] : a.planes) {  // clip by n_i x + n_j y <= b (Sutherland–Hodgman)
    const double nx = n[i].get_d(), ny = n[j].get_d(), off = b.get_d();
    std::vector<P2> out;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const P2 p = poly[k], q = poly[(k + 1) % poly.size()];
      const double sp = nx * p.x + ny * p.y - off, sq = nx * q.x + ny * q.y - off;
      if (sp <= 0) out.push_back(p);
      if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
        const double t = sp / (sp - sq);
        out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
      }
    }
    poly = std::move(out);
  }
  return poly;
}

std::string render_quality(const Scene& s, const Quality_item& r, const std::string& source) {
  const Quality_answer& a = r.answer;
  const std::string t = quality_norm_name(a.query.norm);
  Svg_panels pic(title_of(s, source), "the grasp wrench space (" + t + ", forces " + normalization_name(a.query.normalize) +
                                           ", moments times " + to_string(a.query.torque_scale) + ") and its largest ball about the origin",
                 a.closure.holds ? "epsilon = " + decimal_text(a.lower, 6) + ": every wrench in the ball is resisted"
                                 : "not in force closure: epsilon = 0");
  double half = 1;
  for (const Vec3q& p : a.points)
    for (const Rational& x : p) half = std::max(half, 2 * std::abs(x.get_d()));
  if (t == "Linf") half *= static_cast<double>(s.contacts.size());
  const char* names[3] = {"f_x", "f_y", "s*m"};
  for (int fixed : {2, 1, 0}) {
    const int i = fixed == 0 ? 1 : 0, j = fixed == 2 ? 1 : 2;
    const int k = pic.panel(std::string("slice ") + names[fixed] + " = 0", names[i], names[j]);
    if (!a.closure.holds) continue;
    pic.polygon(k, slice(a, fixed, half), "fill=\"#2f6fd0\" fill-opacity=\"0.25\" stroke=\"#2f6fd0\" stroke-width=\"1.5\"");
    pic.circle(k, a.lower.get_d(), "fill=\"#f0a030\" fill-opacity=\"0.45\" stroke=\"#b06a00\"");
  }
  pic.legend_box(0, "fill=\"#2f6fd0\" fill-opacity=\"0.25\" stroke=\"#2f6fd0\"", "the wrench space's slice");
  pic.legend_box(260, "fill=\"#f0a030\" fill-opacity=\"0.45\" stroke=\"#b06a00\"", "the ball of radius epsilon");
  return pic.finish();
}

// The part with the largest region's placements on its two edges (one colour per finger), and the (s, t) squares of
// the largest regions (up to three) with their closure polygons.
// Three fingers: the part once per triple with the largest certified cubes (up to four), each finger's interval of the
// cube on its edge in its colour, a dot at the cube's centre placement and its friction cone's two edges there.
std::string render_grasp_triples(const Scene& s, const Grasp_regions_item& r, const std::string& source) {
  const Grasp_regions& g = r.regions;
  std::vector<const Triple_region*> boxed;
  for (const Triple_region& t : g.triples)
    if (t.box) boxed.push_back(&t);
  std::stable_sort(boxed.begin(), boxed.end(), [](const Triple_region* a, const Triple_region* b) { return a->side > b->side; });
  Svg_panels pic(title_of(s, source), "where three fingers may go: independent cubes of force closure, mu = " + to_string(g.mu),
                 std::to_string(g.boxed_triples()) + " of " + std::to_string(g.triples.size()) + " edge triples with a cube, " +
                     std::to_string(g.never_triples()) + " never close; each finger anywhere in its interval");
  const std::vector<Vec2>& V = s.body.outline;
  const std::string finger[3] = {"#2f6fd0", "#d0602f", "#2f9f5f"};
  std::vector<P2> outline;
  double size = 0;
  for (const Vec2& v : V) outline.push_back(to_p2(v));
  for (const P2& a : outline)
    for (const P2& b : outline) size = std::max(size, std::hypot(a.x - b.x, a.y - b.y));
  if (boxed.empty()) pic.polygon(pic.panel("the part: no cube found", "x", "y"), outline, "fill=\"#e8e8e8\" stroke=\"#444\" stroke-width=\"1.5\"");
  const int orientation = outline_orientation(V);
  for (std::size_t k = 0; k < boxed.size() && k < 4; ++k) {
    const Triple_region& t = *boxed[k];
    const int i = pic.panel("edges " + std::to_string(t.edges[0]) + ", " + std::to_string(t.edges[1]) + ", " +
                                std::to_string(t.edges[2]) + ": cube side " + decimal_text(t.side, 3),
                            "x", "y");
    pic.polygon(i, outline, "fill=\"#e8e8e8\" stroke=\"#444\" stroke-width=\"1.5\"");
    for (int f = 0; f < 3; ++f) {
      const auto& iv = (*t.box)[static_cast<std::size_t>(f)];
      const std::size_t e = t.edges[static_cast<std::size_t>(f)];
      pic.polygon(i, {to_p2(edge_point(V, e, iv[0])), to_p2(edge_point(V, e, iv[1]))},
                  "fill=\"none\" stroke=\"" + finger[f] + "\" stroke-width=\"5\"");
      const P2 c = to_p2(edge_point(V, e, Rational((iv[0] + iv[1]) / 2)));
      const Vec2 n = edge_inward_normal(V, e, orientation), tg{-n.y, n.x};
      for (const int side : {-1, 1}) {  // the cone's edges n ± mu rot90 n, a sixth of the part long
        const double dx = Rational(n.x + side * g.mu * tg.x).get_d(), dy = Rational(n.y + side * g.mu * tg.y).get_d();
        const double len = std::hypot(dx, dy);
        if (len > 0) pic.polygon(i, {c, {c.x + dx / len * size / 6, c.y + dy / len * size / 6}},
                                 "fill=\"none\" stroke=\"" + finger[f] + "\" stroke-width=\"1.2\"");
      }
      pic.polygon(i, {c, {c.x, c.y}}, "fill=\"none\" stroke=\"" + finger[f] + "\" stroke-width=\"7\" stroke-linecap=\"round\"");
    }
  }
  for (int f = 0; f < 3; ++f)
    pic.legend_line(200.0 * f, "stroke=\"" + finger[f] + "\" stroke-width=\"5\"", "finger " + std::to_string(f + 1) + "'s interval");
  return pic.finish();
}

std::string render_grasp_regions(const Scene& s, const Grasp_regions_item& r, const std::string& source) {
  const Grasp_regions& g = r.regions;
  if (g.fingers == 3) return render_grasp_triples(s, r, source);
  std::vector<const Pair_region*> closed;
  for (const Pair_region& p : g.pairs)
    if (!p.polygon.empty()) closed.push_back(&p);
  std::stable_sort(closed.begin(), closed.end(), [](const Pair_region* a, const Pair_region* b) { return a->area > b->area; });
  Svg_panels pic(title_of(s, source), "where two fingers may go: force closure with mu = " + to_string(g.mu) + " (Nguyen)",
                 std::to_string(g.closed_pairs()) + " of " + std::to_string(g.pairs.size()) +
                     " edge pairs close; a finger on edge i at s (0 at vertex i, 1 at vertex i + 1)");
  const std::vector<Vec2>& V = s.body.outline;
  const std::string finger[2] = {"#2f6fd0", "#d0602f"};
  const int part = pic.panel("the part" + std::string(closed.empty() ? "" : ": the largest region's edges"), "x", "y");
  std::vector<P2> outline;
  for (const Vec2& v : V) outline.push_back(to_p2(v));
  pic.polygon(part, outline, "fill=\"#e8e8e8\" stroke=\"#444\" stroke-width=\"1.5\"");
  if (!closed.empty()) {
    const Pair_region& p = *closed.front();
    for (int f = 0; f < 2; ++f) {  // the range of s (t) over the region: each finger's reach on its edge
      Rational lo = 1, hi = 0;
      for (const auto& c : p.polygon) lo = std::min(lo, c[f]), hi = std::max(hi, c[f]);
      const std::size_t e = f == 0 ? p.i : p.j;
      pic.polygon(part, {to_p2(edge_point(V, e, lo)), to_p2(edge_point(V, e, hi))},
                  "fill=\"none\" stroke=\"" + finger[f] + "\" stroke-width=\"5\"");
    }
  }
  for (std::size_t k = 0; k < closed.size() && k < 3; ++k) {
    const Pair_region& p = *closed[k];
    const int i = pic.panel("edges " + std::to_string(p.i) + " and " + std::to_string(p.j) + ": area " + decimal_text(p.area, 3),
                            "s (edge " + std::to_string(p.i) + ")", "t (edge " + std::to_string(p.j) + ")");
    pic.polygon(i, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "fill=\"none\" stroke=\"#888\" stroke-dasharray=\"4 3\"");
    std::vector<P2> poly;
    for (const auto& c : p.polygon) poly.push_back({c[0].get_d(), c[1].get_d()});
    pic.polygon(i, poly, "fill=\"#2f9f5f\" fill-opacity=\"0.35\" stroke=\"#2f9f5f\" stroke-width=\"1.5\"");
  }
  pic.legend_line(0, "stroke=\"" + finger[0] + "\" stroke-width=\"5\"", "finger 1's reach");
  pic.legend_line(200, "stroke=\"" + finger[1] + "\" stroke-width=\"5\"", "finger 2's reach");
  pic.legend_box(400, "fill=\"#2f9f5f\" fill-opacity=\"0.35\" stroke=\"#2f9f5f\"", "force closure in (s, t)");
  return pic.finish();
}


// The body's motion of a decided contact mode (PU-2), from the brackets' midpoints: its rotation centre
// (rotation_centre: a support point exactly for a pivot) and rate, or, when it translates, its velocity at the pusher;
// none when not decided or not bracketed.
struct Push_motion {
  double omega = 0;
  std::optional<P2> centre;  // ω ≠ 0
  P2 u;                      // the velocity at the pusher (the pusher's, plus the slip along its face)
  bool exact_pivot = false;
};
std::optional<Push_motion> push_motion(const Scene& s, const Push_answer& a) {
  if (!a.contact) return std::nullopt;
  const Push_contact& k = *a.contact;
  const bool sticks = k.mode == Push_mode::sticks || k.mode == Push_mode::impending;
  if (!sticks && !((k.mode == Push_mode::slides_left || k.mode == Push_mode::slides_right) && k.has_motion))
    return std::nullopt;
  const Rational tau = sticks ? Rational(0) : Rational((k.slip_lo + k.slip_hi) / 2);
  const Rational w = sticks ? Rational((k.omega_lo + k.omega_hi) / 2) : Rational((k.motion_lo + k.motion_hi) / 2);
  const Vec2 u{a.velocity.x - tau * a.normal.y, a.velocity.y + tau * a.normal.x};  // v + τ·rot90(n)
  const std::optional<std::size_t> pivot = sticks ? k.pivot : k.motion_pivot;
  Push_motion m;
  m.omega = w.get_d(), m.u = to_p2(u), m.exact_pivot = pivot.has_value();
  if (w != 0) m.centre = to_p2(pivot ? s.support->points[*pivot].at : rotation_centre(a.at, u, w));
  return m;
}

// --what push: the body, its support (discs ∝ μf, hollow where the force is unknown; regions shaded), the centre of
// friction, the pusher with its friction cone and velocity, and the three voting lines through it — blue where the
// line votes ccw (c on its left), red cw, black dashed through c — as in Mason's figures of the voting theorem. With
// the contact mode (--contact): where the body turns — its rotation centre p + rot90(u)/ω, marked ↺ or ↻, or the
// direction it translates — and the mode in the caption.
std::string render_push(const Scene& s, const Push_item& r, const std::string& source) {
  const Push_answer& a = r.push;
  const std::optional<Push_motion> motion = push_motion(s, a);
  Bounds b;
  add_scene_bounds(b, s);
  b.add(to_p2(a.at));
  if (s.pusher->end) b.add(to_p2(*s.pusher->end));
  for (const Support_point& p : s.support->points) b.add(to_p2(p.at));
  for (const Support_region& g : s.support->regions)
    for (const Vec2& v : g.outline) b.add(to_p2(v));
  if (a.center) b.add(to_p2(*a.center));
  if (a.locus)  // the rotation centres' bounded pieces (PU-4) in view
    for (const Locus_side& side : a.locus->side)
      for (const Locus_piece& piece : side.pieces)
        if (piece.bounded)
          for (const Vec2& v : piece.polygon) b.add(to_p2(v));
  if (a.region && a.center)  // a line pusher's stable region: each side's vertex nearest the centre of friction in view
    for (const Stable_region_side& side : a.region->side) {
      std::optional<P2> near;
      const P2 ctr = to_p2(*a.center);
      for (const Vec2& v : side.polygon)
        if (const P2 x = to_p2(v); !near || std::hypot(x.x - ctr.x, x.y - ctr.y) < std::hypot(near->x - ctr.x, near->y - ctr.y))
          near = x;
      if (near) b.add(*near);
    }
  // the rotation centre, in the picture when it is within a few body sizes (else the caption gives it)
  const std::optional<P2> centre = motion                      ? motion->centre
                                   : a.stable && a.stable->centre ? std::optional<P2>(to_p2(*a.stable->centre))
                                                                  : std::nullopt;  // (a line pusher's rotation centre)
  bool centre_shown = false;
  if (centre) {
    const double size = std::max(b.x1 - b.x0, b.y1 - b.y0);
    centre_shown = std::hypot(centre->x - (b.x0 + b.x1) / 2, centre->y - (b.y0 + b.y1) / 2) <= 3 * size;
    if (centre_shown) b.add(*centre);
  }
  Svg_canvas c = b.canvas(title_of(s, source), a.stable ? "push: does the body stay with the line pusher, for every pressure distribution"
                                                        : "push: which way the body turns, for every pressure distribution");
  if (s.body.outline.size() >= 2) {
    std::vector<P2> o;
    for (const Vec2& v : s.body.outline) o.push_back(to_p2(v));
    c.polygon(o, "fill=\"#d8d8d8\" fill-opacity=\"0.55\" stroke=\"#333\" stroke-width=\"2\"");
  }
  for (const Support_region& g : s.support->regions) {
    std::vector<P2> o;
    for (const Vec2& v : g.outline) o.push_back(to_p2(v));
    c.polygon(o, swatch(kSupport, 0.25));
  }
  Rational most;
  for (const Support_point& p : s.support->points) {
    const Rational mu = s.support->mu_of(p);
    if (p.force && mu * *p.force > most) most = mu * *p.force;
  }
  for (const Support_point& p : s.support->points) {
    const Rational mu = s.support->mu_of(p);
    const double rad = p.force && most > 0 ? 4 + 8 * std::sqrt(Rational(mu * *p.force / most).get_d()) : 6;
    c.dot(to_p2(p.at), rad, p.force ? "fill=\"" + std::string(kSupport) + "\" fill-opacity=\"0.5\" stroke=\"#222\""
                                    : "fill=\"none\" stroke=\"" + std::string(kSupport) + "\" stroke-width=\"2\"");
  }
  const double L = 0.13 * c.world_radius();
  // the verdicts and their reasons, in lines that fit the page
  const auto captions = [&c](const std::string& text) {
    std::string line;
    std::istringstream words(text);
    for (std::string w; words >> w;) {
      if (!line.empty() && line.size() + w.size() > 85) c.caption(line), line = " ";
      line += (line.empty() ? "" : " ") + w;
    }
    c.caption(line);
  };
  if (a.stable) {  // a line pusher (PU-3): the segment, the friction cone at both ends, its motion, the verdict
    const Stable_push& st = *a.stable;
    if (a.region)  // the stable region: the rotation centres certified stable, ccw and cw (within the picture)
      for (int k = 0; k < 2; ++k) {
        std::vector<P2> poly;
        for (const Vec2& v : a.region->side[k].polygon) poly.push_back(to_p2(v));
        if (poly.size() >= 3)
          c.polygon(poly, "fill=\"" + std::string(k == 0 ? kPlus : kMinus) + "\" fill-opacity=\"0.18\" stroke=\"" +
                              (k == 0 ? kPlus : kMinus) + "\" stroke-width=\"1\"");
      }
    const P2 e0 = to_p2(a.at), e1 = to_p2(*s.pusher->end), n = unit(to_p2(a.normal)), t{-n.y, n.x};
    const double mu = a.mu.get_d(), len = std::min(1.6 * L, 1.2 * std::hypot(e1.x - e0.x, e1.y - e0.y));
    for (const P2& e : {e0, e1}) {  // (as long as the segment at most: a fence's cones stay beside it)
      const P2 eL = unit({n.x + mu * t.x, n.y + mu * t.y}), eR = unit({n.x - mu * t.x, n.y - mu * t.y});
      c.polygon({e, {e.x + len * eL.x, e.y + len * eL.y}, {e.x + len * eR.x, e.y + len * eR.y}},
                "fill=\"" + std::string(kCone) + "\" fill-opacity=\"0.55\" stroke=\"" + kCone + "\"");
    }
    c.line(e0, e1, "stroke=\"#222\" stroke-width=\"5\"");
    const P2 m{(e0.x + e1.x) / 2, (e0.y + e1.y) / 2}, vel = unit(to_p2(a.velocity));
    c.arrow({m.x - len * vel.x, m.y - len * vel.y}, m, kLoad, 3);
    c.text(e0, "end 0", "fill=\"#222\"");
    c.text(e1, "end 1", "fill=\"#222\"");
    if (a.center) {
      const P2 ctr = to_p2(*a.center);
      c.dot(ctr, 6, "fill=\"white\" stroke=\"#222\" stroke-width=\"2\"");
      c.text(ctr, "centre of friction", "fill=\"#222\"");
    }
    const char* kMotion = "#7b3fa0";
    if (centre_shown) {  // (else the caption gives it)
      const P2 q = *centre;
      c.line(m, q, "stroke=\"" + std::string(kMotion) + "\" stroke-width=\"1\" stroke-dasharray=\"2 4\"");
      c.dot(q, 6, "fill=\"" + std::string(kMotion) + "\" stroke=\"#222\"");
      c.text(q, std::string("the pusher's rotation centre ") + (st.sense > 0 ? "\u21ba" : "\u21bb"),
             "fill=\"" + std::string(kMotion) + "\"");
    }
    for (std::size_t k = 0; k < st.points.size(); ++k)  // an unstable push's witness distribution
      c.dot(to_p2(st.points[k]), 9, "fill=\"none\" stroke=\"" + std::string(kMinus) + "\" stroke-width=\"3\"");
    c.legend(swatch(kCone, 0.55), "the friction cone at each end of the line contact; green: its velocity");
    c.legend(swatch(kSupport, 0.5), "support: discs grow with mu*f (hollow: force unknown)");
    if (centre_shown) c.legend("stroke=\"" + std::string(kMotion) + "\" fill=\"" + kMotion + "\"", "the pusher's rotation centre");
    if (!st.points.empty())
      c.legend("stroke=\"" + std::string(kMinus) + "\" fill=\"none\"", "a distribution with the centre of friction that breaks the contact");
    if (a.region) {
      c.legend(swatch(kPlus, 0.18), "rotation centres certified stable turning ccw (PU-3: an inner region)");
      c.legend(swatch(kMinus, 0.18), "rotation centres certified stable turning cw");
    }
    std::string motion = " (the pusher translates)";
    if (st.centre) {
      char at[96];
      std::snprintf(at, sizeof at, " (the pusher turns %s about (%.4g, %.4g))", st.sense > 0 ? "ccw" : "cw",
                    st.centre->x.get_d(), st.centre->y.get_d());
      motion = at;
    }
    captions("stable: " + std::string(stability_name(st.verdict)) + motion + " \u2014 " + st.why);
    captions("rotation: " + std::string(rotation_name(a.rotation)) + " \u2014 " + a.why);
    return c.finish();
  }
  if (a.locus && a.locus->friction_centre) {  // where the body may turn about (PU-4): per sense, the three pieces
    for (int k = 0; k < 2; ++k)
      for (const Locus_piece& piece : a.locus->side[k].pieces) {
        std::vector<P2> poly;
        for (const Vec2& v : piece.polygon) poly.push_back(to_p2(v));
        const std::string col = k == 0 ? kPlus : kMinus;
        const char* dash = piece.mode == Locus_mode::slides_left ? " stroke-dasharray=\"6 3\""
                           : piece.mode == Locus_mode::slides_right ? " stroke-dasharray=\"2 3\"" : "";
        if (poly.size() >= 3)
          c.polygon(poly, "fill=\"" + col + "\" fill-opacity=\"" + (piece.bounded ? "0.16" : "0.07") + "\" stroke=\"" +
                              col + "\" stroke-width=\"1.5\"" + dash);
        else if (poly.size() == 2)
          c.line(poly[0], poly[1], "stroke=\"" + col + "\" stroke-width=\"5\" stroke-opacity=\"0.7\"");
        else if (poly.size() == 1)
          c.dot(poly[0], 5, "fill=\"" + col + "\"");
      }
  }
  const P2 p = to_p2(a.at), n = unit(to_p2(a.normal));
  const std::string colour[3] = {kMinus, kBoth, kPlus};  // cw, through, ccw
  for (const Push_vote& v : a.votes) {
    if (!a.votes_known) break;
    const std::optional<int> sign = v.sign();
    const std::string col = sign ? colour[*sign + 1] : std::string(kInfinity);
    const std::string dash = v.line == Push_line::velocity ? "" : " stroke-dasharray=\"8 5\"";
    c.full_line(p, unit(to_p2(v.direction)), "stroke=\"" + col + "\" stroke-width=\"1.5\"" + dash);
  }
  const double mu = a.mu.get_d();
  if (mu > 0) {
    const P2 t{-n.y, n.x};
    const P2 eL = unit({n.x + mu * t.x, n.y + mu * t.y}), eR = unit({n.x - mu * t.x, n.y - mu * t.y});
    c.polygon({p, {p.x + 1.6 * L * eL.x, p.y + 1.6 * L * eL.y}, {p.x + 1.6 * L * eR.x, p.y + 1.6 * L * eR.y}},
              "fill=\"" + std::string(kCone) + "\" fill-opacity=\"0.55\" stroke=\"" + kCone + "\"");
  }
  const P2 vel = unit(to_p2(a.velocity));
  c.arrow({p.x - 1.5 * L * vel.x, p.y - 1.5 * L * vel.y}, p, kLoad, 3);
  c.dot(p, 4, "fill=\"#222\"");
  c.text(p, "pusher", "fill=\"#222\"");
  if (a.center) {
    const P2 ctr = to_p2(*a.center);
    c.dot(ctr, 6, "fill=\"white\" stroke=\"#222\" stroke-width=\"2\"");
    const std::string turn = a.rotation == Rotation::ccw ? " \u21ba" : a.rotation == Rotation::cw ? " \u21bb" : "";
    c.text(ctr, "centre of friction" + turn, "fill=\"#222\"");
  }
  c.legend("stroke=\"" + std::string(kPlus) + "\" fill=\"" + kPlus + "\"", "a line that votes ccw (the centre of friction on its left)");
  c.legend("stroke=\"" + std::string(kMinus) + "\" fill=\"" + kMinus + "\"", "a line that votes cw; black: through the centre");
  if (!a.center) c.legend("stroke=\"" + std::string(kInfinity) + "\" fill=\"" + kInfinity + "\"", "a vote that changes with the distribution");
  c.legend(swatch(kCone, 0.55), "the pusher's friction cone (dashed lines: its edges); green: its velocity");
  c.legend(swatch(kSupport, 0.5), "support: discs grow with mu*f (hollow: force unknown)");
  if (motion) {  // the body's motion: its rotation centre (exactly a support point for a pivot), or its direction
    const char* kMotion = "#7b3fa0";
    const std::string turn = motion->omega > 0 ? " \u21ba" : motion->omega < 0 ? " \u21bb" : "";
    if (centre && std::isfinite(centre->x) && std::isfinite(centre->y)) {
      c.line(to_p2(a.at), *centre, "stroke=\"" + std::string(kMotion) + "\" stroke-width=\"1\" stroke-dasharray=\"2 4\"");
      c.dot(*centre, 6, "fill=\"" + std::string(kMotion) + "\" stroke=\"#222\"");
      c.text(*centre, std::string(motion->exact_pivot ? "pivot: rotation centre" : "rotation centre") + turn,
             "fill=\"" + std::string(kMotion) + "\"");
    } else if (a.center) {  // a translation: its direction from the centre of friction
      const P2 ctr = to_p2(*a.center), d = unit(motion->u);
      c.arrow(ctr, {ctr.x + 1.5 * L * d.x, ctr.y + 1.5 * L * d.y}, kMotion, 2);
    }
    c.legend("stroke=\"" + std::string(kMotion) + "\" fill=\"" + kMotion + "\"",
             "the body's motion: its rotation centre (sticking: with the pusher), or its direction");
  }
  if (a.rotation == Rotation::depends) {  // where c is under the two witnesses
    for (int k = 0; k < 2; ++k) {
      const P2 ctr = to_p2(friction_center(*s.support, k == 0 ? a.turns_ccw : a.turns_cw));
      c.dot(ctr, 5, "fill=\"white\" stroke=\"" + std::string(k == 0 ? kPlus : kMinus) + "\" stroke-width=\"2\"");
      c.text(ctr, k == 0 ? "c under the forces that turn it \u21ba" : "c under the forces that turn it \u21bb",
             "fill=\"" + std::string(k == 0 ? kPlus : kMinus) + "\"");
    }
  }
  if (a.locus && a.locus->friction_centre) {
    c.legend(swatch(kPlus, 0.7), "where it may turn ccw, every distribution (PU-4): sticking, on the thick segment");
    c.legend(swatch(kPlus, 0.16), "... sliding on the left edge (dashed) or the right edge (dotted); red: cw");
  }
  captions("rotation: " + std::string(rotation_name(a.rotation)) + " \u2014 " + a.why);
  if (a.locus && !a.locus->friction_centre) captions("rotation centres: not answered \u2014 " + a.locus->why);
  if (a.locus && a.locus->friction_centre)
    captions(a.locus->arm_hi ? "rotation centres: within " + decimal_text(*a.locus->arm_hi, 4) +
                                   " of the pusher's normal line \u2014 the body turns at least 1 radian per " +
                                   decimal_text(*a.locus->arm_hi, 4) + " the pusher advances"
                             : "rotation centres: " + a.locus->arm_why);
  if (a.contact) {
    const Push_contact& k = *a.contact;
    std::string mode = "contact: " + std::string(push_mode_name(k.mode));
    if (motion && centre) {
      char at[96];
      std::snprintf(at, sizeof at, " \u2014 the body turns %s about (%.4g, %.4g)%s", motion->omega > 0 ? "ccw" : "cw",
                    centre->x, centre->y, motion->exact_pivot ? ", a support point (exactly)" : "");
      mode += at;
      if (k.pivot && k.mode != Push_mode::sticks) mode += " (sliding from the facet of support point " + std::to_string(*k.pivot) + ")";
    } else if (motion) {
      mode += " \u2014 the body translates";
    } else if (k.mode == Push_mode::undecided) {
      mode += " \u2014 " + k.why;
    }
    captions(mode);
  }
  return c.finish();
}

}  // namespace

std::string render_svg(const Options& o, const std::string& text, const std::string& source, bool* undecided) {
  if (!o.what) throw Usage_error("render needs --what labels|dual|reuleaux|limit-surface|hold|quality|grasp-regions|push");
  const Picture what = *o.what;
  if (o.sides && what != Picture::limit_surface) throw Usage_error("--sides goes with --what limit-surface");
  if (o.push.contact && what != Picture::push) throw Usage_error("--contact goes with --what push");
  if (o.push.region && what != Picture::push) throw Usage_error("--region goes with --what push");
  if (o.push.locus && what != Picture::push) throw Usage_error("--locus goes with --what push");
  const Scene s = read_scene(text, o.limits, source);
  if (what == Picture::hold) {
    const Hold_item h = answered(answer_hold(text, source, request_of(o)));
    if (undecided) *undecided = h.answer.verdict == Hold_verdict::undecided;
    return render_hold(s, h, source);
  }
  if (what == Picture::limit_surface) return render_limit_surface_svg(s, o.sides.value_or(32));
  if (what == Picture::grasp_regions)
    return render_grasp_regions(s, answered(answer_grasp_regions(text, source, request_of(o), o.regions)), source);
  if (what == Picture::push) {
    const Push_item r = answered(answer_push(text, source, request_of(o), o.push));
    if (undecided)
      *undecided = r.push.stable ? r.push.stable->verdict == Stability::undecided : r.push.rotation == Rotation::undecided;
    return render_push(s, r, source);
  }
  if (what == Picture::quality) {
    Quality_query q = o.quality;
    q.critical_mu = false;
    q.keep_planes = true;
    return render_quality(s, answered(answer_quality(text, source, request_of(o), q)), source);
  }
  const bool frictionless = what == Picture::reuleaux;
  const std::vector<Generator> gens = generators(s, frictionless ? Reading::frictionless : Reading::friction);
  std::vector<Vec3q> ws;
  for (const Generator& g : gens) ws.push_back(g.w);
  const Moment_labels l = moment_labels(ws);
  if (what == Picture::labels || what == Picture::reuleaux) {
    Bounds b;
    add_scene_bounds(b, s);
    b.add(l.plus);
    b.add(l.minus);
    if (l.both.kind != Both_set::Kind::none && l.both.kind != Both_set::Kind::plane) b.add(to_p2(l.both.point));
    Svg_canvas c = b.canvas(title_of(s, source), frictionless ? "Reuleaux's method: the contacts read frictionless"
                                                              : "moment labels of the contact wrench cone");
    draw_labels(c, l);
    draw_scene(c, s, gens, frictionless);
    labels_legend(c, l, s, frictionless);
    const bool closed = l.cone.force_closure();
    c.caption(frictionless ? std::string("first-order form closure: ") + (closed ? "yes" : "no")
                           : std::string("force closure: ") + (closed ? "yes (nothing labeled)" : "no"));
    if (l.both.kind == Both_set::Kind::plane) c.caption("no contact wrench: every point is labeled \u00b1");
    return c.finish();
  } else {
    const Force_dual d = force_dual(l, ws);
    Bounds b;
    b.add({0, 0});
    b.add(d.plus_sheet);
    b.add(d.minus_sheet);
    for (const Dual_point& p : d.generators)
      if (p.sheet == '+' || p.sheet == '-') b.add(to_p2(p.at));
    if (s.load) {
      const Vec3q w = load_wrench(s);
      const Dual_point a = dual_point({-w[0], -w[1], -w[2]});
      if (a.sheet == '+' || a.sheet == '-') b.add(to_p2(a.at));
    }
    Svg_canvas c = b.canvas(title_of(s, source), "force dual of the contact wrench cone on the two-sided plane");
    c.region(d.plus_sheet, kPlus, kPlus, "+ sheet");
    c.region(d.minus_sheet, kMinus, kMinus, "\u2212 sheet");
    c.infinity_cone(d.infinity, kInfinity);
    c.dot({0, 0}, 3, "fill=\"#222\"");
    c.text({0, 0}, "O");
    bool generator_at_infinity = false;
    for (std::size_t i = 0; i < d.generators.size(); ++i) {
      const Dual_point& p = d.generators[i];
      generator_at_infinity |= p.sheet == 'i';
      const std::string name = "c" + std::to_string(gens[i].contact) + (gens[i].edge == Edge::left ? "L" : gens[i].edge == Edge::right ? "R" : "");
      if (p.sheet == 'i') {
        c.infinity_dot(to_p2(p.at), "#222");
      } else if (p.sheet == '+') {
        c.dot(to_p2(p.at), 5, "fill=\"" + std::string(kPlus) + "\" stroke=\"#222\"");
        c.text(to_p2(p.at), name);
      } else {
        c.dot(to_p2(p.at), 5, "fill=\"white\" stroke=\"" + std::string(kMinus) + "\" stroke-width=\"2\"");
        c.text(to_p2(p.at), name + "\u2032");
      }
    }
    if (s.load) {
      const Vec3q w = load_wrench(s);
      const Dual_point a = dual_point({-w[0], -w[1], -w[2]});
      if (a.sheet == '0') {
        c.caption("load: zero");
      } else if (a.sheet == 'i') {
        c.infinity_dot(to_p2(a.at), kLoad);
      } else {
        c.dot(to_p2(a.at), 7, "fill=\"" + std::string(kLoad) + "\" stroke=\"#111\"");
        c.text(to_p2(a.at), std::string("\u2212load"), "fill=\"" + std::string(kLoad) + "\"");
      }
    }
    if (!d.plus_sheet.empty()) c.legend(swatch(kPlus), "front (+) sheet of the dual polygon: wrenches with m > 0 (filled dots)");
    if (!d.minus_sheet.empty()) c.legend(swatch(kMinus), "back (\u2212) sheet: wrenches with m < 0, drawn where they sit (hollow dots)");
    if (d.infinity.shape != Cone2::Shape::zero) c.legend(swatch(kInfinity, 1), "points at infinity of the polygon: forces through the origin O");
    if (generator_at_infinity)
      c.legend(swatch("#222", 1), "black dots on the rim: generators through O (m = 0), their dual points at infinity");
    if (s.load) c.legend(swatch(kLoad, 1), "antipode of the load: balanced iff it lies in the polygon");
    c.caption(std::string("covers the whole two-sided plane: ") + (d.covers_all ? "yes (force closure)" : "no"));
    c.caption("a wrench (fx, fy, m) is the point D(w) = (\u2212fy, fx, m): (\u2212fy/m, fx/m) on the sheet of sign m");
    if (s.load) {
      const Vec3q w = load_wrench(s);
      c.caption(std::string("load balanced: ") + (in_cone(l.cone, {-w[0], -w[1], -w[2]}) ? "yes" : "no"));
    }
    return c.finish();
  }
}

int run_render(const Options& o, const std::string& text, const std::string& source) {
  bool undecided = false;  // the hold picture of an undecided answer: drawn, and exit 3 like every undecided answer
  const std::string svg = render_svg(o, text, source, &undecided);
  if (!o.output.empty()) write_file(o.output, svg);
  else std::cout << svg;
  return undecided ? kUndecided : kAnswered;
}

}  // namespace wrenchkit::cli
