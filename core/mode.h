// How signs are decided (interface.md §2), for every command that decides something.
#pragma once

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

}  // namespace wrenchkit
