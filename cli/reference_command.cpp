// wrenchkit reference: the reference corpus for other implementations (docs/reference-format.md):
// golden textbook scenes, near-degenerate families and random scenes, each with its exact answers,
// certificates re-checked by the independent checker, and its distance to a degenerate boundary.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cli/common.h"
#include "cli/reference.h"
#include "exact/statics/boundary_distance.h"
#include "exact/io/input_error.h"
#include "exact/io/json.h"
#include "exact/io/json_writer.h"
#include "exact/sliding/limit_surface.h"
#include "exact/statics/moment_labels.h"
#include "exact/io/scene_writer.h"
#include "exact/sliding/sliding.h"
#include "testing/stress_families.h"

namespace wrenchkit::cli {

namespace {

struct Golden {
  const char* name;
  const char* scene;
  const char* expected;
};
const Golden kGoldens[] = {
#include "cli/reference_goldens.inc"
};

const int kEpsilonExponents[] = {2, 6, 10, 14, 16, 20, 40};

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

void write_double(Json_writer& w, double d) {  // a double for reading, as a JSON number
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", d);
  w.raw(b);
}
void write_double(Json_writer& w, const std::optional<double>& d) { d ? write_double(w, *d) : void(w.null()); }
// A text, or null when it is empty.
void write_text_or_null(Json_writer& w, const std::string& s) { s.empty() ? void(w.null()) : void(w.string(s)); }

// The canonical text (exact/io/scene_writer.h) on one line: newlines (never inside strings, which
// json::quote escapes) and their indentation removed.
std::string one_line(const std::string& canonical) {
  std::string s;
  for (std::size_t i = 0; i < canonical.size(); ++i) {
    if (canonical[i] != '\n') {
      s += canonical[i];
      continue;
    }
    while (i + 1 < canonical.size() && canonical[i + 1] == ' ') ++i;
    if (!s.empty() && s.back() == ',') s += ' ';
  }
  return s;
}

struct Entry {
  std::string id, family, source, epsilon, side, seed;  // empty: JSON null
  std::string text;                                      // the scene as generated
  std::string expected;                                  // golden: the expected answers
};

std::vector<Entry> corpus_entries(const Reference_options& ro) {
  std::vector<Entry> out;
  for (const Golden& g : kGoldens) {
    std::string name = g.name, family = "golden", id = "golden." + name;
    for (char& c : id)
      if (c == '/') c = '.';
    out.push_back({id, family, "tests/golden/" + name + ".scene.json", "", "", "", g.scene, g.expected});
  }
  int family_index = 0;
  for (const stress::Family& f : stress::families()) {
    ++family_index;
    if (!f.uses_epsilon) continue;
    for (int k : kEpsilonExponents)
      for (int c = 0; c < ro.cases; ++c) {
        const std::uint64_t seed =
            splitmix64(ro.seed ^ splitmix64(static_cast<std::uint64_t>(family_index * 100000 + k * 1000 + c)));
        const stress::Family_scene s = stress::make_scene(f.name, std::stod("1e-" + std::to_string(k)), seed);
        out.push_back({std::string(f.name) + ".1e-" + std::to_string(k) + "." + std::to_string(c), f.name, "",
                       "1e-" + std::to_string(k), s.above ? "above" : "below", std::to_string(seed), s.text, ""});
      }
  }
  family_index = 0;
  for (const stress::Family& f : stress::families()) {
    ++family_index;
    if (f.uses_epsilon) continue;
    char num[16];
    for (int c = 0; c < ro.random; ++c) {
      const std::uint64_t seed = splitmix64(ro.seed ^ splitmix64(static_cast<std::uint64_t>(family_index) << 32 | c));
      std::snprintf(num, sizeof num, "%04d", c);
      out.push_back({std::string(f.name) + "." + num, f.name, "", "", "", std::to_string(seed),
                     stress::make_scene(f.name, 0, seed).text, ""});
    }
  }
  return out;
}

void write_flip(Json_writer& w, const std::optional<Friction_flip>& f) {
  if (!f) {
    w.null();
    return;
  }
  w.object().key("flips_between").array().rational(f->lo).rational(f->hi).end_array();
  write_double(w.key("distance"), f->distance);
  w.end_object();
}

void write_boundary(Json_writer& w, const Boundary_distance& b, const std::string& epsilon, bool load) {
  w.object().key("epsilon");
  epsilon.empty() ? w.null() : w.raw(epsilon);
  write_double(w.key("distance"), b.distance);
  write_text_or_null(w.key("nearest"), b.nearest);
  w.member("exact_zero_determinants", b.exact_zeros());
  write_double(w.key("min_relative_determinant").object().key("force_closure"), b.force.min_relative);
  write_double(w.key("form_closure"), b.form.min_relative);
  if (load) write_double(w.key("equilibrium"), b.equilibrium.min_relative);
  write_flip(w.end_object().key("friction_scale").object().key("force_closure"), b.closure_flip);
  if (load) write_flip(w.key("equilibrium"), b.equilibrium_flip);
  w.end_object().end_object();
}

// The twists at which the power is bracketed: translations along x and y, a rotation about the
// origin, a generic twist, and a rotation about the first support point (a facet of the true LS).
std::vector<Vec3q> reference_twists(const Ls_support& s) {
  std::vector<Vec3q> t = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 2, 3}};
  if (!s.points.empty()) t.push_back({s.points[0].at.y, -s.points[0].at.x, 1});
  return t;
}

