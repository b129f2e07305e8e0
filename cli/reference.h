// The reference corpus (`wrenchkit reference`) and its comparison with another implementation's
// answers (`wrenchkit compare`); format: docs/reference-format.md.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace wrenchkit::cli {

struct Reference_options {
  std::uint64_t seed = 20261122;
  int cases = 2;     // scenes per near-degenerate family and ε
  int random = 100;  // scenes per random family
  int sides = 16;    // limit-surface polygon sides
};

struct Reference_corpus {
  std::vector<std::string> ids, lines, scenes, csv;  // per scene: id, JSON line, canonical text, CSV row
  std::size_t certificates = 0;                      // all accepted by the independent checker
};

// Builds the corpus in memory (deterministic). Throws Self_check_failure if a certificate is
// rejected or an answer contradicts a golden file.
Reference_corpus build_reference(const Reference_options& options);

}  // namespace wrenchkit::cli
