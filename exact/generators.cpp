#include "exact/generators.h"

#include <cstdlib>
#include <optional>
#include <stdexcept>

namespace wrenchkit {

Wrench wrench_at(const Vec2& p, const Vec2& f) { return {f.x, f.y, p.x * f.y - p.y * f.x}; }

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
    point_contact_generators(c.at.x, c.at.y, c.normal.x, c.normal.y, c.mu, c.mu != 0, reading,
                             [&](Edge e, Rational fx, Rational fy, Rational m) {
                               out.push_back({i, e, Wrench{std::move(fx), std::move(fy), std::move(m)}});
                             });
  }
  return out;
}

void primitive(const Rational in[3], Integer out[3]) {
  Integer l = 1;
  for (int c = 0; c < 3; ++c) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), in[c].get_den_mpz_t());
  Integer g = 0;
  for (int c = 0; c < 3; ++c) {
    out[c] = in[c].get_num() * (l / in[c].get_den());
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), out[c].get_mpz_t());
  }
  if (g == 0) throw std::invalid_argument("primitive: zero vector");
  for (int c = 0; c < 3; ++c) mpz_divexact(out[c].get_mpz_t(), out[c].get_mpz_t(), g.get_mpz_t());
}

Vec3 as_vec(const Wrench& w) { return {w.fx, w.fy, w.m}; }

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec3 primitive_vec(const Vec3& v) {
  const Rational in[3] = {v[0], v[1], v[2]};
  Integer out[3];
  primitive(in, out);
  return {Rational(out[0]), Rational(out[1]), Rational(out[2])};
}

namespace {

__extension__ typedef __int128 i128;  // GCC and Clang both provide it

Sign sign128(i128 v) { return v < 0 ? Sign::negative : (v > 0 ? Sign::positive : Sign::zero); }
Sign signz(const Integer& v) { return sign_of(sgn(v)); }

const Integer kSmallBound = Integer(1) << 40;

}  // namespace

Exact_kernel::Exact_kernel(const std::vector<Wrench>& wrenches) {
  rows_.reserve(wrenches.size());
  for (const Wrench& w : wrenches) {
    const Rational in[3] = {w.fx, w.fy, w.m};
    Row r;
    if (w.fx == 0 && w.fy == 0 && w.m == 0) {  // a zero row (an extra row such as a zero load)
      r.small = true;
      rows_.push_back(std::move(r));
      continue;
    }
    primitive(in, r.v);
    r.small = true;
    for (int c = 0; c < 3; ++c) r.small &= abs(r.v[c]) < kSmallBound;
    if (r.small)
      for (int c = 0; c < 3; ++c) r.s[c] = r.v[c].get_si();
    rows_.push_back(std::move(r));
  }
}

Sign Exact_kernel::cross_sign(std::size_t i, std::size_t j) const {
  const Row& a = rows_[i];
  const Row& b = rows_[j];
  if (a.small && b.small) {
    const i128 c0 = i128(a.s[1]) * b.s[2] - i128(a.s[2]) * b.s[1];
    const i128 c1 = i128(a.s[2]) * b.s[0] - i128(a.s[0]) * b.s[2];
    const i128 c2 = i128(a.s[0]) * b.s[1] - i128(a.s[1]) * b.s[0];
    return (c0 == 0 && c1 == 0 && c2 == 0) ? Sign::zero : Sign::positive;
  }
  // Primitive vectors are parallel iff equal or opposite.
  const bool same = a.v[0] == b.v[0] && a.v[1] == b.v[1] && a.v[2] == b.v[2];
  const bool opposite = a.v[0] == -b.v[0] && a.v[1] == -b.v[1] && a.v[2] == -b.v[2];
  return (same || opposite) ? Sign::zero : Sign::positive;
}

Sign Exact_kernel::det_sign(std::size_t i, std::size_t j, std::size_t k) const {
  const Row& a = rows_[i];
  const Row& b = rows_[j];
  const Row& c = rows_[k];
  if (a.small && b.small && c.small) {
    const i128 m0 = i128(b.s[1]) * c.s[2] - i128(b.s[2]) * c.s[1];
    const i128 m1 = i128(b.s[0]) * c.s[2] - i128(b.s[2]) * c.s[0];
    const i128 m2 = i128(b.s[0]) * c.s[1] - i128(b.s[1]) * c.s[0];
    return sign128(a.s[0] * m0 - a.s[1] * m1 + a.s[2] * m2);
  }
  const Integer d = a.v[0] * (b.v[1] * c.v[2] - b.v[2] * c.v[1]) -
                    a.v[1] * (b.v[0] * c.v[2] - b.v[2] * c.v[0]) +
                    a.v[2] * (b.v[0] * c.v[1] - b.v[1] * c.v[0]);
  return signz(d);
}

}  // namespace wrenchkit
