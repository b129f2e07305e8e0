// The command line's one table (docs/cli.md): every command with its summary, usage, help prose,
// options, positional arguments and handler. The parser (Boost.Program_options), `wrenchkit --help`,
// `wrenchkit COMMAND --help` and `wrenchkit batch COMMAND` are all generated from it.
#pragma once

#include <string>
#include <vector>

#include "cli/common.h"

namespace wrenchkit::cli {

// One option. `read` validates the value's text (empty for a flag) into its typed field of Options,
// or throws Usage_error naming `option` ("--sides"); it is called where the command line is parsed,
// the scene limits first (the exact numbers are read within them), then the others in their order.
struct Option {
  enum class Role { ordinary, limit, file };  // limit: --max-*; file: writes or shapes a file (not in batch)
  const char* name;                           // Boost's spelling: "sides", "output,o"
  const char* value;                          // the value's name in help ("N", "x,y"); nullptr: a flag
  const char* help;
  void (*read)(Options& o, const std::string& option, const std::string& value);
  Role role = Role::ordinary;
};

// The conformance commands (reference, compare: the corpus with its test scenery, and compare; conformance/), whose
// handlers the program binds (cli/main.cpp) rather than this library: the Python bindings share the table and the
// batch lines (prepare_batch, batch_line) and link neither the corpus nor the test scenery.
struct Conformance_commands {
  int (*reference)(const Options& o);
  int (*compare)(const Options& o);
};
using Conformance_command = int (*Conformance_commands::*)(const Options& o);

struct Command {
  const char* name;
  const char* summary;      // its line in `wrenchkit --help`
  const char* usage;        // after "usage: wrenchkit NAME "
  const char* description;  // `wrenchkit NAME --help`, before the options
  std::vector<Option> options;
  std::vector<const char*> positionals;  // exactly these, in this order
  // The handler: per-scene commands read their scene (the first positional; - for standard input)
  // and answer it with `scene`; the others are `run`.
  int (*scene)(const Options& o, const std::string& text, const std::string& source) = nullptr;
  int (*run)(const Options& o) = nullptr;
  // Per-scene commands: their JSON answer for `batch COMMAND`, and the options batch adds to theirs.
  Scene_answer (*prepare)(const Options& o) = nullptr;
  std::vector<Option> batch_options = {};
  // A conformance command: its handler among those the program binds (instead of `run`).
  Conformance_command conformance = nullptr;
};

// The table, in the order of `wrenchkit --help`.
const std::vector<Command>& commands();

// `batch COMMAND [OPTIONS]` without the word batch: the options parsed and validated as the command line does,
// and the command's per-scene JSON answer prepared from them (for cli/common.h's batch_line). Usage_error as
// `wrenchkit batch` gives it.
struct Batch_job {
  Options options;
  Scene_answer answer;
};
Batch_job prepare_batch(const std::vector<std::string>& command_and_options);

// COMMAND's options (no scene file), parsed and validated as `wrenchkit COMMAND ARGS…` parses them, for the front
// ends that answer one command's question without a command line (the Python bindings' render, reuleaux, compare).
// Usage_error as the command line gives it.
Options parse_options(const std::string& command, const std::vector<std::string>& args);

// `wrenchkit ARGS…` (argv without the program name): parses, validates and runs, the conformance commands with the
// program's handlers; the exit code. Throws Usage_error, Input_error, Undecided, Self_check_failure as the commands do.
int run_command_line(const std::vector<std::string>& args, const Conformance_commands& conformance);

}  // namespace wrenchkit::cli
