// Another implementation's answers against the reference corpus (`wrenchkit compare`; docs/reference-format.md §5):
// agreement per field and per family, and every disagreement with its scene and how close that scene is to a
// degenerate boundary (tolerance issue or real bug?).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "exact/numbers/limits.h"
#include "exact/numbers/rational.h"

namespace wrenchkit {

struct Compare_options {
  std::string format;  // the answers' format: "jsonl" or "csv"; "" by the file name (jsonl for -)
  Rational rtol{"1/1000000000"}, atol{"1/1000000000000"};  // numbers agree when |a - r| <= atol + rtol*|r|
  Rational near{"1/1000000000"};  // a disagreement within this distance of a degenerate boundary is near it
  std::optional<Rational> tolerance;  // the peer's documented tolerance: near when larger than `near`
  std::string tolerance_text;         // as given, for the report
  Input_limits limits;                // the answers' (their file's size: limits.max_file_bytes)
  bool json = false;                  // the report as one JSON line (else text for people)
};

// Reads a file (standard input for "-") within `limit` bytes, or throws Input_error: the front end's reader, so
// that its messages are the front end's.
using Read_file = std::string (*)(const std::string& path, std::size_t limit);

struct Compare_report {
  std::string text;    // the report, ending in a newline
  bool agree = false;  // every given answer agrees with the reference
};

// Compares the answers in ANSWERS (a file, "-" for standard input) with the corpus CORPUS (its directory or its
// reference.jsonl), each read with `read`, the corpus first. Throws Input_error naming the line and field for a
// malformed line, an unknown id or field.
Compare_report compare_answers(const std::string& corpus, const std::string& answers, const Compare_options& options,
                               Read_file read);

}  // namespace wrenchkit
