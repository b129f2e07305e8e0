// [ST-1] Scene families (testing/stress_families.h): near-degenerate families and random scenes.
#include "testing/stress_families.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>

#include "exact/io/json.h"
#include "exact/io/json_writer.h"
#include "exact/io/scene.h"
#include "exact/numbers/rational.h"
#include "exact/sliding/region_sliding.h"

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

double naive_double(std::string_view text) {
  if (text.size() >= 2 && text.front() == '"' && text.back() == '"') text = text.substr(1, text.size() - 2);
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) return std::strtod(std::string(text).c_str(), nullptr);
  return std::strtod(std::string(text.substr(0, slash)).c_str(), nullptr) /
         std::strtod(std::string(text.substr(slash + 1)).c_str(), nullptr);
}

namespace {

// The contacts (and optional gravity) as scene text: decimal text of the doubles, as users write it.
std::string scene_text(const std::vector<Contact_spec>& cs, const Gravity_spec& g) {
  Json_writer w(128 + 128 * cs.size());
  w.object().member("wrenchkit", 1);
  if (g.present) {
    w.key("body").object().key("com").array().raw(number_text(g.cx)).raw(number_text(g.cy)).end_array().end_object();
    w.key("load").object().key("gravity").raw(number_text(g.w)).end_object();
  }
  w.key("contacts").array();
  for (const Contact_spec& c : cs) {
    w.object().key("at").array().raw(number_text(c.ax)).raw(number_text(c.ay)).end_array();
    w.key("normal").array().raw(number_text(c.nx)).raw(number_text(c.ny)).end_array().key("mu");
    c.mu_text.empty() ? w.raw(number_text(c.mu)) : w.string(c.mu_text);
    w.end_object();
  }
  return w.end_array().end_object().take();
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

// The member "support" of a random scene.
void write_random_support(Json_writer& w, Rng& r, bool grid) {
  const int k = r.integer(1, 4);
  static const char* mus[] = {"1/2", "1", "1/3", "0.3"};
  static const char* forces[] = {"1", "1/2", "2", "3/2"};
  w.key("support").object().member("mu", mus[r.integer(0, 3)]).key("points").array();
  for (int i = 0; i < k; ++i) {
    const std::string x = grid ? std::to_string(r.integer(-2, 2)) : decimal(r.integer(-999, 999));
    const std::string y = grid ? std::to_string(r.integer(-2, 2)) : decimal(r.integer(-999, 999));
    w.object().key("at").array().raw(x).raw(y).end_array().member("force", forces[r.integer(0, 3)]).end_object();
  }
  w.end_array().end_object();
}

// Random scenes draw the numbers of one contact (or load) last to first: the order the scenes were
// first generated in (string concatenation, evaluated right to left by GCC), which the seeds of the
// reference corpus and of recorded failures name.
std::string random_generic(Rng& r) {
  const int k = r.integer(3, 8);
  Json_writer w(1024);
  w.object().member("wrenchkit", 1).key("contacts").array();
  for (int i = 0; i < k; ++i) {
    int nx = r.integer(-999, 999), ny = r.integer(-999, 999);
    if (nx == 0 && ny == 0) nx = 1;
    const std::string mu = decimal(r.integer(0, 800)), ay = decimal(r.integer(-999, 999));
    const std::string ax = decimal(r.integer(-999, 999));
    w.object().key("at").array().raw(ax).raw(ay).end_array();
    w.key("normal").array().integer(nx).integer(ny).end_array().key("mu").raw(mu).end_object();
  }
  w.end_array();
  if (r.integer(0, 2) == 0) {
    std::string v[4];  // force x, y, at x, y
    for (int i = 3; i >= 0; --i) v[i] = decimal(r.integer(-999, 999));
    w.key("load").object().key("force").array().raw(v[0]).raw(v[1]).end_array();
    w.key("at").array().raw(v[2]).raw(v[3]).end_array().end_object();
  }
  if (r.integer(0, 3) == 0) write_random_support(w, r, false);
  return w.end_object().take();
}

std::string random_grid(Rng& r) {
  static const char* mus[] = {"0", "0", "1/4", "1/2", "1", "2", "1/3"};
  static const int normals[][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, 1},
                                   {1, -1}, {-1, -1}, {2, 1}, {1, 2}, {-2, 3}, {3, -1}};
  const int k = r.integer(0, 6);
  Json_writer w(1024);
  w.object().member("wrenchkit", 1).key("contacts").array();
  for (int i = 0; i < k; ++i) {
    if (r.integer(0, 11) == 0) {
      int x[3];
      do
        for (int& c : x) c = r.integer(-2, 2);
      while (x[0] == 0 && x[1] == 0 && x[2] == 0);
      w.object().key("wrench").array().integer(x[0]).integer(x[1]).integer(x[2]).end_array().end_object();
    } else {
      const auto& n = normals[r.integer(0, 11)];
      const int len = r.integer(1, 2);
      const char* mu = mus[r.integer(0, 6)];
      const int y = r.integer(-3, 3), x = r.integer(-3, 3);
      w.object().key("at").array().integer(x).integer(y).end_array();
      w.key("normal").array().integer(n[0] * len).integer(n[1] * len).end_array().member("mu", mu).end_object();
    }
  }
  w.end_array();
  switch (r.integer(0, 3)) {
    case 0: {
      const int ay = r.integer(-3, 3), ax = r.integer(-3, 3), fy = r.integer(-2, 2), fx = r.integer(-2, 2);
      w.key("load").object().key("force").array().integer(fx).integer(fy).end_array();
      w.key("at").array().integer(ax).integer(ay).end_array().end_object();
      break;
    }
    case 1: {
      int m[3];
      for (int i = 2; i >= 0; --i) m[i] = r.integer(-2, 2);
      w.key("load").object().key("wrench").array().integer(m[0]).integer(m[1]).integer(m[2]).end_array().end_object();
      break;
    }
    default: break;
  }
  if (r.integer(0, 3) == 0) write_random_support(w, r, true);
  return w.end_object().take();
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
  out.known = f.known;  // the ladder: exact fractions, balanced iff above for every ε
  return out;
}

// ---- The exact families (issue 6): built in exact rational arithmetic, answer known by construction ----

Integer power_of_ten(int k) {
  Integer r;
  mpz_ui_pow_ui(r.get_mpz_t(), 10, static_cast<unsigned long>(k));
  return r;
}

Rational ten_to(int k) { return k >= 0 ? Rational(power_of_ten(k)) : Rational(Integer(1), power_of_ten(-k)); }

// A random integer of exactly `digits` decimal digits.
Integer random_digits(Rng& r, int digits) {
  std::string s(static_cast<std::size_t>(digits), '0');
  for (int i = 0; i < digits; ++i) s[static_cast<std::size_t>(i)] = static_cast<char>('0' + r.integer(i ? 0 : 1, 9));
  return Integer(s);
}

// lo + (hi − lo)·N/(N + D) with random `digits`-digit N and D: a long fraction strictly inside (lo, hi).
Rational long_fraction(Rng& r, const Rational& lo, const Rational& hi, int digits) {
  const Integer n = random_digits(r, digits), d = random_digits(r, digits);
  Rational f(n, n + d);
  f.canonicalize();
  return lo + (hi - lo) * f;
}

// An integer in [lo, hi] over 10^decimals.
Rational short_decimal(Rng& r, int lo, int hi, int decimals) {
  Rational q(Integer(r.integer(lo, hi)), power_of_ten(decimals));
  q.canonicalize();
  return q;
}

// Exact text of a rational: an integer, a decimal (with an exponent when it is very large or small)
// when the denominator is 2^a·5^b, else a "p/q" string. Read back exactly by the engine.
std::string exact_text(const Rational& q) {
  Integer den = q.get_den();
  int twos = 0, fives = 0;
  while (mpz_divisible_ui_p(den.get_mpz_t(), 2)) den /= 2, ++twos;
  while (mpz_divisible_ui_p(den.get_mpz_t(), 5)) den /= 5, ++fives;
  if (den != 1) return json::quote(to_string(q));
  const int e = std::max(twos, fives);
  const Integer m = q.get_num() * (power_of_ten(e) / q.get_den());  // q = m·10^-e exactly
  std::string digits = Integer(abs(m)).get_str();
  int shift = -e;  // q = ±digits·10^shift
  while (digits.size() > 1 && digits.back() == '0') digits.pop_back(), ++shift;
  const std::string sign = m < 0 ? "-" : "";
  const int n = static_cast<int>(digits.size()), exponent = n - 1 + shift;
  if (exponent < -6 || exponent > 20)
    return sign + digits[0] + (n > 1 ? "." + digits.substr(1) : std::string()) + "e" + std::to_string(exponent);
  if (shift >= 0) return sign + digits + std::string(static_cast<std::size_t>(shift), '0');
  const int point = n + shift;  // digits before the decimal point
  if (point > 0)
    return sign + digits.substr(0, static_cast<std::size_t>(point)) + "." +
           digits.substr(static_cast<std::size_t>(point));
  return sign + "0." + std::string(static_cast<std::size_t>(-point), '0') + digits;
}

struct Exact_contact {
  Rational ax, ay, nx, ny, mu;
};

// The scene text of exact contacts (and an optional tail of members), and the doubles naive code
// reads from it.
std::string exact_scene_text(const std::vector<Exact_contact>& cs, std::vector<Contact_spec>* naive = nullptr) {
  Json_writer w(128 + 160 * cs.size());
  w.object().member("wrenchkit", 1).key("contacts").array();
  if (naive) naive->clear();
  for (const Exact_contact& c : cs) {
    const std::string ax = exact_text(c.ax), ay = exact_text(c.ay), nx = exact_text(c.nx), ny = exact_text(c.ny),
                      mu = exact_text(c.mu);
    w.object().key("at").array().raw(ax).raw(ay).end_array().key("normal").array().raw(nx).raw(ny).end_array();
    w.key("mu").raw(mu).end_object();
    if (naive)
      naive->push_back({naive_double(ax), naive_double(ay), naive_double(nx), naive_double(ny), naive_double(mu), ""});
  }
  return w.end_array().end_object().take();
}

// A rotation by exact rationals, c² + s² = 1.
struct Rotation {
  Rational c = 1, s = 0;
};
Rotation rotation_of(const Rational& t) {  // ((1 − t²), 2t)/(1 + t²)
  const Rational d = 1 + t * t;
  return {(1 - t * t) / d, 2 * t / d};
}
Rotation compose(const Rotation& a, const Rotation& b) { return {a.c * b.c - a.s * b.s, a.s * b.c + a.c * b.s}; }

// p ↦ scale·(R p + (tx, ty)), n ↦ R n: closure and equilibrium are invariant under each (exactly).
void transform(std::vector<Exact_contact>& cs, const Rotation& R, const Rational& tx, const Rational& ty,
               const Rational& scale) {
  for (Exact_contact& k : cs) {
    const Rational x = R.c * k.ax - R.s * k.ay + tx, y = R.s * k.ax + R.c * k.ay + ty;
    const Rational nx = R.c * k.nx - R.s * k.ny, ny = R.s * k.nx + R.c * k.ny;
    k.ax = scale * x;
    k.ay = scale * y;
    k.nx = nx;
    k.ny = ny;
  }
}

// μ·(10^k ± 1)/10^k: μ moved by the relative distance 10^-k, exactly.
Rational nudged(const Rational& mu, int k, bool above) {
  const Integer p = power_of_ten(k);
  return mu * Rational(p + (above ? 1 : -1), p);
}

// Two fingers A = (0, 1/2) with n = (1, 0) and B = (1, 1/2 + d) with n = (−1, 0), d = j/1000: the
// segment AB makes the angle atan d with both normals, so force closure ⇔ μ > μ* = d (Nguyen).
std::vector<Exact_contact> exact_pair(Rng& r, int k, bool above) {
  const Rational d = short_decimal(r, 100, 450, 3), half(1, 2), mu = nudged(d, k, above);
  return {{0, half, 1, 0, mu}, {1, half + d, -1, 0, mu}};
}

// The exact rotation by the angle of (3, 4)/5 taken j times (denominator 5^j: every coordinate stays a
// finite decimal), then a quarter turn q times.
Rotation decimal_rotation(Rng& r) {
  Rotation R;
  const int j = r.integer(0, 6), q = r.integer(0, 3);
  for (int i = 0; i < j; ++i) R = compose(R, {Rational(3, 5), Rational(4, 5)});
  for (int i = 0; i < q; ++i) R = compose(R, {0, 1});
  return R;
}

Family_scene exact_family(const Family& f, double eps, Rng& r) {
  Family_scene out;
  out.family = f.name;
  out.epsilon = eps;
  out.known = true;
  const std::string name = f.name;
  const int k = decimal_exponent(eps);
  out.above = r.coin();
  std::vector<Exact_contact> cs;
  if (name == "long_rational") {
    // A and B anywhere with 30-digit fractions; slope δ/w: force closure ⇔ μ > |δ|/w.
    const Rational xa = long_fraction(r, -5, 5, 30), ya = long_fraction(r, -5, 5, 30);
    const Rational w = long_fraction(r, Rational(1, 2), 2, 30),
                   delta = long_fraction(r, Rational(1, 20), Rational(3, 2), 30);
    const Rational dy = r.coin() ? delta : Rational(-delta), mu = nudged(delta / w, k, out.above);
    cs = {{xa, ya, 1, 0, mu}, {xa + w, ya + dy, -1, 0, mu}};
    if (r.coin()) transform(cs, {0, 1}, 0, 0, 1);  // a quarter turn: normals along ±y
  } else if (name == "rational_rotation") {
    cs = exact_pair(r, k, out.above);
    out.untransformed = exact_scene_text(cs);
    // t = a/b with 20-digit a and b: cos and sin with 40-digit numerators and denominators.
    const Integer a = random_digits(r, 20), b = random_digits(r, 20);
    Rational t(r.coin() ? a : Integer(-a), b);
    t.canonicalize();
    transform(cs, rotation_of(t), short_decimal(r, -5000, 5000, 3), short_decimal(r, -5000, 5000, 3), 1);
  } else if (name == "huge_scale" || name == "tiny_scale" || name == "beyond_double") {
    // Rotated exactly, moved by 10^3 times its size, scaled by 10^s: every number an exact decimal.
    cs = exact_pair(r, k, out.above);
    out.untransformed = exact_scene_text(cs);
    int s;
    if (name == "huge_scale") s = r.integer(250, 300);
    else if (name == "tiny_scale") s = -r.integer(250, 300);
    else s = r.coin() ? r.integer(310, 330) : -r.integer(330, 360);  // coordinates beyond 1.8e308 or below 5e-324
    const Rational tx = short_decimal(r, 500000, 1500000, 3) * (r.coin() ? 1 : -1);
    const Rational ty = short_decimal(r, 500000, 1500000, 3) * (r.coin() ? 1 : -1);
    transform(cs, decimal_rotation(r), tx, ty, ten_to(s));
  } else if (name == "many_contacts") {
    // n contacts on an arc of the unit circle at u(t) = ((1 − t²), 2t)/(1 + t²), inward normals. The two
    // end contacts (t1 < t2) carry μ, the others a smaller μ: the force directions of every contact lie
    // between the ends' outer friction edges, so force closure ⇔ the ends close ⇔ μ > tan(δ/2) =
    // (1 + t1·t2)/(t2 − t1) = μ*, δ = π − (θ2 − θ1) (proofs in docs/stability.md).
    const int n = r.integer(1000, 10000), j = r.integer(800, 1200);
    const Rational t1(-j, 1000), mu_star = short_decimal(r, 30, 100, 3);
    const Rational t2 = (1 + mu_star * t1) / (mu_star - t1), mu = nudged(mu_star, k, out.above);
    const Rational mu_small = short_decimal(r, 1, 20, 3);
    auto at = [](const Rational& t, const Rational& m) {
      const Rational d = 1 + t * t;
      const Integer p = t.get_num(), q = t.get_den();
      return Exact_contact{(1 - t * t) / d, 2 * t / d, Rational(p * p - q * q), Rational(-2 * p * q), m};
    };
    // The other contacts at distinct t = a/10^6 strictly between t1 = −j/1000 and t2: one at a random
    // place in each of n − 2 equal slots (no two coincide: coincident contacts would be an exact
    // degeneracy of their own, which the twin rightly declines).
    const Rational t2_scaled = t2 * 1000000;
    const Integer floor_t2 = t2_scaled.get_num() / t2_scaled.get_den();  // t2 > 0: truncation is the floor
    const long lo = -1000L * j + 1, hi = mpz_get_si(floor_t2.get_mpz_t()) - 1, slot = (hi - lo + 1) / (n - 2);
    cs.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n - 2; ++i) {
      const long a = lo + i * slot + static_cast<long>(r.bits() % static_cast<std::uint64_t>(slot));
      cs.push_back(at(Rational(a, 1000000), mu_small));
    }
    const std::size_t i1 = static_cast<std::size_t>(r.integer(0, n - 2));
    cs.insert(cs.begin() + static_cast<std::ptrdiff_t>(i1), at(t1, mu));
    const std::size_t i2 = static_cast<std::size_t>(r.integer(0, n - 1));
    cs.insert(cs.begin() + static_cast<std::ptrdiff_t>(i2), at(t2, mu));
  } else if (name == "collinear_support") {
    return out;  // filled by collinear_support()
  }
  out.text = exact_scene_text(cs, &out.contacts);
  return out;
}

