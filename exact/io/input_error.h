// Bad user input: the message names the JSON path (or file position) and the offending text.
// The CLI prints it on stderr and exits with code 2 (docs/cli.md, "Exit codes").
#pragma once

#include <stdexcept>
#include <string>

namespace wrenchkit {

class Input_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace wrenchkit
