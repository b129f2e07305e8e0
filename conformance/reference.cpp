// The reference corpus (conformance/reference.h): the built-in scenes — golden textbook scenes, near-degenerate
// families and random scenes — or the user's own scenes (--scenes), each with its exact answers, certificates
// re-checked by the independent checker, and its distance to a degenerate boundary; every line is built by
// conformance/corpus.h.
#include "conformance/reference.h"

#include <cstdio>
#include <string>
#include <vector>

#include "exact/io/json.h"
#include "exact/io/json_writer.h"
#include "testing/stress_families.h"

namespace wrenchkit {

namespace {

struct Golden {
  const char* name;
  const char* scene;
  const char* expected;
};
const Golden kGoldens[] = {
#include "conformance/reference_goldens.inc"
};

const int kEpsilonExponents[] = {2, 6, 10, 14, 16, 20, 40};
// The stress report's families the corpus carries (stress::report_only_families()), in this order; the pushing ones
// (issue 33) come last, after the polygon parts.
const char* const kAppendedFamilies[] = {"unknown_support", "region_support", "fixture_pin"};
const char* const kPushFamilies[] = {"push_near_tie", "push_motion_cone", "push_fence_edge"};

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

struct Entry : Reference_scene {
  std::string expected;  // golden: the expected answers
};
Entry entry(std::string id, std::string family, std::string source, std::string epsilon, std::string side,
            std::string seed, std::string text, std::string expected) {
  Entry e;
  static_cast<Reference_scene&>(e) = {std::move(id), std::move(family), std::move(source), std::move(epsilon),
                                      std::move(side), std::move(seed), std::move(text), ""};
  e.expected = std::move(expected);
  return e;
}

// The stick/slide families hand their load beside the scene (Family_scene::load_text, exact JSON number texts):
// the corpus writes it into the scene as {"wrench": [fx, fy, m]}, so that motion and hold are the scene's answers.
std::string with_family_load(const stress::Family_scene& s) {
  if (s.load_text[0].empty() || s.text.find("\"load\"") != std::string::npos) return s.text;
  const std::size_t end = s.text.rfind('}');
  return s.text.substr(0, end) + ", \"load\": {\"wrench\": [" + s.load_text[0] + ", " + s.load_text[1] + ", " +
         s.load_text[2] + "]}" + s.text.substr(end);
}

std::vector<Entry> corpus_entries(const Reference_options& ro) {
  std::vector<Entry> out;
  for (const Golden& g : kGoldens) {
    std::string name = g.name, family = "golden", id = "golden." + name;
    for (char& c : id)
      if (c == '/') c = '.';
    out.push_back(entry(id, family, "tests/golden/" + name + ".scene.json", "", "", "", g.scene, g.expected));
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
        out.push_back(entry(std::string(f.name) + ".1e-" + std::to_string(k) + "." + std::to_string(c), f.name, "",
                       "1e-" + std::to_string(k), s.above ? "above" : "below", std::to_string(seed), s.text, ""));
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
      out.push_back(entry(std::string(f.name) + "." + num, f.name, "", "", "", std::to_string(seed),
                     stress::make_scene(f.name, 0, seed).text, ""));
    }
  }
  // Issue 20: this round's answers — stick/slide over unknown distributions, support regions, hold — by the
  // stress report's families (testing/stress_families.h), appended so every earlier scene keeps its id, seed and
  // bytes; then generic fixtures (contacts, a known support, a load near the support's friction): hold either way.
  // A stress report family, `cases` scenes per ε, its seeds from `index`.
  const auto append_family = [&](const char* name, int index) {
    for (int k : kEpsilonExponents)
      for (int c = 0; c < ro.cases; ++c) {
        const std::uint64_t seed =
            splitmix64(ro.seed ^ splitmix64(static_cast<std::uint64_t>(index * 100000 + k * 1000 + c)));
        const stress::Family_scene s = stress::make_scene(name, std::stod("1e-" + std::to_string(k)), seed);
        out.push_back(entry(std::string(name) + ".1e-" + std::to_string(k) + "." + std::to_string(c), name, "",
                            "1e-" + std::to_string(k), s.above ? "above" : "below", std::to_string(seed),
                            with_family_load(s), ""));
      }
  };
  family_index = static_cast<int>(stress::families().size());
  for (const char* name : kAppendedFamilies) append_family(name, ++family_index);
  ++family_index;
  char num[16];
  for (int c = 0; c < ro.random / 4; ++c) {
    const std::uint64_t seed = splitmix64(ro.seed ^ splitmix64(static_cast<std::uint64_t>(family_index) << 32 | c));
    stress::Rng rng(seed);
    const int contacts = rng.integer(1, 3), points = rng.integer(2, 5);
    const double load = rng.uniform(0.5, 1.5);
    std::snprintf(num, sizeof num, "%04d", c);
    out.push_back(entry(std::string("random_fixture.") + num, "random_fixture", "", "", "", std::to_string(seed),
                        stress::fixture_text(rng, contacts, points, load), ""));
  }
  // Issue 16 [HD-2]: hold over a support region together with legs whose forces are not given (the mat and legs of
  // proofs/examples/mat_legs_*, with and without a pin): held by every distribution, by none, and depending on it;
  // their stick/slide [RG-3] sticks, slides and depends over F too (format-2 certificates).
  const char* const mat_legs = R"("support": {"mu": "1/2", "weight": 5, "pressure_center": [0, 0], "points": [{"at": [-2, 0]}, {"at": [0, 0]}, {"at": [2, 0]}], "regions": [{"outline": [["-1/2", "-1/2"], ["1/2", "-1/2"], ["1/2", "1/2"], ["-1/2", "1/2"]], "pressure": "uniform", "force": 1}]})";
  const char* const pin = R"("contacts": [{"at": [-3, 0], "normal": [1, 0], "name": "pin"}], )";
  const struct {
    const char *id, *contacts, *load;
  } fixture_regions[] = {
      {"nudged", "", R"({"wrench": ["9/4", 0, 0]})"},     {"shoved", "", R"({"wrench": [3, 0, 0]})"},
      {"twisted", "", R"({"wrench": [0, 0, 1]})"},         {"pinned_shoved", pin, R"({"wrench": [-3, 0, 0]})"},
      {"pinned_twisted", pin, R"({"wrench": [-1, 0, 1]})"}, {"pinned_pulled", pin, R"({"wrench": [3, 0, 0]})"},
  };
  for (const auto& f : fixture_regions)
    out.push_back(entry(std::string("fixture_regions.") + f.id, "fixture_regions", "", "", "", "",
                        std::string(R"({"wrenchkit": 1, "name": "mat and legs of unknown force", )") + f.contacts +
                            mat_legs + R"(, "load": )" + f.load + "}",
                        ""));
  // Issue 32 [GR-1, GR-2]: polygon parts without contacts, for where two and three fingers may go — the lines'
  // "grasp_regions" (docs/reference-format.md §2) — including the rational boundaries: the square's adjacent sides
  // close for no placement at mu = 1 exactly and for a sliver just above; the L part's edges 1, 2, 3 never close at
  // mu = 1 and do just above.
  const char* const square = "[[0, 0], [1, 0], [1, 1], [0, 1]]";
  const char* const l_part = "[[0, 0], [6, 0], [6, 2], [2, 2], [2, 5], [0, 5]]";
  const char* const twelve =
      R"([["-1419/1469", "-380/1469"], ["-48081/68081", "-48200/68081"], ["-69/269", "-260/269"], ["4071/15929", "-15400/15929"], )"
      R"(["8319/11681", "-8200/11681"], ["9831/10169", "-2600/10169"], ["9831/10169", "2600/10169"], ["8319/11681", "8200/11681"], )"
      R"(["4071/15929", "15400/15929"], ["-69/269", "260/269"], ["-48081/68081", "48200/68081"], ["-1419/1469", "380/1469"]])";
  const struct {
    const char *id, *name, *mu, *outline;
  } parts[] = {
      {"triangle", "the triangle of Example 3", "1/2", "[[0, 0], [6, 0], [0, 6]]"},
      {"square", "the unit square", "1/2", square},
      {"square_mu_1", "the unit square at mu = 1: adjacent sides close nowhere", "1", square},
      {"square_mu_1_plus_1e-12", "the unit square just above mu = 1: adjacent sides close in a sliver",
       "1000000000001/1000000000000", square},
      {"rectangle", "a 4 x 2 rectangle", "1/4", "[[0, 0], [4, 0], [4, 2], [0, 2]]"},
      {"l_part", "an L-shaped part", "1/2", l_part},
      {"l_part_mu_1", "an L-shaped part at mu = 1: edges 1, 2, 3 never close", "1", l_part},
      {"l_part_mu_1_plus_1e-9", "an L-shaped part just above mu = 1", "1000000001/1000000000", l_part},
      {"pentagon", "a convex pentagon", "1/3", "[[0, 0], [3, 0], [5, 2], [4, 5], [1, 4]]"},
      {"twelve_gon", "a 12-gon of rational points on the unit circle", "1/5", twelve},
  };
  for (const auto& p : parts)
    out.push_back(entry(std::string("polygon_part.") + p.id, "polygon_part", "", "", "", "",
                        std::string(R"({"wrenchkit": 1, "name": ")") + p.name + R"(", "mu": ")" + p.mu +
                            R"(", "body": {"outline": )" + p.outline + "}}",
                        ""));
  // Issue 33: pushing — which way the body turns beside a tie of the votes (push_near_tie: ccw iff above) and whether
  // the contact sticks beside a motion-cone edge (push_motion_cone: slides left iff above), appended last; then a
  // fence translating beside its friction cone's edge (push_fence_edge: stable iff below), appended after them.
  family_index = 1000;
  for (const char* name : kPushFamilies) append_family(name, ++family_index);
  return out;
}

