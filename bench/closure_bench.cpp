// Closure throughput: the float twin (robot-side API), hybrid and exact decisions, with and
// without certificates, on random generic 6-contact frictional grasps (fixed seed).
//   cmake -S . -B build -DWRENCHKIT_BUILD_BENCH=ON && cmake --build build --target closure_bench
//   build/bench/closure_bench
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "core/dual_cone.h"
#include "exact/closure.h"
#include "exact/to_float.h"
#include "float/closure_twin.h"

namespace {

using namespace wrenchkit;

// Random grasps: contacts on the unit circle (decimal text, as users write it), inward normals
// perturbed, μ in [0.1, 0.6]. Mostly force closure, sometimes not.
std::vector<std::string> scenes(int contacts, int count) {
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> angle(0, 6.283185307179586), jitter(-0.3, 0.3), mu(0.1, 0.6);
  std::vector<std::string> out;
  for (int s = 0; s < count; ++s) {
    std::string t = "{\"wrenchkit\": 1, \"contacts\": [";
    for (int i = 0; i < contacts; ++i) {
      const double a = angle(rng), x = std::cos(a), y = std::sin(a);
      char buf[256];
      std::snprintf(buf, sizeof buf, "%s{\"at\": [%.6f, %.6f], \"normal\": [%.6f, %.6f], \"mu\": %.3f}", i ? ", " : "",
                    x, y, -x + jitter(rng), -y + jitter(rng), mu(rng));
      t += buf;
    }
    out.push_back(t + "]}");
  }
  return out;
}

std::vector<Scene> parsed(int contacts) {
  std::vector<Scene> v;
  for (const auto& t : scenes(contacts, 256)) v.push_back(read_scene(t, Input_limits{}));
  return v;
}

void BM_twin_plain_doubles(benchmark::State& st) {
  std::vector<std::vector<fl::Point_contact>> sets;
  for (const Scene& s : parsed(int(st.range(0)))) {
    std::vector<fl::Point_contact> c;
    for (const Contact& k : s.contacts)
      c.push_back({k.at.x.get_d(), k.at.y.get_d(), k.normal.x.get_d(), k.normal.y.get_d(), k.mu.get_d()});
    sets.push_back(c);
  }
  std::size_t i = 0;
  for (auto _ : st) benchmark::DoNotOptimize(fl::force_closure(sets[i++ % sets.size()]));
}

void BM_naive_plain_doubles(benchmark::State& st) {
  std::vector<std::vector<fl::Bounded3>> sets;
  for (const Scene& s : parsed(int(st.range(0)))) sets.push_back(fl::generators(to_bounded(s), Reading::friction));
  std::size_t i = 0;
  for (auto _ : st) {
    const fl::Naive_kernel k(sets[i++ % sets.size()]);
    benchmark::DoNotOptimize(compute_dual_cone(k).force_closure());
  }
}

// The certified kernel on precomputed generators: the same work as BM_naive_plain_doubles.
void BM_twin_kernel_only(benchmark::State& st) {
  std::vector<std::vector<fl::Bounded3>> sets;
  for (const Scene& s : parsed(int(st.range(0)))) sets.push_back(fl::generators(to_bounded(s), Reading::friction));
  std::size_t i = 0;
  for (auto _ : st) {
    const fl::Float_kernel k(sets[i++ % sets.size()]);
    benchmark::DoNotOptimize(compute_dual_cone(k).force_closure());
  }
}

void BM_decide(benchmark::State& st, Mode mode, bool certify) {
  const std::vector<Scene> s = parsed(int(st.range(0)));
  std::size_t i = 0;
  for (auto _ : st)
    benchmark::DoNotOptimize(decide_closure(s[i++ % s.size()], Property::force_closure, mode, certify).holds);
}

void BM_parse(benchmark::State& st) {
  const auto t = scenes(int(st.range(0)), 256);
  std::size_t i = 0;
  for (auto _ : st) benchmark::DoNotOptimize(read_scene(t[i++ % t.size()], Input_limits{}).contacts.size());
}

BENCHMARK(BM_twin_plain_doubles)->Arg(3)->Arg(6)->Arg(8);
BENCHMARK(BM_naive_plain_doubles)->Arg(6);
BENCHMARK(BM_twin_kernel_only)->Arg(6);
BENCHMARK_CAPTURE(BM_decide, float_verdict_only, Mode::float_only, false)->Arg(6);
BENCHMARK_CAPTURE(BM_decide, hybrid_verdict_only, Mode::hybrid, false)->Arg(6);
BENCHMARK_CAPTURE(BM_decide, exact_verdict_only, Mode::exact, false)->Arg(6);
BENCHMARK_CAPTURE(BM_decide, hybrid_with_certificate, Mode::hybrid, true)->Arg(6);
BENCHMARK_CAPTURE(BM_decide, exact_with_certificate, Mode::exact, true)->Arg(6);
BENCHMARK(BM_parse)->Arg(6);

}  // namespace

BENCHMARK_MAIN();
