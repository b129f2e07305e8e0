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
  }
  return "?";
}

std::string num(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

std::string scene_text(const std::vector<Spec>& cs, const Gravity& g) {
  std::string s = "{\"wrenchkit\": 1, ";
  if (g.present)
    s += "\"body\": {\"com\": [" + num(g.cx) + ", " + num(g.cy) + "]}, \"load\": {\"gravity\": " + num(g.w) + "}, ";
  s += "\"contacts\": [";
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const Spec& c = cs[i];
    s += (i ? ", " : "") + std::string("{\"at\": [") + num(c.ax) + ", " + num(c.ay) + "], \"normal\": [" + num(c.nx) +
         ", " + num(c.ny) + "], \"mu\": " + (c.mu_text.empty() ? num(c.mu) : "\"" + c.mu_text + "\"") + "}";
  }
  return s + "]}";
}

namespace {

double uni(std::mt19937_64& r, double a, double b) { return std::uniform_real_distribution<double>(a, b)(r); }

// Rotate, scale and translate a configuration (its exact structure is kept only up to rounding:
// that is the point — the decimal text is the scene).
std::vector<Spec> place(std::vector<Spec> cs, double angle, double tx, double ty, double scale) {
  const double c = std::cos(angle), s = std::sin(angle);
  for (Spec& k : cs) {
    const double x = k.ax * scale, y = k.ay * scale;
    k.ax = c * x - s * y + tx;
    k.ay = s * x + c * y + ty;
    const double nx = c * k.nx - s * k.ny, ny = s * k.nx + c * k.ny;
    k.nx = nx;
    k.ny = ny;
  }
  return cs;
}

std::vector<Family> make_families() {
  return {
      {"friction_threshold", "two fingers, μ = μ*·(1 ± ε): closure iff μ > μ*", Question::force_closure,
       [](std::mt19937_64& r, double eps, Gravity&) {
         const double y2 = uni(r, 0.6, 0.95), mu_star = (y2 - 0.5);  // d = (1, y2 − 1/2)
         const double mu = mu_star * (1 + ((r() & 1) ? eps : -eps));
         return place({{0, 0.5, 1, 0, mu}, {1, y2, -1, 0, mu}}, uni(r, 0, 6.28), uni(r, -5, 5), uni(r, -5, 5), 1);
       }},
      {"cone_edge", "two fingers, the segment between them ε (in slope) from the friction-cone edge",
       Question::force_closure,
       [](std::mt19937_64& r, double eps, Gravity&) {
         const double mu = uni(r, 0.2, 0.8), y2 = 0.5 + mu * (1 + ((r() & 1) ? eps : -eps));
         return place({{0, 0.5, 1, 0, mu}, {1, y2, -1, 0, mu}}, uni(r, 0, 6.28), uni(r, -5, 5), uni(r, -5, 5), 1);
       }},
      {"nearly_concurrent", "Example 3 frictionless: third normal ε off the common point (rank 2 vs 3)",
       Question::form_closure,
       [](std::mt19937_64& r, double eps, Gravity&) {
         const double off = (r() & 1) ? eps : -eps;
         return place({{1, 0, 0, 1, 0}, {0, 1, 1, 0, 0}, {3, 3 + off, -1, -1, 0}, {uni(r, 1.5, 2.5), 4, 0, -1, 0}},
                      uni(r, 0, 6.28), uni(r, -5, 5), uni(r, -5, 5), uni(r, 0.5, 2));
       }},
      {"nearly_parallel",
       "vertical-walls squeeze (integer offsets) with one wall tilted by ε: never closed, so the verdict does not "
       "flip; it shows exactly parallel exact walls certified next to an inexact one",
       Question::force_closure,
       [](std::mt19937_64& r, double eps, Gravity&) {
         const double t = (r() & 1) ? eps : -eps;
         return place({{-1, 1, 1, t, 0}, {-1, -1, 1, 0, 0}, {1, 1, -1, 0, 0}, {1, -1, -1, 0, 0}}, 0,
                      std::round(uni(r, -5, 5)), std::round(uni(r, -5, 5)), 1);
       }},
      {"huge_offset", "friction threshold ±ε, the grasp translated by 10^6 and scaled by 10^3", Question::force_closure,
       [](std::mt19937_64& r, double eps, Gravity&) {
         const double y2 = uni(r, 0.6, 0.95), mu_star = (y2 - 0.5);
         const double mu = mu_star * (1 + ((r() & 1) ? eps : -eps));
         return place({{0, 0.5, 1, 0, mu}, {1, y2, -1, 0, mu}}, uni(r, 0, 6.28), 1e6 * uni(r, 1, 2), -1e6 * uni(r, 1, 2),
                      1e3);
       }},
      {"ladder_equilibrium",
       "leaning square under gravity (equilibrium), μ = (1/7)·(1 ± ε) written as an exact fraction: balanced iff μ ≥ 1/7",
       Question::equilibrium,
       [](std::mt19937_64& r, double eps, Gravity& load) {
         // μ = (10^k ± 1) / (7·10^k) written as an exact fraction, ε = 10^-k; the naive reading
         // divides the two integers in double, as float code would.
         const int k = static_cast<int>(std::lround(-std::log10(eps)));
         const bool above = r() & 1;
         const std::string p = above ? "1" + std::string(k - 1, '0') + "1" : std::string(k, '9');
         const std::string q = "7" + std::string(k, '0');
         const double mu = std::strtod(p.c_str(), nullptr) / std::strtod(q.c_str(), nullptr);
         // Floor contact at (0,0) n=(0,1), wall contact at (−4,3) n=(1,0), the COM at (−1/2, 7/2).
         std::vector<Spec> cs{{0, 0, 0, 1, mu}, {-4, 3, 1, 0, mu}};
         cs[0].mu_text = cs[1].mu_text = p + "/" + q;
         load = Gravity{true, -0.5, 3.5, 1};
         return cs;
       }},
  };
}

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
  static const std::vector<Family> f = make_families();
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

Case make_case(const Family& f, double eps, std::mt19937_64& rng) {
  Case c;
  c.family = f.name;
  c.eps = eps;
  c.question = f.question;
  c.contacts = f.make(rng, eps, c.load);
  c.text = scene_text(c.contacts, c.load);
  c.expected = decide(read_scene(c.text, Input_limits{}), f.question, Mode::exact).holds;
  return c;
}

Case make_case(const Family& f, double eps, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
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

std::string random_grasp_text(int contacts, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> angle(0, 6.283185307179586), jitter(-0.3, 0.3), mu(0.1, 0.6);
  std::string t = "{\"wrenchkit\": 1, \"contacts\": [";
  for (int i = 0; i < contacts; ++i) {
    const double a = angle(rng), x = std::cos(a), y = std::sin(a);
    const double nx = -x + jitter(rng), ny = -y + jitter(rng), m = mu(rng);  // in this order on every compiler
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s{\"at\": [%.6f, %.6f], \"normal\": [%.6f, %.6f], \"mu\": %.3f}", i ? ", " : "", x,
                  y, nx, ny, m);
    t += buf;
  }
  return t + "]}";
}

}  // namespace wrenchkit::families