// Support points r_i = c + d_i·R·u(t_i) with |t_i| ≈ 10^-k/2: at the exact distances |d_i| from c, and
// ≈ |d_i|·10^-k off the line through c along R·(1, 0). For the rotation about c, q = (c_y, −c_x, 1),
// v_i = perp(r_i − c) has the rational length |d_i|, so the load p(q) = Σ ρ_i (v̂_i, r_i × v̂_i) on the
// limit surface is rational; the question's load is p(q)·(1 ± 10^-k): outside LS (slides) above,
// inside (sticks) below, since LS is convex with 0 inside.
Family_scene collinear_support(const Family& f, double eps, Rng& r) {
  Family_scene out;
  out.family = f.name;
  out.epsilon = eps;
  out.known = true;
  const int k = decimal_exponent(eps);
  out.above = r.coin();
  const Rational cx = short_decimal(r, -2000, 2000, 3), cy = short_decimal(r, -2000, 2000, 3);
  const Rotation R = rotation_of(short_decimal(r, -1000, 1000, 3));
  const int points = r.integer(3, 6);
  const Rational rho_per_force(1, 2);
  Rational px = 0, py = 0, pm = 0;
  Json_writer w(256 + 96 * static_cast<std::size_t>(points));
  w.object().member("wrenchkit", 1).key("contacts").array().end_array();
  w.key("support").object().member("mu", "1/2").key("points").array();
  for (int i = 0; i < points; ++i) {
    const Rational d = short_decimal(r, 200, 2000, 3) * (r.coin() ? 1 : -1);
    const Rational t = short_decimal(r, 500, 1000, 3) * (r.coin() ? 1 : -1) / (2 * ten_to(k));
    const Rotation u = compose(R, rotation_of(t));
    const Rational x = cx + d * u.c, y = cy + d * u.s;
    const int force = r.integer(1, 5);
    const Rational rho = rho_per_force * force;
    // v̂ = sign(d)·perp(u) = sign(d)·(−u_s, u_c).
    const Rational vx = d > 0 ? Rational(-u.s) : u.s, vy = d > 0 ? u.c : Rational(-u.c);
    px += rho * vx;
    py += rho * vy;
    pm += rho * (x * vy - y * vx);
    const std::string xt = exact_text(x), yt = exact_text(y);
    w.object().key("at").array().raw(xt).raw(yt).end_array().member("force", force).end_object();
    out.support.push_back({naive_double(xt), naive_double(yt), static_cast<double>(force), 0.5});
  }
  out.text = w.end_array().end_object().end_object().take();
  const Rational p[3] = {nudged(px, k, out.above), nudged(py, k, out.above), nudged(pm, k, out.above)};
  for (int i = 0; i < 3; ++i) {
    out.load_text[static_cast<std::size_t>(i)] = exact_text(p[i]);
    out.load[static_cast<std::size_t>(i)] = naive_double(out.load_text[static_cast<std::size_t>(i)]);
  }
  return out;
}

