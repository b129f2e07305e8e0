// [ST-1] Scene families (exact/stress_families.h): near-degenerate families and random scenes.
#include "exact/stress_families.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace wrenchkit::stress {

double Rng::unit() { return static_cast<double>(g_() >> 11) * (1.0 / 9007199254740992.0); }  // 2^-53

double Rng::uniform(double a, double b) { return a + (b - a) * unit(); }

int Rng::integer(int lo, int hi) {
  const std::uint64_t span = static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - lo) + 1;
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % span;  // reject the biased tail
  std::uint64_t x;
  do x = g_();
  while (x >= limit);
  return static_cast<int>(lo + static_cast<std::int64_t>(x % span));
}

std::string number_text(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

namespace {

// The contacts (and optional gravity) as scene text: decimal text of the doubles, as users write it.
std::string scene_text(const std::vector<Contact_spec>& cs, const Gravity_spec& g) {
  std::string s = "{\"wrenchkit\": 1, ";
  if (g.present)
    s += "\"body\": {\"com\": [" + number_text(g.cx) + ", " + number_text(g.cy) + "]}, \"load\": {\"gravity\": " +
         number_text(g.w) + "}, ";
  s += "\"contacts\": [";
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const Contact_spec& c = cs[i];
    s += (i ? ", " : "") + std::string("{\"at\": [") + number_text(c.ax) + ", " + number_text(c.ay) +
         "], \"normal\": [" + number_text(c.nx) + ", " + number_text(c.ny) + "], \"mu\": " +
         (c.mu_text.empty() ? number_text(c.mu) : "\"" + c.mu_text + "\"") + "}";
  }
  return s + "]}";
}

// Rotate by a random angle (rational parametrisation, then a random half-turn), scale, translate.
// Rounded in double on purpose: the decimal text of the result is the scene.
std::vector<Contact_spec> place(std::vector<Contact_spec> cs, Rng& r, double tx, double ty, double scale,
                                bool rotate = true) {
  double c = 1, s = 0;
  if (rotate) {
    const double t = r.uniform(-1, 1), d = 1 + t * t;
    c = (1 - t * t) / d;
    s = 2 * t / d;
    if (r.coin()) c = -c, s = -s;
  }
  for (Contact_spec& k : cs) {
    const double x = k.ax * scale, y = k.ay * scale;
    k.ax = c * x - s * y + tx;
    k.ay = s * x + c * y + ty;
    const double nx = c * k.nx - s * k.ny, ny = s * k.nx + c * k.ny;
    k.nx = nx;
    k.ny = ny;
  }
  return cs;
}

// The largest k ≥ 1 with 10^-k ≥ ε/2 (the power of ten nearest ε from below, for ε = 10^-k exactly).
int decimal_exponent(double eps) {
  int k = 0;
  for (double x = eps; x < 0.5 && k < 400; x *= 10) ++k;
  return k < 1 ? 1 : k;
}

std::string ladder_mu_text(int k, bool above) {
  // μ = (10^k ± 1) / (7·10^k): (1/7)(1 ± 10^-k), an exact fraction.
  const std::string p = above ? "1" + std::string(static_cast<std::size_t>(k - 1), '0') + "1"
                              : std::string(static_cast<std::size_t>(k), '9');
  return p + "/7" + std::string(static_cast<std::size_t>(k), '0');
}

// Random scenes: text built directly (numbers as a user types them).
std::string decimal(int thousandths) {
  const bool neg = thousandths < 0;
  const int a = neg ? -thousandths : thousandths;
  char b[32];
  std::snprintf(b, sizeof b, "%s%d.%03d", neg ? "-" : "", a / 1000, a % 1000);
  return b;
}

std::string random_support(Rng& r, bool grid) {
  const int k = r.integer(1, 4);
  static const char* mus[] = {"1/2", "1", "1/3", "0.3"};
  static const char* forces[] = {"1", "1/2", "2", "3/2"};
  std::string s = ", \"support\": {\"mu\": \"" + std::string(mus[r.integer(0, 3)]) + "\", \"points\": [";
  for (int i = 0; i < k; ++i) {
    const std::string x = grid ? std::to_string(r.integer(-2, 2)) : decimal(r.integer(-999, 999));
    const std::string y = grid ? std::to_string(r.integer(-2, 2)) : decimal(r.integer(-999, 999));
    s += (i ? ", " : "") + std::string("{\"at\": [") + x + ", " + y + "], \"force\": \"" + forces[r.integer(0, 3)] + "\"}";
  }
  return s + "]}";
}

std::string random_generic(Rng& r) {
  const int k = r.integer(3, 8);
  std::string s = "{\"wrenchkit\": 1, \"contacts\": [";
  for (int i = 0; i < k; ++i) {
    int nx = r.integer(-999, 999), ny = r.integer(-999, 999);
    if (nx == 0 && ny == 0) nx = 1;
    s += (i ? ", " : "") + std::string("{\"at\": [") + decimal(r.integer(-999, 999)) + ", " +
         decimal(r.integer(-999, 999)) + "], \"normal\": [" + std::to_string(nx) + ", " + std::to_string(ny) +
         "], \"mu\": " + decimal(r.integer(0, 800)) + "}";
  }
  s += "]";
  if (r.integer(0, 2) == 0)
    s += ", \"load\": {\"force\": [" + decimal(r.integer(-999, 999)) + ", " + decimal(r.integer(-999, 999)) +
         "], \"at\": [" + decimal(r.integer(-999, 999)) + ", " + decimal(r.integer(-999, 999)) + "]}";
  if (r.integer(0, 3) == 0) s += random_support(r, false);
  return s + "}";
}

std::string random_grid(Rng& r) {
  static const char* mus[] = {"0", "0", "1/4", "1/2", "1", "2", "1/3"};
  static const int normals[][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, 1},
                                   {1, -1}, {-1, -1}, {2, 1}, {1, 2}, {-2, 3}, {3, -1}};
  const int k = r.integer(0, 6);
  std::string s = "{\"wrenchkit\": 1, \"contacts\": [";
  for (int i = 0; i < k; ++i) {
    s += i ? ", " : "";
    if (r.integer(0, 11) == 0) {
      int w[3];
      do
        for (int& x : w) x = r.integer(-2, 2);
      while (w[0] == 0 && w[1] == 0 && w[2] == 0);
      s += "{\"wrench\": [" + std::to_string(w[0]) + ", " + std::to_string(w[1]) + ", " + std::to_string(w[2]) + "]}";
    } else {
      const auto& n = normals[r.integer(0, 11)];
      const int len = r.integer(1, 2);
      s += "{\"at\": [" + std::to_string(r.integer(-3, 3)) + ", " + std::to_string(r.integer(-3, 3)) +
           "], \"normal\": [" + std::to_string(n[0] * len) + ", " + std::to_string(n[1] * len) + "], \"mu\": \"" +
           mus[r.integer(0, 6)] + "\"}";
    }
  }
  s += "]";
  switch (r.integer(0, 3)) {
    case 0:
      s += ", \"load\": {\"force\": [" + std::to_string(r.integer(-2, 2)) + ", " + std::to_string(r.integer(-2, 2)) +
           "], \"at\": [" + std::to_string(r.integer(-3, 3)) + ", " + std::to_string(r.integer(-3, 3)) + "]}";
      break;
    case 1:
      s += ", \"load\": {\"wrench\": [" + std::to_string(r.integer(-2, 2)) + ", " + std::to_string(r.integer(-2, 2)) +
           ", " + std::to_string(r.integer(-2, 2)) + "]}";
      break;
    default: break;
  }
  if (r.integer(0, 3) == 0) s += random_support(r, true);
  return s + "}";
}

