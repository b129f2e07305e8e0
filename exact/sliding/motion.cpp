// [SL-1] [SL-3] [RG-1] [RG-3] The one decision of "does the load stick or slide?" (exact/sliding/motion.h): every force
// given — points by their verdict and then their witness, regions by their cells; some force not given — one
// skeleton over the vertices of F for points and regions alike.
#include "exact/sliding/motion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>

#include "exact/io/support_check.h"
#include "exact/numbers/work_budget.h"
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

const char* decided_by_words(Decided_by d) {
  switch (d) {
    case Decided_by::none: return "nothing";
    case Decided_by::float_search: return "the float twin's certified search on the true limit surface";
    case Decided_by::polygons: return "the exact polygons";
    case Decided_by::newton: return "Newton's method in multiple precision, checked exactly";
    case Decided_by::flat: return "a flat limit surface (friction at fewer than two places): all of it is surface";
    case Decided_by::certificate: return "an exact witness (twists and forces tried, each checked exactly)";
    case Decided_by::vertices: return "the extreme distributions";
    case Decided_by::twist: return "one twist for every distribution";
    case Decided_by::minimax: return "the minimax over the extreme distributions";
    case Decided_by::lp: return "the exact LP over the admissible distributions";
    case Decided_by::lp_over_f: return "the exact LP over the admissible distributions and inscribed polygons";
    case Decided_by::zero_load: return "the zero load";
    case Decided_by::equilibrium: return "the contacts alone";
    case Decided_by::smoothed_witness: return "the smoothed witness";
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

Vec3q rational_twist(const std::array<double, 3>& w) { return {Rational(w[0]), Rational(w[1]), Rational(w[2])}; }

// Twists that may prove "slides" or "impending" for the distribution f: the verdict's own twist (the certified
// search's, Newton's), else the outward normals of LS_out at the load (its normal cone's generators: from the caller's
// polytope, else one built here); then the load itself, the rotations about each point with friction (a facet of LS:
// on a flat surface they cost no friction), the translation along the load's force, the search's and Newton's twists
// made rational (continued fractions: an exact normal with short numbers), and the translation (1, 0, 0).
std::vector<Vec3q> twist_candidates(const Support& s, const std::vector<Rational>& f, const Vec3q& p,
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
    if (model.candidate_count() <= kMaxCandidates) {
      const Ls_polytope out = model.build(Side::outer);
      cone = model.normal_cone(out, Side::outer, p);
    }
  }
  if (cone)
    for (const Vec3z& g : cone->generators) c.push_back({Rational(g[0]), Rational(g[1]), Rational(g[2])});
  if (!is_zero(p)) c.push_back(p);
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Support_point& pt = s.points[i];
    if (s.mu_of(pt) * f[i] == 0) continue;
    c.push_back({pt.at.y, -pt.at.x, Rational(1)});  // v(r) = 0
    c.push_back({-pt.at.y, pt.at.x, Rational(-1)});
  }
  if (p[0] != 0 || p[1] != 0) c.push_back({p[0], p[1], Rational(0)});
  for (const auto& d2 : {std::optional<std::array<double, 3>>(searched ? std::optional<std::array<double, 3>>(d.witness)
                                                                        : std::nullopt),
                         d.proposal})
    if (d2)
      if (const auto r = rationalized(*d2)) c.push_back(*r);
  c.push_back({Rational(1), Rational(0), Rational(0)});
  return c;
}

template <class Witness, class Find>
std::optional<Witness> first_of(const std::vector<Vec3q>& candidates, Find find) {
  for (const Vec3q& q : candidates)
    if (auto w = find(q)) return w;
  return std::nullopt;
}

