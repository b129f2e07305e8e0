// wrenchkit compare: another implementation's answers against the reference corpus
// (docs/reference-format.md §5): agreement per field, and every disagreement with its scene and how
// close that scene is to a degenerate boundary (tolerance issue or real bug?).
#include <cctype>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/common.h"
#include "cli/reference.h"
#include "exact/io/input_error.h"
#include "exact/io/json.h"
#include "exact/io/json_writer.h"

namespace wrenchkit::cli {

namespace {

namespace fs = std::filesystem;

struct Ref {
  std::string id, family, epsilon, side, scene_file, nearest;
  std::optional<double> distance;
  long exact_zeros = 0;
  std::map<std::string, bool> verdicts;  // force_closure, form_closure, equilibrium
  const json::Value* labels = nullptr;
  const json::Value* limit_surface = nullptr;
};

struct Disagreement {
  const Ref* ref;
  std::string field, reference, answer;
  bool near = false;
};

struct Field_tally {
  std::size_t compared = 0, agree = 0, disagree = 0, no_answer = 0;
};

const char* const kFields[] = {"force_closure", "form_closure", "equilibrium", "center_of_friction", "power", "labels"};

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

Corpus read_corpus(const std::string& path) {
  Corpus c;
  fs::path file = path;
  std::error_code ec;
  if (fs::is_directory(file, ec)) file /= "reference.jsonl";
  c.dir = file.parent_path();
  const std::string text = read_input(file.string(), std::size_t(1) << 32);
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
    if (const json::Value* b = v.find("boundary")) {
      if (const json::Value* d = b->find("distance"); d && d->type == json::Type::number) r.distance = std::stod(d->text);
      if (const json::Value* n = b->find("nearest"); n && n->type == json::Type::string) r.nearest = n->text;
      if (const json::Value* z = b->find("exact_zero_determinants"); z && z->type == json::Type::number)
        r.exact_zeros = std::stol(z->text);
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
  std::size_t start = 0, line = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    ++line;
    std::string_view l(text.data() + start, end - start);
    start = end + 1;
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    if (l.find_first_not_of(" \t") == std::string_view::npos) continue;
    const std::string where = path + ":" + std::to_string(line);
    json::Value v;
    try {
      v = json::parse(l, limits, path);
    } catch (const Input_error& e) {  // "PATH:1:COL: invalid JSON: …" → "PATH:LINE:COL: …"
      std::string m = e.what();
      const std::string prefix = path + ":1:";
      if (m.compare(0, prefix.size(), prefix) == 0) m = where + ":" + m.substr(prefix.size());
      throw Input_error(m);
    }
    if (v.type != json::Type::object) throw Input_error(where + ": an answer must be a JSON object, not a " + json::type_name(v.type));
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
                          ": unknown field (known: id, force_closure, form_closure, equilibrium, center_of_friction, "
                          "power, labels, error; fields starting with _ are ignored)");
      } else {
        a.fields.emplace_back(k, std::move(x));
      }
    }
    if (a.id.empty()) throw Input_error(where + ": id: missing");
    out.push_back(std::move(a));
  }
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
        if (h != "force_closure" && h != "form_closure" && h != "equilibrium")
          throw Input_error(where + ": column " + std::to_string(i + 1) + ": \"" + h +
                            "\" is not one of force_closure, form_closure, equilibrium");
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
      json::Value v;
      const std::string& c = cells[i];
      std::string lower = c;
      for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      if (lower == "true" || c == "1") v.type = json::Type::boolean, v.boolean = true;
      else if (lower == "false" || c == "0") v.type = json::Type::boolean, v.boolean = false;
      else if (!c.empty()) throw Input_error(where + ": " + header[i] + ": \"" + c + "\" is not true, false (any case), 1, 0 or empty");
      a.fields.emplace_back(header[i], v);
    }
    out.push_back(std::move(a));
  }
  if (header.empty()) throw Input_error(path + ": empty (a CSV answer file needs a header line: id,force_closure,...)");
  return out;
}

struct Comparison {
  std::map<std::string, Field_tally> fields;
  std::vector<Disagreement> disagreements;
  std::size_t answered = 0, errors = 0;
};

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

