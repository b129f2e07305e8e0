// [FL-2] Predicate kernels of the float twin for core/dual_cone.h, over generators with error bounds.
//
//   Float_kernel  certified: each sign comes from Bounded arithmetic [FL-1] and is exact or
//                 Sign::uncertain; a certified answer is the exact answer for the scene as written.
//   Naive_kernel  raw double signs, no bound: it guesses. For benchmarks and stress tests only, to
//                 measure how often guessing is wrong; never used to answer a user.
// Standard library only.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/sign.h"
#include "float/bounded.h"

namespace wrenchkit::fl {

using Bounded3 = std::array<Bounded, 3>;

class Float_kernel {
 public:
  explicit Float_kernel(std::vector<Bounded3> g) : g_(std::move(g)) { stage0_bounds(); }
  // Stage 0 from column bounds the caller computed with the generators: M_c ≥ max |x̂_c|, Mu_c ≥ max(|x̂_c| + e_c)
  // and E_c ≥ max e_c over column c. The caller also guarantees Stage 0's guard (every nonzero |x̂| in
  // [2^-300, 2^300], e < 2^300, Mu ≤ 2^301): the static generators of float/closure_twin.h do, by their
  // input range (proofs/notes/FL-1, "Static generators").
  struct Column_bounds {
    double M[3] = {0, 0, 0}, Mu[3] = {0, 0, 0}, E[3] = {0, 0, 0};
  };
  Float_kernel(std::vector<Bounded3> g, const Column_bounds& b) : g_(std::move(g)) { stage0_from(b.M, b.Mu, b.E); }
  std::size_t size() const { return g_.size(); }
  const std::vector<Bounded3>& generators() const { return g_; }

  // zero iff g_i × g_j = 0: every minor certified zero; positive if one is certified nonzero.
  // Stage 1 as for det_sign: a minor's static bound (proofs/notes/FL-1, "Stage 1") certifies most
  // non-parallel pairs without Bounded arithmetic.
  // Stage 0 first: each minor against one bound per column pair for the whole kernel (FL-1 "Stage 0").
  Sign cross_sign(std::size_t i, std::size_t j) const {
    const Bounded3& a = g_[i];
    const Bounded3& b = g_[j];
    for (int p = 0; p < 3; ++p) {
      const int q = (p + 1) % 3, r = (p + 2) % 3;
      const double m = a[q].v * b[r].v - a[r].v * b[q].v;
      if (std::fabs(m) > cross_bound_[p]) return Sign::positive;
    }
    const Magnitudes& ma = mag()[i];
    const Magnitudes& mb = mag()[j];
    for (int p = 0; p < 3; ++p) {
      const int q = (p + 1) % 3, r = (p + 2) % 3;
      const double m = a[q].v * b[r].v - a[r].v * b[q].v;
      const double perm = ma.abs[q] * mb.abs[r] + ma.abs[r] * mb.abs[q];
      const double perm_up = ma.up[q] * mb.up[r] + ma.up[r] * mb.up[q];
      const double bound =
          (perm_up * (1 + 0x1p-48) - perm * (1 - 0x1p-48) + 0x1p-49 * perm) * Bounded::kInflate + Bounded::kSlack;
      if (bound < Bounded::kInf && std::isfinite(m) && perm >= Bounded::kUnderflow * 0x1p60 && std::fabs(m) > bound)
        return Sign::positive;
    }
    const Sign s[3] = {(a[1] * b[2] - a[2] * b[1]).sign(), (a[2] * b[0] - a[0] * b[2]).sign(),
                       (a[0] * b[1] - a[1] * b[0]).sign()};
    bool uncertain = false;
    for (Sign x : s) {
      if (x == Sign::positive || x == Sign::negative) return Sign::positive;
      uncertain |= x == Sign::uncertain;
    }
    return uncertain ? Sign::uncertain : Sign::zero;
  }

  // Two stages [FL-2]: a plain-double determinant with a bound from magnitudes (cheap, decides
  // almost every non-degenerate sign), then the Bounded evaluation [FL-1], whose exact rounding
  // errors also certify exact zeros of exact data.
  // Stage 0 [FL-2] first: the plain-double determinant against one bound for the whole scene
  // (scene_bound(), computed once from the columns' largest magnitudes and input errors); it decides
  // almost every sign of an ordinary scene for the price of the determinant alone.
  Sign det_sign(std::size_t i, std::size_t j, std::size_t k) const {
    const Bounded3& a = g_[i];
    const Bounded3& b = g_[j];
    const Bounded3& c = g_[k];
    const double d0 = a[0].v * (b[1].v * c[2].v - b[2].v * c[1].v) - a[1].v * (b[0].v * c[2].v - b[2].v * c[0].v) +
                      a[2].v * (b[0].v * c[1].v - b[1].v * c[0].v);
    if (d0 > scene_bound_) return Sign::positive;
    if (-d0 > scene_bound_) return Sign::negative;
    return det_sign_filtered(i, j, k);
  }

