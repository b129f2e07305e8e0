#include "exact/io/json_writer.h"

#include <cstdint>
#include <cstring>

#include "exact/numbers/wide_int.h"

namespace wrenchkit {

namespace {

// GMP writes the digits straight into the output, between quotes: `room` bytes (the digits, a sign, a
// '/' and GMP's terminating NUL), so an exact number costs no allocation of its own.
template <class Digits>
void quoted_digits(std::string& out, std::size_t room, Digits digits) {
  const std::size_t at = out.size();
  out.resize(at + room + 2);
  out[at] = '"';
  digits(&out[at + 1]);
  const std::size_t n = std::strlen(&out[at + 1]);
  out[at + 1 + n] = '"';
  out.resize(at + 2 + n);
}

// |z| in at most two limbs (< 2^128), as an unsigned 128-bit integer; false if larger.
bool two_limbs(const mpz_t z, wide::u128& out) {
  static_assert(GMP_NUMB_BITS == 64, "64-bit limbs");
  const std::size_t n = mpz_size(z);
  if (n > 2) return false;
  out = n == 0 ? 0 : static_cast<wide::u128>(mpz_getlimbn(z, 0));
  if (n == 2) out |= static_cast<wide::u128>(mpz_getlimbn(z, 1)) << 64;
  return true;
}

// The decimal digits of x (at most 39) written backwards ending at `end`; returns their first byte. At most
// two 128-bit divisions (by 10^19), the rest in 64 bits.
char* digits_before(char* end, wide::u128 x) {
  constexpr std::uint64_t k1e19 = 10000000000000000000ull;
  while (x > ~std::uint64_t(0)) {
    const wide::u128 q = x / k1e19;
    std::uint64_t r = static_cast<std::uint64_t>(x - q * k1e19);
    for (int i = 0; i < 19; ++i) *--end = static_cast<char>('0' + r % 10), r /= 10;
    x = q;
  }
  std::uint64_t v = static_cast<std::uint64_t>(x);
  do {
    *--end = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v != 0);
  return end;
}

// The same digits GMP writes (mpz_get_str / mpq_get_str: "-"? numerator ("/" denominator)?) for numbers
// below 2^128, without GMP's size estimate and conversion (the certificates' weights and twists, mostly).
bool quoted_small(std::string& out, const mpz_t num, const mpz_t den) {
  wide::u128 n = 0, d = 1;
  if (!two_limbs(num, n) || (den && !two_limbs(den, d))) return false;
  char b[84];  // '"', '-', 39 digits, '/', 39 digits, '"'
  char* end = b + sizeof b;
  *--end = '"';
  if (d != 1) end = digits_before(end, d), *--end = '/';
  end = digits_before(end, n);
  if (mpz_sgn(num) < 0) *--end = '-';
  *--end = '"';
  out.append(end, static_cast<std::size_t>(b + sizeof b - end));
  return true;
}

}  // namespace

Json_writer& Json_writer::rational(const Rational& q) {
  separate();
  if (quoted_small(out_, q.get_num_mpz_t(), q.get_den_mpz_t())) return *this;
  const std::size_t room = mpz_sizeinbase(q.get_num_mpz_t(), 10) + mpz_sizeinbase(q.get_den_mpz_t(), 10) + 3;
  quoted_digits(out_, room, [&q](char* at) { mpq_get_str(at, 10, q.get_mpq_t()); });
  return *this;
}

Json_writer& Json_writer::rational(const Integer& z) {
  separate();
  if (quoted_small(out_, z.get_mpz_t(), nullptr)) return *this;
  quoted_digits(out_, mpz_sizeinbase(z.get_mpz_t(), 10) + 2, [&z](char* at) { mpz_get_str(at, 10, z.get_mpz_t()); });
  return *this;
}

}  // namespace wrenchkit