Comparison compare(const Corpus& corpus, const std::vector<Answer>& answers, const Tolerance& tol, double near) {
  Comparison c;
  std::set<std::string> seen;
  for (const Answer& a : answers) {
    const auto it = corpus.index.find(a.id);
    if (it == corpus.index.end()) throw Input_error(a.where + ": id: \"" + a.id + "\" is not in the corpus");
    if (!seen.insert(a.id).second) throw Input_error(a.where + ": id: \"" + a.id + "\" is answered twice");
    const Ref& ref = corpus.refs[it->second];
    ++c.answered;
    c.errors += a.error;
    auto disagree = [&](const std::string& field, const std::string& r, const std::string& ans) {
      Disagreement d{&ref, field, r, ans, false};
      d.near = ref.exact_zeros > 0 || (ref.distance && *ref.distance <= near);
      c.disagreements.push_back(d);
      ++c.fields[field].disagree;
    };
    for (const auto& [field, v] : a.fields) {
      Field_tally& t = c.fields[field];
      const std::string where = a.where + ": " + field;
      if (v.type == json::Type::null) {
        // No answer; not counted where the scene has nothing to answer (equilibrium without a load).
        const bool applicable = field == "equilibrium" ? ref.verdicts.count(field) != 0
                                : (field == "center_of_friction" || field == "power") ? ref.limit_surface != nullptr
                                                                                    : true;
        if (applicable) ++t.no_answer;
        continue;
      }
      if (field == "force_closure" || field == "form_closure" || field == "equilibrium") {
        if (v.type != json::Type::boolean) throw Input_error(where + ": " + json::text_of(v) + " is not true, false or null");
        const auto r = ref.verdicts.find(field);
        if (r == ref.verdicts.end()) throw Input_error(where + ": scene \"" + a.id + "\" has no load (no equilibrium answer)");
        ++t.compared;
        if (r->second == v.boolean) ++t.agree;
        else disagree(field, r->second ? "true" : "false", v.boolean ? "true" : "false");
      } else if (field == "center_of_friction" || field == "power") {
        if (!ref.limit_surface)
          throw Input_error(where + ": scene \"" + a.id + "\" has no support (no " + field + " answer)");
        if (v.type != json::Type::array) throw Input_error(where + ": " + json::text_of(v) + " is not an array");
        ++t.compared;
        bool ok = true;
        std::string reference;
        if (field == "center_of_friction") {
          if (v.items.size() != 2) throw Input_error(where + ": " + json::text_of(v) + " is not [x, y]");
          const json::Value& r = *ref.limit_surface->find("center_of_friction");
          reference = json::text_of(r);
          for (std::size_t i = 0; i < 2; ++i)
            ok &= tol.close(exact_number(v.items[i], where + "[" + std::to_string(i) + "]"),
                            exact_number(r.items[i], "reference"));
        } else {
          const json::Value& twists = *ref.limit_surface->find("twists");
          if (v.items.size() != twists.items.size())
            throw Input_error(where + ": " + std::to_string(v.items.size()) + " values, the scene has " +
                              std::to_string(twists.items.size()) + " twists (limit_surface.twists)");
          reference = "[";
          for (std::size_t i = 0; i < v.items.size(); ++i) {
            const json::Value& br = *twists.items[i].find("power_bracket");
            reference += (i ? ", " : "") + json::text_of(br);
            if (v.items[i].type == json::Type::null) continue;
            const Rational h = exact_number(v.items[i], where + "[" + std::to_string(i) + "]");
            const Rational lo = exact_number(br.items[0], "reference"), hi = exact_number(br.items[1], "reference");
            const Rational slack = tol.atol + tol.rtol * abs(hi);
            ok &= h >= lo - slack && h <= hi + slack;
          }
          reference += "]";
        }
        if (ok) ++t.agree;
        else disagree(field, reference, json::text_of(v));
      } else if (field == "labels") {
        if (v.type != json::Type::object) throw Input_error(where + ": " + json::text_of(v) + " is not an object");
        ++t.compared;
        std::string why;
        for (const auto& [k, region] : v.members) {
          if (k != "plus" && k != "minus")
            throw Input_error(where + ": " + json::quote(k) + ": unknown field (known: plus, minus)");
          if (region.type == json::Type::null) continue;
          if (auto m = region_mismatch(region, *ref.labels->find(k), where + "." + k, tol))
            why += (why.empty() ? "" : "; ") + k + ": reference " + *m;
        }
        if (why.empty()) ++t.agree;
        else disagree(field, why, json::text_of(v));
      }
    }
  }
  return c;
}

std::string distance_text(const Ref& r) {
  std::ostringstream s;
  if (r.distance) s << "distance " << *r.distance << " (" << r.nearest << ")";
  else s << "distance unknown";
  if (r.exact_zeros) s << ", " << r.exact_zeros << " exactly degenerate determinant" << (r.exact_zeros == 1 ? "" : "s");
  return s.str();
}

}  // namespace

