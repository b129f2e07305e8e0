#include "exact/statics/generators.h"

#include "exact/numbers/wide_int.h"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <stdexcept>

namespace wrenchkit {

namespace {
bool small_generators(const Contact& c, std::size_t i, Reading reading, std::vector<Generator>& out);
}  // namespace

std::vector<Generator> generators(const Scene& scene, Reading reading) {
  std::vector<Generator> out;
  out.reserve(2 * scene.contacts.size());
  for (std::size_t i = 0; i < scene.contacts.size(); ++i) {
    std::optional<Contact> built;  // rationals of a lazily read contact, built here
    if (scene.contacts[i].exact_pending) built = exact_contact(scene.contacts[i]);
    const Contact& c = built ? *built : scene.contacts[i];
    if (c.kind == Contact::Kind::wrench) {
      out.push_back({i, Edge::wrench, c.wrench});
      continue;
    }
    if (small_generators(c, i, reading, out)) continue;
    point_contact_generators(c.at.x, c.at.y, c.normal.x, c.normal.y, c.mu, c.mu != 0, reading,
                             [&](Edge e, Rational fx, Rational fy, Rational m) {
                               out.push_back({i, e, Vec3q{std::move(fx), std::move(fy), std::move(m)}});
                             });
  }
  return out;
}

namespace {

using wide::i128;
using wide::u128;

constexpr std::int64_t kSmall40 = std::int64_t(1) << 40;

using wide::gcd128;
using wide::gcd64;
using wide::uabs;

// z as an int64 when |z| ≤ kMax62 (reads the limbs: no library call).
bool small_z(mpz_srcptr z, std::int64_t& v) {
  const std::size_t n = mpz_size(z);
  if (n > 1) return false;
  const mp_limb_t limb = n ? mpz_getlimbn(z, 0) : 0;
  if (limb > static_cast<mp_limb_t>(wide::kMax62)) return false;
  v = mpz_sgn(z) < 0 ? -static_cast<std::int64_t>(limb) : static_cast<std::int64_t>(limb);
  return true;
}

// Numerator and denominator of q when both are ≤ kMax62 in magnitude.
bool small_q(const Rational& q, std::int64_t& num, std::int64_t& den) {
  return small_z(q.get_num_mpz_t(), num) && small_z(q.get_den_mpz_t(), den);
}

// lcm of two positive values ≤ kMax62, if it is ≤ kMax62.
bool small_lcm(std::int64_t a, std::int64_t b, std::int64_t& l) {
  const i128 m = static_cast<i128>(a / static_cast<std::int64_t>(gcd64(a, b))) * b;  // < 2^124
  if (!wide::fits62(m)) return false;
  l = static_cast<std::int64_t>(m);
  return true;
}

// The common-denominator form of a rational 2-vector: (X, Y)/D with D > 0, all ≤ kMax62.
bool small_vec2(const Rational& x, const Rational& y, std::int64_t& X, std::int64_t& Y, std::int64_t& D) {
  std::int64_t nx, dx, ny, dy;
  if (!small_q(x, nx, dx) || !small_q(y, ny, dy) || !small_lcm(dx, dy, D)) return false;
  const i128 X128 = static_cast<i128>(nx) * (D / dx), Y128 = static_cast<i128>(ny) * (D / dy);
  if (!wide::fits62(X128) || !wide::fits62(Y128)) return false;
  X = static_cast<std::int64_t>(X128);
  Y = static_cast<std::int64_t>(Y128);
  return true;
}

// A rational num/den in lowest terms with |num|, den ≤ 2^62 − 1 (den > 0), for the generators of short numbers:
// each operation is exact in 128 bits and reduced by its gcd; `ok` turns false (for good) when a result does not
// fit, and the caller takes the rationals instead. The same values as Rational arithmetic, without allocation.
struct Frac62 {
  std::int64_t num = 0, den = 1;
  bool ok = true;
};
Frac62 frac62(i128 num, i128 den, bool ok) {  // den > 0
  if (!ok) return {0, 1, false};
  if (num == 0) return {0, 1, true};
  const u128 g = gcd128(uabs(num), static_cast<u128>(den));
  num /= static_cast<i128>(g), den /= static_cast<i128>(g);
  if (!wide::fits62(num) || !wide::fits62(den)) return {0, 1, false};
  return {static_cast<std::int64_t>(num), static_cast<std::int64_t>(den), true};
}
Frac62 operator*(const Frac62& a, const Frac62& b) {
  return frac62(static_cast<i128>(a.num) * b.num, static_cast<i128>(a.den) * b.den, a.ok && b.ok);
}
Frac62 operator+(const Frac62& a, const Frac62& b) {  // |terms| < 2^124: the sum fits
  return frac62(static_cast<i128>(a.num) * b.den + static_cast<i128>(b.num) * a.den, static_cast<i128>(a.den) * b.den,
                a.ok && b.ok);
}
Frac62 operator-(const Frac62& a, const Frac62& b) { return a + Frac62{-b.num, b.den, b.ok}; }

Rational rational_of(const Frac62& f) {  // already in lowest terms
  Rational q;
  mpz_set_si(q.get_num_mpz_t(), f.num);
  mpz_set_si(q.get_den_mpz_t(), f.den);
  return q;
}

// [FC-0] The point contact's generators by point_contact_generators over Frac62 (the one construction) when its
// numbers are short and every intermediate result fits; false (nothing appended) otherwise.
bool small_generators(const Contact& c, std::size_t i, Reading reading, std::vector<Generator>& out) {
  Frac62 v[5];
  const Rational* q[5] = {&c.at.x, &c.at.y, &c.normal.x, &c.normal.y, &c.mu};
  for (int k = 0; k < 5; ++k)
    if (!small_q(*q[k], v[k].num, v[k].den)) return false;
  Edge edge[2] = {Edge::normal, Edge::normal};
  Frac62 w[2][3];
  int n = 0;
  bool ok = true;
  point_contact_generators(v[0], v[1], v[2], v[3], v[4], c.mu != 0, reading,
                           [&](Edge e, const Frac62& fx, const Frac62& fy, const Frac62& m) {
                             ok = ok && fx.ok && fy.ok && m.ok;
                             edge[n] = e;
                             w[n][0] = fx, w[n][1] = fy, w[n][2] = m;
                             ++n;
                           });
  if (!ok) return false;
  for (int k = 0; k < n; ++k)
    out.push_back({i, edge[k], Vec3q{rational_of(w[k][0]), rational_of(w[k][1]), rational_of(w[k][2])}});
  return true;
}

// The integer vector e (|entries| < 2^127) as a kernel row: s and its tier
// (0: < 2^40, 1: ≤ 2^62 − 1), or tier 2 with v. The zero vector stays zero (tier 0). Returns the
// positive integer e was divided by (1 unless that brought it to 62 bits).
u128 int128_row(i128 e[3], std::int64_t s[3], std::uint8_t& tier, std::array<Integer, 3>& v) {
  tier = 0;
  u128 divisor = 1;
  if (!wide::fits62(e[0]) || !wide::fits62(e[1]) || !wide::fits62(e[2])) {
    // Divided by the gcd of its entries when that brings it to 62 bits (then fixed-width signs).
    const u128 g = gcd128(gcd128(uabs(e[0]), uabs(e[1])), uabs(e[2]));
    for (int c = 0; c < 3; ++c) e[c] /= static_cast<i128>(g);
    divisor = g;
    if (!wide::fits62(e[0]) || !wide::fits62(e[1]) || !wide::fits62(e[2])) {
      tier = 2;
      for (int c = 0; c < 3; ++c) v[c] = integer_of(e[c]);
      return divisor;
    }
  }
  for (int c = 0; c < 3; ++c) {
    s[c] = static_cast<std::int64_t>(e[c]);
    if (s[c] >= kSmall40 || s[c] <= -kSmall40) tier = 1;
  }
  return divisor;
}

}  // namespace

wide::u128 Exact_kernel::push_int128(wide::i128 x, wide::i128 y, wide::i128 z) {
  i128 e[3] = {x, y, z};
  Row r;
  std::array<Integer, 3> v;
  const u128 divisor = int128_row(e, r.s, r.tier, v);
  if (r.tier == 2) {
    r.big = static_cast<std::uint32_t>(big_.size());
    big_.push_back(std::move(v));
  }
  rows_.push_back(r);
  return divisor;
}

void Exact_kernel::note(std::size_t contact, Edge edge, std::int64_t f0, std::int64_t f1, std::int64_t f2,
                        wide::u128 divisor) {
  Provenance p;
  p.contact = contact;
  p.edge = edge;
  p.f[0] = f0, p.f[1] = f1, p.f[2] = f2;
  p.divisor = divisor;
  prov_.push_back(p);
}

void Exact_kernel::note_big(std::size_t contact, Edge edge, Integer scale) {
  Provenance p;
  p.contact = contact;
  p.edge = edge;
  p.big = static_cast<std::int32_t>(big_scale_.size());
  big_scale_.push_back(std::move(scale));
  prov_.push_back(p);
}

void Exact_kernel::scale(std::size_t i, Integer& num, Integer& den) const {
  const Provenance& p = prov_.at(i);
  if (p.big >= 0) {
    num = big_scale_[static_cast<std::size_t>(p.big)];
    den = 1;
    return;
  }
  num = static_cast<long>(p.f[0]);
  for (int k = 1; k < 3; ++k)
    if (p.f[k] != 1) num *= static_cast<long>(p.f[k]);
  den = integer_of(static_cast<i128>(p.divisor));  // ≤ 2^125: the gcd of entries below 2^125
}

void Exact_kernel::push_rational(const Rational in[3], std::size_t contact) {
  // Fast path: numerators and denominators of 62 bits, common denominator of 62 bits.
  std::int64_t num[3], den[3], l = 1;
  bool fast = true;
  for (int c = 0; c < 3 && fast; ++c) fast = small_q(in[c], num[c], den[c]) && small_lcm(l, den[c], l);
  if (fast) {  // row = l · in / divisor
    const u128 divisor =
        push_int128(i128(num[0]) * (l / den[0]), i128(num[1]) * (l / den[1]), i128(num[2]) * (l / den[2]));  // < 2^124
    if (record_) note(contact, Edge::wrench, l, 1, 1, divisor);
    return;
  }
  // Otherwise GMP integers: scale by the product of the denominators (positive; no gcd).
  const Integer& d0 = in[0].get_den();
  const Integer& d1 = in[1].get_den();
  const Integer& d2 = in[2].get_den();
  push_big({in[0].get_num() * d1 * d2, in[1].get_num() * d0 * d2, in[2].get_num() * d0 * d1});
  if (record_) note_big(contact, Edge::wrench, d0 * d1 * d2);
}

void Exact_kernel::push_big(std::array<Integer, 3> v) {
  Row r;
  bool fits = true;
  for (int c = 0; c < 3 && fits; ++c) fits = small_z(v[c].get_mpz_t(), r.s[c]);
  if (fits) {
    for (int c = 0; c < 3; ++c)
      if (r.s[c] >= kSmall40 || r.s[c] <= -kSmall40) r.tier = 1;
  } else {
    r.tier = 2;
    r.big = static_cast<std::uint32_t>(big_.size());
    big_.push_back(std::move(v));
  }
  rows_.push_back(r);
}

Exact_kernel::Exact_kernel(const std::vector<Vec3q>& wrenches) {
  rows_.reserve(wrenches.size());
  for (const Vec3q& w : wrenches) {
    const Rational in[3] = {w[0], w[1], w[2]};
    push_rational(in, kNoContact);
  }
}

Exact_kernel::Exact_kernel(const Scene& scene, Reading reading, const std::vector<Vec3q>& extra) {
  build(scene, reading, extra);
}

Exact_kernel::Exact_kernel(const Scene& scene, Reading reading, const std::vector<Vec3q>& extra, With_provenance)
    : record_(true) {
  build(scene, reading, extra);
}

void Exact_kernel::build(const Scene& scene, Reading reading, const std::vector<Vec3q>& extra) {
  rows_.reserve(2 * scene.contacts.size() + extra.size());
  if (record_) prov_.reserve(2 * scene.contacts.size() + extra.size());
  for (std::size_t ci = 0; ci < scene.contacts.size(); ++ci) {
    const Contact& original = scene.contacts[ci];
    std::optional<Contact> built;  // rationals of a lazily read contact
    if (original.exact_pending) built = exact_contact(original);
    const Contact& c = built ? *built : original;
    if (c.kind == Contact::Kind::wrench) {
      const Rational in[3] = {c.wrench[0], c.wrench[1], c.wrench[2]};
      push_rational(in, ci);
      continue;
    }
    const bool frictional = c.mu != 0;
    // p = (Px, Py)/dp, n = (Nx, Ny)/dn, μ = M/dm. A generator W(p, f) with f = F/(dn·dm) scaled by
    // dp·dn·dm > 0 is (dp·Fx, dp·Fy, Px·Fy − Py·Fx).
    std::int64_t Px, Py, dp, Nx, Ny, dn, M = 0, dm = 1;
    if (small_vec2(c.at.x, c.at.y, Px, Py, dp) && small_vec2(c.normal.x, c.normal.y, Nx, Ny, dn) &&
        (!frictional || small_q(c.mu, M, dm))) {
      // Row = dp·dn·W (normal) or dp·dn·dm·W (left, right), divided by the divisor push_int128 applied.
      auto emit = [&](Edge edge, i128 Fx, i128 Fy) {  // |F| < 2^125
        if (!wide::fits62(Fx) || !wide::fits62(Fy)) return false;  // then through the rationals
        const std::int64_t fx = static_cast<std::int64_t>(Fx), fy = static_cast<std::int64_t>(Fy);
        const u128 divisor = push_int128(i128(dp) * fx, i128(dp) * fy, wide::minor2(Px, Py, fx, fy));  // each < 2^125
        if (record_) note(ci, edge, dp, dn, edge == Edge::normal ? 1 : dm, divisor);
        return true;
      };
      const std::size_t before = rows_.size(), big_before = big_.size(), prov_before = prov_.size();
      bool ok;
      if (reading == Reading::frictionless || !frictional)
        ok = emit(Edge::normal, Nx, Ny);
      else  // left: n + μ·rot90 n, right: n − μ·rot90 n, rot90 n = (−ny, nx)
        ok = emit(Edge::left, i128(dm) * Nx - i128(M) * Ny, i128(dm) * Ny + i128(M) * Nx) &&
             emit(Edge::right, i128(dm) * Nx + i128(M) * Ny, i128(dm) * Ny - i128(M) * Nx);
      if (ok) continue;
      rows_.resize(before);
      big_.resize(big_before);
      prov_.resize(prov_before);
    }
    // The same formulas in GMP integers, with products of denominators as common denominators.
    const Integer &axn = c.at.x.get_num(), &axd = c.at.x.get_den(), &ayn = c.at.y.get_num(), &ayd = c.at.y.get_den();
    const Integer &nxn = c.normal.x.get_num(), &nxd = c.normal.x.get_den();
    const Integer &nyn = c.normal.y.get_num(), &nyd = c.normal.y.get_den();
    const Integer dpz = axd * ayd, pxz = axn * ayd, pyz = ayn * axd, nx = nxn * nyd, ny = nyn * nxd;
    // Row = dpz·nxd·nyd·W (normal), times md for left and right.
    auto emit_big = [&](Edge edge, const Integer& fx, const Integer& fy, const Integer* md) {
      push_big({dpz * fx, dpz * fy, pxz * fy - pyz * fx});
      if (record_) note_big(ci, edge, md ? Integer(dpz * nxd * nyd * *md) : Integer(dpz * nxd * nyd));
    };
    if (reading == Reading::frictionless || !frictional) {
      emit_big(Edge::normal, nx, ny, nullptr);
    } else {
      const Integer &mn = c.mu.get_num(), &md = c.mu.get_den();
      emit_big(Edge::left, md * nx - mn * ny, md * ny + mn * nx, &md);
      emit_big(Edge::right, md * nx + mn * ny, md * ny - mn * nx, &md);
    }
  }
  for (const Vec3q& w : extra) {
    const Rational in[3] = {w[0], w[1], w[2]};
    push_rational(in, kNoContact);
  }
}

std::size_t generator_count(const Scene& scene, Reading reading) {
  std::size_t n = 0;
  for (const Contact& c : scene.contacts) {
    const bool frictional = c.exact_pending ? c.twin.frictional : c.mu != 0;
    n += c.kind == Contact::Kind::point && reading == Reading::friction && frictional ? 2 : 1;
  }
  return n;
}

std::array<Integer, 3> Exact_kernel::row(std::size_t i) const {
  const Row& r = rows_[i];
  if (r.tier == 2) return big_[r.big];
  return {Integer(static_cast<long>(r.s[0])), Integer(static_cast<long>(r.s[1])), Integer(static_cast<long>(r.s[2]))};
}

namespace {

// GMP scratch integers, reused (no allocation per predicate once warm); one set per thread.
struct Scratch {
  mpz_t r[9], t, u;
  Scratch() {
    for (mpz_t& x : r) mpz_init(x);
    mpz_init(t);
    mpz_init(u);
  }
  ~Scratch() {
    for (mpz_t& x : r) mpz_clear(x);
    mpz_clear(t);
    mpz_clear(u);
  }
};

Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

}  // namespace

// Row i as GMP integers in out[0..2].
void Exact_kernel::load(std::size_t i, mpz_ptr out) const {
  const Row& r = rows_[i];
  for (int c = 0; c < 3; ++c) {
    if (r.tier == 2) mpz_set(out + c, big_[r.big][c].get_mpz_t());
    else mpz_set_si(out + c, static_cast<long>(r.s[c]));
  }
}

Sign Exact_kernel::cross_sign(std::size_t i, std::size_t j) const {
  const Row& a = rows_[i];
  const Row& b = rows_[j];
  if (a.tier < 2 && b.tier < 2)  // each product < 2^124
    return (wide::minor2(a.s[1], a.s[2], b.s[1], b.s[2]) == 0 && wide::minor2(a.s[0], a.s[2], b.s[0], b.s[2]) == 0 &&
            wide::minor2(a.s[0], a.s[1], b.s[0], b.s[1]) == 0)
               ? Sign::zero
               : Sign::positive;
  Scratch& z = scratch();
  load(i, z.r[0]);
  load(j, z.r[3]);
  mpz_srcptr x = z.r[0], y = z.r[3];
  for (const auto& [p, q] : {std::pair<int, int>{1, 2}, {0, 2}, {0, 1}}) {
    mpz_mul(z.t, x + p, y + q);
    mpz_mul(z.u, x + q, y + p);
    if (mpz_cmp(z.t, z.u) != 0) return Sign::positive;
  }
  return Sign::zero;
}

Sign Exact_kernel::det_sign(std::size_t i, std::size_t j, std::size_t k) const {
  const Row& a = rows_[i];
  const Row& b = rows_[j];
  const Row& c = rows_[k];
  const int tier = std::max({a.tier, b.tier, c.tier});
  if (tier == 0) return sign_of(wide::det3_sign_small(a.s, b.s, c.s));
  if (tier == 1) return sign_of(wide::det3_sign(a.s, b.s, c.s));
  Scratch& z = scratch();
  load(i, z.r[0]);
  load(j, z.r[3]);
  load(k, z.r[6]);
  mpz_srcptr x = z.r[0], y = z.r[3], w = z.r[6];
  // x0 (y1 w2 − y2 w1) − x1 (y0 w2 − y2 w0) + x2 (y0 w1 − y1 w0), accumulated in z.t.
  mpz_set_ui(z.t, 0);
  const int terms[3][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};  // cyclic: + x_a (y_b w_c − y_c w_b)
  for (const auto& [p, q, r] : terms) {
    mpz_mul(z.u, y + q, w + r);
    mpz_submul(z.u, y + r, w + q);
    mpz_addmul(z.t, x + p, z.u);
  }
  return sign_of(mpz_sgn(z.t));
}

}  // namespace wrenchkit
