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

// Which arithmetic decided an answer's signs (its "decided_by"): the twin's certified floats alone, both, or exact
// arithmetic alone. The order is Python's wrenchkit.DECIDED_BY (0, 1, 2).
enum class Arithmetic { floats, hybrid, exact };
inline const char* arithmetic_name(Arithmetic a) {
  switch (a) {
    case Arithmetic::floats: return "float";
    case Arithmetic::hybrid: return "hybrid";
    case Arithmetic::exact: return "exact";
  }
  return "?";
}
// An answer that asked `predicates` signs, `exact` of them in exact arithmetic: exact in exact mode or when every
// sign was exact, floats when none was, else hybrid.
inline Arithmetic decided_by(Mode m, std::size_t predicates, std::size_t exact) {
  if (m == Mode::exact) return Arithmetic::exact;
  return exact == 0 ? Arithmetic::floats : (exact == predicates ? Arithmetic::exact : Arithmetic::hybrid);
}
// Two parts of one answer: the same when they agree, else hybrid.
inline Arithmetic decided_by(Arithmetic a, Arithmetic b) { return a == b ? a : Arithmetic::hybrid; }

}  // namespace wrenchkit
