// Shared pieces of the wrenchkit command: exit codes, options, file I/O, error kinds, and the
// commands' entry points (each command lives in its own file, named after it).
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "exact/closure.h"
#include "exact/equilibrium.h"
#include "exact/limits.h"
#include "proofs/checker/checker.h"

namespace wrenchkit::cli {

// interface.md §2.
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
  // Command-specific options with a value (--resultant, --center, --sense, --direction,
  // --twist, --what, --output/-o, --sides for render): set only when given.
  std::map<std::string, std::string> values;
  bool has(const std::string& option) const { return values.count(option) != 0; }
};

// Exit 2 (usage), 3 (--mode float undecided), 4 (our own certificate rejected: a bug).
struct Usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct Undecided : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct Self_check_failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

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
Mode mode_of(const std::string& m);

// closure_command.cpp
struct Closure_result {
  Scene scene;
  Closure_answer fc, fo;
  std::string fc_json, fo_json;  // empty when not certified (batch --verdict-only)
};
// `lazy`: read the scene lazily (batch: rationals only if an exact predicate or a certificate needs them).
Closure_result compute_closure(const Options& o, const std::string& scene_text, const std::string& source,
                               bool lazy = false);
std::string closure_json(const Options& o, const Closure_result& r, const char* command, std::size_t line = 0);
std::string closure_human(const Closure_result& r);
std::string decided_by(const Closure_answer& a, const Closure_answer& b);
int run_closure(const Options& o, const std::string& scene_text, const std::string& source, const char* command);

// equilibrium_command.cpp
struct Equilibrium_result {
  Equilibrium_answer a;
  std::string cert;
};
Equilibrium_result compute_equilibrium(const Options& o, const Scene& scene, const std::string& scene_text);
std::string equilibrium_json(const Options& o, const Scene& scene, const Equilibrium_result& r, const char* command);
std::string equilibrium_human(const Equilibrium_result& r);
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

// limit_surface_command.cpp, sliding_command.cpp: they read their own options (--sides, --twist, …)
// and pass the rest to parse_options.
int run_limit_surface(int argc, char** argv);
int run_sliding(int argc, char** argv);

}  // namespace wrenchkit::cli
