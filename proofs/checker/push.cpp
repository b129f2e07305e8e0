// proofs/checker/push.cpp - certificate-format.md §8 (format 6): which way a pushed body turns, by Mason's voting
// theorem over the support's admissible distributions F (proofs/notes/PU-1-voting-theorem.md). The checker computes
// the three lines through the pusher's point p from the scene (the friction cone's edges n + mu rot90 n, n - mu
// rot90 n, and the velocity v), and for a line along d the vote's numerator
//
//   N_d(f) = sum_i mu_i f_i (p - r_i) x d + sum_R mu_R (W_R p - M_R) x d,
//
// linear in the distribution f (its sign is the side of the centre of friction the line passes); D(f) = sum_i mu_i
// f_i + sum_R mu_R W_R is the friction under the body. The certificate's bounds are accepted only when proven: the
// value itself when every force is given, else by the LP dual over F (Support_witnesses::linear_bound). The rule is
// applied to every combination of the signs the bounds allow; the claim must be the one outcome. "depends": two
// distributions of F whose votes turn the body ccw and cw.
#include "proofs/checker/certificate.h"
#include "proofs/checker/generators.h"
#include "proofs/checker/support_witnesses.h"

#include <algorithm>

namespace wrenchkit_checker::detail {

void read_dual(Reader& r, Q (&out)[3]) {
  read_fixed(r, 3, "an array of three rationals [y0, yx, yy]", [&](std::size_t k) { out[k] = read_rational(r); });
}

// lo <= sqrt(s) <= hi for a rational s >= 0: the integer root of s's numerator times its denominator scaled by 4^B,
// B = bits + the denominator's bit length (the engine's precision for the same bits; a finer one only tightens).
void sqrt_bounds(const Q& s, std::size_t bits, Q& lo, Q& hi) {
  if (sgn(s) == 0) return void(lo = 0), void(hi = 0);
  const Z& p = s.get_num();
  const Z& q = s.get_den();
  const unsigned long B = bits + mpz_sizeinbase(q.get_mpz_t(), 2);
  Z x = p * q, root;
  mpz_mul_2exp(x.get_mpz_t(), x.get_mpz_t(), 2 * B);
  mpz_sqrt(root.get_mpz_t(), x.get_mpz_t());
  Z den = q;
  mpz_mul_2exp(den.get_mpz_t(), den.get_mpz_t(), B);
  lo = Q(root, den), hi = Q(root + (root * root == x ? 0 : 1), den);
  lo.canonicalize(), hi.canonicalize();
}

namespace {

Q cross(const Q& ax, const Q& ay, const Q& bx, const Q& by) { return ax * by - ay * bx; }


Push_part::Range read_range(Reader& r, bool lower_only) {
  Push_part::Range g;
  begin_object(r, lower_only ? "expected an object {\"lower\", \"dual_lower\"?}"
                             : "expected an object {\"lower\", \"upper\", \"dual_lower\"?, \"dual_upper\"?}");
  std::string_view k;
  bool lower = false;
  while (r.next_key(k)) {
    if (k == "lower") lower = true, g.lower = read_rational(r);
    else if (k == "upper" && !lower_only) g.has_upper = true, g.upper = read_rational(r);
    else if (k == "dual_lower") g.has_dual_lower = true, read_dual(r, g.dual_lower);
    else if (k == "dual_upper" && !lower_only) g.has_dual_upper = true, read_dual(r, g.dual_upper);
    else r.fail("unknown key " + quote(k), true);
  }
  if (!lower) r.fail("missing required key \"lower\"");
  if (!lower_only && !g.has_upper) r.fail("missing required key \"upper\"");
  return g;
}

std::vector<Q> read_distribution(Reader& r) {
  std::vector<Q> f;
  begin_array(r, "expected an array of forces, one per support point");
  while (r.next_item()) f.push_back(read_rational(r));
  return f;
}

// The rule on one distribution's votes (+1 ccw, -1 cw, 0 through c); 2 stands for "none".
int rule(int left, int right, int v) {
  if (left != 0 && left == right) return left;
  if (left != 0 && right != 0) return v == 0 ? 2 : v;
  if (left == 0 && right == 0) return 2;
  const int s = left != 0 ? left : right;
  return v == s ? s : 2;
}
const char* word(int o) { return o == 1 ? "ccw" : o == -1 ? "cw" : "none"; }

// ---- §8.2 the contact mode (proofs/notes/PU-2-contact-mode.md) ----

struct Rho {
  Q x, y, rho;  // a support point and mu f
};

// The interval of sum rho_i (l_i . v_i(x)) / |v_i(x)| over x in [a, b], l_i = l, or rot90(r_i - p) for the moment
// about p. v_i(x) = u + x rot90(r_i - p) (x the rotation rate), or with `slip`: u + w rot90(r_i - p) + x slip (x the
// slip speed, at the fixed rate *w). False when a speed may vanish on the interval.
bool interval(const std::vector<Rho>& pts, const Q (&p)[2], const Q (&u)[2], const Q (&l)[2], bool moment, const Q& a,
              const Q& b, std::size_t bits, Q& lo, Q& hi, const Q* slip = nullptr, const Q* w = nullptr) {
  lo = 0, hi = 0;
  for (const Rho& q : pts) {
    if (sgn(q.rho) == 0) continue;
    const Q dx = q.x - p[0], dy = q.y - p[1], rx = -dy, ry = dx;
    const Q bx = slip ? Q(u[0] + *w * rx) : u[0], by = slip ? Q(u[1] + *w * ry) : u[1];
    const Q wx = slip ? slip[0] : rx, wy = slip ? slip[1] : ry;
    const Q lx = moment ? rx : l[0], ly = moment ? ry : l[1];
    const Q c0 = lx * bx + ly * by, c1 = lx * wx + ly * wy;
    Q n0 = c0 + a * c1, n1 = c0 + b * c1;
    if (n0 > n1) std::swap(n0, n1);
    const Q uu = bx * bx + by * by, uw = bx * wx + by * wy, dd = wx * wx + wy * wy;
    const auto quad = [&](const Q& x) { return Q(uu + 2 * x * uw + x * x * dd); };
    Q qmin = std::min(quad(a), quad(b)), qmax = std::max(quad(a), quad(b));
    if (sgn(dd) != 0) {
      const Q v = -uw / dd;
      if (a <= v && v <= b) qmin = std::min(qmin, quad(v));
    }
    if (sgn(qmin) <= 0) return false;
    Q s0, s1, t0, t1;
    sqrt_bounds(qmin, bits, s0, s1);
    const Q slo = s0;
    sqrt_bounds(qmax, bits, s0, s1);
    const Q shi = s1;
    if (sgn(slo) <= 0) return false;
    if (sgn(n0) >= 0) t0 = n0 / shi, t1 = n1 / slo;
    else if (sgn(n1) <= 0) t0 = n0 / slo, t1 = n1 / shi;
    else t0 = n0 / slo, t1 = n1 / slo;
    lo += q.rho * t0, hi += q.rho * t1;
  }
  return true;
}

// A candidate's bracket [w0, w1] of the root of g (the moment about p of the load of u + w rotation about p),
// nondecreasing: g(w0) < 0 < g(w1) certified; or w0 = w1 = 0 with g(0) = 0 exactly ((c - p) x u = 0).
void bracket(const std::vector<Rho>& pts, const Q (&p)[2], const Q (&u)[2], const Q (&w)[2], std::size_t bits,
             const std::string& path) {
  const Q none[2] = {Q(0), Q(0)};
  if (w[0] == w[1]) {
    Q g0 = 0;
    for (const Rho& q : pts) g0 += q.rho * ((q.x - p[0]) * u[1] - (q.y - p[1]) * u[0]);
    if (sgn(w[0]) != 0 || sgn(g0) != 0)
      throw Failure{path + ": a one-point bracket is only the translation through the centre of friction (omega 0 "
                           "with the velocity through c)"};
    return;
  }
  if (w[0] > w[1]) throw Failure{path + ": not an interval [lower, upper]"};
  for (int k = 0; k < 2; ++k) {
    Q lo, hi;
    if (!interval(pts, p, u, none, true, w[k], w[k], bits, lo, hi))
      throw Failure{path + ": a support point is at rest at omega " + show(w[k]) + " (a pivot: not a bracket end)"};
    if (k == 0 ? !(hi < 0) : !(lo > 0))
      throw Failure{path + ": the moment about the pusher at omega " + show(w[k]) + " is not certainly " +
                    (k == 0 ? "negative" : "positive") + " (bits " + std::to_string(bits) + ")"};
  }
}

// The sign of l . F over a candidate's bracket: +1, -1, or 0 when not certain (exact: F along u).
int force_sign(const std::vector<Rho>& pts, const Q (&p)[2], const Q (&u)[2], const Q (&w)[2], const Q (&l)[2],
               std::size_t bits) {
  if (w[0] == w[1]) {
    const Q v = l[0] * u[0] + l[1] * u[1];
    return sgn(v) > 0 ? 1 : sgn(v) < 0 ? -1 : 3;
  }
  Q lo, hi;
  if (!interval(pts, p, u, l, false, w[0], w[1], bits, lo, hi)) return 0;
  return lo > 0 ? 1 : hi < 0 ? -1 : 0;
}

// PU-2 §6–8: the facet of the rotation about support point j (rate w, velocity u at p): the other points' force F' and
// moment M' about p, bracketed (fx, fy, m); d = r_j - p.
void facet_rest(const std::vector<Rho>& pts, std::size_t j, const Q (&p)[2], const Q (&u)[2], const Q& w,
                std::size_t bits, const std::string& path, Q (&fx)[2], Q (&fy)[2], Q (&m)[2]) {
  if (sgn(pts[j].rho) == 0) throw Failure{path + ": that support point cannot be the pivot (no friction)"};
  std::vector<Rho> rest;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (i != j) rest.push_back(pts[i]);
  const Q ex[2] = {Q(1), Q(0)}, ey[2] = {Q(0), Q(1)}, none[2] = {Q(0), Q(0)};
  if (!interval(rest, p, u, ex, false, w, w, bits, fx[0], fx[1]) ||
      !interval(rest, p, u, ey, false, w, w, bits, fy[0], fy[1]) ||
      !interval(rest, p, u, none, true, w, w, bits, m[0], m[1]))
    throw Failure{path + ": another support point is at rest"};
}

// [lo, hi] of k x for x in [lo, hi]
void range(const Q& k, const Q& lo, const Q& hi, Q (&out)[2]) {
  out[0] = k * lo, out[1] = k * hi;
  if (out[0] > out[1]) std::swap(out[0], out[1]);
}

// PU-2 §6–7: the facet holds a force along e through p: lambda = (d x F' - M') / (d x e) certainly > 0 and
// |lambda e - F'|^2 certainly < rho_j^2.
void check_facet(const std::vector<Rho>& pts, std::size_t j, const Q (&p)[2], const Q (&u)[2], const Q& w,
                 const Q (&e)[2], std::size_t bits, const std::string& path, const char* along) {
  const Rho& pj = pts[j];
  const Q d[2] = {pj.x - p[0], pj.y - p[1]}, de = d[0] * e[1] - d[1] * e[0];
  if (sgn(de) == 0) throw Failure{path + ": that support point cannot be the pivot (its line is the force's)"};
  Q fx[2], fy[2], m[2];
  facet_rest(pts, j, p, u, w, bits, path, fx, fy, m);
  Q a[2], b[2], lam[2];
  range(d[0], fy[0], fy[1], a), range(-d[1], fx[0], fx[1], b);
  range(1 / de, a[0] + b[0] - m[1], a[1] + b[1] - m[0], lam);
  Q gx[2], gy[2];
  range(e[0], lam[0], lam[1], gx), range(e[1], lam[0], lam[1], gy);
  const Q g0 = std::max(Q((gx[0] - fx[1]) * (gx[0] - fx[1])), Q((gx[1] - fx[0]) * (gx[1] - fx[0])));
  const Q g1 = std::max(Q((gy[0] - fy[1]) * (gy[0] - fy[1])), Q((gy[1] - fy[0]) * (gy[1] - fy[0])));
  if (!(lam[0] > 0) || !(g0 + g1 < pj.rho * pj.rho))
    throw Failure{path + ": no force of the pivot's facet is certainly along " + along + " through the pusher"};
}

// PU-2 §8: the facet's forces through p — the chord d x F = d x F' - M', |F - F'| <= rho_j — are not empty (M'^2 <
// rho_j^2 |d|^2 certainly: g's jump holds 0) and all strictly on the positive side of l: A = |d|^2 (l . F') - M' (l .
// rot90 d) certainly > 0 and A^2 certainly > (l . d)^2 (rho_j^2 |d|^2 - M'^2).
void check_facet_beyond(const std::vector<Rho>& pts, std::size_t j, const Q (&p)[2], const Q (&u)[2], const Q& w,
                        const Q (&l)[2], std::size_t bits, const std::string& path) {
  const Rho& pj = pts[j];
  const Q d[2] = {pj.x - p[0], pj.y - p[1]};
  Q fx[2], fy[2], m[2];
  facet_rest(pts, j, p, u, w, bits, path, fx, fy, m);
  const Q dd = d[0] * d[0] + d[1] * d[1], reach = pj.rho * pj.rho * dd;
  const Q m2_max = std::max(Q(m[0] * m[0]), Q(m[1] * m[1]));
  const Q m2_min = sgn(m[0]) <= 0 && sgn(m[1]) >= 0 ? Q(0) : std::min(Q(m[0] * m[0]), Q(m[1] * m[1]));
  if (!(m2_max < reach))
    throw Failure{path + ": the pivot's facet holds no force through the pusher certainly (its moment jump may miss 0)"};
  Q a[2], b[2], c[2];
  range(l[0] * dd, fx[0], fx[1], a), range(l[1] * dd, fy[0], fy[1], b);
  range(-(l[0] * -d[1] + l[1] * d[0]), m[0], m[1], c);
  const Q A = a[0] + b[0] + c[0], ld = l[0] * d[0] + l[1] * d[1];
  if (!(sgn(A) > 0) || !(A * A > ld * ld * (reach - m2_min)))
    throw Failure{path + ": not every force of the pivot's facet through the pusher is certainly beyond the claimed edge"};
}

// §8.2 "sliding" with "pivot" (PU-2 §6): the rotation about support point j. Exact slip x = -(v . d) / (t . d) and rate
// w = -(u . rot90 d) / |d|^2 (d = r_j - p, u = v + x t: the rotation's velocity at p); its facet holds a force along
// the edge (check_facet).
void check_pivot(const Push_part& c, const std::vector<Rho>& pts, const Q (&p)[2], const Q (&n)[2], const Q (&v)[2],
                 const Q (&l)[2]) {
  if (c.pivot >= pts.size()) throw Failure{"contact.sliding.pivot: no such support point"};
  const Rho& pj = pts[c.pivot];
  const Q t[2] = {-n[1], n[0]}, d[2] = {pj.x - p[0], pj.y - p[1]}, e[2] = {l[1], -l[0]};
  const Q td = t[0] * d[0] + t[1] * d[1];
  if (sgn(td) == 0) throw Failure{"contact.sliding.pivot: no slip brings that support point to rest"};
  const Q x = -(v[0] * d[0] + v[1] * d[1]) / td, u[2] = {v[0] + x * t[0], v[1] + x * t[1]};
  const Q w = (u[0] * d[1] - u[1] * d[0]) / (d[0] * d[0] + d[1] * d[1]);  // -(u . rot90 d) / |d|^2
  if (c.mode == "slides right" ? !(sgn(x) > 0) : !(sgn(x) < 0))
    throw Failure{"contact.sliding.pivot: the rotation about that point slips the wrong way for the claimed edge"};
  if (c.slip[0] != x || c.slip[1] != x || c.motion[0] != w || c.motion[1] != w)
    throw Failure{"contact.sliding: the rotation about the pivot has slip " + show(x) + " and omega " + show(w)};
  check_facet(pts, c.pivot, p, u, w, e, c.bits, "contact.sliding.pivot", "the edge");
}

// PU-2 §7–8: the rotation about support point j that moves p with u — u . d = 0 exactly (d = r_j - p != 0) — at the
// rate w = -(u . rot90 d) / |d|^2, which the claimed interval must be exactly. Returns w.
Q pivot_rate(const std::vector<Rho>& pts, std::size_t j, const Q (&p)[2], const Q (&u)[2], const Q (&claimed)[2],
             const char* velocity, const std::string& path, const std::string& rate_path) {
  if (j >= pts.size()) throw Failure{path + ": no such support point"};
  const Q d[2] = {pts[j].x - p[0], pts[j].y - p[1]}, dd = d[0] * d[0] + d[1] * d[1];
  if (sgn(dd) == 0 || sgn(u[0] * d[0] + u[1] * d[1]) != 0)
    throw Failure{path + ": " + velocity + " is not perpendicular to the line to that support point"};
  const Q w = (u[0] * d[1] - u[1] * d[0]) / dd;
  if (claimed[0] != w || claimed[1] != w) throw Failure{rate_path + ": the rotation about the pivot has omega " + show(w)};
  return w;
}

// §8.2 "sliding" (PU-2 §5): the body's velocity at p is u(x) = v + x t (t = rot90 n) with its force along the edge e
// (l = rot90 e: l . F = e x F, which increases with x). Exact: x0 = x1 with omega 0, u(x0) along e and through c.
// Else e x F certainly negative at x0 and positive at x1 (each by its own omega bracket), and the rate's bracket
// certain over the whole slip bracket: the moment about p at omega[0] negative and at omega[1] positive for every x.
void check_sliding(const Push_part& c, const std::vector<Rho>& pts, const Q (&p)[2], const Q (&n)[2], const Q (&v)[2],
                   const Q (&l)[2]) {
  const Q t[2] = {-n[1], n[0]};
  const auto at = [&](const Q& x, Q (&u)[2]) { u[0] = v[0] + x * t[0], u[1] = v[1] + x * t[1]; };
  if (c.slip[0] > c.slip[1] || c.motion[0] > c.motion[1])
    throw Failure{"contact.sliding: \"slip\" and \"omega\" are intervals [lower, upper]"};
  if (c.has_pivot) return check_pivot(c, pts, p, n, v, l);
  if (c.slip[0] == c.slip[1]) {
    Q u[2];
    at(c.slip[0], u);
    Q rho = 0, g0 = 0;
    for (const Rho& q : pts) rho += q.rho, g0 += q.rho * ((q.x - p[0]) * u[1] - (q.y - p[1]) * u[0]);
    if (sgn(c.motion[0]) != 0 || sgn(c.motion[1]) != 0 || sgn(g0) != 0 || sgn(l[0] * u[0] + l[1] * u[1]) != 0 ||
        sgn(rho) == 0)
      throw Failure{"contact.sliding: an exact slip is only the translation along the edge through the centre of "
                    "friction (omega 0)"};
    const Q e[2] = {l[1], -l[0]};
    if (sgn(e[0] * u[0] + e[1] * u[1]) <= 0) throw Failure{"contact.sliding: the translation does not go along the edge"};
    return;
  }
  for (int k = 0; k < 2; ++k) {
    Q u[2];
    at(c.slip[k], u);
    const std::string path = "contact.sliding.slip_omega[" + std::to_string(k) + "]";
    bracket(pts, p, u, c.slip_omega[k], c.bits, path);
    if (force_sign(pts, p, u, c.slip_omega[k], l, c.bits) != (k == 0 ? -1 : 1))
      throw Failure{"contact.sliding: at slip " + show(c.slip[k]) + " the force is not certainly " +
                    (k == 0 ? "clockwise" : "counter-clockwise") + " of the edge"};
  }
  const Q none[2] = {Q(0), Q(0)};
  for (int k = 0; k < 2; ++k) {
    Q lo, hi;
    if (!interval(pts, p, v, none, true, c.slip[0], c.slip[1], c.bits, lo, hi, t, &c.motion[k]) ||
        (k == 0 ? !(hi < 0) : !(lo > 0)))
      throw Failure{"contact.sliding.omega: the moment about the pusher at omega " + show(c.motion[k]) +
                    " is not certainly " + (k == 0 ? "negative" : "positive") + " over the slip bracket"};
  }
}

// §8.2: the contact mode claimed in "contact" for the support points with the forces `pts` (every one given).
void check_contact_on(const Push_part& c, const std::vector<Rho>& pts, const Q (&p)[2], const Q (&n)[2], const Q& mu,
                      const Q (&v)[2]) {
  if (c.bits < 16 || c.bits > 4096) throw Failure{"contact.bits: expected bits from 16 to 4096"};
  const Q eL[2] = {n[0] - mu * n[1], n[1] + mu * n[0]}, eR[2] = {n[0] + mu * n[1], n[1] - mu * n[0]};
  const Q rl[2] = {-eL[1], eL[0]}, rr[2] = {-eR[1], eR[0]};  // rot90: rot90(a) . F = a x F
  const Q lr[2] = {rr[0], rr[1]}, ll[2] = {-rl[0], -rl[1]};  // e_R x F > 0, F x e_L > 0: inside the cone
  // The sticking motion: a pivot (PU-2 §7–8: ω exact, its forces the facet's chord) or a bracket of ω (§4). `all_beyond`:
  // every force of it certainly on the positive side of l.
  const bool pivot = c.has_stick_pivot;
  const Q w = pivot ? pivot_rate(pts, c.stick_pivot, p, v, c.omega, "the pusher's velocity", "contact.pivot",
                                  "contact.omega")
                    : Q(0);
  if (!pivot) bracket(pts, p, v, c.omega, c.bits, "contact.omega");
  const auto all_beyond = [&](const Q (&l)[2]) {
    if (!pivot) return force_sign(pts, p, v, c.omega, l, c.bits);
    check_facet_beyond(pts, c.stick_pivot, p, v, w, l, c.bits, "contact.pivot");
    return 1;
  };
  if (c.has_sliding && c.mode != "slides left" && c.mode != "slides right")
    throw Failure{"contact.sliding: only a sliding contact has a sliding motion"};
  if (c.mode == "sticks" && pivot) {  // a force of the facet strictly inside the cone, along "force"
    if (sgn(lr[0] * c.force[0] + lr[1] * c.force[1]) <= 0 || sgn(ll[0] * c.force[0] + ll[1] * c.force[1]) <= 0)
      throw Failure{"contact.force: not strictly inside the friction cone"};
    check_facet(pts, c.stick_pivot, p, v, w, c.force, c.bits, "contact.pivot", "the claimed force");
  } else if (c.mode == "sticks") {
    if (sgn(mu) == 0 || all_beyond(lr) != 1 || all_beyond(ll) != 1)
      throw Failure{"contact: \"sticks\", but the sticking motion's force is not certainly inside the friction cone"};
  } else if (c.mode == "impending") {
    if (pivot || (force_sign(pts, p, v, c.omega, lr, c.bits) != 3 && force_sign(pts, p, v, c.omega, ll, c.bits) != 3))
      throw Failure{"contact: \"impending\" is the translation along a cone edge, exactly (omega 0 and the velocity "
                    "along an edge)"};
  } else {  // slides: the force outside the cone, beyond the claimed edge within the pushing half-plane
    if (!c.has_tangent) throw Failure{"contact: a sliding claim needs \"tangent_omega\""};
    const Q t[2] = {-n[1], n[0]};
    const bool on_left = c.mode == "slides left";
    const Q(&re)[2] = on_left ? rl : rr;
    const Q beyond[2] = {on_left ? re[0] : Q(-re[0]), on_left ? re[1] : Q(-re[1])};  // e_L x F > 0; F x e_R > 0
    int in_h = 1;  // e x F(t) > 0: e in the pushing half-plane — for every force of F(t) when it is a facet's chord
    if (c.has_tangent_pivot) {
      const Q wt = pivot_rate(pts, c.tangent_pivot, p, t, c.tangent, "the tangent rot90(n)", "contact.tangent_pivot",
                              "contact.tangent_omega");
      check_facet_beyond(pts, c.tangent_pivot, p, t, wt, re, c.bits, "contact.tangent_pivot");
    } else {
      bracket(pts, p, t, c.tangent, c.bits, "contact.tangent_omega");
      in_h = force_sign(pts, p, t, c.tangent, re, c.bits);
    }
    if (!pivot && sgn(mu) != 0 && all_beyond(lr) == 1 && all_beyond(ll) == 1)
      throw Failure{"contact: the sticking motion's force is inside the cone"};
    if (in_h != 1 || all_beyond(beyond) != 1)
      throw Failure{std::string("contact: \"") + std::string(c.mode) + "\", but the sticking motion's force is not "
                    "certainly beyond that edge of the cone within the forces that push"};
    if (c.has_sliding) check_sliding(c, pts, p, n, v, re);
  }
}

// The support points with ρ_i = μ_i f_i: the given forces, or `forces` (a distribution, one per point).
std::vector<Rho> contact_points(const Support& s, const Limits& lim, const std::vector<Q>* forces) {
  std::vector<Rho> pts;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    Point_values scratch;
    const Point_values& pv = values(s.points[i], lim, scratch);
    pts.push_back({pv.x, pv.y, Q(pv.mu * (forces ? (*forces)[i] : pv.f))});
  }
  return pts;
}

// §8.2: every force given — the contact mode on them; forces not given — "depends": two distributions of F whose
// certified modes differ, each checked as if its forces were the scene's.
void check_contact(const Push_part& c, const Support& s, const Support_witnesses& sw, const Limits& lim, const Q (&p)[2],
                   const Q (&n)[2], const Q& mu, const Q (&v)[2]) {
  if (!s.regions.empty()) throw Failure{"contact: the contact mode is claimed for support points (no regions)"};
  const auto on = [&](const Push_part& k, const std::vector<Q>* forces) {
    check_contact_on(k, contact_points(s, lim, forces), p, n, mu, v);
  };
  if (c.mode != "depends") {
    if (s.unknown != 0)
      throw Failure{"contact: a contact mode is claimed for support points with every force given (else \"depends\")"};
    return on(c, nullptr);
  }
  if (s.unknown == 0) throw Failure{"contact: \"depends\" needs a support force that is not given"};
  if (c.contact_witnesses.size() != 2 || c.contact_witnesses[0]->mode == c.contact_witnesses[1]->mode)
    throw Failure{"contact.witnesses: \"depends\" needs two distributions whose contact modes differ"};
  for (std::size_t k = 0; k < 2; ++k) {
    const Push_part& w = *c.contact_witnesses[k];
    sw.in_f(w.witness_forces, ("contact.witnesses[" + std::to_string(k) + "].forces").c_str());
    on(w, &w.witness_forces);
  }
}

}  // namespace

