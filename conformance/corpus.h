// The reference corpus' format (docs/reference-format.md), the conformance part's base: one scene's line through
// the pipeline — the verdicts and their certificates by answer_closure / answer_equilibrium (each certificate
// accepted by the independent checker before the line exists), the moment labels, the limit surface and the
// stick/slide answer of the scene's load by answer_support, the boundary measure [RF-1], and every exact number
// again as its nearest double ("approx") — the user's own scenes, and the corpus directory. Used by `wrenchkit
// reference` (conformance/reference.h: the built-in scenes, or the user's, --scenes) and by the Python bindings
// (wrenchkit.reference: the user's scenes), so both write the same bytes; no test scenery here.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "exact/io/json_writer.h"
#include "exact/numbers/limits.h"
#include "exact/pipeline/pipeline.h"

namespace wrenchkit {

// The corpus format version written in manifest.json ("wrenchkit_reference"). 2 (issue 29): `motion` may be
// "impending" and `hold` "impending" (a load on the boundary; version 1 called them "slides" and true); the
// certificates are format 3. compare reads versions 1 and 2.
inline constexpr int kReferenceFormat = 2;

// A scene of the corpus: where it comes from (empty strings are written as JSON null) and its text.
struct Reference_scene {
  std::string id, family, source, epsilon, side, seed;
  std::string text;   // the scene as given (any valid scene text)
  std::string where;  // names the text in messages ("FILE:LINE"); the id when empty
};

// The line and what a front end needs besides it; status/message as in pipeline.h (a bad scene is
// bad_input with the reader's message prefixed by `where`; a rejected certificate check_failed).
struct Reference_item {
  Status status = Status::answered;
  std::string message;
  std::string line;       // the corpus line (one JSON object, no newline)
  std::string canonical;  // the scene's canonical text (scenes/ID.json)
  std::string csv;        // "id,force_closure,form_closure,equilibrium"
  std::size_t certificates = 0;  // certificates in the line, every one accepted by the independent checker
  bool force_closure = false, form_closure = false;
  int rank_force = 0, rank_form = 0;
  std::optional<bool> balanced;  // with a load
};

// The corpus line of `scene` (limit surfaces with `sides`-gons, 4..64). Never throws. Exact answers
// (Mode::exact; stick/slide in Mode::hybrid, whose certified answers are exact ones).
Reference_item reference_item(const Reference_scene& scene, int sides);

// A corpus in memory: the scenes' ids and items in order, and how its making ended — answered, or the status and
// message of the first item that was not (its scenes before it kept).
struct Reference_corpus {
  Status status = Status::answered;
  std::string message;
  std::vector<std::string> ids;
  std::vector<Reference_item> items;  // per scene: its line, canonical text, CSV row
  std::size_t certificates = 0;       // all accepted by the independent checker
  // Appends `item`, the line of scene `id`; or, when the item was not answered, ends the corpus with its status
  // and message and returns false.
  bool add(const std::string& id, Reference_item item);
};

// The corpus of the user's own scenes read from PATH (read_user_scenes; Input_error for a bad file or line),
// limit surfaces with `sides`-gons.
Reference_corpus user_corpus(const std::string& path, int sides);

// The user's own scenes (`reference --scenes PATH`, docs/reference-format.md §7). PATH is a JSON-lines
// file — each non-blank line a scene, id "line.N" (N its line number), or {"id": ID, "family": F,
// "scene": SCENE} — or a directory, whose *.json files (recursively, in path order) are scenes with id
// their relative path without ".json" ('/' becomes '.') and family their directory ("user" at the top).
// Ids are [A-Za-z0-9_.-], at most 200 characters, not starting with '.', unique. Throws Input_error
// naming the file, line and field.
std::vector<Reference_scene> read_user_scenes(const std::string& path, const Input_limits& limits);

// Why DIR cannot receive a corpus ("" when it can: missing, empty, or an earlier corpus with our
// manifest.json).
std::string corpus_dir_problem(const std::string& dir);

// Writes a corpus: reference.jsonl, scenes/ID.json, expected.csv and `manifest` (manifest.json) into
// a temporary sibling, then replaces DIR in one rename (nothing half-written). Throws Input_error.
// Returns the size of reference.jsonl in bytes.
std::size_t write_corpus(const std::string& dir, const std::vector<std::string>& ids,
                         const std::vector<Reference_item>& items, const std::string& manifest);

// The manifest of a corpus of the user's scenes read from `scenes_from`.
std::string user_manifest(const std::string& scenes_from, int sides, std::size_t scenes);

// Writes `value` (a JSON document of exact answers) with every exact number — a JSON number, or a string
// that reads as one ("p/q", "1e-10") — as its nearest double (nearest_double; null beyond the double
// range), other strings, booleans and nulls as they are; members named "name" (free text) are kept.
void write_approx(Json_writer& w, const json::Value& value);

// A double as the shortest JSON number that reads back to it (std::to_chars).
void write_shortest(Json_writer& w, double d);

}  // namespace wrenchkit