// ---- region_support: stick/slide on a support region [RG-1] -----------------------------------------------

// Family "region_support". A support region — a rectangle or a triangle on a short-decimal grid, sometimes with a
// triangular hole (the outline's shape shrunk by 1/4 about its centroid: strictly inside a convex outline), a
// uniform or a linear pressure — sometimes with a support point, and the translation along a Pythagorean
// direction v̂ = (a, b)/c. Its load p* = μf0 (v̂, c_f × v̂) through the friction centroid c_f is exactly on the
// limit surface (p* = ∂h(v̂), and the region makes the surface strictly convex). The load is p*(1 ± ε): above,
// q = (v̂, 0) has q·p = (1 + ε) μf0 > h(q) = μf0: it slides; below, (1 − ε)p* is inside (0 is interior and the
// set convex): it sticks. Known by construction for every ε; the naive guess searches h in double.
//
// Family "region_legs" (regions with points whose force is not given, RG-3): the same region with 1–3 legs whose
// forces are not given, `weight` W and `pressure_center` c those of one admissible distribution (random forces
// 1–4 placed the centre), one μ for all. A translation moves every point at speed |v̂| = 1, so every admissible
// distribution f has h_f(v̂, 0) = μW and the same friction centroid c (Σ f_i r_i + Σ_R M_R = W c for all of F): p*
// is on every limit surface of F at once. Above, (v̂, 0) proves it slides for every distribution (the LP over F is
// constant); below, (1 − ε)p* is inside every LS(f): sticks for every one. Known by construction for every ε.
Family_scene region_support(const Family& fam, double eps, Rng& r) {
  const int k = decimal_exponent(eps);
  const bool legs = std::string(fam.name) == "region_legs";
  for (;;) {
    Family_scene out;
    out.family = fam.name;
    out.epsilon = eps;
    out.known = true;
    out.above = r.coin();
    std::vector<std::pair<Rational, Rational>> poly;
    const Rational x0 = short_decimal(r, -2000, 1000, 3), y0 = short_decimal(r, -2000, 1000, 3);
    if (r.coin()) {
      const Rational w = short_decimal(r, 100, 3000, 3), h = short_decimal(r, 100, 3000, 3);
      poly = {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
    } else {
      for (int i = 0; i < 3; ++i) poly.push_back({short_decimal(r, -2000, 2000, 3), short_decimal(r, -2000, 2000, 3)});
      const auto& [a, b] = poly[0];
      const Rational cross = (poly[1].first - a) * (poly[2].second - b) - (poly[1].second - b) * (poly[2].first - a);
      if (cross == 0) continue;
    }
    Rational gx = 0, gy = 0;
    for (const auto& [x, y] : poly) gx += x, gy += y;
    gx /= static_cast<long>(poly.size()), gy /= static_cast<long>(poly.size());
    static const char* mus[] = {"1/2", "1", "1/3", "3/4"};
    const char* mu = mus[r.integer(0, 3)];
    struct Point {
      Rational x, y, force;
    };
    std::vector<Point> points;  // region_support: at most one, its force given; region_legs: 1–3 legs
    if (legs) {
      const int n = r.integer(1, 3);
      for (int i = 0; i < n; ++i) {
        const Rational x = short_decimal(r, -3000, 3000, 3), y = short_decimal(r, -3000, 3000, 3);
        points.push_back({x, y, Rational(r.integer(1, 4))});
      }
    } else if (r.integer(0, 2) == 0) {
      const Rational x = short_decimal(r, -3000, 3000, 3), y = short_decimal(r, -3000, 3000, 3);
      points.push_back({x, y, Rational(r.integer(1, 4))});
    }
    const bool hole = r.coin(), uniform = r.coin();
    Rational force, c0, c1, c2;
    if (uniform) {
      force = short_decimal(r, 100, 5000, 3);
    } else {  // p = c0 + c1 x + c2 y, positive on the outline (|x|, |y| ≤ 5)
      c1 = short_decimal(r, -1000, 1000, 3), c2 = short_decimal(r, -1000, 1000, 3);
      c0 = 5 * (abs(c1) + abs(c2)) + short_decimal(r, 100, 2000, 3);
    }
    // The scene's text: the points' forces given, or (region_legs) not given, with the weight and the centre.
    const auto write = [&](const Rational* weight, const Vec2* center) {
      Json_writer w(1024);
      w.object().member("wrenchkit", 1).member("name", fam.name).key("support").object();
      w.key("mu").raw(json::quote(mu));
      if (weight) w.key("weight").raw(exact_text(*weight));
      if (center) w.key("pressure_center").array().raw(exact_text(center->x)).raw(exact_text(center->y)).end_array();
      if (!points.empty()) {
        w.key("points").array();
        for (const Point& pt : points) {
          w.object().key("at").array().raw(exact_text(pt.x)).raw(exact_text(pt.y)).end_array();
          if (!weight) w.key("force").raw(exact_text(pt.force));
          w.end_object();
        }
        w.end_array();
      }
      w.key("regions").array().object().key("outline").array();
      for (const auto& [x, y] : poly) w.array().raw(exact_text(x)).raw(exact_text(y)).end_array();
      w.end_array();
      if (hole) {
        w.key("holes").array().array();
        for (std::size_t i = 0; i < 3; ++i) {
          const auto& [x, y] = poly[i];
          w.array().raw(exact_text(gx + (x - gx) / 4)).raw(exact_text(gy + (y - gy) / 4)).end_array();
        }
        w.end_array().end_array();
      }
      if (uniform) {
        w.member("pressure", "uniform").key("force").raw(exact_text(force));
      } else {
        w.key("pressure").object().key("linear").array().raw(exact_text(c0)).raw(exact_text(c1)).raw(exact_text(c2));
        w.end_array().end_object();
      }
      w.end_object().end_array().end_object().end_object();
      return w.take();
    };
    out.text = write(nullptr, nullptr);
    const Scene scene = read_scene(out.text, Input_limits{}, fam.name);
    const Region_sliding st = region_sliding(*scene.support, std::nullopt, 1);
    if (legs) {
      // The legs' forces dropped: W and c are every admissible distribution's; the naive reading splits the rest.
      out.text = write(&st.total_force, &st.center_of_pressure);
      Rational legs_force = 0;
      for (const Point& pt : points) legs_force += pt.force;
      const double split = Rational(legs_force / static_cast<long>(points.size())).get_d();
      const double mu_d = Rational(mu).get_d();
      for (const Point& pt : points) out.support.push_back({pt.x.get_d(), pt.y.get_d(), split, mu_d});
      out.allowed = out.above ? answer_slides : answer_sticks;
    }
    static const int triples[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {1, 0, 1}, {0, 1, 1}};
    const auto& t = triples[r.integer(0, 5)];
    Rational vx(t[0], t[2]), vy(t[1], t[2]);
    if (r.coin()) std::swap(vx, vy);
    if (r.coin()) vx = -vx;
    if (r.coin()) vy = -vy;
    const Rational& cx = st.friction_centroid.x;
    const Rational& cy = st.friction_centroid.y;
    const Rational s = 1 + (out.above ? Rational(1) : Rational(-1)) * ten_to(-k);
    const Rational p[3] = {st.mu_f0 * vx * s, st.mu_f0 * vy * s, st.mu_f0 * (cx * vy - cy * vx) * s};
    for (int i = 0; i < 3; ++i) {
      out.load_text[static_cast<std::size_t>(i)] = exact_text(p[i]);
      out.load[static_cast<std::size_t>(i)] = naive_double(out.load_text[static_cast<std::size_t>(i)]);
    }
    return out;
  }
}

// ---- unknown_support: stick/slide over every admissible distribution ---------------------------------------

struct Leg {
  Rational x, y, mu, force;  // force: given, or the one that placed the centre of pressure (random supports)
  bool known = false;
};

// The admissible distributions' vertices by brute force, independently of the engine: every set of 1–3 unknown
// forces solving Σ f = W', Σ f r = M' (the rest after the given forces) with f ≥ 0, each once.
std::vector<std::vector<Rational>> brute_vertices(const std::vector<Leg>& legs, const Rational& w,
                                                  const Rational& cx, const Rational& cy) {
  Rational rw = w, rx = w * cx, ry = w * cy;
  std::vector<std::size_t> u;
  std::vector<Rational> base(legs.size());
  for (std::size_t i = 0; i < legs.size(); ++i) {
    if (!legs[i].known) {
      u.push_back(i);
      continue;
    }
    base[i] = legs[i].force;
    rw -= legs[i].force, rx -= legs[i].force * legs[i].x, ry -= legs[i].force * legs[i].y;
  }
  std::vector<std::vector<Rational>> out;
  const auto offer = [&](const std::vector<std::pair<std::size_t, Rational>>& sol) {
    std::vector<Rational> f = base;
    Rational sw = 0, sx = 0, sy = 0;
    for (const auto& [i, v] : sol) {
      if (v < 0) return;
      f[i] = v, sw += v, sx += v * legs[i].x, sy += v * legs[i].y;
    }
    if (sw != rw || sx != rx || sy != ry) return;
    for (const auto& g : out)
      if (g == f) return;
    out.push_back(std::move(f));
  };
  for (std::size_t a = 0; a < u.size(); ++a) {
    offer({{u[a], rw}});
    for (std::size_t b = a + 1; b < u.size(); ++b) {
      const Leg &A = legs[u[a]], &B = legs[u[b]];
      const Rational dx = B.x - A.x, dy = B.y - A.y;
      if (dx != 0 || dy != 0) {
        const Rational fb = dx != 0 ? (rx - rw * A.x) / dx : (ry - rw * A.y) / dy;
        offer({{u[a], rw - fb}, {u[b], fb}});
      }
      for (std::size_t c = b + 1; c < u.size(); ++c) {
        const Leg& C = legs[u[c]];
        // Cramer on the columns (1, x, y) of A, B, C.
        const Rational det = (B.x - A.x) * (C.y - A.y) - (C.x - A.x) * (B.y - A.y);
        if (det == 0) continue;
        const auto area = [](const Rational& px, const Rational& py, const Leg& P, const Leg& Q) -> Rational {
          return (P.x - px) * (Q.y - py) - (Q.x - px) * (P.y - py);
        };
        // Barycentric coordinates of the rest's centre (rx, ry)/rw, times rw.
        const Rational gx = rx / (rw == 0 ? Rational(1) : rw), gy = ry / (rw == 0 ? Rational(1) : rw);
        if (rw == 0) continue;
        offer({{u[a], rw * area(gx, gy, B, C) / det},
               {u[b], rw * area(gx, gy, C, A) / det},
               {u[c], rw * area(gx, gy, A, B) / det}});
      }
    }
  }
  if (u.empty() || rw == 0) offer({});
  return out;
}

// Friction at two distinct points at least (else the limit surface is flat and nothing sticks on it).
bool two_points(const std::vector<Leg>& legs, const std::vector<Rational>& f) {
  const Leg* first = nullptr;
  for (std::size_t i = 0; i < legs.size(); ++i) {
    if (legs[i].mu * f[i] == 0) continue;
    if (first && (first->x != legs[i].x || first->y != legs[i].y)) return true;
    if (!first) first = &legs[i];
  }
  return false;
}

// ⌊√n⌋ for n ≥ 0.
Integer isqrt(const Integer& n) {
  Integer r;
  mpz_sqrt(r.get_mpz_t(), n.get_mpz_t());
  return r;
}

// Family "unknown_support". A support (random 4–8 points with a few forces given, the table (±1, ±1) or the
// dinner plate, every force unknown), a twist q and one admissible distribution f — the vertex of F with the
// largest power h_f(q) (its limit surface touches the union U of all of them there), the one with the smallest,
// or any — not flat. With rational l_i ≤ 1/|v_i(q)| (D = k + 6 digits), the forces g_i = μ_i f_i l_i v_i are
// inside the discs, and p̂ = Σ (g_i, r_i × g_i) lies within 10^-D of the boundary point of LS(f) for q. The
// load is p̂·(1 ± 10^-k): below, the forces (1 − 10^-k) g_i hold it strictly inside LS(f): f sticks, so the
// answer is sticks or depends; above, q·p > Σ μ_i f_i u_i with u_i ≥ |v_i| (checked here exactly): f slides —
// and for the largest vertex q·p exceeds every vertex's bound, so the load slides for every distribution.
Family_scene unknown_support(const Family& fam, double eps, Rng& r) {
  const int k = decimal_exponent(eps), digits = k + 6;
  for (;;) {
    Family_scene out;
    out.family = fam.name;
    out.epsilon = eps;
    out.known = true;
    out.above = r.coin();
    const int shape = r.integer(0, 3);  // 0, 1: random; 2: the table; 3: the plate
    std::vector<Leg> legs;
    Rational w = 1, cx = 0, cy = 0;
    std::string support_mu;
    if (shape >= 2) {
      static const int rim[][2][2] = {{{1, 1}, {0, 1}},  {{3, 5}, {4, 5}},  {{0, 1}, {1, 1}},  {{-3, 5}, {4, 5}},
                                      {{-1, 1}, {0, 1}}, {{-3, 5}, {-4, 5}}, {{0, 1}, {-1, 1}}, {{3, 5}, {-4, 5}},
                                      {{0, 1}, {0, 1}}};
      if (shape == 2)
        for (const auto& [x, y] : {std::pair{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}) legs.push_back({x, y, 1, 0});
      else
        for (const auto& p : rim) legs.push_back({Rational(p[0][0], p[0][1]), Rational(p[1][0], p[1][1]), 1, 0});
      support_mu = "1";
    } else {
      const int n = r.integer(4, 8);
      static const char* mus[] = {"1/2", "1", "1/3", "3/4"};
      support_mu = mus[r.integer(0, 3)];
      Rational sw = 0, sx = 0, sy = 0;
      for (int i = 0; i < n; ++i) {
        Leg g{short_decimal(r, -1000, 1000, 3), short_decimal(r, -1000, 1000, 3), 0, r.integer(1, 5), false};
        g.mu = r.integer(0, 3) == 0 ? Rational(r.integer(1, 8), 4) : Rational(0);  // 0: the support's μ
        g.known = r.integer(0, 2) == 0;
        sw += g.force, sx += g.force * g.x, sy += g.force * g.y;
        legs.push_back(g);
      }
      legs[static_cast<std::size_t>(r.integer(0, n - 1))].known = false;
      w = sw, cx = sx / sw, cy = sy / sw;
    }
    Rational support_mu_q;
    {
      const std::size_t slash = support_mu.find('/');
      support_mu_q = slash == std::string::npos ? Rational(std::stoi(support_mu))
                                                : Rational(std::stoi(support_mu.substr(0, slash)),
                                                           std::stoi(support_mu.substr(slash + 1)));
    }
    for (Leg& g : legs)
      if (g.mu == 0) g.mu = support_mu_q;
    const std::vector<std::vector<Rational>> vs = brute_vertices(legs, w, cx, cy);
    // The twist (a translation a quarter of the time) and each point's speed, bracketed.
    const Rational q0 = short_decimal(r, -1000, 1000, 3), q1 = short_decimal(r, -1000, 1000, 3),
                   q2 = r.integer(0, 3) == 0 ? Rational(0) : short_decimal(r, -1000, 1000, 3);
    std::vector<Rational> vx, vy, lower_inv, upper;
    bool still = false;
    const Integer scale = power_of_ten(digits);
    for (const Leg& g : legs) {
      vx.push_back(q0 - q2 * g.y);
      vy.push_back(q1 + q2 * g.x);
      const Rational s2 = vx.back() * vx.back() + vy.back() * vy.back();
      if (s2 == 0) still = true;
      // √s2 = √(n·d)/d: S = ⌊√(n·d)·10^D⌋, so S/(d·10^D) ≤ √s2 ≤ (S + 1)/(d·10^D).
      const Integer n = s2.get_num(), d = s2.get_den(), S = isqrt(n * d * scale * scale);
      const Rational hi(S + 1, d * scale);
      upper.push_back(hi);
      Rational inv(Integer(d * scale * scale) / (S + 1), scale);  // ⌊10^D/hi⌋/10^D ≤ 1/hi ≤ 1/|v|
      inv.canonicalize();
      lower_inv.push_back(inv);
    }
    if (still) continue;  // a rotation about a support point: its friction direction is free; draw again
    const auto power_bound = [&](const std::vector<Rational>& f) {
      Rational h = 0;
      for (std::size_t i = 0; i < legs.size(); ++i) h += legs[i].mu * f[i] * upper[i];
      return h;
    };
    const int which = r.integer(0, 2);  // 0: the largest power (U's boundary); 1: the smallest; 2: any vertex
    std::size_t pick = 0;
    std::vector<std::size_t> usable;
    for (std::size_t i = 0; i < vs.size(); ++i)
      if (two_points(legs, vs[i])) usable.push_back(i);
    if (usable.empty()) continue;
    pick = usable[static_cast<std::size_t>(r.integer(0, static_cast<int>(usable.size()) - 1))];
    if (which < 2) {
      for (std::size_t i : usable) {
        const Rational a = power_bound(vs[i]), b = power_bound(vs[pick]);
        if (which == 0 ? a > b : a < b) pick = i;
      }
      if (which == 0) {  // the largest among all vertices, flat ones included
        bool largest = true;
        for (const auto& g : vs) largest &= power_bound(g) <= power_bound(vs[pick]);
        if (!largest) continue;
      }
    }
    const std::vector<Rational>& f = vs[pick];
    Rational px = 0, py = 0, pm = 0;
    for (std::size_t i = 0; i < legs.size(); ++i) {
      const Rational c = legs[i].mu * f[i] * lower_inv[i];
      const Rational gx = c * vx[i], gy = c * vy[i];
      px += gx, py += gy, pm += legs[i].x * gy - legs[i].y * gx;
    }
    const Rational p[3] = {nudged(px, k, out.above), nudged(py, k, out.above), nudged(pm, k, out.above)};
    const Rational qp = q0 * p[0] + q1 * p[1] + q2 * p[2];
    if (out.above) {
      if (qp <= power_bound(f)) continue;  // not proved outside LS(f) (never seen: the margin is 10^-k vs 10^-D)
      bool every = which == 0;
      if (every)
        for (const auto& g : vs) every &= qp > power_bound(g);
      out.allowed = every ? answer_slides : (answer_slides | answer_depends);
    } else {
      out.allowed = answer_sticks | answer_depends;
    }
    // The text: the support's μ, the points (a force where given), the weight and the centre of pressure.
    Json_writer jw(256 + 96 * legs.size());
    jw.object().member("wrenchkit", 1).key("contacts").array().end_array();
    jw.key("support").object().key("mu").raw(exact_text(support_mu_q)).key("weight").raw(exact_text(w));
    jw.key("pressure_center").array().raw(exact_text(cx)).raw(exact_text(cy)).end_array().key("points").array();
    Rational rest = w;
    int unknown = 0;
    for (const Leg& g : legs) {
      if (g.known) rest -= g.force;
      unknown += !g.known;
    }
    for (const Leg& g : legs) {
      const std::string xt = exact_text(g.x), yt = exact_text(g.y);
      jw.object().key("at").array().raw(xt).raw(yt).end_array();
      if (g.mu != support_mu_q) jw.key("mu").raw(exact_text(g.mu));
      if (g.known) jw.key("force").raw(exact_text(g.force));
      jw.end_object();
      const Rational naive_force = g.known ? g.force : rest / unknown;  // the "natural" even split
      out.support.push_back({naive_double(xt), naive_double(yt), naive_double(exact_text(naive_force)),
                             naive_double(exact_text(g.mu))});
    }
    out.text = jw.end_array().end_object().end_object().take();
    for (int i = 0; i < 3; ++i) {
      out.load_text[static_cast<std::size_t>(i)] = exact_text(p[i]);
      out.load[static_cast<std::size_t>(i)] = naive_double(out.load_text[static_cast<std::size_t>(i)]);
    }
    return out;
  }
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
       Question::equilibrium, true, true},
      {"random_generic", "3–8 contacts with 3-decimal coordinates, integer normals and μ, sometimes a load or a support",
       Question::all, false},
      {"random_grid",
       "0–6 contacts on a small integer grid (axis and diagonal normals, μ ∈ {0, 1/4, 1/3, 1/2, 1, 2}, some wrench "
       "generators), sometimes a load or a support: exact degeneracies are frequent",
       Question::all, false},
      // Issue 6: exact by construction (the answer is `above` for every ε).
      {"long_rational",
       "two fingers anywhere, coordinates 30-digit fractions, μ = μ*·(1 ± ε) exactly (μ* = |δ|/w, a 60-digit "
       "fraction): closure iff μ > μ*",
       Question::force_closure, true, true},
      {"rational_rotation",
       "exact two-finger threshold μ = d·(1 ± ε) turned by the exact rotation ((1−t²), 2t)/(1+t²), t = a/b with "
       "20-digit a, b (40-digit coordinates)",
       Question::force_closure, true, true},
  };
  return f;
}

