// wrenchkit — the command line (docs/cli.md): the one exit-code mapping of cli/common.h for what a command
// ends with. The commands, their options and help texts are the table of cli/command_table.cpp; each
// command lives in cli/<command>_command.cpp; shared pieces in cli/common.h. The program binds the conformance
// commands (reference, compare: conformance/), which the library wrenchkit_cli, shared with Python, does not link.
#include <iostream>
#include <string>
#include <vector>

#include "cli/command_table.h"
#include "exact/io/input_error.h"
#include "exact/numbers/rational.h"

int main(int argc, char** argv) {
  using namespace wrenchkit::cli;
  std::ios::sync_with_stdio(false);
  wrenchkit::use_throwing_gmp_allocation();  // out of memory: exit 70 with a message, never an abort  // buffered iostreams (batch reads and writes millions of lines)
  try {
    return run_command_line(std::vector<std::string>(argv + 1, argv + argc), {run_reference, run_compare});
  } catch (...) {
    return report(failure_of(std::current_exception()));
  }
}
