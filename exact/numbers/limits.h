// Input limits: no scene can make wrenchkit allocate without bound or run without end.
// Defaults are those of docs/scene-format.md, "Limits"; every one can be raised on the command line.
#pragma once

#include <cstddef>
#include <limits>

namespace wrenchkit {

struct Input_limits {
  std::size_t max_digits = 10000;                // digits in one number
  long max_exponent = 10000;                     // |decimal exponent|
  std::size_t max_file_bytes = 64u << 20;        // 64 MiB
  std::size_t max_depth = 64;                    // JSON nesting
  std::size_t max_contacts = 100000;             // contacts[] entries; also support.points and body.outline
  std::size_t max_region_vertices = 4096;        // vertices of all support regions' rings together
  // [BUDGET] The scene-wide budget on exact arithmetic (docs/scene-format.md "Limits"; Budget_tally below):
  std::size_t max_total_digits = 20000000;       // the digits of all the scene's numbers together
  std::size_t max_digits_times_contacts = 10000000;  // longest number's digits × (contacts + support points)
  // [WORK] What one question may cost, in the engine's work units (exact/numbers/work_budget.h): past it, undecided.
  std::size_t max_work = 10000000;
  // The longest certificate a question may write (and the checker reads): past it, undecided (and rejected by check).
  std::size_t max_certificate_bytes = 8u << 20;
  // Not a limit but the reading's one policy: a contact off body.outline or with an outward normal, or an outline
  // that is not a simple polygon, is kept as a warning instead of refused (--lenient; exact/io/outline.h).
  bool lenient = false;
};

// [BUDGET] The tally of a scene's budget measures, kept while its numbers are read, in any order:
//   total   = Σ digits(x) over every number x of the scene (the version, body, contacts, load, support; a
//             point contact's absent mu counts as its default "0", so that the canonical text, which writes
//             it, never measures more), digits(x) counted as the digit limit counts them (scene-format.md
//             "Numbers": the larger of the digits of its text and of its value written out exactly);
//   longest = max digits(x);   entries = contacts + support points.
// Why they bound the work (docs/design.md "Input, limits and batch"): an exact number of d digits takes about
// 0.42·d bytes, so `total` bounds the memory of the scene's rationals and the time to read them (every
// later quantity of the engine and of the checker is built from them); a generator's integers have
// O(longest) digits, each certified predicate combines a bounded number of generators, and the number of
// predicates grows with `entries`, so longest × entries bounds the size of the generator matrix and, with
// it, the work per pass over the generators. Both measures only grow as numbers and entries are added, so
// a reader may refuse at the first number that goes over, and a prefix over budget means the scene is.
struct Budget_tally {
  std::size_t total = 0, longest = 0, entries = 0;

  static std::size_t product(std::size_t a, std::size_t b) {  // saturating a·b
    return a != 0 && b > std::numeric_limits<std::size_t>::max() / a ? std::numeric_limits<std::size_t>::max()
                                                                     : a * b;
  }
  std::size_t digits_times_contacts() const { return product(longest, entries); }
  bool within(const Input_limits& l) const {
    return total <= l.max_total_digits && digits_times_contacts() <= l.max_digits_times_contacts;
  }
  // One more number of `digits`; false (the tally unchanged) when it would take the scene over budget.
  bool add_number(std::size_t digits, const Input_limits& l) {
    const std::size_t t = total + digits, m = longest > digits ? longest : digits;
    if (t < total || t > l.max_total_digits || product(m, entries) > l.max_digits_times_contacts) return false;
    total = t;
    longest = m;
    return true;
  }
  // One more contact or support point; false (unchanged) when it would take the scene over budget.
  bool add_entry(const Input_limits& l) {
    if (product(longest, entries + 1) > l.max_digits_times_contacts) return false;
    ++entries;
    return true;
  }
};

}  // namespace wrenchkit