const std::vector<Family>& report_only_families() {
  static const std::vector<Family> f = {
      {"huge_scale",
       "exact two-finger threshold μ = d·(1 ± ε), moved by 10^3 times its size and scaled by 10^s, s ∈ [250, 300] "
       "(every number an exact decimal)",
       Question::force_closure, true, true},
      {"tiny_scale",
       "the same scaled by 10^-s, s ∈ [250, 300]: the twin abstains where a value drops below 2^-960 ≈ 1e-289",
       Question::force_closure, true, true},
      {"beyond_double",
       "the same scaled by 10^s, s ∈ [310, 330] or [−360, −330]: coordinates beyond the double range (strtod "
       "gives ±inf or 0); the twin must abstain",
       Question::force_closure, true, true},
      {"many_contacts",
       "1000–10000 contacts on an arc of the unit circle (inward normals, exact fractions); the two end contacts "
       "carry μ = μ*·(1 ± ε) and decide: closure iff μ > μ* = (1 + t1·t2)/(t2 − t1)",
       Question::force_closure, true, true},
      {"collinear_support",
       "3–6 support points ε off a line (at rational distances from c), load p(q)·(1 ± ε) for the rotation q about c "
       "(p(q) on the limit surface, exact): slides iff above",
       Question::stick_slide, true, true},
      {"unknown_support",
       "the distribution unknown: random supports of 4–8 points (some forces given), the table (±1, ±1) and the "
       "dinner plate; load p·(1 ± ε) with p within 10^-(k+6) of a vertex distribution's limit surface for a random "
       "twist (the one with the largest power: U's boundary, the smallest, or any): the answers left possible are "
       "known by construction",
       Question::stick_slide_over, true, true},
      {"fixture_pin",
       "hold: a frictionless pin pushing through the centre of friction of a symmetric support (2–4 pairs of points, "
       "exact rational normal), the push μW·(1 ± ε): holds iff below (a force through the centre of friction is in "
       "the closed limit surface iff it is at most μW)",
       Question::hold, true, true},
      {"push_near_tie",
       "push: 3–8 support points (3-decimal places, forces and coefficients), a pusher aimed at the centre of friction "
       "c with its normal along p → c and μ = 1/2 (the edges vote apart), its velocity turned by ±ε off p → c: it turns "
       "ccw iff above (the velocity decides, Mason's voting theorem)",
       Question::push, true, true},
      {"push_motion_cone",
       "push --contact: push_near_tie's support, the pusher's normal n and μ = 1/2 chosen so that the left friction-cone "
       "edge n + μ·rot90 n points from p at the centre of friction c (the translation along it has its force exactly "
       "on that edge: a motion-cone edge), its velocity turned by ±ε off p → c: it slides left iff above (turned ccw: "
       "the force turns past the edge), else it sticks",
       Question::push_contact, true, true},
      {"push_fence_edge",
       "push with a line pusher: push_near_tie's support, a fence below it (normal (0, 1), μ ∈ {1/4, 1/2, 3/4, 1}) "
       "across the line through the centre of friction along its left friction-cone edge e₊ = (−μ, 1), translating "
       "along e₊ turned by ±ε: stable for every distribution iff below (turned into the cone; the load is v through c, "
       "PU-3 §8)",
       Question::push_stable, true, true},
      {"region_support",
       "a support region (rectangle or triangle, maybe a hole, uniform or linear pressure, maybe a point); load "
       "p*·(1 ± ε) with p* the exact boundary load of a translation along a Pythagorean direction: slides iff above",
       Question::stick_slide_region, true, true},
      {"region_legs",
       "a support region as region_support with 1–3 legs whose forces are not given (weight and centre of one "
       "admissible distribution); load p*·(1 ± ε), p* the translation's boundary load, the same for every admissible "
       "distribution: slides for every one iff above, else sticks for every one",
       Question::stick_slide_over, true, true},
  };
  return f;
}

