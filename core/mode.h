// How signs are decided (docs/cli.md "Modes"), for every question the engine answers: the mode, its one
// parser, and the one rule that reports which arithmetic decided an answer.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace wrenchkit {

// `exact` — exact integer/rational arithmetic only; `hybrid` — the float twin's certified predicates
// [FL-2], and exact arithmetic for each predicate they leave uncertain (per predicate, as CGAL's
// Filtered_predicate); `float_only` — the twin alone, which may leave the question undecided.
enum class Mode { exact, hybrid, float_only };

inline const char* mode_name(Mode m) {
  switch (m) {
    case Mode::exact: return "exact";
    case Mode::hybrid: return "hybrid";
    case Mode::float_only: return "float";
  }
  return "?";
}

// The mode called `name` ("exact", "hybrid", "float"), or nothing: every front end parses modes here, once.
inline std::optional<Mode> parse_mode(std::string_view name) {
  if (name == "exact") return Mode::exact;
  if (name == "hybrid") return Mode::hybrid;
  if (name == "float") return Mode::float_only;
  return std::nullopt;
}
// The message of a front end that met an unknown mode (the option's name first).
inline constexpr const char* kModeChoices = "is not one of exact, hybrid, float";

// Which arithmetic decided an answer that asked `predicates` signs, `exact` of them in exact arithmetic:
// "exact" in exact mode or when every sign was exact, "float" when none was, else "hybrid".
inline const char* decided_by(Mode m, std::size_t predicates, std::size_t exact) {
  if (m == Mode::exact) return "exact";
  return exact == 0 ? "float" : (exact == predicates ? "exact" : "hybrid");
}
// Two parts of one answer: the same word when they agree, else "hybrid".
inline const char* decided_by(const char* a, const char* b) {
  return std::string_view(a) == std::string_view(b) ? a : "hybrid";
}

}  // namespace wrenchkit
