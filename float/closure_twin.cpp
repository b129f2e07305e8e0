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

bool static_generators(const std::vector<Point_contact>& contacts, Reading reading, std::vector<Bounded3>& out,
                       Float_kernel::Column_bounds* columns) {
  const auto in_range = [](double x) { return x == 0 || (std::fabs(x) >= 0x1p-64 && std::fabs(x) <= 0x1p64); };
  for (const Point_contact& p : contacts)
    if (!in_range(p.ax) || !in_range(p.ay) || !in_range(p.nx) || !in_range(p.ny) || !in_range(p.mu)) return false;
  constexpr double u = 0x1p-53, inflate = 1 + 0x1p-45, slack = 0x1p-1000;
  // W(p, F) for F = (fx, fy) with |Fx − fx| ≤ ex, |Fy − fy| ≤ ey: m̂ = fl(fl(ax·fy) − fl(ay·fx)) and
  //   |m − m̂| ≤ u·(|m̂| + |fl(ax·fy)| + |fl(ay·fx)|) + |ax|·ey + |ay|·ex.
  Float_kernel::Column_bounds b;
  const auto push = [&out, &b](const Point_contact& p, double fx, double ex, double fy, double ey) {
    const double p1 = p.ax * fy, p2 = p.ay * fx, m = p1 - p2;
    const double em = (u * (std::fabs(m) + std::fabs(p1) + std::fabs(p2)) + std::fabs(p.ax) * ey + std::fabs(p.ay) * ex) *
                          inflate + slack;
    out.push_back({Bounded{fx, ex}, Bounded{fy, ey}, Bounded{m, em}});
    const double v[3] = {fx, fy, m}, e[3] = {ex, ey, em};
    for (int c = 0; c < 3; ++c) {  // Stage 0's column bounds (X' = fl(|x̂| + e)·(1 + 2^-51) ≥ |x̂| + e)
      const double a = std::fabs(v[c]), up = (a + e[c]) * (1 + 0x1p-51);
      b.M[c] = a > b.M[c] ? a : b.M[c];
      b.Mu[c] = up > b.Mu[c] ? up : b.Mu[c];
      b.E[c] = e[c] > b.E[c] ? e[c] : b.E[c];
    }
  };
  for (const Point_contact& p : contacts) {
    if (reading == Reading::frictionless || p.mu == 0) {
      push(p, p.nx, 0, p.ny, 0);  // F = n exactly
      continue;
    }
    // left F = (nx − μ·ny, ny + μ·nx), right F = (nx + μ·ny, ny − μ·nx); with t = fl(μ·n·),
    // |F̂ − F| ≤ u·(|F̂| + |t|) per coordinate.
    const double t1 = p.mu * p.ny, t2 = p.mu * p.nx;
    const double lx = p.nx - t1, ly = p.ny + t2, rx = p.nx + t1, ry = p.ny - t2;
    const double a1 = std::fabs(t1), a2 = std::fabs(t2);
    push(p, lx, (u * (std::fabs(lx) + a1)) * inflate + slack, ly, (u * (std::fabs(ly) + a2)) * inflate + slack);
    push(p, rx, (u * (std::fabs(rx) + a1)) * inflate + slack, ry, (u * (std::fabs(ry) + a2)) * inflate + slack);
  }
  if (columns) *columns = b;
  return true;
}

namespace {

Verdict verdict(const Dual_cone& dc) {
  if (!dc.decided) return Verdict::undecided;
  return dc.force_closure() ? Verdict::closed : Verdict::open;
}

// generators(bounded_contacts(contacts), reading) without the intermediate contacts (the same checks,
// the same generators in the same order).
Verdict closure_of(const std::vector<Point_contact>& contacts, Reading reading) {
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Point_contact& p = contacts[i];
    if (p.nx == 0 && p.ny == 0)
      throw std::invalid_argument("contacts[" + std::to_string(i) + "].normal: zero vector");
    if (!(p.mu >= 0) || !std::isfinite(p.mu))
      throw std::invalid_argument("contacts[" + std::to_string(i) + "].mu: must be finite and >= 0");
  }
  std::vector<Bounded3> g;
  g.reserve(2 * contacts.size());
  // Static generators first; the running-error ones (exact rounding errors: exact zeros certified) only
  // when that leaves a predicate undecided or an input out of the static range.
  Float_kernel::Column_bounds columns;
  if (static_generators(contacts, reading, g, &columns)) {
    const Dual_cone dc = compute_dual_cone(Float_kernel(std::move(g), columns));
    if (dc.decided) return verdict(dc);
    g = std::vector<Bounded3>();
    g.reserve(2 * contacts.size());
  }
  for (const Point_contact& p : contacts) {
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
