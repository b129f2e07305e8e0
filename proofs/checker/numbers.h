// proofs/checker/numbers.h - numbers: certificate-format.md §2 (certificate rationals) and docs/scene-format.md
// "Numbers" and "Limits" (scene numbers, read exactly and counted against the scene's budget); and the two integer
// types that the checks of §1 and §3 are written over: GMP's, and Fixed (fixed width, on the stack).
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "proofs/checker/checker.h"
#include "proofs/checker/json.h"

namespace wrenchkit_checker::detail {

using Kind = Reader::Kind;
using Q = mpq_class;
using Z = mpz_class;

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
std::string clip(const std::string& s);   // text for a message, cut if long
std::string show(const Q& q);             // a rational for a message (a huge one not written out)
std::string show(const Q& a, const Q& b);  // "(a, b)"

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
  static inline thread_local Tally* reading = nullptr;
};

// JSON's number grammar is a subset of `decimal`. number_text() checks the grammar and the digit and
// exponent limits on the text, before any big number is built (no overflow, no huge power of ten), and
// returns its parts (views of the text); exact_value() is its value.
struct Number_text {
  bool negative = false, fraction = false;
  std::string_view whole, frac, den;  // fraction: whole / den; decimal: the digits before and after '.'
  long long scale = 0;                // decimal: value = mantissa * 10^scale, mantissa = the digits whole frac
  std::size_t counted = 0;            // its digits as the scene's budget counts them: text or value written out
};

Number_text number_text(std::string_view s, const Limits& lim, const std::string& path);
bool is_zero(const Number_text& n);   // the numerator's digits (a decimal's mantissa) are all zeros
Q exact_value(const Number_text& n);  // the exact value of a checked number text

// The longest rational a certificate about the scene being checked may hold (certificate-format.md §2):
// max(100000, 32 L + 64) characters for L the digits of the scene's longest number (a weight is a ratio of
// 3x3 minors of generator integers of at most 5 L + 1 digits each). Set by check_certificate.
inline thread_local std::size_t certificate_rational_limit = 100000;

// The exact value of a scene number's text (see number_text()). With `tally`, the number is counted against
// the scene's budget, before it is built; with `build` false nothing is built (the result is 0): the number
// is only validated and counted.
Q scene_number(std::string_view s, const Limits& lim, const std::string& path, Tally* tally = nullptr,
               bool build = true);

// A number num/den with den > 0 in 64 bits, not necessarily in lowest terms: a short decimal m·10^-k is
// m/10^k as written ("0.500000" is 500000/10^6). Positive scalings of a generator change none of the
// conditions checked, and the decimals of one scene usually have one number of digits each, so the
// generators of its contacts then share one denominator.
struct Small {
  long long num = 0, den = 1;
};
bool small_value(const Number_text& n, Small& out);  // its value as a Small, or false if it does not fit
void set_small(Q& q, const Small& s);                // q = the Small's value, in lowest terms

// A certificate rational (§2): a JSON string matching -?(0|[1-9][0-9]*)(/[1-9][0-9]*)? of at most
// certificate_rational_limit characters, and its value.
bool rational_grammar(std::string_view s);
[[noreturn]] void not_a_rational(std::string_view s, const std::string& path);  // the failure of a text that is not
Q rational_value(std::string_view s);  // of a text that matches the grammar

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

// The integers of the checks of §1 and §3. Each of these checks is written once, over a number type N, and
// run by fast_then_exact(): with N = Fixed (fixed width, on the stack) and, only if a result overflows it,
// again from the start with N = Z (GMP). Every value of either type is exact, so the two runs take the same
// steps and reach the same verdict and message; Fixed only decides sooner.

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
}  // namespace wrenchkit_checker::detail
