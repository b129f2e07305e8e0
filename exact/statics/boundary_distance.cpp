// [RF-1] Distance of a scene to a degenerate boundary (exact/statics/boundary_distance.h).
#include "exact/statics/boundary_distance.h"

#include "exact/statics/critical_mu.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "core/dual_cone.h"
#include "exact/statics/critical_mu.h"
#include "exact/statics/equilibrium.h"
#include "exact/statics/generators.h"

namespace wrenchkit {

namespace {

// A number as m·2^e with m in [0.5, 1) (0 for zero), for magnitudes beyond the range of doubles.
struct Big_double {
  double m = 0;
  long e = 0;
};
Big_double big(const Integer& z) {
  Big_double b;
  b.m = mpz_get_d_2exp(&b.e, z.get_mpz_t());
  return b;
}

// The exact predicate kernel of core/dual_cone.h over primitive integer rows, recording the size of
// every determinant it is asked for. Rows beyond `n` (the load) may be named by det_sign.
class Measuring_kernel {
 public:
  Measuring_kernel(const std::vector<Vec3q>& rows, std::size_t n) : n_(n) {
    for (const Vec3q& r : rows) {
      std::array<Integer, 3> z;
      if (sgn(r[0]) != 0 || sgn(r[1]) != 0 || sgn(r[2]) != 0) z = primitive(r);  // else the zero row
      rows_.push_back(z);
      const Integer sq = z[0] * z[0] + z[1] * z[1] + z[2] * z[2];
      const Big_double b = big(sq);
      // |r| = sqrt(m·2^e) = sqrt(m·2^(e mod 2))·2^(e div 2)
      const long half = b.e >= 0 ? b.e / 2 : -((-b.e + 1) / 2);
      norm_.push_back({std::sqrt(std::ldexp(b.m, static_cast<int>(b.e - 2 * half))), half});
    }
  }
  std::size_t size() const { return n_; }
  Sign cross_sign(std::size_t i, std::size_t j) const {
    const auto& a = rows_[i];
    const auto& b = rows_[j];
    const bool zero = a[1] * b[2] == a[2] * b[1] && a[2] * b[0] == a[0] * b[2] && a[0] * b[1] == a[1] * b[0];
    return zero ? Sign::zero : Sign::positive;
  }
  Sign det_sign(std::size_t i, std::size_t j, std::size_t k) const {
    const auto& a = rows_[i];
    const auto& b = rows_[j];
    const auto& c = rows_[k];
    const Integer d = c[0] * (a[1] * b[2] - a[2] * b[1]) + c[1] * (a[2] * b[0] - a[0] * b[2]) +
                      c[2] * (a[0] * b[1] - a[1] * b[0]);
    ++margin_.determinants;
    const int s = sgn(d);
    if (s == 0) {
      ++margin_.exact_zeros;
      return Sign::zero;
    }
    const Big_double bd = big(abs(d));
    const double m = bd.m / (norm_[i].m * norm_[j].m * norm_[k].m);
    const long e = bd.e - norm_[i].e - norm_[j].e - norm_[k].e;
    double rel = e < -2000 ? 0.0 : std::ldexp(m, static_cast<int>(std::min<long>(e, 2000)));
    if (rel == 0) rel = std::numeric_limits<double>::denorm_min();  // nonzero, below the double range
    rel = std::min(rel, 1.0);
    if (!margin_.min_relative || rel < *margin_.min_relative) margin_.min_relative = rel;
    return s > 0 ? Sign::positive : Sign::negative;
  }
  const Predicate_margin& margin() const { return margin_; }