  // Stage 0's bound on |D − D̂| for every determinant of this kernel (+∞ when the stage declines).
  double scene_bound() const { return scene_bound_; }
  // … and for the minor p (columns p+1, p+2 mod 3) of every pair.
  double cross_bound(int p) const { return cross_bound_[p]; }

  // Stages 1 and 2 alone (what det_sign does when stage 0 cannot decide).
  Sign det_sign_filtered(std::size_t i, std::size_t j, std::size_t k) const {
    const Sign fast = det_sign_static(i, j, k);
    if (fast != Sign::uncertain) return fast;
    // det is invariant under cyclic permutations of its rows: expand along the row with the largest
    // input error, so that the 2×2 cofactors come from the other rows — exact when those rows are
    // exact, and then an exactly zero cofactor stays a certified zero (e.g. two parallel exact
    // forces with an inexact third: the cancellation happens inside an exact minor).
    const double ei = mag()[i].err, ej = mag()[j].err, ek = mag()[k].err;
    if (ej > ei && ej >= ek) {
      const std::size_t t = i;
      i = j, j = k, k = t;
    } else if (ek > ei && ek > ej) {
      const std::size_t t = k;
      k = j, j = i, i = t;
    }
    const Bounded3& a = g_[i];
    const Bounded3& b = g_[j];
    const Bounded3& c = g_[k];
    const Bounded d = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                      a[2] * (b[0] * c[1] - b[1] * c[0]);
    return d.sign();
  }

  // Stage 1 (proofs/notes/FL-1, "Stage 1"): D̂ = det of the doubles in the order above; with
  // A = |â| and A' ≥ |â| + e_a ≥ |a| (per coordinate), and perm(·) the permanent of three rows,
  //   |D − D̂| ≤ perm(A', B', C') − perm(A, B, C) + 8u·perm(A, B, C),
  // evaluated with outward-rounding nudges (two permanents of 9 products each).
  Sign det_sign_static(std::size_t i, std::size_t j, std::size_t k) const {
    const Bounded3& a = g_[i];
    const Bounded3& b = g_[j];
    const Bounded3& c = g_[k];
    const double d = a[0].v * (b[1].v * c[2].v - b[2].v * c[1].v) - a[1].v * (b[0].v * c[2].v - b[2].v * c[0].v) +
                     a[2].v * (b[0].v * c[1].v - b[1].v * c[0].v);
    const std::vector<Magnitudes>& mg = mag();
    const double perm = permanent(mg[i].abs, mg[j].abs, mg[k].abs);
    const double perm_up =
        mg[i].err + mg[j].err + mg[k].err == 0 ? perm : permanent(mg[i].up, mg[j].up, mg[k].up);
    const double bound =
        (perm_up * (1 + 0x1p-48) - perm * (1 - 0x1p-48) + 0x1p-49 * perm) * Bounded::kInflate + Bounded::kSlack;
    if (!(bound < Bounded::kInf) || !std::isfinite(d) || perm < Bounded::kUnderflow * 0x1p60) return Sign::uncertain;
    if (d > bound) return Sign::positive;
    if (-d > bound) return Sign::negative;
    return Sign::uncertain;
  }

 private:
  struct Magnitudes {
    std::array<double, 3> abs;  // |v| of each coordinate
    std::array<double, 3> up;   // an upper bound of the exact |x| of each coordinate
    double err;                 // total input error of the generator
  };
  // Per generator, for Stages 1 and 2: computed on the first predicate Stage 0 cannot decide (most
  // kernels never need them). A kernel is used by one thread at a time (each decision builds its own).
  const std::vector<Magnitudes>& mag() const {
    if (mag_.size() != g_.size()) {
      mag_.resize(g_.size());
      for (std::size_t i = 0; i < g_.size(); ++i) {
        const Bounded3& x = g_[i];
        Magnitudes& m = mag_[i];
        for (int c = 0; c < 3; ++c) {
          m.abs[c] = std::fabs(x[c].v);
          m.up[c] = up(x[c]);
        }
        m.err = x[0].e + x[1].e + x[2].e;
      }
    }
    return mag_;
  }

