// [SL-1] [SL-3] [RG-1] [RG-3] The one decision of "does the load stick or slide?" (exact/sliding/motion.h): every force
// given — points by their verdict and then their witness, regions by their cells; some force not given — one
// skeleton over the vertices of F for points and regions alike.
#include "exact/sliding/motion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "exact/io/support_check.h"
#include "exact/sliding/strategies.h"

namespace wrenchkit {

Support_model::Support_model(const Scene& scene) : support_(&*scene.support), admissible_(admissible_set(scene)) {}

Support_model::Support_model(const Support& support, Admissible admissible)
    : support_(&support), admissible_(std::move(admissible)) {}

const std::vector<std::vector<Rational>>& Support_model::extreme() const {
  if (!extreme_) extreme_ = vertices(*support_, admissible_);
  return *extreme_;
}

const char* decided_by_name(Decided_by d) {
  switch (d) {
    case Decided_by::none: return "none";
    case Decided_by::float_search: return "float";
    case Decided_by::polygons: return "polygons";
    case Decided_by::newton: return "newton";
    case Decided_by::flat: return "flat";
    case Decided_by::certificate: return "certificate";
    case Decided_by::vertices: return "vertices";
    case Decided_by::twist: return "twist";
    case Decided_by::minimax: return "minimax";
    case Decided_by::lp: return "lp";
    case Decided_by::lp_over_f: return "lp over F";
    case Decided_by::zero_load: return "zero load";
    case Decided_by::equilibrium: return "equilibrium";
    case Decided_by::smoothed_witness: return "smoothed witness";
  }
  return "?";
}

namespace {

constexpr double kPi = 3.141592653589793;

// A relative gap for a sentence (two significant digits; text only, never a predicate).
std::string gap_text(double g) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2g", g);
  return b;
}

const char* const kNoWitness =
    ", but no rational witness was found (the load is too close to the limit surface for the witnesses: the smoothed "
    "twist witness in double and the exact LP on inscribed 256-gons)";

// Friction at fewer than two distinct points under f: LS(f) is flat and has no interior (every load slides on it).
bool flat(const Support& s, const std::vector<Rational>& f) {
  const Vec2* first = nullptr;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    if (s.mu_of(s.points[i]) * f[i] == 0) continue;
    if (first && (first->x != s.points[i].at.x || first->y != s.points[i].at.y)) return false;
    if (!first) first = &s.points[i].at;
  }
  return true;
}

Vec3q rational_twist(const std::array<double, 3>& w) { return {Rational(w[0]), Rational(w[1]), Rational(w[2])}; }

// Twists that may prove "slides" for the distribution f: the verdict's own twist (the certified search's, Newton's),
// else the outward normals of LS_out at the load (its normal cone's generators: from the caller's polytope, else one
// built here); then the load itself, the rotations about the first point with friction (they cost no friction on a
// flat surface), and the translation (1, 0, 0).
std::vector<Vec3q> slide_candidates(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                    const Points_verdict& d, int sides, const Built_polygons& built) {
  std::vector<Vec3q> c;
  const bool searched = d.decided_by == Decided_by::float_search;
  if (searched) c.push_back(rational_twist(d.witness));
  if (d.exact_witness) c.push_back(*d.exact_witness);
  std::optional<Polygonal_ls::Normal_cone> cone;
  if (built.model && built.outer) {
    cone = built.model->normal_cone(*built.outer, Side::outer, p);
    if (cone->generators.empty() && cone->lineality.empty()) cone.reset();
  }
  if (!cone && !searched && !d.exact_witness) {
    const Polygonal_ls model(merge_support(s, &f), make_directions(sides));
    if (model.candidate_count() > kMaxCandidates) return c;
    const Ls_polytope out = model.build(Side::outer);
    cone = model.normal_cone(out, Side::outer, p);
  }
  if (cone)
    for (const Vec3z& g : cone->generators) c.push_back({Rational(g[0]), Rational(g[1]), Rational(g[2])});
  if (!is_zero(p)) c.push_back(p);
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Support_point& pt = s.points[i];
    if (s.mu_of(pt) * f[i] == 0) continue;
    c.push_back({pt.at.y, -pt.at.x, Rational(1)});  // v(r) = 0
    c.push_back({-pt.at.y, pt.at.x, Rational(-1)});
    break;
  }
  c.push_back({Rational(1), Rational(0), Rational(0)});
  return c;
}

