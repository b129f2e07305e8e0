// Another implementation's answers against the reference corpus (conformance/compare.h).
#include "conformance/compare.h"

#include <cctype>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "conformance/corpus.h"
#include "exact/io/input_error.h"
#include "exact/io/json.h"
#include "exact/io/json_writer.h"
#include "exact/io/outline.h"
#include "exact/io/scene.h"
#include "exact/sliding/motion.h"
#include "exact/sliding/push_locus.h"
#include "exact/statics/closure.h"

namespace wrenchkit {

namespace {

namespace fs = std::filesystem;

// A field's own distance to a degenerate boundary (corpus boundary.fields; [RF-1]). `measured`: the corpus
// measures this field (the verdicts); a value (power, centre of friction, motion) has no boundary measure.
struct Field_distance {
  bool measured = false;
  std::optional<double> distance;
  std::string nearest;
  long exact_zeros = 0;
};

struct Ref {
  std::string id, family, epsilon, side, scene_file, nearest;
  std::optional<double> distance;
  long exact_zeros = 0;
  std::map<std::string, bool> verdicts;  // force_closure, form_closure, equilibrium
  std::map<std::string, Field_distance> fields;  // force_closure, form_closure, equilibrium
  bool has_motion = false;               // the line has "motion" (a load on a support)
  std::string motion;                    // sticks, impending, slides, depends; empty: no certified answer
  bool has_hold = false;                 // the line has "hold" (a load)
  std::string hold;                      // true, impending, false, depends; empty: no certified answer (or refused)
  const json::Value* labels = nullptr;
  const json::Value* limit_surface = nullptr;
  bool has_push = false;                   // the line has "push" (a pusher on a support)
  std::string rotation;                    // ccw, cw, none, depends; empty: no certified answer (undecided or refused)
  bool has_contact = false;                // the line has "push.contact" (the pusher's contact mode)
  std::string contact_mode;                // sticks, impending, slides left, slides right; empty: not certified
  bool has_stable = false;                 // the line has "push.stable" (a line pusher: is its motion stable)
  std::string stable;                      // stable, unstable; empty: not certified
  bool has_quality = false;                // the line has "quality" (contacts)
  const json::Value* quality_epsilon = nullptr;  // quality.epsilon {lower, upper, …}; none: refused (too much work)
  const json::Value* scene = nullptr;            // the line's canonical scene
  const json::Value* regions_mu = nullptr;       // grasp_regions.mu: the line has fingers' regions (a polygon part)
  Field_distance distance_of(const std::string& field) const {
    // labels and ε: the friction reading's (ε is 0 exactly where force closure fails)
    const auto it = fields.find(field == "labels" || field == "epsilon" ? "force_closure" : field);
    return it == fields.end() ? Field_distance{} : it->second;
  }
};

// One twist of a power disagreement: the exact bracket, the peer's value, the relative error.
struct Power_detail {
  std::size_t index;
  const json::Value* twist;
  Rational lo, hi, answer;
  std::string answer_text;
  std::optional<double> relative_error;  // distance to the bracket over |hi|; none when hi = 0
};

struct Disagreement {
  const Ref* ref;
  std::string field, reference, answer;
  bool near = false;
  std::string kind;     // "falsely closed", … for verdicts; "value" for numbers and labels
  bool unsafe = false;  // the answer claims more than holds (closed, balanced, sticks)
  Field_distance at;    // the field's own distance
  const json::Value* reference_value = nullptr;  // for reference_approx
  std::vector<Power_detail> power;
};

// `boundary`: the reference is "impending" (the load on the boundary: friction can just hold it) and the answer
// names a side (sticks or slides, true or false) or "depends" — a convention at the boundary, neither unsafe nor
// lost, counted apart from agree and disagree.
struct Field_tally {
  std::size_t compared = 0, agree = 0, disagree = 0, no_answer = 0, unsafe = 0, lost = 0, boundary = 0;
};

const char* const kFields[] = {"force_closure", "form_closure", "equilibrium", "hold", "motion",
                               "center_of_friction", "power", "power_range", "labels", "epsilon", "rotation",
                               "contact_mode", "stable_push", "rotation_centre", "placements"};
bool is_verdict(const std::string& f) { return f == "force_closure" || f == "form_closure" || f == "equilibrium"; }

// The words of a wrong verdict: unsafe (the answer claims closure, balance, holding or sticking that does not
// hold) or lost (it misses one that does).
std::pair<std::string, bool> verdict_kind(const std::string& field, bool answer) {
  if (field == "equilibrium") return {answer ? "falsely balanced" : "falsely unbalanced", answer};
  return {answer ? "falsely closed" : "falsely open", answer};
}
const char* unsafe_words(const std::string& f) {
  return f == "equilibrium" ? "falsely balanced"
         : f == "motion"    ? "falsely sticks or impending"
         : f == "hold"      ? "falsely holds or impending"
         : f == "rotation"  ? "a rotation sense claimed that does not hold for every distribution"
         : f == "contact_mode" ? "a contact mode claimed that does not hold (sticks where it slides, or the wrong edge)"
         : f == "stable_push" ? "a line pusher's motion claimed stable (or unstable) that is not"
         : f == "rotation_centre" ? "a rotation centre no distribution can turn the body about (outside the certified bound)"
         : f == "placements" ? "a placement claimed closed that is open"
                            : "falsely closed";
}
const char* lost_words(const std::string& f) {
  return f == "equilibrium" ? "falsely unbalanced"
         : f == "motion"    ? "falsely slides, impending or depends"
         : f == "hold"      ? "falsely fails, impending or depends"
         : f == "rotation"  ? "depends or undecided where the rotation is certain"
         : f == "contact_mode" ? "undecided where the contact mode is certain"
         : f == "stable_push" ? "undecided where the stable push is certain"
         : f == "rotation_centre" ? "(none: a centre is consistent or impossible)"
         : f == "placements" ? "a placement claimed open that closes"
                            : "falsely open";
}
// Fields with a safety split (unsafe / lost): the verdicts, motion, hold and epsilon (across 0).
bool has_split(const std::string& f) {
  return is_verdict(f) || f == "motion" || f == "hold" || f == "epsilon" || f == "rotation" || f == "contact_mode" ||
         f == "stable_push" || f == "rotation_centre" || f == "placements";
}

Rational exact_number(const json::Value& v, const std::string& where) {
  std::string why;
  const Input_limits limits;
  std::optional<Rational> q;
  if (v.type == json::Type::number) q = parse_rational(v.text, true, limits, why);
  else if (v.type == json::Type::string) q = parse_rational(v.text, false, limits, why);
  else throw Input_error(where + ": a " + json::type_name(v.type) + " is not a number");
  if (!q) throw Input_error(where + ": \"" + v.text + "\" " + why);
  return *q;
}

// A verdict as implementations write it, in JSON lines and CSV alike: true/false; a number equal to 1 or 0
// (1, 0, 1.0, 0.0, 1e0: NumPy's integers and floats through json.dumps(default=int) or float columns with
// gaps in pandas); the strings "true"/"false" (any case: NumPy's booleans through default=str, pandas'
// True/False) and numbers written as strings ("1", "0.0"). nullopt for anything else (2, 0.5, "yes").
std::optional<bool> verdict_value(const json::Value& v) {
  if (v.type == json::Type::boolean) return v.boolean;
  if (v.type != json::Type::number && v.type != json::Type::string) return std::nullopt;
  if (v.type == json::Type::string) {
    std::string lower = v.text;
    for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (lower == "true") return true;
    if (lower == "false") return false;
  }
  std::string why;
  const std::optional<Rational> q = parse_rational(v.text, v.type == json::Type::number, Input_limits{}, why);
  if (q && (*q == 0 || *q == 1)) return *q == 1;
  return std::nullopt;
}
const char* const kVerdictWords = "true, false, 1, 0 (also 1.0, 0.0, \"true\", \"1\"; any case)";

struct Tolerance {
  Rational rtol, atol;
  bool close(const Rational& a, const Rational& r) const { return abs(a - r) <= atol + rtol * abs(r); }
};

// The corpus: every line parsed once and kept (labels and limit surfaces are compared from the DOM).
struct Corpus {
  fs::path dir;
  std::vector<json::Value> lines;
  std::vector<Ref> refs;
  std::map<std::string, std::size_t> index;
};

Corpus read_corpus(const std::string& path, Read_file read) {
  Corpus c;
  fs::path file = path;
  std::error_code ec;
  if (fs::is_directory(file, ec)) file /= "reference.jsonl";
  c.dir = file.parent_path();
  // The format version, when the manifest is there: 1 or 2 (docs/reference-format.md); a newer corpus is refused.
  if (const fs::path m = c.dir / "manifest.json"; fs::exists(m, ec)) {
    const json::Value manifest = json::parse(read(m.string(), std::size_t(1) << 20), Input_limits{}, m.string());
    const json::Value* v = manifest.find("wrenchkit_reference");
    if (!v || v->type != json::Type::number || (v->text != "1" && v->text != "2"))
      throw Input_error(m.string() + ": wrenchkit_reference: " + (v ? json::text_of(*v) : std::string("missing")) +
                        " is not a corpus format this compare reads (1 or 2; a newer wrenchkit writes newer ones)");
  }
  const std::string text = read(file.string(), std::size_t(1) << 32);
  Input_limits limits;
  limits.max_file_bytes = std::size_t(1) << 32;
  std::size_t start = 0, line = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    ++line;
    const std::string_view l(text.data() + start, end - start);
    start = end + 1;
    if (l.empty()) continue;
    c.lines.push_back(json::parse(l, limits, file.string() + ":" + std::to_string(line)));
  }
  if (c.lines.empty()) throw Input_error(file.string() + ": no reference lines (is it a 'wrenchkit reference' corpus?)");
  for (std::size_t i = 0; i < c.lines.size(); ++i) {
    const json::Value& v = c.lines[i];
    const std::string where = file.string() + ":" + std::to_string(i + 1);
    const json::Value* id = v.find("id");
    if (!id || id->type != json::Type::string) throw Input_error(where + ": id: missing (not a reference corpus line)");
    Ref r;
    r.id = id->text;
    auto str = [&](const char* key) {
      const json::Value* x = v.find(key);
      return x && x->type == json::Type::string ? x->text : std::string();
    };
    r.family = str("family");
    r.epsilon = str("epsilon");
    r.side = str("side");
    r.scene_file = str("scene_file");
    for (const char* f : {"force_closure", "form_closure", "equilibrium"})
      if (const json::Value* x = v.find(f); x && x->type == json::Type::boolean) r.verdicts[f] = x->boolean;
    r.labels = v.find("labels");
    r.limit_surface = v.find("limit_surface");
    if (r.limit_surface && r.limit_surface->type != json::Type::object) r.limit_surface = nullptr;  // refused
    if (const json::Value* q = v.find("quality")) {
      r.has_quality = true;
      if (q->type == json::Type::object) r.quality_epsilon = q->find("epsilon");
    }
    r.scene = v.find("scene");
    if (const json::Value* g = v.find("grasp_regions"); g && g->type == json::Type::object) r.regions_mu = g->find("mu");
    if (const json::Value* m = v.find("motion")) {
      r.has_motion = true;
      if (m->type == json::Type::string) r.motion = m->text;
    }
    if (const json::Value* pu = v.find("push")) {
      r.has_push = true;
      if (pu->type == json::Type::object)
        if (const json::Value* rot = pu->find("rotation"); rot && rot->type == json::Type::string && rot->text != "undecided")
          r.rotation = rot->text;
      if (pu->type == json::Type::object)
        if (const json::Value* k = pu->find("contact"); k && k->type == json::Type::object) {
          r.has_contact = true;
          if (const json::Value* m = k->find("mode"); m && m->type == json::Type::string && m->text != "undecided")
            r.contact_mode = m->text;
        }
      if (pu->type == json::Type::object)
        if (const json::Value* st = pu->find("stable"); st && st->type == json::Type::object) {
          r.has_stable = true;
          if (const json::Value* m = st->find("verdict"); m && m->type == json::Type::string && m->text != "undecided")
            r.stable = m->text;
        }
    }
    if (const json::Value* h = v.find("hold")) {
      r.has_hold = true;
      if (h->type == json::Type::boolean) r.hold = h->boolean ? "true" : "false";
      else if (h->type == json::Type::string) r.hold = h->text;
    }
    const auto read_distance = [](const json::Value& b, std::optional<double>& d, std::string& nearest, long& zeros) {
      if (const json::Value* x = b.find("distance"); x && x->type == json::Type::number) d = std::stod(x->text);
      if (const json::Value* n = b.find("nearest"); n && n->type == json::Type::string) nearest = n->text;
      if (const json::Value* z = b.find("exact_zero_determinants"); z && z->type == json::Type::number)
        zeros = std::stol(z->text);
    };
    if (const json::Value* b = v.find("boundary")) {
      read_distance(*b, r.distance, r.nearest, r.exact_zeros);
      // Each verdict's own distance; a corpus written before boundary.fields: the scene's.
      const json::Value* fields = b->find("fields");
      for (const auto& [f, verdict] : r.verdicts) {
        Field_distance& fd = r.fields[f];
        fd.measured = true;
        const json::Value* x = fields ? fields->find(f) : nullptr;
        if (x) read_distance(*x, fd.distance, fd.nearest, fd.exact_zeros);
        else fd.distance = r.distance, fd.nearest = r.nearest, fd.exact_zeros = r.exact_zeros;
      }
      // hold's own distance: only without a support, where hold is equilibrium (over a support: none, like motion).
      if (const json::Value* x = fields ? fields->find("hold") : nullptr) {
        Field_distance& fd = r.fields["hold"];
        fd.measured = true;
        read_distance(*x, fd.distance, fd.nearest, fd.exact_zeros);
      }
    }
    if (!c.index.emplace(r.id, c.refs.size()).second) throw Input_error(where + ": id: \"" + r.id + "\" appears twice");
    c.refs.push_back(std::move(r));
  }
  return c;
}

// One answer: field name → value (JSON lines give the DOM; CSV cells become booleans or null).
struct Answer {
  std::string where;  // "FILE:LINE"
  std::string id;
  std::vector<std::pair<std::string, json::Value>> fields;
  bool error = false;
};

std::vector<Answer> read_jsonl_answers(const std::string& path, const std::string& text, const Input_limits& limits) {
  std::vector<Answer> out;
  json::for_each_object_line(text, limits, path, "an answer",
                             [&](std::size_t, const std::string& where, std::string_view, json::Value& v) {
    Answer a;
    a.where = where;
    for (auto& [k, x] : v.members) {
      if (k == "id") {
        if (x.type != json::Type::string) throw Input_error(where + ": id: " + json::text_of(x) + " is not a string");
        a.id = x.text;
      } else if (k == "error") {
        if (x.type != json::Type::string && x.type != json::Type::null)
          throw Input_error(where + ": error: " + json::text_of(x) + " is not a string");
        a.error = x.type == json::Type::string;
      } else if (!k.empty() && k[0] == '_') {
        continue;
      } else if (std::find(std::begin(kFields), std::end(kFields), k) == std::end(kFields)) {
        throw Input_error(where + ": " + json::quote(k) +
                          ": unknown field (known: id, force_closure, form_closure, equilibrium, hold, motion, "
                          "center_of_friction, power, power_range, labels, epsilon, rotation, contact_mode, stable_push, rotation_centre, "
                          "placements, "
                          "error; fields "
                          "starting with _ "
                          "are ignored)");
      } else {
        a.fields.emplace_back(k, std::move(x));
      }
    }
    if (a.id.empty()) throw Input_error(where + ": id: missing");
    out.push_back(std::move(a));
  });
  return out;
}

// The cells of one CSV line (RFC 4180 within a line): a cell is plain text or "quoted", with "" for a
// quote inside quotes; blanks around a cell are ignored (pandas and csv.writer output both read).
std::vector<std::string> csv_cells(const std::string& l, const std::string& where) {
  std::vector<std::string> cells(1);
  std::size_t i = 0;
  const auto blank = [&](std::size_t k) { return k < l.size() && (l[k] == ' ' || l[k] == '\t'); };
  for (;;) {
    while (blank(i)) ++i;
    if (i < l.size() && l[i] == '"') {
      for (++i;; ++i) {
        if (i >= l.size()) throw Input_error(where + ": a quoted cell is not closed (a \" is missing)");
        if (l[i] == '"') {
          if (i + 1 < l.size() && l[i + 1] == '"') cells.back() += '"', ++i;
          else break;
        } else {
          cells.back() += l[i];
        }
      }
      ++i;
      while (blank(i)) ++i;
      if (i < l.size() && l[i] != ',')
        throw Input_error(where + ": text after a quoted cell: \"" + l.substr(i, 20) + "\"");
    } else {
      std::size_t end = l.find(',', i);
      if (end == std::string::npos) end = l.size();
      std::size_t last = end;
      while (last > i && (l[last - 1] == ' ' || l[last - 1] == '\t')) --last;
      cells.back() = l.substr(i, last - i);
      if (cells.back().find('"') != std::string::npos)
        throw Input_error(where + ": a quote inside an unquoted cell: \"" + cells.back() + "\"");
      i = end;
    }
    if (i >= l.size()) return cells;
    ++i;  // the comma
    cells.emplace_back();
  }
}

std::vector<Answer> read_csv_answers(const std::string& path, const std::string& text) {
  std::vector<Answer> out;
  std::vector<std::string> header;
  std::size_t start = 0, line = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    ++line;
    std::string l = text.substr(start, end - start);
    start = end + 1;
    if (!l.empty() && l.back() == '\r') l.pop_back();
    if (l.find_first_not_of(" \t") == std::string::npos) continue;
    const std::string where = path + ":" + std::to_string(line);
    const std::vector<std::string> cells = csv_cells(l, where);
    if (header.empty()) {
      header = cells;
      if (header[0] != "id") throw Input_error(where + ": the header's first column must be id, not \"" + header[0] + "\"");
      for (std::size_t i = 1; i < header.size(); ++i) {
        const std::string& h = header[i];
        if (h != "force_closure" && h != "form_closure" && h != "equilibrium" && h != "hold")
          throw Input_error(where + ": column " + std::to_string(i + 1) + ": \"" + h +
                            "\" is not one of force_closure, form_closure, equilibrium, hold");
        if (std::count(header.begin(), header.end(), h) > 1) throw Input_error(where + ": column \"" + h + "\" appears twice");
      }
      continue;
    }
    if (cells.size() != header.size())
      throw Input_error(where + ": " + std::to_string(cells.size()) + " cells, the header has " +
                        std::to_string(header.size()));
    Answer a;
    a.where = where;
    a.id = cells[0];
    if (a.id.empty()) throw Input_error(where + ": id: empty");
    for (std::size_t i = 1; i < cells.size(); ++i) {
      json::Value v, cell;
      const std::string& c = cells[i];
      cell.type = json::Type::string, cell.text = c;
      if (const std::optional<bool> b = verdict_value(cell)) v.type = json::Type::boolean, v.boolean = *b;
      else if (header[i] == "hold" && (c == "depends" || c == "impending")) v = cell;
      else if (!c.empty())
        throw Input_error(where + ": " + header[i] + ": \"" + c + "\" is not true, false (any case), 1, 0 (or 1.0, 0.0)" +
                          (header[i] == "hold" ? ", impending, depends" : "") + " or empty");
      a.fields.emplace_back(header[i], v);
    }
    out.push_back(std::move(a));
  }
  if (header.empty()) throw Input_error(path + ": empty (a CSV answer file needs a header line: id,force_closure,...)");
  return out;
}

