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
  explicit Float_kernel(std::vector<Bounded3> g) : g_(std::move(g)) {}
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

  Sign det_sign(std::size_t i, std::size_t j, std::size_t k) const {
    const Bounded3& a = g_[i];
    const Bounded3& b = g_[j];
    const Bounded3& c = g_[k];
    const Bounded d = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                      a[2] * (b[0] * c[1] - b[1] * c[0]);
    return d.sign();
  }

 private:
  std::vector<Bounded3> g_;
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