 private:
  std::size_t n_;
  std::vector<std::array<Integer, 3>> rows_;
  std::vector<Big_double> norm_;
  mutable Predicate_margin margin_;
};

bool has_friction(const Scene& s) {
  for (const Contact& c : s.contacts)
    if (c.kind == Contact::Kind::point && sgn(c.mu) > 0) return true;
  return false;
}

Rational pow2(int k) {
  Rational r = 1;
  if (k >= 0) mpz_mul_2exp(r.get_num_mpz_t(), r.get_num_mpz_t(), static_cast<mp_bitcnt_t>(k));
  else mpz_mul_2exp(r.get_den_mpz_t(), r.get_den_mpz_t(), static_cast<mp_bitcnt_t>(-k));
  return r;
}

// The flip of a verdict that is monotone non-decreasing in the friction scale s (see the header).
std::optional<Friction_flip> find_flip(const std::function<bool(const Rational&)>& verdict) {
  constexpr int kNear = 160, kFar = 64, kRefine = 10;
  Rational lo, hi;  // verdict(lo) false, verdict(hi) true
  // Smallest k in [1, n] with pred(k) true, given pred monotone non-decreasing in k; n + 1 if none.
  auto first_true = [](int n, const std::function<bool(int)>& pred) {
    int a = 1, b = n + 1;
    while (a < b) {
      const int m = (a + b) / 2;
      if (pred(m)) b = m;
      else a = m + 1;
    }
    return a;
  };
  if (verdict(1)) {
    if (verdict(0)) return std::nullopt;
    if (!verdict(Rational(1, 2))) {  // s* in (1/2, 1]: s_k = 1 − 2^-k
      const int k = first_true(kNear, [&](int j) { return verdict(1 - pow2(-j)); });
      if (k > kNear) lo = 1 - pow2(-kNear), hi = 1;
      else lo = 1 - pow2(-(k - 1)), hi = 1 - pow2(-k);
    } else {  // s* in [0, 1/2]: s_j = 2^-j, verdict decreasing in j
      const int j = first_true(kFar, [&](int i) { return !verdict(pow2(-i)); });
      if (j > kFar) lo = 0, hi = pow2(-kFar);
      else lo = pow2(-j), hi = pow2(-(j - 1));
    }
  } else {
    if (!verdict(pow2(kFar))) return std::nullopt;
    if (verdict(Rational(3, 2))) {  // s* in (1, 3/2]: s_k = 1 + 2^-k, verdict decreasing in k
      const int k = first_true(kNear, [&](int j) { return !verdict(1 + pow2(-j)); });
      if (k > kNear) lo = 1, hi = 1 + pow2(-kNear);
      else lo = 1 + pow2(-k), hi = 1 + pow2(-(k - 1));
    } else {  // s* in (3/2, 2^64]: s_j = 2^j
      const int j = first_true(kFar, [&](int i) { return verdict(pow2(i)); });
      lo = j == 1 ? Rational(3, 2) : pow2(j - 1);
      hi = pow2(j);
    }
  }
  for (int i = 0; i < kRefine; ++i) {
    Rational mid = (lo + hi) / 2;
    if (verdict(mid)) hi = mid;
    else lo = mid;
  }
  Friction_flip f{lo, hi, 0};
  f.distance = std::max(Rational(abs(lo - 1)).get_d(), Rational(abs(hi - 1)).get_d());
  return f;
}

// Wrenches in the scene's own frame: moments about the centroid c of the contact points, divided by
// a length L near their RMS distance from c (a rational choice; any positive L gives the same signs).
// The determinants' signs are unchanged (a shear and a positive column scaling, determinant > 0); their
// relative sizes no longer depend on where the origin is or on the unit of length.
struct Frame {
  Vec2 c{0, 0};
  Rational L = 1;
};
Frame frame_of(const Scene& scene) {
  Frame f;
  std::size_t n = 0;
  for (const Contact& k : scene.contacts)
    if (k.kind == Contact::Kind::point) {
      const Contact e = exact_contact(k);
      f.c.x += e.at.x;
      f.c.y += e.at.y;
      ++n;
    }
  if (n == 0) return f;
  f.c.x /= static_cast<long>(n);
  f.c.y /= static_cast<long>(n);
  Rational r2 = 0;
  for (const Contact& k : scene.contacts)
    if (k.kind == Contact::Kind::point) {
      const Contact e = exact_contact(k);
      r2 += (e.at.x - f.c.x) * (e.at.x - f.c.x) + (e.at.y - f.c.y) * (e.at.y - f.c.y);
    }
  const double rms = std::sqrt(r2.get_d() / static_cast<double>(n));
  if (std::isfinite(rms) && rms > 1e-300 && rms < 1e300) f.L = Rational(rms);
  return f;
}
Vec3q in_frame(const Frame& f, const Vec3q& w) {
  return {w[0], w[1], (w[2] - (f.c.x * w[1] - f.c.y * w[0])) / f.L};
}

std::vector<Vec3q> rows_of(const Scene& scene, Reading reading, const Frame& f) {
  std::vector<Vec3q> rows;
  for (const Generator& g : generators(scene, reading)) rows.push_back(in_frame(f, g.w));
  return rows;
}

}  // namespace

Predicate_margin predicate_margin(const Scene& scene, Reading reading, const Vec3q* load) {
  const Frame f = frame_of(scene);
  std::vector<Vec3q> rows = rows_of(scene, reading, f);
  const std::size_t n = rows.size();
  if (load) rows.push_back(in_frame(f, *load));
  const Measuring_kernel k(rows, n);
  const Dual_cone dc = compute_dual_cone(k);
  if (!load) return k.margin();
  // Only the load's predicates: a fresh count (the cone's own are in the reading's margin).
  const Measuring_kernel kl(rows, n);
  if (dc.rank == 3 && !is_zero(*load)) load_balanced(kl, dc, n);
  return kl.margin();
}


Boundary_distance boundary_distance(const Scene& scene) {
  Boundary_distance b;
  b.force = predicate_margin(scene, Reading::friction);
  b.form = predicate_margin(scene, Reading::frictionless);
  std::optional<Vec3q> load;
  if (scene.load) {
    load = load_wrench(scene);
    b.equilibrium = predicate_margin(scene, Reading::friction, &*load);
  }
  if (has_friction(scene)) {
    b.closure_flip = find_flip([&](const Rational& s) {
      return decide_closure(at_mu(scene, s, Friction_scaling::proportional), Property::force_closure, Mode::hybrid, false).holds;
    });
    if (scene.load)
      b.equilibrium_flip = find_flip([&](const Rational& s) {
        return decide_equilibrium(at_mu(scene, s, Friction_scaling::proportional), Mode::hybrid, false).balanced;
      });
  }
  auto consider = [&](std::optional<double> d, const char* what) {
    if (d && (!b.distance || *d < *b.distance)) {
      b.distance = d;
      b.nearest = what;
    }
  };
  consider(b.force.min_relative, "determinant");
  consider(b.form.min_relative, "determinant");
  consider(b.equilibrium.min_relative, "determinant");
  if (b.closure_flip) consider(b.closure_flip->distance, "friction_scale");
  if (b.equilibrium_flip) consider(b.equilibrium_flip->distance, "friction_scale");
  return b;
}

}  // namespace wrenchkit
