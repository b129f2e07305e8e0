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

// Seed for randomized tests: WRENCHKIT_SEED from the environment, else `fallback`.
std::uint64_t seed(std::uint64_t fallback);

// Random scene on a small integer grid, so that degenerate configurations (parallel, concurrent,
// coincident, on a cone edge) are frequent. 0 … max_contacts contacts; a few wrench generators.
std::vector<Contact_spec> random_contacts(std::mt19937_64& rng, int max_contacts);

// Random contacts as users write them: decimal coordinates with 3 digits (0.137 is not a double),
// integer normals, μ in 0.01 … 0.80: generic, nothing exactly degenerate by construction.
std::vector<Contact_spec> decimal_contacts(std::mt19937_64& rng, int contacts);

// Writes the scene to failures/<tag>.json under the build tree's working directory and returns the
// path, so a failing random case can be replayed with `wrenchkit closure PATH`.
std::string dump_failure(const std::string& scene_text, const std::string& tag);

// Brute force (theory.md §3 algorithm 2): rank, and force closure ⇔ rank 3 and no candidate ray
// ±(g_i × g_j) has power ≥ 0 against every generator. O(k³), exact.
int brute_force_rank(const std::vector<Wrench>& g);
bool brute_force_closure(const std::vector<Wrench>& g);
// x ∈ pos(g) by Carathéodory: x is a non-negative combination of ≤ 3 generators. O(k³), exact.
bool brute_force_in_cone(const std::vector<Wrench>& g, const std::array<Rational, 3>& x);

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

}  // namespace wrenchkit::test