// A scene of an exact family, its side drawn (the first draw of the case).
Family_scene known_side(const Family& fam, double eps, Rng& r) {
  Family_scene out;
  out.family = fam.name;
  out.epsilon = eps;
  out.known = true;
  out.above = r.coin();
  return out;
}

// Family "fixture_pin" (hold, issue 16). A support symmetric about its centre of friction c: 2–4 pairs of points
// c ± d_j with equal forces (integers 1–5) and one μ (1/2, 1, 1/3, 3/4), sometimes a point at c; a frictionless pin
// at c − s·n̂ with the rational unit normal n̂ = ((1 − t²), 2t)/(1 + t²); the load κ n̂ at c, on the pin's line. The
// pin's wrench and the load are parallel, so −w_L ∈ W ⊕ LS ⇔ κ n̂ through c ∈ LS, and a force through the centre of
// friction is in the (closed) limit surface iff κ ≤ μW (the translation load μW n̂ through c is on it, with the
// rational witness μ f_i n̂ at every point). κ = μW·(1 ± 10^-k): holds iff below (`above`: it does not hold).
Family_scene fixture_pin(const Family& fam, double eps, Rng& r) {
  const int k = decimal_exponent(eps);
  Family_scene out = known_side(fam, eps, r);
  static const char* mus[] = {"1/2", "1", "1/3", "3/4"};
  const int which = r.integer(0, 3);
  const Rational mu = which == 0 ? Rational(1, 2) : which == 1 ? Rational(1) : which == 2 ? Rational(1, 3) : Rational(3, 4);
  const Rational cx = short_decimal(r, -2000, 2000, 3), cy = short_decimal(r, -2000, 2000, 3);
  std::string points;
  Rational w = 0;
  const int pairs = r.integer(2, 4);
  for (int j = 0; j < pairs; ++j) {
    const Rational dx = short_decimal(r, -1500, 1500, 3), dy = short_decimal(r, -1500, 1500, 3);
    const int f = r.integer(1, 5);
    w += 2 * f;
    for (const int s : {1, -1})
      points += std::string(points.empty() ? "" : ", ") + "{\"at\": [" + exact_text(cx + s * dx) + ", " +
                exact_text(cy + s * dy) + "], \"force\": " + std::to_string(f) + "}";
  }
  if (r.coin()) {
    const int f = r.integer(1, 5);
    w += f;
    points += ", {\"at\": [" + exact_text(cx) + ", " + exact_text(cy) + "], \"force\": " + std::to_string(f) + "}";
  }
  const Rational t = short_decimal(r, -999, 999, 3), d = 1 + t * t;
  const Rational nx = (1 - t * t) / d, ny = 2 * t / d, s = short_decimal(r, 500, 3000, 3);
  const Rational tenth(Integer(1), power_of_ten(k));
  const Rational kappa = mu * w * (out.above ? Rational(1 + tenth) : Rational(1 - tenth));
  out.text = "{\"wrenchkit\": 1, \"name\": \"fixture_pin\", \"contacts\": [{\"at\": [" + exact_text(cx - s * nx) + ", " +
             exact_text(cy - s * ny) + "], \"normal\": [" + exact_text(nx) + ", " + exact_text(ny) +
             "]}], \"support\": {\"mu\": \"" + mus[which] + "\", \"points\": [" + points +
             "]}, \"load\": {\"force\": [" + exact_text(kappa * nx) + ", " + exact_text(kappa * ny) + "], \"at\": [" +
             exact_text(cx) + ", " + exact_text(cy) + "]}}";
  return out;
}