Family_scene near_degenerate(const Family& f, double eps, Rng& r) {
  Family_scene out;
  out.family = f.name;
  out.epsilon = eps;
  const std::string name = f.name;
  std::vector<Contact_spec>& cs = out.contacts;
  if (name == "friction_threshold" || name == "huge_offset") {
    // Two fingers, d = (1, y2 − 1/2): closure iff μ > μ* = y2 − 1/2.
    const double y2 = r.uniform(0.6, 0.95), mu_star = y2 - 0.5;
    out.above = r.coin();
    const double mu = mu_star * (1 + (out.above ? eps : -eps));
    const bool huge = name == "huge_offset";
    const double tx = huge ? 1e6 * r.uniform(1, 2) : r.uniform(-5, 5);
    const double ty = huge ? -1e6 * r.uniform(1, 2) : r.uniform(-5, 5);
    cs = place({{0, 0.5, 1, 0, mu, ""}, {1, y2, -1, 0, mu, ""}}, r, tx, ty, huge ? 1e3 : 1);
  } else if (name == "cone_edge") {
    const double mu = r.uniform(0.2, 0.8);
    out.above = r.coin();
    const double y2 = 0.5 + mu * (1 + (out.above ? eps : -eps));
    const double tx = r.uniform(-5, 5), ty = r.uniform(-5, 5);
    cs = place({{0, 0.5, 1, 0, mu, ""}, {1, y2, -1, 0, mu, ""}}, r, tx, ty, 1);
  } else if (name == "nearly_concurrent") {
    out.above = r.coin();
    const double off = out.above ? eps : -eps;
    const double x4 = r.uniform(1.5, 2.5), tx = r.uniform(-5, 5), ty = r.uniform(-5, 5), sc = r.uniform(0.5, 2);
    cs = place({{1, 0, 0, 1, 0, ""}, {0, 1, 1, 0, 0, ""}, {3, 3 + off, -1, -1, 0, ""}, {x4, 4, 0, -1, 0, ""}}, r, tx, ty,
               sc);
  } else if (name == "nearly_parallel") {
    out.above = r.coin();
    const double t = out.above ? eps : -eps;
    const double tx = static_cast<double>(r.integer(-5, 5)), ty = static_cast<double>(r.integer(-5, 5));
    cs = place({{-1, 1, 1, t, 0, ""}, {-1, -1, 1, 0, 0, ""}, {1, 1, -1, 0, 0, ""}, {1, -1, -1, 0, 0, ""}}, r, tx, ty, 1,
               false);
  } else if (name == "ladder_equilibrium") {
    // Floor contact at (0,0) n = (0,1), wall contact at (−4,3) n = (1,0), COM (−1/2, 7/2), μ written as
    // an exact fraction; the doubles are what float code gets by dividing the two integers.
    const int k = decimal_exponent(eps);
    out.above = r.coin();
    const std::string mu = ladder_mu_text(k, out.above);
    const std::size_t slash = mu.find('/');
    const double mu_d = std::strtod(mu.substr(0, slash).c_str(), nullptr) / std::strtod(mu.substr(slash + 1).c_str(), nullptr);
    cs = {{0, 0, 0, 1, mu_d, mu}, {-4, 3, 1, 0, mu_d, mu}};
    out.gravity = {true, -0.5, 3.5, 1};
  }
  out.text = scene_text(cs, out.gravity);
  return out;
}

}  // namespace

