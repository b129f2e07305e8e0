// [PU-1] Pushing: the voting theorem over F. See pushing.h.
#include "exact/sliding/pushing.h"

#include <set>

#include "core/contact_generators.h"
#include "core/voting_rule.h"
#include "float/push_twin.h"
#include "exact/io/input_error.h"

namespace wrenchkit {

const char* rotation_name(Rotation r) {
  switch (r) {
    case Rotation::ccw: return "ccw";
    case Rotation::cw: return "cw";
    case Rotation::none: return "none";
    case Rotation::depends: return "depends";
    case Rotation::undecided: return "undecided";
  }
  return "?";
}

const char* push_line_name(Push_line l) {
  switch (l) {
    case Push_line::left: return "left edge";
    case Push_line::right: return "right edge";
    case Push_line::velocity: return "velocity";
  }
  return "?";
}

std::optional<int> Push_vote::sign() const {
  if (value.lower_sign() == value.upper_sign()) return value.lower_sign();
  return std::nullopt;
}

Vec2 friction_center(const Support& s, const std::vector<Rational>& f) {
  Vec2 m{0, 0};
  Rational d = 0;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Rational w = s.mu_of(s.points[i]) * f[i];
    m.x += w * s.points[i].at.x, m.y += w * s.points[i].at.y, d += w;
  }
  for (const Support_region& r : s.regions) {
    const Rational& mu = s.mu_of(r);
    m.x += mu * r.moment.x, m.y += mu * r.moment.y, d += mu * r.total;
  }
  return {m.x / d, m.y / d};
}

Rotation voting_rule(int left, int right, int velocity) {
  const int s = voting_rule_sense(left, right, velocity);
  return s > 0 ? Rotation::ccw : s < 0 ? Rotation::cw : Rotation::none;
}

namespace {

// Σ coef_i f_i + constant over F (`lower_only`: its minimum alone, one LP; upper is then the lower bound too).
F_range range_over(const Support_model& model, const std::vector<Rational>& coef, const Rational& constant,
                   bool lower_only = false) {
  F_range r;
  if (model.known()) {  // (argmin and argmax empty: the one distribution, model.given())
    Rational& v = r.lower;
    v = constant;
    Rational t;
    for (std::size_t i = 0; i < coef.size(); ++i) {
      mpq_mul(t.get_mpq_t(), coef[i].get_mpq_t(), model.given()[i].get_mpq_t());
      v += t;
    }
    r.upper = v;
    return r;
  }
  std::vector<Rational> neg(coef.size());
  for (std::size_t i = 0; i < coef.size(); ++i) neg[i] = -coef[i];
  F_optimum lo = maximise_over(model.support(), model.admissible(), neg);
  r.lower = constant - lo.value;
  r.argmin = std::move(lo.distribution);
  r.dual_lower = lo.dual;
  if (lower_only) {
    r.upper = r.lower;
    return r;
  }
  F_optimum hi = maximise_over(model.support(), model.admissible(), coef);
  r.upper = hi.value + constant;
  r.argmax = std::move(hi.distribution);
  r.dual_upper = hi.dual;
  return r;
}

Rational value_at(const std::vector<Rational>& coef, const Rational& constant, const std::vector<Rational>& f) {
  Rational v = constant;
  for (std::size_t i = 0; i < coef.size(); ++i) v += coef[i] * f[i];
  return v;
}

// The twin on a support of points with every force given (the rationals rounded with certified bounds).
std::optional<Push_answer> twin_push(const Support_model& model, const Pusher& pusher, Push_answer a,
                                     const std::array<Vec2, 3>& dirs) {
  const Support& s = model.support();
  if (!a.known || !s.regions.empty()) return std::nullopt;
  fl::Push_twin_input in;
  const Contact& c = pusher.contact;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    in.x.push_back(to_bounded(s.points[i].at.x));
    in.y.push_back(to_bounded(s.points[i].at.y));
    in.w.push_back(to_bounded(s.mu_of(s.points[i])) * to_bounded(model.given()[i]));
  }
  in.px = to_bounded(c.at.x), in.py = to_bounded(c.at.y), in.nx = to_bounded(c.normal.x), in.ny = to_bounded(c.normal.y);
  in.mu = to_bounded(c.mu), in.vx = to_bounded(pusher.velocity.x), in.vy = to_bounded(pusher.velocity.y);
  const fl::Push_twin_answer t = fl::push_twin(in);
  if (!t.certain) return std::nullopt;
  a.by_twin = true;
  for (int k = 0; k < 3; ++k) {
    const Rational v(static_cast<int>(t.votes[k]));
    a.votes[k] = Push_vote{static_cast<Push_line>(k), dirs[k], F_range{v, v, {}, {}, {}, {}}};
  }
  const int l = static_cast<int>(t.votes[0]), r = static_cast<int>(t.votes[1]);
  a.rotation = voting_rule(l, r, static_cast<int>(t.votes[2]));
  a.why = "the float twin's certified signs (its error bounds decide every vote): " +
          std::string(l == r && l != 0 ? "both edges vote alike"
                      : l != 0 && r != 0 ? "the edges vote apart, the velocity decides"
                                         : "an edge passes through the centre of friction");
  return a;
}

}  // namespace

