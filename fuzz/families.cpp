#include "fuzz/families.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/dual_cone.h"
#include "exact/equilibrium.h"
#include "float/float_kernel.h"

namespace wrenchkit::families {

const char* question_name(Question q) {
  switch (q) {
    case Question::force_closure: return "force_closure";
    case Question::form_closure: return "form_closure";
    case Question::equilibrium: return "equilibrium";
    case Question::all: return "all";
  }
  return "?";
}

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
    for (const Family& x : stress::families())
      if (x.uses_epsilon) out.push_back(x);
    return out;
  }();
  return f;
}

const Family* find(std::string_view name) {
  for (const Family& f : all())
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
  c.expected = decide(read_scene(c.text, Input_limits{}), f.question, Mode::exact).holds;
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
    const Reading reading = c.question == Question::force_closure ? Reading::friction : Reading::frictionless;
    const fl::Naive_kernel k(naive_generators(c.contacts, reading));
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