// §8.2's "contact" (or, `witness`, one of a "depends" claim's two distributions with its own contact mode and "forces").
void read_contact(Reader& r, Push_part& p, bool witness) {
  p.has_contact = true;
  begin_object(r, "expected an object {\"mode\", \"bits\", \"omega\", \"tangent_omega\"?}");
  std::string_view k;
  unsigned seen = 0;
  while (r.next_key(k)) {
    if (k == "mode") {
      seen |= 1;
      const char* modes = witness ? "expected \"sticks\", \"impending\", \"slides left\" or \"slides right\""
                                  : "expected \"sticks\", \"impending\", \"slides left\", \"slides right\" or \"depends\"";
      if (r.peek() != Reader::Kind::string) r.fail(modes);
      p.mode = r.string_view();
      if (p.mode != "sticks" && p.mode != "impending" && p.mode != "slides left" && p.mode != "slides right" &&
          (witness || p.mode != "depends"))
        r.fail(modes);
    } else if (k == "forces" && witness) {
      seen |= 16;
      p.witness_forces = read_distribution(r);
    } else if (k == "witnesses" && !witness) {
      seen |= 32;
      begin_array(r, "expected the two distributions [{\"forces\", \"mode\", …}, {…}]");
      while (r.next_item()) {
        if (p.contact_witnesses.size() == 2) r.fail("\"depends\" has two witnesses");
        read_contact(r, *p.contact_witnesses.emplace_back(std::make_unique<Push_part>()), true);
      }
    } else if (k == "bits") {
      seen |= 2;
      p.bits = read_index(r, "number of bits");  // (its range: check_contact, once the certificate is read)
    } else if (k == "omega") {
      seen |= 4;
      read_fixed(r, 2, "an interval [lower, upper]", [&](std::size_t m) { p.omega[m] = read_rational(r); });
    } else if (k == "pivot") {
      p.has_stick_pivot = true;
      p.stick_pivot = read_index(r, "support point index");
    } else if (k == "force") {
      seen |= 8;
      read_fixed(r, 2, "a force direction [fx, fy]", [&](std::size_t m) { p.force[m] = read_rational(r); });
    } else if (k == "tangent_pivot") {
      p.has_tangent_pivot = true;
      p.tangent_pivot = read_index(r, "support point index");
    } else if (k == "tangent_omega") {
      p.has_tangent = true;
      read_fixed(r, 2, "an interval [lower, upper]", [&](std::size_t m) { p.tangent[m] = read_rational(r); });
    } else if (k == "sliding") {
      p.has_sliding = true;
      begin_object(r, "expected an object {\"slip\", \"slip_omega\", \"omega\"}");
      std::string_view j;
      unsigned got = 0;
      while (r.next_key(j)) {
        if (j == "slip") {
          got |= 1;
          read_fixed(r, 2, "an interval [lower, upper]", [&](std::size_t m) { p.slip[m] = read_rational(r); });
        } else if (j == "pivot") {
          p.has_pivot = true;
          p.pivot = read_index(r, "support point index");
        } else if (j == "slip_omega") {
          p.has_slip_omega = true;
          read_fixed(r, 2, "two intervals (one per end of the slip)", [&](std::size_t e) {
            read_fixed(r, 2, "an interval [lower, upper]", [&](std::size_t m) { p.slip_omega[e][m] = read_rational(r); });
          });
        } else if (j == "omega") {
          got |= 4;
          read_fixed(r, 2, "an interval [lower, upper]", [&](std::size_t m) { p.motion[m] = read_rational(r); });
        } else {
          r.fail("unknown key " + quote(j), true);
        }
      }
      if (got != 5 || p.has_pivot == p.has_slip_omega)
        r.fail("a sliding motion needs \"slip\", \"omega\" and either \"slip_omega\" or \"pivot\"");
    } else {
      r.fail("unknown key " + quote(k), true);
    }
  }
  if (p.mode == "depends") {
    if (seen != 33) r.fail("\"depends\" has \"mode\" and \"witnesses\" only");
    return;
  }
  if (witness && !(seen & 16)) r.fail("a witness of \"depends\" needs its \"forces\"");
  if ((seen & 7) != 7) r.fail("a contact needs \"mode\", \"bits\" and \"omega\"");
  // "pivot": the sticking motion a rotation about a support point — sticking with "force" (§7), or sliding (§8)
  const bool sticks = p.mode == "sticks", sliding = p.mode == "slides left" || p.mode == "slides right";
  if ((seen & 8) && !(p.has_stick_pivot && sticks)) r.fail("\"force\" is a sticking pivot's (with \"pivot\", \"mode\": \"sticks\")");
  if (p.has_stick_pivot && !sliding && !(seen & 8)) r.fail("a sticking pivot needs both \"pivot\" and \"force\"");
}

