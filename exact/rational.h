// Exact rationals (GMP's mpq_class, the exact number type CGAL's Epeck uses with CGAL_USE_GMPXX)
// and their exact reading from decimal or fraction text (docs/scene-format.md, "Numbers").
#pragma once

#include <gmpxx.h>

#include <optional>
#include <string>
#include <string_view>

#include "exact/limits.h"

namespace wrenchkit {

using Rational = mpq_class;
using Integer = mpz_class;

// Reads `text` exactly. `json_number` selects JSON's number grammar (text of a JSON number token);
// otherwise the string grammar (decimal with optional exponent, or p/q). On failure returns
// nullopt and sets `why` to a short reason ("is not a number", "has more than 10000 digits", …).
std::optional<Rational> parse_rational(std::string_view text, bool json_number,
                                       const Input_limits& limits, std::string& why);

// Lowest terms, "p" or "p/q" (q > 0): the JSON output form of interface.md §3.
std::string to_string(const Rational& q);

}  // namespace wrenchkit
