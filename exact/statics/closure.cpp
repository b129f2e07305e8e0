#include "exact/statics/closure.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>

#include "exact/statics/cone_lp.h"
#include "exact/statics/hybrid_kernel.h"
#include "exact/io/to_float.h"

namespace wrenchkit {

const char* property_name(Property p) {
  return p == Property::force_closure ? "force_closure" : "form_closure";
}

Reading reading_of(Property p) {
  return p == Property::force_closure ? Reading::friction : Reading::frictionless;
}

namespace {

using Int3 = std::array<Integer, 3>;

Int3 cross3(const Int3& a, const Int3& b) {
  return {Integer(a[1] * b[2] - a[2] * b[1]), Integer(a[2] * b[0] - a[0] * b[2]), Integer(a[0] * b[1] - a[1] * b[0])};
}

std::array<Rational, 3> as_rationals(const Int3& v) { return {Rational(v[0]), Rational(v[1]), Rational(v[2])}; }

}  // namespace

std::array<Rational, 3> twist_of_ray(const Exact_kernel& k, std::size_t a, std::size_t b) {
  return as_rationals(primitive(cross3(k.row(a), k.row(b))));
}

namespace {

// [FC-3] A nonzero twist with power ≥ 0 against every generator, from the kernel's integer rows
// (positive multiples of the generators: the same twist as from the generators themselves).
std::array<Rational, 3> negative_twist(const Dual_cone& dc, const Exact_kernel& k) {
  switch (dc.shape) {
    case Dual_shape::lineality: {
      if (dc.rank == 0) return {Rational(0), Rational(0), Rational(1)};
      if (dc.rank == 2) return twist_of_ray(k, dc.basis[0], dc.basis[1]);
      const Int3 g = k.row(dc.basis[0]);  // rank 1: any t ⊥ g
      for (int axis = 2; axis >= 0; --axis) {
        Int3 e{Integer(0), Integer(0), Integer(0)};
        e[static_cast<std::size_t>(axis)] = 1;
        const Int3 t = cross3(g, e);
        if (t[0] != 0 || t[1] != 0 || t[2] != 0) return as_rationals(primitive(t));
      }
      break;
    }
    case Dual_shape::polygon:
    case Dual_shape::arc:
    case Dual_shape::ray:
      return twist_of_ray(k, dc.edges[0], dc.edges[1]);
    case Dual_shape::zero:
      break;
  }
  throw std::logic_error("negative_twist: no twist for this dual cone");
}

}  // namespace

// [FC-2] [FC-5] Strictly positive weights on a rank-3 subset summing to zero, from the generators H
// whose cone is already R³: with an independent triple b of H, solve −(r_b1 + r_b2 + r_b3) =
// Σ μ_h r_h, μ ≥ 0, over the kernel's integer rows r_h = s_h·g_h (integer phase 1 [FC-5]); then
// λ = μ + 1_b is > 0 on b ∪ supp μ and Σ λ_h r_h = 0, so the weights λ_h·s_h on the UNSCALED generators
// g_h sum them to zero; scaled to coprime integers.
void positive_certificate(const Exact_kernel& k, std::vector<std::size_t> H, Closure_certificate& cert) {
  std::sort(H.begin(), H.end());
  H.erase(std::unique(H.begin(), H.end()), H.end());
  // An independent triple of H: the first generator, the first not parallel to it, the first off
  // their plane.
  std::size_t b[3] = {H.at(0), 0, 0};
  std::size_t found = 1;
  for (std::size_t h : H) {
    if (found == 1 && k.cross_sign(b[0], h) != Sign::zero) b[found++] = h;
    else if (found == 2 && h != b[1] && k.det_sign(b[0], b[1], h) != Sign::zero) b[found++] = h;
    if (found == 3) break;
  }
  if (found != 3) throw std::logic_error("positive_certificate: the closing generators do not span R³");
  // Λ_h > 0 on the support, Σ Λ_h·r_h = 0: for four generators the cofactors (no LP; the same weights once
  // scaled to coprime integers), else Λ_h = denominator·[h ∈ b] + numerator_h (= denominator·λ_h).
  std::vector<Integer> Lambda(H.size());
  std::array<Integer, 4> four;
  if (H.size() == 4 && four_spanning_weights(k, {H[0], H[1], H[2], H[3]}, four)) {
    for (std::size_t i = 0; i < 4; ++i) Lambda[i].swap(four[i]);
  } else {
    Integer_cone_membership lp = cone_membership(k, H, {b[0], b[1], b[2]});
    if (!lp.member) throw std::logic_error("positive_certificate: exact LP found no combination");
    for (std::size_t i = 0; i < H.size(); ++i) {
      Lambda[i].swap(lp.numerators[i]);
      if (H[i] == b[0] || H[i] == b[1] || H[i] == b[2]) Lambda[i] += lp.denominator;
    }
  }
  // w_h = Λ_h·s_h with s_h = sn/sd.
  // In place (no GMP temporaries): the numerators into Lambda itself, the denominators' lcm only where they
  // differ (a scene's rows mostly share one).
  std::vector<Integer> den(H.size());
  Integer l = 1, sn;
  for (std::size_t i = 0; i < H.size(); ++i) {
    if (Lambda[i] == 0) continue;
    k.scale(H[i], sn, den[i]);
    mpz_mul(Lambda[i].get_mpz_t(), Lambda[i].get_mpz_t(), sn.get_mpz_t());
    if (den[i] != l) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), den[i].get_mpz_t());
  }
  Integer g = 0;
  for (std::size_t i = 0; i < H.size(); ++i) {
    if (Lambda[i] == 0) continue;
    if (den[i] != l) {
      mpz_divexact(sn.get_mpz_t(), l.get_mpz_t(), den[i].get_mpz_t());
      mpz_mul(Lambda[i].get_mpz_t(), Lambda[i].get_mpz_t(), sn.get_mpz_t());
    }
    if (g != 1) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), Lambda[i].get_mpz_t());  // (once 1, it stays 1)
  }
  cert.combination.reserve(H.size());
  for (std::size_t i = 0; i < H.size(); ++i) {
    Integer& x = Lambda[i];
    if (x == 0) continue;
    if (g != 1) mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), g.get_mpz_t());
    cert.combination.emplace_back(Generator_ref{k.contact(H[i]), k.edge(H[i])}, Rational());
    mpz_swap(mpq_numref(cert.combination.back().second.get_mpq_t()), x.get_mpz_t());  // x/1, in lowest terms
  }
  for (int i = 0; i < 3; ++i) cert.independent[i] = {k.contact(b[i]), k.edge(b[i])};
}