void read_push_member(Reader& r, std::string_view key, Certificate& c) {
  Push_part& p = c.pu();
  if (key == "rotation") {
    if (r.peek() != Reader::Kind::string) r.fail("expected \"ccw\", \"cw\", \"none\" or \"depends\"");
    p.rotation = r.string_view();
    if (p.rotation != "ccw" && p.rotation != "cw" && p.rotation != "none" && p.rotation != "depends")
      r.fail("expected \"ccw\", \"cw\", \"none\" or \"depends\"");
  } else if (key == "friction") {
    p.has_friction = true;
    p.friction = read_range(r, true);
  } else if (key == "votes") {
    read_fixed(r, 3, "an array of three ranges (left edge, right edge, velocity)",
               [&](std::size_t) { p.votes.push_back(read_range(r, false)); });
  } else if (key == "center") {
    p.has_center = true;
    read_fixed(r, 2, "a point [x, y]", [&](std::size_t k) { p.center[k] = read_rational(r); });
  } else if (key == "contact") {
    read_contact(r, p, false);
  } else if (key == "region" || key == "stable") {  // §8.3 (stable_push.cpp)
    read_line_push_member(r, key, p);
  } else if (key == "locus") {  // §8.4 (push_locus.cpp)
    read_locus_member(r, p);
  } else {  // turns
    p.has_turns = true;
    begin_object(r, "expected an object {\"ccw\": [forces], \"cw\": [forces]}");
    std::string_view k;
    unsigned seen = 0;
    while (r.next_key(k)) {
      if (k == "ccw") seen |= 1, p.turns_ccw = read_distribution(r);
      else if (k == "cw") seen |= 2, p.turns_cw = read_distribution(r);
      else r.fail("unknown key " + quote(k), true);
    }
    if (seen != 3) r.fail("expected both \"ccw\" and \"cw\"");
  }
}

