// The reference corpus (`wrenchkit reference`) and its comparison with another implementation's
// answers (`wrenchkit compare`); format: docs/reference-format.md.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "exact/pipeline/reference.h"

namespace wrenchkit::cli {

struct Reference_options {
  std::uint64_t seed = 20261122;
  int cases = 2;     // scenes per near-degenerate family and ε
  int random = 100;  // scenes per random family
  int sides = 16;    // limit-surface polygon sides
  std::string scenes;  // --scenes FILE.jsonl|DIR: the user's own scenes instead of the families
};

struct Reference_corpus {
  std::vector<std::string> ids;
  std::vector<Reference_item> items;  // per scene: its line, canonical text, CSV row (exact/pipeline/reference.h)
  std::size_t certificates = 0;       // all accepted by the independent checker
};

// Builds the corpus in memory (deterministic): the built-in families, or with `scenes` the user's own
// scenes (read_user_scenes). Throws Input_error for a bad user scene, Failure(check_failed) if a
// certificate is rejected, Self_check_failure if an answer contradicts a golden file.
Reference_corpus build_reference(const Reference_options& options);

}  // namespace wrenchkit::cli
