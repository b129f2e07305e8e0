#include "fuzz/families.h"

#include "exact/sliding/region_sliding.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/dual_cone.h"
#include "exact/statics/equilibrium.h"
#include "exact/sliding/sliding.h"
#include "exact/sliding/strategies.h"
#include "float/float_kernel.h"
#include "float/limit_surface_twin.h"

namespace wrenchkit::families {

const char* question_name(Question q) {
  switch (q) {
    case Question::force_closure: return "force_closure";
    case Question::form_closure: return "form_closure";
    case Question::equilibrium: return "equilibrium";
    case Question::all: return "all";
    case Question::stick_slide: return "stick_slide";
    case Question::stick_slide_over: return "stick_slide_over";
    case Question::hold: return "hold";
    case Question::stick_slide_region: return "stick_slide_region";
    case Question::push: return "push";
    case Question::push_contact: return "push_contact";
    case Question::push_stable: return "push_stable";
  }
  return "?";
}

Reading reading_of(Question q) { return q == Question::form_closure ? Reading::frictionless : Reading::friction; }

namespace {

std::vector<fl::Bounded3> naive_generators(const std::vector<Spec>& cs, Reading reading) {
  std::vector<fl::Bounded_contact> b;
  for (const Spec& c : cs) {
    fl::Bounded_contact k;
    k.ax = fl::Bounded::exact(c.ax);
    k.ay = fl::Bounded::exact(c.ay);
    k.nx = fl::Bounded::exact(c.nx);
    k.ny = fl::Bounded::exact(c.ny);
    k.mu = fl::Bounded::exact(c.mu);
    k.frictional = c.mu != 0;
    b.push_back(k);
  }
  return fl::generators(b, reading);
}

}  // namespace

const std::vector<Family>& all() {
  static const std::vector<Family> f = [] {
    std::vector<Family> out;
    for (const char* name : {"friction_threshold", "cone_edge", "nearly_concurrent", "nearly_parallel", "huge_offset",
                             "ladder_equilibrium"})
      out.push_back(*stress::find_family(name));
    return out;
  }();
  return f;
}

const std::vector<Family>& report() {
  static const std::vector<Family> f = [] {
    std::vector<Family> out;
    for (const Family& x : stress::families())
      if (x.uses_epsilon) out.push_back(x);
    for (const Family& x : stress::report_only_families()) out.push_back(x);
    return out;
  }();
  return f;
}

const Family* find(std::string_view name) {
  for (const Family& f : report())
    if (name == f.name) return &f;
  return nullptr;
}

Verdict decide(const Scene& scene, Question q, Mode mode) {
  if (q == Question::equilibrium) {
    const Equilibrium_answer a = decide_equilibrium(scene, mode, false);
    return {a.decided, a.balanced};
  }
  const Closure_answer a =
      decide_closure(scene, q == Question::force_closure ? Property::force_closure : Property::form_closure, mode, false);
  return {a.decided, a.holds};
}

Case make_case(const Family& f, double eps, stress::Rng& rng) {
  stress::Family_scene fs = stress::make_scene(f, eps, rng);
  Case c;
  c.family = f.name;
  c.eps = eps;
  c.question = f.question;
  c.contacts = std::move(fs.contacts);
  c.load = fs.gravity;
  c.text = std::move(fs.text);
  c.known = fs.known;
  c.above = fs.above;
  c.untransformed = std::move(fs.untransformed);
  c.support = std::move(fs.support);
  c.allowed = fs.allowed;
  if (f.question == Question::stick_slide || f.question == Question::stick_slide_over ||
      f.question == Question::stick_slide_region) {
    for (std::size_t i = 0; i < 3; ++i) {
      std::string why;
      const std::string& t = fs.load_text[i];
      const bool quoted = t.size() >= 2 && t.front() == '"';
      c.motion_load[i] = *parse_rational(quoted ? std::string_view(t).substr(1, t.size() - 2) : std::string_view(t),
                                         !quoted, Input_limits{}, why);
    }
    c.motion_load_naive = fs.load;
  }
  c.expected = c.known || f.question == Question::stick_slide_over || f.question == Question::stick_slide_region
                   ? c.above : decide(read_scene(c.text, Input_limits{}), f.question, Mode::exact).holds;
  return c;
}

Case make_case(const Family& f, double eps, std::uint64_t seed) {
  stress::Rng rng(seed);
  return make_case(f, eps, rng);
}

std::vector<fl::Bounded3> naive_generators(const Case& c) {
  return naive_generators(c.contacts, c.question == Question::form_closure ? Reading::frictionless : Reading::friction);
}

bool naive_verdict(const Case& c) {
  if (c.question != Question::equilibrium) {
    const fl::Naive_kernel k(naive_generators(c.contacts, reading_of(c.question)));
    return compute_dual_cone(k).force_closure();
  }
  std::vector<fl::Bounded3> rows = naive_generators(c.contacts, Reading::friction);
  const std::size_t n = rows.size();
  const Gravity& g = c.load;
  rows.push_back({fl::Bounded::exact(0), fl::Bounded::exact(-g.w), fl::Bounded::exact(-g.w * g.cx)});
  const fl::Naive_kernel k(rows);
  const Dual_cone dc = compute_dual_cone(First_rows<fl::Naive_kernel>{k, n});
  if (dc.rank < 3) return false;  // naive code would not special-case it either; counts as a guess
  return load_balanced(k, dc, n) == Sign::positive;
}

Verdict decide_motion(const Case& c, const Scene& scene, Mode mode, int sides) {
  if (mode == Mode::float_only) {
    const fl::Motion_answer a = fl::classify_load(
        twin_support(merge_support(*scene.support)),
        {to_bounded(c.motion_load[0]), to_bounded(c.motion_load[1]), to_bounded(c.motion_load[2])});
    return {a.motion != fl::Motion_twin::undecided, a.motion == fl::Motion_twin::slides};
  }
  const Polygonal_ls model(merge_support(*scene.support), make_directions(sides));
  const Points_verdict d = points_verdict(model, c.motion_load, mode);
  return {d.motion != Motion::undecided, d.motion == Motion::slides};
}

namespace {

// f(q)/|q|∞ = (h(q) − q·p)/|q|∞ in plain doubles, h(q) = Σ ρ_i |v_i(q)|, v_i = (v_x − ω y_i, v_y + ω x_i).
double naive_gap(const std::vector<stress::Support_spec>& s, const std::array<double, 3>& p,
                 const std::array<double, 3>& q) {
  double h = 0;
  for (const stress::Support_spec& x : s) {
    const double vx = q[0] - q[2] * x.y, vy = q[1] + q[2] * x.x;
    h += x.mu * x.force * std::sqrt(vx * vx + vy * vy);
  }
  const double norm = std::fmax(std::fabs(q[0]), std::fmax(std::fabs(q[1]), std::fabs(q[2])));
  return (h - (q[0] * p[0] + q[1] * p[1] + q[2] * p[2])) / norm;
}

}  // namespace

bool naive_region_slides(const Case& c) {
  const Scene scene = read_scene(c.text, Input_limits{});
  const Support& s = *scene.support;
  const auto h = [&](const double* q) {
    double v = 0;
    if (!c.support.empty()) {  // forces not given: the naive even split (stress::Family_scene::support)
      for (const stress::Support_spec& x : c.support) v += x.mu * x.force * std::hypot(q[0] - q[2] * x.y, q[1] + q[2] * x.x);
    } else {
      for (const Support_point& p : s.points)
        v += s.mu_of(p).get_d() * p.force->get_d() *
             std::hypot(q[0] - q[2] * p.at.y.get_d(), q[1] + q[2] * p.at.x.get_d());
    }
    for (const Support_region& r : s.regions) v += s.mu_of(r).get_d() * region_power_double(r, q);
    return v;
  };
  const Vec3q p{Rational(c.motion_load_naive[0]), Rational(c.motion_load_naive[1]), Rational(c.motion_load_naive[2])};
  const Plane_minimum m = minimise_on_load_plane(p, h);
  return m.found && m.h <= 1;
}

bool naive_slides(const Case& c) {
  const std::array<double, 3>& p = c.motion_load_naive;
  std::array<double, 3> best{0, 0, 1};
  double f_best = naive_gap(c.support, p, best);
  const int n = 8;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = -1; side <= 1; side += 2)
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          std::array<double, 3> q;
          q[static_cast<std::size_t>(axis)] = side;
          q[static_cast<std::size_t>((axis + 1) % 3)] = -1 + (2 * i + 1) / double(n);
          q[static_cast<std::size_t>((axis + 2) % 3)] = -1 + (2 * j + 1) / double(n);
          const double f = naive_gap(c.support, p, q);
          if (f < f_best) f_best = f, best = q;
        }
  // Compass search: try ±step along each coordinate, keep any improvement (back on the cube's surface),
  // halve the step otherwise.
  int moves = 0;
  for (double step = 1.0 / n; step > 0x1p-60 && f_best > 0 && moves < 100000; ++moves) {
    bool improved = false;
    for (std::size_t k = 0; k < 3 && !improved; ++k)
      for (double sgn : {1.0, -1.0}) {
        std::array<double, 3> q = best;
        q[k] += sgn * step;
        const double f = naive_gap(c.support, p, q);
        if (f < f_best) {
          const double norm = std::fmax(std::fabs(q[0]), std::fmax(std::fabs(q[1]), std::fabs(q[2])));
          for (double& x : q) x /= norm;
          f_best = f, best = q, improved = true;
          break;
        }
      }
    if (!improved) step /= 2;
  }
  return f_best <= 0;
}