void check_push(const Certificate& c, const Scene& scene, const Limits& lim) {
  const Push_part& p = *c.push_members;
  if (!scene.pusher) throw Failure{"push: the scene has no pusher"};
  if (!scene.support) throw Failure{"push: the scene has no support"};
  if (scene.pusher->line) return check_line_push(p, scene, lim);
  if (p.has_stable) throw Failure{"stable: a point pusher's certificate has no \"stable\" (§8.3 is a line pusher's)"};
  const Support& s = *scene.support;
  const Support_witnesses sw(s, lim);
  const std::vector<Q> pn = contact_numbers(scene.pusher->contact, lim);  // x, y, nx, ny, mu
  const Q &px = pn[0], &py = pn[1], &nx = pn[2], &ny = pn[3], &mu = pn[4];
  const Q(&v)[2] = scene.pusher->velocity;
  if (sgn(Q(v[0] * nx + v[1] * ny)) <= 0) throw Failure{"pusher.velocity: does not push into the body (v . n <= 0)"};
  const Q dir[3][2] = {{nx - mu * ny, ny + mu * nx}, {nx + mu * ny, ny - mu * nx}, {v[0], v[1]}};
  const bool known = s.unknown == 0;
  const std::vector<Q> given = sw.given();
  const std::size_t n = s.points.size();
  // A claimed range [lower, upper] of sum coef_i f_i + K over F, proven: lower <= min, upper >= max.
  const auto proven = [&](const std::vector<Q>& coef, const Q& K, const Push_part::Range& g, bool lower_only,
                          const std::string& path) {
    if (!known && (!g.has_dual_lower || (!lower_only && !g.has_dual_upper)))
      throw Failure{path + ": some support force is not given, so each bound needs its LP dual over F"};
    if (known && (g.has_dual_lower || g.has_dual_upper))
      throw Failure{path + ": every support force is given: no dual (the bounds are the value)"};
    std::vector<Q> neg(coef.size());
    for (std::size_t i = 0; i < coef.size(); ++i) neg[i] = -coef[i];
    const Q min = K - sw.linear_bound(neg, given, known ? nullptr : g.dual_lower, (path + ".dual_lower: -coef_i").c_str());
    if (g.lower > min) throw Failure{path + ".lower: " + show(g.lower) + " is more than the proven " + show(min)};
    if (lower_only) return;
    const Q max = K + sw.linear_bound(coef, given, known ? nullptr : g.dual_upper, (path + ".dual_upper: coef_i").c_str());
    if (g.upper < max) throw Failure{path + ".upper: " + show(g.upper) + " is less than the proven " + show(max)};
  };
  // D(f) > 0: friction under the body for every distribution.
  std::vector<Q> coef(n);
  Q K = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Point_values scratch;
    coef[i] = values(s.points[i], lim, scratch).mu;
  }
  for (const Region& g : s.regions) K += g.mu * g.W;
  proven(coef, K, p.friction, true, "friction");
  if (sgn(p.friction.lower) <= 0)
    throw Failure{"friction.lower: " + show(p.friction.lower) + " is not positive (the claim needs friction under the body)"};
  // The votes' numerators for one distribution f.
  std::array<std::vector<Q>, 3> vcoef;
  std::array<Q, 3> vK;
  for (int k = 0; k < 3; ++k) {
    vcoef[k].resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      Point_values scratch;
      const Point_values& pv = values(s.points[i], lim, scratch);
      vcoef[k][i] = pv.mu * cross(px - pv.x, py - pv.y, dir[k][0], dir[k][1]);
    }
    vK[k] = 0;
    for (const Region& g : s.regions)
      vK[k] += g.mu * cross(g.W * px - g.M[0], g.W * py - g.M[1], dir[k][0], dir[k][1]);
  }
  // The given forces' friction D and moment sum mu_i f_i r_i + sum mu_R M_R (0 where a force is unknown): the centre
  // of friction when every force is given (checked by "center", and by a tied "none" below).
  Q given_moment[2] = {0, 0}, given_friction = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Point_values scratch;
    const Point_values& pv = values(s.points[i], lim, scratch);
    given_moment[0] += pv.mu * pv.f * pv.x, given_moment[1] += pv.mu * pv.f * pv.y, given_friction += pv.mu * pv.f;
  }
  for (const Region& g : s.regions)
    given_moment[0] += g.mu * g.M[0], given_moment[1] += g.mu * g.M[1], given_friction += g.mu * g.W;
  const auto at = [&](int k, const std::vector<Q>& f) {
    Q x = vK[k];
    for (std::size_t i = 0; i < n; ++i) x += vcoef[k][i] * f[i];
    return sgn(x);
  };
  if (p.has_center) {  // c = (sum mu_i f_i r_i + sum mu_R M_R) / D: the given forces', or, when every coefficient is
    // the same, the centre of pressure c of F (the same for every distribution); else c moves and is not claimed
    Point_values first_scratch;
    const Q first_mu = n ? values(s.points[0], lim, first_scratch).mu : s.regions.front().mu;  // (points or regions)
    bool same_mu = true;
    for (std::size_t i = 0; i < n; ++i) {
      Point_values scratch;
      same_mu = same_mu && values(s.points[i], lim, scratch).mu == first_mu;
    }
    for (const Region& g : s.regions) same_mu = same_mu && g.mu == first_mu;
    const Q(&m)[2] = given_moment;
    const Q& d = given_friction;
    if (known) {
      if (p.center[0] * d != m[0] || p.center[1] * d != m[1])
        throw Failure{"center: " + show(p.center[0], p.center[1]) + " is not the centre of friction " +
                      show(Q(m[0] / d), Q(m[1] / d))};
    } else if (!same_mu) {
      throw Failure{"center: the support's coefficients differ and some force is not given, so the centre of friction "
                    "moves with the distribution (no one centre to claim)"};
    } else if (p.center[0] != s.c[0] || p.center[1] != s.c[1]) {
      throw Failure{"center: " + show(p.center[0], p.center[1]) + " is not the centre of pressure " + show(s.c[0], s.c[1]) +
                    " (every coefficient is the same: the centre of friction)"};
    }
  }
  if (p.has_contact) check_contact(p, s, sw, lim, {px, py}, {nx, ny}, mu, v);
  if (p.has_locus) check_locus(p, scene, lim);  // (on the rotation claimed: the rest of this check proves it)
  if (p.slowest) {  // §8.4: a distribution of F turning the body at a certified rate: its centre at least arm_lo away
    const Push_part& w = *p.slowest;
    if (known) {
      if (w.witness_forces != given) throw Failure{"locus.slowest.forces: not the given forces"};
    } else {
      sw.in_f(w.witness_forces, "locus.slowest.forces");
    }
    if (!s.regions.empty()) throw Failure{"locus.slowest: a distribution of support points (no regions)"};
    check_contact_on(w, contact_points(s, lim, &w.witness_forces), {px, py}, {nx, ny}, mu, v);
    const bool sticks = w.mode == "sticks", slides = (w.mode == "slides left" || w.mode == "slides right") && w.has_sliding;
    if (!sticks && !slides) throw Failure{"locus.slowest: a sticking or sliding motion with its rate"};
    const Q(&om)[2] = sticks ? w.omega : w.motion;
    if (sgn(om[0]) == 0 || sgn(om[0]) != sgn(om[1])) throw Failure{"locus.slowest: its rate's sense is not certain"};
    const Q most = std::max(abs(om[0]), abs(om[1])), vn = v[0] * nx + v[1] * ny;
    if (sgn(p.arm_lo) < 0 || p.arm_lo * p.arm_lo * most * most * (nx * nx + ny * ny) > vn * vn)
      throw Failure{"locus.arm_lo: " + show(p.arm_lo) + " is more than v.n / (|omega| |n|) of the slowest distribution's "
                    "centre"};
  }
  if (p.rotation == "depends") {
    if (!p.has_turns) throw Failure{"missing required key \"turns\" (two distributions that turn the body apart)"};
    if (!p.votes.empty()) throw Failure{"key \"votes\" is not allowed when \"rotation\" is \"depends\""};
    sw.in_f(p.turns_ccw, "turns.ccw");
    sw.in_f(p.turns_cw, "turns.cw");
    if (rule(at(0, p.turns_ccw), at(1, p.turns_ccw), at(2, p.turns_ccw)) != 1)
      throw Failure{"turns.ccw: its votes do not turn the body ccw"};
    if (rule(at(0, p.turns_cw), at(1, p.turns_cw), at(2, p.turns_cw)) != -1)
      throw Failure{"turns.cw: its votes do not turn the body cw"};
    return;
  }
  if (p.has_turns) throw Failure{"key \"turns\" is allowed only when \"rotation\" is \"depends\""};
  if (p.votes.size() != 3) throw Failure{"missing required key \"votes\""};
  static const char* const names[3] = {"votes[0]", "votes[1]", "votes[2]"};
  std::vector<int> signs[3];
  for (int k = 0; k < 3; ++k) {
    proven(vcoef[k], vK[k], p.votes[k], false, names[k]);
    for (int t = -1; t <= 1; ++t)
      if (sgn(p.votes[k].lower) <= t && t <= sgn(p.votes[k].upper)) signs[k].push_back(t);
  }
  const int claim = p.rotation == "ccw" ? 1 : p.rotation == "cw" ? -1 : 2;
  bool smooth = false;  // a "none" that rests on a smooth translation point (PU-1 section 4)
  for (int l : signs[0])
    for (int r : signs[1])
      for (int w : signs[2]) {
        const int o = rule(l, r, w);
        if (o != claim)
          throw Failure{std::string("rotation: \"") + std::string(p.rotation) + "\", but votes " +
                        word(l == 0 ? 2 : l) + "/" + word(r == 0 ? 2 : r) + "/" + word(w == 0 ? 2 : w) +
                        " (left edge, right edge, velocity; \"none\" = through c) allowed by the bounds give \"" +
                        word(o) + "\""};
        smooth |= o == 2 && !(l != 0 && r != 0 && l != r);
      }
  if (!smooth) return;
  // "none" from an edge through c: no distribution may put all its friction on one line through c. A region with
  // friction spreads it over an area; else every force is given and some point with friction is off that line.
  for (const Region& g : s.regions)
    if (sgn(g.mu) > 0) return;
  if (!known) throw Failure{"rotation: \"none\" needs a support whose friction is not on one line (a region with mu > 0, "
                            "or every force given)"};
  // (every force given, no region with friction: the given forces' centre of friction)
  const Q cx = given_moment[0] / given_friction, cy = given_moment[1] / given_friction, dx = cx - px, dy = cy - py;
  bool first = true;
  Q lx, ly;
  for (std::size_t i = 0; i < n; ++i) {
    Point_values scratch;
    const Point_values& pv = values(s.points[i], lim, scratch);
    if (sgn(pv.mu) == 0 || sgn(pv.f) == 0) continue;
    const Q rx = pv.x - cx, ry = pv.y - cy;
    if (sgn(dx) != 0 || sgn(dy) != 0) {
      if (sgn(Q(rx * dx + ry * dy)) != 0) return;
    } else if (sgn(rx) != 0 || sgn(ry) != 0) {
      if (first) lx = rx, ly = ry, first = false;
      else if (sgn(cross(lx, ly, rx, ry)) != 0) return;
    }
  }
  throw Failure{"rotation: \"none\", but the support's friction lies on one line through the centre of friction, where "
                "the limit surface turns at the translation: the votes do not decide"};
}

}  // namespace wrenchkit_checker::detail
