#include "exact/statics/equilibrium.h"

#include <array>
#include <stdexcept>
#include <type_traits>

#include "core/dual_cone.h"
#include "exact/statics/cone_lp.h"
#include "exact/statics/hybrid_kernel.h"
#include "exact/io/input_error.h"
#include "exact/io/support_check.h"
#include "exact/io/to_float.h"

namespace wrenchkit {

Vec3q load_wrench(const Scene& scene) {
  const Load& l = *scene.load;
  switch (l.kind) {
    case Load::Kind::wrench:
      return l.wrench;
    case Load::Kind::gravity:  // weight w at the centre of mass, acting in −y; across a support: nothing in-plane
      if (gravity_across_support(scene)) return {Rational(0), Rational(0), Rational(0)};
      return wrench_at(*scene.body.com, Vec2{Rational(0), Rational(-l.weight)});
    case Load::Kind::force:
      break;
  }
  return wrench_at(l.at, l.force);
}

namespace {

// The kernel of the friction generators and the load (last row), with provenance [FC-5].
Exact_kernel load_kernel(const Scene& scene, const Vec3q& load) {
  return Exact_kernel(scene, Reading::friction, {load}, Exact_kernel::With_provenance{});
}

// [EQ-1] [FC-5] The integer LP decides and certifies: balancing weights, or a Farkas twist. `k` holds
// the n generators' rows r_h = s_h·g_h and the load's r_L = s_L·w_ext (row n). A solution
// Σ μ_h r_h = −r_L gives Σ (μ_h s_h / s_L) g_h + w_ext = 0: the weights on the unscaled generators.
void decide_by_lp(const Exact_kernel& k, Equilibrium_answer& a, bool certify) {
  const std::size_t n = k.size() - 1;
  std::vector<std::size_t> columns(n);
  for (std::size_t i = 0; i < n; ++i) columns[i] = i;
  const Integer_cone_membership m = cone_membership(k, columns, {n});
  a.balanced = m.member;
  a.certificate.holds = m.member;
  if (!certify) return;
  if (m.member) {
    Integer ln, ld, sn, sd;
    k.scale(n, ln, ld);  // s_L = ln / ld
    for (std::size_t i = 0; i < n; ++i) {
      if (m.numerators[i] == 0) continue;
      k.scale(i, sn, sd);
      Rational w(Integer(m.numerators[i] * sn * ld), Integer(m.denominator * sd * ln));
      w.canonicalize();
      a.certificate.combination.push_back({{k.contact(i), k.edge(i)}, std::move(w)});
    }
  } else {
    a.certificate.twist = {Rational(m.twist[0]), Rational(m.twist[1]), Rational(m.twist[2])};
  }
}

// The load as error-bounded doubles [FL-4].
fl::Bounded3 load_bounded(const Scene& scene) {
  const Load& l = *scene.load;
  switch (l.kind) {
    case Load::Kind::wrench:
      return {to_bounded(l.wrench[0]), to_bounded(l.wrench[1]), to_bounded(l.wrench[2])};
    case Load::Kind::gravity: {
      if (gravity_across_support(scene)) return {fl::Bounded::exact(0), fl::Bounded::exact(0), fl::Bounded::exact(0)};
      const fl::Bounded w = to_bounded(l.weight);
      return {fl::Bounded::exact(0), -w, -(w * to_bounded(scene.body.com->x))};
    }
    case Load::Kind::force:
      break;
  }
  const fl::Bounded fx = to_bounded(l.force.x), fy = to_bounded(l.force.y);
  return {fx, fy, to_bounded(l.at.x) * fy - to_bounded(l.at.y) * fx};
}

}  // namespace

Equilibrium_answer decide_equilibrium(const Scene& scene, Mode mode, bool certify) {
  if (!scene.load) throw Input_error("load: the scene has no load (equilibrium needs one)");
  Equilibrium_answer a;
  a.mode = mode;
  a.load = load_wrench(scene);
  if (mode != Mode::exact && a.load[0] == 0 && a.load[1] == 0 && a.load[2] == 0) {
    a.generators = generator_count(scene, Reading::friction);
    a.balanced = a.certificate.holds = true;  // the zero load needs no force
    return a;
  }
  if (mode == Mode::exact) {
    const Exact_kernel k = load_kernel(scene, a.load);
    a.generators = k.size() - 1;
    decide_by_lp(k, a, certify);
    return a;
  }
  // [EQ-2] The dual cone over the filtered kernel, with the load as an extra row (index n). (Exact mode
  // decided above, by the LP.)
  const std::size_t n = generator_count(scene, Reading::friction);
  a.generators = n;
  const Lazy_generators lazy(scene, Reading::friction, {a.load});
  const auto make_twin = [&] {
    std::vector<fl::Bounded3> rows = fl::generators(to_bounded(scene), Reading::friction);
    rows.push_back(load_bounded(scene));
    return fl::Float_kernel(std::move(rows));
  };
  const auto no_exact = []() -> const Exact_kernel& { throw std::logic_error("equilibrium: exact mode is the LP's"); };
  struct Run {
    Dual_cone dc;
    Sign balanced = Sign::uncertain;
    std::array<std::size_t, 2> witness{};  // an extreme ray of W* with ⟨ray, w⟩ > 0, if any
  };
  Predicate_tally tally;
  const Run run = in_mode(mode, no_exact, make_twin, lazy, tally, [&](const auto& kernel) {
    Run r;
    r.dc = compute_dual_cone(First_rows<std::decay_t<decltype(kernel)>>{kernel, n});
    if (r.dc.decided && r.dc.rank == 3) r.balanced = load_balanced(kernel, r.dc, n, &r.witness);
    return r;
  });
  a.predicates = tally.predicates;
  a.exact_predicates = tally.exact;
  const auto undecided = [&] {
    a.decided = false;
    return a;
  };
  if (!run.dc.decided) return undecided();
  if (run.dc.rank < 3) {  // W* has a lineality space: decide by the exact LP (hybrid) or abstain (float)
    if (mode == Mode::float_only) return undecided();
    ++a.predicates;
    ++a.exact_predicates;
    decide_by_lp(load_kernel(scene, a.load), a, certify);
    return a;
  }
  const Sign balanced = run.balanced;
  const std::array<std::size_t, 2>& witness = run.witness;
  if (balanced == Sign::uncertain) return undecided();
  a.balanced = balanced == Sign::positive;
  a.certificate.holds = a.balanced;
  if (!certify) return a;
  const Exact_kernel k = load_kernel(scene, a.load);
  if (k.size() != n + 1) throw std::logic_error("decide_equilibrium: twin and engine disagree on generators");
  if (a.balanced) {
    Equilibrium_answer lp = a;
    decide_by_lp(k, lp, true);
    if (!lp.balanced) throw std::logic_error("decide_equilibrium: dual cone and LP disagree");
    a.certificate = lp.certificate;
  } else {
    a.certificate.twist = twist_of_ray(k, witness[0], witness[1]);
  }
  return a;
}

}  // namespace wrenchkit