// Compares a region-like answer {"empty", "shape", "vertices"} with the reference REGION.
std::optional<std::string> region_mismatch(const json::Value& ans, const json::Value& ref, const std::string& where,
                                           const Tolerance& tol) {
  if (ans.type != json::Type::object) throw Input_error(where + ": " + json::text_of(ans) + " is not an object");
  for (const auto& [k, v] : ans.members) {
    if (k == "empty") {
      if (v.type != json::Type::boolean) throw Input_error(where + ".empty: " + json::text_of(v) + " is not true or false");
      const json::Value* r = ref.find("empty");
      if (r && r->boolean != v.boolean) return std::string("empty ") + (r->boolean ? "true" : "false");
    } else if (k == "shape") {
      if (v.type != json::Type::string) throw Input_error(where + ".shape: " + json::text_of(v) + " is not a string");
      const json::Value* r = ref.find("shape");
      if (r && r->text != v.text) return "shape " + json::quote(r->text);
    } else if (k == "vertices") {
      if (v.type != json::Type::array) throw Input_error(where + ".vertices: " + json::text_of(v) + " is not an array");
      std::vector<std::array<Rational, 2>> a, r;
      for (std::size_t i = 0; i < v.items.size(); ++i) {
        const json::Value& p = v.items[i];
        const std::string w = where + ".vertices[" + std::to_string(i) + "]";
        if (p.type != json::Type::array || p.items.size() != 2) throw Input_error(w + ": " + json::text_of(p) + " is not [x, y]");
        a.push_back({exact_number(p.items[0], w + "[0]"), exact_number(p.items[1], w + "[1]")});
      }
      if (const json::Value* rv = ref.find("vertices"))
        for (const json::Value& p : rv->items) r.push_back({exact_number(p.items[0], "reference"), exact_number(p.items[1], "reference")});
      auto covered = [&](const std::vector<std::array<Rational, 2>>& x, const std::vector<std::array<Rational, 2>>& y) {
        for (const auto& p : x) {
          bool found = false;
          for (const auto& q : y) found |= tol.close(p[0], q[0]) && tol.close(p[1], q[1]);
          if (!found) return false;
        }
        return true;
      };
      if (a.size() != r.size() || !covered(a, r) || !covered(r, a))
        return "vertices " + (ref.find("vertices") ? json::text_of(*ref.find("vertices")) : std::string("[]"));
    } else {
      throw Input_error(where + ": " + json::quote(k) + ": unknown field (known: empty, shape, vertices)");
    }
  }
  return std::nullopt;
}