Closure_answer decide_closure(const Scene& scene, Property property, Mode mode, bool certify) {
  const Lazy_generators lazy(scene, reading_of(property));
  Closure_answer a;
  a.mode = mode;
  std::optional<Exact_kernel> exact;  // integer rows straight from the contacts (exact mode, certificates)
  const auto make_exact = [&]() -> const Exact_kernel& {
    if (certify) exact.emplace(scene, reading_of(property), std::vector<Vec3q>{}, Exact_kernel::With_provenance{});
    else exact.emplace(scene, reading_of(property));
    return *exact;
  };
  const auto make_twin = [&] { return fl::Float_kernel(fl::generators(to_bounded(scene), reading_of(property))); };
  Predicate_tally tally;
  const Dual_cone dc = in_mode(mode, make_exact, make_twin, lazy, tally, [&](const auto& kernel) {
    a.generators = kernel.size();
    return compute_dual_cone(kernel);
  });
  a.predicates = tally.predicates;
  a.exact_predicates = tally.exact;
  if (!dc.decided) {  // only in Mode::float_only
    a.decided = false;
    return a;
  }

  a.rank = dc.rank;
  a.shape = dc.shape;
  a.holds = dc.force_closure();
  a.certificate.property = property;
  a.certificate.holds = a.holds;
  if (!certify) return a;
  // The certificate from the integer rows of the generators it names, each with its scale [FC-5].
  if (!exact) exact.emplace(scene, reading_of(property), std::vector<Vec3q>{}, Exact_kernel::With_provenance{});
  const Exact_kernel& k = *exact;
  if (k.size() != a.generators) throw std::logic_error("decide_closure: twin and engine disagree on generators");
  if (a.holds) {
    std::vector<std::size_t> H = dc.defining;
    H.push_back(dc.closing);
    positive_certificate(k, std::move(H), a.certificate);
  } else {
    a.certificate.twist = negative_twist(dc, k);
  }
  return a;
}

Twist_reading read_twist(const std::array<Rational, 3>& t) {
  Twist_reading r;
  const Rational& w = t[2];
  if (w != 0) {
    r.label = w > 0 ? '+' : '-';
    r.point = {-t[1] / w, t[0] / w};
  } else if (t[0] != 0 || t[1] != 0) {
    const std::array<Integer, 2> d = primitive(-t[1], t[0]);
    r.point = {Rational(d[0]), Rational(d[1])};
  }
  return r;
}

}  // namespace wrenchkit
