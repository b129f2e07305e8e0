#include "exact/io/json_writer.h"

#include <cstring>

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

}  // namespace

Json_writer& Json_writer::rational(const Rational& q) {
  separate();
  const std::size_t room = mpz_sizeinbase(q.get_num_mpz_t(), 10) + mpz_sizeinbase(q.get_den_mpz_t(), 10) + 3;
  quoted_digits(out_, room, [&q](char* at) { mpq_get_str(at, 10, q.get_mpq_t()); });
  return *this;
}

Json_writer& Json_writer::rational(const Integer& z) {
  separate();
  quoted_digits(out_, mpz_sizeinbase(z.get_mpz_t(), 10) + 2, [&z](char* at) { mpz_get_str(at, 10, z.get_mpz_t()); });
  return *this;
}

}  // namespace wrenchkit
