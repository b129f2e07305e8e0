// proofs/checker/numbers.cpp - numbers: certificate rationals (certificate-format.md §2) and scene numbers
// (docs/scene-format.md "Numbers", "Limits"), read exactly; see numbers.h.
#include "proofs/checker/numbers.h"

#include <climits>

namespace wrenchkit_checker::detail {

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
Q scene_number(std::string_view s, const Limits& lim, const std::string& path, Tally* tally, bool build) {
  const Number_text n = number_text(s, lim, path);
  if (tally) tally->number(n.counted, lim);
  return build ? exact_value(n) : Q(0);
}
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
}  // namespace wrenchkit_checker::detail
