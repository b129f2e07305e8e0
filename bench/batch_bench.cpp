// Batch throughput (issue 5): scenes per second on one core for `batch closure`'s work, the scene
// readers alone, where a certified answer's time goes, and the robot-side twin call. Every scene is a
// random 6-contact frictional grasp written as decimal text, one JSON line, as a grasp planner would
// send it: contacts on the unit circle ("%.6f"), inward normals perturbed by U(-0.3, 0.3), mu in
// [0.1, 0.6] ("%.3f"); fixed seed.
//   cmake -S . -B build-bench -G Ninja -DWRENCHKIT_BUILD_BENCH=ON && cmake --build build-bench --target batch_bench
//   build-bench/bench/batch_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// items_per_second is scenes per second (one thread). End to end, with JSON parsing and writing and
// the process's I/O: `wrenchkit batch closure --jobs 1 --verdict-only < scenes.jsonl` (docs/cli.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "exact/certificates/certificates.h"
#include "exact/pipeline/batch.h"
#include "exact/pipeline/hold_answer.h"
#include "exact/pipeline/labels_answer.h"
#include "exact/statics/closure.h"
#include "exact/io/scene.h"
#include "exact/io/streaming_scene_reader.h"
#include "float/closure_twin.h"
#include "proofs/checker/checker.h"
#include "testing/stress_families.h"

namespace {

using namespace wrenchkit;

const std::vector<std::string>& scene_lines() {
  static const std::vector<std::string> lines = [] {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> angle(0, 6.283185307179586), jitter(-0.3, 0.3), mu(0.1, 0.6);
    std::vector<std::string> out;
    for (int s = 0; s < 1000; ++s) {
      std::string t = "{\"wrenchkit\": 1, \"contacts\": [";
      for (int i = 0; i < 6; ++i) {
        const double a = angle(rng), x = std::cos(a), y = std::sin(a);
        char buf[160];
        std::snprintf(buf, sizeof buf, "%s{\"at\": [%.6f, %.6f], \"normal\": [%.6f, %.6f], \"mu\": %.3f}", i ? ", " : "",
                      x, y, -x + jitter(rng), -y + jitter(rng), mu(rng));
        t += buf;
      }
      out.push_back(t + "]}");
    }
    return out;
  }();
  return lines;
}

// ---- batch closure: read + force and form closure (+ certificates, + the checker), one thread ----

void BM_batch_closure(benchmark::State& st, bool certify, bool check) {
  const auto& lines = scene_lines();
  Request o;
  o.certify = certify;
  o.check = check ? Check::independent : Check::none;
  Scene scratch;
  std::size_t i = 0;
  for (auto _ : st) {
    const Closure_item r = answer_closure(lines[i++ % lines.size()], "line", o, scratch);
    benchmark::DoNotOptimize(r.force.holds);
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations()));
}
BENCHMARK_CAPTURE(BM_batch_closure, verdict_only, false, false);
BENCHMARK_CAPTURE(BM_batch_closure, certificates, true, false);
BENCHMARK_CAPTURE(BM_batch_closure, certificates_checked, true, true);

// batch labels' work (issue 19): read + the exact moment labels in hybrid (no certificate: labels have none).
void BM_batch_labels(benchmark::State& st) {
  const auto& lines = scene_lines();
  const Request o;
  std::size_t i = 0;
  for (auto _ : st) {
    const Labels_item r = answer_labels(lines[i++ % lines.size()], "line", o, Labels_query{});
    benchmark::DoNotOptimize(r.status);
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations()));
}
BENCHMARK(BM_batch_labels);

// The C++ batch API on 1000 scenes per iteration, one thread (its ordered map included).
void BM_batch_api_verdict_only(benchmark::State& st) {
  const auto& lines = scene_lines();
  Batch_options o;
  o.request.certify = false;
  o.jobs = 1;
  for (auto _ : st) benchmark::DoNotOptimize(batch_closure(lines, o).size());
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * lines.size()));
}
BENCHMARK(BM_batch_api_verdict_only);

// batch hold's work (issue 16): read + hold with its certificate checked, one thread, per scene: 4 frictional
// contacts and 10 known support points (testing/stress_families.h fixture_text, loads 0.5–1.5 of Σ μ_i f_i).
const std::vector<std::string>& fixture_lines() {
  static const std::vector<std::string> lines = [] {
    stress::Rng rng(16);
    std::vector<std::string> out;
    for (int s = 0; s < 500; ++s) out.push_back(stress::fixture_text(rng, 4, 10, 0.5 + (s % 11) / 10.0));
    return out;
  }();
  return lines;
}