std::string labels_signature(const Moment_labels& l) {
  auto region = [](const Region& r) {
    return std::string(shape_name(r.shape)) + "/" + std::to_string(r.vertices.size()) + "/" +
           std::to_string(r.directions.size());
  };
  return region(l.plus) + " " + region(l.minus) + " both" + std::to_string(int(l.both.kind)) + " " +
         shape_name(l.infinity.shape) + "/" + std::to_string(l.infinity.extreme.size());
}

std::string labels_signature(const fl::Labels_twin& l) {
  auto region = [](const fl::Region2& r) {
    return std::string(fl::shape_name(r.shape)) + "/" + std::to_string(r.vertices.size()) + "/" +
           std::to_string(r.directions.size());
  };
  const Cone2::Shape inf[] = {Cone2::Shape::zero, Cone2::Shape::ray, Cone2::Shape::wedge, Cone2::Shape::plane};
  return region(l.plus) + " " + region(l.minus) + " both0 " + shape_name(inf[int(l.infinity.shape)]) + "/" +
         std::to_string(l.infinity.extreme.size());
}

std::string random_grasp_text(int contacts, stress::Rng& rng) {
  std::string t = "{\"wrenchkit\": 1, \"contacts\": [";
  for (int i = 0; i < contacts; ++i) {
    const double a = rng.uniform(0, 6.283185307179586), x = std::cos(a), y = std::sin(a);
    const double nx = -x + rng.uniform(-0.3, 0.3), ny = -y + rng.uniform(-0.3, 0.3), m = rng.uniform(0.1, 0.6);
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s{\"at\": [%.6f, %.6f], \"normal\": [%.6f, %.6f], \"mu\": %.3f}", i ? ", " : "", x,
                  y, nx, ny, m);
    t += buf;
  }
  return t + "]}";
}

}  // namespace wrenchkit::families