// A load the verdict leaves undecided, one distribution f: the polygon rounds (strategies.h) on the disc polygons
// refined where friction acts, the candidates' exact velocities among their directions — p in the closed LS_in:
// a margin witness (sticks) or, with none, the candidates and the rounds' dual for "impending"; p outside LS_in: the
// dual twist y (y·p > h_in(y)) and its rational neighbour for "slides" or "impending".
void polygon_rounds_at(const Support& s, const Admissible& a, const std::vector<Rational>& f, const Vec3q& p,
                       const std::vector<Vec3q>& candidates, Motion_answer& r) {
  Polygon_rounds rounds;
  rounds.support = &s;
  rounds.admissible = &a;
  rounds.fixed = &f;
  for (const Vec3q& q : candidates) add_exact_directions(s, q, rounds.common);
  int count = 0;
  polygon_rounds(rounds, p, [&](const Friction_lp_solution& lp) {
    const Vec3q y{lp.lp.y[0], lp.lp.y[1], lp.lp.y[2]};
    std::vector<Vec3q> twists;
    if (!is_zero(y)) twists.push_back(y);
    if (const auto q = rationalized({y[0].get_d(), y[1].get_d(), y[2].get_d()})) twists.push_back(*q);
    if (lp.goal >= 1) {  // p ∈ LS_in(f), closed
      if ((r.sticking = rounds.margin(p))) return r.motion = Motion::sticks, true;
      twists.insert(twists.end(), candidates.begin(), candidates.end());
    } else {
      for (const Vec3q& q : twists)
        if ((r.sliding = slide_witness(s, f, p, q))) return r.motion = Motion::slides, true;
    }
    for (const Vec3q& q : twists)
      if ((r.impending = impending_witness(s, f, p, q))) return r.motion = Motion::impending, true;
    return false;
  }, count);
  if (r.motion != Motion::undecided) r.decided_by = Decided_by::polygons;
}

// Every force given, points: the verdict (strategies.h points_verdict), then its witness [SL-4] [SL-1]. The verdict
// "slides" says "not inside": a twist whose power the load's exceeds proves "outside" (slides), one whose power it
// meets with exact speeds, and forces on that face, prove "on the surface" (impending). A load the verdict leaves
// undecided — within the search's and the polygons' resolution, or exactly on the surface — is tried for "impending".
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
  std::optional<std::vector<Vec3q>> cands;
  const auto candidates = [&]() -> const std::vector<Vec3q>& {
    if (!cands) cands = twist_candidates(s, f, p, v, o.sides, r.motion == Motion::slides ? b : Built_polygons{});
    return *cands;
  };
  const auto slides = [&] {
    r.sliding = first_of<Slide_witness>(candidates(), [&](const Vec3q& q) { return slide_witness(s, f, p, q); });
    return r.sliding.has_value();
  };
  const auto impending = [&] {
    r.impending = first_of<Impending_witness>(candidates(), [&](const Vec3q& q) { return impending_witness(s, f, p, q); });
    return r.impending.has_value();
  };
  const auto now = [&](Motion m) {
    if (r.decided_by != Decided_by::flat) r.decided_by = m == r.motion ? r.decided_by : Decided_by::certificate;
    r.motion = m;
  };
  if (r.motion == Motion::sticks) {
    if (auto w = stick_witness_refined(s, model.admissible(), p, std::max(o.sides, 8), f)) r.sticking = std::move(*w);
    else if (impending()) now(Motion::impending);
    else if (slides()) now(Motion::slides);
  } else if (r.motion == Motion::slides) {
    if (!slides() && impending()) now(Motion::impending);
  } else if (impending()) {
    now(Motion::impending);
  } else if (slides()) {  // the candidates (the translation along the force, …) with exact speed bounds
    now(Motion::slides);
  } else if (mode != Mode::float_only) {
    polygon_rounds_at(s, model.admissible(), f, p, candidates(), r);
  }
  if (r.motion == Motion::sticks && !r.sticking &&
      s.points.size() * static_cast<std::size_t>(std::max(o.sides, 8)) > kMaxStickWitnessColumns) {
    // Too many support points for the stick witness LP: the certified search's verdict stands, unchecked.
    r.uncertified = "no certificate: the stick witness LP is run up to " + std::to_string(kMaxStickWitnessColumns) +
                    " columns (support points x sides); the verdict is the float twin's certified search's";
    return r;
  }
  if (r.motion != Motion::undecided && !r.sticking && !r.sliding && !r.impending) {
    r.uncertified = std::string("the certified search says ") + motion_name(r.motion) + kNoWitness;
    r.motion = Motion::undecided;
  }
  if (r.motion == Motion::undecided && r.uncertified.empty())
    r.undecided_why =
        std::string("the load is within the resolution of ") +
        (mode == Mode::float_only ? "the float twin's certified search"
                                  : "the exact tests (the " + std::to_string(o.sides) +
                                        "-gons, then polygons refined where friction acts, to about 10^-11 of the "
                                        "discs)") +
        " of the limit surface, and no twist tried meets the friction's power exactly (a load exactly on the surface "
        "whose supporting twists give a point an irrational speed has no certificate in rationals)" +
        (mode == Mode::exact ? "; hybrid mode adds Newton's method in multiple precision" : "");
  return r;
}