const std::vector<Family>& families() {
  static const std::vector<Family> f = {
      {"friction_threshold", "two fingers, μ = μ*·(1 ± ε): closure iff μ > μ*", Question::force_closure, true},
      {"cone_edge", "two fingers, the segment between them ε (in slope) from the friction-cone edge",
       Question::force_closure, true},
      {"nearly_concurrent", "Example 3 frictionless: third normal ε off the common point (rank 2 vs 3)",
       Question::form_closure, true},
      {"nearly_parallel",
       "vertical-walls squeeze (integer offsets) with one wall tilted by ε: never closed, so the verdict does not "
       "flip; it shows exactly parallel exact walls certified next to an inexact one",
       Question::force_closure, true},
      {"huge_offset", "friction threshold ±ε, the grasp translated by 10^6 and scaled by 10^3", Question::force_closure,
       true},
      {"ladder_equilibrium",
       "leaning square under gravity (equilibrium), μ = (1/7)·(1 ± ε) written as an exact fraction: balanced iff μ ≥ 1/7",
       Question::equilibrium, true},
      {"random_generic", "3–8 contacts with 3-decimal coordinates, integer normals and μ, sometimes a load or a support",
       Question::all, false},
      {"random_grid",
       "0–6 contacts on a small integer grid (axis and diagonal normals, μ ∈ {0, 1/4, 1/3, 1/2, 1, 2}, some wrench "
       "generators), sometimes a load or a support: exact degeneracies are frequent",
       Question::all, false},
  };
  return f;
}

const Family* find_family(std::string_view name) {
  for (const Family& f : families())
    if (name == f.name) return &f;
  return nullptr;
}

Family_scene make_scene(const Family& family, double epsilon, Rng& rng) {
  if (!family.uses_epsilon) {
    Family_scene out;
    out.family = family.name;
    out.text = std::string(family.name) == "random_generic" ? random_generic(rng) : random_grid(rng);
    return out;
  }
  if (!(epsilon > 0 && epsilon < 1))
    throw std::invalid_argument(std::string(family.name) + ": epsilon must be in (0, 1), got " + number_text(epsilon));
  return near_degenerate(family, epsilon, rng);
}

Family_scene make_scene(std::string_view family, double epsilon, std::uint64_t seed) {
  const Family* f = find_family(family);
  if (!f) throw std::invalid_argument("unknown scene family \"" + std::string(family) + "\"");
  Rng rng(seed);
  return make_scene(*f, epsilon, rng);
}

}  // namespace wrenchkit::stress