Push_answer decide_push(const Support_model& model, const Pusher& pusher, Mode mode) {
  const Support& s = model.support();
  const Contact& pc = pusher.contact;
  Push_answer a;
  a.at = pc.at, a.normal = pc.normal, a.velocity = pusher.velocity, a.mu = pc.mu;
  a.known = model.known();
  // The lines: the cone's edges by the contacts' one construction (both, μ = 0 too: then both are n), and v.
  std::array<Vec2, 2> edge;
  point_contact_generators(pc.at.x, pc.at.y, pc.normal.x, pc.normal.y, pc.mu, true, Reading::friction,
                           [&](Edge e, const Rational& fx, const Rational& fy, const Rational&) {
                             edge[e == Edge::left ? 0 : 1] = Vec2{fx, fy};
                           });
  const std::array<Vec2, 3> dirs{edge[0], edge[1], pusher.velocity};
  if (mode != Mode::exact) {
    if (std::optional<Push_answer> t = twin_push(model, pusher, a, dirs)) return *t;
    if (mode == Mode::float_only) {
      a.rotation = Rotation::undecided;
      a.votes_known = false;
      a.why = a.known && s.regions.empty()
                  ? "the float twin cannot decide (a vote within its error bound, or a translation that needs the "
                    "support's shape): use --mode hybrid or exact"
                  : "the float twin answers a support of points with every force given: use --mode hybrid or exact";
      return a;
    }
  }
  const std::size_t n = s.points.size();
  // D(f): the friction under the body.
  std::vector<Rational> coef(n);
  Rational constant = 0;
  for (std::size_t i = 0; i < n; ++i) coef[i] = s.mu_of(s.points[i]);
  for (const Support_region& r : s.regions) constant += s.mu_of(r) * r.total;
  a.friction = range_over(model, coef, constant, /*lower_only=*/true);  // (the certificate needs D > 0 only)
  if (a.friction.lower_sign() <= 0)
    throw Input_error(std::string("support: ") +
                      (a.known ? "no friction under the body (every support point with a force has mu = 0)"
                               : "a distribution of the support's forces puts the whole weight where mu = 0") +
                      ": nothing resists the pusher, so the body does not slide quasi-statically; give the support a "
                      "friction coefficient (support.mu)");
  // The centre of friction: known, or the same for every distribution when every coefficient is the same.
  std::set<Rational> mus;
  for (const Support_point& p : s.points) mus.insert(s.mu_of(p));
  for (const Support_region& r : s.regions) mus.insert(s.mu_of(r));
  if (a.known || mus.size() == 1) a.center = friction_center(s, a.known ? model.given() : a.friction.argmin);
  // The votes: N_d(f) = Σ μ_i f_i (p − r_i) × d + Σ_R μ_R (W_R p − M_R) × d.
  std::array<std::vector<Rational>, 3> vote_coef;
  std::array<Rational, 3> vote_constant;
  for (int k = 0; k < 3; ++k) {
    const Vec2& d = dirs[k];
    std::vector<Rational>& c = vote_coef[k];
    c.resize(n);
    for (std::size_t i = 0; i < n; ++i) c[i] = s.mu_of(s.points[i]) * cross(minus(pc.at, s.points[i].at), d);
    Rational k0 = 0;
    for (const Support_region& r : s.regions)
      k0 += s.mu_of(r) * cross(Vec2{r.total * pc.at.x - r.moment.x, r.total * pc.at.y - r.moment.y}, d);
    vote_constant[k] = k0;
    a.votes[k] = Push_vote{static_cast<Push_line>(k), d, range_over(model, c, k0)};
  }
  // Could all of some distribution's friction lie on one line through c, where the translation's point of the limit
  // surface has rotations in its normal cone (PU-1 §4)? Regions spread friction over an area; known points are tested.
  const auto line_friction = [&]() {
    for (const Support_region& r : s.regions)
      if (s.mu_of(r) != 0) return false;
    if (!a.known || !a.center) return true;  // (conservative over F)
    const Vec2 c = *a.center, d = minus(c, pc.at);
    std::optional<Vec2> dir;  // c = p: the line of the first point off c
    for (std::size_t i = 0; i < n; ++i) {
      if (s.mu_of(s.points[i]) == 0 || model.given()[i] == 0) continue;
      const Vec2 rc = minus(s.points[i].at, c);
      if (!is_zero(d)) {
        if (dot(rc, d) != 0) return false;
      } else if (!is_zero(rc)) {
        if (!dir) dir = rc;
        else if (cross(*dir, rc) != 0) return false;
      }
    }
    return true;
  };
  // Every sign each vote takes over F; the rule on every combination.
  std::array<std::vector<int>, 3> signs;
  for (int k = 0; k < 3; ++k)
    for (int t = -1; t <= 1; ++t)
      if (a.votes[k].value.lower_sign() <= t && t <= a.votes[k].value.upper_sign()) signs[k].push_back(t);
  std::set<Rotation> outcomes;
  bool smooth_needed = false;
  for (int l : signs[0])
    for (int r : signs[1])
      for (int v : signs[2]) {
        const Rotation o = voting_rule(l, r, v);
        outcomes.insert(o);
        smooth_needed |= o == Rotation::none && none_needs_smooth(l, r);
      }
  const auto vote_word = [](int t) { return t > 0 ? "ccw" : t < 0 ? "cw" : "through c"; };
  if (outcomes.size() == 1) {
    a.rotation = *outcomes.begin();
    const int l = signs[0][0], r = signs[1][0], v = signs[2].size() == 1 ? signs[2][0] : 2;
    if (a.rotation == Rotation::none && smooth_needed) {
      a.line_friction_possible = line_friction();
      if (a.line_friction_possible) {
        a.rotation = Rotation::undecided;
        a.why = "the rule says a translation (no rotation), but the support's friction may lie on one line through the "
                "centre of friction, where the limit surface has rotations at the translation's point: the motion, "
                "not the votes, decides";
        return a;
      }
    }
    if (signs[0].size() == 1 && signs[1].size() == 1 && l != 0 && l == r)
      a.why = std::string("both friction-cone edges pass the centre of friction on the same side (both vote ") +
              vote_word(l) + "): every force the pusher can apply turns the body " + vote_word(l);
    else if (signs[0].size() == 1 && signs[1].size() == 1 && l != 0 && r != 0)
      a.why = std::string("the edges vote apart (left ") + vote_word(l) + ", right " + vote_word(r) +
              "): the pusher's velocity decides" + (v == 0 ? " — it points at the centre of friction: the body translates"
                                                          : std::string(" — it votes ") + vote_word(v));
    else if (signs[0].size() == 1 && signs[1].size() == 1 && l == 0 && r == 0)
      a.why = "every line of the friction cone passes through the centre of friction: the body translates";
    else if (signs[0].size() == 1 && signs[1].size() == 1)
      a.why = std::string("one edge passes through the centre of friction, the other votes ") + vote_word(l ? l : r) +
              "; the velocity " + (a.rotation == Rotation::none ? "does not vote with it: the body translates along the "
                                                                  "line from the pusher to the centre"
                                                                : "votes with it");
    else
      a.why = "every distribution of the support's forces gives votes that turn the body the same way";
    return a;
  }
  // The votes change over F: the rule at the extreme distributions that bound them.
  std::vector<const std::vector<Rational>*> tried;  // (F has more than one distribution here: the LPs' optima)
  for (const Push_vote& v : a.votes) tried.push_back(&v.value.argmin), tried.push_back(&v.value.argmax);
  for (const std::vector<Rational>* f : tried) {
    int t[3];
    for (int k = 0; k < 3; ++k) t[k] = sgn(value_at(vote_coef[k], vote_constant[k], *f));
    const Rotation o = voting_rule(t[0], t[1], t[2]);
    if (o == Rotation::ccw && a.turns_ccw.empty()) a.turns_ccw = *f;
    if (o == Rotation::cw && a.turns_cw.empty()) a.turns_cw = *f;
  }
  if (!a.turns_ccw.empty() && !a.turns_cw.empty()) {
    a.rotation = Rotation::depends;
    a.why = "the centre of friction moves with the distribution (the coefficients differ and some forces are not "
            "given): one admissible distribution turns the body ccw, another cw";
    return a;
  }
  a.turns_ccw.clear(), a.turns_cw.clear();
  a.rotation = Rotation::undecided;
  a.why = "the votes change sign over the admissible distributions, and the extreme distributions tried do not turn "
          "the body opposite ways";
  return a;
}

}  // namespace wrenchkit