std::optional<Slide_witness> first_slide_witness(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
                                                 const std::vector<Vec3q>& candidates) {
  for (const Vec3q& q : candidates)
    if (auto w = slide_witness(s, f, p, q)) return w;
  return std::nullopt;
}

// Every force given, points: the verdict (strategies.h points_verdict), then its witness [SL-4]. A sticking verdict
// without a stick witness may still be a load on a flat surface (friction at fewer than two places): a slide witness
// then decides "slides".
Motion_answer known_points(const Support_model& model, const Vec3q& p, Mode mode, const Motion_options& o) {
  const Support& s = model.support();
  const std::vector<Rational>& f = model.given();
  const Built_polygons& b = o.polygons;
  const Points_verdict v = b.model ? points_verdict(*b.model, p, mode, b.inner, b.outer)
                                   : points_verdict(Polygonal_ls(merge_support(s), make_directions(o.sides)), p, mode);
  Motion_answer r;
  r.motion = v.motion;
  r.decided_by = v.decided_by;
  r.search_twists = v.cells;
  r.search_twist = v.witness;
  if (r.motion == Motion::sticks) {
    if (auto w = stick_witness_refined(s, model.admissible(), p, std::max(o.sides, 8), f)) {
      r.sticking = std::move(*w);
    } else if (auto sw = first_slide_witness(s, f, p, slide_candidates(s, f, p, v, o.sides, {}))) {
      r.sliding = std::move(*sw);
      r.motion = Motion::slides;
      r.decided_by = Decided_by::certificate;
    }
  } else if (r.motion == Motion::slides) {
    r.sliding = first_slide_witness(s, f, p, slide_candidates(s, f, p, v, o.sides, b));
  }
  if (r.motion == Motion::sticks && !r.sticking &&
      s.points.size() * static_cast<std::size_t>(std::max(o.sides, 8)) > kMaxStickWitnessColumns) {
    // Too many support points for the stick witness LP: the certified search's verdict stands, unchecked.
    r.uncertified = "no certificate: the stick witness LP is run up to " + std::to_string(kMaxStickWitnessColumns) +
                    " columns (support points x sides); the verdict is the float twin's certified search's";
    return r;
  }
  if (r.motion != Motion::undecided && !r.sticking && !r.sliding) {
    r.uncertified = std::string("the certified search says ") + motion_name(r.motion) + kNoWitness;
    r.motion = Motion::undecided;
  }
  return r;
}

// The support with the points' forces f put in place (one distribution of F).
Support with_forces(const Support& s, const std::vector<Rational>& f) {
  Support t = s;
  for (std::size_t i = 0; i < t.points.size(); ++i) t.points[i].force = f[i];
  return t;
}

// [RG-3] Does q prove "slides for every distribution" over points and regions? q·p ≥ max_F Σ μ_i f_i u_i (the LP over F,
// with its dual) plus the regions' slide blocks, refined within max_cells until their bound fits the slack. Exact.
std::optional<Slide_witness> slides_for_every_regions(const Support& s, const Admissible& a, const Vec3q& p,
                                                      const Vec3q& q, std::size_t max_cells, std::size_t& cells) {
  std::optional<Slide_witness> w = slides_for_every(s, a, p, q);
  if (!w) return std::nullopt;
  const Rational power = dot(q, p);
  // The points' bound over F, by LP duality: Σ_given μ_i f_i u_i + y0 W' + yx M'_x + yy M'_y (the LP's maximum).
  const std::array<Rational, 3>& y = *w->dual;
  Rational points = y[0] * a.rest + y[1] * a.rest_moment.x + y[2] * a.rest_moment.y;
  for (std::size_t i = 0; i < s.points.size(); ++i)
    if (s.points[i].force) points += s.mu_of(s.points[i]) * *s.points[i].force * w->speed_bounds[i];
  Region_slide_blocks b = region_slide_blocks(s, q, Rational(power - points), max_cells);
  if (!b.ok || points + b.bound > power) return std::nullopt;
  w->regions = std::move(b.blocks);
  cells = b.cells;
  return w;
}

