#include "exact/numbers/rational.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>

namespace wrenchkit {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Consumes [0-9]* from s at i; returns the count.
std::size_t digits(std::string_view s, std::size_t& i) {
  const std::size_t start = i;
  while (i < s.size() && is_digit(s[i])) ++i;
  return i - start;
}

Integer integer_of(std::string_view ds) {
  // ds is a non-empty digit string (already length-limited by the caller).
  return Integer(std::string(ds), 10);
}

template <std::size_t N>
std::array<Integer, N> primitive_of(std::array<Integer, N> v) {
  Integer g = 0;
  for (const Integer& x : v) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), x.get_mpz_t());
  if (g == 0) throw std::logic_error("primitive: zero vector");
  if (g != 1)
    for (Integer& x : v) mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), g.get_mpz_t());
  return v;
}

template <std::size_t N>
std::array<Integer, N> primitive_of(const std::array<Rational, N>& v) {  // clear the denominators first
  Integer l = 1;
  for (const Rational& x : v) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x.get_den_mpz_t());
  std::array<Integer, N> z;
  for (std::size_t c = 0; c < N; ++c) z[c] = v[c].get_num() * (l / v[c].get_den());
  return primitive_of(std::move(z));
}

}  // namespace

namespace {
void* gmp_allocate(std::size_t n) {
  void* p = std::malloc(n);
  if (!p) throw std::bad_alloc();
  return p;
}
void* gmp_reallocate(void* p, std::size_t, std::size_t n) {
  void* q = std::realloc(p, n);
  if (!q) throw std::bad_alloc();  // p is still valid, and still the number's storage
  return q;
}
void gmp_free(void* p, std::size_t) { std::free(p); }
}  // namespace

void use_throwing_gmp_allocation() { mp_set_memory_functions(gmp_allocate, gmp_reallocate, gmp_free); }

fl::Bounded to_bounded(const Rational& q) {
  const double v = q.get_d();  // truncation toward zero: |q − v| < ulp(v)
  if (!std::isfinite(v)) return {v, fl::Bounded::kInf};
  if (Rational(v) == q) return {v, 0.0};
  if (std::fabs(v) < fl::Bounded::kUnderflow) return {v, fl::Bounded::kInf};
  return {v, std::fabs(v) * 0x1p-51};
}

