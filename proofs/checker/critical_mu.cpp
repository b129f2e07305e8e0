// proofs/checker/critical_mu.cpp - the critical friction coefficient μ*, certificate-format.md §3.5 (theory:
// proofs/notes/QL-2-critical-friction.md). With μ common to the point contacts, contact i's edges are a_i ± μ·b_i (or,
// "proportional", a_i ± t·μ_i·b_i with the contacts' own μ_i); the claim is about force closure (holds on (μ*, ∞)) or
// the load's equilibrium (holds on [μ*, ∞) or (μ*, ∞)). The certificates on
// either side are those of §3.1–§3.3, checked by their own checks against the scene with every point contact's μ set.
#include <algorithm>

#include "proofs/checker/certificate.h"

namespace wrenchkit_checker::detail {
namespace {

using V3 = std::array<Q, 3>;
using Poly = std::vector<Q>;  // coefficients in μ, lowest degree first

V3 at(const Q& px, const Q& py, const Q& fx, const Q& fy) { return {fx, fy, px * fy - py * fx}; }  // W(p, f)
V3 cross(const V3& a, const V3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
Q dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Q det(const V3& a, const V3& b, const V3& c) { return dot(a, cross(b, c)); }

// The scene with every point contact's μ set to `mu` — or, proportional, its own μ times `mu` (the numbers kept as
// values).
Scene at_mu(const Scene& scene, const Q& mu, bool proportional, const Limits& lim) {
  Scene s;
  s.longest = scene.longest;
  s.has_load = scene.has_load;
  s.load = scene.load;
  s.contacts = scene.contacts;
  for (Contact& c : s.contacts) {
    if (c.wrench) continue;
    std::vector<Q> v = contact_numbers(c, lim);
    v[4] = proportional ? Q(v[4] * mu) : mu;
    c.fixed = false, c.text.clear(), c.value = std::move(v), c.frictional = sgn(mu) > 0;
  }
  return s;
}

// The edges as families a + t b (left a + tb, right a − tb; a wrench contact's wrench and the load with b = 0); b is
// the tangent wrench, times the contact's own μ when proportional.
struct Family {
  V3 a, b;
};
std::vector<Family> families(const Scene& scene, bool with_load, bool proportional, const Limits& lim) {
  std::vector<Family> out;
  for (const Contact& c : scene.contacts) {
    const std::vector<Q> v = contact_numbers(c, lim);
    if (c.wrench) {
      out.push_back({{v[0], v[1], v[2]}, {0, 0, 0}});
      continue;
    }
    const V3 a = at(v[0], v[1], v[2], v[3]);
    V3 b = at(v[0], v[1], -v[3], v[2]);
    if (proportional) b = {b[0] * v[4], b[1] * v[4], b[2] * v[4]};
    out.push_back({a, b});
    out.push_back({a, {-b[0], -b[1], -b[2]}});
  }
  if (with_load) out.push_back({{scene.load->fx, scene.load->fy, scene.load->m}, {0, 0, 0}});
  return out;
}

// Every minor (1×1, 2×2, 3×3) of the families' matrix as a polynomial in μ; `maximal`: the 3×3 ones alone.
std::vector<Poly> minors(const std::vector<Family>& F, bool maximal) {
  std::vector<Poly> out;
  for (const Family& f : F)
    for (int k = 0; k < 3 && !maximal; ++k) out.push_back({f.a[k], f.b[k]});
  for (std::size_t i = 0; i < F.size() && !maximal; ++i)
    for (std::size_t j = i + 1; j < F.size(); ++j) {
      const V3 c0 = cross(F[i].a, F[j].a), c2 = cross(F[i].b, F[j].b), u = cross(F[i].a, F[j].b), v = cross(F[i].b, F[j].a);
      for (int k = 0; k < 3; ++k) out.push_back({c0[k], u[k] + v[k], c2[k]});
    }
  for (std::size_t i = 0; i < F.size(); ++i)
    for (std::size_t j = i + 1; j < F.size(); ++j)
      for (std::size_t k = j + 1; k < F.size(); ++k) {
        const V3 &A = F[i].a, &B = F[j].a, &C = F[k].a, &a = F[i].b, &b = F[j].b, &c = F[k].b;
        out.push_back({det(A, B, C), det(a, B, C) + det(A, b, C) + det(A, B, c), det(A, b, c) + det(a, B, c) + det(a, b, C),
                       det(a, b, c)});
      }
  return out;
}

Poly times(const Poly& p, const Q& c0, const Q& c1) {  // p · (c0 + c1 x)
  Poly r(p.size() + 1, Q(0));
  for (std::size_t i = 0; i < p.size(); ++i) r[i] += p[i] * c0, r[i + 1] += p[i] * c1;
  return r;
}
bool one_sign(const Poly& q) {  // no sign variation among the nonzero coefficients
  int last = 0;
  for (const Q& c : q)
    if (sgn(c) != 0) {
      if (last != 0 && sgn(c) != last) return false;
      last = sgn(c);
    }
  return true;
}
Q value(const Poly& p, const Q& x) {
  Q v = 0;
  for (std::size_t k = p.size(); k-- > 0;) v = v * x + p[k];
  return v;
}
bool zero(const Poly& p) {
  return std::all_of(p.begin(), p.end(), [](const Q& c) { return sgn(c) == 0; });
}
// Descartes' rule of signs: p has no root in (l, h) if (1 + x)^d p((l + h x)/(1 + x)) has no sign variation; none
// beyond M if p(M + x) has none.
bool no_root_between(const Poly& p, const Q& l, const Q& h) {
  const std::size_t d = p.size() - 1;
  Poly q(d + 1, Q(0));
  for (std::size_t k = 0; k <= d; ++k) {
    Poly t{p[k]};
    for (std::size_t i = 0; i < k; ++i) t = times(t, l, h);
    for (std::size_t i = k; i < d; ++i) t = times(t, 1, 1);
    for (std::size_t i = 0; i < t.size(); ++i) q[i] += t[i];
  }
  return one_sign(q);
}
bool no_root_beyond(const Poly& p, const Q& M) {
  Poly q(p.size(), Q(0));
  for (std::size_t k = 0; k < p.size(); ++k) {
    Poly t{p[k]};
    for (std::size_t i = 0; i < k; ++i) t = times(t, M, 1);
    for (std::size_t i = 0; i < t.size(); ++i) q[i] += t[i];
  }
  return one_sign(q);
}

// The property fails (`holds` false) or holds at the side's μ: its certificate, of §3.1–§3.3, for the scene at μ.
void check_side(const Critical_part::Side& side, const char* key, bool holds, const Critical_part& cm, const Scene& scene,
                const Limits& lim) {
  const std::string at_key = std::string(key) + ".certificate: ";
  if (!side.present) throw Failure{std::string("missing required key \"") + key + "\""};
  if (sgn(side.mu) < 0) throw Failure{std::string(key) + ".mu: " + show(side.mu) + " is negative"};
  const Certificate& c = *side.certificate;
  if (c.version == 4 || c.property != cm.of)
    throw Failure{at_key + "expected a certificate of " + quote(cm.of) + " in format 1, 2 or 3"};
  try {
    check_keys(c);
    if (c.holds != holds)
      throw Failure{std::string("\"holds\" is ") + (c.holds ? "true" : "false") + ", expected " + (holds ? "true" : "false")};
    const Scene s = at_mu(scene, side.mu, cm.proportional, lim);
    if (c.equilibrium) check_equilibrium(c, s, lim);
    else check_closure(c, s, lim);
  } catch (const Failure& f) {
    throw Failure{at_key + f.message + " (at mu = " + show(side.mu) + ")"};
  }
}

// Every minor keeps one sign on the interval between `excluded` and `included`, that end included.
void check_constant(const std::vector<Poly>& P, const Q& excluded, const Q& included) {
  const Q l = std::min(excluded, included), h = std::max(excluded, included);
  for (const Poly& p : P)
    if (!zero(p) && (sgn(value(p, included)) == 0 || !no_root_between(p, l, h)))
      throw Failure{"constant: a minor of the edges may change sign between " + show(l) + " and " + show(h)};
}

}  // namespace

// §3.5, theory [QL-2]. The cones a_i ± μ b_i grow with μ, so closure holds on (μ*, ∞) and balance on [μ*, ∞); where
// no minor of the edges changes sign, their oriented matroid, and so both answers, stay the same.
void check_critical_mu(const Certificate& c, const Scene& scene, const Limits& lim) {
  for (const char* key : {"of", "critical_mu"})
    if (!c.keys.count(key)) throw Failure{std::string("missing required key \"") + key + "\""};
  for (const char* key : {"holds", "combination", "independent", "twist", "reading", "load", "motion"})
    if (c.keys.count(key)) throw Failure{std::string("key \"") + key + "\" is not allowed for property \"critical_mu\""};
  const Critical_part& cm = *c.critical_members;
  const bool balance = cm.of == "equilibrium";
  if (balance && !scene.has_load) throw Failure{"of: \"equilibrium\", but the scene has no load"};
  if (balance && cm.proportional) throw Failure{"scaling: \"proportional\" is a claim of force closure only"};
  const auto no = [&c](const char* key, const char* when) {
    if (c.keys.count(key)) throw Failure{std::string("key \"") + key + "\" is not allowed " + when};
  };
  if (cm.word == "always") {  // holds at μ = 0, so at every μ
    no("below", "for \"always\""), no("constant", "for \"always\""), no("constant_beyond", "for \"always\""), no("limit_twist", "for \"always\"");
    if (sgn(cm.above.mu) != 0 && cm.above.present) throw Failure{"above.mu: " + show(cm.above.mu) + ", expected 0 for \"always\""};
    check_side(cm.above, "above", true, cm, scene, lim);
    return;
  }
  if (cm.word == "never") {
    no("above", "for \"never\""), no("constant", "for \"never\"");
    if (cm.has_limit_twist) {  // power >= 0 against every a_i, 0 against every b_i: not closed (balanced) at any μ
      no("below", "with \"limit_twist\""), no("constant_beyond", "with \"limit_twist\"");
      const V3 t = {cm.limit_twist[0], cm.limit_twist[1], cm.limit_twist[2]};
      if (sgn(t[0]) == 0 && sgn(t[1]) == 0 && sgn(t[2]) == 0) throw Failure{"limit_twist: the zero twist proves nothing"};
      const std::vector<Family> F = families(scene, false, cm.proportional, lim);
      for (std::size_t k = 0; k < F.size(); ++k) {
        if (sgn(dot(t, F[k].a)) < 0) throw Failure{"limit_twist: power " + show(dot(t, F[k].a)) + " against a contact's normal wrench"};
        if (sgn(dot(t, F[k].b)) != 0) throw Failure{"limit_twist: power " + show(dot(t, F[k].b)) + " against a contact's tangent wrench, not 0"};
      }
      if (balance && sgn(dot(t, {scene.load->fx, scene.load->fy, scene.load->m})) <= 0)
        throw Failure{"limit_twist: the load's power is not > 0"};
      return;
    }
    if (!balance || !cm.constant_beyond)  // the load on the limit cone's boundary: fails beyond every minor's root
      throw Failure{"never: expected \"limit_twist\"" + std::string(balance ? ", or \"below\" with \"constant_beyond\"" : "")};
    check_side(cm.below, "below", false, cm, scene, lim);
    for (const Poly& p : minors(families(scene, true, false, lim), false))
      if (!zero(p) && (sgn(value(p, cm.below.mu)) == 0 || !no_root_beyond(p, cm.below.mu)))
        throw Failure{"constant_beyond: a minor of the edges may change sign beyond " + show(cm.below.mu)};
    return;
  }
  // a value μ* in [lower, upper]
  no("limit_twist", "for a value"), no("constant_beyond", "for a value");
  if (sgn(cm.lower) < 0 || cm.lower > cm.upper)
    throw Failure{"critical_mu: [" + show(cm.lower) + ", " + show(cm.upper) + "] is not a bracket of a number >= 0"};
  check_side(cm.below, "below", false, cm, scene, lim);
  check_side(cm.above, "above", true, cm, scene, lim);
  if (cm.below.mu >= cm.above.mu) throw Failure{"below.mu is not below above.mu"};
  if (!cm.constant) {  // fails at lower, holds at upper
    if (cm.below.mu != cm.lower || cm.above.mu != cm.upper)
      throw Failure{"critical_mu: a bracket is [below.mu, above.mu] = [" + show(cm.below.mu) + ", " + show(cm.above.mu) + "]"};
    return;
  }
  // exact: μ* = below.mu (the property fails there) and the minors keep their signs on (μ*, above.mu] — it holds on
  // all of it —, or μ* = above.mu (it holds there) and they keep their signs on [below.mu, μ*) — it fails on all of it
  if (cm.lower != cm.upper) throw Failure{"critical_mu: \"constant\" proves one value, but lower != upper"};
  if (cm.lower != cm.below.mu && cm.lower != cm.above.mu)
    throw Failure{"critical_mu: " + show(cm.lower) + " is neither below.mu nor above.mu"};
  const bool at_below = cm.lower == cm.below.mu;
  // (closure: the 3×3 minors — closure holds at above.mu, checked, so one of them is nonzero there and the rank is 3 on
  // the interval, where the chirotope fixes the oriented matroid; balance: every minor, any rank)
  check_constant(minors(families(scene, balance, cm.proportional, lim), !balance), cm.lower,
                 at_below ? cm.above.mu : cm.below.mu);
}

}  // namespace wrenchkit_checker::detail
