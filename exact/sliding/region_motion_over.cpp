#include "exact/sliding/region_motion_over.h"

#include <stdexcept>
#include <utility>

#include "exact/sliding/motion_certificate.h"

namespace wrenchkit {

namespace {


// The support with the points' forces f (a distribution of F): the known-forces question over the regions.
Support with_forces(const Support& s, const std::vector<Rational>& f) {
  Support t = s;
  for (std::size_t i = 0; i < t.points.size(); ++i) t.points[i].force = f[i];
  return t;
}

// [RG-3] Does q prove "slides for every distribution"? q·p ≥ max_F Σ μ_i f_i u_i (the LP over F, with its dual) plus
// the regions' slide blocks, refined within max_cells until their bound fits the slack. Exact; fills r on success.
bool slides_for_every_regions(const Support& s, const Admissible& a, const Vec3q& p, const Vec3q& q,
                              std::size_t max_cells, Region_motion_over& r) {
  if (q[0] == 0 && q[1] == 0 && q[2] == 0) return false;
  const Rational power = dot(q, p);
  std::vector<Rational> u = speed_bounds(s, q);
  std::vector<Rational> coef(s.points.size());
  for (std::size_t i = 0; i < coef.size(); ++i) coef[i] = s.mu_of(s.points[i]) * u[i];
  const F_optimum o = maximise_over(s, a, coef);
  if (o.value > power) return false;
  Region_slide_blocks b = region_slide_blocks(s, q, Rational(power - o.value), max_cells);
  if (!b.ok || o.value + b.bound > power) return false;
  r.over.separating_twist = q;
  r.speed_bounds = std::move(u);
  r.dual = o.dual;
  r.slide_blocks = std::move(b.blocks);
  r.cells = b.cells;
  return true;
}

// A distribution of F that sticks on the regions' coarse cells as support points with their forces given (each cell
// carries F_k at its pressure centroid, so the cells have the regions' force and moment and F is the same; their
// limit surface is inside the regions', RG-1): the exact LP over F × inscribed N-gons (closed), then a strict stick
// witness with that distribution fixed; its cells' forces become the regions' stick blocks.
bool stick_over_cells(const Support& s, const Admissible& a, const Vec3q& p, Region_motion_over& r) {
  Support aug = s;
  aug.regions.clear();
  Admissible b = a;
  std::vector<Region_cells> cells;
  for (const Support_region& g : s.regions) {
    cells.push_back(region_cells(g, 1));
    for (Support_point& c : cell_points(g, s.mu_of(g), cells.back())) {
      b.given.push_back(*c.force);
      aug.points.push_back(std::move(c));
    }
  }
  const std::size_t k = s.points.size();
  for (int n = 8; n <= 256 && aug.points.size() * static_cast<std::size_t>(n) <= 1024; n *= 2) {
    const std::optional<Stick_witness> some = stick_witness(aug, b, p, n);
    if (!some) continue;
    const std::optional<Stick_witness> w = stick_witness_refined(aug, b, p, n, some->distribution);
    if (!w) continue;
    const auto at = [](const auto& v, std::size_t i) { return v.begin() + static_cast<std::ptrdiff_t>(i); };
    r.sticking_distribution.emplace(at(w->distribution, 0), at(w->distribution, k));
    Region_motion m;
    m.motion = Motion::sticks;
    m.support_forces.assign(at(w->forces, 0), at(w->forces, k));
    std::size_t next = k;
    for (Region_cells& c : cells) {
      Region_stick_block blk{std::move(c), {}};
      blk.forces.assign(at(w->forces, next), at(w->forces, next + blk.cells.triangles.size()));
      next += blk.cells.triangles.size();
      m.cells += blk.cells.triangles.size();
      m.stick_blocks.push_back(std::move(blk));
    }
    r.over.sticking = Stick_witness{*r.sticking_distribution, m.support_forces};
    r.sticking = std::move(m);
    return true;
  }
  return false;
}

// The certificate (format 2, certificate-format.md §6.5).
std::string certificate_of(const Vec3q& p, const Region_motion_over& r, const std::vector<std::vector<Rational>>& v) {
  const Motion_over_f& o = r.over;
  Json_writer w = motion_certificate_head(p, motion_over_name(o.motion), 2);
  const auto witness = [&w](const std::vector<Rational>& f, const Region_motion& m) {
    w.object().key("distribution").rationals(f);
    write_region_witness_members(w, m);
    w.end_object();
  };
  if (o.motion == Motion_over::sticks) {
    w.key("vertices").array();
    for (std::size_t i = 0; i < v.size(); ++i) witness(v[i], r.per_vertex[i]);
    w.end_array();
  } else if (o.motion == Motion_over::slides) {
    w.key("twist").rationals(*o.separating_twist).key("speed_bounds").rationals(r.speed_bounds);
    w.key("dual").rationals(r.dual).key("regions").array();
    for (const Region_slide_block& b : r.slide_blocks) write_region_slide_block(w, b);
    w.end_array();
  } else {
    w.key("sticking");
    if (r.sticking) witness(*r.sticking_distribution, *r.sticking);
    else witness(v[*o.sticking_vertex], r.per_vertex[*o.sticking_vertex]);
    w.key("sliding");
    witness(v[*o.sliding_vertex], r.per_vertex[*o.sliding_vertex]);
  }
  return w.end_object().take();
}

}  // namespace

Region_motion_over decide_region_motion_over(const Support& s, const Admissible& a, const Vec3q& p,
                                             const std::vector<std::vector<Rational>>& v) {
  if (s.regions.empty() || a.known()) throw std::invalid_argument("decide_region_motion_over: needs regions and an unknown force");
  Region_motion_over r;
  Motion_over_f& o = r.over;
  std::vector<Vec3q> twists;  // the sliding vertices' twists: candidates for step 2
  for (std::size_t i = 0; i < v.size(); ++i) {
    r.per_vertex.push_back(decide_region_motion(with_forces(s, v[i]), p));
    const Region_motion& m = r.per_vertex.back();
    r.per_vertex.back().certificate.clear();  // format 1 of one distribution: not this claim's certificate
    o.per_vertex.push_back(m.motion);
    if (m.motion == Motion::sticks && !o.sticking_vertex) o.sticking_vertex = i;
    if (m.motion == Motion::slides && !o.sliding_vertex) o.sliding_vertex = i;
    if (m.twist) twists.push_back(*m.twist);
  }
  bool all_stick = true, all_slide = true;
  for (const Motion m : o.per_vertex) {
    all_stick &= m == Motion::sticks;
    all_slide &= m == Motion::slides;
  }
  const auto done = [&](Motion_over verdict, const char* by) {
    o.motion = verdict;
    o.decided_by = by;
    if (verdict == Motion_over::sticks)
      for (const Region_motion& m : r.per_vertex) r.cells += m.cells;
    if (verdict == Motion_over::depends)
      r.cells = (r.sticking ? r.sticking->cells : r.per_vertex[*o.sticking_vertex].cells) +
                r.per_vertex[*o.sliding_vertex].cells;
    r.certificate = certificate_of(p, r, v);
    return r;
  };
  if (o.sticking_vertex && o.sliding_vertex) return done(Motion_over::depends, "vertices");
  if (all_stick) return done(Motion_over::sticks, "vertices");
  if (!all_slide) {  // some vertex undecided and none of the other kind
    o.decided_by = "none";
    for (std::size_t i = 0; i < v.size(); ++i)
      if (o.per_vertex[i] == Motion::undecided) {
        o.undecided_why = "extreme distribution " + std::to_string(i + 1) + " of " + std::to_string(v.size()) +
                          " is undecided: " + r.per_vertex[i].undecided_why;
        break;
      }
    return r;
  }
  // Every vertex slides: one twist for all of F. The vertices' twists (their sum first) with a small budget of cells,
  // then the search's twist with the whole budget.
  if (twists.size() > 1) {
    Vec3q sum{};
    for (const Vec3q& q : twists)
      for (std::size_t c = 0; c < 3; ++c) sum[c] += q[c];
    twists.insert(twists.begin(), sum);
  }
  for (const Vec3q& q : twists)
    if (slides_for_every_regions(s, a, p, q, 500, r)) return done(Motion_over::slides, "twist");
  // The search (unknown_motion.h) with the regions' power, the same for every distribution, added.
  std::vector<double> mu_r;
  for (const Support_region& g : s.regions) mu_r.push_back(s.mu_of(g).get_d());
  const auto regions_power = [&](const double* q) {
    double h = 0;
    for (std::size_t g = 0; g < s.regions.size(); ++g)
      if (mu_r[g] != 0) h += mu_r[g] * region_power_double(s.regions[g], q);
    return h;
  };
  if (const auto q = union_search(s, v, p, twists.empty() ? nullptr : &twists.front(), regions_power))
    if (slides_for_every_regions(s, a, p, *q, kMaxRegionCells, r)) return done(Motion_over::slides, "twist");
  if (stick_over_cells(s, a, p, r)) return done(Motion_over::depends, "lp");
  o.decided_by = "none";
  o.undecided_why = "every extreme distribution slides, no twist tried separates the load from the union of the limit "
                    "surfaces (the regions' slide blocks with up to " + std::to_string(kMaxRegionCells) +
                    " cells and the LP over the distributions), and no distribution holds it on the regions' coarse "
                    "cells (inscribed polygons of up to 256 sides): the load is near the boundary of that union";
  return r;
}

}  // namespace wrenchkit