void write_limit_surface(Json_writer& w, const Scene& scene, int sides) {
  const Polygonal_ls model(merge_support(*scene.support), make_directions(sides));
  if (model.candidate_count() > kMaxCandidates) throw Usage_error("--sides: too many for the corpus' supports");
  const Ls_polytope in = model.build(Side::inner), out = model.build(Side::outer);
  const Sliding_answer base = compute_sliding(model, std::nullopt);
  w.object().member("sides", sides).member("lambda_squared", model.directions().lambda_sq);
  w.member("dimension", model.dimension()).key("center_of_friction").array();
  w.rational(base.center_of_friction.x).rational(base.center_of_friction.y).end_array().member("mu_f0", base.mu_f0);
  w.key("inner").object().member("facets", in.facets.size()).member("vertices", in.vertices.size()).end_object();
  w.key("outer").object().member("facets", out.facets.size()).member("vertices", out.vertices.size()).end_object();
  const char* kinds[] = {"facet", "vertex", "smooth"};
  w.key("twists").array();
  for (const Vec3q& t : reference_twists(model.support())) {
    const Sliding_answer a = compute_sliding(model, t);
    w.object().key("twist").rationals(t);
    w.member("h_inner", a.h_inner).member("h_outer", a.h_outer);
    w.key("power_bracket").array().rational(a.h_lo).rational(a.h_hi).end_array();
    w.member("true_surface", kinds[static_cast<int>(a.cls.kind)]).end_object();
  }
  w.end_array().end_object();
}

// A golden's expected answers against ours: a disagreement is a bug in one of them (exit 4).
void check_expected(const Entry& e, bool fc, bool fo, int rank_force, int rank_form, const bool* balanced) {
  if (e.expected.empty()) return;
  const json::Value v = json::parse(e.expected, Input_limits{}, e.source);
  auto expect_bool = [&](const char* key, bool ours) {
    if (const json::Value* x = v.find(key); x && x->type == json::Type::boolean && x->boolean != ours)
      throw Self_check_failure(e.id + ": " + key + " is " + (ours ? "true" : "false") + ", the golden file says " +
                               (x->boolean ? "true" : "false"));
  };
  expect_bool("force_closure", fc);
  expect_bool("form_closure", fo);
  if (balanced) expect_bool("balanced", *balanced);
  if (const json::Value* r = v.find("rank")) {
    const json::Value* a = r->find("force");
    const json::Value* b = r->find("form");
    if ((a && a->text != std::to_string(rank_force)) || (b && b->text != std::to_string(rank_form)))
      throw Self_check_failure(e.id + ": rank differs from the golden file");
  }
}

struct Built {
  std::string line, canonical, csv;
  std::size_t certificates = 0;
};

Built build_line(const Entry& e, const Reference_options& ro) {
  Options o;
  o.mode = Mode::exact;
  const Scene parsed = read_scene(e.text, o.limits, e.id);
  Built b;
  b.canonical = write_scene(parsed);
  const std::string text = one_line(b.canonical);
  if (write_scene(read_scene(text, o.limits, e.id)) != b.canonical)
    throw Self_check_failure(e.id + ": the one-line scene does not read back to the canonical scene");
  // Closure and equilibrium through the commands' own checked path: every certificate is accepted by
  // the independent checker (on `text`, the bytes written) before we go on.
  Scene scene;
  const Request request = request_of(o);
  const Closure_item c = answered(answer_closure(text, e.id, request, scene));
  std::optional<Equilibrium_item> eq;
  if (scene.load) eq = answered(answer_equilibrium(scene, text, request));
  bool balanced = eq && eq->answer.balanced;
  check_expected(e, c.force.holds, c.form.holds, c.force.rank, c.form.rank, eq ? &balanced : nullptr);
  const Moment_labels labels = moment_labels(scene, Reading::friction);
  const Boundary_distance bd = boundary_distance(scene);

  Json_writer w(8192);
  w.object().member("id", e.id).member("family", e.family);
  write_text_or_null(w.key("epsilon"), e.epsilon);
  write_text_or_null(w.key("side"), e.side);
  write_text_or_null(w.key("seed"), e.seed);
  write_text_or_null(w.key("source"), e.source);
  w.member("scene_file", "scenes/" + e.id + ".json").key("scene").raw(text);
  w.member("force_closure", c.force.holds).member("form_closure", c.form.holds);
  w.key("rank").object().member("force", c.force.rank).member("form", c.form.rank).end_object();
  if (eq) {
    const Wrench& l = eq->answer.load;
    w.member("equilibrium", eq->answer.balanced);
    w.key("load").array().rational(l.fx).rational(l.fy).rational(l.m).end_array();
  }
  write_labels(w.key("labels").object(), labels);
  w.end_object();
  if (scene.support) write_limit_surface(w.key("limit_surface"), scene, ro.sides);
  w.key("certificates").object().key("force_closure").raw(c.force_certificate);
  w.key("form_closure").raw(c.form_certificate);
  if (eq) w.key("equilibrium").raw(eq->certificate);
  write_boundary(w.end_object().key("boundary"), bd, e.epsilon, eq.has_value());
  b.line = w.end_object().take();
  b.certificates = eq ? 3 : 2;
  b.csv = e.id + "," + (c.force.holds ? "true" : "false") + "," + (c.form.holds ? "true" : "false") + "," +
          (eq ? (eq->answer.balanced ? "true" : "false") : "");
  return b;
}

