#include "float/closure_twin.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace wrenchkit::fl {

std::vector<Bounded3> generators(const std::vector<Bounded_contact>& contacts, Reading reading) {
  std::vector<Bounded3> out;
  out.reserve(2 * contacts.size());
  for (const Bounded_contact& c : contacts) {
    if (c.is_wrench) {
      out.push_back({c.fx, c.fy, c.m});
      continue;
    }
    point_contact_generators(c.ax, c.ay, c.nx, c.ny, c.mu, c.frictional, reading,
                             [&](Edge, const Bounded& fx, const Bounded& fy, const Bounded& m) {
                               out.push_back({fx, fy, m});
                             });
  }
  return out;
}

Dual_cone dual_cone(const std::vector<Bounded_contact>& contacts, Reading reading) {
  const Float_kernel kernel(generators(contacts, reading));
  return compute_dual_cone(kernel);
}

std::vector<Bounded_contact> bounded_contacts(const std::vector<Point_contact>& contacts) {
  std::vector<Bounded_contact> out;
  out.reserve(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Point_contact& p = contacts[i];
    if (p.nx == 0 && p.ny == 0)
      throw std::invalid_argument("contacts[" + std::to_string(i) + "].normal: zero vector");
    if (!(p.mu >= 0) || !std::isfinite(p.mu))
      throw std::invalid_argument("contacts[" + std::to_string(i) + "].mu: must be finite and >= 0");
    Bounded_contact b;
    b.ax = Bounded::exact(p.ax);
    b.ay = Bounded::exact(p.ay);
    b.nx = Bounded::exact(p.nx);
    b.ny = Bounded::exact(p.ny);
    b.mu = Bounded::exact(p.mu);
    b.frictional = p.mu != 0;
    out.push_back(b);
  }
  return out;
}

namespace {

Verdict verdict(const Dual_cone& dc) {
  if (!dc.decided) return Verdict::undecided;
  return dc.force_closure() ? Verdict::closed : Verdict::open;
}

// generators(bounded_contacts(contacts), reading) without the intermediate contacts (the same checks,
// the same generators in the same order).
Verdict closure_of(const std::vector<Point_contact>& contacts, Reading reading) {
  std::vector<Bounded3> g;
  g.reserve(2 * contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Point_contact& p = contacts[i];
    if (p.nx == 0 && p.ny == 0)
      throw std::invalid_argument("contacts[" + std::to_string(i) + "].normal: zero vector");
    if (!(p.mu >= 0) || !std::isfinite(p.mu))
      throw std::invalid_argument("contacts[" + std::to_string(i) + "].mu: must be finite and >= 0");
    point_contact_generators(Bounded::exact(p.ax), Bounded::exact(p.ay), Bounded::exact(p.nx), Bounded::exact(p.ny),
                             Bounded::exact(p.mu), p.mu != 0, reading,
                             [&](Edge, const Bounded& fx, const Bounded& fy, const Bounded& m) {
                               g.push_back({fx, fy, m});
                             });
  }
  return verdict(compute_dual_cone(Float_kernel(std::move(g))));
}

}  // namespace

Verdict force_closure(const std::vector<Point_contact>& contacts) { return closure_of(contacts, Reading::friction); }

Verdict form_closure(const std::vector<Point_contact>& contacts) { return closure_of(contacts, Reading::frictionless); }

}  // namespace wrenchkit::fl
