// wrenchkit compare: another implementation's answers against the reference corpus (conformance/compare.h); exit 0
// when every given answer agrees, 1 when some disagree.
#include <iostream>

#include "cli/common.h"
#include "conformance/compare.h"

namespace wrenchkit::cli {

int run_compare(const Options& o) {
  Compare_options c = o.compare;
  c.tolerance = o.tolerance, c.tolerance_text = o.tolerance_text;
  c.limits = o.limits;
  c.json = o.json;
  const Compare_report report = compare_answers(o.positional[0], o.positional[1], c, read_input);
  std::cout << report.text;
  return report.agree ? kAnswered : kRejected;
}

}  // namespace wrenchkit::cli