struct Comparison {
  std::map<std::string, Field_tally> fields;
  std::map<std::string, std::map<std::string, Field_tally>> families;  // family → field → tally
  std::vector<Disagreement> disagreements;
  std::size_t answered = 0, errors = 0;
};

// The relative error of h against the bracket [lo, hi]: its distance to the bracket over |hi|.
std::optional<double> relative_error(const Rational& h, const Rational& lo, const Rational& hi) {
  if (hi == 0) return std::nullopt;
  const Rational d = h < lo ? lo - h : h > hi ? h - hi : Rational(0);
  return nearest_double(d / abs(hi));
}

Comparison compare(const Corpus& corpus, const std::vector<Answer>& answers, const Tolerance& tol) {
  Comparison c;
  std::set<std::string> seen;
  for (const Answer& a : answers) {
    const auto it = corpus.index.find(a.id);
    if (it == corpus.index.end()) throw Input_error(a.where + ": id: \"" + a.id + "\" is not in the corpus");
    if (!seen.insert(a.id).second) throw Input_error(a.where + ": id: \"" + a.id + "\" is answered twice");
    const Ref& ref = corpus.refs[it->second];
    ++c.answered;
    c.errors += a.error;
    for (const auto& entry : a.fields) {
      const std::string& field = entry.first;  // a named reference: lambdas may capture it (C++17)
      const auto& v = entry.second;
      Field_tally& t = c.fields[field];
      Field_tally& ft = c.families[ref.family][field];
      const auto count = [&](std::size_t Field_tally::*n) { ++(t.*n), ++(ft.*n); };
      const auto disagree = [&](Disagreement d) {
        d.ref = &ref;
        d.field = field;
        d.at = ref.distance_of(field);
        c.disagreements.push_back(std::move(d));
        count(&Field_tally::disagree);
        if (c.disagreements.back().kind != "value") count(c.disagreements.back().unsafe ? &Field_tally::unsafe : &Field_tally::lost);
      };
      // hold and motion, one rule (docs/reference-format.md §6): agree; on an impending reference a side is the
      // boundary, neither unsafe nor lost; else a disagreement, unsafe where the answer claims friction holds (with
      // margin, `held`, or just, "impending") and the reference does not hold with margin.
      const auto outcome = [&](const std::string& reference, const std::string& answer, const char* held,
                               const std::string& word) {
        count(&Field_tally::compared);
        if (reference == answer) return count(&Field_tally::agree);
        if (reference == "impending") return count(&Field_tally::boundary);
        Disagreement d;
        d.reference = reference;
        d.answer = answer;
        d.unsafe = answer == held || (answer == "impending" && reference != held);
        d.kind = "falsely " + word;
        disagree(std::move(d));
      };
      const std::string where = a.where + ": " + field;
      const bool applicable = field == "equilibrium"                                  ? ref.verdicts.count(field) != 0
                              : field == "motion"                                     ? ref.has_motion
                              : field == "hold"                                       ? ref.has_hold
                              : field == "rotation"                                   ? ref.has_push
                              : field == "contact_mode"                               ? ref.has_contact
                              : field == "stable_push"                                ? ref.has_stable
                              : field == "rotation_centre"                            ? ref.has_push
                              : field == "center_of_friction" || field == "power"     ? ref.limit_surface != nullptr
                              : field == "power_range"                                ? ref.limit_surface != nullptr
                              : field == "epsilon"                                    ? ref.has_quality
                              : field == "placements"                                 ? ref.regions_mu != nullptr
                                                                                      : true;
      if (v.type == json::Type::null) {
        // No answer; not counted where the scene has nothing to answer (equilibrium without a load).
        if (applicable) count(&Field_tally::no_answer);
        continue;
      }
      if (is_verdict(field)) {
        const std::optional<bool> b = verdict_value(v);
        if (!b) throw Input_error(where + ": " + json::text_of(v) + " is not " + kVerdictWords + " or null");
        const auto r = ref.verdicts.find(field);
        if (r == ref.verdicts.end()) throw Input_error(where + ": scene \"" + a.id + "\" has no load (no equilibrium answer)");
        count(&Field_tally::compared);
        if (r->second == *b) {
          count(&Field_tally::agree);
        } else {
          Disagreement d;
          d.reference = r->second ? "true" : "false";
          d.answer = *b ? "true" : "false";
          std::tie(d.kind, d.unsafe) = verdict_kind(field, *b);
          disagree(std::move(d));
        }
      } else if (field == "hold") {
        // A verdict (true/false, 1/0, …), "impending" (on the boundary) or "depends" (an unknown distribution).
        std::string h;
        if (v.type == json::Type::string && (v.text == "depends" || v.text == "impending")) h = v.text;
        else if (const std::optional<bool> b = verdict_value(v)) h = *b ? "true" : "false";
        else
          throw Input_error(where + ": " + json::text_of(v) + " is not " + kVerdictWords +
                            ", \"impending\", \"depends\" or null");
        if (!ref.has_hold) throw Input_error(where + ": scene \"" + a.id + "\" has no load (no hold answer)");
        if (ref.hold.empty()) continue;  // the corpus has no certified answer (undecided or refused): nothing to compare
        outcome(ref.hold, h, "true", h == "true" ? "holds" : h == "false" ? "fails" : h);
      } else if (field == "rotation") {
        // Which way a pushed body turns (docs/pushing.md): unsafe where the answer claims a sense (ccw, cw or none)
        // that is not the certain one — or any where the truth depends on the distribution —, lost where it says
        // depends or undecided and the sense is certain.
        if (v.type != json::Type::string || (v.text != "ccw" && v.text != "cw" && v.text != "none" &&
                                             v.text != "depends" && v.text != "undecided"))
          throw Input_error(where + ": " + json::text_of(v) +
                            " is not \"ccw\", \"cw\", \"none\", \"depends\", \"undecided\" or null");
        if (!ref.has_push) throw Input_error(where + ": scene \"" + a.id + "\" has no pusher on a support (no rotation answer)");
        if (ref.rotation.empty()) continue;  // the corpus has no certified answer: nothing to compare with
        count(&Field_tally::compared);
        if (v.text == ref.rotation) {
          count(&Field_tally::agree);
        } else {
          Disagreement d;
          d.reference = ref.rotation;
          d.answer = v.text;
          d.unsafe = v.text != "depends" && v.text != "undecided";
          d.kind = d.unsafe ? "a wrong rotation" : "an uncertain rotation";
          disagree(std::move(d));
        }
      } else if (field == "contact_mode") {
        // Whether the pusher's contact sticks or slides (docs/pushing.md, PU-2): unsafe where the answer claims a mode
        // that is not the reference's (sticking where it slides — a plan that expects the body to follow the pusher —,
        // or the wrong edge), lost where it says undecided; the reference "impending" (the force on a cone edge
        // exactly) is the boundary, where a side is a convention.
        if (v.type != json::Type::string || (v.text != "sticks" && v.text != "impending" && v.text != "slides left" &&
                                             v.text != "slides right" && v.text != "depends" && v.text != "undecided"))
          throw Input_error(where + ": " + json::text_of(v) +
                            " is not \"sticks\", \"impending\", \"slides left\", \"slides right\", \"depends\", "
                            "\"undecided\" or null");
        if (!ref.has_contact)
          throw Input_error(where + ": scene \"" + a.id + "\" has no contact mode (no pusher on support points with every force given)");
        if (ref.contact_mode.empty()) continue;  // the corpus has no certified answer: nothing to compare with
        count(&Field_tally::compared);
        if (v.text == ref.contact_mode) {
          count(&Field_tally::agree);
        } else if (ref.contact_mode == "impending" && v.text != "undecided") {
          count(&Field_tally::boundary);
        } else {
          Disagreement d;
          d.reference = ref.contact_mode;
          d.answer = v.text;
          // (a mode where the reference "depends" claims a certainty that does not hold; "depends" where it is certain
          // is lost, as undecided)
          d.unsafe = v.text != "undecided" && v.text != "depends";
          d.kind = d.unsafe ? (v.text == "sticks" ? "falsely sticks" : "a wrong contact mode") : "an uncertain contact mode";
          disagree(std::move(d));
        }
      } else if (field == "stable_push") {
        // Whether a line pusher's motion keeps the body with it for every distribution (docs/pushing.md, PU-3): unsafe
        // where the answer claims a verdict that is not the reference's (stable where the contact breaks — a plan that
        // expects the part to stay on the fence —, or unstable where it holds), lost where it says undecided.
        if (v.type != json::Type::string || (v.text != "stable" && v.text != "unstable" && v.text != "undecided"))
          throw Input_error(where + ": " + json::text_of(v) + " is not \"stable\", \"unstable\", \"undecided\" or null");
        if (!ref.has_stable)
          throw Input_error(where + ": scene \"" + a.id + "\" has no line pusher on a support (no stable_push answer)");
        if (ref.stable.empty()) continue;  // the corpus has no certified answer: nothing to compare with
        count(&Field_tally::compared);
        if (v.text == ref.stable) {
          count(&Field_tally::agree);
        } else {
          Disagreement d;
          d.reference = ref.stable;
          d.answer = v.text;
          d.unsafe = v.text != "undecided";
          d.kind = d.unsafe ? (v.text == "stable" ? "falsely stable" : "falsely unstable") : "an uncertain stable push";
          disagree(std::move(d));
        }
      } else if (field == "rotation_centre") {
        // A point pusher's rotation centre [x, y] (a simulation's answer for its own pressure distribution), tested
        // exactly against the certified outer bound of the centres over every distribution (docs/pushing.md --locus,
        // PU-4): outside every piece of the senses the certain rotation allows — no admissible distribution turns the
        // body about it — is unsafe; inside, consistent (counted as agree: the bound cannot say more).
        if (!ref.has_push) throw Input_error(where + ": scene \"" + a.id + "\" has no pusher on a support (no rotation_centre)");
        if (v.type != json::Type::array || v.items.size() != 2)
          throw Input_error(where + ": " + json::text_of(v) + " is not a point [x, y]");
        const Vec2 q{exact_number(v.items[0], where + "[0]"), exact_number(v.items[1], where + "[1]")};
        if (ref.rotation.empty() || ref.rotation == "depends") continue;  // (no certain sense: the bound is not given)
        const Scene scene = read_scene(json::text_of(*ref.scene), Input_limits{}, a.id);
        if (!scene.pusher || scene.pusher->line()) continue;  // (a line pusher's centres are its stable region)
        const Push_locus g = push_locus(Support_model(scene), *scene.pusher, {ref.rotation == "ccw", ref.rotation == "cw"});
        if (!g.friction_centre) continue;
        count(&Field_tally::compared);
        bool possible = false;
        for (const Locus_side& side : g.side)
          for (const Locus_piece& piece : side.pieces)
            possible = possible || (side.possible && std::all_of(piece.halfplanes.begin(), piece.halfplanes.end(),
                                                                 [&](const Locus_halfplane& h) { return dot(h.h.a, q) <= h.h.b; }));
        if (possible) {
          count(&Field_tally::agree);
        } else {
          Disagreement d;
          d.reference = ref.rotation == "none" ? "none (the body translates)" : "turns " + ref.rotation + " about a centre in the certified bound";
          d.answer = json::text_of(v);
          d.unsafe = true;
          d.kind = "an impossible rotation centre";
          disagree(std::move(d));
        }
      } else if (field == "motion") {
        if (v.type != json::Type::string ||
            (v.text != "sticks" && v.text != "impending" && v.text != "slides" && v.text != "depends"))
          throw Input_error(where + ": " + json::text_of(v) +
                            " is not \"sticks\", \"impending\", \"slides\", \"depends\" or null");
        if (!ref.has_motion)
          throw Input_error(where + ": scene \"" + a.id + "\" has no load on a support (no motion answer)");
        if (ref.motion.empty()) continue;  // the corpus has no certified answer: nothing to compare with
        outcome(ref.motion, v.text, "sticks", v.text);
      } else if (field == "center_of_friction" || field == "power" || field == "power_range") {
        if (!ref.limit_surface)
          throw Input_error(where + ": scene \"" + a.id + "\" has no support (no " + field + " answer)");
        if (v.type != json::Type::array) throw Input_error(where + ": " + json::text_of(v) + " is not an array");
        const json::Value* dist = ref.limit_surface->find("distribution");
        const bool unknown = dist && dist->type == json::Type::string && dist->text == "unknown";
        if (field == "center_of_friction" && unknown)
          throw Input_error(where + ": scene \"" + a.id + "\" has an unknown distribution (no one centre of friction)");
        if (field == "power" && unknown)
          throw Input_error(where + ": scene \"" + a.id + "\" has an unknown distribution (answer power_range)");
        if (field == "power_range" && !unknown)
          throw Input_error(where + ": scene \"" + a.id + "\" has a known distribution (answer power)");
        bool ok = true, incomplete = false;
        Disagreement d;
        d.kind = "value";
        if (field == "center_of_friction") {
          if (v.items.size() != 2) throw Input_error(where + ": " + json::text_of(v) + " is not [x, y]");
          const json::Value& r = *ref.limit_surface->find("center_of_friction");
          d.reference = json::text_of(r);
          d.reference_value = &r;
          for (std::size_t i = 0; i < 2; ++i) {
            if (v.items[i].type == json::Type::null) {
              incomplete = true;
              continue;
            }
            ok &= tol.close(exact_number(v.items[i], where + "[" + std::to_string(i) + "]"),
                            exact_number(r.items[i], "reference"));
          }
        } else {
          const json::Value& twists = *ref.limit_surface->find("twists");
          if (v.items.size() != twists.items.size())
            throw Input_error(where + ": " + std::to_string(v.items.size()) + " values, the scene has " +
                              std::to_string(twists.items.size()) + " twists (limit_surface.twists)");
          d.reference = "[";
          for (std::size_t i = 0; i < v.items.size(); ++i) {
            const json::Value& tw = twists.items[i];
            const std::string w = where + "[" + std::to_string(i) + "]";
            if (field == "power") {
              const json::Value& br = *tw.find("power_bracket");
              d.reference += (i ? ", " : "") + json::text_of(br);
              if (v.items[i].type == json::Type::null) {
                incomplete = true;
                continue;
              }
              const Rational h = exact_number(v.items[i], w);
              const Rational lo = exact_number(br.items[0], "reference"), hi = exact_number(br.items[1], "reference");
              const Rational slack = tol.atol + tol.rtol * abs(hi);
              if (h < lo - slack || h > hi + slack) {
                ok = false;
                d.power.push_back({i, tw.find("twist"), lo, hi, h, json::text_of(v.items[i]), relative_error(h, lo, hi)});
              }
            } else {  // power_range: [min, max] over the admissible distributions, each within the tolerance
              const json::Value& br = *tw.find("power_range");
              d.reference += (i ? ", " : "") + json::text_of(br);
              if (v.items[i].type == json::Type::null) {
                incomplete = true;
                continue;
              }
              if (v.items[i].type != json::Type::array || v.items[i].items.size() != 2)
                throw Input_error(w + ": " + json::text_of(v.items[i]) + " is not [min, max]");
              for (std::size_t k = 0; k < 2; ++k) {
                if (v.items[i].items[k].type == json::Type::null) {
                  incomplete = true;
                  continue;
                }
                const Rational h = exact_number(v.items[i].items[k], w + "[" + std::to_string(k) + "]");
                const Rational r = exact_number(br.items[k], "reference");
                if (!tol.close(h, r)) {
                  ok = false;
                  d.power.push_back({i, tw.find("twist"), r, r, h, json::text_of(v.items[i].items[k]),
                                     relative_error(h, r, r)});
                }
              }
            }
          }
          d.reference += "]";
        }
        if (ok && incomplete) {  // some values missing, the rest right: no answer, not agreement
          count(&Field_tally::no_answer);
          continue;
        }
        count(&Field_tally::compared);
        if (ok) {
          count(&Field_tally::agree);
        } else {
          d.answer = json::text_of(v);
          disagree(std::move(d));
        }
      } else if (field == "placements") {
        // Sampled finger placements on a polygon part (docs/grasp-regions.md): each [{"edges": [i, j] or [i, j, k],
        // "s": [...], "closed": verdict}] decided here exactly — the engine's closure decision of the placed
        // frictional fingers with the line's grasp_regions.mu —; one count per placement: a placement claimed closed
        // that is open is unsafe, one claimed open that closes is lost (an open set: its boundary is open).
        if (!ref.regions_mu) throw Input_error(where + ": scene \"" + a.id + "\" is not a polygon part with fingers' regions");
        if (v.type != json::Type::array) throw Input_error(where + ": " + json::text_of(v) + " is not an array of placements");
        const Scene part = read_scene(json::text_of(*ref.scene), Input_limits{}, a.id);
        const std::vector<Vec2>& V = part.body.outline;
        const Rational mu = exact_number(*ref.regions_mu, "reference");
        for (std::size_t k = 0; k < v.items.size(); ++k) {
          const json::Value& p = v.items[k];
          const std::string at = where + "[" + std::to_string(k) + "]";
          if (p.type != json::Type::object) throw Input_error(at + ": " + json::text_of(p) + " is not {\"edges\", \"s\", \"closed\"}");
          const json::Value *edges = p.find("edges"), *params = p.find("s"), *closed = p.find("closed");
          for (const auto& m : p.members)
            if (m.first != "edges" && m.first != "s" && m.first != "closed" && (m.first.empty() || m.first[0] != '_'))
              throw Input_error(at + ": " + json::quote(m.first) + ": unknown field (known: edges, s, closed)");
          if (!edges || !params || !closed) throw Input_error(at + ": expected \"edges\", \"s\" and \"closed\"");
          if (edges->type != json::Type::array || (edges->items.size() != 2 && edges->items.size() != 3))
            throw Input_error(at + ".edges: " + json::text_of(*edges) + " is not [i, j] or [i, j, k]");
          if (params->type != json::Type::array || params->items.size() != edges->items.size())
            throw Input_error(at + ".s: " + json::text_of(*params) + " is not one parameter per finger");
          std::vector<std::size_t> on;
          std::vector<Rational> at_s;
          std::string text = "edges " + json::text_of(*edges) + " at s = (";
          for (std::size_t f = 0; f < edges->items.size(); ++f) {
            const Rational e = exact_number(edges->items[f], at + ".edges");
            if (e.get_den() != 1 || sgn(e) < 0 || e >= static_cast<long>(V.size()))
              throw Input_error(at + ".edges: " + edges->items[f].text + " is not an edge of the outline (0 to " +
                                std::to_string(V.size() - 1) + ")");
            const std::size_t edge = static_cast<std::size_t>(e.get_num().get_ui());
            const Rational t = exact_number(params->items[f], at + ".s");
            if (sgn(t) < 0 || t > 1) throw Input_error(at + ".s: " + params->items[f].text + " is not in [0, 1]");
            on.push_back(edge), at_s.push_back(t);
            text += (f ? ", " : "") + params->items[f].text;
          }
          text += ")";
          if (closed->type == json::Type::null) {
            count(&Field_tally::no_answer);
            continue;
          }
          const std::optional<bool> claim = verdict_value(*closed);
          if (!claim) throw Input_error(at + ".closed: " + json::text_of(*closed) + " is not " + kVerdictWords + " or null");
          const bool truth = decide_closure(with_fingers(part, mu, on, at_s), Property::force_closure, Mode::exact, false).holds;
          count(&Field_tally::compared);
          if (truth == *claim) {
            count(&Field_tally::agree);
            continue;
          }
          Disagreement d;
          d.reference = std::string(truth ? "closed" : "open") + " at " + text;
          d.answer = *claim ? "closed" : "open";
          std::tie(d.kind, d.unsafe) = verdict_kind("force_closure", *claim);
          disagree(std::move(d));
        }
      } else if (field == "epsilon") {
        // ε within the tolerance of the certified bracket [lower, upper]; wrong across ε = 0 is a wrong closure
        // verdict (a positive ε for an open grasp: unsafe; zero for a closed one: lost), else a wrong value
        if (!ref.has_quality) throw Input_error(where + ": scene \"" + a.id + "\" has no contacts (no epsilon answer)");
        if (!ref.quality_epsilon) continue;  // refused by the engine's work bound: nothing to compare with
        const Rational h = exact_number(v, where);
        const Rational lo = exact_number(*ref.quality_epsilon->find("lower"), "reference");
        const Rational hi = exact_number(*ref.quality_epsilon->find("upper"), "reference");
        const Rational slack = tol.atol + tol.rtol * abs(hi);
        count(&Field_tally::compared);
        if (h >= lo - slack && h <= hi + slack) {
          count(&Field_tally::agree);
          continue;
        }
        Disagreement d;
        d.kind = "value";
        if (hi == 0 && h > slack) d.kind = "falsely closed", d.unsafe = true;
        else if (lo > 0 && h <= slack) d.kind = "falsely open";
        d.reference = "[" + ref.quality_epsilon->find("lower")->text + ", " + ref.quality_epsilon->find("upper")->text + "]";
        d.reference_value = ref.quality_epsilon;
        d.answer = json::text_of(v);
        disagree(std::move(d));
      } else if (field == "labels") {
        if (v.type != json::Type::object) throw Input_error(where + ": " + json::text_of(v) + " is not an object");
        count(&Field_tally::compared);
        std::string why;
        for (const auto& [k, region] : v.members) {
          if (k != "plus" && k != "minus")
            throw Input_error(where + ": " + json::quote(k) + ": unknown field (known: plus, minus)");
          if (region.type == json::Type::null) continue;
          if (auto m = region_mismatch(region, *ref.labels->find(k), where + "." + k, tol))
            why += (why.empty() ? "" : "; ") + k + ": reference " + *m;
        }
        if (why.empty()) {
          count(&Field_tally::agree);
        } else {
          Disagreement d;
          d.kind = "value";
          d.reference = why;
          d.answer = json::text_of(v);
          d.reference_value = ref.labels;
          disagree(std::move(d));
        }
      }
    }
  }
  return c;
}

