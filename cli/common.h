// Shared pieces of the wrenchkit command: exit codes, options, file I/O, error kinds, and the
// commands' entry points (each command lives in its own file, named after it).
#pragma once

#include <array>
#include <exception>
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "exact/pipeline/pipeline.h"
#include "exact/statics/closure.h"
#include "exact/statics/equilibrium.h"
#include "exact/numbers/limits.h"
#include "proofs/checker/checker.h"

namespace wrenchkit::cli {

// docs/cli.md, "Exit codes".
enum Exit { kAnswered = 0, kRejected = 1, kBadInput = 2, kUndecided = 3, kSelfCheck = 4, kInternal = 70 };

struct Options {
  bool json = false;
  bool help = false;
  bool verdict_only = false;  // batch: skip certificates (throughput); never the default
  unsigned jobs = 0;          // batch: threads, 0 = all cores
  std::string mode = "hybrid";
  std::string certificate_file, form_certificate_file;
  Input_limits limits;
  std::vector<std::string> positional;
  // Command-specific options (--resultant, --center, --sense, --direction, --twist, --what,
  // --output/-o, --sides, --tolerance, --load, --off, --obj, --svg; the flag --list with the empty
  // value): set only when given.
  std::map<std::string, std::string> values;
  bool has(const std::string& option) const { return values.count(option) != 0; }
};

// Exit 2 (usage), 3 (--mode float undecided: the engine's Undecided_error), 4 (our own certificate or
// golden file contradicted: a bug).
struct Usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};
using Undecided = Undecided_error;
struct Self_check_failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// A pipeline answer that did not end in `answered` (exact/pipeline/pipeline.h), unwinding a command to
// main or to batch's line.
struct Failure : std::runtime_error {
  Failure(Status s, const std::string& message) : std::runtime_error(message), status(s) {}
  Status status;
};
// The one place where the command line meets how an answer ended. cli_message: the engine's message as the
// CLI writes it (an undecided answer gets the advice to change mode); answered: a pipeline item itself when
// it was answered, else its Failure; failure_of: the status and message of the exception in flight
// (Usage_error → bad_input with its own prefix, see `usage`); report: the stderr line of a single command and
// its exit code (docs/cli.md).
std::string cli_message(Status s, const std::string& message);
template <class Item>
Item answered(Item item) {
  if (item.status != Status::answered) throw Failure(item.status, cli_message(item.status, item.message));
  return item;
}
struct Ended {
  Status status;
  std::string message;
  bool usage = false;
};
Ended failure_of(std::exception_ptr e);
int report(const Ended& e);
// The pipeline request of the command line's options: --mode, --verdict-only, the --max-* limits.
Request request_of(const Options& o);

Options parse_options(int argc, char** argv, int first);
// The exact numbers of a "a,b,…" option value (decimal or p/q each, as in scenes); exactly n of them.
std::vector<Rational> parse_vector(const Options& o, const std::string& option, std::size_t n);
// Reads a whole file (or standard input for "-"), refusing more than `limit` bytes.
std::string read_input(const std::string& path, std::size_t limit);
// Writes FILE atomically: a temporary beside it, then a rename, so nothing is half-written.
void write_file(const std::string& path, const std::string& text);
wrenchkit_checker::Limits checker_limits(const Input_limits& l);
// An exact rational for human output: "p/q" when short, else "~" and 12 significant digits (the
// exact value is in --json).
std::string human_number(const Rational& q);
std::string vec_text(const std::array<Rational, 3>& v);
// The words for a region of the plane (docs/cli.md, REGION) from its shape name (shape_name of
// exact/statics/planar_region.h, which the twin's regions share) and the texts of its corners and
// directions: one sentence for the exact regions and the twin's.
std::string region_sentence(const std::string& shape, const std::vector<std::string>& corners,
                            const std::vector<std::string>& directions);
Mode mode_of(const std::string& m);

// ---------------------------------------------------------------------------------------------
// The per-scene commands' JSON answers, shared by the single commands (`wrenchkit COMMAND --json`),
// `wrenchkit batch COMMAND` and any other front end.
//
// A Scene_answer maps one scene text to the command's --json answer: one line, no newline, exactly
// what `wrenchkit COMMAND --json SCENE` prints. `source` names the text in messages. It throws
// Input_error for a bad scene (exit 2), Undecided (exit 3), Self_check_failure (exit 4), and
// Usage_error when the options cannot apply to this scene (limit-surface's --sides on a large
// support). It may be called from several threads at once.
using Scene_answer = std::function<std::string(const std::string& scene_text, const std::string& source)>;

struct Scene_command {
  const char* name;  // closure, equilibrium, labels, dual, reuleaux, analyze, limit-surface, sliding
  // Reads and validates the command's options from `o`, once (Usage_error for an option the command
  // does not take or a bad value), and returns its Scene_answer, which keeps what it needs of them.
  Scene_answer (*prepare)(const Options& o);
};
// The per-scene command called `name`, or nullptr.
const Scene_command* find_scene_command(const std::string& name);
// The commands' names, "closure|equilibrium|…", for messages.
std::string scene_command_names();

Scene_answer prepare_closure_json(const Options& o);
Scene_answer prepare_equilibrium_json(const Options& o);
Scene_answer prepare_labels_json(const Options& o);
Scene_answer prepare_dual_json(const Options& o);
Scene_answer prepare_reuleaux_json(const Options& o);
Scene_answer prepare_analyze_json(const Options& o);
Scene_answer prepare_limit_surface_json(const Options& o);
Scene_answer prepare_sliding_json(const Options& o);

// closure_command.cpp, equilibrium_command.cpp (analyze and reference use these pieces): the pipeline's
// items (exact/pipeline/pipeline.h) written as JSON and as text.
std::string closure_json(const Options& o, const Closure_item& r, const char* command);
std::string closure_human(const Closure_item& r);
int run_closure(const Options& o, const std::string& scene_text, const std::string& source, const char* command);
std::string equilibrium_json(const Options& o, const Equilibrium_item& r, const char* command);
std::string equilibrium_human(const Equilibrium_item& r);
int run_equilibrium(const Options& o, const std::string& scene_text, const std::string& source);

// analyze_command.cpp, batch_command.cpp, check_command.cpp
int run_analyze(const Options& o, const std::string& scene_text, const std::string& source, const char* command);
int run_batch(const Options& o);
int run_check(const Options& o);

// labels_command.cpp: labels, dual, reuleaux;  render_command.cpp: render
int run_labels(const Options& o, const std::string& scene_text, const std::string& source);
int run_dual(const Options& o, const std::string& scene_text, const std::string& source);
int run_reuleaux(const Options& o, const std::string& scene_text, const std::string& source);
int run_render(const Options& o, const std::string& scene_text, const std::string& source);

// limit_surface_command.cpp, sliding_command.cpp
int run_limit_surface(const Options& o, const std::string& scene_text, const std::string& source);
int run_sliding(const Options& o, const std::string& scene_text, const std::string& source);
extern const char* kLimitSurfaceHelp;
extern const char* kSlidingHelp;

// Usage_error unless every command-specific option given is one of `allowed`.
void only_options(const Options& o, const char* command, std::initializer_list<const char*> allowed);

}  // namespace wrenchkit::cli