// The pushing families' support: 3–8 points with 3-decimal places, forces and coefficients (every force given), as
// JSON `points`; returns the centre of friction c, exact.
std::pair<Rational, Rational> pushed_support(Rng& r, std::string& points) {
  const int n = r.integer(3, 8);
  Rational mx = 0, my = 0, d = 0;
  for (int i = 0; i < n; ++i) {
    const Rational x = short_decimal(r, -2000, 2000, 3), y = short_decimal(r, -2000, 2000, 3);
    const Rational f = short_decimal(r, 100, 900, 2), mu = short_decimal(r, 10, 90, 2);
    mx += mu * f * x, my += mu * f * y, d += mu * f;
    points += std::string(i ? ", " : "") + "{\"at\": [" + exact_text(x) + ", " + exact_text(y) + "], \"force\": " +
              exact_text(f) + ", \"mu\": " + exact_text(mu) + "}";
  }
  return {mx / d, my / d};
}

// The scene of the pushing families: 3–8 support points with 3-decimal places, forces and coefficients (every force
// given: the centre of friction c exact), a pusher at a 3-decimal point p with μ = 1/2, d = c − p, its normal from
// `normal`(d), and its velocity d + s·10^-k·rot90(d) — s = 1 when `above` and `ccw_above`, or when neither; else −1.
template <class Normal>
Family_scene push_family(const Family& fam, double eps, Rng& r, bool ccw_above, Normal normal) {
  const int k = decimal_exponent(eps);
  Family_scene out = known_side(fam, eps, r);
  std::string points;
  const auto [cx, cy] = pushed_support(r, points);
  const Rational px = short_decimal(r, -4000, 4000, 3), py = short_decimal(r, -4000, -2500, 3);
  const Rational dx = cx - px, dy = cy - py;
  const auto [nx, ny] = normal(dx, dy);
  const Rational e = Rational(out.above == ccw_above ? 1 : -1) * Rational(Integer(1), power_of_ten(k));
  const Rational vx = dx - e * dy, vy = dy + e * dx;  // d + s ε rot90(d), rot90(d) = (−dy, dx)
  out.text = "{\"wrenchkit\": 1, \"name\": \"" + std::string(fam.name) + "\", \"support\": {\"points\": [" + points +
             "]}, \"pusher\": {\"at\": [" + exact_text(px) + ", " + exact_text(py) + "], \"normal\": [" + exact_text(nx) +
             ", " + exact_text(ny) + "], \"mu\": \"1/2\", \"velocity\": [" + exact_text(vx) + ", " + exact_text(vy) + "]}}";
  return out;
}