std::string double_text(double d) {
  std::ostringstream x;  // the stream's default format (%g, 6 significant digits)
  x << d;
  return x.str();
}

// Where a disagreement stands: far (its field's distance above the threshold), near (within it, or an
// exact degeneracy), or unmeasured (no distance for this field).
enum class Place { far, unmeasured, near };
Place place_of(const Disagreement& d) {
  if (!d.at.measured || (!d.at.distance && d.at.exact_zeros == 0)) return Place::unmeasured;
  return d.near ? Place::near : Place::far;
}

std::string distance_text(const Disagreement& d) {
  const Field_distance& f = d.at;
  std::ostringstream s;
  if (!f.measured)
    s << "no boundary measure for " << d.field
      << (d.field == "motion" ? " (how close the load is to the limit surface is not measured)"
          : d.field == "hold"   ? " (over a support, how close the load is to holding is not measured)"
          : d.field == "rotation" ? " (how close a voting line passes the centre of friction is not measured)"
          : d.field == "contact_mode" ? " (how close the pusher's velocity is to a motion-cone edge is not measured)"
          : d.field == "stable_push" ? " (how close the fence's load is to its composite cone's boundary is not measured)"
          : d.field == "rotation_centre" ? " (how far the centre is from the certified bound is not measured)"
          : d.field == "placements" ? " (each placement decided exactly; how far it is from the region's boundary is not measured)"
                              : " (a value: compared within --rtol/--atol)");
  else if (f.distance)
    s << (d.field == "epsilon" ? "force closure (where epsilon becomes 0)" : d.field) << " distance " << *f.distance << " (" << f.nearest << ")";
  else
    s << d.field << " distance unknown (no nonzero deciding determinant and no friction scale that flips it)";
  if (f.exact_zeros) s << ", " << f.exact_zeros << " exactly degenerate determinant" << (f.exact_zeros == 1 ? "" : "s");
  return s.str();
}

