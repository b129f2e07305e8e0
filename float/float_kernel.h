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
  explicit Float_kernel(std::vector<Bounded3> g) : g_(std::move(g)) {
    mag_.reserve(g_.size());
    err_.reserve(g_.size());
    for (const Bounded3& x : g_) {
      std::array<double, 6> m{};
      for (int c = 0; c < 3; ++c) {
        m[c] = std::fabs(x[c].v);
        m[3 + c] = x[c].e;
      }
      mag_.push_back(m);
      err_.push_back(x[0].e + x[1].e + x[2].e);
    }
  }
  std::size_t size() const { return g_.size(); }
  const std::vector<Bounded3>& generators() const { return g_; }

  // zero iff g_i × g_j = 0: every minor certified zero; positive if one is certified nonzero.
  Sign cross_sign(std::size_t i, std::size_t j) const {
    const Bounded3& a = g_[i];
    const Bounded3& b = g_[j];
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
  Sign det_sign(std::size_t i, std::size_t j, std::size_t k) const {
    const Sign fast = det_sign_static(i, j, k);
    if (fast != Sign::uncertain) return fast;
    // det is invariant under cyclic permutations of its rows: expand along the row with the largest
    // input error, so that the 2×2 cofactors come from the other rows — exact when those rows are
    // exact, and then an exactly zero cofactor stays a certified zero (e.g. two parallel exact
    // forces with an inexact third: the cancellation happens inside an exact minor).
    const double ei = err_[i], ej = err_[j], ek = err_[k];
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
  // A = |â| + e_a etc., |D − D̂| ≤ Σ_σ (e_a·B·C + |â|·e_b·C + |â|·|b̂|·e_c) + 6u·Σ_σ |â||b̂||ĉ|,
  // the sums over the six terms of the determinant; the bound is inflated for its own rounding.
  Sign det_sign_static(std::size_t i, std::size_t j, std::size_t k) const {
    const Bounded3& a = g_[i];
    const Bounded3& b = g_[j];
    const Bounded3& c = g_[k];
    const double d = a[0].v * (b[1].v * c[2].v - b[2].v * c[1].v) - a[1].v * (b[0].v * c[2].v - b[2].v * c[0].v) +
                     a[2].v * (b[0].v * c[1].v - b[1].v * c[0].v);
    const auto& ma = mag_[i];
    const auto& mb = mag_[j];
    const auto& mc = mag_[k];
    double perm = 0, prop = 0;
    // The six terms a_p·b_q·c_r, (p, q, r) a permutation of (0, 1, 2).
    static constexpr int kPerm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    for (const auto& s : kPerm) {
      const double xa = ma[s[0]], xb = mb[s[1]], xc = mc[s[2]];
      const double ea = ma[3 + s[0]], eb = mb[3 + s[1]], ec = mc[3 + s[2]];
      perm += xa * xb * xc;
      prop += ea * (xb + eb) * (xc + ec) + xa * eb * (xc + ec) + xa * xb * ec;
    }
    const double bound = (prop + 0x1p-50 * perm) * Bounded::kInflate + Bounded::kSlack;
    if (!(bound < Bounded::kInf) || !std::isfinite(d) || perm < Bounded::kUnderflow * 0x1p60) return Sign::uncertain;
    if (d > bound) return Sign::positive;
    if (-d > bound) return Sign::negative;
    return Sign::uncertain;
  }

 private:
  std::vector<Bounded3> g_;
  std::vector<std::array<double, 6>> mag_;  // |v| and e of each coordinate
  std::vector<double> err_;                 // total input error of each generator
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