namespace {

const char* const kOverBudget = "is over the scene's budget";

// The grammar, the limits, the certified double and the exact sign of a number; the exact value
// into `out` unless `out` is null and the digits make it unnecessary (then `*exact_skipped`).
// With `tally` [BUDGET], the number's digits (as number_digits counts them) join the scene's tally, and a
// number over what the tally still allows is refused before any conversion. With no approx, out and sign
// it only validates and counts.
bool parse_impl(std::string_view s, bool json_number, const Input_limits& limits, std::string& why,
                fl::Bounded* approx, Rational* out, int* sign, Budget_tally* tally = nullptr,
                std::size_t* counted = nullptr) {
  auto fail = [&why](const char* reason) {
    why = reason;
    return false;
  };
  std::size_t i = 0;
  bool negative = false;
  if (i < s.size() && (s[i] == '-' || (!json_number && s[i] == '+'))) {
    negative = s[i] == '-';
    ++i;
  }
  const std::size_t int_start = i;
  const std::size_t int_digits = digits(s, i);
  const std::string_view int_part = s.substr(int_start, int_digits);

  // Fraction p/q (strings only).
  if (!json_number && i < s.size() && s[i] == '/') {
    if (int_digits == 0) return fail("is not a number");
    ++i;
    const std::size_t den_start = i;
    const std::size_t den_digits = digits(s, i);
    if (den_digits == 0 || i != s.size()) return fail("is not a number");
    if (int_digits + den_digits > limits.max_digits)
      return fail("has more digits than the digit limit");
    if (den_digits == static_cast<std::size_t>(std::count(s.begin() + static_cast<long>(den_start), s.end(), '0')))
      return fail("has a zero denominator");
    if (counted) *counted = int_digits + den_digits;
    if (tally && !tally->add_number(int_digits + den_digits, limits)) return fail(kOverBudget);
    if (!approx && !out && !sign) return true;
    Rational q(integer_of(int_part), integer_of(s.substr(den_start, den_digits)));
    q.canonicalize();
    if (negative) q = -q;
    if (approx) *approx = to_bounded(q);
    if (sign) *sign = sgn(q);
    if (out) *out = std::move(q);
    return true;
  }

  std::string_view frac_part;
  bool had_point = false;
  if (i < s.size() && s[i] == '.') {
    had_point = true;
    ++i;
    const std::size_t f_start = i;
    const std::size_t f_digits = digits(s, i);
    frac_part = s.substr(f_start, f_digits);
  }
  if (int_digits == 0 && frac_part.empty()) return fail("is not a number");
  if (json_number) {
    // JSON: int part required, no leading zeros, a point needs digits after it.
    if (int_digits == 0 || (int_digits > 1 && int_part[0] == '0') ||
        (had_point && frac_part.empty()))
      return fail("is not a number");
  }
  long exponent = 0;
  std::size_t exponent_digits = 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool exp_negative = false;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) {
      exp_negative = s[i] == '-';
      ++i;
    }
    const std::size_t e_start = i;
    const std::size_t e_digits = digits(s, i);
    if (e_digits == 0) return fail("is not a number");
    exponent_digits = e_digits;
    std::size_t k = e_start;
    while (k < i && s[k] == '0') ++k;  // leading zeros
    if (i - k > 18) return fail("has an exponent beyond the exponent limit");
    for (; k < i; ++k) exponent = exponent * 10 + (s[k] - '0');
    if (exponent > limits.max_exponent)
      return fail("has an exponent beyond the exponent limit");
    if (exp_negative) exponent = -exponent;
  }
  if (i != s.size()) return fail("is not a number");
  // The digit limit counts every digit of the text, exponent included (as the checker does).
  if (int_digits + frac_part.size() + exponent_digits > limits.max_digits)
    return fail("has more digits than the digit limit");

  const long scale = exponent - static_cast<long>(frac_part.size());
  std::size_t lead = 0;  // leading zeros of the mantissa digits
  while (lead < int_part.size() && int_part[lead] == '0') ++lead;
  if (lead == int_part.size()) {
    std::size_t f = 0;
    while (f < frac_part.size() && frac_part[f] == '0') ++f;
    lead += f;
  }
  const std::size_t significant = int_part.size() + frac_part.size() - lead;
  // The value written out counts too: m·10^scale as an integer (significant + scale digits) or as
  // m/10^k before reduction (significant + k + 1), so that a scene's canonical text (exact/scene_writer:
  // "p/q" in lowest terms, no exponent) reads back under the same limits. Found by fuzz_scene_parser:
  // "1e200" was accepted at --max-digits 200 and its 201-digit canonical text was not. (The checker agrees.)
  std::size_t count = int_digits + frac_part.size() + exponent_digits;  // number_digits(): the larger count
  if (significant > 0) {
    const std::size_t k = static_cast<std::size_t>(scale < 0 ? -scale : scale);
    const std::size_t written = significant + k + (scale < 0 ? 1 : 0);
    if (written > limits.max_digits)
      return fail("has more digits than the digit limit when written out exactly");
    count = std::max(count, written);
  }
  if (counted) *counted = count;
  if (tally && !tally->add_number(count, limits)) return fail(kOverBudget);
  if (!approx && !out && !sign) return true;
  bool approx_done = false;
  // Fast path: at most 18 significant digits and |scale| ≤ 18 fit in 64-bit integers (the value is
  // m·10^scale with m < 10^18 and 10^|scale| ≤ 10^18), so no string-to-GMP conversion is needed.
  const bool fast = significant <= 18 && scale >= -18 && scale <= 18 && (scale <= 0 || significant + scale <= 18);
  unsigned long m = 0, p = 1;
  if (fast) {
    for (char c : int_part) m = m * 10 + static_cast<unsigned long>(c - '0');
    for (char c : frac_part) m = m * 10 + static_cast<unsigned long>(c - '0');
    for (long k = 0; k < (scale < 0 ? -scale : scale); ++k) p *= 10;
    if (sign) *sign = m == 0 ? 0 : (negative ? -1 : 1);
    // The certified double straight from the digits: m < 2^53 and p = 10^k ≤ 10^15 < 2^53 are
    // exact doubles, so one correctly rounded operation gives v, and fma gives its exact error
    // (the value lies in [10^-18, 10^18], far from underflow and overflow). [FL-4]
    if (approx && m < (1ul << 53) && p <= 1000000000000000ul) {
      const double dm = static_cast<double>(m), dp = static_cast<double>(p);
      if (scale >= 0) {
        const double v = dm * dp;
        *approx = {v, std::fabs(std::fma(dm, dp, -v))};  // exact rounding error of the product
      } else {
        const double v = dm / dp;
        const double rem = std::fma(-v, dp, dm);  // m − v·p, exact for a correctly rounded quotient
        // |m/p − v| = |rem|/p; the division rounds, so inflate (or 0 when exact).
        *approx = {v, rem == 0 ? 0.0 : (std::fabs(rem) / dp) * fl::Bounded::kInflate};
      }
      if (negative) approx->v = -approx->v;
      approx_done = true;
    }
    if (approx_done && !out) return true;  // double and sign from the digits: no rational at all
  }
  std::optional<Rational> local;  // the exact value goes straight into *out when there is one
  Rational& q = out ? *out : local.emplace();
  if (fast) {
    if (scale >= 0) {
      mpz_set_ui(mpq_numref(q.get_mpq_t()), m * p);
      mpz_set_ui(mpq_denref(q.get_mpq_t()), 1);
    } else {
      // Lowest terms without a gcd: p = 10^k = 2^k·5^k, so gcd(m, p) = 2^a·5^b with a, b ≤ k.
      const long k = -scale;
      unsigned long num = m, den = p;
      if (num == 0) {
        den = 1;
      } else {
        const long twos = std::min<long>(__builtin_ctzl(num), k);
        num >>= twos, den >>= twos;
        for (long fives = 0; fives < k && num % 5 == 0; ++fives) num /= 5, den /= 5;
      }
      mpz_set_ui(mpq_numref(q.get_mpq_t()), num);
      mpz_set_ui(mpq_denref(q.get_mpq_t()), den);
    }
  } else {
    std::string mantissa;
    mantissa.reserve(int_digits + frac_part.size());
    mantissa.append(int_part);
    mantissa.append(frac_part);
    const Integer mi = integer_of(mantissa);
    if (mi == 0) {
      q = 0;
    } else if (scale >= 0) {
      Integer pw;
      mpz_ui_pow_ui(pw.get_mpz_t(), 10, static_cast<unsigned long>(scale));
      q = Rational(mi * pw);
    } else {
      Integer pw;
      mpz_ui_pow_ui(pw.get_mpz_t(), 10, static_cast<unsigned long>(-scale));
      q = Rational(mi, pw);
      q.canonicalize();
    }
  }
  if (negative) mpq_neg(q.get_mpq_t(), q.get_mpq_t());
  if (approx && !approx_done) *approx = to_bounded(q);
  if (sign && !approx_done) *sign = sgn(q);
  return true;
}

}  // namespace

