// Kernels of the modes [FL-2]: per-predicate filtering (the float twin's certified sign, else the exact
// sign), exact generators built only when needed, predicate counters, and in_mode — the one dispatch on
// the mode for every sign-deciding algorithm of statics/ (closure, equilibrium, the wrench cone).
#pragma once

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <vector>

#include "core/mode.h"
#include "exact/statics/generators.h"
#include "float/float_kernel.h"

namespace wrenchkit {

// Counts the predicates of an exact kernel.
struct Counting_exact_kernel {
  const Exact_kernel& k;
  mutable std::size_t n = 0;
  std::size_t size() const { return k.size(); }
  Sign cross_sign(std::size_t i, std::size_t j) const { return ++n, k.cross_sign(i, j); }
  Sign det_sign(std::size_t i, std::size_t j, std::size_t l) const { return ++n, k.det_sign(i, j, l); }
};

// The exact generators of a scene, computed on first use only: the float path needs them only for
// an uncertain predicate or a certificate.
class Lazy_generators {
 public:
  // `extra`: rows appended after the generators for predicates only (equilibrium's load).
  Lazy_generators(const Scene& s, Reading r, std::vector<Vec3q> extra = {})
      : scene_(&s), reading_(r), extra_(std::move(extra)) {}
  // Wrenches that are already exact (no scene behind them): only wrenches() is available. `ready` is
  // not copied: it must outlive this object.
  explicit Lazy_generators(const std::vector<Vec3q>& ready) : ready_(&ready) {}
  const std::vector<Generator>& get() const {
    if (!gens_) {
      if (!scene_) throw std::logic_error("Lazy_generators: no scene behind these wrenches");
      gens_ = std::make_unique<std::vector<Generator>>(generators(*scene_, reading_));
      ws_ = std::make_unique<std::vector<Vec3q>>();
      for (const Generator& g : *gens_) ws_->push_back(g.w);
      for (const Vec3q& w : extra_) ws_->push_back(w);
    }
    return *gens_;
  }
  const std::vector<Vec3q>& wrenches() const { return ready_ ? *ready_ : ws_ ? *ws_ : (get(), *ws_); }
  // The exact kernel of the generators and the extra rows: built from the contacts' integers
  // directly (Exact_kernel(scene, reading, extra): no rational generators) when a scene is behind
  // them, else from the ready wrenches.
  std::unique_ptr<Exact_kernel> kernel() const {
    if (!scene_) return std::make_unique<Exact_kernel>(wrenches());
    return std::make_unique<Exact_kernel>(*scene_, reading_, extra_);
  }

 private:
  const Scene* scene_ = nullptr;
  const std::vector<Vec3q>* ready_ = nullptr;
  Reading reading_ = Reading::friction;
  std::vector<Vec3q> extra_;
  mutable std::unique_ptr<std::vector<Generator>> gens_;
  mutable std::unique_ptr<std::vector<Vec3q>> ws_;
};

// Per-predicate filtering: the twin's certified sign, else the exact sign (the exact kernel is
// built on the first uncertain predicate only).
class Hybrid_kernel {
 public:
  Hybrid_kernel(const fl::Float_kernel& f, const Lazy_generators& gens, bool fallback)
      : f_(f), gens_(gens), fallback_(fallback) {}
  std::size_t size() const { return f_.size(); }
  Sign cross_sign(std::size_t i, std::size_t j) const {
    ++n;
    const Sign s = f_.cross_sign(i, j);
    return s != Sign::uncertain || !fallback_ ? s : (++exact_n, exact().cross_sign(i, j));
  }
  Sign det_sign(std::size_t i, std::size_t j, std::size_t k) const {
    ++n;
    const Sign s = f_.det_sign(i, j, k);
    return s != Sign::uncertain || !fallback_ ? s : (++exact_n, exact().det_sign(i, j, k));
  }
  mutable std::size_t n = 0, exact_n = 0;

 private:
  const Exact_kernel& exact() const {
    if (!e_) e_ = gens_.kernel();
    return *e_;
  }
  const fl::Float_kernel& f_;
  const Lazy_generators& gens_;
  bool fallback_;
  mutable std::unique_ptr<Exact_kernel> e_;
};


// Signs asked and those of them decided in exact arithmetic (decided_by in core/mode.h reads them).
struct Predicate_tally {
  std::size_t predicates = 0, exact = 0;
};

// [FL-2] The one dispatch on the mode: `run(kernel)` on the exact kernel `exact()` (Mode::exact: every sign
// exact, no floating point at all) or on the kernel of the twin's rows `twin()` with per-predicate exact
// fallback from `lazy` (Mode::hybrid) or without it (Mode::float_only: a sign may be uncertain, and `run`
// must say so). `exact` returns a const Exact_kernel& and `twin` an fl::Float_kernel; each is asked only in
// its modes. Adds to `tally`; returns what `run` returns (the same type for both kernels).
template <class Exact, class Twin, class Run>
auto in_mode(Mode mode, Exact&& exact, Twin&& twin, const Lazy_generators& lazy, Predicate_tally& tally, Run&& run) {
  if (mode == Mode::exact) {
    const Counting_exact_kernel k{exact()};
    auto r = run(k);
    tally.predicates += k.n;
    tally.exact += k.n;
    return r;
  }
  const fl::Float_kernel rows = twin();
  const Hybrid_kernel k(rows, lazy, mode == Mode::hybrid);
  auto r = run(k);
  tally.predicates += k.n;
  tally.exact += k.exact_n;
  return r;
}

}  // namespace wrenchkit
