#include "exact/closure.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "exact/cone_lp.h"
#include "exact/json.h"
#include "exact/hybrid_kernel.h"
#include "exact/to_float.h"

namespace wrenchkit {

const char* property_name(Property p) {
  return p == Property::force_closure ? "force_closure" : "form_closure";
}

Reading reading_of(Property p) {
  return p == Property::force_closure ? Reading::friction : Reading::frictionless;
}

namespace {

// [FC-3] A nonzero twist with power ≥ 0 against every generator.
Vec3 negative_twist(const Dual_cone& dc, const std::vector<Generator>& gens) {
  switch (dc.shape) {
    case Dual_shape::lineality: {
      if (dc.rank == 0) return {0, 0, 1};
      if (dc.rank == 2)
        return primitive_vec(cross(as_vec(gens[dc.basis[0]].w), as_vec(gens[dc.basis[1]].w)));
      const Vec3 g = as_vec(gens[dc.basis[0]].w);  // rank 1: any t ⊥ g
      for (int axis = 2; axis >= 0; --axis) {
        Vec3 e{0, 0, 0};
        e[axis] = 1;
        const Vec3 t = cross(g, e);
        if (t[0] != 0 || t[1] != 0 || t[2] != 0) return primitive_vec(t);
      }
      break;
    }
    case Dual_shape::polygon:
    case Dual_shape::arc:
    case Dual_shape::ray:
      return primitive_vec(cross(as_vec(gens[dc.edges[0]].w), as_vec(gens[dc.edges[1]].w)));
    case Dual_shape::zero:
      break;
  }
  throw std::logic_error("negative_twist: no twist for this dual cone");
}

// [FC-2] Strictly positive weights on a rank-3 subset summing to zero, from the generators H
// whose cone is already R³: with an independent triple b of H, solve −(g_b1 + g_b2 + g_b3) =
// Σ μ_h g_h, μ ≥ 0 [FC-4]; then weights μ + 1_b are > 0 on b ∪ supp μ and sum the g's to zero.
void positive_certificate(const std::vector<Generator>& gens, std::vector<std::size_t> H,
                          Closure_certificate& cert) {
  std::sort(H.begin(), H.end());
  H.erase(std::unique(H.begin(), H.end()), H.end());
  std::vector<Wrench> hw;
  for (std::size_t h : H) hw.push_back(gens[h].w);
  const Exact_kernel k(hw);
  const Dual_cone basis_scan = compute_dual_cone(k);  // rank and basis of H
  if (basis_scan.rank != 3 || basis_scan.shape != Dual_shape::zero)
    throw std::logic_error("positive_certificate: the closing generators do not span R³");
  const auto& b = basis_scan.basis;
  Wrench target{-(hw[b[0]].fx + hw[b[1]].fx + hw[b[2]].fx),
                -(hw[b[0]].fy + hw[b[1]].fy + hw[b[2]].fy),
                -(hw[b[0]].m + hw[b[1]].m + hw[b[2]].m)};
  Cone_membership lp = cone_membership(hw, target);
  if (!lp.member) throw std::logic_error("positive_certificate: exact LP found no combination");
  for (int i = 0; i < 3; ++i) lp.weights[b[i]] += 1;
  // Scale to the smallest integer weights.
  Integer l = 1, g = 0;
  for (const Rational& w : lp.weights)
    if (w != 0) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), w.get_den_mpz_t());
  for (const Rational& w : lp.weights)
    if (w != 0) {
      const Integer num = w.get_num() * (l / w.get_den());
      mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), num.get_mpz_t());
    }
  for (std::size_t i = 0; i < H.size(); ++i) {
    if (lp.weights[i] == 0) continue;
    const Rational w = Rational(lp.weights[i].get_num() * (l / lp.weights[i].get_den()) / g);
    cert.combination.push_back({{gens[H[i]].contact, gens[H[i]].edge}, w});
  }
  for (int i = 0; i < 3; ++i) cert.independent[i] = {gens[H[b[i]]].contact, gens[H[b[i]]].edge};
}

}  // namespace

Closure_answer decide_closure(const Scene& scene, Property property, Mode mode, bool certify) {
  const Lazy_generators lazy(scene, reading_of(property));
  Closure_answer a;
  a.mode = mode;
  Dual_cone dc;
  if (mode == Mode::exact) {
    const Exact_kernel exact(scene, reading_of(property));  // integer rows straight from the contacts
    const Counting_exact_kernel kernel{exact};
    dc = compute_dual_cone(kernel);
    a.predicates = a.exact_predicates = kernel.n;
    a.generators = exact.size();
  } else {
    const fl::Float_kernel twin(fl::generators(to_bounded(scene), reading_of(property)));
    const Hybrid_kernel kernel(twin, lazy, mode == Mode::hybrid);
    dc = compute_dual_cone(kernel);
    a.predicates = kernel.n;
    a.exact_predicates = kernel.exact_n;
    a.generators = twin.size();
    if (!dc.decided) {
      a.decided = false;
      return a;
    }
  }

  a.rank = dc.rank;
  a.shape = dc.shape;
  a.holds = dc.force_closure();
  a.certificate.property = property;
  a.certificate.holds = a.holds;
  if (!certify) return a;
  const std::vector<Generator>& gens = lazy.get();
  if (gens.size() != a.generators) throw std::logic_error("decide_closure: twin and engine disagree on generators");
  if (a.holds) {
    std::vector<std::size_t> H = dc.defining;
    H.push_back(dc.closing);
    positive_certificate(gens, std::move(H), a.certificate);
  } else {
    a.certificate.twist = negative_twist(dc, gens);
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
    const Rational in[3] = {-t[1], t[0], 0};
    Integer out[3];
    primitive(in, out);
    r.point = {Rational(out[0]), Rational(out[1])};
  }
  return r;
}

std::string combination_json(const std::vector<std::pair<Generator_ref, Rational>>& terms) {
  std::string s = "[";
  for (std::size_t i = 0; i < terms.size(); ++i) {
    const auto& [ref, w] = terms[i];
    s += (i ? ", " : "") + std::string("{\"contact\": ") + std::to_string(ref.contact) + ", \"edge\": \"" +
         edge_name(ref.edge) + "\", \"weight\": " + json::quote(to_string(w)) + "}";
  }
  return s + "]";
}

std::string twist_json(const std::array<Rational, 3>& t) {
  auto q = [](const Rational& x) { return json::quote(to_string(x)); };
  std::string s = "\"twist\": [" + q(t[0]) + ", " + q(t[1]) + ", " + q(t[2]) + "]";
  const Twist_reading r = read_twist(t);
  if (r.label == 'i')
    s += ", \"reading\": {\"label\": \"infinity\", \"direction\": [";
  else
    s += std::string(", \"reading\": {\"label\": \"") + r.label + "\", \"point\": [";
  return s + q(r.point[0]) + ", " + q(r.point[1]) + "]}";
}

std::string certificate_json(const Closure_certificate& c) {
  std::string s = "{\"wrenchkit_certificate\": 1, \"property\": \"";
  s += property_name(c.property);
  s += "\", \"holds\": ";
  if (!c.holds) return s + "false, " + twist_json(c.twist) + "}";
  s += "true, \"combination\": " + combination_json(c.combination) + ", \"independent\": [";
  for (int i = 0; i < 3; ++i)
    s += (i ? ", " : "") + std::string("{\"contact\": ") + std::to_string(c.independent[i].contact) +
         ", \"edge\": \"" + edge_name(c.independent[i].edge) + "\"}";
  return s + "]}";
}

}  // namespace wrenchkit
