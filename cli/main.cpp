// wrenchkit — the command line (interface.md §2, docs/cli.md): exit codes of the error kinds. The
// commands, their options and help texts are the table of cli/command_table.cpp; each command lives
// in cli/<command>_command.cpp; shared pieces in cli/common.h.
#include <iostream>
#include <string>
#include <vector>

#include "cli/command_table.h"
#include "exact/io/input_error.h"

int main(int argc, char** argv) {
  using namespace wrenchkit::cli;
  std::ios::sync_with_stdio(false);  // buffered iostreams (batch reads and writes millions of lines)
  try {
    return run_command_line(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const Usage_error& e) {
    std::cerr << "wrenchkit: usage error: " << e.what() << "\n";
    return kBadInput;
  } catch (const wrenchkit::Input_error& e) {
    std::cerr << "wrenchkit: error: " << e.what() << "\n";
    return kBadInput;
  } catch (const Undecided& e) {
    std::cerr << "wrenchkit: undecided: " << e.what() << "\n";
    return kUndecided;
  } catch (const Self_check_failure& e) {
    std::cerr << "wrenchkit: internal error (please report): " << e.what() << "\n";
    return kSelfCheck;
  } catch (const std::bad_alloc&) {
    std::cerr << "wrenchkit: internal error: out of memory\n";
    return kInternal;
  } catch (const std::exception& e) {
    std::cerr << "wrenchkit: internal error (please report): " << e.what() << "\n";
    return kInternal;
  }
}