// A distribution of F that sticks, by the exact LP over F × inscribed N-gons (N = first, doubled up to 256 while the
// LP stays within 1024 columns), then a strict witness with that distribution fixed. With regions, on their coarse
// cells as support points with their forces given (each cell carries F_k at its pressure centroid: the regions' force
// and moment, so F is the same; their limit surface is inside the regions', RG-1); the cells' forces become the
// regions' stick blocks.
std::optional<Stick_witness> stick_over_f(const Support& s, const Admissible& a, const Vec3q& p, int first,
                                          int& largest, std::size_t& cells) {
  Support aug = s;
  aug.regions.clear();
  Admissible b = a;
  std::vector<Region_cells> coarse;
  for (const Support_region& g : s.regions) {
    coarse.push_back(region_cells(g, 1));
    for (Support_point& c : cell_points(g, s.mu_of(g), coarse.back())) {
      b.given.push_back(*c.force);
      aug.points.push_back(std::move(c));
    }
  }
  const std::size_t k = s.points.size();
  for (int n = first; n <= 256 && aug.points.size() * static_cast<std::size_t>(n) <= 1024; n *= 2) {
    largest = n;
    const std::optional<Stick_witness> some = stick_witness(aug, b, p, n);  // closed: confirmed strictly below
    if (!some) continue;
    std::optional<Stick_witness> w = stick_witness_refined(aug, b, p, n, some->distribution);
    if (!w) continue;
    if (s.regions.empty()) return w;
    const auto at = [](const auto& v, std::size_t i) { return v.begin() + static_cast<std::ptrdiff_t>(i); };
    Stick_witness out{{at(w->distribution, 0), at(w->distribution, k)}, {at(w->forces, 0), at(w->forces, k)}, {}};
    std::size_t next = k;
    cells = 0;
    for (Region_cells& c : coarse) {
      Region_stick_block blk{std::move(c), {}};
      blk.forces.assign(at(w->forces, next), at(w->forces, next + blk.cells.triangles.size()));
      next += blk.cells.triangles.size();
      cells += blk.cells.triangles.size();
      out.regions.push_back(std::move(blk));
    }
    return out;
  }
  return std::nullopt;
}