// A golden's expected answers against ours: "" when they agree, else the disagreement (a bug in one of them).
std::string golden_disagreement(const Entry& e, const Reference_item& b) {
  const json::Value v = json::parse(e.expected, Input_limits{}, e.source);
  std::string why;
  auto expect_bool = [&](const char* key, bool ours) {
    if (const json::Value* x = v.find(key); why.empty() && x && x->type == json::Type::boolean && x->boolean != ours)
      why = e.id + ": " + key + " is " + (ours ? "true" : "false") + ", the golden file says " +
            (x->boolean ? "true" : "false");
  };
  expect_bool("force_closure", b.force_closure);
  expect_bool("form_closure", b.form_closure);
  if (b.balanced) expect_bool("balanced", *b.balanced);
  if (const json::Value* r = v.find("rank"); why.empty() && r) {
    const json::Value* f = r->find("force");
    const json::Value* g = r->find("form");
    if ((f && f->text != std::to_string(b.rank_force)) || (g && g->text != std::to_string(b.rank_form)))
      why = e.id + ": rank differs from the golden file";
  }
  return why;
}

}  // namespace

Reference_corpus build_reference(const Reference_options& ro) {
  if (!ro.scenes.empty()) return user_corpus(ro.scenes, ro.sides);
  Reference_corpus corpus;
  for (const Entry& e : corpus_entries(ro)) {
    Reference_item b = reference_item(e, ro.sides);
    if (b.status == Status::answered && !e.expected.empty())
      if (std::string why = golden_disagreement(e, b); !why.empty()) b.status = Status::check_failed, b.message = why;
    if (!corpus.add(e.id, std::move(b))) break;
  }
  return corpus;
}

std::string reference_manifest(const Reference_options& ro, std::size_t scenes) {
  if (!ro.scenes.empty()) return user_manifest(ro.scenes, ro.sides, scenes);
  Json_writer m(512);
  m.object().member("wrenchkit_reference", kReferenceFormat).member("generator", "wrenchkit 0.1.0");
  m.member("format", "docs/reference-format.md").member("seed", std::to_string(ro.seed)).member("cases", ro.cases);
  m.member("random", ro.random).member("sides", ro.sides);
  m.key("epsilons").array();
  for (int k : kEpsilonExponents) m.string("1e-" + std::to_string(k));
  m.end_array().member("scenes", scenes).key("files").object().member("corpus", "reference.jsonl");
  m.member("scenes", "scenes/").member("verdicts", "expected.csv").end_object().end_object();
  return m.take() + "\n";
}

}  // namespace wrenchkit