// The suggestion when most far disagreements sit within a plausible documented tolerance (≤ 10^-3) of a
// boundary: the smallest power of ten that covers every one of them within 10^-3, when those are more
// than half; nullopt otherwise.
std::optional<std::string> suggested_tolerance(const std::vector<Disagreement>& ds, std::size_t& covered,
                                               std::size_t& far) {
  std::vector<double> d;
  for (const Disagreement& x : ds)
    if (place_of(x) == Place::far) d.push_back(*x.at.distance);
  far = d.size();
  std::sort(d.begin(), d.end());
  const std::size_t within = static_cast<std::size_t>(std::upper_bound(d.begin(), d.end(), 1e-3) - d.begin());
  if (far < 2 || 2 * within <= far) return std::nullopt;
  const double largest = d[within - 1];
  int k = static_cast<int>(std::ceil(std::log10(largest)));
  if (std::pow(10.0, k) < largest) ++k;
  covered = within;
  return "1e" + std::to_string(k);
}

void write_tally(Json_writer& w, const std::string& field, const Field_tally& t) {
  w.object().member("compared", t.compared).member("agree", t.agree).member("disagree", t.disagree);
  w.member("no_answer", t.no_answer);
  if (has_split(field)) {
    w.member("unsafe", t.unsafe).member("lost", t.lost);
    w.member("unsafe_means", unsafe_words(field)).member("lost_means", lost_words(field));
  }
  if (field == "motion" || field == "hold") w.member("boundary", t.boundary);
  w.end_object();
}

