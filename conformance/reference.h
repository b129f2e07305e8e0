// The reference corpus (`wrenchkit reference`; format: docs/reference-format.md): the built-in scenes — the golden
// textbook scenes of tests/golden (embedded at build time, their expected answers checked), the near-degenerate
// families and random scenes of the test scenery (testing/stress_families.h) — or the user's own scenes, each
// line made by conformance/corpus.h. Library wrenchkit_builtin_corpus, the one part that links the test scenery.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "conformance/corpus.h"

namespace wrenchkit {

struct Reference_options {
  std::uint64_t seed = 20261122;
  int cases = 2;     // scenes per near-degenerate family and ε
  int random = 100;  // scenes per random family
  int sides = 16;    // limit-surface polygon sides
  std::string scenes;  // --scenes FILE.jsonl|DIR: the user's own scenes instead of the families
};

// Builds the corpus in memory (deterministic): the built-in scenes, or with `scenes` the user's own
// (user_corpus). Throws Input_error for a bad user scene file; a scene whose line was not answered ends the
// corpus with its status (check_failed if a certificate was rejected or an answer contradicts a golden file).
Reference_corpus build_reference(const Reference_options& options);

// The corpus' manifest.json for `scenes` scenes built with `options`.
std::string reference_manifest(const Reference_options& options, std::size_t scenes);

}  // namespace wrenchkit