namespace fs = std::filesystem;

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << text;
  out.flush();
  if (!out) throw Input_error(p.string() + ": cannot write");
}

// DIR may be missing, empty, or an earlier corpus (it has our manifest.json); anything else is refused.
void check_out_dir(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) return;
  if (!fs::is_directory(dir, ec)) throw Usage_error("--out: " + dir.string() + " exists and is not a directory");
  if (fs::is_empty(dir, ec)) return;
  std::ifstream m(dir / "manifest.json");
  std::string head(64, '\0');
  m.read(head.data(), 64);
  if (head.find("\"wrenchkit_reference\"") == std::string::npos)
    throw Usage_error("--out: " + dir.string() +
                      " is not empty and holds no wrenchkit reference corpus (manifest.json); refusing to replace it");
}

}  // namespace

Reference_corpus build_reference(const Reference_options& ro) {
  Reference_corpus corpus;
  for (const Entry& e : corpus_entries(ro)) {
    Built b = build_line(e, ro);
    corpus.ids.push_back(e.id);
    corpus.lines.push_back(std::move(b.line));
    corpus.scenes.push_back(std::move(b.canonical));
    corpus.csv.push_back(std::move(b.csv));
    corpus.certificates += b.certificates;
  }
  return corpus;
}

int run_reference(const Options& o) {
  const Reference_options& ro = o.reference;
  const std::string& out_dir = o.out_dir;
  if (out_dir.empty()) throw Usage_error("reference needs --out DIR");
  const fs::path dir(out_dir);
  check_out_dir(dir);

  const Reference_corpus corpus = build_reference(ro);

  // Everything goes to a temporary sibling first, then replaces DIR in one rename.
  const fs::path tmp = dir.string() + ".tmp-wrenchkit";
  std::error_code ec;
  fs::remove_all(tmp, ec);
  fs::create_directories(tmp / "scenes", ec);
  if (ec) throw Input_error(out_dir + ": cannot create (" + ec.message() + ")");
  std::string jsonl, csv = "id,force_closure,form_closure,equilibrium\n";
  for (std::size_t i = 0; i < corpus.ids.size(); ++i) {
    jsonl += corpus.lines[i] + "\n";
    csv += corpus.csv[i] + "\n";
    write_text(tmp / "scenes" / (corpus.ids[i] + ".json"), corpus.scenes[i]);
  }
  write_text(tmp / "reference.jsonl", jsonl);
  write_text(tmp / "expected.csv", csv);
  Json_writer m(512);
  m.object().member("wrenchkit_reference", 1).member("generator", "wrenchkit 0.1.0");
  m.member("format", "docs/reference-format.md").member("seed", std::to_string(ro.seed)).member("cases", ro.cases);
  m.member("random", ro.random).member("sides", ro.sides);
  m.key("epsilons").array();
  for (int k : kEpsilonExponents) m.string("1e-" + std::to_string(k));
  m.end_array().member("scenes", corpus.ids.size()).key("files").object().member("corpus", "reference.jsonl");
  m.member("scenes", "scenes/").member("verdicts", "expected.csv").end_object().end_object();
  const std::string manifest = m.take() + "\n";
  write_text(tmp / "manifest.json", manifest);
  fs::remove_all(dir, ec);
  fs::rename(tmp, dir, ec);
  if (ec) throw Input_error(out_dir + ": cannot write (" + ec.message() + ")");

  const std::size_t certificates = corpus.certificates;
  if (o.json)
    std::cout << json_answer([&](Json_writer& w) {
      w.member("command", "reference").member("out", out_dir).member("scenes", corpus.ids.size());
      w.member("certificates_checked", certificates).member("bytes", jsonl.size());
    }) << "\n";
  else
    std::cout << "wrote " << corpus.ids.size() << " scenes to " << out_dir << "/reference.jsonl (" << jsonl.size()
              << " bytes), scenes/, expected.csv, manifest.json\n"
              << "all " << certificates << " certificates accepted by the independent checker (exact arithmetic)\n";
  return kAnswered;
}

}  // namespace wrenchkit::cli