int run_compare(const Options& o) {
  const Tolerance tol{o.rtol, o.atol};
  const double near = o.near.get_d();
  const std::string& answers_path = o.positional[1];
  std::string format = o.format;
  if (format.empty())
    format = answers_path.size() >= 4 && answers_path.compare(answers_path.size() - 4, 4, ".csv") == 0 ? "csv" : "jsonl";

  const Corpus corpus = read_corpus(o.positional[0]);
  const std::string source = answers_path == "-" ? "<stdin>" : answers_path;
  const std::string text = read_input(answers_path, o.limits.max_file_bytes);
  const std::vector<Answer> answers =
      format == "csv" ? read_csv_answers(source, text) : read_jsonl_answers(source, text, o.limits);
  Comparison c = compare(corpus, answers, tol, near);
  // Far from any boundary first (likely bugs), then the nearest to a boundary last; by id within.
  std::stable_sort(c.disagreements.begin(), c.disagreements.end(), [](const Disagreement& a, const Disagreement& b) {
    if (a.near != b.near) return !a.near;
    const double da = a.ref->distance ? *a.ref->distance : 0, db = b.ref->distance ? *b.ref->distance : 0;
    return da > db;
  });
  std::size_t near_count = 0;
  for (const Disagreement& d : c.disagreements) near_count += d.near;
  const std::size_t missing = corpus.refs.size() - c.answered;
  auto scene_path = [&](const Ref& r) { return (corpus.dir / r.scene_file).string(); };

  if (o.json) {
    Json_writer w(4096);
    w.object().member("command", "compare").member("reference_scenes", corpus.refs.size());
    w.member("answered", c.answered);
    w.member("not_answered", missing).member("errors", c.errors).key("fields").object();
    for (const char* f : kFields) {
      const auto it = c.fields.find(f);
      if (it == c.fields.end()) continue;
      const Field_tally& t = it->second;
      w.key(f).object().member("compared", t.compared).member("agree", t.agree).member("disagree", t.disagree);
      w.member("no_answer", t.no_answer).end_object();
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
      if (r.distance) {
        std::ostringstream x;  // the stream's default format (%g, 6 significant digits)
        x << *r.distance;
        w.raw(x.str());
      } else {
        w.null();
      }
      w.key("nearest");
      text_or_null(r.nearest);
      w.member("exact_zero_determinants", r.exact_zeros).member("near_boundary", d.near).member("field", d.field);
      w.member("reference", d.reference).member("answer", d.answer).member("scene_file", scene_path(r)).end_object();
    }
    w.end_array().member("near_boundary", near_count).member("far_from_boundary", c.disagreements.size() - near_count);
    w.member("agree", c.disagreements.empty()).end_object();
    std::cout << w.str() << "\n";
  } else {
    std::ostringstream s;
    s << "reference: " << corpus.refs.size() << " scenes; answers: " << c.answered << " (" << missing
      << " scenes not answered";
    if (c.errors) s << ", " << c.errors << " answers with an error";
    s << ")\n";
    for (const char* f : kFields) {
      const auto it = c.fields.find(f);
      if (it == c.fields.end()) continue;
      const Field_tally& t = it->second;
      char line[160];
      std::snprintf(line, sizeof line, "  %-19s %6zu compared  %6zu agree  %6zu disagree  %6zu no answer\n", f, t.compared,
                    t.agree, t.disagree, t.no_answer);
      s << line;
    }
    if (c.disagreements.empty()) {
      s << "every given answer agrees with the reference\n";
    } else {
      s << c.disagreements.size() << " disagreement" << (c.disagreements.size() == 1 ? "" : "s") << ": "
        << c.disagreements.size() - near_count << " far from any degenerate boundary (likely bugs), " << near_count
        << " within " << near << " of one or exactly degenerate (likely tolerance issues)\n";
      bool printed_near_header = false;
      if (near_count < c.disagreements.size()) s << "\nfar from any degenerate boundary:\n";
      for (const Disagreement& d : c.disagreements) {
        if (d.near && !printed_near_header) {
          s << "\nnear a degenerate boundary:\n";
          printed_near_header = true;
        }
        const Ref& r = *d.ref;
        s << "  " << r.id << "  family " << r.family;
        if (!r.epsilon.empty()) s << ", eps " << r.epsilon << (r.side.empty() ? "" : " (" + r.side + ")");
        s << ", " << distance_text(r) << "\n    " << d.field << ": reference " << d.reference << ", answer " << d.answer
          << "\n    scene: " << scene_path(r) << "\n";
      }
    }
    std::cout << s.str();
  }
  return c.disagreements.empty() ? kAnswered : kRejected;
}

}  // namespace wrenchkit::cli