// Family "push_near_tie" (push, issue 33): the normal d (the line p → c is inside the cone) and μ = 1/2, so the edges
// vote apart and the velocity decides; (p − c) × v = −s·10^-k·|d|², so it votes ccw iff s < 0 (`above`: ccw).
Family_scene push_near_tie(const Family& fam, double eps, Rng& r) {
  return push_family(fam, eps, r, false, [](const Rational& dx, const Rational& dy) { return std::pair{dx, dy}; });
}

// Family "push_motion_cone" (push --contact, issue 33): with μ = 1/2 and n = (dx + dy/2, dy − dx/2), the left edge
// n + μ·rot90 n = (5/4)·d points at c: the translation along d has its force D·d̂ through c and p, on that edge — its
// velocity d is on an edge of the motion cone. Turned ccw (s = 1, `above`) the sticking candidate's force turns ccw
// past the left edge (the force turns with the velocity, PU-2 §5): it slides left; turned cw the force is inside the
// cone: it sticks.
Family_scene push_motion_cone(const Family& fam, double eps, Rng& r) {
  return push_family(fam, eps, r, true, [](const Rational& dx, const Rational& dy) {
    return std::pair{Rational(dx + dy / 2), Rational(dy - dx / 2)};
  });
}

// Family "push_fence_edge" (push with a line pusher, issue 33, PU-3 §8): the support of push_near_tie, a fence on the
// line y = y0 below it with normal (0, 1) and μ, across the line through c along e₊ = (−μ, 1) (its ends a half-width
// w ∈ [1, 3] either side), translating along v = e₊ − s·10^-k·rot90(e₊): v × e₊ = s·10^-k·|e₊|², e₋ × v > 0 and the
// line through c along v crosses the fence well inside, so the push is stable iff s = 1 (`above` false: stable iff
// below).
Family_scene push_fence_edge(const Family& fam, double eps, Rng& r) {
  const int k = decimal_exponent(eps);
  Family_scene out = known_side(fam, eps, r);
  std::string points;
  const auto [cx, cy] = pushed_support(r, points);
  const Rational mu(r.integer(1, 4), 4), y0 = short_decimal(r, -4000, -2500, 3), w = short_decimal(r, 1000, 3000, 3);
  const Rational xs = cx + mu * (cy - y0);  // c − t·e₊ on y = y0: t = cy − y0
  const Rational s = Rational(out.above ? -1 : 1) * Rational(Integer(1), power_of_ten(k));
  const Rational vx = -mu + s, vy = 1 + s * mu;  // e₊ − s·rot90(e₊), rot90(e₊) = (−1, −μ)
  out.text = "{\"wrenchkit\": 1, \"name\": \"" + std::string(fam.name) + "\", \"support\": {\"points\": [" + points +
             "]}, \"pusher\": {\"segment\": [[" + exact_text(xs - w) + ", " + exact_text(y0) + "], [" + exact_text(xs + w) +
             ", " + exact_text(y0) + "]], \"normal\": [0, 1], \"mu\": \"" + exact_text(mu) + "\", \"velocity\": [" +
             exact_text(vx) + ", " + exact_text(vy) + "]}}";
  return out;
}