// The support with the points' forces f put in place (one distribution of F).
Support with_forces(const Support& s, const std::vector<Rational>& f) {
  Support t = s;
  for (std::size_t i = 0; i < t.points.size(); ++i) t.points[i].force = f[i];
  return t;
}

// [SL-3] [RG-3] Does q prove "outside every limit surface of F" (`strict`; else "on or outside")? q·p > max_F Σ μ_i f_i
// u_i (the LP over F, with its dual) plus the regions' slide blocks, refined within max_cells until their bound fits
// the slack. Exact.
std::optional<Slide_witness> outside_every(const Support& s, const Admissible& a, const Vec3q& p, const Vec3q& q,
                                           bool strict, std::size_t max_cells, std::size_t& cells) {
  std::optional<Slide_witness> w = slides_for_every(s, a, p, q, strict);
  if (!w || s.regions.empty()) return w;
  if (!w) return std::nullopt;
  const Rational power = dot(q, p);
  // The points' bound over F, by LP duality: Σ_given μ_i f_i u_i + y0 W' + yx M'_x + yy M'_y (the LP's maximum).
  const std::array<Rational, 3>& y = *w->dual;
  Rational points = y[0] * a.rest + y[1] * a.rest_moment.x + y[2] * a.rest_moment.y;
  for (std::size_t i = 0; i < s.points.size(); ++i)
    if (s.points[i].force) points += s.mu_of(s.points[i]) * *s.points[i].force * w->speed_bounds[i];
  Region_slide_blocks b = region_slide_blocks(s, q, Rational(power - points), max_cells);
  if (!b.ok || (strict ? points + b.bound >= power : points + b.bound > power)) return std::nullopt;
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

// One distribution's decision: the known-forces strategies on the support with f put in place.
Motion_answer at_distribution(const Support& s, const std::vector<Rational>& f, const Vec3q& p, Mode mode,
                              const Motion_options& o) {
  const Support t = with_forces(s, f);
  if (!s.regions.empty()) return decide_on_regions(t, p);
  Admissible known;
  known.given = f;
  Motion_options own;
  own.sides = o.sides;
  return known_points(Support_model(t, std::move(known)), p, mode, own);
}

// The regions' frictional power in double (the same for every distribution), for the union searches; empty without
// regions.
std::function<double(const double*)> regions_power(const Support& s) {
  if (s.regions.empty()) return {};
  std::vector<double> mu_r;
  for (const Support_region& g : s.regions) mu_r.push_back(s.mu_of(g).get_d());
  return [&s, mu_r](const double* q) {
    double h = 0;
    for (std::size_t g = 0; g < s.regions.size(); ++g)
      if (mu_r[g] != 0) h += mu_r[g] * region_power_double(s.regions[g], q);
    return h;
  };
}

// [WORK] When deciding every extreme distribution is beyond the work budget (issue 34): the answers that need no
// vertex but the ones they name — slides for every distribution by one twist (the load's own, then the translation
// along its force) against the LP over F (and the regions' slide blocks), or depends by the LP's two extreme
// distributions for the load's twist (the least and the most frictional power), decided alone (charged as two). Sticks
// for every distribution has no such certificate (it is every vertex's): nothing then, and the caller's budget error
// stands. The answer's per_vertex stays empty.
std::optional<Motion_answer> without_every_vertex(const Support_model& model, const Vec3q& p, Mode mode,
                                                  const Motion_options& o) {
  const Support& s = model.support();
  const Admissible& a = model.admissible();
  if (is_zero(p)) return std::nullopt;
  Motion_answer r;
  std::vector<Vec3q> twists{p};
  if (p[2] != 0 && (p[0] != 0 || p[1] != 0)) twists.push_back({p[0], p[1], Rational(0)});
  for (const Vec3q& q : twists)
    if ((r.sliding = outside_every(s, a, p, q, true, 500, r.cells))) {
      r.motion = Motion::slides;
      r.decided_by = Decided_by::twist;
      return r;
    }
  r.cells = 0;
  const auto inside = [](const Motion_answer& m) { return m.motion == Motion::sticks || m.motion == Motion::impending; };
  const auto outside = [](const Motion_answer& m) { return m.motion == Motion::slides || m.motion == Motion::impending; };
  // Two rounds: the load's twist, then the separating twist of the most frictional distribution when it slides (its
  // least frictional distribution is the likeliest to slide too, its most the likeliest to stick).
  Vec3q q = p;
  std::vector<Rational> most;  // the most frictional distribution for the load's twist: the cutting planes' first
  for (int round = 0; round < 2; ++round) {
    const Power_range range = power_range(s, a, q);
    if (round == 0) most = range.max_distribution;
    charge_distributions(s, {range.min_distribution, range.max_distribution});
    const Motion_answer lo = at_distribution(s, range.min_distribution, p, mode, o);
    const Motion_answer hi = at_distribution(s, range.max_distribution, p, mode, o);
    for (const auto& [in, out] : {std::pair{&hi, &lo}, std::pair{&lo, &hi}})
      if (inside(*in) && outside(*out) && (in->motion == Motion::sticks || out->motion == Motion::slides)) {
        r.sticking = in->sticking ? in->sticking : in->impending->forces;
        r.sliding = out->sliding ? out->sliding : out->impending->twist;
        r.held_as = in->motion;
        r.moved_as = out->motion;
        r.cells = in->cells + out->cells;
        r.motion = Motion::depends;
        r.decided_by = Decided_by::lp;
        return r;
      }
    if (hi.motion != Motion::slides) return std::nullopt;
    q = hi.sliding->twist;
    if ((r.sliding = outside_every(s, a, p, q, true, 500, r.cells))) {
      r.motion = Motion::slides;
      r.decided_by = Decided_by::twist;
      return r;
    }
  }
  // Slides for every distribution by cutting planes: the union search over a few vertices proposes a twist, the exact
  // LP over F checks it and, when the twist is not enough, adds its most frictional vertex (at most 8 rounds).
  std::vector<std::vector<Rational>> some{std::move(most)};
  const std::function<double(const double*)> common = regions_power(s);
  Vec3q start = q;
  for (int round = 0; round < 8; ++round) {
    const std::optional<Vec3q> t = union_search(s, some, p, &start, common);
    if (!t) break;
    if ((r.sliding = outside_every(s, a, p, *t, true, kMaxRegionCells, r.cells))) {
      r.motion = Motion::slides;
      r.decided_by = Decided_by::twist;
      return r;
    }
    std::vector<Rational> f = power_range(s, a, *t).max_distribution;
    if (std::find(some.begin(), some.end(), f) != some.end()) break;
    some.push_back(std::move(f));
    start = *t;
  }
  return std::nullopt;
}

// [SL-3] [RG-3] Some force not given: the extreme distributions first (each by the known-forces decision, with its
// witness), then what every vertex shares needs one more step:
//
//   1. outcomes of two kinds among the vertices: depends (a witness of each kind); some undecided and the rest of one
//      kind: undecided;
//   2. every vertex sticks: sticks for every distribution (LS is Minkowski-linear in f);
//   3. every vertex on its surface: one twist for all of F whose bound the load meets (the vertices' twists, their
//      sum; the LP over F and the regions' slide blocks) — impending for every distribution; else a mixture of the
//      vertices sticks (depends);
//   4. every vertex slides: one twist for all of F whose bound the load exceeds (the vertices' twists, their sum; the
//      union's minimax in hybrid for points, whose multipliers may instead give a distribution that sticks; the
//      union's compass search), or a distribution that sticks by the exact LP over F (depends);
//   5. else undecided, with the reason.
Motion_answer over_f(const Support_model& model, const Vec3q& p, Mode mode, const Motion_options& o) {
  const Support& s = model.support();
  const Admissible& a = model.admissible();
  const bool regions = model.has_regions();
  const std::vector<std::vector<Rational>>& v = model.extreme();
  try {
    charge_distributions(s, v);
  } catch (const Work_exhausted&) {  // too many to decide each: the cheap routes, else undecided
    if (std::optional<Motion_answer> cheap = without_every_vertex(model, p, mode, o)) return *cheap;
    throw;
  }
  Motion_answer r;
  std::vector<Motion_answer> at;  // each vertex's answer, with its witness
  std::optional<std::size_t> first[3];  // the first vertex that sticks, is on its surface, slides
  for (std::size_t i = 0; i < v.size(); ++i) {
    at.push_back(at_distribution(s, v[i], p, mode, o));
    const Motion m = at.back().motion;
    r.per_vertex.push_back(m);
    const int kind = m == Motion::sticks ? 0 : m == Motion::impending ? 1 : m == Motion::slides ? 2 : -1;
    if (kind >= 0 && !first[kind]) first[kind] = i;
  }
  const int kinds = (first[0] ? 1 : 0) + (first[1] ? 1 : 0) + (first[2] ? 1 : 0);
  const auto decided = [&](Motion m, Decided_by by) {
    r.motion = m;
    r.decided_by = by;
    return r;
  };
  if (kinds >= 2) {  // one inside (or on) and one outside (or on), one of them strictly
    const Motion_answer& in = at[*(first[0] ? first[0] : first[1])];
    const Motion_answer& out = at[*(first[2] ? first[2] : first[1])];
    r.sticking = in.sticking ? in.sticking : in.impending->forces;
    r.sliding = out.sliding ? out.sliding : out.impending->twist;
    r.held_as = in.motion;
    r.moved_as = out.motion;
    r.cells = in.cells + out.cells;
    return decided(Motion::depends, Decided_by::vertices);
  }
  for (std::size_t i = 0; i < at.size(); ++i)
    if (at[i].motion == Motion::undecided) {
      r.undecided_why = "extreme distribution " + std::to_string(i + 1) + " of " + std::to_string(v.size()) +
                        " is undecided: " +
                        (!at[i].undecided_why.empty() ? at[i].undecided_why
                         : !at[i].uncertified.empty() ? at[i].uncertified
                                                      : "the load lies between its inscribed and circumscribed " +
                                                            std::to_string(o.sides) + "-gon limit surfaces, within " +
                                                            gap_text(1 / std::cos(kPi / o.sides) - 1) +
                                                            " of its limit surface (relative, along the load's ray; "
                                                            "refine --sides)");
      return r;
    }
  if (first[0]) {  // every vertex sticks
    for (Motion_answer& x : at) {
      r.cells += x.cells;
      r.vertices.push_back(std::move(*x.sticking));
    }
    return decided(Motion::sticks, Decided_by::vertices);
  }
  // Every vertex on its surface, or every vertex outside: one twist for all of F, from the vertices' own (their sum
  // first: a twist between them).
  const bool on = first[1].has_value();
  std::vector<Vec3q> twists;
  for (const Motion_answer& x : at) twists.push_back(on ? x.impending->twist.twist : x.sliding->twist);
  if (twists.size() > 1) {
    Vec3q sum{};
    for (const Vec3q& q : twists)
      for (std::size_t c = 0; c < 3; ++c) sum[c] += q[c];
    twists.insert(twists.begin(), sum);
  }
  const auto for_all = [&](const Vec3q& q, std::size_t max_cells) {
    r.sliding = outside_every(s, a, p, q, !on, max_cells, r.cells);
    return r.sliding.has_value();
  };
  for (const Vec3q& q : twists)
    if (for_all(q, 500)) {
      if (!on) return decided(Motion::slides, Decided_by::twist);
      for (Motion_answer& x : at) {
        r.cells += x.cells;
        r.vertices.push_back(std::move(x.impending->forces));
      }
      return decided(Motion::impending, Decided_by::twist);
    }
  r.cells = 0;
  std::optional<Stick_witness> found;  // a distribution of F that sticks (depends)
  if (on) {  // the vertices' surfaces meet the load with different normals: their mixture holds it inside
    std::vector<Rational> mean(s.points.size());
    for (const std::vector<Rational>& f : v)
      for (std::size_t i = 0; i < f.size(); ++i) mean[i] += f[i] / static_cast<long>(v.size());
    const Motion_answer m = at_distribution(s, mean, p, mode, o);
    if (m.motion == Motion::sticks) {
      r.sticking = m.sticking;
      r.sliding = at[*first[1]].impending->twist;
      r.moved_as = Motion::impending;
      r.cells = m.cells + at[*first[1]].cells;
      return decided(Motion::depends, Decided_by::twist);
    }
    r.undecided_why = "every extreme distribution has the load on its limit surface, no twist tried is normal to every "
                      "one there, and their mean distribution does not hold it inside";
    return r;
  }
  if (!regions && mode == Mode::hybrid)  // the union's minimax (points): its twist, or its distribution that sticks
    if (const Union_minimax m = union_minimax(s, v, p); m.found) {
      if (m.t < 1) {
        if (for_all(rational_twist(m.q), 0)) return decided(Motion::slides, Decided_by::minimax);
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
        if (found) {
          r.sticking = std::move(found);
          r.sliding = at[*first[2]].sliding;
          return decided(Motion::depends, Decided_by::minimax);
        }
      }
    }
  if (const auto q = union_search(s, v, p, &twists.front(), regions_power(s)))
    if (for_all(*q, kMaxRegionCells)) return decided(Motion::slides, Decided_by::twist);
  int largest = 0;
  std::size_t cells = 0;
  if ((found = stick_over_f(s, a, p, regions ? 8 : o.sides, largest, cells))) {
    r.sticking = std::move(found);
    r.sliding = at[*first[2]].sliding;
    r.cells = cells + at[*first[2]].cells;
    return decided(Motion::depends, Decided_by::lp);
  }
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
  return r;
}

}  // namespace