  // An upper bound of the exact |x|: |v| + e rounded up (a sum and a nudge of 2^-51 cover both
  // roundings; proofs/notes/FL-1, "Stage 1").
  static double up(const Bounded& x) { return x.e == 0 ? std::fabs(x.v) : (std::fabs(x.v) + x.e) * (1 + 0x1p-51); }

  // Stage 0 (proofs/notes/FL-1, "Stage 0"): with M_c = max |x̂_c|, M'_c ≥ max(|x̂_c| + e_c) and E_c = max e_c
  // over the generators (column c), every determinant of three of them has
  //   |D − D̂| ≤ 6·(E0·M'1·M'2 + M'0·E1·M'2 + M'0·M'1·E2) + 48u·M0·M1·M2,
  // and every minor a_q·b_r − a_r·b_q of two of them
  //   |m − m̂| ≤ 2·(E_q·M'_r + M'_q·E_r) + 5u·M_q·M_r,
  // provided no product underflows or overflows: every nonzero |x̂| within [2^-300, 2^300] (else +∞: the
  // stage declines). Evaluated with an upward nudge of 2^-45 and a slack of 2^-1000.
  void stage0_bounds() {
    double M[3] = {0, 0, 0}, Mu[3] = {0, 0, 0}, E[3] = {0, 0, 0};
    for (const Bounded3& x : g_)
      for (int c = 0; c < 3; ++c) {
        const double a = std::fabs(x[c].v), u = up(x[c]);
        if (a != 0 && !(a >= 0x1p-300 && a <= 0x1p300)) return;  // also NaN and ±∞: the bounds stay +∞
        if (!(x[c].e < 0x1p300) || !(u <= 0x1p301)) return;       // also NaN
        M[c] = a > M[c] ? a : M[c];
        Mu[c] = u > Mu[c] ? u : Mu[c];
        E[c] = x[c].e > E[c] ? x[c].e : E[c];
      }
    stage0_from(M, Mu, E);
  }
  void stage0_from(const double (&M)[3], const double (&Mu)[3], const double (&E)[3]) {
    const double in = 6 * (E[0] * Mu[1] * Mu[2] + Mu[0] * E[1] * Mu[2] + Mu[0] * Mu[1] * E[2]);
    const double round = 0x1p-53 * 48 * (M[0] * M[1] * M[2]);
    scene_bound_ = (in + round) * (1 + 0x1p-45) + 0x1p-1000;
    for (int p = 0; p < 3; ++p) {
      const int q = (p + 1) % 3, r = (p + 2) % 3;
      cross_bound_[p] = (2 * (E[q] * Mu[r] + Mu[q] * E[r]) + 0x1p-53 * 5 * M[q] * M[r]) * (1 + 0x1p-45) + 0x1p-1000;
    }
  }

  // Σ over the six permutations σ of x_σ0·y_σ1·z_σ2 (non-negative entries).
  static double permanent(const std::array<double, 3>& x, const std::array<double, 3>& y, const std::array<double, 3>& z) {
    return x[0] * (y[1] * z[2] + y[2] * z[1]) + x[1] * (y[0] * z[2] + y[2] * z[0]) + x[2] * (y[0] * z[1] + y[1] * z[0]);
  }
  std::vector<Bounded3> g_;
  mutable std::vector<Magnitudes> mag_;  // filled by mag() on first use
  double scene_bound_ = Bounded::kInf;   // stage 0's bound for every determinant (+∞: declined)
  double cross_bound_[3] = {Bounded::kInf, Bounded::kInf, Bounded::kInf};  // … for minor p (columns p+1, p+2)
};

class Naive_kernel {
 public:
  explicit Naive_kernel(const std::vector<Bounded3>& g) {
    for (const Bounded3& x : g) g_.push_back({x[0].v, x[1].v, x[2].v});
  }
  std::size_t size() const { return g_.size(); }
  Sign cross_sign(std::size_t i, std::size_t j) const {
    const auto& a = g_[i];
    const auto& b = g_[j];
    const bool zero = a[1] * b[2] - a[2] * b[1] == 0 && a[2] * b[0] - a[0] * b[2] == 0 &&
                      a[0] * b[1] - a[1] * b[0] == 0;
    return zero ? Sign::zero : Sign::positive;
  }
  Sign det_sign(std::size_t i, std::size_t j, std::size_t k) const {
    const auto& a = g_[i];
    const auto& b = g_[j];
    const auto& c = g_[k];
    const double d = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                     a[2] * (b[0] * c[1] - b[1] * c[0]);
    return d > 0 ? Sign::positive : (d < 0 ? Sign::negative : Sign::zero);
  }

 private:
  std::vector<std::array<double, 3>> g_;
};

}  // namespace wrenchkit::fl
