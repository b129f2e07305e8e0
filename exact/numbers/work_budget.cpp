// [WORK] exact/numbers/work_budget.h.
#include "exact/numbers/work_budget.h"

#include <limits>

namespace wrenchkit {

namespace {
thread_local Work_scope* current = nullptr;
thread_local std::size_t last_used = 0;
}

Work_scope::Work_scope(std::size_t limit) : limit_(limit), used_(0), outer_(current) { current = this; }
Work_scope::~Work_scope() {
  last_used = used_;
  current = outer_;
}

std::size_t Work::times(std::size_t a, std::size_t b) {
  return a != 0 && b > std::numeric_limits<std::size_t>::max() / a ? std::numeric_limits<std::size_t>::max() : a * b;
}

void Work::charge(std::size_t units, const std::string& what) {
  Work_scope* s = current;
  if (!s) return;
  if (units > s->limit_ - s->used_)  // used_ ≤ limit_ always
    throw Work_exhausted(std::string(kWorkBudget) + std::to_string(s->limit_) + " units (--max-work) is not enough: " +
                         what + " costs " + std::to_string(units) + " units, and " + std::to_string(s->used_) +
                         " are spent (the cost grows with the points whose force is not given, the regions' cells and "
                         "the numbers' length; raise --max-work to let it run)");
  s->used_ += units;
}

std::size_t Work::last() { return last_used; }

std::size_t Work::size(const Rational& x) {
  const std::size_t n = mpz_size(x.get_num_mpz_t()) + (mpz_cmp_ui(x.get_den_mpz_t(), 1) == 0 ? 0 : mpz_size(x.get_den_mpz_t()));
  return 1 + n / kLimbsPerSize;
}

}  // namespace wrenchkit