std::optional<Rational> parse_rational(std::string_view s, bool json_number, const Input_limits& limits,
                                       std::string& why, fl::Bounded* approx) {
  Rational q;
  if (!parse_impl(s, json_number, limits, why, approx, &q, nullptr)) return std::nullopt;
  return q;
}

bool parse_rational_into(std::string_view s, bool json_number, const Input_limits& limits, std::string& why,
                         Rational& out, fl::Bounded* approx, Budget_tally* tally) {
  return parse_impl(s, json_number, limits, why, approx, &out, nullptr, tally);
}

bool scan_number(std::string_view s, bool json_number, const Input_limits& limits, std::string& why,
                 fl::Bounded& approx, int& sign, Budget_tally* tally) {
  return parse_impl(s, json_number, limits, why, &approx, nullptr, &sign, tally);
}

bool number_digits(std::string_view s, bool json_number, const Input_limits& limits, std::size_t& digits) {
  std::string why;
  return parse_impl(s, json_number, limits, why, nullptr, nullptr, nullptr, nullptr, &digits);
}


std::optional<double> nearest_double(const Rational& q) {
  const int sign = sgn(q);
  if (sign == 0) return 0.0;
  const Integer n = abs(q.get_num()), &d = q.get_den();
  // 2^E ≤ n/d < 2^(E+1)
  long E = static_cast<long>(mpz_sizeinbase(n.get_mpz_t(), 2)) - static_cast<long>(mpz_sizeinbase(d.get_mpz_t(), 2));
  {
    Integer a = n, b = d;
    if (E >= 0) b <<= static_cast<mp_bitcnt_t>(E);
    else a <<= static_cast<mp_bitcnt_t>(-E);
    if (a < b) --E;
  }
  if (E > 1023) return std::nullopt;
  // The unit in the last place of a double of that size (subnormals: 2^-1074); m = n/d / 2^u rounded
  // to the nearest integer, ties to even: m ≤ 2^53, so m·2^u is exact in a double (or overflows).
  const long u = std::max(E, -1022L) - 52;
  Integer num = n, den = d;
  if (u >= 0) den <<= static_cast<mp_bitcnt_t>(u);
  else num <<= static_cast<mp_bitcnt_t>(-u);
  Integer m, r;
  mpz_tdiv_qr(m.get_mpz_t(), r.get_mpz_t(), num.get_mpz_t(), den.get_mpz_t());
  const int c = cmp(Integer(r * 2), den);
  if (c > 0 || (c == 0 && mpz_odd_p(m.get_mpz_t()))) ++m;
  const double v = std::ldexp(m.get_d(), static_cast<int>(u));  // m.get_d() is exact: m ≤ 2^53
  if (std::isinf(v)) return std::nullopt;
  return sign < 0 ? -v : v;
}