void BM_batch_hold(benchmark::State& st, Mode mode) {
  const auto& lines = fixture_lines();
  Request o;
  o.mode = mode;
  std::size_t i = 0, held = 0, undecided = 0;
  for (auto _ : st) {
    const Hold_item r = answer_hold(lines[i++ % lines.size()], "line", o);
    held += r.answer.verdict == Hold_verdict::holds;
    undecided += r.status != Status::answered || r.answer.verdict == Hold_verdict::undecided;
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations()));
  st.counters["held"] = benchmark::Counter(double(held) / double(st.iterations()));
  st.counters["undecided"] = double(undecided);
}
BENCHMARK_CAPTURE(BM_batch_hold, hybrid, Mode::hybrid);
BENCHMARK_CAPTURE(BM_batch_hold, float, Mode::float_only);

// ---- the scene readers alone ----

void BM_read_dom(benchmark::State& st, bool lazy) {
  const auto& lines = scene_lines();
  std::size_t i = 0;
  for (auto _ : st)
    benchmark::DoNotOptimize(read_scene(lines[i++ % lines.size()], Input_limits{}, "line", lazy).contacts.size());
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations()));
}
BENCHMARK_CAPTURE(BM_read_dom, eager, false);
BENCHMARK_CAPTURE(BM_read_dom, lazy, true);

void BM_read_streaming(benchmark::State& st, bool lazy) {
  const auto& lines = scene_lines();
  Scene scratch;
  std::size_t i = 0;
  for (auto _ : st) {
    read_scene_into(scratch, lines[i++ % lines.size()], Input_limits{}, "line", lazy);
    benchmark::DoNotOptimize(scratch.contacts.size());
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations()));
}
BENCHMARK_CAPTURE(BM_read_streaming, eager, false);
BENCHMARK_CAPTURE(BM_read_streaming, lazy, true);

// ---- where a certified answer's time goes (per scene: both properties) ----

// decide_closure ×2 on a scene already read eagerly: verdicts only, and with both certificates built.
void BM_decide_both(benchmark::State& st, bool certify) {
  const auto& lines = scene_lines();
  std::vector<Scene> scenes;
  for (std::size_t k = 0; k < 256; ++k) scenes.push_back(read_scene(lines[k], Input_limits{}));
  std::size_t i = 0;
  for (auto _ : st) {
    const Scene& s = scenes[i++ % scenes.size()];
    benchmark::DoNotOptimize(decide_closure(s, Property::force_closure, Mode::hybrid, certify).holds);
    benchmark::DoNotOptimize(decide_closure(s, Property::form_closure, Mode::hybrid, certify).holds);
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations()));
}
BENCHMARK_CAPTURE(BM_decide_both, verdict_only, false);
BENCHMARK_CAPTURE(BM_decide_both, certificates_built, true);

// The independent checker on both certificates of a scene: one scene read (check_all, what the CLI
// does) and two (check() per certificate).
void BM_checker(benchmark::State& st, bool together) {
  const auto& lines = scene_lines();
  std::vector<std::string> fc, fo;
  for (std::size_t k = 0; k < 256; ++k) {
    const Scene s = read_scene(lines[k], Input_limits{});
    fc.push_back(certificate_json(decide_closure(s, Property::force_closure, Mode::hybrid).certificate));
    fo.push_back(certificate_json(decide_closure(s, Property::form_closure, Mode::hybrid).certificate));
  }
  std::size_t i = 0;
  for (auto _ : st) {
    const std::size_t k = i++ % fc.size();
    if (together) {
      benchmark::DoNotOptimize(wrenchkit_checker::check_all(lines[k], {fc[k], fo[k]}).size());
    } else {
      benchmark::DoNotOptimize(wrenchkit_checker::check(lines[k], fc[k]).outcome);
      benchmark::DoNotOptimize(wrenchkit_checker::check(lines[k], fo[k]).outcome);
    }
  }
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations()));
}
BENCHMARK_CAPTURE(BM_checker, both_one_scene_read, true);
BENCHMARK_CAPTURE(BM_checker, each_reads_the_scene, false);

// ---- the robot-side twin: fl::force_closure on 6 frictional contacts given as plain doubles ----

void BM_twin_force_closure(benchmark::State& st) {
  const auto& lines = scene_lines();
  std::vector<std::vector<fl::Point_contact>> sets;
  for (std::size_t k = 0; k < 256; ++k) {
    std::vector<fl::Point_contact> c;
    for (const Contact& x : read_scene(lines[k], Input_limits{}).contacts)
      c.push_back({x.at.x.get_d(), x.at.y.get_d(), x.normal.x.get_d(), x.normal.y.get_d(), x.mu.get_d()});
    sets.push_back(c);
  }
  std::size_t i = 0;
  for (auto _ : st) benchmark::DoNotOptimize(fl::force_closure(sets[i++ % sets.size()]));
  st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations()));
}
BENCHMARK(BM_twin_force_closure);

}  // namespace

BENCHMARK_MAIN();
