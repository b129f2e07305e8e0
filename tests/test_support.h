// Shared helpers of the test suite: scene text builders, seeded random scenes, an O(k³) brute
// force, failure dumps, and the independent checker as a GoogleTest predicate.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "exact/io/scene.h"

namespace wrenchkit::test {

std::string source_dir();
std::string read_text(const std::string& path);
// The *.scene.json files of a folder under the source tree (not recursive), sorted, and the text of
// the matching *.expected.json.
std::vector<std::string> scene_files(const std::string& folder);
std::string expected_of(const std::string& scene_file);

// A contact written as text, exactly as a user would (empty mu: none written).
struct Contact_spec {
  std::string ax, ay, nx, ny, mu;
  std::string wrench = "";  // non-empty: a wrench generator "[fx, fy, m]" written verbatim
};
std::string scene_json(const std::vector<Contact_spec>& contacts, const std::string& name = "");

// Two fingers with the segment between them 10^-k away from the friction-cone edge (theory.md §8.5,
// μ = 1/2): y2 = 1 − 10^-k (closed: force closure) and 1 + 10^-k (not), k = 1 … 40; the contacts as text
// and, for the naive float kernels, as the nearest doubles (strtod).
struct Near_edge_grasp {
  std::string y2, text;
  bool closed = false;
  double contacts[2][5];  // ax, ay, nx, ny, mu
};
std::vector<Near_edge_grasp> near_edge_grasps();

// Seed for randomized tests: WRENCHKIT_SEED from the environment, else `fallback`.
std::uint64_t seed(std::uint64_t fallback);

// Random scene on a small integer grid, so that degenerate configurations (parallel, concurrent,
// coincident, on a cone edge) are frequent. 0 … max_contacts contacts; a few wrench generators.
std::vector<Contact_spec> random_contacts(std::mt19937_64& rng, int max_contacts);

// Random contacts as users write them: decimal coordinates with 3 digits (0.137 is not a double),
// integer normals, μ in 0.01 … 0.80: generic, nothing exactly degenerate by construction.
std::vector<Contact_spec> decimal_contacts(std::mt19937_64& rng, int contacts);

// Calls check(text, tag) on n random scenes, the i-th written by make(rng, i) (contacts) with one generator
// seeded by seed(fallback) and tagged "<prefix>_<seed>_<i>" (for dump_failure); stops at the first fatal
// failure (the caller then returns: HasFatalFailure()).
template <class Make, class Check>
void for_random_scenes(std::uint64_t fallback, int n, const std::string& prefix, Make make, Check check) {
  const std::uint64_t s = seed(fallback);
  std::mt19937_64 rng(s);
  for (int i = 0; i < n && !::testing::Test::HasFatalFailure(); ++i)
    check(scene_json(make(rng, i)), prefix + "_" + std::to_string(s) + "_" + std::to_string(i));
}

// Writes the scene to failures/<tag>.json under the build tree's working directory and returns the
// path, so a failing random case can be replayed with `wrenchkit closure PATH`.
std::string dump_failure(const std::string& scene_text, const std::string& tag);

// Brute force (theory.md §3 algorithm 2): rank, and force closure ⇔ rank 3 and no candidate ray
// ±(g_i × g_j) has power ≥ 0 against every generator. O(k³), exact.
int brute_force_rank(const std::vector<Vec3q>& g);
bool brute_force_closure(const std::vector<Vec3q>& g);
// x ∈ pos(g) by Carathéodory: x is a non-negative combination of ≤ 3 generators. O(k³), exact.
bool brute_force_in_cone(const std::vector<Vec3q>& g, const std::array<Rational, 3>& x);

// Runs a command line `env exe args` with stdin_text on standard input, in a per-process scratch
// folder under the system temp dir named after `tag`; returns the exit code and both outputs.
struct Cli_result {
  int code;
  std::string out, err;
};
std::string scratch_dir(const std::string& tag);
Cli_result run_cli(const std::string& exe, const std::string& env, const std::string& args,
                   const std::string& stdin_text, const std::string& tag);

// The independent checker on a scene text and a certificate text.
::testing::AssertionResult checker_accepts(const std::string& scene_text, const std::string& cert);
// The certificate with its first `from` replaced by `to` is rejected by the checker with a message containing `reason`.
::testing::AssertionResult checker_refuses_edit(const std::string& scene_text, std::string cert, const std::string& from,
                                                const std::string& to, const std::string& reason);

}  // namespace wrenchkit::test
