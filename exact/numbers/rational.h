// Exact rationals (GMP's mpq_class, the exact number type CGAL's Epeck uses with CGAL_USE_GMPXX)
// and their exact reading from decimal or fraction text (docs/scene-format.md, "Numbers").
#pragma once

#include <gmpxx.h>

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "exact/numbers/limits.h"
#include "exact/numbers/wide_int.h"
#include "float/bounded.h"

namespace wrenchkit {

using Rational = mpq_class;
using Integer = mpz_class;

// GMP aborts the process when an allocation fails (its default allocation functions). This installs
// allocation functions that throw std::bad_alloc instead, so that what the scene budget did not prevent
// becomes an error (the pipeline's internal_error "out of memory", exit 70; in batch one error line, the
// other answers kept), never an abort. Process-wide (mp_set_memory_functions); the command line and the
// Python module call it once at start, a C++ program may too. Idempotent. The unwinding passes through
// GMP's C frames (built with unwind tables); a number being resized keeps its old storage, temporary
// blocks of the failed operation are lost (a bounded leak, on an error path).
void use_throwing_gmp_allocation();

// Reads `text` exactly. `json_number` selects JSON's number grammar (text of a JSON number token);
// otherwise the string grammar (decimal with optional exponent, or p/q). On failure returns
// nullopt and sets `why` to a short reason ("is not a number", "has more than 10000 digits", …).
// With `approx`, also sets it to a double with a certified bound on its distance to the exact value
// [FL-4], computed from the digits when they are short (no rational arithmetic), else from the
// rational.
std::optional<Rational> parse_rational(std::string_view text, bool json_number,
                                       const Input_limits& limits, std::string& why,
                                       fl::Bounded* approx = nullptr);

// parse_rational into an existing Rational (the streaming scene reader reuses its storage); the
// same grammar, limits, value, certified double and reasons. `out` is unspecified on failure.
// With `tally` [BUDGET], the number's digits join the scene's tally (limits.h), and a number that would take
// the scene over its budget fails ("is over the scene's budget") before it is converted.
bool parse_rational_into(std::string_view text, bool json_number, const Input_limits& limits, std::string& why,
                         Rational& out, fl::Bounded* approx = nullptr, Budget_tally* tally = nullptr);

// Validates `text` exactly as parse_rational does and returns its certified double and its exact
// sign (−1, 0, 1), building no rational when the digits are short enough to avoid it (≤ 18
// significant digits, |scale| ≤ 15). For the lazy scene reading of the float path.
bool scan_number(std::string_view text, bool json_number, const Input_limits& limits, std::string& why,
                 fl::Bounded& approx, int& sign, Budget_tally* tally = nullptr);

// [BUDGET] Whether `text` is a valid number within the limits (as parse_rational decides, building
// nothing), and then its digits as the digit limit counts them: the larger of the digits of its text
// (integer, fraction, exponent; numerator and denominator) and, for a decimal with a nonzero value, of its
// value written out (an integer, or m/10^k before reduction). O(|text|).
bool number_digits(std::string_view text, bool json_number, const Input_limits& limits, std::size_t& digits);

// |q − v| ≤ e: v is q rounded toward zero; e = 0 if exact, 2^-51·|v| otherwise (one ulp of a
// normal double is at most 2^-52·|v|), +∞ if q is outside the normal range of doubles. [FL-4]
fl::Bounded to_bounded(const Rational& q);

// q correctly rounded to the nearest double (ties to even, IEEE 754 binary64, subnormals included):
// exact integer division with a sticky remainder, no floating-point step before the last (exact)
// scaling. mpq_get_d truncates toward zero and is not this. nullopt when q rounds beyond the largest
// finite double (|q| ≥ 2^1024 − 2^970); a tiny q rounds to ±0.
std::optional<double> nearest_double(const Rational& q);

// Lowest terms, "p" or "p/q" (q > 0): the JSON output form of docs/cli.md.
std::string to_string(const Rational& q);

// The simplest rational in [l, h] (l ≤ h): least denominator, then least absolute numerator (0 when the interval holds
// it; the Stern–Brocot descent by continued fractions) — a readable number where any of the interval will do.
Rational simplest_in(const Rational& l, const Rational& h);

// A fixed-width integer (exact/numbers/wide_int.h) as a GMP integer, exactly.
Integer integer_of(wide::i128 v);

// The primitive integer vector positively parallel to v: the positive multiple of v whose entries are
// coprime integers — the one reduction of every 2-D and 3-D direction of the engine (twists, rays,
// normals, edge directions). Exact; O(1) gcds. v must be nonzero: a zero vector has no direction, every
// caller knows its v ≠ 0 or tests it first, so a zero v is a bug and throws std::logic_error.
std::array<Integer, 3> primitive(std::array<Integer, 3> v);
std::array<Integer, 3> primitive(const std::array<Rational, 3>& v);
std::array<Integer, 2> primitive(const Rational& x, const Rational& y);

}  // namespace wrenchkit