namespace {

// [WORK] The scale that makes a support's lengths coprime integers: k = lcm(denominators) / gcd(numerators) of every
// nonzero coordinate of its points, regions and pressure centre — when it shortens them by more than 200 bits (a scene
// written at 10^9990 or 10^-9990 is the same scene at 1; the scenes people write are left as they are, so their
// certificates keep their numbers). None when every coordinate is zero.
std::optional<Rational> shortening_scale(const Support& s) {
  Integer g = 0, l = 1;
  const auto see = [&](const Rational& x) {
    if (x == 0) return;
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), x.get_num_mpz_t());
    mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x.get_den_mpz_t());
  };
  for_each_coordinate(s, see);
  if (s.pressure_center) see(s.pressure_center->x), see(s.pressure_center->y);
  if (g == 0) return std::nullopt;
  const Rational k = Rational(l) / Rational(g);
  const long bits = static_cast<long>(mpz_sizeinbase(k.get_num_mpz_t(), 2)) +
                    static_cast<long>(mpz_sizeinbase(k.get_den_mpz_t(), 2));
  if (bits <= 200) return std::nullopt;
  return k;
}

}  // namespace

// A support whose lengths share a long common factor is decided in the frame that removes it (scaled_support), the
// witness mapped back (unscale); polygons built by the caller are in the scene's frame, so then it is decided as given.
Motion_answer decide_motion(const Support_model& model, const Vec3q& load, Mode mode, const Motion_options& options) {
  if (!options.polygons.model && !options.polygons.inner && !options.polygons.outer)
    if (const std::optional<Rational> k = shortening_scale(model.support())) {
      const Support t = scaled_support(model.support(), *k);
      Admissible a = model.admissible();
      a.rest_moment = scaled(a.rest_moment, *k);
      Motion_answer r = decide_motion(Support_model(t, std::move(a)), {load[0], load[1], load[2] * *k}, mode, options);
      unscale(r, *k);
      return r;
    }
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