std::string tally_line(const std::string& f, const Field_tally& t) {
  char line[200];
  std::snprintf(line, sizeof line, "  %-19s %6zu compared  %6zu agree  %6zu disagree  %6zu no answer", f.c_str(),
                t.compared, t.agree, t.disagree, t.no_answer);
  std::string s = line;
  if (has_split(f) && t.disagree)
    s += "  (unsafe: " + std::to_string(t.unsafe) + " " + unsafe_words(f) + "; lost: " + std::to_string(t.lost) + " " +
         lost_words(f) + ")";
  if (t.boundary)
    s += "  (" + std::to_string(t.boundary) + " on an impending reference answered with a side: the boundary, neither "
         "unsafe nor lost)";
  return s + "\n";
}

}  // namespace

Compare_report compare_answers(const std::string& corpus_path, const std::string& answers_path,
                               const Compare_options& o, Read_file read) {
  const Tolerance tol{o.rtol, o.atol};
  // The threshold of "near": --near, or the documented --tolerance when it is larger.
  const Rational threshold = o.tolerance && *o.tolerance > o.near ? *o.tolerance : o.near;
  // The corpus' distances are doubles (3 significant digits): compared with the threshold's nearest double,
  // so that a distance written 0.001 is within --tolerance 1e-3.
  const double near = nearest_double(threshold).value_or(HUGE_VAL);
  std::string format = o.format;
  if (format.empty())
    format = answers_path.size() >= 4 && answers_path.compare(answers_path.size() - 4, 4, ".csv") == 0 ? "csv" : "jsonl";

  const Corpus corpus = read_corpus(corpus_path, read);
  const std::string source = answers_path == "-" ? "<stdin>" : answers_path;
  const std::string text = read(answers_path, o.limits.max_file_bytes);
  const std::vector<Answer> answers =
      format == "csv" ? read_csv_answers(source, text) : read_jsonl_answers(source, text, o.limits);
  Comparison c = compare(corpus, answers, tol);
  for (Disagreement& d : c.disagreements)
    d.near = d.at.measured && (d.at.exact_zeros > 0 || (d.at.distance && *d.at.distance <= near));
  // Far from any boundary first (likely bugs), then those with no measure, then the nearest to a boundary
  // last; by distance, then id within.
  std::stable_sort(c.disagreements.begin(), c.disagreements.end(), [](const Disagreement& a, const Disagreement& b) {
    const Place pa = place_of(a), pb = place_of(b);
    if (pa != pb) return pa < pb;
    const double da = a.at.distance.value_or(0), db = b.at.distance.value_or(0);
    return da > db;
  });
  std::size_t near_count = 0, unmeasured = 0, unsafe = 0, lost = 0;
  for (const Disagreement& d : c.disagreements) {
    near_count += place_of(d) == Place::near;
    unmeasured += place_of(d) == Place::unmeasured;
    unsafe += d.kind != "value" && d.unsafe;
    lost += d.kind != "value" && !d.unsafe;
  }
  const std::size_t far_count = c.disagreements.size() - near_count - unmeasured;
  std::size_t covered = 0, far_measured = 0;
  const std::optional<std::string> hint =
      o.tolerance ? std::nullopt : suggested_tolerance(c.disagreements, covered, far_measured);
  const std::size_t missing = corpus.refs.size() - c.answered;
  auto scene_path = [&](const Ref& r) { return (corpus.dir / r.scene_file).string(); };
  const auto approx = [](Json_writer& w, const Rational& q) {
    const std::optional<double> d = nearest_double(q);
    d ? write_shortest(w, *d) : void(w.null());
  };

  Compare_report report;
  if (o.json) {
    Json_writer w(4096);
    w.object().member("command", "compare").member("reference_scenes", corpus.refs.size());
    w.member("answered", c.answered);
    w.member("not_answered", missing).member("errors", c.errors).key("fields").object();
    for (const char* f : kFields)
      if (const auto it = c.fields.find(f); it != c.fields.end()) write_tally(w.key(f), f, it->second);
    w.end_object().key("families").object();
    for (const auto& [family, fields] : c.families) {
      w.key(family).object();
      for (const char* f : kFields)
        if (const auto it = fields.find(f); it != fields.end()) write_tally(w.key(f), f, it->second);
      w.end_object();
    }
    w.end_object().key("disagreements").array();
    const auto text_or_null = [&w](const std::string& x) { x.empty() ? void(w.null()) : void(w.string(x)); };
    for (const Disagreement& d : c.disagreements) {
      const Ref& r = *d.ref;
      w.object().member("id", r.id).member("family", r.family);
      w.key("epsilon");
      text_or_null(r.epsilon);
      w.key("side");
      text_or_null(r.side);
      w.key("distance");
      d.at.distance ? void(w.raw(double_text(*d.at.distance))) : void(w.null());
      w.key("nearest");
      text_or_null(d.at.nearest);
      w.member("exact_zero_determinants", d.at.exact_zeros).member("boundary_measured", d.at.measured);
      w.key("scene_distance");
      r.distance ? void(w.raw(double_text(*r.distance))) : void(w.null());
      w.member("near_boundary", d.near).member("field", d.field).member("kind", d.kind);
      if (d.kind != "value") w.member("unsafe", d.unsafe);
      w.member("reference", d.reference);
      if (d.reference_value) write_approx(w.key("reference_approx"), *d.reference_value);
      w.member("answer", d.answer);
      if (!d.power.empty()) {
        w.key("twists").array();
        for (const Power_detail& p : d.power) {
          w.object().member("index", p.index).key("twist");
          p.twist ? void(w.raw(json::text_of(*p.twist))) : void(w.null());
          w.key("bracket").array().rational(p.lo).rational(p.hi).end_array();
          w.key("bracket_approx").array();
          approx(w, p.lo);
          approx(w, p.hi);
          w.end_array().member("answer", p.answer_text);
          approx(w.key("answer_approx"), p.answer);
          w.key("relative_error");
          p.relative_error ? write_shortest(w, *p.relative_error) : void(w.null());
          w.end_object();
        }
        w.end_array();
      }
      w.member("scene_file", scene_path(r)).end_object();
    }
    w.end_array().member("near_boundary", near_count).member("far_from_boundary", far_count);
    w.member("no_boundary_measure", unmeasured).member("unsafe", unsafe).member("lost", lost);
    w.member("near_threshold", double_text(near));
    w.key("tolerance");
    o.tolerance ? void(w.string(o.tolerance_text)) : void(w.null());
    w.key("suggested_tolerance");
    hint ? void(w.string(*hint)) : void(w.null());
    w.member("agree", c.disagreements.empty()).end_object();
    report.text = w.str() + "\n";
  } else {
    std::ostringstream s;
    s << "reference: " << corpus.refs.size() << " scenes; answers: " << c.answered << " (" << missing
      << " scenes not answered";
    if (c.errors) s << ", " << c.errors << " answers with an error";
    s << ")\n";
    for (const char* f : kFields)
      if (const auto it = c.fields.find(f); it != c.fields.end()) s << tally_line(f, it->second);
    if (c.disagreements.empty()) {
      s << "every given answer agrees with the reference\n";
    } else {
      s << c.disagreements.size() << " disagreement" << (c.disagreements.size() == 1 ? "" : "s") << ": " << far_count
        << " far from any degenerate boundary (likely bugs), ";
      if (unmeasured) s << unmeasured << " with no boundary measure, ";
      s << near_count << " within " << near << (o.tolerance ? " (your documented tolerance)" : "")
        << " of one or exactly degenerate (likely tolerance issues)\n";
      if (unsafe || lost)
        s << "verdicts: " << unsafe << " unsafe (the answer claims closure, balance, holding or sticking that does not hold), "
          << lost << " lost (it misses one that holds)\n";
      // Per family: the families with disagreements.
      s << "\nby family (those with disagreements):\n";
      for (const auto& [family, fields] : c.families) {
        bool named = false;
        for (const char* f : kFields) {
          const auto it = fields.find(f);
          if (it == fields.end() || !it->second.disagree) continue;
          if (!named) s << "  " << family << "\n";
          named = true;
          s << "  " << tally_line(f, it->second);
        }
      }
      if (hint)
        s << "\nhint: " << covered << " of the " << far_measured << " disagreements far from a boundary are within "
          << *hint << " of one. If your implementation documents a tolerance of that size, rerun with --tolerance "
          << *hint << " to count them as near.\n";
      Place printed = Place::far;
      bool first = true;
      for (const Disagreement& d : c.disagreements) {
        const Place p = place_of(d);
        if (first || p != printed)
          s << (p == Place::far          ? "\nfar from any degenerate boundary:\n"
                : p == Place::unmeasured ? "\nno boundary measure:\n"
                                         : "\nnear a degenerate boundary:\n");
        first = false;
        printed = p;
        const Ref& r = *d.ref;
        s << "  " << r.id << "  family " << r.family;
        if (!r.epsilon.empty()) s << ", eps " << r.epsilon << (r.side.empty() ? "" : " (" + r.side + ")");
        s << ", " << distance_text(d) << "\n    " << d.field << ": ";
        if (d.kind != "value") s << d.kind << (d.unsafe ? " (unsafe)" : " (lost)") << ": ";
        if (d.power.empty()) {
          s << "reference " << d.reference;
          if (d.field == "epsilon") {  // its size is the distance of the wrench space's boundary to the origin
            const std::optional<double> up = nearest_double(exact_number(*d.reference_value->find("upper"), "reference"));
            if (up) s << " (≈ " << *up << (*up == 0 ? ": the grasp is not in force closure" : ": its boundary's distance to the origin") << ")";
          }
          if (d.field == "center_of_friction") {  // the exact point also as nearest doubles
            Json_writer a(64);
            write_approx(a, *d.reference_value);
            s << " (nearest doubles " << a.str() << ")";
          }
          s << ", answer " << d.answer;
        } else {
          s << d.power.size() << " of " << d.ref->limit_surface->find("twists")->items.size()
            << " twists outside the reference";
          for (const Power_detail& p : d.power) {
            const auto num = [](const Rational& q) {
              const std::optional<double> x = nearest_double(q);
              return x ? double_text(*x) : std::string("beyond the double range");
            };
            s << "\n      twist " << p.index << " " << (p.twist ? json::text_of(*p.twist) : "") << ": reference ";
            if (p.lo == p.hi) s << num(p.lo) << " (exact " << to_string(p.lo) << ")";
            else s << "[" << num(p.lo) << ", " << num(p.hi) << "] (exact [" << to_string(p.lo) << ", " << to_string(p.hi) << "])";
            s << ", answer " << p.answer_text << ", relative error "
              << (p.relative_error ? double_text(*p.relative_error) : std::string("undefined (reference 0)"));
          }
        }
        s << "\n    scene: " << scene_path(r) << "\n";
      }
    }
    report.text = s.str();
  }
  report.agree = c.disagreements.empty();
  return report;
}

}  // namespace wrenchkit
