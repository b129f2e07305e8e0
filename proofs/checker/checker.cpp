// proofs/checker/checker.cpp - certificate format v1: reading the scene, recomputing its generators
// and its load, and the conditions of proofs/certificate-format.md §3.1 (holds = true), §3.2
// (holds = false), §3.3 (equilibrium) and §6 (motion: sliding on the support, [SL-1]).
#include "proofs/checker/checker.h"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <climits>
#include <type_traits>
#include <deque>
#include <exception>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "proofs/checker/json.h"

namespace wrenchkit_checker {
namespace {

using detail::Failure;
using detail::quote;
using detail::Reader;
using Kind = Reader::Kind;
using Q = mpq_class;

struct Wrench {  // (fx, fy, m), m about the origin (theory.md §1.2)
  Q fx, fy, m;
};

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Text for a message, cut if long.
std::string clip(const std::string& s) {
  return s.size() <= 64 ? s : s.substr(0, 40) + "... (" + std::to_string(s.size()) + " characters)";
}
// A rational for a message; a huge one is not converted to decimal (that alone can take seconds).
std::string show(const Q& q) {
  const std::size_t digits = mpz_sizeinbase(q.get_num_mpz_t(), 10) + mpz_sizeinbase(q.get_den_mpz_t(), 10);
  return digits <= 10000
             ? clip(q.get_str())
             : std::string(sgn(q) < 0 ? "-" : "") + "(a rational of about " + std::to_string(digits) + " digits)";
}
std::string show(const Q& a, const Q& b) { return "(" + show(a) + ", " + show(b) + ")"; }

// ---------------------------------------------------------------------------------------------
// Numbers

// A scene number's text (docs/scene-format.md "Numbers"), the text of a JSON number or of a number string:
//   decimal := sign? (digits ("." digits?)? | "." digits) exponent?    exponent := [eE] sign? digits
//   fraction := sign? digits "/" digits (denominator not zero)
// The scene-wide budget while a scene is read (Limits::max_total_digits, max_digits_times_contacts):
// read_whole_scene sets `reading` for the duration of the reading, so that the numbers read again later
// (generators, support values) are not counted twice.
struct Tally {
  std::size_t total = 0, longest = 0, entries = 0;
  static std::size_t times(std::size_t a, std::size_t b) {  // saturating a * b
    return a != 0 && b > static_cast<std::size_t>(-1) / a ? static_cast<std::size_t>(-1) : a * b;
  }
  // One more number of d digits, refused (a Failure, message after the path) when it takes the scene over.
  void number(std::size_t d, const Limits& lim) {
    const std::size_t t = total + d < total ? static_cast<std::size_t>(-1) : total + d;
    if (t > lim.max_total_digits)
      throw Failure{": the scene's numbers have " + std::to_string(t) + " digits in all up to here (limit " +
                    std::to_string(lim.max_total_digits) + ", the budget on all digits, --max-total-digits)"};
    const std::size_t m = std::max(longest, d);
    if (times(m, entries) > lim.max_digits_times_contacts) throw Failure{over(m, entries, lim)};
    total = t, longest = m;
  }
  // One more contact or support point: list[index].
  void entry(const char* list, std::size_t index, const Limits& lim) {
    if (times(longest, entries + 1) > lim.max_digits_times_contacts)
      throw Failure{list + ("[" + std::to_string(index) + "]") + over(longest, entries + 1, lim)};
    ++entries;
  }
  static std::string over(std::size_t longest, std::size_t entries, const Limits& lim) {
    return ": the longest number up to here has " + std::to_string(longest) + " digits, times " +
           std::to_string(entries) + " contacts and support points makes " + std::to_string(times(longest, entries)) +
           " (limit " + std::to_string(lim.max_digits_times_contacts) +
           ", the budget on digits times contacts, --max-digits-times-contacts)";
  }
  static thread_local Tally* reading;
};
thread_local Tally* Tally::reading = nullptr;

// JSON's number grammar is a subset of `decimal`. number_text() checks the grammar and the digit and
// exponent limits on the text, before any big number is built (no overflow, no huge power of ten), and
// returns its parts (views of the text); exact_value() is its value.
struct Number_text {
  bool negative = false, fraction = false;
  std::string_view whole, frac, den;  // fraction: whole / den; decimal: the digits before and after '.'
  long long scale = 0;                // decimal: value = mantissa * 10^scale, mantissa = the digits whole frac
  std::size_t counted = 0;            // its digits as the scene's budget counts them: text or value written out
};

Number_text number_text(std::string_view s, const Limits& lim, const std::string& path) {
  struct At {  // path + ": ", built only for a message
    const std::string& path;
    std::string operator+(const std::string& what) const { return path + ": " + what; }
  } const at{path};
  auto not_a_number = [&] { return Failure{at + (quote(s) + " is not a number")}; };
  std::size_t i = 0, digits = 0;
  auto run = [&] {  // a maximal run of digits
    const std::size_t begin = i;
    while (i < s.size() && is_digit(s[i])) ++i;
    digits += i - begin;
    return s.substr(begin, i - begin);
  };
  auto next = [&](char a, char b) {  // consumes a or b, if next
    return i < s.size() && (s[i] == a || s[i] == b) ? (++i, true) : false;
  };
  Number_text n;
  n.negative = !s.empty() && s[0] == '-';
  next('+', '-');
  n.whole = run();
  std::string_view exp;
  bool exp_negative = false;
  n.fraction = !n.whole.empty() && next('/', '/');
  if (n.fraction) {
    n.den = run();
    if (n.den.empty()) throw not_a_number();
  } else {
    if (next('.', '.')) n.frac = run();
    if (n.whole.empty() && n.frac.empty()) throw not_a_number();
    if (next('e', 'E')) {
      exp_negative = i < s.size() && s[i] == '-';
      next('+', '-');
      exp = run();
      if (exp.empty()) throw not_a_number();
    }
  }
  if (i != s.size()) throw not_a_number();
  if (digits > lim.max_digits)
    throw Failure{at + "number with " + std::to_string(digits) + " digits (limit " + std::to_string(lim.max_digits) +
                  ")"};
  n.counted = digits;
  if (n.fraction) {
    if (n.den.find_first_not_of('0') == std::string_view::npos) throw Failure{at + quote(s) + " has a zero denominator"};
    return n;
  }
  exp.remove_prefix(std::min(exp.find_first_not_of('0'), exp.size()));
  unsigned long long e = exp.size() > 18 ? ULLONG_MAX : 0;  // |exponent|; 18 digits cannot overflow
  for (std::size_t k = 0; k < exp.size() && e != ULLONG_MAX; ++k) e = e * 10 + static_cast<unsigned>(exp[k] - '0');
  if (lim.max_exponent < 0 || e > static_cast<unsigned long long>(lim.max_exponent))
    throw Failure{at + "exponent " + (exp_negative ? "-" : "") + clip(exp.empty() ? "0" : std::string(exp)) +
                  " out of range (limit " + std::to_string(lim.max_exponent) + ")"};
  // value = mantissa * 10^scale, |scale| <= max_exponent + max_digits
  n.scale = (exp_negative ? -static_cast<long long>(e) : static_cast<long long>(e)) - static_cast<long long>(n.frac.size());
  // The value written out counts too (scene-format.md): mantissa·10^scale as an integer, or
  // mantissa/10^k before reduction, has significant + |scale| (+1 for the denominator's 1) digits.
  std::size_t lead = 0;  // leading zeros of the mantissa's digits (whole, then frac)
  while (lead < n.whole.size() + n.frac.size() &&
         (lead < n.whole.size() ? n.whole[lead] : n.frac[lead - n.whole.size()]) == '0')
    ++lead;
  const std::size_t significant = n.whole.size() + n.frac.size() - lead;
  if (significant > 0) {
    const std::size_t value_digits =
        significant + static_cast<std::size_t>(n.scale < 0 ? -n.scale : n.scale) + (n.scale < 0 ? 1 : 0);
    if (value_digits > lim.max_digits)
      throw Failure{at + "number with " + std::to_string(value_digits) + " digits written out (limit " +
                    std::to_string(lim.max_digits) + ")"};
    n.counted = std::max(n.counted, value_digits);  // the budget counts the larger: text or value written out
  }
  return n;
}

// Whether the number is zero: its numerator's digits (a decimal's mantissa) are all zeros.
bool is_zero(const Number_text& n) {
  return n.whole.find_first_not_of('0') == std::string_view::npos &&
         n.frac.find_first_not_of('0') == std::string_view::npos;
}

// The exact value of a checked number text.
Q exact_value(const Number_text& n) {
  const std::string_view whole = n.whole, frac = n.frac;
  const bool negative = n.negative;
  const long long scale = n.scale;
  Q q;
  if (n.fraction) {
    q = Q(mpz_class(std::string(whole), 10), mpz_class(std::string(n.den), 10));  // base 10: "010" is ten
  } else {
    if (whole.size() + frac.size() <= 19 && scale >= -19 && scale <= 19) {
      // Short decimals (what scenes mostly hold): mantissa and power of ten in 64 bits (10^19 < 2^64),
      // lowest terms by a 64-bit gcd; the same value as below.
      static_assert(sizeof(unsigned long) >= 8, "64-bit unsigned long (LP64)");
      unsigned long m = 0, p10 = 1;
      for (const char d : whole) m = m * 10 + static_cast<unsigned>(d - '0');
      for (const char d : frac) m = m * 10 + static_cast<unsigned>(d - '0');
      if (m == 0) return Q(0);
      for (long long k = 0; k < (scale < 0 ? -scale : scale); ++k) p10 *= 10;
      Q r;
      if (scale >= 0) {
        mpz_set_ui(mpq_numref(r.get_mpq_t()), m);
        mpz_mul_ui(mpq_numref(r.get_mpq_t()), mpq_numref(r.get_mpq_t()), p10);
      } else {
        unsigned long a = m, b = p10;
        while (b != 0) a %= b, std::swap(a, b);  // a = gcd(m, p10)
        mpz_set_ui(mpq_numref(r.get_mpq_t()), m / a);
        mpz_set_ui(mpq_denref(r.get_mpq_t()), p10 / a);
      }
      return negative ? Q(-r) : r;
    }
    const mpz_class mantissa(std::string(whole) + std::string(frac), 10);
    if (mantissa == 0) return Q(0);
    mpz_class ten;
    mpz_ui_pow_ui(ten.get_mpz_t(), 10, static_cast<unsigned long>(scale < 0 ? -scale : scale));
    q = scale < 0 ? Q(mantissa, ten) : Q(mpz_class(mantissa * ten));
  }
  q.canonicalize();
  return negative ? Q(-q) : q;
}

// The longest rational a certificate about the scene being checked may hold (certificate-format.md §2):
// max(100000, 32 L + 64) characters for L the digits of the scene's longest number (a weight is a ratio of
// 3x3 minors of generator integers of at most 5 L + 1 digits each). Set by check_certificate.
thread_local std::size_t certificate_rational_limit = 100000;

// The exact value of a scene number's text (see number_text()). With `tally`, the number is counted against
// the scene's budget, before it is built; with `build` false nothing is built (the result is 0): the number
// is only validated and counted.
Q scene_number(std::string_view s, const Limits& lim, const std::string& path, Tally* tally = nullptr,
               bool build = true) {
  const Number_text n = number_text(s, lim, path);
  if (tally) tally->number(n.counted, lim);
  return build ? exact_value(n) : Q(0);
}

// A number num/den with den > 0 in 64 bits, not necessarily in lowest terms: a short decimal m·10^-k is
// m/10^k as written ("0.500000" is 500000/10^6). Positive scalings of a generator change none of the
// conditions checked, and the decimals of one scene usually have one number of digits each, so the
// generators of its contacts then share one denominator.
struct Small {
  long long num = 0, den = 1;
};

// The value of a checked number text as a Small, or false if it does not fit (then exact_value()).
bool small_value(const Number_text& n, Small& out) {
  // the value of a run of at most 18 digits (< 10^18 < 2^63), or false
  auto digits = [](std::string_view d, unsigned long long& v) {
    d.remove_prefix(std::min(d.find_first_not_of('0'), d.size()));
    if (d.size() > 18) return false;
    v = 0;
    for (const char c : d) v = v * 10 + static_cast<unsigned>(c - '0');
    return true;
  };
  unsigned long long num = 0, den = 1;
  if (n.fraction) {
    if (!digits(n.whole, num) || !digits(n.den, den)) return false;
  } else {
    std::size_t count = 0;  // the mantissa's digits, whole then frac, leading zeros skipped
    for (const std::string_view part : {n.whole, n.frac})
      for (const char c : part) {
        if (num == 0 && c == '0') continue;
        if (++count > 18) return false;
        num = num * 10 + static_cast<unsigned>(c - '0');
      }
    if (num != 0) {
      const long long k = n.scale < 0 ? -n.scale : n.scale;
      if (k > 18) return false;
      unsigned long long p = 1;
      for (long long j = 0; j < k; ++j) p *= 10;
      if (n.scale < 0) den = p;
      else if (__builtin_mul_overflow(num, p, &num) || num > static_cast<unsigned long long>(LLONG_MAX)) return false;
    }
  }
  out.num = n.negative ? -static_cast<long long>(num) : static_cast<long long>(num);
  out.den = static_cast<long long>(den);
  return true;
}

// q = a Small's value, in lowest terms (a 64-bit gcd; no text, no temporary).
void set_small(Q& q, const Small& s) {
  unsigned long long a = s.num < 0 ? 0ULL - static_cast<unsigned long long>(s.num) : static_cast<unsigned long long>(s.num);
  unsigned long long b = static_cast<unsigned long long>(s.den), g = a, h = b;
  while (h != 0) g %= h, std::swap(g, h);  // g = gcd(|num|, den) (den when num is 0)
  mpz_set_ui(mpq_numref(q.get_mpq_t()), static_cast<unsigned long>(a / g));
  mpz_set_ui(mpq_denref(q.get_mpq_t()), static_cast<unsigned long>(b / g));
  if (s.num < 0) mpq_neg(q.get_mpq_t(), q.get_mpq_t());
}
Q small_q(const Small& s) {
  Q q;
  set_small(q, s);
  return q;
}

// A certificate rational (certificate-format.md §2): a JSON string matching
// -?(0|[1-9][0-9]*)(/[1-9][0-9]*)? of at most certificate_rational_limit characters. The grammar is checked
// here, in full, before GMP sees the text (mpq_set_str alone would accept "1/0" and more).
bool rational_grammar(std::string_view s) {
  if (s.size() > certificate_rational_limit) return false;
  std::size_t i = !s.empty() && s[0] == '-' ? 1 : 0;
  auto integer = [&](bool zero_allowed) {  // 0 | [1-9][0-9]*
    if (i < s.size() && s[i] == '0' && zero_allowed) return ++i, true;
    if (i >= s.size() || s[i] < '1' || s[i] > '9') return false;
    while (i < s.size() && is_digit(s[i])) ++i;
    return true;
  };
  bool ok = integer(true);
  if (ok && i < s.size() && s[i] == '/') ++i, ok = integer(false);
  return ok && i == s.size();
}
// The failure of a text that is not a certificate rational, naming `path`.
[[noreturn]] void not_a_rational(std::string_view s, const std::string& path) {
  if (s.size() > certificate_rational_limit)
    throw Failure{path + ": rational of " + std::to_string(s.size()) + " characters (limit " +
                  std::to_string(certificate_rational_limit) + ")"};
  throw Failure{path + ": " + quote(s) + " is not a rational of the form -?(0|[1-9][0-9]*)(/[1-9][0-9]*)?"};
}
// The value of a text that matches the grammar. Short ones (numerator and denominator of at most 18 digits: most
// weights and forces) by a 64-bit gcd, without GMP's text conversion; the same value.
Q rational_value(std::string_view s) {
  if (s.size() <= 38) {
    const bool negative = s[0] == '-';
    const std::size_t slash = s.find('/'), begin = negative ? 1 : 0, end = slash == std::string_view::npos ? s.size() : slash;
    const std::size_t den_digits = slash == std::string_view::npos ? 0 : s.size() - slash - 1;
    if (end - begin <= 18 && den_digits <= 18) {
      unsigned long long num = 0, den = slash == std::string_view::npos ? 1 : 0;
      for (std::size_t i = begin; i < end; ++i) num = num * 10 + static_cast<unsigned>(s[i] - '0');
      for (std::size_t i = end + 1; i < s.size(); ++i) den = den * 10 + static_cast<unsigned>(s[i] - '0');
      Small v;  // |num|, den < 10^18 < 2^63; den > 0 (grammar)
      v.num = negative ? -static_cast<long long>(num) : static_cast<long long>(num);
      v.den = static_cast<long long>(den);
      return small_q(v);
    }
  }
  Q q;
  mpq_set_str(q.get_mpq_t(), std::string(s).c_str(), 10);  // cannot fail: grammar checked, denominator not zero
  q.canonicalize();
  return q;
}

// ---------------------------------------------------------------------------------------------
// Scene

// One entry of contacts[], validated. When every number fits 64 bits (Small; short decimals, what
// scenes mostly hold) only those values are kept. Otherwise the numbers are kept as text and read again
// when a generator is needed: "1e10000" is 7 bytes of input but 4 KB as a rational, so keeping the text
// keeps memory proportional to the input; when every number is small (numerator and denominator of at
// most kKeptLimbs limbs each, a constant size) their values are kept as well.
struct Contact {
  bool wrench = false;
  bool frictional = false;         // a point contact with mu > 0 (edges left and right under the friction reading)
  bool fixed = false;              // every number fits a Small: `small` holds them, text and value are empty
  std::array<Small, 5> small{};    // point contact: x, y, nx, ny, mu (0 if absent); wrench: fx, fy, m
  std::vector<std::string> text;   // (!fixed) the numbers' texts, in the same order
  std::vector<Q> value;            // (!fixed) the same numbers' values, or empty (some number is not small)
};
constexpr std::size_t kKeptLimbs = 4;
bool small(const Q& q) {
  return mpz_size(q.get_num_mpz_t()) <= kKeptLimbs && mpz_size(q.get_den_mpz_t()) <= kKeptLimbs;
}

std::string read_string(Reader& r) {
  if (r.peek() != Kind::string) r.fail("expected a string");
  return r.string();
}

// A scene number: a JSON number or a number string.
Q read_number(Reader& r, const Limits& lim, std::string* text = nullptr) {
  const Kind k = r.peek();
  if (k != Kind::number && k != Kind::string) r.fail("expected a number (a JSON number or a number string)");
  std::string s = k == Kind::number ? std::string(r.number()) : r.string();
  Q q;
  try {  // the path only for the message (building it for every number costs more than the number)
    q = scene_number(s, lim, "", Tally::reading);
  } catch (const Failure& f) {
    throw Failure{r.path() + f.message};
  }
  if (text) *text = std::move(s);
  return q;
}

// A contact's number as read: its text (a view, valid while the reader is), its sign, and its value
// when it fits a Small.
struct Read_number {
  std::string_view text = "0";
  bool zero = true, negative = false, fits = true;
  Small value;
};
// A JSON number (its grammar checked by the reader) without an exponent and of at most 18 digits, the usual
// contact number: what number_text(), is_zero() and small_value() make of it, in one pass; false for any
// other text and whenever a limit could be in question (then those functions decide, and name it).
bool short_json_decimal(std::string_view s, const Limits& lim, Read_number& n, std::size_t& counted) {
  std::size_t i = s[0] == '-' ? 1 : 0, whole = 0, frac = 0;
  unsigned long long m = 0;
  for (; i < s.size() && is_digit(s[i]); ++i, ++whole) m = m * 10 + static_cast<unsigned>(s[i] - '0');
  if (i < s.size() && s[i] == '.')
    for (++i; i < s.size() && is_digit(s[i]); ++i, ++frac) m = m * 10 + static_cast<unsigned>(s[i] - '0');
  if (i != s.size() || whole + frac > 18 || lim.max_exponent < 0) return false;  // an exponent, or long
  // As number_text(): the digits, or the value written out when larger (significant + |scale| + 1).
  std::size_t significant = 0;
  for (unsigned long long v = m; v != 0; v /= 10) ++significant;
  counted = whole + frac;
  if (significant > 0) counted = std::max(counted, significant + frac + (frac > 0 ? 1 : 0));
  if (counted > lim.max_digits) return false;
  n.zero = m == 0;
  n.negative = s[0] == '-' && !n.zero;
  n.fits = true;  // as small_value(): m < 10^18 over 10^frac (1 when m is zero)
  n.value.num = s[0] == '-' ? -static_cast<long long>(m) : static_cast<long long>(m);
  unsigned long long p = 1;
  if (m != 0)
    for (std::size_t j = 0; j < frac; ++j) p *= 10;
  n.value.den = static_cast<long long>(p);
  return true;
}

Read_number read_contact_number(Reader& r, const Limits& lim) {
  const Kind k = r.peek();
  if (k != Kind::number && k != Kind::string) r.fail("expected a number (a JSON number or a number string)");
  Read_number n;
  n.text = k == Kind::number ? r.number() : r.string_view();
  std::size_t counted = 0;
  if (k == Kind::number && short_json_decimal(n.text, lim, n, counted)) {
    try {
      if (Tally::reading) Tally::reading->number(counted, lim);
    } catch (const Failure& f) {
      throw Failure{r.path() + f.message};
    }
    return n;
  }
  Number_text t;
  try {  // the path only for the message, as read_number(); counted in the budget as there
    t = number_text(n.text, lim, "");
    if (Tally::reading) Tally::reading->number(t.counted, lim);
  } catch (const Failure& f) {
    throw Failure{r.path() + f.message};
  }
  n.zero = is_zero(t);
  n.negative = t.negative && !n.zero;
  n.fits = small_value(t, n.value);
  return n;
}

// An array of exactly n values; item(k) reads the k-th.
template <class Item>
void read_fixed(Reader& r, std::size_t n, const std::string& what, Item item) {
  if (r.peek() != Kind::array) r.fail("expected " + what);
  r.begin_array();
  std::size_t k = 0;
  while (r.next_item()) {
    if (k == n) r.fail("expected " + what, true);
    item(k++);
  }
  if (k != n) r.fail("expected " + what);
}

// "an array of n numbers" (built once for the usual sizes: every contact asks).
const std::string& numbers_text(std::size_t n) {
  static const std::string two = "an array of 2 numbers", three = "an array of 3 numbers";
  thread_local std::string other;
  if (n == 2) return two;
  if (n == 3) return three;
  other = "an array of " + std::to_string(n) + " numbers";
  return other;
}

// n numbers into out[0..n); true if all are zero.
bool read_numbers(Reader& r, const Limits& lim, std::size_t n, Read_number* out) {
  bool zero = true;
  read_fixed(r, n, numbers_text(n), [&](std::size_t k) {
    out[k] = read_contact_number(r, lim);
    zero = out[k].zero && zero;
  });
  return zero;
}

// The values to keep with a contact: all of them if all are small, else none.
std::vector<Q> kept(std::vector<Q> values) {
  for (const Q& q : values)
    if (!small(q)) return {};
  return values;
}

// A contact of these numbers (validated): their Smalls if all fit, else their texts (and values).
Contact make_contact(bool wrench, const Read_number* n, std::size_t count, const Limits& lim) {
  Contact c;
  c.wrench = wrench;
  c.frictional = !wrench && !n[4].zero;
  c.fixed = true;
  for (std::size_t k = 0; k < count; ++k) c.fixed = c.fixed && n[k].fits;
  if (c.fixed) {
    for (std::size_t k = 0; k < count; ++k) c.small[k] = n[k].value;
    return c;
  }
  std::vector<Q> values;
  for (std::size_t k = 0; k < count; ++k) {
    c.text.emplace_back(n[k].text);
    values.push_back(scene_number(n[k].text, lim, "contacts"));  // valid: read before
  }
  c.value = kept(std::move(values));
  return c;
}

// {at, normal, mu?, name?} (normal != 0, mu >= 0) or {wrench, name?} (wrench != 0).
Contact read_contact(Reader& r, const Limits& lim) {
  if (r.peek() != Kind::object)
    r.fail("expected an object {\"at\", \"normal\", \"mu\"?, \"name\"?} or {\"wrench\", \"name\"?}");
  r.begin_object();
  Read_number point[5], wrench[3];  // x, y, nx, ny, mu ("0" if absent); fx, fy, m
  std::string_view key;
  enum : unsigned { kAt = 1, kNormal = 2, kMu = 4, kWrench = 8 };
  unsigned keys = 0;  // the keys present (a bit set: cheaper than a set of strings, read per contact)
  while (r.next_key(key)) {
    if (key == "at") {
      keys |= kAt;
      read_numbers(r, lim, 2, point);
    } else if (key == "normal") {
      keys |= kNormal;
      if (read_numbers(r, lim, 2, point + 2)) r.fail("zero vector");
    } else if (key == "mu") {
      keys |= kMu;
      point[4] = read_contact_number(r, lim);
      if (point[4].negative) r.fail(quote(point[4].text) + " is negative");
    } else if (key == "wrench") {
      keys |= kWrench;
      if (read_numbers(r, lim, 3, wrench)) r.fail("zero wrench");
    } else if (key == "name") {
      read_string(r);
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  const bool is_point = keys & (kAt | kNormal | kMu);
  if (keys & kWrench) {
    if (is_point) r.fail("a contact has either \"at\", \"normal\" and \"mu\" (a point contact) or \"wrench\", not both");
    return make_contact(true, wrench, 3, lim);
  }
  if (!(keys & (kAt | kNormal)))
    r.fail("expected \"at\" and \"normal\" (a point contact) or \"wrench\"");
  if (!(keys & kAt)) r.fail("missing required key \"at\"");
  if (!(keys & kNormal)) r.fail("missing required key \"normal\"");
  if (!(keys & kMu) && Tally::reading) {  // an absent mu counts as its "0" (docs/scene-format.md "Limits")
    try {
      Tally::reading->number(1, lim);
    } catch (const Failure& f) {
      r.fail(f.message.substr(2));
    }
  }
  return make_contact(false, point, 5, lim);
}

// n numbers, read exactly into out[0..n).
void read_vector(Reader& r, const Limits& lim, std::size_t n, Q* out) {
  read_fixed(r, n, numbers_text(n),
             [&](std::size_t k) { out[k] = read_number(r, lim); });
}

// {"outline"?: [points], "com"?: [x, y]}. Only com is used (by a gravity load); outline must be an
// array, its points are not interpreted (the checker draws nothing).
void read_body(Reader& r, const Limits& lim, bool& has_com, Q (&com)[2]) {
  if (r.peek() != Kind::object) r.fail("expected an object");
  r.begin_object();
  std::string_view key;
  while (r.next_key(key)) {
    if (key == "outline") {  // not interpreted, but limited and counted in the budget like every point
      if (r.peek() != Kind::array) r.fail("expected an array of points");
      r.begin_array();
      for (std::size_t points = 0; r.next_item(); ++points) {
        if (points == lim.max_contacts)
          throw Failure{"body.outline: more than " + std::to_string(lim.max_contacts) + " points"};
        if (r.peek() != Kind::array) {
          r.skip();
          continue;
        }
        r.begin_array();
        while (r.next_item()) {
          const Kind k = r.peek();
          if (k != Kind::number && k != Kind::string) {
            r.skip();
            continue;
          }
          const std::string_view s = k == Kind::number ? r.number() : r.string_view();
          Number_text t;
          try {  // a valid number counts (the engine refuses an invalid one; the checker ignores it)
            t = number_text(s, lim, "");
          } catch (const Failure&) {
            continue;
          }
          try {
            if (Tally::reading) Tally::reading->number(t.counted, lim);
          } catch (const Failure& f) {
            throw Failure{r.path() + f.message};
          }
        }
      }
    } else if (key == "com") {
      read_vector(r, lim, 2, com);
      has_com = true;
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
}

// The scene's load as written; its wrench w_ext is computed once the whole scene is read (gravity
// acts at body.com, and "body" may come after "load").
struct Load {
  enum class Form { none, force, wrench, gravity } form = Form::none;
  Q force[2], at[2], wrench[3], weight;
};

// Exactly one of {"force": [fx, fy], "at": [x, y]}, {"wrench": [fx, fy, m]}, {"gravity": w} with w > 0.
// Which form is meant is decided as the engine does (gravity, else wrench, else force/at); any other
// key, including one of another form, is an unknown key.
Load read_load(Reader& r, const Limits& lim) {
  const char* const forms = "{\"force\", \"at\"}, {\"wrench\"} or {\"gravity\"}";
  if (r.peek() != Kind::object) r.fail(std::string("expected an object ") + forms);
  r.begin_object();
  Load load;
  std::vector<std::string> keys;  // in the order written
  std::string_view key;
  while (r.next_key(key)) {
    keys.emplace_back(key);
    if (key == "force") {
      read_vector(r, lim, 2, load.force);
    } else if (key == "at") {
      read_vector(r, lim, 2, load.at);
    } else if (key == "wrench") {
      read_vector(r, lim, 3, load.wrench);
    } else if (key == "gravity") {
      std::string text;
      load.weight = read_number(r, lim, &text);
      if (load.weight <= 0) r.fail(quote(text) + " is not positive (a weight must be > 0)");
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  // The object is closed: r.fail() now names "load" itself.
  auto has = [&keys](const char* k) { return std::find(keys.begin(), keys.end(), k) != keys.end(); };
  std::set<std::string> form;  // the keys of the form meant
  if (has("gravity"))
    load.form = Load::Form::gravity, form = {"gravity"};
  else if (has("wrench"))
    load.form = Load::Form::wrench, form = {"wrench"};
  else if (has("force") || has("at"))
    load.form = Load::Form::force, form = {"force", "at"};
  else
    r.fail(std::string("expected one of ") + forms);
  for (const std::string& k : keys)
    if (!form.count(k)) r.fail("unknown key " + quote(k));
  for (const std::string& k : form)
    if (!has(k.c_str())) r.fail("missing required key " + quote(k));
  return load;
}

// A support region (docs/scene-format.md "Support regions"; proofs/notes/RG-1-regions.md): a polygon with
// holes and the pressure p = c0 + c1 x + c2 y >= 0. Checked here by the checker's own exact geometry (no CGAL):
// every ring simple (no repeated vertex, non-adjacent edges apart, adjacent ones meeting only at their common
// vertex), holes strictly inside the outline and apart from each other and from it, p >= 0 at the outline's
// vertices, a positive total force. The rings are oriented (outline counter-clockwise, holes clockwise) and the
// force W_R and moment M_R = integral of r p are computed exactly, by fan triangles from the origin.
struct P2 {
  Q x, y;
};
struct Region {
  std::string path;
  std::vector<std::vector<P2>> rings;  // as read; oriented by settle_region
  bool uniform = true, has_mu = false;
  Q force, linear[3], mu;
  Q c[3];          // the pressure's coefficients
  Q W, M[2];       // integral of p, of r p
};

int orient(const P2& a, const P2& b, const P2& c) {
  return sgn(Q((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)));
}
// p on the closed segment ab, given the three are collinear.
bool on_segment(const P2& p, const P2& a, const P2& b) {
  return (p.x - a.x) * (p.x - b.x) <= 0 && (p.y - a.y) * (p.y - b.y) <= 0;
}
// Do the closed segments ab and cd share a point?
bool segments_meet(const P2& a, const P2& b, const P2& c, const P2& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on_segment(c, a, b)) || (o2 == 0 && on_segment(d, a, b)) || (o3 == 0 && on_segment(a, c, d)) ||
         (o4 == 0 && on_segment(b, c, d));
}
Q pressure(const Q (&c)[3], const P2& r) { return c[0] + c[1] * r.x + c[2] * r.y; }
Q twice_area(const std::vector<P2>& ring) {
  Q a = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const P2 &p = ring[i], &q = ring[(i + 1) % ring.size()];
    a += p.x * q.y - p.y * q.x;
  }
  return a;
}
// Strictly inside a simple ring, for a point on none of its edges: the parity of the crossings of the ray to +x.
bool inside(const std::vector<P2>& ring, const P2& p) {
  bool in = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const P2 &a = ring[i], &b = ring[(i + 1) % ring.size()];
    if (a.y <= p.y && p.y < b.y && orient(a, b, p) > 0) in = !in;  // upward, p to its left
    if (b.y <= p.y && p.y < a.y && orient(a, b, p) < 0) in = !in;  // downward, p to its right
  }
  return in;
}
// A sum of many terms added pairwise, as a balanced tree (0 for none): rationals (one gcd with the growing
// denominator per level, not per term), or integer wrenches over denominators that differ (about log k rounds of
// work on k terms of n digits, where a running sum would take k rounds).
template <class T>
T tree_sum(std::vector<T> t) {
  if (t.empty()) return T();
  while (t.size() > 1) {
    std::size_t k = 0;
    for (std::size_t i = 0; i + 1 < t.size(); i += 2) t[k++] = t[i] + t[i + 1];
    if (t.size() % 2) t[k++] = std::move(t.back());
    t.resize(k);
  }
  return t[0];
}

// Every ring simple and the rings apart. Edges are swept in order of their smallest x, each compared with the
// edges that start before it ends (O(n log n) for ordinary polygons, O(n^2) at worst; n is at most
// max_region_vertices).
void check_rings(const Region& g) {
  struct Edge {
    std::size_t ring, i;
    Q lo, hi;
  };
  std::vector<Edge> edges;
  for (std::size_t k = 0; k < g.rings.size(); ++k) {
    const auto& r = g.rings[k];
    const std::string at = g.path + (k == 0 ? std::string(".outline") : ".holes[" + std::to_string(k - 1) + "]");
    if (r.size() < 3) throw Failure{at + ": has " + std::to_string(r.size()) + " vertices (a polygon needs at least 3)"};
    std::vector<const P2*> sorted;
    for (const P2& v : r) sorted.push_back(&v);
    std::sort(sorted.begin(), sorted.end(), [](const P2* a, const P2* b) { return a->x < b->x || (a->x == b->x && a->y < b->y); });
    for (std::size_t i = 1; i < sorted.size(); ++i)
      if (sorted[i]->x == sorted[i - 1]->x && sorted[i]->y == sorted[i - 1]->y)
        throw Failure{at + ": is not a simple polygon (a vertex is repeated)"};
    for (std::size_t i = 0; i < r.size(); ++i) {
      const P2 &a = r[i], &b = r[(i + 1) % r.size()];
      edges.push_back({k, i, a.x < b.x ? a.x : b.x, a.x < b.x ? b.x : a.x});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.lo < b.lo; });
  const auto ring_name = [&](std::size_t k) {
    return k == 0 ? std::string("the outline") : "holes[" + std::to_string(k - 1) + "]";
  };
  for (std::size_t u = 0; u < edges.size(); ++u)
    for (std::size_t w = u + 1; w < edges.size() && edges[w].lo <= edges[u].hi; ++w) {
      const Edge &e = edges[u], &f = edges[w];
      const auto& re = g.rings[e.ring];
      const auto& rf = g.rings[f.ring];
      const P2 &a = re[e.i], &b = re[(e.i + 1) % re.size()], &c = rf[f.i], &d = rf[(f.i + 1) % rf.size()];
      if (e.ring != f.ring) {
        if (segments_meet(a, b, c, d)) {
          const std::size_t hi = std::max(e.ring, f.ring), lo = std::min(e.ring, f.ring);
          throw Failure{g.path + ".holes[" + std::to_string(hi - 1) + "]: meets " + ring_name(lo) +
                        (lo == 0 ? " (a hole must lie strictly inside it)" : " (holes must be disjoint)")};
        }
        continue;
      }
      const std::size_t n = re.size();
      const std::string at = g.path + (e.ring == 0 ? std::string(".outline") : ".holes[" + std::to_string(e.ring - 1) + "]");
      const bool next = (e.i + 1) % n == f.i, prev = (f.i + 1) % n == e.i;
      if (next || prev) {  // adjacent: they meet at the shared vertex only (no fold back along one line)
        const P2& shared = next ? b : a;
        const P2& x = next ? a : b;            // e's other end
        const P2& y = next ? d : c;            // f's other end
        if (orient(x, shared, y) == 0 && (x.x - shared.x) * (y.x - shared.x) + (x.y - shared.y) * (y.y - shared.y) > 0)
          throw Failure{at + ": is not a simple polygon (two of its edges cross, touch or overlap)"};
        if (!(next && prev)) continue;  // a triangle: every pair is adjacent both ways; checked above
        continue;
      }
      if (segments_meet(a, b, c, d)) throw Failure{at + ": is not a simple polygon (two of its edges cross, touch or overlap)"};
    }
  for (std::size_t k = 1; k < g.rings.size(); ++k) {
    const std::string at = g.path + ".holes[" + std::to_string(k - 1) + "]";
    if (!inside(g.rings[0], g.rings[k][0])) throw Failure{at + ": is not inside the outline (a hole must lie strictly inside it)"};
    for (std::size_t j = 1; j < g.rings.size(); ++j)
      if (j != k && inside(g.rings[j], g.rings[k][0]))
        throw Failure{at + ": lies inside holes[" + std::to_string(j - 1) + "] (holes must be disjoint)"};
  }
}

// Validates the region and settles it: rings oriented, pressure coefficients, W and M (fan triangles (0, a, b)
// of the oriented boundary, whose signed integrals sum to the region's; degree <= 2, so the edge-midpoint rule
// is exact on each).
void settle_region(Region& g) {
  check_rings(g);
  Q area2 = 0;
  for (std::size_t k = 0; k < g.rings.size(); ++k) {
    const Q a = twice_area(g.rings[k]);
    if (sgn(a) == 0) throw Failure{g.path + ".outline: has zero area"};  // not reached for a simple ring
    if ((sgn(a) > 0) != (k == 0)) std::reverse(g.rings[k].begin(), g.rings[k].end());
    area2 += k == 0 ? abs(a) : Q(-abs(a));
  }
  if (g.uniform) {
    if (sgn(g.force) <= 0) throw Failure{g.path + ".force: " + show(g.force) + " is not positive (a region's force must be > 0)"};
    g.c[0] = 2 * g.force / area2, g.c[1] = 0, g.c[2] = 0;
  } else {
    for (int k = 0; k < 3; ++k) g.c[k] = g.linear[k];
    for (std::size_t i = 0; i < g.rings[0].size(); ++i)
      if (sgn(pressure(g.c, g.rings[0][i])) < 0)
        throw Failure{g.path + ".pressure: p = " + show(pressure(g.c, g.rings[0][i])) + " < 0 at a vertex of the outline " +
                      show(g.rings[0][i].x, g.rings[0][i].y) + " (a pressure must be >= 0 on the region)"};
  }
  std::vector<Q> w, mx, my;
  for (const auto& ring : g.rings)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const P2 &a = ring[i], &b = ring[(i + 1) % ring.size()];
      const Q area = (a.x * b.y - a.y * b.x) / 2;  // signed
      if (sgn(area) == 0) continue;
      const P2 ma{a.x / 2, a.y / 2}, mb{b.x / 2, b.y / 2}, mab{(a.x + b.x) / 2, (a.y + b.y) / 2};
      const Q pa = pressure(g.c, ma), pb = pressure(g.c, mb), pab = pressure(g.c, mab);
      w.push_back(area * (pa + pb + pab) / 3);
      mx.push_back(area * (ma.x * pa + mb.x * pb + mab.x * pab) / 3);
      my.push_back(area * (ma.y * pa + mb.y * pb + mab.y * pab) / 3);
    }
  g.W = tree_sum(std::move(w));
  g.M[0] = tree_sum(std::move(mx));
  g.M[1] = tree_sum(std::move(my));
  if (sgn(g.W) <= 0)
    throw Failure{g.path + ".pressure: the pressure is zero on the whole region (a region's total force must be > 0)"};
}

// {"outline": ring, "holes"?: [ring, ...], "pressure": "uniform" | {"linear": [a, b, c]}, "force"?: F, "mu"?: mu}
Region read_region(Reader& r, const Limits& lim, std::size_t& vertices) {
  Region g;
  g.path = r.path();
  if (r.peek() != Kind::object) r.fail("expected an object {\"outline\", \"holes\"?, \"pressure\", \"force\"?, \"mu\"?}");
  r.begin_object();
  const auto ring = [&](std::vector<P2>& out) {
    if (r.peek() != Kind::array) r.fail("expected an array of points");
    r.begin_array();
    while (r.next_item()) {
      if (++vertices > lim.max_region_vertices)
        r.fail("the support's regions have more than " + std::to_string(lim.max_region_vertices) + " vertices in all", true);
      Q v[2];
      read_fixed(r, 2, numbers_text(2), [&](std::size_t k) { v[k] = read_number(r, lim); });
      out.push_back({v[0], v[1]});
    }
  };
  bool has_outline = false, has_pressure = false, has_force = false;
  std::string_view key;
  g.rings.emplace_back();
  while (r.next_key(key)) {
    if (key == "outline") {
      ring(g.rings[0]);
      has_outline = true;
    } else if (key == "holes") {
      if (r.peek() != Kind::array) r.fail("expected an array of rings");
      r.begin_array();
      while (r.next_item()) {
        g.rings.emplace_back();
        ring(g.rings.back());
      }
    } else if (key == "pressure") {
      has_pressure = true;
      if (r.peek() == Kind::string) {
        if (r.string_view() != "uniform") r.fail("expected \"uniform\" or {\"linear\": [a, b, c]}");
        g.uniform = true;
      } else {
        if (r.peek() != Kind::object) r.fail("expected \"uniform\" or {\"linear\": [a, b, c]}");
        r.begin_object();
        bool has_linear = false;
        std::string_view k;
        while (r.next_key(k)) {
          if (k != "linear") r.fail("unknown key " + quote(k), true);
          read_fixed(r, 3, numbers_text(3), [&](std::size_t j) { g.linear[j] = read_number(r, lim); });
          has_linear = true;
        }
        if (!has_linear) r.fail("missing required key \"linear\"");
        g.uniform = false;
      }
    } else if (key == "force") {
      g.force = read_number(r, lim);
      has_force = true;
    } else if (key == "mu") {
      std::string text;
      g.mu = read_number(r, lim, &text);
      if (sgn(g.mu) < 0) r.fail(quote(text) + " is negative");
      g.has_mu = true;
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  if (!has_outline) r.fail("missing required key \"outline\"");
  if (!has_pressure) r.fail("missing required key \"pressure\"");
  if (g.uniform && !has_force) r.fail("missing key \"force\" (a uniform pressure needs the region's force)");
  if (!g.uniform && has_force) throw Failure{g.path + ".force: not allowed with a linear pressure"};
  if (g.rings.size() > 1) g.rings.shrink_to_fit();
  return g;
}

// The scene's support (docs/scene-format.md; the unknown distribution of docs/theory-sliding.md §1).
// Each point's numbers are kept as text, and as values when they are small, as for contacts.
struct Point_values {
  Q x, y, mu, f;  // f = 0 if unknown
};
struct Support_point {
  bool known = false;                // "force" given
  std::array<std::string, 4> text;   // x, y, mu (its own or support.mu), force ("" if unknown)
  bool kept = false;                 // the values are small and kept in `value`
  Point_values value;                // (kept) the same values
};
// The point's values: the kept ones (no copy), or read again from their text into `scratch` (valid: read before).
const Point_values& values(const Support_point& p, const Limits& lim, Point_values& scratch) {
  if (p.kept) return p.value;
  auto q = [&](std::size_t k) { return p.text[k].empty() ? Q(0) : scene_number(p.text[k], lim, "support"); };
  scratch = {q(0), q(1), q(2), q(3)};
  return scratch;
}

struct Support {
  std::deque<Support_point> points;  // (a deque: no copies of its rationals as it grows)
  std::vector<Region> regions;  // settled: oriented, with W and M
  std::size_t unknown = 0;  // points without a given force
  bool has_weight = false, has_center = false;
  Q weight, center[2];      // as written (support.weight, support.pressure_center)
  // The admissible set F = {f >= 0 : f_i = given where given, sum f = W, sum f r = W c} (theory-sliding
  // §1): with unknown forces, W = weight and c = pressure_center or body.com, and the unknown forces
  // must carry rest_weight = W - sum_known f_i with moment rest_moment = W c - sum_known f_i r_i.
  Q W, c[2], rest_weight, rest_moment[2];  // (W: not set when every force is given and no weight is written)
};

// {"mu"?, "weight"?, "pressure_center"?, "points": [{"at": [x, y], "force"?: f, "mu"?: mu}, ...]}
// (docs/scene-format.md). Every number is read exactly and checked: forces, weights and mu >= 0.
Support read_support(Reader& r, const Limits& lim) {
  if (r.peek() != Kind::object) r.fail("expected an object");
  r.begin_object();
  Support s;
  bool has_mu = false, has_points = false;
  std::string mu_text;
  std::string_view key;
  struct Raw {  // what a point needs until support.mu (which may follow) is known
    bool has_mu = false, positive = false;  // positive: a given force > 0
  };
  std::vector<Raw> raw;          // one per point of s.points
  std::string points_path;       // the points' array ("support.points"): point i is points_path + "[i]"
  const auto point_path = [&](std::size_t i) { return points_path + "[" + std::to_string(i) + "]"; };
  while (r.next_key(key)) {
    if (key == "mu") {
      if (read_number(r, lim, &mu_text) < 0) r.fail(quote(mu_text) + " is negative");
      has_mu = true;
    } else if (key == "weight") {
      std::string text;
      s.weight = read_number(r, lim, &text);
      if (s.weight <= 0) r.fail(quote(text) + " is not positive (a weight must be > 0)");
      s.has_weight = true;
    } else if (key == "pressure_center") {
      read_vector(r, lim, 2, s.center);
      s.has_center = true;
    } else if (key == "regions") {
      if (r.peek() != Kind::array) r.fail("expected an array");
      r.begin_array();
      std::size_t vertices = 0;
      while (r.next_item()) s.regions.push_back(read_region(r, lim, vertices));
    } else if (key == "points") {
      has_points = true;
      if (r.peek() != Kind::array) r.fail("expected an array");
      r.begin_array();
      while (r.next_item()) {
        if (raw.size() == lim.max_contacts)
          throw Failure{"support.points: more than " + std::to_string(lim.max_contacts) + " points"};
        if (Tally::reading) Tally::reading->entry("support.points", raw.size(), lim);
        Raw p;
        if (raw.empty()) {  // the first point's path ends in "[0]" (json.cpp Reader::path): the array's is before it
          points_path = r.path();
          points_path.resize(points_path.size() - 3);
        }
        if (r.peek() != Kind::object) r.fail("expected an object {\"at\", \"force\"?, \"mu\"?}");
        r.begin_object();
        std::string_view point_key;
        // x, y, mu, force as read (validated and counted; "0" where absent: mu until support.mu is known)
        Read_number n[4];
        bool has_at = false, has_force = false;
        while (r.next_key(point_key)) {
          if (point_key == "at") {
            read_numbers(r, lim, 2, n);
            has_at = true;
          } else if (point_key == "force") {
            n[3] = read_contact_number(r, lim);
            if (n[3].negative) r.fail(quote(n[3].text) + " is negative");
            has_force = true;
          } else if (point_key == "mu") {
            n[2] = read_contact_number(r, lim);
            if (n[2].negative) r.fail(quote(n[2].text) + " is negative");
            p.has_mu = true;
          } else {
            r.fail("unknown key " + quote(point_key), true);
          }
        }
        if (!has_at) r.fail("missing required key \"at\"");
        Support_point& sp = s.points.emplace_back();
        sp.known = has_force;
        p.positive = has_force && !n[3].zero && !n[3].negative;
        // the values kept if all are small (mu 0 until support.mu is known); the texts only when not
        Q* const value[4] = {&sp.value.x, &sp.value.y, &sp.value.mu, &sp.value.f};
        for (std::size_t k = 0; k < 4; ++k)
          if (n[k].fits) set_small(*value[k], n[k].value);
          else *value[k] = scene_number(n[k].text, lim, "support");  // valid: read before
        sp.kept = small(sp.value.x) && small(sp.value.y) && small(sp.value.mu) && small(sp.value.f);
        if (!sp.kept || !p.has_mu)  // (support.mu, read later, may make the point's values not kept)
          for (std::size_t k = 0; k < 4; ++k)
            if (k != 2 || p.has_mu) sp.text[k] = std::string(k == 3 && !has_force ? std::string_view() : n[k].text);
        raw.push_back(p);
      }
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  if (!has_points && s.regions.empty()) r.fail("missing required key \"points\" (a support needs points or regions)");
  if (raw.empty() && s.regions.empty()) throw Failure{"support.points: empty (a support needs at least one point or region)"};
  const Q support_mu = has_mu ? scene_number(mu_text, lim, "support.mu") : Q(0);
  bool any_force = false;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const Raw& p = raw[i];
    Support_point& sp = s.points[i];
    if (!p.has_mu && !has_mu) throw Failure{point_path(i) + ": missing key \"mu\" (and support.mu gives no default)"};
    if (!p.has_mu) {
      sp.text[2] = mu_text;
      if (sp.kept) sp.value.mu = support_mu;
      if (!small(support_mu)) sp.kept = false;
    }
    any_force = any_force || p.positive;
    s.unknown += sp.known ? 0 : 1;
  }
  if (s.unknown == 0 && !any_force && s.regions.empty()) throw Failure{"support.points: all forces are zero"};
  for (Region& g : s.regions) {
    if (!g.has_mu && !has_mu) throw Failure{g.path + ": missing key \"mu\" (and support.mu gives no default)"};
    if (!g.has_mu) g.mu = support_mu;
    settle_region(g);
  }
  return s;
}

// The distribution's condition of F once the whole scene is read (body.com may follow support): W and
// c, and an empty F reported in words. F is not empty iff rest_weight >= 0 and the point
// rest_moment / rest_weight lies in the convex hull of the points without a given force (or
// rest_weight = 0 and rest_moment = 0, when they all carry nothing).
void settle_support(Support& s, bool has_com, const Q (&com)[2], const Limits& lim) {
  // Every force given and neither weight nor pressure_center written: nothing to agree with, and W is not needed
  // (only in_f uses it, for a distribution chosen in F: some force unknown).
  if (s.unknown == 0 && !s.has_weight && !s.has_center) return;
  Q sum = 0, moment[2] = {0, 0};
  for (const Support_point& p : s.points) {
    if (!p.known) continue;
    Point_values scratch;
    const Point_values& v = values(p, lim, scratch);
    sum += v.f, moment[0] += v.f * v.x, moment[1] += v.f * v.y;
  }
  for (const Region& g : s.regions) sum += g.W, moment[0] += g.M[0], moment[1] += g.M[1];  // a known pressure
  if (s.unknown == 0) {  // a known distribution: weight and pressure_center, if given, must agree
    s.W = s.has_weight ? s.weight : sum;
    if (s.has_weight && s.weight != sum)
      throw Failure{"support.weight: " + show(s.weight) + " is not the sum " + show(sum) + " of the given forces"};
    if (s.has_center && (s.W * s.center[0] != moment[0] || s.W * s.center[1] != moment[1]))
      throw Failure{"support.pressure_center: " + show(s.center[0], s.center[1]) +
                    " is not the centre of pressure " + show(moment[0] / sum, moment[1] / sum) +
                    " of the given forces"};
    return;
  }
  if (!s.has_weight) throw Failure{"support: missing key \"weight\" (required when a point has no \"force\")"};
  if (!s.has_center && !has_com)
    throw Failure{"support: missing key \"pressure_center\" (required when a point has no \"force\" and body.com "
                  "is not given)"};
  s.W = s.weight;
  for (int k = 0; k < 2; ++k) s.c[k] = s.has_center ? s.center[k] : com[k];
  s.rest_weight = s.W - sum;
  for (int k = 0; k < 2; ++k) s.rest_moment[k] = s.W * s.c[k] - moment[k];
  const std::string none = "support: no admissible distribution: ";
  if (s.rest_weight < 0)
    throw Failure{none + "the given forces sum to " + show(sum) + ", more than support.weight " + show(s.W)};
  if (s.rest_weight == 0) {
    if (s.rest_moment[0] != 0 || s.rest_moment[1] != 0)
      throw Failure{none + "the given forces carry the whole weight " + show(s.W) + ", but their centre of pressure " +
                    show(moment[0] / sum, moment[1] / sum) + " is not the centre of pressure " + show(s.c[0], s.c[1])};
    return;
  }
  // Is 0 in the convex hull of d_i = rest_weight r_i - rest_moment (i unknown)? Equivalently: do the
  // d_i fail to fit in an open half-plane? One pass keeps the smallest cone [R, L] (counter-clockwise
  // from R to L, angle < pi) holding every d_i so far; a d_i that cannot join it with an angle < pi
  // (or d_i = 0) puts 0 in the hull (separation: 0 outside a compact convex set means an open
  // half-plane holds it). Only signs of cross and dot products: exact, no angles.
  auto cross = [](const Q(&a)[2], const Q(&b)[2]) { return sgn(Q(a[0] * b[1] - a[1] * b[0])); };
  auto dot = [](const Q(&a)[2], const Q(&b)[2]) { return sgn(Q(a[0] * b[0] + a[1] * b[1])); };
  bool inside = false, started = false;
  Q R[2], L[2];
  for (std::size_t i = 0; i < s.points.size() && !inside; ++i) {
    if (s.points[i].known) continue;
    Point_values scratch;
    const Point_values& v = values(s.points[i], lim, scratch);
    const Q d[2] = {s.rest_weight * v.x - s.rest_moment[0], s.rest_weight * v.y - s.rest_moment[1]};
    if (d[0] == 0 && d[1] == 0) {
      inside = true;
    } else if (!started) {
      started = true, R[0] = L[0] = d[0], R[1] = L[1] = d[1];
    } else if ((cross(R, d) == 0 && dot(R, d) < 0) || (cross(L, d) == 0 && dot(L, d) < 0)) {
      inside = true;  // opposite to a direction held: 0 on the segment between them
    } else if (cross(R, d) < 0) {  // clockwise of R: R moves to d if the cone stays below pi
      if (cross(d, L) > 0) R[0] = d[0], R[1] = d[1];
      else inside = true;
    } else if (cross(d, L) < 0) {  // counter-clockwise of L
      if (cross(R, d) > 0) L[0] = d[0], L[1] = d[1];
      else inside = true;
    }  // else d is in the cone already
  }
  if (inside) return;
  const Q cx = s.rest_moment[0] / s.rest_weight, cy = s.rest_moment[1] / s.rest_weight;
  if (s.unknown == s.points.size())
    throw Failure{none + "the centre of pressure " + show(cx, cy) +
                  " is outside the convex hull of the support points (the body would tip over)"};
  throw Failure{none + "the points without a given force must carry the remaining weight " + show(s.rest_weight) +
                " with its centre at " + show(cx, cy) + ", which is outside their convex hull"};
}

struct Scene {
  std::size_t longest = 0;  // digits of the longest number (as the budget counts them)
  std::vector<Contact> contacts;
  bool has_load = false;
  std::optional<Wrench> load;  // w_ext (certificate-format.md §3.3), if has_load
  std::optional<Support> support;
};

// The top-level scene object. body is read for body.com, load for w_ext, support for the sliding
// certificates (§6); an empty admissible set F is a bad scene.
Scene read_scene(Reader& r, const Limits& lim) {
  Scene scene;
  if (r.peek() != Kind::object) r.fail("a scene must be a JSON object");
  r.begin_object();
  bool has_version = false, has_com = false;
  struct Body {
    Q com[2];
  };
  std::optional<Body> body;  // (rationals only for the members present: each costs an allocation)
  std::optional<Load> load;
  std::string_view key;
  while (r.next_key(key)) {
    if (key == "wrenchkit") {
      const Read_number v = read_contact_number(r, lim);
      if (v.fits ? v.value.num != v.value.den : scene_number(v.text, lim, "") != 1)
        r.fail("expected 1 (the scene format version)");
      has_version = true;
    } else if (key == "name") {
      read_string(r);
    } else if (key == "body") {
      read_body(r, lim, has_com, body.emplace().com);
    } else if (key == "load") {
      load = read_load(r, lim);
    } else if (key == "support") {
      scene.support = read_support(r, lim);
    } else if (key == "contacts") {
      if (r.peek() != Kind::array) r.fail("expected an array");
      r.begin_array();
      while (r.next_item()) {
        if (scene.contacts.size() == lim.max_contacts)
          throw Failure{"contacts: more than " + std::to_string(lim.max_contacts) + " contacts"};
        if (Tally::reading) Tally::reading->entry("contacts", scene.contacts.size(), lim);
        scene.contacts.push_back(read_contact(r, lim));
      }
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  if (!has_version) r.fail("missing required key \"wrenchkit\"");
  if (scene.support) {
    if (has_com) settle_support(*scene.support, true, body->com, lim);
    else settle_support(*scene.support, false, Body{}.com, lim);
  }
  if (!load) return scene;
  // w_ext (theory.md §9): W(p, f) = (fx, fy, x*fy - y*fx); gravity w at com is W(com, (0, -w)) = (0, -w, -w*com_x)
  scene.has_load = load->form != Load::Form::none;
  switch (load->form) {
    case Load::Form::none: break;
    case Load::Form::force:
      scene.load = Wrench{load->force[0], load->force[1], load->at[0] * load->force[1] - load->at[1] * load->force[0]};
      break;
    case Load::Form::wrench: scene.load = Wrench{load->wrench[0], load->wrench[1], load->wrench[2]}; break;
    case Load::Form::gravity:
      if (!has_com) throw Failure{"load.gravity: needs body.com (the point where the weight acts)"};
      scene.load = Wrench{0, -load->weight, -load->weight * body->com[0]};
      break;
  }
  return scene;
}

// ---------------------------------------------------------------------------------------------
// The integers of the checks of §1 and §3. Each of these checks is written once, over a number type N, and
// run by fast_then_exact(): with N = Fixed (fixed width, on the stack) and, only if a result overflows it,
// again from the start with N = Z (GMP). Every value of either type is exact, so the two runs take the same
// steps and reach the same verdict and message; Fixed only decides sooner.

using Z = mpz_class;

struct Overflow {};  // a Fixed result that might not fit: the check starts again with N = Z

// A signed integer of at most kLimbs 64-bit limbs, on GMP's mpn layer (sign and magnitude). A result that
// might not fit (a product of m and n limbs with m + n > kLimbs, a carry out of the top limb) throws Overflow.
static_assert(GMP_NUMB_BITS == 64 && sizeof(mp_limb_t) == 8, "64-bit limbs");
class Fixed {
 public:
  static constexpr mp_size_t kLimbs = 8;
  Fixed() = default;
  Fixed(long x) : size_(x != 0), negative_(x < 0) {
    limb_[0] = x < 0 ? 0UL - static_cast<unsigned long>(x) : static_cast<unsigned long>(x);
  }
  static Fixed of(const Z& z) {
    Fixed r;
    r.size_ = static_cast<mp_size_t>(mpz_size(z.get_mpz_t()));
    if (r.size_ > kLimbs) throw Overflow{};
    for (mp_size_t i = 0; i < r.size_; ++i) r.limb_[i] = mpz_getlimbn(z.get_mpz_t(), i);
    r.negative_ = sgn(z) < 0;
    return r;
  }
  static Fixed of_digits(std::string_view d) {  // a run of decimal digits
    d.remove_prefix(std::min(d.find_first_not_of('0'), d.size()));
    if (d.size() > 154) throw Overflow{};  // 10^154 < 2^512
    Fixed r;
    if (d.empty()) return r;
    unsigned char digit[154];
    for (std::size_t i = 0; i < d.size(); ++i) digit[i] = static_cast<unsigned char>(d[i] - '0');
    mp_limb_t out[kLimbs + 1];  // mpn_set_str's room: the largest number of d.size() digits, and one limb
    r.size_ = static_cast<mp_size_t>(mpn_set_str(out, digit, d.size(), 10));
    std::copy(out, out + r.size_, r.limb_);
    return r;
  }
  friend Z to_z(const Fixed& x) {
    Z r;
    mpz_import(r.get_mpz_t(), static_cast<std::size_t>(x.size_), -1, sizeof(mp_limb_t), 0, 0, x.limb_);
    return x.negative_ ? Z(-r) : r;
  }
  friend int sgn(const Fixed& x) { return x.size_ == 0 ? 0 : x.negative_ ? -1 : 1; }
  friend bool operator==(const Fixed& a, const Fixed& b) {
    return a.size_ == b.size_ && a.negative_ == b.negative_ && (a.size_ == 0 || mpn_cmp(a.limb_, b.limb_, a.size_) == 0);
  }
  friend Fixed operator-(Fixed x) {
    x.negative_ = x.size_ != 0 && !x.negative_;
    return x;
  }
  friend Fixed operator+(const Fixed& a, const Fixed& b) {
    if (a.size_ == 0) return b;
    if (b.size_ == 0) return a;
    const bool a_larger = a.size_ != b.size_ ? a.size_ > b.size_ : mpn_cmp(a.limb_, b.limb_, a.size_) >= 0;
    const Fixed& x = a_larger ? a : b;  // |x| >= |y|
    const Fixed& y = a_larger ? b : a;
    Fixed r;
    r.size_ = x.size_;
    if (a.negative_ == b.negative_) {
      if (mpn_add(r.limb_, x.limb_, x.size_, y.limb_, y.size_) != 0) {
        if (r.size_ == kLimbs) throw Overflow{};
        r.limb_[r.size_++] = 1;
      }
    } else {
      mpn_sub(r.limb_, x.limb_, x.size_, y.limb_, y.size_);  // no borrow: |x| >= |y|
      while (r.size_ > 0 && r.limb_[r.size_ - 1] == 0) --r.size_;
    }
    r.negative_ = r.size_ != 0 && x.negative_;
    return r;
  }
  friend Fixed operator-(const Fixed& a, const Fixed& b) { return a + -b; }
  friend Fixed operator*(const Fixed& a, const Fixed& b) {
    Fixed r;
    if (a.size_ == 0 || b.size_ == 0) return r;
    if (a.size_ + b.size_ > kLimbs) throw Overflow{};
    if (a.size_ == 1 && b.size_ == 1) {
      __extension__ const unsigned __int128 p = static_cast<unsigned __int128>(a.limb_[0]) * b.limb_[0];
      r.limb_[0] = static_cast<mp_limb_t>(p), r.limb_[1] = static_cast<mp_limb_t>(p >> 64);
    } else if (a.size_ >= b.size_) {
      mpn_mul(r.limb_, a.limb_, a.size_, b.limb_, b.size_);
    } else {
      mpn_mul(r.limb_, b.limb_, b.size_, a.limb_, a.size_);
    }
    r.size_ = a.size_ + b.size_ - (r.limb_[a.size_ + b.size_ - 1] == 0 ? 1 : 0);
    r.negative_ = a.negative_ != b.negative_;
    return r;
  }

 private:
  mp_size_t size_ = 0;  // limbs in use, the top one not zero; 0 for the integer 0
  bool negative_ = false;
  mp_limb_t limb_[kLimbs];
};
inline const Z& to_z(const Z& z) { return z; }

// check(Fixed()) and, if that overflows (or Limits::fixed_width is false), check(Z()): check is generic over the
// type of its argument, a zero of the number type to compute in.
template <class Check>
void fast_then_exact(const Limits& lim, const Check& check) {
  if (lim.fixed_width) try {
      return check(Fixed());
    } catch (const Overflow&) {
    }
  check(Z());
}

// A rational as num / den, den > 0, not necessarily in lowest terms.
template <class N>
struct Frac {
  N num, den;
};
template <class N>
Frac<N> fraction(const Q& q) {
  if constexpr (std::is_same_v<N, Z>) return {q.get_num(), q.get_den()};
  else return {Fixed::of(q.get_num()), Fixed::of(q.get_den())};
}
// A certificate rational's text, its grammar checked (the numerator and denominator as written).
template <class N>
Frac<N> fraction(std::string_view s) {
  const auto digits = [](std::string_view d) {
    if constexpr (std::is_same_v<N, Z>) return Z(std::string(d), 10);
    else return Fixed::of_digits(d);
  };
  const bool negative = s[0] == '-';
  const std::size_t slash = s.find('/'), begin = negative ? 1 : 0;
  Frac<N> f{digits(s.substr(begin, slash - begin)), slash == std::string_view::npos ? N(1L) : digits(s.substr(slash + 1))};
  if (negative) f.num = -f.num;
  return f;
}

// ---------------------------------------------------------------------------------------------
// Generators (certificate-format.md §1)

enum class Reading { friction, frictionless };  // of force_closure, of form_closure

// A wrench in integers: (v[0], v[1], v[2]) / d with d > 0. A positive denominator changes neither the
// sign of a power nor whether a determinant is zero, and a sum of such fractions is zero exactly when
// the numerator over their product (or their common denominator) is: so the conditions of §3 are
// checked on integers, with no gcd (mpq arithmetic reduces every intermediate result).
template <class N>
struct Int_wrench {
  N v[3], d;
};

// The rationals (a, b, c) as an Int_wrench over the product of their denominators.
template <class N>
Int_wrench<N> integer_form(const Frac<N>& a, const Frac<N>& b, const Frac<N>& c) {
  return {{N(a.num * b.den * c.den), N(b.num * a.den * c.den), N(c.num * a.den * b.den)}, N(a.den * b.den * c.den)};
}
template <class N, class T>
Int_wrench<N> integer_form(const T (&x)[3]) {  // of three rationals (Q) or certificate rational texts
  return integer_form(fraction<N>(x[0]), fraction<N>(x[1]), fraction<N>(x[2]));
}

Q value(const Z& num, const Z& den) {  // num / den as a rational in lowest terms (for messages)
  Q q(num, den);
  q.canonicalize();
  return q;
}
template <class N>
std::string show(const Int_wrench<N>& w) {
  const Z d = to_z(w.d);
  return "(" + show(value(to_z(w.v[0]), d)) + ", " + show(value(to_z(w.v[1]), d)) + ", " + show(value(to_z(w.v[2]), d)) + ")";
}

// The edges of a contact under a reading (the table of §1): their number, names in `names`.
int edge_names(const Contact& c, Reading reading, const char* (&names)[2]) {
  if (c.wrench) return names[0] = "wrench", 1;
  if (reading == Reading::frictionless || !c.frictional) return names[0] = "normal", 1;
  names[0] = "left", names[1] = "right";
  return 2;
}

// The generators of one contact under a reading, recomputed exactly from the scene text, in edge_names()' order.
template <class N>
struct Generators {
  int count;
  const char* edge[2];
  Int_wrench<N> w[2];
};
template <class N>
Generators<N> generators(const Contact& c, Reading reading, const Limits& lim) {
  Frac<N> in[5];  // point contact: x, y, nx, ny, mu; wrench: fx, fy, m
  const std::size_t count = c.wrench ? 3 : 5;
  if (c.fixed) {
    for (std::size_t k = 0; k < count; ++k) in[k] = {N(static_cast<long>(c.small[k].num)), N(static_cast<long>(c.small[k].den))};
  } else {
    std::vector<Q> read;
    if (c.value.empty())
      for (const std::string& s : c.text) read.push_back(scene_number(s, lim, "contacts"));  // valid: read before
    for (std::size_t k = 0; k < count; ++k) in[k] = fraction<N>(c.value.empty() ? read[k] : c.value[k]);
  }
  Generators<N> g;
  g.count = edge_names(c, reading, g.edge);
  if (c.wrench) return g.w[0] = integer_form(in[0], in[1], in[2]), g;
  // p = P / dp, n = Nn / dn over the products of the coordinates' denominators. W(p, f) = (fx, fy, px*fy - py*fx)
  // for f = F / df: (dp*Fx, dp*Fy, Px*Fy - Py*Fx) / (dp*df).
  const N P[2] = {N(in[0].num * in[1].den), N(in[1].num * in[0].den)}, dp(in[0].den * in[1].den);
  const N Nn[2] = {N(in[2].num * in[3].den), N(in[3].num * in[2].den)}, dn(in[2].den * in[3].den);
  const auto force_at = [&](const N& Fx, const N& Fy, const N& df) {
    return Int_wrench<N>{{N(dp * Fx), N(dp * Fy), N(P[0] * Fy - P[1] * Fx)}, N(dp * df)};
  };
  if (g.count == 1) return g.w[0] = force_at(Nn[0], Nn[1], dn), g;
  // n + mu*rot90(n) = (nx - mu*ny, ny + mu*nx),  n - mu*rot90(n) = (nx + mu*ny, ny - mu*nx); with mu = a/b
  // these are (b*Nn -+ a*rot90(Nn)) / (dn*b).
  const N &a = in[4].num, &b = in[4].den;
  const N bN[2] = {N(b * Nn[0]), N(b * Nn[1])}, aN[2] = {N(a * Nn[0]), N(a * Nn[1])}, df(dn * b);
  g.w[0] = force_at(N(bN[0] - aN[1]), N(bN[1] + aN[0]), df);
  g.w[1] = force_at(N(bN[0] + aN[1]), N(bN[1] - aN[0]), df);
  return g;
}

// Power <T, w> = vx*fx + vy*fy + w*m (theory.md §1.4) of the numerators: the power of T/T.d against w/w.d times
// T.d * w.d > 0.
template <class N>
N power(const Int_wrench<N>& t, const Int_wrench<N>& g) {
  return N(t.v[0] * g.v[0] + t.v[1] * g.v[1] + t.v[2] * g.v[2]);
}

// det[a; b; c] of the numerators: the determinant of the wrenches times a.d * b.d * c.d > 0.
template <class N>
N det3(const Int_wrench<N>& a, const Int_wrench<N>& b, const Int_wrench<N>& c) {
  const N(&x)[3] = a.v, (&y)[3] = b.v, (&z)[3] = c.v;
  return N(x[0] * N(y[1] * z[2] - y[2] * z[1]) - x[1] * N(y[0] * z[2] - y[2] * z[0]) + x[2] * N(y[0] * z[1] - y[1] * z[0]));
}

// x + y: over the common denominator when the denominators are equal, else over their product.
template <class N>
Int_wrench<N> operator+(const Int_wrench<N>& x, const Int_wrench<N>& y) {
  if (x.d == y.d) return {{N(x.v[0] + y.v[0]), N(x.v[1] + y.v[1]), N(x.v[2] + y.v[2])}, x.d};
  return {{N(x.v[0] * y.d + y.v[0] * x.d), N(x.v[1] * y.d + y.v[1] * x.d), N(x.v[2] * y.d + y.v[2] * x.d)}, N(x.d * y.d)};
}

// ---------------------------------------------------------------------------------------------
// Certificate

// Texts below (std::string_view) are views of the certificate's text or of its reader's decoded strings:
// valid while the reader is.
struct Ref {  // {"contact": i, "edge": E}, the item-th element of the array `list` (in the object at `owner`)
  std::string owner;  // "" at the top level, else the path of the witness holding `list`, and "."
  const char* list = "";
  std::size_t item = 0;
  std::string_view index, edge;
  std::size_t contact = SIZE_MAX;  // SIZE_MAX if the index text is too long to be in range
  std::string path() const { return owner + list + ("[" + std::to_string(item) + "]"); }  // for messages
};
struct Term {
  Ref ref;
  std::string_view weight;  // its text (grammar checked); rational_value() is the weight
};
using Pair = std::array<Q, 2>;
// A stick witness {"distribution", "support_forces"} or a slide witness {"distribution", "twist",
// "speed_bounds"} (§6.2); a hold witness {"distribution", "combination", "support_forces"} and a fail witness
// (a slide witness's keys) of property "hold" (§7).
struct Witness {
  std::string path;
  std::vector<Q> distribution;
  std::vector<Pair> forces;  // support_forces
  Q twist[3];
  std::vector<Q> speeds;  // speed_bounds
  bool has_combination = false;
  std::vector<Term> combination;
  bool has_regions = false;  // format 2 (§7.5): the regions' blocks of this witness's distribution
  std::vector<struct Block> regions;
};
// A region's block (certificate-format.md §6.4): cells (vertices and counter-clockwise index triples) that tile
// the region, with a force per cell (sticks) or a speed bound per vertex (slides).
struct Block {
  std::string path;
  std::vector<P2> vertices;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<Pair> forces;
  std::vector<Q> speeds;
  bool has_forces = false, has_speeds = false;
};
// The keys present in a certificate: one bit per key of the format (an unknown key is rejected as it is
// read, so it is never asked for). Used as the set of keys it replaces: insert() and count().
class Key_set {
 public:
  void insert(std::string_view key) {
    const int i = index(key);
    if (i >= 0) bits_ |= 1u << i;
  }
  std::size_t count(std::string_view key) const {
    const int i = index(key);
    if (i < 0) throw std::logic_error("Key_set: \"" + std::string(key) + "\" is not a key of the format");
    return (bits_ >> i) & 1u;
  }
  // The bits of these keys, to test many at once (any()): computed once by the caller, not per certificate.
  template <std::size_t N>
  static unsigned mask(const char* const (&keys)[N]) {
    unsigned m = 0;
    for (const std::string_view k : keys) {
      const int i = index(k);
      if (i < 0) throw std::logic_error("Key_set: \"" + std::string(k) + "\" is not a key of the format");
      m |= 1u << i;
    }
    return m;
  }
  bool any(unsigned mask) const { return (bits_ & mask) != 0; }

 private:
  static int index(std::string_view key) {
    static const std::string_view known[] = {"wrenchkit_certificate", "property", "holds", "combination",
                                             "independent", "twist", "reading", "load", "motion",
                                             "support_forces", "speed_bounds", "dual", "vertices", "sticking",
                                             "sliding", "holding", "failing", "regions"};
    for (int i = 0; i < static_cast<int>(sizeof known / sizeof known[0]); ++i)
      if (known[i] == key) return i;
    return -1;
  }
  unsigned bits_ = 0;
};

// The members of properties "motion" (§6) and "hold" (§7), read only when present (each costs allocations).
struct Motion_part {
  Q load[3], dual[3];
  std::vector<Pair> support_forces;
  std::vector<Q> speed_bounds;
  std::vector<Witness> vertices;
  Witness sticking, sliding;
  Witness holding, failing;  // property "hold", "holds": "depends"
  std::vector<Block> regions;
};

struct Certificate {
  Key_set keys;  // the keys present
  std::string_view property;
  Reading reading = Reading::friction;
  bool equilibrium = false;  // property "equilibrium" (§3.3), read with friction
  bool motion = false;       // property "motion" (§6)
  bool hold = false;         // property "hold" (§7), read with friction
  bool holds = false;
  bool depends = false;      // "holds": "depends" (property "hold" only)
  int version = 1;           // "wrenchkit_certificate": 1, or 2 (§7.5: a witness may carry its regions' blocks)
  std::vector<Term> combination;
  std::vector<Ref> independent;
  std::string_view twist[3] = {"0", "0", "0"}, where[2] = {"0", "0"};  // texts; where: reading.point or .direction
  std::string_view label;  // reading.label
  // property "motion" (and, in motion_members, the support's blocks that "hold" shares with it)
  std::string_view claim;  // "sticks", "slides" or "depends"
  std::unique_ptr<Motion_part> motion_members;  // allocated by m() when a member is read; see members()
  Motion_part& m() {
    if (!motion_members) motion_members = std::make_unique<Motion_part>();
    return *motion_members;
  }
};

// The certificate's members of properties "motion" and "hold" (all empty if it has none).
const Motion_part& members(const Certificate& c) {
  static const Motion_part none;
  return c.motion_members ? *c.motion_members : none;
}

// A certificate rational's text (a JSON string, its grammar checked; a view valid while the reader is).
std::string_view read_rational_text(Reader& r) {
  if (r.peek() != Kind::string) r.fail("expected a rational as a JSON string, such as \"-3/4\"");
  const std::string_view s = r.string_view();
  if (!rational_grammar(s)) not_a_rational(s, r.path());
  return s;
}
Q read_rational(Reader& r) { return rational_value(read_rational_text(r)); }

// {"contact": i, "edge": E} and, if weighted, "weight": "p/q".
Term read_term(Reader& r, bool weighted, const char* list, std::size_t item) {
  Term t;
  t.ref.list = list, t.ref.item = item;
  if (r.peek() != Kind::object)
    r.fail(weighted ? "expected an object {\"contact\", \"edge\", \"weight\"}"
                    : "expected an object {\"contact\", \"edge\"}");
  r.begin_object();
  enum : unsigned { kContact = 1, kEdge = 2, kWeight = 4 };
  unsigned keys = 0;  // the keys present
  std::string_view key;
  while (r.next_key(key)) {
    if (key == "contact") {
      keys |= kContact;
      if (r.peek() != Kind::number) r.fail("expected a contact index (a JSON integer)");
      t.ref.index = r.number();
      if (t.ref.index.find_first_not_of("0123456789") != std::string::npos)
        r.fail("expected a contact index: a JSON integer without sign, fraction or exponent, not " +
               clip(std::string(t.ref.index)));
      if (t.ref.index.size() <= 18) {  // no overflow; a longer index is out of range anyway
        unsigned long long v = 0;
        for (const char d : t.ref.index) v = v * 10 + static_cast<unsigned>(d - '0');
        t.ref.contact = v < SIZE_MAX ? static_cast<std::size_t>(v) : SIZE_MAX;
      }
    } else if (key == "edge") {
      keys |= kEdge;
      if (r.peek() != Kind::string) r.fail("expected a string");
      t.ref.edge = r.string_view();
    } else if (key == "weight" && weighted) {
      keys |= kWeight;
      t.weight = read_rational_text(r);
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  if (!(keys & kContact)) r.fail("missing required key \"contact\"");
  if (!(keys & kEdge)) r.fail("missing required key \"edge\"");
  if (weighted && !(keys & kWeight)) r.fail("missing required key \"weight\"");
  return t;
}

// An array of rationals, of any length.
std::vector<Q> read_rationals(Reader& r) {
  if (r.peek() != Kind::array) r.fail("expected an array of rationals");
  r.begin_array();
  std::vector<Q> out;
  out.reserve(16);  // (a reallocation copies the rationals: room for 16 at once, then doubling)
  while (r.next_item()) out.push_back(read_rational(r));
  return out;
}
// An array of [x, y] pairs of rationals.
std::vector<Pair> read_pairs(Reader& r) {
  if (r.peek() != Kind::array) r.fail("expected an array of [gx, gy] pairs of rationals");
  r.begin_array();
  std::vector<Pair> out;
  out.reserve(16);  // (a reallocation copies the rationals: room for 16 at once, then doubling)
  while (r.next_item()) {
    out.emplace_back();
    read_fixed(r, 2, "an array of two rationals [gx, gy]", [&](std::size_t k) { out.back()[k] = read_rational(r); });
  }
  return out;
}

// A stick witness {"distribution", "support_forces"} or (slide) a slide witness {"distribution",
// "twist", "speed_bounds"}: exactly these keys; a stick witness may also hold "combination" (a hold witness,
// §7: which keys a property allows is checked once the property is known).
Block read_block(Reader& r);

Witness read_witness(Reader& r, bool slide) {
  Witness w;
  w.path = r.path();
  const char* const what = slide ? "expected an object {\"distribution\", \"twist\", \"speed_bounds\"}"
                                 : "expected an object {\"distribution\", \"support_forces\"}";
  if (r.peek() != Kind::object) r.fail(what);
  r.begin_object();
  std::set<std::string> keys;
  std::string_view key;
  while (r.next_key(key)) {
    keys.insert(std::string(key));
    if (key == "distribution") {
      w.distribution = read_rationals(r);
    } else if (key == "support_forces" && !slide) {
      w.forces = read_pairs(r);
    } else if (key == "combination" && !slide) {
      if (r.peek() != Kind::array) r.fail("expected an array of {\"contact\", \"edge\", \"weight\"}");
      r.begin_array();
      while (r.next_item()) {
        w.combination.push_back(read_term(r, true, "combination", w.combination.size()));
        w.combination.back().ref.owner = w.path + ".";
      }
      w.has_combination = true;
    } else if (key == "twist" && slide) {
      read_fixed(r, 3, "an array of three rationals [vx, vy, w]", [&](std::size_t k) { w.twist[k] = read_rational(r); });
    } else if (key == "speed_bounds" && slide) {
      w.speeds = read_rationals(r);
    } else if (key == "regions") {  // format 2 only (§6.5, §7.5: checked with the scene)
      if (r.peek() != Kind::array) r.fail("expected an array of region blocks (one per support region)");
      r.begin_array();
      while (r.next_item()) w.regions.push_back(read_block(r));
      w.has_regions = true;
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  for (const char* k : slide ? std::vector<const char*>{"distribution", "twist", "speed_bounds"}
                             : std::vector<const char*>{"distribution", "support_forces"})
    if (!keys.count(k)) r.fail(std::string("missing required key \"") + k + "\"");
  return w;
}

// {"vertices": [[x, y], ...], "triangles": [[i, j, k], ...], "forces": [[gx, gy], ...]} or with "speed_bounds":
// [u, ...] instead of "forces" (§6.4); indices are JSON integers without sign, fraction or exponent.
Block read_block(Reader& r) {
  Block b;
  b.path = r.path();
  if (r.peek() != Kind::object)
    r.fail("expected an object {\"vertices\", \"triangles\", \"forces\" or \"speed_bounds\"}");
  r.begin_object();
  std::set<std::string> keys;
  std::string_view key;
  while (r.next_key(key)) {
    keys.insert(std::string(key));
    if (key == "vertices") {
      for (const Pair& v : read_pairs(r)) b.vertices.push_back({v[0], v[1]});
    } else if (key == "triangles") {
      if (r.peek() != Kind::array) r.fail("expected an array of [i, j, k] vertex indices");
      r.begin_array();
      while (r.next_item()) {
        b.triangles.emplace_back();
        read_fixed(r, 3, "an array of three vertex indices [i, j, k]", [&](std::size_t k) {
          if (r.peek() != Kind::number) r.fail("expected a vertex index (a JSON integer)");
          const std::string t(r.number());
          if (t.find_first_not_of("0123456789") != std::string::npos || t.size() > 18)
            r.fail("expected a vertex index: a JSON integer without sign, fraction or exponent, not " + clip(t));
          unsigned long long v = 0;
          for (const char d : t) v = v * 10 + static_cast<unsigned>(d - '0');
          b.triangles.back()[k] = v < SIZE_MAX ? static_cast<std::size_t>(v) : SIZE_MAX;
        });
      }
    } else if (key == "forces") {
      b.forces = read_pairs(r);
      b.has_forces = true;
    } else if (key == "speed_bounds") {
      b.speeds = read_rationals(r);
      b.has_speeds = true;
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  for (const char* k : {"vertices", "triangles"})
    if (!keys.count(k)) r.fail(std::string("missing required key \"") + k + "\"");
  if (b.has_forces == b.has_speeds) r.fail("expected exactly one of \"forces\" (sticks) and \"speed_bounds\" (slides)");
  return b;
}

// {"label": "+" | "-", "point": [x, y]} or {"label": "infinity", "direction": [dx, dy]}
void read_reading(Reader& r, Certificate& c) {
  if (r.peek() != Kind::object) r.fail("expected an object {\"label\", \"point\"} or {\"label\", \"direction\"}");
  r.begin_object();
  std::set<std::string> keys;
  std::string_view key;
  while (r.next_key(key)) {
    keys.insert(std::string(key));
    if (key == "label") {
      c.label = r.peek() == Kind::string ? r.string_view() : "";
      if (c.label != "+" && c.label != "-" && c.label != "infinity") r.fail("expected \"+\", \"-\" or \"infinity\"");
    } else if (key == "point" || key == "direction") {
      read_fixed(r, 2, "an array of two rationals", [&](std::size_t k) { c.where[k] = read_rational_text(r); });
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  if (!keys.count("label")) r.fail("missing required key \"label\"");
  const bool infinite = c.label == "infinity", point = keys.count("point") > 0, direction = keys.count("direction") > 0;
  if (infinite ? point || !direction : !point || direction)
    r.fail(infinite ? "label \"infinity\" needs \"direction\" and no \"point\""
                    : "label " + quote(c.label) + " needs \"point\" and no \"direction\"");
}

Certificate read_certificate(Reader& r) {
  Certificate c;
  if (r.peek() != Kind::object) r.fail("a certificate must be a JSON object");
  r.begin_object();
  // An empty combination is allowed for "equilibrium" only; if "property" comes after
  // "combination", that is decided once the whole object is read.
  const std::string non_empty = "expected a non-empty array of {\"contact\", \"edge\", \"weight\"}";
  bool empty_combination = false;
  std::string_view key;
  while (r.next_key(key)) {
    c.keys.insert(key);
    if (key == "wrenchkit_certificate") {
      const std::string_view v = r.peek() == Kind::number ? r.number() : "";
      if (v != "1" && v != "2") r.fail("expected the integer 1 or 2");
      c.version = v == "2" ? 2 : 1;
    } else if (key == "property") {
      const std::string_view p = r.peek() == Kind::string ? r.string_view() : "";
      if (p != "force_closure" && p != "form_closure" && p != "equilibrium" && p != "motion" && p != "hold")
        r.fail("expected \"force_closure\", \"form_closure\", \"equilibrium\", \"motion\" or \"hold\"");
      c.property = p;
      c.reading = p == "form_closure" ? Reading::frictionless : Reading::friction;
      c.equilibrium = p == "equilibrium";
      c.motion = p == "motion";
      c.hold = p == "hold";
    } else if (key == "holds") {
      if (r.peek() == Kind::string) {  // "depends": property "hold" only (checked once the property is known)
        if (r.string_view() != "depends") r.fail("expected true or false (or \"depends\" for property \"hold\")");
        c.depends = true;
      } else {
        if (r.peek() != Kind::boolean) r.fail("expected true or false");
        c.holds = r.boolean();
      }
    } else if (key == "combination") {
      if (r.peek() != Kind::array)
        r.fail(c.equilibrium ? "expected an array of {\"contact\", \"edge\", \"weight\"}" : non_empty);
      r.begin_array();
      c.combination.reserve(8);
      while (r.next_item()) c.combination.push_back(read_term(r, true, "combination", c.combination.size()));
      if (c.combination.empty() && c.keys.count("property") && !c.equilibrium && !c.hold) r.fail(non_empty);
      empty_combination = c.combination.empty();
    } else if (key == "independent") {
      read_fixed(r, 3, "an array of three {\"contact\", \"edge\"}",
                 [&](std::size_t k) { c.independent.push_back(read_term(r, false, "independent", k).ref); });
    } else if (key == "twist") {
      read_fixed(r, 3, "an array of three rationals [vx, vy, w]",
                 [&](std::size_t k) { c.twist[k] = read_rational_text(r); });
    } else if (key == "reading") {
      read_reading(r, c);
    } else if (key == "load") {
      read_fixed(r, 3, "an array of three rationals [fx, fy, m]", [&](std::size_t k) { c.m().load[k] = read_rational(r); });
    } else if (key == "motion") {
      c.claim = r.peek() == Kind::string ? r.string_view() : "";
      if (c.claim != "sticks" && c.claim != "slides" && c.claim != "depends")
        r.fail("expected \"sticks\", \"slides\" or \"depends\"");
    } else if (key == "support_forces") {
      c.m().support_forces = read_pairs(r);
    } else if (key == "speed_bounds") {
      c.m().speed_bounds = read_rationals(r);
    } else if (key == "dual") {
      read_fixed(r, 3, "an array of three rationals [y0, yx, yy]", [&](std::size_t k) { c.m().dual[k] = read_rational(r); });
    } else if (key == "vertices") {
      if (r.peek() != Kind::array) r.fail("expected an array of {\"distribution\", \"support_forces\"}");
      r.begin_array();
      while (r.next_item()) c.m().vertices.push_back(read_witness(r, false));
    } else if (key == "sticking") {
      c.m().sticking = read_witness(r, false);
    } else if (key == "sliding") {
      c.m().sliding = read_witness(r, true);
    } else if (key == "holding") {
      c.m().holding = read_witness(r, false);
    } else if (key == "failing") {
      c.m().failing = read_witness(r, true);
    } else if (key == "regions") {
      if (r.peek() != Kind::array) r.fail("expected an array of region blocks (one per support region)");
      r.begin_array();
      while (r.next_item()) c.m().regions.push_back(read_block(r));
    } else {
      r.fail("unknown key " + quote(key), true);
    }
  }
  if (empty_combination && !c.equilibrium && !c.hold) throw Failure{"combination: " + non_empty};
  return c;
}

// The keys that must, and must not, be present (certificate-format.md §3, §3.3).
void check_keys(const Certificate& c) {
  auto need = [&c](const char* key) {
    if (!c.keys.count(key)) throw Failure{std::string("missing required key \"") + key + "\""};
  };
  auto ban = [&c](const char* key) {
    if (c.keys.count(key))
      throw Failure{std::string("key \"") + key + "\" is not allowed when \"holds\" is " +
                    (c.holds ? "true" : "false")};
  };
  auto no_independent = [&c, &ban] {  // "equilibrium" never uses it
    if (!c.equilibrium) return ban("independent");
    if (c.keys.count("independent"))
      throw Failure{"key \"independent\" is not allowed when \"property\" is \"equilibrium\""};
  };
  need("wrenchkit_certificate"), need("property");
  if (c.depends && !c.hold)
    throw Failure{"holds: \"depends\" is only a claim of property \"hold\" (expected true or false)"};
  if (c.motion || c.hold) return;  // check_motion() and check_hold() decide, knowing the scene's support
  static const char* const motion_keys[] = {"load",    "motion",   "support_forces", "speed_bounds",
                                            "dual",    "vertices", "sticking",       "sliding",
                                            "holding", "failing",  "regions"};
  static const unsigned motion_mask = Key_set::mask(motion_keys);
  if (c.keys.any(motion_mask))  // (one test for the usual certificate; the loop names the key)
    for (const char* key : motion_keys)
      if (c.keys.count(key))
        throw Failure{std::string("key \"") + key + "\" is not allowed when \"property\" is " + quote(c.property)};
  need("holds");
  if (c.holds) {
    need("combination");
    if (c.equilibrium)
      no_independent();
    else
      need("independent");
    ban("twist"), ban("reading");
  } else {
    need("twist"), ban("combination"), no_independent();
  }
}

std::string name(std::size_t contact, std::string_view edge) {
  return "contacts[" + std::to_string(contact) + "] edge " + std::string(edge);
}

// Rule 1 of §3.1: the reference names an existing contact and an edge that contact has under the reading.
// Returns the edge's index in generators().
int check_reference(const Ref& ref, const std::vector<Contact>& contacts, Reading reading) {
  if (ref.contact >= contacts.size())
    throw Failure{ref.path() + ".contact: index " + clip(std::string(ref.index)) + " is out of range (the scene has " +
                  std::to_string(contacts.size()) + " contacts)"};
  const char* names[2];
  const int n = edge_names(contacts[ref.contact], reading, names);
  for (int k = 0; k < n; ++k)
    if (ref.edge == names[k]) return k;
  const std::string edges = quote(names[0]) + (n == 2 ? " or " + quote(names[1]) : "");
  throw Failure{ref.path() + ".edge: contacts[" + std::to_string(ref.contact) + "] has no edge " + quote(ref.edge) +
                " under the " + (reading == Reading::friction ? "friction" : "frictionless") + " reading (it has " +
                edges + ")"};
}

// Rules (1)-(3) of §3.1 for the terms of a combination: each names a generator of the scene under the reading,
// no generator appears twice, every weight is strictly positive. Holds each term's generator g_k, recomputed from
// the scene, and weight_k g_k.
template <class N>
struct Combination {
  std::vector<std::size_t> order;  // the terms by generator (contact, edge), then by place
  std::vector<Int_wrench<N>> generator, weighted;
  Combination(const std::vector<Term>& terms, const std::vector<Contact>& contacts, Reading reading, const Limits& lim)
      : order(terms.size()), generator(terms.size()), weighted(terms.size()), terms_(terms) {
    const std::size_t n = terms.size();
    for (std::size_t k = 0; k < n; ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return std::make_pair(key(a), a) < std::make_pair(key(b), b); });
    // (2) no generator appears twice in combination: the first term to repeat one is named. Checked on the
    // references before (1), so that (1) recomputes each generator once.
    std::size_t twice = n, first = n;
    for (std::size_t i = 0; i + 1 < n; ++i)
      if (key(order[i]) == key(order[i + 1]) && order[i + 1] < twice) twice = order[i + 1], first = order[i];
    if (twice < n)
      throw Failure{terms[twice].ref.path() + ": " + name(terms[twice].ref.contact, terms[twice].ref.edge) +
                    " appears twice (also at " + terms[first].ref.path() + ")"};
    // (1) every reference names a generator of the scene under the reading
    std::vector<int> edge(n);
    for (std::size_t k = 0; k < n; ++k) edge[k] = check_reference(terms[k].ref, contacts, reading);
    // (3) every weight is strictly positive: by the grammar of §2, its text starts with neither '-' nor '0'
    for (const Term& t : terms)
      if (t.weight[0] == '-' || t.weight[0] == '0')
        throw Failure{t.ref.path() + ".weight: " + quote(t.weight) + " is not strictly positive"};
    // g_k and weight_k g_k = (a g.v) / (b g.d) for weight_k = a / b, each contact's generators computed once
    Generators<N> g{};
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = order[i], contact = terms[k].ref.contact;
      if (i == 0 || contact != terms[order[i - 1]].ref.contact) g = generators<N>(contacts[contact], reading, lim);
      const Int_wrench<N>& gk = generator[k] = g.w[edge[k]];
      const Frac<N> w = fraction<N>(terms[k].weight);
      weighted[k] = {{N(w.num * gk.v[0]), N(w.num * gk.v[1]), N(w.num * gk.v[2])}, N(w.den * gk.d)};
    }
  }
  // The term whose generator the reference names, or none (terms.size()).
  std::size_t find(const Ref& ref) const {
    const auto at = std::lower_bound(order.begin(), order.end(), std::make_pair(ref.contact, ref.edge),
                                     [&](std::size_t k, const std::pair<std::size_t, std::string_view>& x) { return key(k) < x; });
    return at != order.end() && key(*at) == std::make_pair(ref.contact, ref.edge) ? *at : terms_.size();
  }

 private:
  std::pair<std::size_t, std::string_view> key(std::size_t k) const { return {terms_[k].ref.contact, terms_[k].ref.edge}; }
  const std::vector<Term>& terms_;
};

// The sum of integer wrenches (not empty) is (0, 0, 0); else the failure `what` + the sum + ", not (0, 0, 0)".
template <class N>
void zero_sum(std::vector<Int_wrench<N>> terms, const std::string& what) {
  const Int_wrench<N> total = tree_sum(std::move(terms));
  if (sgn(total.v[0]) != 0 || sgn(total.v[1]) != 0 || sgn(total.v[2]) != 0)
    throw Failure{what + show(total) + ", not (0, 0, 0)"};
}

// §3.1, theory [FC-2]. With S the generators of `combination`: (3) and (4) give, for every g_j in S,
// -g_j = sum_{k != j} (l_k / l_j) g_k in pos(S), so pos(S) is a linear subspace; (5) makes it
// 3-dimensional, so W contains pos(S) = R^3.
// §3.3, theory [EQ-1], when `load` is w_ext: (1)-(3) as above and (4') sum_k l_k g_k + w_ext = 0, so
// -w_ext = sum_k l_k g_k is in W: the contact forces l_k (force of g_k) balance the load. There is no
// (5), and the combination may be empty (then w_ext must be zero).
template <class N>
void check_positive(const Certificate& c, const std::vector<Contact>& contacts, const Limits& lim,
                    const Int_wrench<N>* load) {
  Combination<N> terms(c.combination, contacts, c.reading, lim);
  for (const Ref& ref : c.independent) check_reference(ref, contacts, c.reading);
  // (4) sum_k weight_k g_k (+ w_ext) = (0, 0, 0) exactly: the numerator of the sum over the product of
  // the (positive) denominators is zero.
  if (load) terms.weighted.push_back(*load);  // not empty: combination is not, or there is a load
  zero_sum(std::move(terms.weighted), std::string("combination: the weighted sum of the generators ") + (load ? "plus the load " : "") + "is ");
  if (load) return;
  // (5) the three independent generators are in combination, and their determinant is not zero
  std::size_t row[3];
  for (std::size_t r = 0; r < 3; ++r)
    if ((row[r] = terms.find(c.independent[r])) == c.combination.size())
      throw Failure{c.independent[r].path() + ": " + name(c.independent[r].contact, c.independent[r].edge) + " is not in combination"};
  if (sgn(det3(terms.generator[row[0]], terms.generator[row[1]], terms.generator[row[2]])) == 0)
    throw Failure{"independent: the three generators are linearly dependent (determinant 0)"};
}

// Rule (2) of §3.2: <t, g> >= 0 for every generator g of the scene under the reading (the motion t is allowed by
// every contact), for t = T / T.d: the sign is that of the numerators' power.
template <class N>
void allowed_by_every_contact(const Int_wrench<N>& t, const std::vector<Contact>& contacts, Reading reading,
                              const Limits& lim, const std::string& prefix) {
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Generators<N> g = generators<N>(contacts[i], reading, lim);
    for (int k = 0; k < g.count; ++k) {
      const N p = power(t, g.w[k]);
      if (sgn(p) < 0)
        throw Failure{prefix + "twist: power " + show(value(to_z(p), to_z(N(t.d * g.w[k].d)))) + " against " + name(i, g.edge[k])};
    }
  }
}

// Rule (3) of §3.2: the reading, if present, is P(t) = (-vy, vx, w) on the two-sided plane, t = T / T.d.
template <class N>
void check_reading(const Certificate& c, const Int_wrench<N>& T) {
  if (!c.keys.count("reading")) return;
  const auto t = [&c](int k) { return rational_value(c.twist[k]); };  // (the values, for messages)
  const auto where = [&c] { return show(rational_value(c.where[0]), rational_value(c.where[1])); };
  const N &vx = T.v[0], &vy = T.v[1], &w = T.v[2];
  const std::string label = sgn(w) > 0 ? "+" : sgn(w) < 0 ? "-" : "infinity";
  if (c.label != label)
    throw Failure{"reading.label: " + quote(c.label) + " does not match the twist, whose label is " + quote(label)};
  const Frac<N> p[2] = {fraction<N>(c.where[0]), fraction<N>(c.where[1])};
  if (sgn(w) != 0) {  // the rotation centre (-vy/w, vx/w)
    if (sgn(N(p[0].num * w + vy * p[0].den)) != 0 || sgn(N(p[1].num * w - vx * p[1].den)) != 0)
      throw Failure{"reading.point: " + where() + " is not the rotation centre " + show(Q(-t(1) / t(2)), Q(t(0) / t(2))) +
                    " of the twist"};
  } else {  // d = (-vy, vx) != 0 as t != 0; e is a positive multiple of d iff d x e = 0 and d . e > 0
    const N e[2] = {N(p[0].num * p[1].den), N(p[1].num * p[0].den)};  // (a positive multiple of the point)
    if (sgn(N(-vy * e[1] - vx * e[0])) != 0 || sgn(N(vx * e[1] - vy * e[0])) <= 0)
      throw Failure{"reading.direction: " + where() + " is not a positive multiple of (-vy, vx) = " + show(Q(-t(1)), t(0))};
  }
}

// §3.2, theory [FC-3]. Every x in W is sum mu_g g with mu >= 0, so <t, x> >= 0, while <t, -t> < 0:
// the wrench -t is not in W, and W != R^3.
// §3.3, theory [EQ-1], when `load` is w_ext: also <t, w_ext> > 0, so <t, -w_ext> < 0 <= <t, x> for every
// x in W: -w_ext is not in W, and no admissible contact forces balance the load.
template <class N>
void check_negative(const Certificate& c, const std::vector<Contact>& contacts, const Limits& lim,
                    const Int_wrench<N>* load) {
  const Int_wrench<N> t = integer_form<N>(c.twist);
  // (1) the twist is not zero
  if (sgn(t.v[0]) == 0 && sgn(t.v[1]) == 0 && sgn(t.v[2]) == 0) throw Failure{"twist: the zero twist proves nothing"};
  // (2) <t, g> >= 0 for every generator g of the scene under the reading
  allowed_by_every_contact(t, contacts, c.reading, lim, "");
  // (2') equilibrium: <t, w_ext> > 0
  if (load && sgn(power(t, *load)) <= 0)
    throw Failure{"twist: power against the load is " + show(value(to_z(power(t, *load)), to_z(N(t.d * load->d)))) + ", not > 0"};
  // (3) the reading, if present, is P(t) = (-vy, vx, w) on the two-sided plane
  check_reading(c, t);
}

// ---------------------------------------------------------------------------------------------
// Sliding certificates (certificate-format.md §6; docs/theory-sliding.md §2-§3; proofs/notes/SL-1)

// "(a, b, c, ...)" for a message, at most 8 entries shown.
std::string show_list(const std::vector<Q>& v) {
  std::string s = "(";
  for (std::size_t i = 0; i < v.size() && i < 8; ++i) s += (i ? ", " : "") + show(v[i]);
  if (v.size() > 8) s += ", ... (" + std::to_string(v.size()) + " entries)";
  return s + ")";
}
std::string point_name(std::size_t i) { return "support.points[" + std::to_string(i) + "]"; }

// The support's blocks of the sliding (§6) and hold (§7) certificates, checked the same way for both: a
// distribution in F, support forces in their friction discs and their wrench, a bound on the frictional power
// of a twist (rational speed bounds; for every distribution, with the LP dual over F), and the vertices of F.
class Support_blocks {
 public:
  Support_blocks(const Support& s, const Limits& lim) : s_(s), lim_(lim) {}

  // --- Region blocks (certificate-format.md §6.4, proofs/notes/RG-1): the shared checks of a region's part of a
  // stick or slide witness.

  // The cells of b tile g: every cell counter-clockwise with positive area, and the sum of the cells' oriented
  // boundaries equals the region's oriented boundary as 1-chains (on each supporting line, the multiplicity of
  // every piece between endpoints is zero; collinear overlapping segments cancel). Then the cells' indicators
  // sum to the region's almost everywhere (RG-1 §2).
  static void check_tiling(const Region& g, const Block& b) {
    struct Event {
      int vertical;
      Q a, b, t;  // the line (y = a x + b, or x = a) and the parameter (x, or y)
      int delta;
    };
    std::vector<Event> events;
    const auto segment = [&](const P2& p, const P2& q, int w) {
      if (p.x != q.x) {
        const Q slope = (q.y - p.y) / (q.x - p.x), icpt = p.y - slope * p.x;
        const int dir = q.x > p.x ? w : -w;
        const Q& lo = q.x > p.x ? p.x : q.x;
        const Q& hi = q.x > p.x ? q.x : p.x;
        events.push_back({0, slope, icpt, lo, dir});
        events.push_back({0, slope, icpt, hi, -dir});
      } else {
        const int dir = q.y > p.y ? w : -w;
        const Q& lo = q.y > p.y ? p.y : q.y;
        const Q& hi = q.y > p.y ? q.y : p.y;
        events.push_back({1, p.x, Q(0), lo, dir});
        events.push_back({1, p.x, Q(0), hi, -dir});
      }
    };
    for (std::size_t k = 0; k < b.triangles.size(); ++k) {
      const auto& t = b.triangles[k];
      const std::string at = b.path + ".triangles[" + std::to_string(k) + "]";
      for (const std::size_t v : t)
        if (v >= b.vertices.size())
          throw Failure{at + ": vertex index " + (v == SIZE_MAX ? std::string("(huge)") : std::to_string(v)) +
                        " out of range (" + std::to_string(b.vertices.size()) + " vertices)"};
      const P2 &p = b.vertices[t[0]], &q = b.vertices[t[1]], &r = b.vertices[t[2]];
      if (orient(p, q, r) <= 0) throw Failure{at + ": not counter-clockwise with a positive area"};
      segment(p, q, 1), segment(q, r, 1), segment(r, p, 1);
    }
    for (const auto& ring : g.rings)
      for (std::size_t i = 0; i < ring.size(); ++i) segment(ring[i], ring[(i + 1) % ring.size()], -1);
    std::sort(events.begin(), events.end(), [](const Event& x, const Event& y) {
      if (x.vertical != y.vertical) return x.vertical < y.vertical;
      if (x.a != y.a) return x.a < y.a;
      if (x.b != y.b) return x.b < y.b;
      return x.t < y.t;
    });
    int sum = 0;
    for (std::size_t i = 0; i < events.size(); ++i) {
      sum += events[i].delta;
      const bool last_at_t = i + 1 == events.size() || events[i + 1].vertical != events[i].vertical ||
                             events[i + 1].a != events[i].a || events[i + 1].b != events[i].b || events[i + 1].t != events[i].t;
      if (last_at_t && sum != 0)
        throw Failure{b.path + ": the cells do not tile " + g.path + " (their boundaries do not add up to the region's "
                      "boundary: a cell outside it, a gap, an overlap or a hole covered)"};
    }
  }

  // A stick block: |g_k|^2 < (mu F_k)^2 (g_k = 0 where mu F_k = 0), F_k = area p(centroid); adds sum_k (g_k, c_k x g_k)
  // to `sum` (c_k = M_k / F_k the cell's pressure centroid, M_k its integral of r p by the edge-midpoint rule) and
  // calls friction(c_k) for every cell with mu F_k > 0.
  // `strict` as support_sum's: a stick (|g_k|^2 < (mu F_k)^2) or a hold (|g_k|^2 <= (mu F_k)^2, closed discs).
  template <class Friction>
  static void add_stick_block(const Region& g, const Block& b, std::array<Q, 3>& sum, Friction friction, bool strict) {
    if (b.forces.size() != b.triangles.size())
      throw Failure{b.path + ".forces: " + std::to_string(b.forces.size()) + " forces for " +
                    std::to_string(b.triangles.size()) + " cells"};
    check_tiling(g, b);
    for (std::size_t k = 0; k < b.triangles.size(); ++k) {
      const auto& t = b.triangles[k];
      const P2 &p = b.vertices[t[0]], &q = b.vertices[t[1]], &r = b.vertices[t[2]];
      const Q area = Q((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x)) / 2;
      const P2 m[3] = {{(p.x + q.x) / 2, (p.y + q.y) / 2}, {(q.x + r.x) / 2, (q.y + r.y) / 2}, {(r.x + p.x) / 2, (r.y + p.y) / 2}};
      Q F = 0, M[2] = {0, 0};
      for (const P2& x : m) {
        const Q pm = pressure(g.c, x);
        F += pm, M[0] += x.x * pm, M[1] += x.y * pm;
      }
      F *= area / 3, M[0] *= area / 3, M[1] *= area / 3;
      const Pair& f = b.forces[k];
      const Q lhs = f[0] * f[0] + f[1] * f[1], rho = g.mu * F;
      const bool inside = strict ? (sgn(rho) == 0 ? sgn(lhs) == 0 : lhs < rho * rho) : lhs <= rho * rho;
      if (!inside)
        throw Failure{b.path + ".forces[" + std::to_string(k) + "]: |g|^2 = " + show(lhs) + " is not " +
                      (strict ? "less than" : "at most") + " (mu F)^2 = " + show(Q(rho * rho)) +
                      (sgn(rho) == 0 ? " (no friction there: g must be 0)" : "")};
      if (sgn(rho) == 0) continue;
      sum[0] += f[0], sum[1] += f[1], sum[2] += (M[0] * f[1] - M[1] * f[0]) / F;
      friction(Q(M[0] / F), Q(M[1] / F));
    }
  }

  // A slide block: u_j >= 0 and u_j^2 >= |v_j(q)|^2 at every vertex; returns mu sum_cells sum_j w_j u_j with
  // w_j = area (p_j + p_a + p_b + p_c)/12, the integral of the barycentric coordinate j times p (|v| is convex and
  // p >= 0, so the integral of |v| p over the region is at most this).
  static Q slide_block_bound(const Region& g, const Block& b, const Q (&q)[3]) {
    if (b.speeds.size() != b.vertices.size())
      throw Failure{b.path + ".speed_bounds: " + std::to_string(b.speeds.size()) + " bounds for " +
                    std::to_string(b.vertices.size()) + " vertices"};
    check_tiling(g, b);
    for (std::size_t j = 0; j < b.vertices.size(); ++j) {
      const P2& v = b.vertices[j];
      const Q vx = q[0] - q[2] * v.y, vy = q[1] + q[2] * v.x, speed2 = vx * vx + vy * vy;
      const Q& u = b.speeds[j];
      if (sgn(u) < 0) throw Failure{b.path + ".speed_bounds[" + std::to_string(j) + "]: " + show(u) + " is negative"};
      if (u * u < speed2)
        throw Failure{b.path + ".speed_bounds[" + std::to_string(j) + "]: u^2 = " + show(Q(u * u)) +
                      " is less than |v(q)|^2 = " + show(speed2)};
    }
    std::vector<Q> terms;
    terms.reserve(b.triangles.size());
    for (const auto& t : b.triangles) {
      const P2 &p = b.vertices[t[0]], &q2 = b.vertices[t[1]], &r = b.vertices[t[2]];
      const Q area = Q((q2.x - p.x) * (r.y - p.y) - (q2.y - p.y) * (r.x - p.x)) / 2;
      const Q pv[3] = {pressure(g.c, p), pressure(g.c, q2), pressure(g.c, r)};
      const Q all = pv[0] + pv[1] + pv[2];
      Q cell = 0;
      for (int j = 0; j < 3; ++j) cell += (pv[j] + all) * b.speeds[t[static_cast<std::size_t>(j)]];
      terms.push_back(cell * area / 12);
    }
    return g.mu * tree_sum(std::move(terms));
  }


  // The scene's forces (0 where unknown).
  std::vector<Q> given() const {
    std::vector<Q> f;
    f.reserve(s_.points.size());
    Point_values scratch;
    for (const Support_point& p : s_.points) f.push_back(values(p, lim_, scratch).f);
    return f;
  }

  // f is in F: one entry per point, f >= 0, f_i the given force where given, sum f = W, sum f r = W c.
  void in_f(const std::vector<Q>& f, const std::string& path) const {
    size(f.size(), path);
    Q sum = 0, moment[2] = {0, 0};
    for (std::size_t i = 0; i < f.size(); ++i) {
      Point_values scratch;
      const Point_values& v = values(s_.points[i], lim_, scratch);
      const auto at = [&] { return path + "[" + std::to_string(i) + "]: "; };  // (built only for a failure)
      if (sgn(f[i]) < 0) throw Failure{at() + show(f[i]) + " is negative"};
      if (s_.points[i].known && f[i] != v.f)
        throw Failure{at() + show(f[i]) + " is not the given force " + show(v.f) + " of " + point_name(i)};
      sum += f[i], moment[0] += f[i] * v.x, moment[1] += f[i] * v.y;
    }
    Q regions = 0;
    for (const Region& g : s_.regions) regions += g.W, moment[0] += g.M[0], moment[1] += g.M[1];  // a known pressure
    sum += regions;
    if (sum != s_.W)
      throw Failure{path + ": the forces sum to " + show(sum) +
                    (s_.regions.empty() ? std::string() : " with the regions' " + show(regions)) + ", not the weight " +
                    show(s_.W)};
    const Q wc[2] = {s_.W * s_.c[0], s_.W * s_.c[1]};
    if (moment[0] != wc[0] || moment[1] != wc[1])
      throw Failure{path + ": sum f_i r_i is " + show(moment[0], moment[1]) + ", not W c = " + show(wc[0], wc[1]) +
                    " (the centre of pressure is not " + show(s_.c[0], s_.c[1]) + ")"};
  }

  void size(std::size_t n, const std::string& path) const {
    if (n != s_.points.size())
      throw Failure{path + ": " + std::to_string(n) + " entries, but the support has " +
                    std::to_string(s_.points.size()) + " points"};
  }

  // Support forces g_i under f, each in its friction disc, and their wrench sum (g_i, r_i x g_i).
  // `strict` (a stick, §6): p in the INTERIOR of LS(f) (a load on the limit surface slides, docs/theory.md §11):
  // |g_i|^2 < (mu_i f_i)^2 where mu_i f_i > 0, g_i = 0 where it is 0, and LS(f) is three-dimensional (two distinct
  // points with mu_i f_i > 0), so the sum of the discs' relative interiors is its interior (SL-1). Not strict (a
  // hold, §7): |g_i|^2 <= (mu_i f_i)^2, the closed discs (so g_i = 0 where mu_i f_i = 0), any number of points.
  // With `blocks` (one per support region, certificate-format.md §6.4), each region's cells add their forces,
  // acting at the cells' pressure centroids, inside their discs as the points' are.
  std::array<Q, 3> support_sum(const std::vector<Q>& f, const std::vector<Pair>& g, const std::string& path,
                               bool strict, const std::vector<Block>* blocks = nullptr) const {
    size(g.size(), path);
    std::array<Q, 3> sum{0, 0, 0};
    bool two = false, one = false;
    Q ax, ay;
    const auto friction_at = [&](const Q& x, const Q& y) {
      if (!strict || two) return;  // (only a stick asks for two distinct points)
      if (one && (x != ax || y != ay)) two = true;
      if (!one) one = true, ax = x, ay = y;
    };
    for (std::size_t i = 0; i < g.size(); ++i) {
      Point_values scratch;
      const Point_values& v = values(s_.points[i], lim_, scratch);
      if (sgn(g[i][0]) == 0 && sgn(g[i][1]) == 0) {  // g_i = 0: in its disc (mu_i f_i >= 0), adds nothing to the sum
        if (sgn(v.mu) > 0 && sgn(f[i]) > 0) friction_at(v.x, v.y);
        continue;
      }
      const Q lhs = g[i][0] * g[i][0] + g[i][1] * g[i][1], bound = v.mu * f[i];
      const bool inside = strict ? (sgn(bound) == 0 ? sgn(lhs) == 0 : lhs < bound * bound) : lhs <= bound * bound;
      if (!inside)
        throw Failure{path + "[" + std::to_string(i) + "]: |g|^2 = " + show(lhs) + " is not " +
                      (strict ? "less than" : "at most") + " (mu f)^2 = " + show(Q(bound * bound)) +
                      (sgn(bound) == 0 ? " (no friction there: g must be 0)" : "")};
      if (sgn(bound) > 0) friction_at(v.x, v.y);
      sum[0] += g[i][0], sum[1] += g[i][1], sum[2] += v.x * g[i][1] - v.y * g[i][0];
    }
    if (blocks)  // each region's cells: forces spread over the cell as p, acting at its pressure centroid
      for (std::size_t k = 0; k < blocks->size(); ++k)
        add_stick_block(s_.regions[k], (*blocks)[k], sum, friction_at, strict);
    if (strict && !two)
      throw Failure{path + ": friction acts at fewer than two distinct points, so the limit surface is flat and no "
                           "load is inside it"};
    return sum;
  }

  // A bound on the frictional power h_f(q) = sum mu_i f_i |v_i(q)| from the rational speed bounds u_i >= 0,
  // u_i^2 >= |v_i(q)|^2: sum mu_i f_i u_i for the distribution f, or, with a dual (every f in F),
  // sum_known mu_i f_i u_i + y0 W' + yx M'x + yy M'y where mu_i u_i <= y0 + y.r_i for every unknown i.
  // With `blocks`, each region's bound mu_R sum_cells sum_j w_j u_j (certificate-format.md §6.4) is added.
  Q friction_bound(const std::vector<Q>& f, const Q (&q)[3], const std::vector<Q>& u, const std::string& prefix,
                   const Q* dual, const std::vector<Block>* blocks = nullptr) const {
    const std::string path = prefix + "speed_bounds";
    size(u.size(), path);
    Q bound = 0;
    for (std::size_t i = 0; i < u.size(); ++i) {
      Point_values scratch;
      const Point_values& v = values(s_.points[i], lim_, scratch);
      const auto at = [&] { return path + "[" + std::to_string(i) + "]: "; };  // (built only for a failure)
      if (sgn(u[i]) < 0) throw Failure{at() + show(u[i]) + " is negative"};
      const Q vx = q[0] - q[2] * v.y, vy = q[1] + q[2] * v.x, speed2 = vx * vx + vy * vy;
      if (u[i] * u[i] < speed2)
        throw Failure{at() + "u^2 = " + show(Q(u[i] * u[i])) + " is less than |v_i(q)|^2 = " + show(speed2)};
      const Q mu_u = v.mu * u[i];
      if (!dual || s_.points[i].known) {
        bound += mu_u * f[i];
      } else if (mu_u > dual[0] + dual[1] * v.x + dual[2] * v.y) {
        throw Failure{"dual: mu_i u_i = " + show(mu_u) + " is more than y0 + yx x_i + yy y_i = " +
                      show(Q(dual[0] + dual[1] * v.x + dual[2] * v.y)) + " at " + point_name(i)};
      }
    }
    if (dual) bound += dual[0] * s_.rest_weight + dual[1] * s_.rest_moment[0] + dual[2] * s_.rest_moment[1];
    if (blocks)  // each region's bound on mu times the integral of |v| p
      for (std::size_t k = 0; k < blocks->size(); ++k) bound += slide_block_bound(s_.regions[k], (*blocks)[k], q);
    return bound;
  }

  // Every vertex of F is one of `distributions` (each already checked to be in F). The vertices are the basic
  // feasible solutions of the three rows (1, x_i, y_i) over the unknown forces (SL-1 §3): a vertex's support S
  // (its positive unknown forces) has linearly independent columns, so |S| <= 3 and the vertex is the unique
  // solution on S. `what` names the list in messages ("vertices").
  void vertices_covered(const std::vector<const std::vector<Q>*>& distributions, const std::string& what) const {
    // Each distribution's unknown support (when at most 3 points) names the vertex it can be.
    std::map<std::vector<std::size_t>, std::size_t> by_support;
    for (std::size_t w = 0; w < distributions.size(); ++w) {
      const std::vector<Q>& d = *distributions[w];
      std::vector<std::size_t> support;
      for (std::size_t i = 0; i < d.size() && support.size() <= 3; ++i)
        if (!s_.points[i].known && sgn(d[i]) > 0) support.push_back(i);
      if (support.size() <= 3) by_support.emplace(support, w);
    }
    std::vector<std::size_t> unknown;  // indices of the points without a given force
    for (std::size_t i = 0; i < s_.points.size(); ++i)
      if (!s_.points[i].known) unknown.push_back(i);
    const unsigned long long n = unknown.size();
    const unsigned long long bases =  // no overflow: n is at most max_contacts, capped here at 10^6
        n > 1000000 ? ULLONG_MAX : n + n * (n - 1) / 2 + n * (n - 1) * (n - 2) / 6;
    if (bases > lim_.max_vertex_bases)
      throw Failure{what + ": too large to check: " + std::to_string(n) + " points without a given force give " +
                    std::to_string(bases) + " candidate bases (limit " + std::to_string(lim_.max_vertex_bases) + ")"};
    const std::vector<Q> base = given();
    // A vertex with unknown support S and values x_S: it must be some witness's distribution.
    auto covered = [&](const std::vector<std::size_t>& S, const std::vector<Q>& x) {
      std::vector<Q> f = base;
      for (std::size_t k = 0; k < S.size(); ++k) f[S[k]] = x[k];
      const auto at = by_support.find(S);
      if (at == by_support.end() || *distributions[at->second] != f)
        throw Failure{what + ": the vertex " + show_list(f) + " of the admissible distributions has no witness"};
    };
    if (s_.rest_weight == 0) return covered({}, {});  // F = {given forces, 0 elsewhere}: one vertex
    // Integer columns a_i = D_i (1, x_i, y_i) and b = B (W', M'): positive scalings, so the signs of
    // the solutions are those of the true ones (x_i = D_i x'_i / B).
    std::vector<std::array<Z, 3>> a;
    std::vector<Point_values> pt;
    for (const std::size_t i : unknown) {
      Point_values scratch;
      pt.push_back(values(s_.points[i], lim_, scratch));
      const Q &x = pt.back().x, &y = pt.back().y;
      a.push_back({Z(x.get_den() * y.get_den()), Z(x.get_num() * y.get_den()), Z(y.get_num() * x.get_den())});
    }
    const Int_wrench<Z> bw = integer_form<Z>({s_.rest_weight, s_.rest_moment[0], s_.rest_moment[1]});
    const Z(&b)[3] = bw.v;
    auto cross = [](const std::array<Z, 3>& u, const std::array<Z, 3>& v) {
      return std::array<Z, 3>{Z(u[1] * v[2] - u[2] * v[1]), Z(u[2] * v[0] - u[0] * v[2]), Z(u[0] * v[1] - u[1] * v[0])};
    };
    auto dot_b = [&b](const std::array<Z, 3>& v) { return Z(b[0] * v[0] + b[1] * v[1] + b[2] * v[2]); };
    const Q cx = s_.rest_moment[0] / s_.rest_weight, cy = s_.rest_moment[1] / s_.rest_weight;  // c' = M'/W'
    // |S| = 1: r_i = c', x_i = W'.
    for (std::size_t p = 0; p < n; ++p)
      if (pt[p].x == cx && pt[p].y == cy) covered({unknown[p]}, {s_.rest_weight});
    // |S| = 2: r_i != r_j and c' strictly between them: b . (a_i x a_j) = 0 (b in their span) and the
    // two coordinates of b in the basis have the sign of |a_i x a_j|^2 > 0.
    std::vector<std::vector<std::array<Z, 3>>> c(n, std::vector<std::array<Z, 3>>(n));  // c[i][j] = a_i x a_j, i < j
    std::vector<std::vector<Z>> beta(n, std::vector<Z>(n));                               // b . c[i][j]
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        c[i][j] = cross(a[i], a[j]), beta[i][j] = dot_b(c[i][j]);
        if (c[i][j][0] == 0 && c[i][j][1] == 0 && c[i][j][2] == 0) continue;  // coincident points
        if (beta[i][j] != 0) continue;
        const std::array<Z, 3> bz{b[0], b[1], b[2]};
        if (sgn(Z(dot3(cross(bz, a[j]), c[i][j]))) <= 0 || sgn(Z(dot3(cross(a[i], bz), c[i][j]))) <= 0) continue;
        // t = x_j: (c' - r_i) = t/W' (r_j - r_i), read on the larger coordinate difference
        const Q dx = pt[j].x - pt[i].x, dy = pt[j].y - pt[i].y;
        const Q t = dx != 0 ? Q(s_.rest_weight * (cx - pt[i].x) / dx) : Q(s_.rest_weight * (cy - pt[i].y) / dy);
        covered({unknown[i], unknown[j]}, {Q(s_.rest_weight - t), t});
      }
    // |S| = 3: D = det[a_i a_j a_k] = a_i . (a_j x a_k) != 0; by Cramer the coordinates of b are
    // (b.(a_j x a_k), b.(a_k x a_i), b.(a_i x a_j)) / D, all > 0.
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        for (std::size_t k = j + 1; k < n; ++k) {
          const Z D = dot3(a[i], c[j][k]);
          const int sd = sgn(D);
          if (sd == 0 || sgn(beta[j][k]) != sd || -sgn(beta[i][k]) != sd || sgn(beta[i][j]) != sd) continue;
          const Z B = bw.d;
          auto value = [&](std::size_t p, const Z& num) {  // x_p = D_p (num / D) / B
            Q x(Z(a[p][0] * num), Z(D * B));
            x.canonicalize();
            return x;
          };
          covered({unknown[i], unknown[j], unknown[k]},
                  {value(i, beta[j][k]), value(j, Z(-beta[i][k])), value(k, beta[i][j])});
        }
  }


  static Z dot3(const std::array<Z, 3>& u, const std::array<Z, 3>& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

 private:
  const Support& s_;
  const Limits& lim_;
};

class Motion_check {
 public:
  Motion_check(const Certificate& c, const Support& s, const Limits& lim)
      : c_(c), m_(members(c)), b_(s, lim), s_(s) {
    for (int k = 0; k < 3; ++k) twist_[k] = rational_value(c.twist[k]);
  }

  void run() {
    const bool known = s_.unknown == 0;
    const bool regions = !s_.regions.empty();
    // Format 2 (§6.5): regions together with a force not given; each witness carries its own regions' blocks
    // (sticks: every vertex witness's stick blocks; depends: the sticking one's stick blocks and the sliding one's
    // slide blocks); "slides" keeps them at the top level, with the dual.
    const bool per_witness = regions && !known;
    if (per_witness && c_.version < 2)
      throw Failure{"motion: a support with regions and points whose force is not given has no certificate in format 1"};
    for (const Witness* w : {&m_.sticking, &m_.sliding}) witness_regions(*w, per_witness);
    for (const Witness& w : m_.vertices) witness_regions(w, per_witness);
    if (c_.claim == "depends" && known)
      throw Failure{"motion: \"depends\" needs a support with an unknown distribution (every force is given)"};
    std::set<std::string> allowed;
    if (c_.claim == "sticks") allowed = known ? std::set<std::string>{"support_forces"} : std::set<std::string>{"vertices"};
    if (c_.claim == "slides")
      allowed = known ? std::set<std::string>{"twist", "speed_bounds"} : std::set<std::string>{"twist", "speed_bounds", "dual"};
    if (c_.claim == "depends") allowed = {"sticking", "sliding"};
    if (regions && (known || c_.claim == "slides")) allowed.insert("regions");
    const char* const keys[] = {"support_forces", "twist", "speed_bounds", "dual", "vertices", "sticking", "sliding",
                                "regions"};
    for (const char* key : keys)
      if (!allowed.count(key) && c_.keys.count(key))
        throw Failure{std::string("key \"") + key + "\" is not allowed when \"motion\" is " + quote(c_.claim) +
                      (std::string(key) == "regions" ? (regions ? " at the top level (format 2: inside each witness)"
                                                                : " and the support has no regions")
                       : known                       ? " and every support force is given"
                                                     : " and some support force is unknown")};
    for (const char* key : keys)
      if (allowed.count(key) && !c_.keys.count(key)) throw Failure{std::string("missing required key \"") + key + "\""};
    const bool top = allowed.count("regions") > 0;  // the regions' blocks at the top level
    if (top && m_.regions.size() != s_.regions.size())
      throw Failure{"regions: " + std::to_string(m_.regions.size()) + " blocks, but the support has " +
                    std::to_string(s_.regions.size()) + " regions"};
    const std::vector<Block>* blocks = top ? &m_.regions : nullptr;
    if (c_.claim == "sticks" && known) return stick(b_.given(), m_.support_forces, "support_forces", blocks);
    if (c_.claim == "slides" && known) return slide(b_.given(), twist_, m_.speed_bounds, "", nullptr, blocks);
    if (c_.claim == "slides") return slide(b_.given(), twist_, m_.speed_bounds, "", m_.dual, blocks);
    if (c_.claim == "depends") {
      b_.in_f(m_.sticking.distribution, m_.sticking.path + ".distribution");
      stick(m_.sticking.distribution, m_.sticking.forces, m_.sticking.path + ".support_forces", own_blocks(m_.sticking));
      b_.in_f(m_.sliding.distribution, m_.sliding.path + ".distribution");
      return slide(m_.sliding.distribution, m_.sliding.twist, m_.sliding.speeds, m_.sliding.path + ".", nullptr,
                   own_blocks(m_.sliding));
    }
    sticks_for_every();
  }

 private:
  // A witness's own "regions" (format 2, §6.5): required, one block per region, where regions meet a force not
  // given; an unknown key elsewhere.
  void witness_regions(const Witness& w, bool required) const {
    if (w.path.empty()) return;  // not present
    if (!required && w.has_regions) throw Failure{w.path + ": unknown key \"regions\""};
    if (!required) return;
    if (!w.has_regions) throw Failure{w.path + ": missing required key \"regions\""};
    if (w.regions.size() != s_.regions.size())
      throw Failure{w.path + ".regions: " + std::to_string(w.regions.size()) + " blocks, but the support has " +
                    std::to_string(s_.regions.size()) + " regions"};
  }
  static const std::vector<Block>* own_blocks(const Witness& w) { return w.has_regions ? &w.regions : nullptr; }

  // Sticks under f: the support forces strictly inside their discs (and the regions' cell forces, with `blocks`)
  // carry the load p exactly (SL-1, RG-1).
  void stick(const std::vector<Q>& f, const std::vector<Pair>& g, const std::string& path,
             const std::vector<Block>* blocks = nullptr) const {
    const std::array<Q, 3> sum = b_.support_sum(f, g, path, true, blocks);
    if (sum[0] != m_.load[0] || sum[1] != m_.load[1] || sum[2] != m_.load[2])
      throw Failure{path + ": the support forces give the load (" + show(sum[0]) + ", " + show(sum[1]) + ", " +
                    show(sum[2]) + "), not (" + show(m_.load[0]) + ", " + show(m_.load[1]) + ", " +
                    show(m_.load[2]) + ")"};
  }

  // Slides: p not in the interior of LS(f) (on or past the limit surface): q != 0 and q.p >= the bound on the
  // frictional power h_f(q) (the regions' bounds included, with `blocks`).
  void slide(const std::vector<Q>& f, const Q (&q)[3], const std::vector<Q>& u, const std::string& prefix,
             const Q* dual, const std::vector<Block>* blocks = nullptr) const {
    b_.size(u.size(), prefix + "speed_bounds");
    if (sgn(q[0]) == 0 && sgn(q[1]) == 0 && sgn(q[2]) == 0) throw Failure{prefix + "twist: the zero twist"};
    const Q bound = b_.friction_bound(f, q, u, prefix, dual, blocks);
    const Q power = q[0] * m_.load[0] + q[1] * m_.load[1] + q[2] * m_.load[2];
    if (power < bound)
      throw Failure{prefix + "twist: power q.p = " + show(power) + " is less than " +
                    (dual ? "the dual bound " : "sum mu_i f_i u_i = ") + show(bound)};
  }

  // Sticks for every f in F: every witness is in F and sticks, and every vertex of F is the distribution of a
  // witness.
  void sticks_for_every() const {
    std::vector<const std::vector<Q>*> distributions;
    for (const Witness& v : m_.vertices) {
      b_.in_f(v.distribution, v.path + ".distribution");
      stick(v.distribution, v.forces, v.path + ".support_forces", own_blocks(v));
      distributions.push_back(&v.distribution);
    }
    b_.vertices_covered(distributions, "vertices");
  }

  const Certificate& c_;
  const Motion_part& m_;
  Q twist_[3];
  Support_blocks b_;
  const Support& s_;
};

// Property "motion" (§6).
void check_motion(const Certificate& c, const Scene& scene, const Limits& lim) {
  for (const char* key : {"load", "motion"})
    if (!c.keys.count(key)) throw Failure{std::string("missing required key \"") + key + "\""};
  for (const char* key : {"holds", "combination", "independent", "reading", "holding", "failing"})
    if (c.keys.count(key)) throw Failure{std::string("key \"") + key + "\" is not allowed when \"property\" is \"motion\""};
  if (c.motion_members) {
    for (const Witness* w : {&c.motion_members->sticking})
      if (w->has_combination) throw Failure{w->path + ": unknown key \"combination\""};
    for (const Witness& w : c.motion_members->vertices)
      if (w.has_combination) throw Failure{w.path + ": unknown key \"combination\""};
  }
  if (!scene.support) throw Failure{"property: \"motion\" needs a scene with a support"};
  Motion_check(c, *scene.support, lim).run();
}

// Property "hold" (§7; docs/theory-sliding.md §5; proofs/notes/HD-1): the contacts (the friction generators)
// together with the support's friction hold the body against the scene's load w_L, i.e. -w_L is in W + LS(f).
// Holds: contact weights (as §3.3) and support forces in their CLOSED discs with sum lambda_k g_k +
// sum (g_i, r_i x g_i) + w_L = 0. Does not hold: a twist t with <t, g> >= 0 for every generator and
// t.w_L > the bound on the frictional power of t (strict). A scene without a support: hold is equilibrium.
class Hold_check {
 public:
  Hold_check(const Certificate& c, const Scene& scene, const Limits& lim)
      : c_(c), m_(members(c)), scene_(scene), lim_(lim), b_(scene.support ? *scene.support : no_support_, lim) {
    for (int k = 0; k < 3; ++k) twist_[k] = rational_value(c.twist[k]);
  }

  void run() {
    if (!scene_.has_load) throw Failure{"property: \"hold\" needs a scene with a load"};
    for (const char* key : {"load", "motion", "independent", "sticking", "sliding"})
      if (c_.keys.count(key)) throw Failure{std::string("key \"") + key + "\" is not allowed when \"property\" is \"hold\""};
    if (!c_.keys.count("holds")) throw Failure{"missing required key \"holds\""};
    const bool support = scene_.support.has_value(), known = !support || scene_.support->unknown == 0;
    const bool regions = support && !scene_.support->regions.empty();
    // Format 2 (§7.5): regions together with a force not given; each witness carries its own regions' blocks
    // (holds: every vertex witness's stick blocks; depends: the holding one's stick blocks and the failing one's
    // slide blocks); "holds": false keeps them at the top level, with the dual.
    const bool per_witness = regions && !known;
    if (per_witness && c_.version < 2)
      throw Failure{"holds: a support with regions and points whose force is not given has no certificate in format 1 "
                    "(format 2, \"wrenchkit_certificate\": 2)"};
    for (const Witness* w : {&m_.holding, &m_.failing})
      witness_regions(*w, per_witness);
    for (const Witness& w : m_.vertices) witness_regions(w, per_witness);
    const std::string claim = c_.depends ? "\"depends\"" : c_.holds ? "true" : "false";
    if (c_.depends && known)
      throw Failure{"holds: \"depends\" needs a support with an unknown distribution (" +
                    std::string(support ? "every force is given" : "the scene has no support") + ")"};
    std::set<std::string> allowed, optional;
    if (c_.depends) {
      allowed = {"holding", "failing"};
    } else if (c_.holds) {
      allowed = known ? std::set<std::string>{"combination"} : std::set<std::string>{"vertices"};
      if (known && support) allowed.insert("support_forces");
    } else {
      allowed = {"twist"};
      optional = {"reading"};
      if (support) allowed.insert("speed_bounds");
      if (!known) allowed.insert("dual");
    }
    if (regions && (known || (!c_.holds && !c_.depends))) allowed.insert("regions");
    const char* const keys[] = {"combination", "support_forces", "twist",   "reading", "speed_bounds",
                                "dual",        "vertices",       "holding", "failing", "regions"};
    const std::string where = !support ? " and the scene has no support"
                              : known  ? " and every support force is given"
                                       : " and some support force is unknown";
    for (const char* key : keys)
      if (!allowed.count(key) && !optional.count(key) && c_.keys.count(key))
        throw Failure{std::string("key \"") + key + "\" is not allowed when \"holds\" is " + claim +
                      (std::string(key) == "regions" ? std::string(regions ? " at the top level (format 2: inside each witness)"
                                                                           : " and the support has no regions")
                                                      : where)};
    for (const char* key : keys)
      if (allowed.count(key) && !c_.keys.count(key)) throw Failure{std::string("missing required key \"") + key + "\""};
    const bool top = allowed.count("regions") > 0;  // the regions' blocks at the top level
    if (top && m_.regions.size() != scene_.support->regions.size())
      throw Failure{"regions: " + std::to_string(m_.regions.size()) + " blocks, but the support has " +
                    std::to_string(scene_.support->regions.size()) + " regions"};
    blocks_ = top ? &m_.regions : nullptr;
    const std::vector<Q> f = support ? b_.given() : std::vector<Q>();
    if (c_.depends) {
      if (!m_.holding.has_combination) throw Failure{m_.holding.path + ": missing required key \"combination\""};
      b_.in_f(m_.holding.distribution, m_.holding.path + ".distribution");
      hold(m_.holding.distribution, m_.holding.combination, m_.holding.forces, m_.holding.path + ".",
           own_blocks(m_.holding));
      b_.in_f(m_.failing.distribution, m_.failing.path + ".distribution");
      return fail(m_.failing.distribution, m_.failing.twist, m_.failing.speeds, m_.failing.path + ".", nullptr,
                  own_blocks(m_.failing));
    }
    if (!c_.holds) {
      fail(f, twist_, m_.speed_bounds, "", known ? nullptr : m_.dual, blocks_);
      return fast_then_exact(lim_, [&](auto zero) { check_reading(c_, integer_form<decltype(zero)>(c_.twist)); });
    }
    if (known) return hold(f, c_.combination, m_.support_forces, "", blocks_);
    // Holds for every f in F: a hold witness at every vertex of F (W is a convex cone and LS is linear in f).
    std::vector<const std::vector<Q>*> distributions;
    for (const Witness& v : m_.vertices) {
      if (!v.has_combination) throw Failure{v.path + ": missing required key \"combination\""};
      b_.in_f(v.distribution, v.path + ".distribution");
      hold(v.distribution, v.combination, v.forces, v.path + ".", own_blocks(v));
      distributions.push_back(&v.distribution);
    }
    b_.vertices_covered(distributions, "vertices");
  }

 private:
  // A witness's own "regions" (format 2): required, one block per region, where regions meet a force not given;
  // an unknown key elsewhere.
  void witness_regions(const Witness& w, bool required) const {
    if (w.path.empty()) return;  // not present
    if (!required && w.has_regions) throw Failure{w.path + ": unknown key \"regions\""};
    if (!required) return;
    if (!w.has_regions) throw Failure{w.path + ": missing required key \"regions\""};
    if (w.regions.size() != scene_.support->regions.size())
      throw Failure{w.path + ".regions: " + std::to_string(w.regions.size()) + " blocks, but the support has " +
                    std::to_string(scene_.support->regions.size()) + " regions"};
  }
  const std::vector<Block>* own_blocks(const Witness& w) const { return w.has_regions ? &w.regions : nullptr; }

  // Contact weights and support forces (closed discs) that cancel the load exactly.
  void hold(const std::vector<Q>& f, const std::vector<Term>& combination, const std::vector<Pair>& g,
            const std::string& prefix, const std::vector<Block>* blocks) const {
    std::vector<Int_wrench<Z>> terms = Combination<Z>(combination, scene_.contacts, Reading::friction, lim_).weighted;
    if (scene_.support.has_value()) {
      const std::array<Q, 3> sum = b_.support_sum(f, g, prefix + "support_forces", false, blocks);
      terms.push_back(integer_form<Z>({sum[0], sum[1], sum[2]}));
    }
    terms.push_back(integer_form<Z>({scene_.load->fx, scene_.load->fy, scene_.load->m}));
    zero_sum(std::move(terms), prefix + "combination: the contact forces" +
                                   (scene_.support.has_value() ? ", the support forces" : "") + " and the load sum to ");
  }

  // A motion every contact allows that the load drives harder than the support's friction can resist.
  void fail(const std::vector<Q>& f, const Q (&t)[3], const std::vector<Q>& u, const std::string& prefix,
            const Q* dual, const std::vector<Block>* blocks) const {
    fast_then_exact(lim_, [&](auto zero) {
      allowed_by_every_contact(integer_form<decltype(zero)>(t), scene_.contacts, Reading::friction, lim_, prefix);
    });
    const Q bound = scene_.support.has_value() ? b_.friction_bound(f, t, u, prefix, dual, blocks) : Q(0);
    const Q power = t[0] * scene_.load->fx + t[1] * scene_.load->fy + t[2] * scene_.load->m;
    if (!(power > bound))
      throw Failure{prefix + "twist: power against the load t.w_L = " + show(power) + " is not more than " +
                    (!scene_.support.has_value() ? std::string("0") : (dual ? "the dual bound " : "sum mu_i f_i u_i = ") + show(bound))};
  }

  static inline const Support no_support_{};  // a scene without a support (b_ is then not used)
  const Certificate& c_;
  const Motion_part& m_;
  Q twist_[3];
  const Scene& scene_;
  const Limits& lim_;
  Support_blocks b_;
  const std::vector<Block>* blocks_ = nullptr;  // the regions' blocks (§6.4), when the support has regions
};

// The certificate against an already read scene.
Result check_certificate(const Scene& scene, std::string_view certificate_json, const Limits& limits) {
  certificate_rational_limit = std::max<std::size_t>(100000, scene.longest > (static_cast<std::size_t>(-1) - 64) / 32
                                                                 ? static_cast<std::size_t>(-1)
                                                                 : 32 * scene.longest + 64);
  try {
    Reader r(certificate_json, limits.max_depth);
    const Certificate c = read_certificate(r);
    r.finish();
    check_keys(c);
    if (c.motion) {
      check_motion(c, scene, limits);
      return {Outcome::accepted, "accepted"};
    }
    if (c.hold) {
      Hold_check(c, scene, limits).run();
      return {Outcome::accepted, "accepted"};
    }
    if (c.equilibrium && !scene.has_load) throw Failure{"property: \"equilibrium\" needs a scene with a load"};
    fast_then_exact(limits, [&](auto zero) {
      using N = decltype(zero);
      Int_wrench<N> w_ext;
      if (c.equilibrium) w_ext = integer_form<N>({scene.load->fx, scene.load->fy, scene.load->m});
      if (c.holds) check_positive(c, scene.contacts, limits, c.equilibrium ? &w_ext : nullptr);
      else check_negative(c, scene.contacts, limits, c.equilibrium ? &w_ext : nullptr);
    });
    return {Outcome::accepted, "accepted"};
  } catch (const Failure& f) {
    return {Outcome::rejected, f.message};
  } catch (const std::bad_alloc&) {
    return {Outcome::rejected, "out of memory while checking the certificate"};
  } catch (...) {
    return {Outcome::rejected, "internal error while checking the certificate"};
  }
}

// The scene, or the bad_scene result that check() gives for it.
bool read_whole_scene(std::string_view scene_json, const Limits& limits, Scene& scene, Result& bad) {
  Tally tally;  // the scene-wide budget, counted while the scene is read
  struct Counting {
    explicit Counting(Tally& t) { Tally::reading = &t; }
    ~Counting() { Tally::reading = nullptr; }
  } counting(tally);
  try {
    Reader r(scene_json, limits.max_depth);
    scene = read_scene(r, limits);
    r.finish();
    scene.longest = tally.longest;
    return true;
  } catch (const Failure& f) {
    bad = {Outcome::bad_scene, f.message};
  } catch (const std::bad_alloc&) {
    bad = {Outcome::bad_scene, "out of memory while reading the scene"};
  } catch (...) {  // not expected; check() never throws
    bad = {Outcome::bad_scene, "internal error while reading the scene"};
  }
  return false;
}

}  // namespace

Result check(std::string_view scene_json, std::string_view certificate_json, const Limits& limits) {
  Scene scene;
  Result bad;
  if (!read_whole_scene(scene_json, limits, scene, bad)) return bad;
  return check_certificate(scene, certificate_json, limits);
}

std::vector<Result> check_all(std::string_view scene_json, const std::vector<std::string_view>& certificates,
                              const Limits& limits) {
  Scene scene;
  Result bad;
  if (!read_whole_scene(scene_json, limits, scene, bad)) return std::vector<Result>(certificates.size(), bad);
  std::vector<Result> out;
  out.reserve(certificates.size());
  for (const std::string_view c : certificates) out.push_back(check_certificate(scene, c, limits));
  return out;
}

}  // namespace wrenchkit_checker