const char* naive_push_stable(const Scene& scene) {
  const auto D = [](const Rational& x) { return naive_double(x.get_str()); };  // as strtod reads the text
  const Support& s = *scene.support;
  const Pusher& ps = *scene.pusher;
  double mx = 0, my = 0, d = 0;
  for (const Support_point& q : s.points) {
    const double w = D(s.mu_of(q)) * D(*q.force);
    mx += w * D(q.at.x), my += w * D(q.at.y), d += w;
  }
  const double cx = mx / d, cy = my / d, nx = D(ps.contact.normal.x), ny = D(ps.contact.normal.y),
               mu = D(ps.contact.mu), vx = D(ps.velocity.x), vy = D(ps.velocity.y);
  const double lx = nx - mu * ny, ly = ny + mu * nx, rx = nx + mu * ny, ry = ny - mu * nx;  // e₊, e₋
  const double ex[2] = {D(ps.contact.at.x), D(ps.end->x)}, ey[2] = {D(ps.contact.at.y), D(ps.end->y)};
  const double turn = (ex[1] - ex[0]) * ny - (ey[1] - ey[0]) * nx;  // > 0: end 0 is PU-3's p₁ (its moment ≥ 0)
  const double sk[2] = {turn > 0 ? 1.0 : -1.0, turn > 0 ? -1.0 : 1.0};
  const double facet[4] = {vx * ly - vy * lx, rx * vy - ry * vx, sk[0] * ((cx - ex[0]) * vy - (cy - ey[0]) * vx),
                           sk[1] * ((cx - ex[1]) * vy - (cy - ey[1]) * vx)};
  for (double f : facet)
    if (f < 0) return "unstable";
  return "stable";
}

const char* naive_push_contact(const Scene& scene) {
  const Support& s = *scene.support;
  const Pusher& ps = *scene.pusher;
  const double px = ps.contact.at.x.get_d(), py = ps.contact.at.y.get_d(), nx = ps.contact.normal.x.get_d(),
               ny = ps.contact.normal.y.get_d(), mu = ps.contact.mu.get_d(), vx = ps.velocity.x.get_d(),
               vy = ps.velocity.y.get_d();
  std::vector<std::array<double, 3>> pts;  // r − p, ρ
  for (const Support_point& q : s.points)
    pts.push_back({q.at.x.get_d() - px, q.at.y.get_d() - py, s.mu_of(q).get_d() * q.force->get_d()});
  // the load's moment about p, and its force, for the twist v + ω·rotation about p
  const auto load = [&](double w, double& fx, double& fy) {
    double m = 0;
    fx = fy = 0;
    for (const auto& [dx, dy, rho] : pts) {
      const double ux = vx - w * dy, uy = vy + w * dx, len = std::sqrt(ux * ux + uy * uy);
      if (len == 0) continue;
      m += rho * (dx * uy - dy * ux) / len, fx += rho * ux / len, fy += rho * uy / len;
    }
    return m;
  };
  double lo = -1, hi = 1, fx = 0, fy = 0;
  while (load(lo, fx, fy) > 0 && lo > -1e300) lo *= 2;
  while (load(hi, fx, fy) < 0 && hi < 1e300) hi *= 2;
  for (int i = 0; i < 200; ++i) {
    const double mid = (lo + hi) / 2;
    (load(mid, fx, fy) < 0 ? lo : hi) = mid;
  }
  load((lo + hi) / 2, fx, fy);
  const double lx = nx - mu * ny, ly = ny + mu * nx, rx = nx + mu * ny, ry = ny - mu * nx;  // n ± μ rot90 n
  const double right = rx * fy - ry * fx, left = fx * ly - fy * lx;  // e_R × F, F × e_L
  if (right > 0 && left > 0) return "sticks";
  return left <= right ? "slides left" : "slides right";
}

std::string fixture_text(Rng& r, int contacts, int points, double load) {
  const auto d3 = [](double v) {  // 3 decimals (printf rounds correctly: the same text everywhere)
    char b[32];
    std::snprintf(b, sizeof b, "%.3f", v);
    return std::string(b);
  };
  // A direction on the unit circle by the rational parametrisation (no libm): (1 − t², 2t)/(1 + t²), either sign.
  const auto direction = [&r](double& x, double& y) {
    const double t = r.uniform(-1, 1), sign = r.coin() ? 1 : -1;
    x = sign * (1 - t * t) / (1 + t * t), y = sign * 2 * t / (1 + t * t);
  };
  std::string s = "{\"wrenchkit\": 1, \"contacts\": [";
  for (int c = 0; c < contacts; ++c) {
    double x = 0, y = 0;
    direction(x, y);
    s += std::string(c ? ", " : "") + "{\"at\": [" + d3(1.5 * x) + ", " + d3(1.5 * y) + "], \"normal\": [" +
         d3(-x + r.uniform(-0.3, 0.3)) + ", " + d3(-y + r.uniform(-0.3, 0.3)) + "], \"mu\": " +
         d3(r.uniform(0.1, 0.6)) + "}";
  }
  s += "], \"support\": {\"points\": [";
  double rho = 0;
  for (int i = 0; i < points; ++i) {
    const std::string f = d3(r.uniform(0.1, 1)), mu = d3(r.uniform(0.2, 0.8));
    rho += std::strtod(f.c_str(), nullptr) * std::strtod(mu.c_str(), nullptr);
    s += std::string(i ? ", " : "") + "{\"at\": [" + d3(r.uniform(-1, 1)) + ", " + d3(r.uniform(-1, 1)) +
         "], \"force\": " + f + ", \"mu\": " + mu + "}";
  }
  double x = 0, y = 0;
  direction(x, y);
  return s + "]}, \"load\": {\"force\": [" + d3(load * rho * x) + ", " + d3(load * rho * y) + "], \"at\": [" +
         d3(r.uniform(-1, 1)) + ", " + d3(r.uniform(-1, 1)) + "]}}";
}

const Family* find_family(std::string_view name) {
  for (const auto* list : {&families(), &report_only_families()})
    for (const Family& f : *list)
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
  const std::string name = family.name;
  if (name == "collinear_support") return collinear_support(family, epsilon, rng);
  if (name == "unknown_support") return unknown_support(family, epsilon, rng);
  if (name == "fixture_pin") return fixture_pin(family, epsilon, rng);
  if (name == "push_near_tie") return push_near_tie(family, epsilon, rng);
  if (name == "push_motion_cone") return push_motion_cone(family, epsilon, rng);
  if (name == "push_fence_edge") return push_fence_edge(family, epsilon, rng);
  if (name == "region_support" || name == "region_legs") return region_support(family, epsilon, rng);
  if (name == "long_rational" || name == "rational_rotation" || name == "huge_scale" || name == "tiny_scale" ||
      name == "beyond_double" || name == "many_contacts")
    return exact_family(family, epsilon, rng);
  return near_degenerate(family, epsilon, rng);
}

Family_scene make_scene(std::string_view family, double epsilon, std::uint64_t seed) {
  const Family* f = find_family(family);
  if (!f) throw std::invalid_argument("unknown scene family \"" + std::string(family) + "\"");
  Rng rng(seed);
  return make_scene(*f, epsilon, rng);
}

}  // namespace wrenchkit::stress
