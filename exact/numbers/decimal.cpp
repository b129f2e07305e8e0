// exact/numbers/decimal.h: a rational's correctly rounded decimal, in GMP integers.
#include "exact/numbers/decimal.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace wrenchkit {

std::string decimal_text(const Rational& q, int digits) {
  if (digits < 1 || digits > 40) throw std::logic_error("decimal_text: digits out of range");
  if (sgn(q) == 0) return "0";
  const Integer n = abs(q.get_num()), &d = q.get_den();
  Integer ten_p;  // 10^digits
  mpz_ui_pow_ui(ten_p.get_mpz_t(), 10, static_cast<unsigned long>(digits));
  // e: 10^e ≤ n/d < 10^(e+1), from the sizes, then corrected (sizeinbase may be one too large).
  long e = static_cast<long>(mpz_sizeinbase(n.get_mpz_t(), 10)) - static_cast<long>(mpz_sizeinbase(d.get_mpz_t(), 10));
  // m = round(n/d · 10^(digits−1−e)), ties to even; digits significant digits unless it rounds up to 10^digits.
  const auto scaled = [&](long ex, Integer& m) {
    const long k = digits - 1 - ex;
    Integer a = n, b = d, p;
    mpz_ui_pow_ui(p.get_mpz_t(), 10, static_cast<unsigned long>(k >= 0 ? k : -k));
    if (k >= 0) a *= p;
    else b *= p;
    Integer r;
    mpz_fdiv_qr(m.get_mpz_t(), r.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
    return std::pair<Integer, Integer>(r * 2, b);  // the remainder's comparison with half of b
  };
  Integer m;
  for (;;) {  // at most two corrections
    const auto [r2, b] = scaled(e, m);
    if (m < ten_p / 10) { --e; continue; }
    if (m >= ten_p) { ++e; continue; }
    const int c = cmp(r2, b);
    if (c > 0 || (c == 0 && mpz_odd_p(m.get_mpz_t()))) ++m;
    if (m == ten_p) { m = ten_p / 10; ++e; }
    break;
  }
  std::string digs = m.get_str(10);  // exactly `digits` digits
  std::string out = sgn(q) < 0 ? "-" : "";
  const auto trim = [](std::string s) {  // trailing zeros of a fraction part, and a bare point
    if (s.find('.') == std::string::npos) return s;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
  };
  if (e >= -4 && e < digits) {
    if (e >= 0) out += trim(digs.substr(0, static_cast<std::size_t>(e + 1)) + "." + digs.substr(static_cast<std::size_t>(e + 1)));
    else out += trim("0." + std::string(static_cast<std::size_t>(-e - 1), '0') + digs);
  } else {
    std::string x = std::to_string(e < 0 ? -e : e);
    if (x.size() < 2) x = "0" + x;
    out += trim(digs.substr(0, 1) + "." + digs.substr(1)) + (e < 0 ? "e-" : "e+") + x;
  }
  return out;
}

}  // namespace wrenchkit
