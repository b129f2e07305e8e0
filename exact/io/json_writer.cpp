#include "exact/io/json_writer.h"

#include <cstring>

namespace wrenchkit {

// GMP writes the digits straight into the output (room for a sign, '/' and its terminating NUL), so an
// exact number costs no allocation of its own.
Json_writer& Json_writer::rational(const Rational& q) {
  separate();
  const std::size_t at = out_.size();
  out_.resize(at + mpz_sizeinbase(q.get_num_mpz_t(), 10) + mpz_sizeinbase(q.get_den_mpz_t(), 10) + 5);
  out_[at] = '"';
  mpq_get_str(&out_[at + 1], 10, q.get_mpq_t());
  const std::size_t n = std::strlen(&out_[at + 1]);
  out_[at + 1 + n] = '"';
  out_.resize(at + 2 + n);
  return *this;
}

Json_writer& Json_writer::rational(const Integer& z) {
  separate();
  const std::size_t at = out_.size();
  out_.resize(at + mpz_sizeinbase(z.get_mpz_t(), 10) + 4);
  out_[at] = '"';
  mpz_get_str(&out_[at + 1], 10, z.get_mpz_t());
  const std::size_t n = std::strlen(&out_[at + 1]);
  out_[at + 1 + n] = '"';
  out_.resize(at + 2 + n);
  return *this;
}

}  // namespace wrenchkit