// [SL-3] [RG-3] Some force not given: the extreme distributions first, then one twist for all of F, the union's
// minimax (points, hybrid), and a distribution that sticks; the witnesses of the verdict last (points: the regions'
// come with their decisions).
//
//   1. each vertex: points — flat, else its verdict (points_verdict); regions — decide_on_regions with its forces. All
//      stick: sticks; a stick and a slide: depends; some undecided and the rest alike: undecided;
//   2. every vertex slides: the vertices' sliding twists (their sum first), each checked by the LP over F (and the
//      regions' slide blocks, within 500 cells);
//   3. points, hybrid: the union's minimax — its twist (slides) or its distribution f* = Σ λ_v f_v (depends when f* has
//      a stick witness);
//   4. the search for a twist separating p from the union (regions: their power added; blocks within 20 000 cells);
//   5. a distribution that sticks, by the exact LP over F (depends);
//   6. else undecided, with the reason.
Motion_answer over_f(const Support_model& model, const Vec3q& p, Mode mode, const Motion_options& o) {
  const Support& s = model.support();
  const Admissible& a = model.admissible();
  const bool regions = model.has_regions();
  const std::vector<std::vector<Rational>>& v = model.extreme();
  Motion_answer r;
  std::vector<Points_verdict> verdicts;        // points: each vertex's (its twists, for its witness)
  std::vector<Motion_answer> region_answers;   // regions: each vertex's, with its witness
  std::vector<Vec3q> twists;                   // the sliding vertices' twists
  std::optional<std::size_t> sticking_vertex, sliding_vertex;
  for (std::size_t i = 0; i < v.size(); ++i) {
    Motion m = Motion::undecided;
    if (regions) {
      region_answers.push_back(decide_on_regions(with_forces(s, v[i]), p));
      const Motion_answer& x = region_answers.back();
      m = x.motion;
      if (x.sliding) twists.push_back(x.sliding->twist);
    } else {
      Points_verdict d;
      if (flat(s, v[i])) {
        d.motion = Motion::slides;
        d.decided_by = Decided_by::flat;
      } else {
        d = points_verdict(merge_support(s, &v[i]), p, mode, o.sides);
      }
      if (d.motion == Motion::slides && d.decided_by == Decided_by::float_search) twists.push_back(rational_twist(d.witness));
      if (d.exact_witness) twists.push_back(*d.exact_witness);
      m = d.motion;
      verdicts.push_back(std::move(d));
    }
    r.per_vertex.push_back(m);
    if (m == Motion::sticks && !sticking_vertex) sticking_vertex = i;
    if (m == Motion::slides && !sliding_vertex) sliding_vertex = i;
  }
  const bool all_stick = std::all_of(r.per_vertex.begin(), r.per_vertex.end(), [](Motion m) { return m == Motion::sticks; });
  const bool all_slide = std::all_of(r.per_vertex.begin(), r.per_vertex.end(), [](Motion m) { return m == Motion::slides; });
  std::optional<Stick_witness> found;  // a sticking distribution found over F (minimax, lp)
  const auto decided = [&](Motion m, Decided_by by) {
    r.motion = m;
    r.decided_by = by;
  };
  if (sticking_vertex && sliding_vertex) {
    decided(Motion::depends, Decided_by::vertices);
  } else if (all_stick) {
    decided(Motion::sticks, Decided_by::vertices);
  } else if (!all_slide) {  // some vertices undecided and none of the other kind: not decided
    for (std::size_t i = 0; i < r.per_vertex.size(); ++i)
      if (r.per_vertex[i] == Motion::undecided) {
        r.undecided_why = "extreme distribution " + std::to_string(i + 1) + " of " + std::to_string(v.size()) +
                          " is undecided: " +
                          (regions ? region_answers[i].undecided_why
                                   : "the load lies between its inscribed and circumscribed " + std::to_string(o.sides) +
                                         "-gon limit surfaces, within " + gap_text(1 / std::cos(kPi / o.sides) - 1) +
                                         " of its limit surface (relative, along the load's ray; refine --sides)");
        break;
      }
    return r;
  } else {
    if (twists.size() > 1) {  // their sum first: a twist between the vertices' own
      Vec3q sum{};
      for (const Vec3q& q : twists)
        for (std::size_t c = 0; c < 3; ++c) sum[c] += q[c];
      twists.insert(twists.begin(), sum);
    }
    const auto slides_for_all = [&](const Vec3q& q, std::size_t max_cells) {
      r.sliding = regions ? slides_for_every_regions(s, a, p, q, max_cells, r.cells) : slides_for_every(s, a, p, q);
      return r.sliding.has_value();
    };
    for (const Vec3q& q : twists)
      if (slides_for_all(q, 500)) {
        decided(Motion::slides, Decided_by::twist);
        break;
      }
    if (r.motion == Motion::undecided && !regions && mode == Mode::hybrid)
      if (const Union_minimax m = union_minimax(s, v, p); m.found) {
        if (m.t < 1) {
          if (slides_for_all(rational_twist(m.q), 0)) decided(Motion::slides, Decided_by::minimax);
        } else if (m.t > 1 + 1e-9) {  // only margins the doubles resolve
          std::vector<Rational> l(v.size());
          Rational total = 0;
          for (std::size_t j = 0; j < v.size(); ++j) total += l[j] = Rational(m.lambda[j]);
          std::vector<Rational> f(s.points.size());
          for (std::size_t j = 0; j < v.size(); ++j)
            if (l[j] != 0)
              for (std::size_t i = 0; i < f.size(); ++i) f[i] += l[j] / total * v[j][i];
          found = smoothed_stick_witness(s, f, p);
          if (!found) found = precise_witness(s, f, p).sticks;
          if (found) decided(Motion::depends, Decided_by::minimax);
        }
      }
    if (r.motion == Motion::undecided) {
      std::function<double(const double*)> common;  // the regions' power, the same for every distribution
      std::vector<double> mu_r;
      for (const Support_region& g : s.regions) mu_r.push_back(s.mu_of(g).get_d());
      if (regions)
        common = [&](const double* q) {
          double h = 0;
          for (std::size_t g = 0; g < s.regions.size(); ++g)
            if (mu_r[g] != 0) h += mu_r[g] * region_power_double(s.regions[g], q);
          return h;
        };
      if (const auto q = union_search(s, v, p, twists.empty() ? nullptr : &twists.front(), common))
        if (slides_for_all(*q, kMaxRegionCells)) decided(Motion::slides, Decided_by::twist);
    }
    int largest = 0;
    if (r.motion == Motion::undecided)
      if ((found = stick_over_f(s, a, p, regions ? 8 : o.sides, largest, r.cells))) decided(Motion::depends, Decided_by::lp);
    if (r.motion == Motion::undecided) {
      if (regions)
        r.undecided_why = "every extreme distribution slides, no twist tried separates the load from the union of the "
                          "limit surfaces (the regions' slide blocks with up to " + std::to_string(kMaxRegionCells) +
                          " cells and the LP over the distributions), and no distribution holds it on the regions' "
                          "coarse cells (inscribed polygons of up to 256 sides): the load is near the boundary of that union";
      else
        r.undecided_why = "every extreme distribution slides, no twist tried separates the load from the union of the "
                          "limit surfaces, and no distribution holds it with forces on inscribed " +
                          std::to_string(largest ? largest : o.sides) + "-gons: if inside that union, the load is within " +
                          gap_text(1 - std::cos(kPi / (largest ? largest : o.sides))) +
                          " of its boundary (relative, along the load's ray)";
      r.cells = 0;
      return r;
    }
  }
  // The witnesses of the verdict.
  if (regions) {
    if (r.motion == Motion::sticks)
      for (const Motion_answer& x : region_answers) {
        r.vertices.push_back(*x.sticking);
        r.cells += x.cells;
      }
    if (r.motion == Motion::depends) {
      const Motion_answer& slid = region_answers[*sliding_vertex];
      r.sticking = found ? *found : *region_answers[*sticking_vertex].sticking;
      r.sliding = slid.sliding;
      r.cells = (found ? r.cells : region_answers[*sticking_vertex].cells) + slid.cells;
    }
    return r;
  }
  const int sides = std::max(o.sides, 8);
  if (r.motion == Motion::sticks) {
    for (const std::vector<Rational>& f : v) {
      auto w = stick_witness_refined(s, a, p, sides, f);
      if (!w) break;
      r.vertices.push_back(std::move(*w));
    }
    if (r.vertices.size() != v.size()) r.vertices.clear();
  } else if (r.motion == Motion::depends) {
    r.sticking = found ? found : stick_witness_refined(s, a, p, sides, v[*sticking_vertex]);
    const std::vector<Rational>& f = v[*sliding_vertex];
    r.sliding = first_slide_witness(s, f, p, slide_candidates(s, f, p, verdicts[*sliding_vertex], sides, {}));
    if (!r.sticking || !r.sliding) r.sticking.reset(), r.sliding.reset();
  }
  if (r.vertices.empty() && !r.sticking && !r.sliding) {
    r.uncertified = std::string("the answer is ") + motion_name(r.motion) + kNoWitness;
    r.motion = Motion::undecided;
  }
  return r;
}

}  // namespace

Motion_answer decide_motion(const Support_model& model, const Vec3q& load, Mode mode, const Motion_options& options) {
  if (model.known()) {
    if (model.has_regions()) return decide_on_regions(model.support(), load);
    return known_points(model, load, mode, options);
  }
  if (mode == Mode::float_only) {
    Motion_answer r;
    r.undecided_why = "the float twin has no LP over the admissible distributions";
    return r;
  }
  return over_f(model, load, mode, options);
}

}  // namespace wrenchkit