std::string to_string(const Rational& q) { return q.get_str(10); }

Rational simplest_in(const Rational& l, const Rational& h) {
  if (sgn(l) <= 0 && sgn(h) >= 0) return 0;
  if (sgn(h) < 0) return -simplest_in(-h, -l);
  Integer f;  // 0 < l ≤ h
  mpz_fdiv_q(f.get_mpz_t(), l.get_num_mpz_t(), l.get_den_mpz_t());
  if (Rational(f) == l) return l;
  if (Rational(f + 1) <= h) return Rational(f + 1);
  return Rational(f) + 1 / simplest_in(1 / (h - f), 1 / (l - f));
}

std::array<Integer, 3> primitive(std::array<Integer, 3> v) { return primitive_of(std::move(v)); }
std::array<Integer, 3> primitive(const std::array<Rational, 3>& v) { return primitive_of(v); }
std::array<Integer, 2> primitive(const Rational& x, const Rational& y) { return primitive_of(std::array<Rational, 2>{x, y}); }

Integer integer_of(wide::i128 v) {
  const wide::u128 u = wide::uabs(v);
  if ((u >> 62) == 0) return Integer(static_cast<long>(v));
  Integer r = Integer(static_cast<unsigned long>(u >> 64));
  r <<= 64;
  r += static_cast<unsigned long>(static_cast<std::uint64_t>(u));
  return v < 0 ? Integer(-r) : r;
}

}  // namespace wrenchkit
