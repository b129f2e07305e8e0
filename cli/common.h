// Shared pieces of the wrenchkit command: exit codes, the typed options, file I/O, error kinds, and the
// commands' entry points (each command lives in its own file, named after it; the table of commands,
// their options and help texts is cli/command_table.cpp).
#pragma once

#include <array>
#include <exception>
#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "conformance/compare.h"
#include "conformance/reference.h"
#include "core/mode.h"
#include "exact/io/json_writer.h"
#include "exact/pipeline/pipeline.h"
#include "exact/pipeline/hold_answer.h"
#include "exact/pipeline/grasp_regions_answer.h"
#include "exact/pipeline/push_answer.h"
#include "exact/pipeline/quality_answer.h"
#include "exact/pipeline/labels_answer.h"
#include "exact/pipeline/support_answer.h"
#include "exact/statics/closure.h"
#include "exact/statics/equilibrium.h"
#include "exact/numbers/limits.h"
#include "proofs/checker/checker.h"

namespace wrenchkit::cli {

// docs/cli.md, "Exit codes".
enum Exit { kAnswered = 0, kRejected = 1, kBadInput = 2, kUndecided = 3, kSelfCheck = 4, kInternal = 70 };

// What `render --what` draws.
enum class Picture { labels, dual, reuleaux, limit_surface, hold, quality, grasp_regions, push };

// The options of one command line, each validated where it is parsed (cli/command_table.cpp: the
// exact numbers through parse_rational within the scene limits) into its typed field. A command
// reads only the fields of the options its table entry lists; the others keep these defaults
// (command-specific ones: empty, std::nullopt).
struct Options {
  bool json = false;
  bool help = false;
  bool verdict_only = false;  // batch closure: skip certificates (throughput); never the default
  unsigned jobs = 0;          // batch: threads, 0 = all cores
  Mode mode = Mode::hybrid;
  std::string certificate_file, form_certificate_file;
  Input_limits limits;
  std::vector<std::string> positional;
  // labels --resultant fx,fy,m; reuleaux --center x,y [--sense], --direction dx,dy (not zero) or
  // --twist; limit-surface, sliding --twist vx,vy,w (not zero); limit-surface --load fx,fy,m.
  std::optional<std::array<Rational, 3>> resultant, twist, load;
  std::optional<std::array<Rational, 2>> center, direction;
  std::optional<int> sense;  // +1 counter-clockwise, -1 clockwise
  // limit-surface, sliding, render: --sides N (even, 4..kMaxSides); limit-surface, analyze:
  // --tolerance EPS (> 0; its text too, for messages).
  std::optional<int> sides;
  std::optional<Rational> tolerance;
  std::string tolerance_text;
  // render --what, -o/--output FILE; limit-surface --list, --off, --obj, --ply, --svg FILE, --exact-coordinates.
  std::optional<Picture> what;
  std::string output, off_file, obj_file, ply_file, svg_file;
  bool list = false, exact_coordinates = false;
  // compare: --format jsonl|csv, --rtol, --atol, --near (exact, >= 0); its --tolerance, --max-file-size and --json
  // are the fields above.
  Compare_options compare;
  // quality: --norm, --normalize, --torque-scale, --about (its --tolerance is the field above).
  Quality_query quality;
  // grasp-regions: --mu, --edges i,j,…, --fingers (2).
  Grasp_regions_query regions;
  // push: --contact (its --tolerance is the field above).
  Push_query push;
  // reference: --out DIR, --seed, --cases, --random, --sides (4..64).
  std::string out_dir;
  Reference_options reference;
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
// CLI writes it (an undecided status comes from the float twin, which gets the advice to change mode, or from a
// budget, whose message names its own --max- option and gets none); answered: a pipeline item itself when
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

// Writes a single command's answer: with --json its JSON line (the members `json` writes, in braces), else its
// text for people (each made only when needed); returns kAnswered, or kUndecided when the answer says undecided
// (the one exit-code rule: an undecided answer exits 3 in every output form and mode).
int write_answer(const Options& o, const std::function<void(Json_writer&)>& json,
                 const std::function<std::string()>& text, bool undecided = false);
// What can help an undecided answer in this mode: "; use --mode hybrid or exact" in float mode, else nothing (the
// answer's own reason says what is left).
std::string undecided_advice(Mode mode);
// The writer of a support's answer by its kind (exact/pipeline/support_answer.h): points with every force given, the
// same by the twin alone (--mode float), some force not given (with regions or not: its writers add the regions'
// statics), regions with every force given (sliding and limit-surface alike).
template <class F>
F by_kind(const Support_item& r, F points, F twin, F unknown, F regions) {
  switch (r.kind) {
    case Support_kind::points: return points;
    case Support_kind::points_twin: return twin;
    case Support_kind::unknown: return unknown;
    case Support_kind::regions: return regions;
  }
  return points;
}

// sliding_command.cpp: a support with regions [RG-1] (sliding and limit-surface alike): its exact statics ("support",
// "total_force", "center_of_friction", "friction_centroid", "mu_f0") and, with a twist, its certified power and
// load ("twist", "motion", "power", "load_box", …), as JSON members and as text lines.
void write_region_statics(Json_writer& w, const Support_item& r);
void write_region_twist(Json_writer& w, const Support_item& r, const Rational& tolerance);
std::string region_statics_text(const Support_item& r, const std::string& source);
std::string region_twist_text(const Support_item& r);

// sliding_command.cpp: a distribution and a support with unknown forces as text (the first lines of the answer).
std::string distribution_text(const std::vector<Rational>& f);
std::string unknown_support_text(const Support_item& r, const std::string& source);
// sliding_command.cpp: a support with unknown forces as JSON members ("distribution": "unknown", … and
// "power": {…}) written into the answer's object, for sliding and limit-surface alike.
void write_unknown_distribution(Json_writer& w, const Support_item& r);
void write_power_over(Json_writer& w, const Support_item& r);
// The regions' part of the power over F ("" without regions or a twist), a text line.
std::string regions_power_text(const Support_item& r);
// "scene: NAME" (or the source when the scene has no name), the first line of every text answer.
// "scene: NAME (or the source)", and a line per warning a --lenient reading let through (exact/io/outline.h).
std::string scene_line(const Scene& scene, const std::string& source);

// Reads a whole file (or standard input for "-"), refusing more than `limit` bytes.
std::string read_input(const std::string& path, std::size_t limit);
// Writes FILE atomically: a temporary beside it, then a rename, so nothing is half-written.
void write_file(const std::string& path, const std::string& text);
// The one way text output writes exact numbers for people (docs/cli.md, "Text output"). human_number: the exact
// rational alone, "p/q" when short, else "~" and 12 significant digits (the exact value is in --json). number_text:
// a number a person reads, with its decimal beside it when it is not an integer, "1/7 (≈ 0.142857)" (6 significant
// digits, correctly rounded from the exact value: decimal_text of exact/numbers/decimal.h). vec_text: a vector (a
// point, load, force, distribution) with, when any entry is not an integer, the decimals beside it: "(0, 1/2) ≈ (0,
// 0.5)". twist_text: a twist as a direction, its primitive integer multiple "(0, 1, 1)" (the scaled value is in
// certificates, where a check needs it).
std::string human_number(const Rational& q);
std::string number_text(const Rational& q);
std::string vec_text(const std::vector<Rational>& v);
std::string vec_text(const Vec3q& v);
std::string vec_text(const Vec2& p);
std::string twist_text(const Vec3q& t);
// motion_words (exact/numbers/vectors.h) with the rotation centre's decimals: "a counter-clockwise rotation about (1/3,
// 0) ≈ (0.333333, 0)".
std::string motion_text(const Vec3q& t);
// The same for JSON: an "_approx" sibling beside an exact value, as force_approx has always been: JSON numbers, each
// the exact value's nearest double (17 significant digits), or its 17-digit decimal beyond the doubles' range.
// approx_number writes one value, write_approx the member KEY_approx of a vector.
void approx_number(Json_writer& w, const Rational& q);
void write_approx(Json_writer& w, const std::string& key, const std::vector<Rational>& v);
// "note: …" when point contacts have no "mu" (frictionless by default; the text output says so once), else "".
std::string frictionless_note(const Scene& scene);
// What a support scene allows to ask, for `sliding` and `limit-surface` asked nothing (text only).
std::string ask_support_text();
// Each contact's force under a certificate's weights, in words: "c0 (floor, left) (0, 1/2) ≈ (0, 0.5); …".
std::string contact_forces_text(const std::vector<Contact_force>& forces);
// The same as JSON: "forces": [{"contact", "name", "force": [fx, fy] exact, "force_approx": [doubles]}, …].
void write_forces(Json_writer& w, const std::vector<Contact_force>& forces);
// The words for a region of the plane (docs/cli.md, REGION) from its shape name (shape_name of
// exact/statics/planar_region.h, which the twin's regions share) and the texts of its corners and
// directions: one sentence for the exact regions and the twin's.
std::string region_sentence(const std::string& shape, const std::vector<std::string>& corners,
                            const std::vector<std::string>& directions);

// ---------------------------------------------------------------------------------------------
// The per-scene commands' JSON answers, shared by the single commands (`wrenchkit COMMAND --json`),
// `wrenchkit batch COMMAND` and any other front end.
//
// A Scene_answer writes one scene text's --json answer into `w` (exact/io/json_writer.h): the members of
// the answer's object, into the object the caller opened, so that `wrenchkit COMMAND --json SCENE`
// prints exactly them in braces on one line (json_answer) and batch puts its "line" member first.
// `source` names the text in messages. It throws Input_error for a bad scene (exit 2), Undecided
// (exit 3), Self_check_failure (exit 4), and Usage_error when the options cannot apply to this scene
// (limit-surface's --sides on a large support), having written nothing or a part the caller drops.
// It may be called from several threads at once (each with its own writer).
using Scene_answer =
    std::function<void(Json_writer& w, const std::string& scene_text, const std::string& source)>;

// One --json answer: the members `write(Json_writer&)` writes, in braces, as one line's text (no newline).
template <class Write>
std::string json_answer(Write&& write, std::size_t reserve = 512) {
  Json_writer w(reserve);
  w.object();
  write(w);
  w.end_object();
  return w.take();
}

// A per-scene command from its parts: `read` takes its options once (before any scene), `answer` answers one
// scene through the pipeline, `json` (Json_writer&, options, item) writes the answer's members and `to_text`
// its text. per_scene gives its batch form (the command's --json answer per scene text); run_per_scene
// answers one scene and writes it.
template <class Read, class Answer, class Json>
Scene_answer per_scene(const Options& o, Read read, Answer answer, Json json) {
  return [o, opts = read(o), answer, json](Json_writer& w, const std::string& text, const std::string& source) {
    json(w, opts, answer(opts, o, text, source));
  };
}
template <class Read, class Answer, class Json, class Text>
int run_per_scene(const Options& o, const std::string& text, const std::string& source, Read read, Answer answer,
                  Json json, Text to_text) {
  const auto opts = read(o);
  const auto item = answer(opts, o, text, source);
  return write_answer(o, [&](Json_writer& w) { json(w, opts, item); }, [&] { return to_text(opts, item, source); });
}

// Each command's prepare_*_json reads what it needs of the (already validated) options once, checks
// how they combine (Usage_error), and returns its Scene_answer, which keeps them.
Scene_answer prepare_closure_json(const Options& o);
Scene_answer prepare_equilibrium_json(const Options& o);
Scene_answer prepare_labels_json(const Options& o);
Scene_answer prepare_dual_json(const Options& o);
Scene_answer prepare_reuleaux_json(const Options& o);
Scene_answer prepare_analyze_json(const Options& o);
Scene_answer prepare_limit_surface_json(const Options& o);
Scene_answer prepare_sliding_json(const Options& o);
Scene_answer prepare_hold_json(const Options& o);

// closure_command.cpp, equilibrium_command.cpp (analyze uses these pieces): the pipeline's items
// (exact/pipeline/pipeline.h) written as the members of a JSON answer and as text.
void write_closure(Json_writer& w, const Options& o, const Closure_item& r, const char* command);
std::string closure_human(const Closure_item& r, const Scene& scene);
int run_closure(const Options& o, const std::string& scene_text, const std::string& source, const char* command);
void write_equilibrium(Json_writer& w, const Options& o, const Equilibrium_item& r, const char* command);
std::string equilibrium_human(const Equilibrium_item& r);
int run_equilibrium(const Options& o, const std::string& scene_text, const std::string& source);

// analyze_command.cpp, batch_command.cpp, check_command.cpp
int run_analyze(const Options& o, const std::string& scene_text, const std::string& source, const char* command);
// batch: `answer` (the command's, prepared from `o`) on every line of standard input.
int run_batch(const Options& o, const Scene_answer& answer);
// One line of batch: the `n`th line's answer (or its error line) into `out` (no newline), and how it ended. Every
// front end's batch writes its lines with it (the Python bindings' wrenchkit.batch too).
Status batch_line(const Options& o, const Scene_answer& answer, const std::string& text, bool too_long,
                  std::size_t n, std::string& out);
int run_check(const Options& o);

// labels_command.cpp: labels, dual, reuleaux;  render_command.cpp: render
int run_labels(const Options& o, const std::string& scene_text, const std::string& source);
int run_quality(const Options& o, const std::string& scene_text, const std::string& source);
int run_grasp_regions(const Options& o, const std::string& scene_text, const std::string& source);
void write_grasp_regions(Json_writer& w, const Grasp_regions_item& r);  // grasp-regions --json
Scene_answer prepare_grasp_regions_json(const Options& o);
int run_push(const Options& o, const std::string& scene_text, const std::string& source);
void write_push(Json_writer& w, const Push_item& r);  // push --json
Scene_answer prepare_push_json(const Options& o);
Scene_answer prepare_quality_json(const Options& o);
Quality_query quality_query(const Options& o);  // --only, --norm, --normalize, --torque-scale, --about, --tolerance
void write_quality(Json_writer& w, const Quality_item& r);
std::string quality_human(const Quality_item& r);
std::string quality_body(const Quality_item& r);  // ε and μ* without the command's closure and closing lines
int run_dual(const Options& o, const std::string& scene_text, const std::string& source);
int run_reuleaux(const Options& o, const std::string& scene_text, const std::string& source);
int run_render(const Options& o, const std::string& scene_text, const std::string& source);
// reuleaux's motion from --center [--sense], --direction or --twist (none: no query); Usage_error for two of them.
Labels_query reuleaux_query(const Options& o);
// render's picture (--what, --sides) of one scene: the SVG text that `render` writes (the Python bindings' too).
std::string render_svg(const Options& o, const std::string& scene_text, const std::string& source,
                       bool* undecided = nullptr);

// hold_command.cpp (analyze uses these pieces): contacts and the support's friction against the load.
void write_hold(Json_writer& w, const Hold_item& r);
std::string hold_human(const Hold_item& r);
int run_hold(const Options& o, const std::string& scene_text, const std::string& source);

// limit_surface_command.cpp, sliding_command.cpp
int run_limit_surface(const Options& o, const std::string& scene_text, const std::string& source);
int run_sliding(const Options& o, const std::string& scene_text, const std::string& source);

// reference_command.cpp, compare_command.cpp: the conformance commands (conformance/), which the program binds
// (cli/command_table.h, Conformance_commands), not this library.
int run_reference(const Options& o);
int run_compare(const Options& o);

}  // namespace wrenchkit::cli
