// The reference corpus for other implementations (docs/reference-format.md): the shared scene
// families [ST-1], the boundary measure [RF-1], and `wrenchkit reference` / `wrenchkit compare` end to
// end — deterministic bytes, every certificate accepted by the independent checker, every answer
// re-derived by brute force, disagreements and bad input reported as documented.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "exact/statics/boundary_distance.h"
#include "exact/statics/equilibrium.h"
#include "exact/statics/generators.h"
#include "exact/io/json.h"
#include "exact/io/scene_writer.h"
#include "testing/stress_families.h"
#include "tests/test_support.h"

namespace wrenchkit {
namespace {

namespace fs = std::filesystem;
using test::Cli_result;

// ---- [ST-1] the scene families -------------------------------------------------------------------

TEST(StressFamilies, SameSeedSameBytesAndPinnedText) {
  for (const stress::Family& f : stress::families()) {
    const auto a = stress::make_scene(f.name, 1e-10, 42), b = stress::make_scene(f.name, 1e-10, 42);
    EXPECT_EQ(a.text, b.text) << f.name;
    EXPECT_NO_THROW(read_scene(a.text, Input_limits{})) << f.name << "\n" << a.text;
  }
  // The bytes are pinned: the corpus must be reproducible on every platform and every version
  // (mt19937_64 and IEEE +, −, ×, ÷ only). A change here changes every corpus: bump its version.
  EXPECT_EQ(stress::make_scene("friction_threshold", 1e-10, 42).text,
            "{\"wrenchkit\": 1, \"contacts\": [{\"at\": [2.0327902363446251, -3.5313974184334911], \"normal\": "
            "[0.21175149048427691, 0.97732354227128249], \"mu\": 0.36430443649765815}, {\"at\": "
            "[1.8884984244502627, -2.4769318687360808], \"normal\": [-0.21175149048427691, -0.97732354227128249], "
            "\"mu\": 0.36430443649765815}]}");
  // The exact families appended to the corpus in issue 6 (GMP integers only: exact, so the same everywhere).
  EXPECT_EQ(stress::make_scene("long_rational", 1e-10, 42).text,
            "{\"wrenchkit\": 1, \"contacts\": [{\"at\": [\"683774450943818934271954891710/465431517333929022340208053667\", "
            "\"1345537714096194554039044117390/642205966322489390039894669079\"], \"normal\": [1, 0], \"mu\": "
            "\"11272979047081908381315339619060217783591587811548060196316734258444487/"
            "12571795519728468074970135291423762500419164364255678118192000000000000\"}, {\"at\": "
            "[\"198753392938101378633975079921988979929756021025096691848394/"
            "76612350348983619176153852936039378020772016094926104659827\", "
            "\"13531669277987668146647132134317089036921473026963465719304367/"
            "4359298518379708873586840361935168326109687584227227033528400\"], \"normal\": [-1, 0], \"mu\": "
            "\"11272979047081908381315339619060217783591587811548060196316734258444487/"
            "12571795519728468074970135291423762500419164364255678118192000000000000\"}]}");
  EXPECT_EQ(stress::make_scene("ladder_equilibrium", 1e-6, 1).text.find("\"mu\": \"999999/7000000\"") !=
                std::string::npos ||
            stress::make_scene("ladder_equilibrium", 1e-6, 1).text.find("\"mu\": \"1000001/7000000\"") !=
                std::string::npos,
            true);
}

TEST(StressFamilies, UnknownFamilyAndBadEpsilonThrow) {
  EXPECT_THROW(stress::make_scene("no_such_family", 1e-3, 1), std::invalid_argument);
  EXPECT_THROW(stress::make_scene("cone_edge", 0, 1), std::invalid_argument);
  EXPECT_THROW(stress::make_scene("cone_edge", 2, 1), std::invalid_argument);
  EXPECT_NO_THROW(stress::make_scene("random_grid", 0, 1));  // random families ignore ε
}

TEST(StressFamilies, NearDegenerateFamiliesLandOnTheStatedSide) {
  // friction_threshold: closure iff above (μ = μ*(1 + ε)); ε large enough that rounding cannot flip it.
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto s = stress::make_scene("friction_threshold", 1e-6, seed);
    EXPECT_EQ(decide_closure(read_scene(s.text, Input_limits{}), Property::force_closure).holds, s.above) << s.text;
    const auto l = stress::make_scene("ladder_equilibrium", 1e-30, seed);  // exact fractions: any ε
    EXPECT_EQ(decide_equilibrium(read_scene(l.text, Input_limits{})).balanced, l.above) << l.text;
  }
}

// ---- [RF-1] the boundary measure -------------------------------------------------------------------

TEST(BoundaryDistance, FrictionScaleBracketsTheThreshold) {
  // Two fingers at y = 1/2 and y = 1, d = (1, 1/2): closure iff μ > 1/2. At μ = 1/2·(1 + 10^-6) the flip
  // is at s* = 1/(1 + 10^-6): the bracket must contain it and the distance be about 10^-6.
  const std::string scene = test::scene_json({{"0", "1/2", "1", "0", "1000001/2000000"}, {"1", "1", "-1", "0", "1000001/2000000"}});
  const Boundary_distance b = boundary_distance(read_scene(scene, Input_limits{}));
  ASSERT_TRUE(b.closure_flip);
  const Rational s_star = Rational(1000000, 1000001);
  EXPECT_LT(b.closure_flip->lo, s_star);
  EXPECT_GE(b.closure_flip->hi, s_star);
  EXPECT_GT(b.closure_flip->distance, 0.9e-6);
  EXPECT_LT(b.closure_flip->distance, 1.1e-6);
  ASSERT_TRUE(b.distance);
  EXPECT_LE(*b.distance, b.closure_flip->distance);
}

TEST(BoundaryDistance, ExactlyAtTheLadderThresholdIsWithin2ToMinus160) {
  const std::string text = test::read_text(test::source_dir() + "/tests/golden/equilibrium/ladder_mu_1_7_gravity.scene.json");
  const Boundary_distance b = boundary_distance(read_scene(text, Input_limits{}));
  ASSERT_TRUE(b.equilibrium_flip);
  EXPECT_EQ(b.equilibrium_flip->hi, 1);  // balanced at μ = 1/7 exactly, not below
  EXPECT_LT(b.equilibrium_flip->distance, 1e-48);
  EXPECT_EQ(b.nearest, "friction_scale");
}

TEST(BoundaryDistance, DeterminantMeasureFollowsEpsilonAndIgnoresPlacement) {
  // nearly_concurrent at ε: the smallest deciding determinant is about ε (the family's geometry), and
  // the same scene moved by 10^6 and scaled by 10^3 measures the same (the scene's own frame).
  for (double eps : {1e-4, 1e-8, 1e-12}) {
    const auto s = stress::make_scene("nearly_concurrent", eps, 7);
    const Boundary_distance b = boundary_distance(read_scene(s.text, Input_limits{}));
    ASSERT_TRUE(b.form.min_relative);
    EXPECT_GT(*b.form.min_relative, eps / 100) << s.text;
    EXPECT_LT(*b.form.min_relative, eps * 100) << s.text;
  }
  const std::string near = test::scene_json({{"1", "0", "0", "1", "0"}, {"0", "1", "1", "0", "0"},
                                             {"3", "3.000000001", "-1", "-1", "0"}, {"2", "4", "0", "-1", "0"}});
  const std::string moved = test::scene_json({{"1000001000", "2000000000", "0", "1", "0"}, {"1000000000", "2000001000", "1", "0", "0"},
                                              {"1000003000", "2000003000.000001", "-1", "-1", "0"}, {"1000002000", "2000004000", "0", "-1", "0"}});
  const auto a = boundary_distance(read_scene(near, Input_limits{}));
  const auto b = boundary_distance(read_scene(moved, Input_limits{}));
  ASSERT_TRUE(a.form.min_relative && b.form.min_relative);
  EXPECT_NEAR(*a.form.min_relative / *b.form.min_relative, 1.0, 1e-6);
}

TEST(BoundaryDistance, ExactDegeneraciesAreCountedAndFrictionlessHasNoScale) {
  // Vertical walls squeeze: parallel frictionless walls, exactly degenerate determinants.
  const std::string text = test::read_text(test::source_dir() + "/tests/golden/vertical_walls_squeeze.scene.json");
  const Boundary_distance b = boundary_distance(read_scene(text, Input_limits{}));
  EXPECT_GT(b.exact_zeros(), 0u);
  EXPECT_FALSE(b.closure_flip);
}

// ---- wrenchkit reference / compare ------------------------------------------------------------------

fs::path scratch() { return test::scratch_dir("reference_test"); }
Cli_result run(const std::string& args, const std::string& in = "") {
  return test::run_cli(WRENCHKIT_CLI, "", args, in, "reference_test");
}

std::map<std::string, std::string> files_of(const fs::path& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) m[fs::relative(e.path(), dir).string()] = test::read_text(e.path().string());
  return m;
}

class Corpus : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = (scratch() / "corpus").string();
    fs::remove_all(dir_);
    const Cli_result r = run("reference --out '" + dir_ + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    std::istringstream in(test::read_text(dir_ + "/reference.jsonl"));
    for (std::string line; std::getline(in, line);) lines_.push_back(json::parse(line, Input_limits{}, "corpus"));
  }
  static std::string dir_;
  static std::vector<json::Value> lines_;
};
std::string Corpus::dir_;
std::vector<json::Value> Corpus::lines_;

TEST_F(Corpus, SameBytesOnEveryRun) {
  const std::string again = (scratch() / "again").string();
  fs::remove_all(again);
  const Cli_result r = run("reference --out '" + again + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto a = files_of(dir_), b = files_of(again);
  EXPECT_GT(a.size(), 300u);
  EXPECT_TRUE(a == b) << "two runs of wrenchkit reference differ";
  // Modest by default: a few MB at most.
  EXPECT_LT(fs::file_size(dir_ + "/reference.jsonl"), 3u << 20);
}

TEST_F(Corpus, HoldsEveryKindOfScene) {
  std::map<std::string, int> families;
  int with_load = 0, with_support = 0;
  std::map<std::string, int> holds, motions, distributions;  // the certified answers of this round's questions
  for (const json::Value& v : lines_) {
    ++families[v.find("family")->text];
    with_load += v.find("equilibrium") != nullptr;
    with_support += v.find("limit_surface") != nullptr;
    if (const json::Value* h = v.find("hold")) {
      EXPECT_NE(v.find("equilibrium"), nullptr) << v.find("id")->text;  // hold needs a load
      ++holds[h->type == json::Type::null ? "null" : json::text_of(*h)];
      // Written only with its certificate, which the checker accepted (EveryCertificateIs…).
      EXPECT_EQ(h->type != json::Type::null, v.find("certificates")->find("hold") != nullptr) << v.find("id")->text;
      EXPECT_EQ(h->type == json::Type::null, v.find("hold_uncertified") != nullptr) << v.find("id")->text;
    } else {
      EXPECT_EQ(v.find("equilibrium"), nullptr) << v.find("id")->text;
    }
    if (const json::Value* ls = v.find("limit_surface"); ls && ls->type == json::Type::object) {
      const json::Value* d = ls->find("distribution");
      const std::string dist = d ? d->text : "known";
      ++distributions[dist];
      if (const json::Value* m = v.find("motion"); m && m->type == json::Type::string) ++motions[dist + " " + m->text];
    }
  }
  for (const char* f : {"golden", "friction_threshold", "cone_edge", "nearly_concurrent", "nearly_parallel", "huge_offset",
                        "ladder_equilibrium", "random_generic", "random_grid", "long_rational", "rational_rotation",
                        "unknown_support", "region_support", "fixture_pin", "random_fixture", "fixture_regions"})
    EXPECT_GT(families[f], 0) << f;
  EXPECT_GT(with_load, 50);
  EXPECT_GT(with_support, 20);
  // Issue 20: hold either way (and "depends" over unknown distributions), regions and unknown distributions with
  // certified motions either way.
  for (const char* h : {"true", "false", "\"depends\""}) EXPECT_GT(holds[h], 0) << h;
  EXPECT_GT(distributions["unknown"], 0);
  EXPECT_GT(distributions["regions"], 0);
  for (const char* m : {"regions sticks", "regions slides", "unknown slides", "unknown depends", "known sticks",
                        "known slides"})
    EXPECT_GT(motions[m], 0) << m;
  // Issue 16 [HD-2] [RG-3]: hold and stick/slide over regions with legs whose forces are not given — every verdict,
  // certified (format 3 since issue 29); the limit surface is the power's range over F.
  std::map<std::string, int> region_holds, region_motions;
  for (const json::Value& v : lines_) {
    if (v.find("family")->text != "fixture_regions") continue;
    const json::Value* h = v.find("hold");
    ASSERT_NE(h, nullptr);
    ASSERT_NE(h->type, json::Type::null) << v.find("id")->text;
    ++region_holds[json::text_of(*h)];
    EXPECT_EQ(v.find("certificates")->find("hold")->find("wrenchkit_certificate")->text, "3") << v.find("id")->text;
    ASSERT_EQ(v.find("limit_surface")->type, json::Type::object) << v.find("id")->text;
    EXPECT_EQ(v.find("limit_surface")->find("distribution")->text, "unknown") << v.find("id")->text;
    EXPECT_EQ(v.find("limit_surface_refused"), nullptr) << v.find("id")->text;
    const json::Value* m = v.find("motion");
    ASSERT_NE(m, nullptr);
    ASSERT_EQ(m->type, json::Type::string) << v.find("id")->text;
    ++region_motions[m->text];
    EXPECT_EQ(v.find("certificates")->find("motion")->find("wrenchkit_certificate")->text, "3") << v.find("id")->text;
  }
  for (const char* h : {"true", "false", "\"depends\""}) EXPECT_GT(region_holds[h], 0) << h;
  for (const char* m : {"sticks", "slides", "depends"}) EXPECT_GT(region_motions[m], 0) << m;
}

TEST_F(Corpus, EveryCertificateIsAcceptedByTheIndependentChecker) {
  std::size_t checked = 0;
  for (const json::Value& v : lines_) {
    const std::string scene = json::text_of(*v.find("scene"));
    for (const auto& [what, cert] : v.find("certificates")->members) {
      EXPECT_TRUE(test::checker_accepts(scene, json::text_of(cert))) << v.find("id")->text << " " << what;
      ++checked;
    }
  }
  EXPECT_GT(checked, 700u);
}

TEST_F(Corpus, SceneFilesAreCanonicalAndMatchTheLines) {
  for (const json::Value& v : lines_) {
    const std::string file = test::read_text(dir_ + "/" + v.find("scene_file")->text);
    const Scene from_file = read_scene(file, Input_limits{});
    EXPECT_EQ(write_scene(from_file), file) << v.find("id")->text;
    EXPECT_EQ(write_scene(read_scene(json::text_of(*v.find("scene")), Input_limits{})), file) << v.find("id")->text;
  }
}

TEST_F(Corpus, AnswersAgreeWithBruteForce) {
  // Independent re-derivation (tests/test_support: O(k³) brute force over the generators, Carathéodory
  // for the load), not the engine's dual cone.
  for (const json::Value& v : lines_) {
    const std::string id = v.find("id")->text;
    const Scene s = read_scene(json::text_of(*v.find("scene")), Input_limits{});
    std::vector<Vec3q> fr, fl;
    for (const Generator& g : generators(s, Reading::friction)) fr.push_back(g.w);
    for (const Generator& g : generators(s, Reading::frictionless)) fl.push_back(g.w);
    EXPECT_EQ(test::brute_force_closure(fr), v.find("force_closure")->boolean) << id;
    EXPECT_EQ(test::brute_force_closure(fl), v.find("form_closure")->boolean) << id;
    if (const json::Value* eq = v.find("equilibrium")) {
      const Vec3q w = load_wrench(s);
      EXPECT_EQ(test::brute_force_in_cone(fr, {-w[0], -w[1], -w[2]}), eq->boolean) << id;
    }
  }
}

TEST_F(Corpus, GoldenAndFamilyFieldsAreAsDocumented) {
  int goldens = 0;
  for (const json::Value& v : lines_) {
    const std::string family = v.find("family")->text;
    const json::Value& b = *v.find("boundary");
    if (family == "golden") {
      ++goldens;
      EXPECT_EQ(v.find("epsilon")->type, json::Type::null);
      EXPECT_TRUE(fs::exists(test::source_dir() + "/" + v.find("source")->text)) << v.find("source")->text;
    } else if (family.rfind("random", 0) != 0) {
      EXPECT_EQ(v.find("epsilon")->text, b.find("epsilon")->text);
    }
    if (const json::Value* ls = v.find("limit_surface"); ls && ls->type == json::Type::object) {
      const json::Value* d = ls->find("distribution");
      for (const json::Value& t : ls->find("twists")->items) {
        if (d && d->text == "unknown") {  // the power's range over the admissible distributions
          EXPECT_LE(Rational(t.find("power_range")->items[0].text), Rational(t.find("power_range")->items[1].text));
          continue;
        }
        const Rational lo(t.find("power_bracket")->items[0].text), hi(t.find("power_bracket")->items[1].text);
        EXPECT_LE(lo, hi);
        if (d) {  // regions: a certified bracket of relative width at most 10^-15
          EXPECT_EQ(d->text, "regions");
          EXPECT_LE(hi - lo, Rational(1, 1000000) * Rational(1, 1000000000) * abs(hi)) << v.find("id")->text;
          continue;
        }
        const Rational in(t.find("h_inner")->text), out(t.find("h_outer")->text);
        EXPECT_LE(in, hi);  // h_in ≤ h ≤ h_out
        EXPECT_GE(out, lo);
      }
    }
  }
  EXPECT_GE(goldens, 60);
}

TEST_F(Corpus, CompareAgreesWithItsOwnVerdicts) {
  Cli_result r = run("compare '" + dir_ + "' '" + dir_ + "/expected.csv'");
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("every given answer agrees"), std::string::npos) << r.out;
  // The same as JSON lines, with numbers: the corpus' own centre of friction and powers (as decimals
  // within tolerance), and labels.
  std::string jsonl;
  for (const json::Value& v : lines_) {
    jsonl += "{\"id\": " + json::quote(v.find("id")->text) + ", \"force_closure\": " + json::text_of(*v.find("force_closure"));
    for (const char* f : {"hold", "motion"})  // this round's answers, as the corpus writes them (null: no answer)
      if (const json::Value* x = v.find(f)) jsonl += std::string(", \"") + f + "\": " + json::text_of(*x);
    const json::Value* ls = v.find("limit_surface");
    const json::Value* d = ls ? ls->find("distribution") : nullptr;
    if (ls && ls->type == json::Type::object && !(d && d->text == "unknown")) {
      jsonl += ", \"center_of_friction\": " + json::text_of(*ls->find("center_of_friction")) + ", \"power\": [";
      const auto& tw = ls->find("twists")->items;
      for (std::size_t i = 0; i < tw.size(); ++i)
        jsonl += (i ? ", " : "") + stress::number_text(Rational(tw[i].find("power_bracket")->items[0].text).get_d());
      jsonl += "]";
    }
    const json::Value& plus = *v.find("labels")->find("plus");
    jsonl += ", \"labels\": {\"plus\": {\"empty\": " + json::text_of(*plus.find("empty")) + ", \"vertices\": " +
             json::text_of(*plus.find("vertices")) + "}}}\n";
  }
  r = run("compare --json '" + dir_ + "' -", jsonl);
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("\"agree\": true"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"power\": {\"compared\": "), std::string::npos) << r.out;
}

TEST_F(Corpus, ExpectedCsvHasEveryLinesVerdictsHoldIncluded) {
  // expected.csv: id,force_closure,form_closure,equilibrium,hold — the lines' verdicts, empty where a line has none
  // (no load, or a hold without a certificate).
  std::istringstream csv(test::read_text(dir_ + "/expected.csv"));
  std::string row;
  std::getline(csv, row);
  EXPECT_EQ(row, "id,force_closure,form_closure,equilibrium,hold");
  const auto cell = [](const json::Value* x) {
    return !x || x->type == json::Type::null ? std::string() : x->type == json::Type::string ? x->text : json::text_of(*x);
  };
  std::size_t rows = 0, holds = 0, depends = 0;
  for (const json::Value& v : lines_) {
    ASSERT_TRUE(std::getline(csv, row));
    const std::string want = v.find("id")->text + "," + cell(v.find("force_closure")) + "," +
                             cell(v.find("form_closure")) + "," + cell(v.find("equilibrium")) + "," + cell(v.find("hold"));
    EXPECT_EQ(row, want);
    ++rows;
    holds += !cell(v.find("hold")).empty();
    depends += cell(v.find("hold")) == "depends";
  }
  EXPECT_FALSE(std::getline(csv, row)) << row;
  EXPECT_GT(holds, 50u);
  EXPECT_GE(depends, 1u);
  EXPECT_GT(rows, 400u);
}

TEST_F(Corpus, CompareReportsADisagreementWithItsScene) {
  // Flip one verdict far from any boundary and one near it: exit 1, both named, far one first.
  std::string csv = test::read_text(dir_ + "/expected.csv");
  auto flip = [&](const std::string& id) {
    const std::size_t at = csv.find("\n" + id + ",") + 1;
    const std::size_t comma = csv.find(',', at) + 1;
    const bool was_true = csv.compare(comma, 4, "true") == 0;
    csv.replace(comma, was_true ? 4 : 5, was_true ? "false" : "true");
  };
  flip("golden.two_finger_y1_2_mu1_10");
  flip("friction_threshold.1e-16.0");
  const fs::path answers = scratch() / "flipped.csv";
  std::ofstream(answers) << csv;
  const Cli_result r = run("compare '" + dir_ + "' '" + answers.string() + "'");
  EXPECT_EQ(r.code, 1) << r.err;
  const std::size_t far = r.out.find("golden.two_finger_y1_2_mu1_10"), near = r.out.find("friction_threshold.1e-16.0");
  ASSERT_NE(far, std::string::npos) << r.out;
  ASSERT_NE(near, std::string::npos) << r.out;
  EXPECT_LT(far, near) << r.out;
  EXPECT_NE(r.out.find("2 disagreements: 1 far from any degenerate boundary"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("scenes/friction_threshold.1e-16.0.json"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("eps 1e-16"), std::string::npos) << r.out;
  const Cli_result j = run("compare --json '" + dir_ + "' '" + answers.string() + "'");
  EXPECT_EQ(j.code, 1);
  EXPECT_NE(j.out.find("\"near_boundary\": 1, \"far_from_boundary\": 1, \"no_boundary_measure\": 0, \"unsafe\": 0, \"lost\": 2"),
            std::string::npos)
      << j.out;
  EXPECT_NE(j.out.find("\"kind\": \"falsely open\", \"unsafe\": false"), std::string::npos) << j.out;
  EXPECT_NE(r.out.find("(unsafe: 0 falsely closed; lost: 2 falsely open)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("force_closure: falsely open (lost): reference true, answer false"), std::string::npos) << r.out;
}

TEST_F(Corpus, CompareReadsQuotedCsvAndPythonBooleans) {
  // What pandas' to_csv and Python's csv.writer produce: "quoted" ids (with "" for a quote), True/False,
  // blanks around cells, CRLF line ends. The same verdicts as expected.csv: agreement, exit 0.
  const std::string csv = test::read_text(dir_ + "/expected.csv");
  std::string out = "\"id\" , force_closure,form_closure ,equilibrium, hold\r\n";
  std::size_t start = csv.find('\n') + 1, rows = 0;
  while (start < csv.size()) {
    std::size_t end = csv.find('\n', start);
    if (end == std::string::npos) end = csv.size();
    std::string l = csv.substr(start, end - start);
    start = end + 1;
    if (l.empty()) continue;
    const std::size_t comma = l.find(',');
    std::string rest = l.substr(comma);
    for (auto [from, to] : {std::pair<std::string, std::string>{"true", "True"}, {"false", "False"}})
      for (std::size_t i = rest.find(from); i != std::string::npos; i = rest.find(from, i + to.size()))
        rest.replace(i, from.size(), to);
    out += " \"" + l.substr(0, comma) + "\"" + rest + "\r\n";
    ++rows;
  }
  ASSERT_GT(rows, 100u);
  const fs::path answers = scratch() / "pandas.csv";
  std::ofstream(answers, std::ios::binary) << out;
  const Cli_result r = run("compare '" + dir_ + "' '" + answers.string() + "'");
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  // A quote inside a quoted id is "": read as one quote, so the id is not in the corpus (named as read).
  const fs::path odd = scratch() / "odd.csv";
  std::ofstream(odd) << "id,force_closure\n\"a\"\"b\",true\n";
  const Cli_result o = run("compare '" + dir_ + "' '" + odd.string() + "'");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("a\"b"), std::string::npos) << o.err;
}

TEST_F(Corpus, CompareReadsVerdictsAsNumPyWritesThem) {
  // The corpus' own verdicts written every way NumPy and pandas users write them, in JSON lines and CSV
  // alike: agreement, exit 0. Then one verdict flipped, written as 1: found.
  const auto forms = [](bool b, int k) -> std::string {
    switch (k % 6) {
      case 0: return b ? "1" : "0";
      case 1: return b ? "1.0" : "0.0";
      case 2: return b ? "true" : "false";
      case 3: return b ? "\"True\"" : "\"False\"";
      case 4: return b ? "\"1\"" : "\"0\"";
      default: return b ? "1e0" : "-0.0";
    }
  };
  std::string jsonl;
  int k = 0;
  for (const json::Value& v : lines_) {
    const bool fc = v.find("force_closure")->boolean, fo = v.find("form_closure")->boolean;
    jsonl += "{\"id\": " + json::quote(v.find("id")->text) + ", \"force_closure\": " + forms(fc, k) +
             ", \"form_closure\": " + forms(fo, k + 1) + "}\n";
    ++k;
  }
  Cli_result r = run("compare '" + dir_ + "' -", jsonl);
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  const fs::path p = scratch() / "numpy.csv";
  std::string fixed = "id,force_closure,form_closure\n";  // pandas: 1.0/0.0 (a float column), True/False
  k = 0;
  for (const json::Value& v : lines_) {
    const bool fc = v.find("force_closure")->boolean, fo = v.find("form_closure")->boolean;
    fixed += v.find("id")->text + "," + (fc ? "1.0" : "0.0") + "," + (k++ % 2 ? (fo ? "True" : "False") : (fo ? "1" : "0")) + "\n";
  }
  std::ofstream(p) << fixed;
  r = run("compare '" + dir_ + "' '" + p.string() + "'");
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  r = run("compare '" + dir_ + "' -", "{\"id\": \"golden.ladder_mu_1_7\", \"force_closure\": 1}\n");
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("force_closure: falsely closed (unsafe): reference false, answer true"), std::string::npos) << r.out;
}

TEST_F(Corpus, ComparePowerShowsTwistBracketAndRelativeErrorAndIncompleteIsNoAnswer) {
  const json::Value* barbell = nullptr;
  for (const json::Value& v : lines_)
    if (v.find("id")->text == "golden.limit_surface.barbell") barbell = &v;
  ASSERT_NE(barbell, nullptr);
  const auto& tw = barbell->find("limit_surface")->find("twists")->items;
  ASSERT_EQ(json::text_of(*tw[2].find("power_bracket")), "[\"1\", \"1\"]");
  std::string good = "[", bad = "[", partial = "[";
  for (std::size_t i = 0; i < tw.size(); ++i) {
    const double h = *nearest_double(Rational(tw[i].find("power_bracket")->items[0].text));
    good += (i ? ", " : "") + stress::number_text(h);
    bad += (i ? ", " : "") + (i == 2 ? std::string("1.001") : stress::number_text(h));  // the bracket at 2 is [1, 1]
    partial += (i ? ", " : "") + (i == 1 ? std::string("null") : stress::number_text(h));
  }
  const std::string id = "{\"id\": \"golden.limit_surface.barbell\", \"power\": ";
  Cli_result r = run("compare '" + dir_ + "' -", id + partial + "]}\n");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("power                    0 compared       0 agree       0 disagree       1 no answer"),
            std::string::npos) << r.out;
  r = run("compare '" + dir_ + "' -", id + bad + "]}\n");
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("1 of 5 twists outside the reference\n      twist 2 [\"0\", \"0\", \"1\"]: reference"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("relative error 0.001"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no boundary measure for power"), std::string::npos) << r.out;
  r = run("compare --json '" + dir_ + "' -", id + bad + "]}\n");
  EXPECT_NE(r.out.find("\"twists\": [{\"index\": 2, \"twist\": [\"0\", \"0\", \"1\"], \"bracket\": ["), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\"relative_error\": 0.001"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"bracket_approx\": ["), std::string::npos) << r.out;
  r = run("compare '" + dir_ + "' -", id + good + "]}\n");
  EXPECT_EQ(r.code, 0) << r.out;
}

// hold as a CSV column (true/false/depends, the corpus' own answers) agrees; each flipped hold is counted unsafe
// (falsely holds) or lost (falsely fails or depends) with no boundary measure over a support.
TEST_F(Corpus, CompareReadsHoldAndSplitsUnsafeFromLost) {
  std::string csv = "id,hold\n", flipped = csv;
  std::size_t holds = 0, fails = 0, depends = 0;
  std::string a_hold, a_fail;  // a certified true and a certified false over a support
  for (const json::Value& v : lines_) {
    const json::Value* h = v.find("hold");
    if (!h || h->type == json::Type::null) continue;
    const std::string id = v.find("id")->text;
    const std::string word = h->type == json::Type::string ? h->text : h->boolean ? "true" : "false";
    (word == "true" ? holds : word == "false" ? fails : depends) += 1;
    csv += id + "," + word + "\n";
    if (v.find("limit_surface") && word == "true" && a_hold.empty()) a_hold = id;
    if (v.find("limit_surface") && word == "false" && a_fail.empty()) a_fail = id;
  }
  ASSERT_GT(holds, 0u);
  ASSERT_GT(fails, 0u);
  ASSERT_GT(depends, 0u);
  ASSERT_FALSE(a_hold.empty() || a_fail.empty());
  const fs::path f = scratch() / "holds.csv";
  std::ofstream(f) << csv;
  Cli_result r = run("compare --json '" + dir_ + "' '" + f.string() + "'");
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  const std::string n = std::to_string(holds + fails + depends);
  EXPECT_NE(r.out.find("\"hold\": {\"compared\": " + n + ", \"agree\": " + n + ","), std::string::npos) << r.out;
  // JSON lines, as a peer writes them: 0 where it holds (lost), 1 where it fails (unsafe).
  r = run("compare --json '" + dir_ + "' -",
          "{\"id\": \"" + a_hold + "\", \"hold\": 0}\n{\"id\": \"" + a_fail + "\", \"hold\": 1}\n");
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  const json::Value rep = json::parse(r.out, Input_limits{}, "report");
  const json::Value& t = *rep.find("fields")->find("hold");
  EXPECT_EQ(t.find("unsafe")->text, "1");
  EXPECT_EQ(t.find("lost")->text, "1");
  for (const json::Value& d : rep.find("disagreements")->items) {
    const std::string id = d.find("id")->text;
    EXPECT_EQ(d.find("kind")->text, id == a_hold ? "falsely fails" : "falsely holds") << id;
    EXPECT_EQ(d.find("unsafe")->boolean, id == a_fail) << id;
    EXPECT_FALSE(d.find("boundary_measured")->boolean) << id;
  }
}

// ε in the corpus (docs/reference-format.md §2): every line with contacts has `quality` — its bracket agreeing with
// force closure (ε > 0 exactly when closed), in the default conventions, its certificate among the line's — and
// compare reads a peer's `epsilon`: the reference's nearest doubles agree; a positive ε for an open grasp is unsafe
// ("falsely closed"), 0 for a closed one lost ("falsely open"), a closed grasp's ε off by 1 % a wrong value; a
// scene without contacts has no epsilon to answer (exit 2).
TEST_F(Corpus, EpsilonIsInTheCorpusAndCompared) {
  std::string good, bad;
  std::string open_id, closed_id, no_contacts;
  std::size_t with = 0;
  for (const json::Value& v : lines_) {
    const std::string id = v.find("id")->text;
    const json::Value* q = v.find("quality");
    const json::Value* contacts = v.find("scene")->find("contacts");
    const bool has_contacts = contacts && !contacts->items.empty();
    ASSERT_EQ(q != nullptr, has_contacts) << id;
    if (!q) {
      if (no_contacts.empty()) no_contacts = id;
      continue;
    }
    ASSERT_EQ(q->type, json::Type::object) << id;  // (none past the work bound in the default corpus)
    ++with;
    const json::Value& e = *q->find("epsilon");
    EXPECT_EQ(e.find("norm")->text, "L1") << id;
    EXPECT_EQ(e.find("normalize")->text, "unit-normal") << id;
    EXPECT_EQ(e.find("torque_scale")->text, "1") << id;
    const Rational lo(e.find("lower")->text), hi(e.find("upper")->text);
    ASSERT_LE(lo, hi) << id;
    EXPECT_EQ(hi > 0, v.find("force_closure")->boolean) << id;
    ASSERT_NE(v.find("certificates")->find("quality"), nullptr) << id;
    const std::string approx = v.find("approx")->find("quality")->find("epsilon")->find("lower")->text;
    good += "{\"id\": \"" + id + "\", \"epsilon\": " + approx + "}\n";
    if (hi == 0 && open_id.empty()) open_id = id, bad += "{\"id\": \"" + id + "\", \"epsilon\": 0.001}\n";
    if (lo > Rational(1, 1000) && closed_id.empty()) closed_id = id, bad += "{\"id\": \"" + id + "\", \"epsilon\": 0}\n";
  }
  ASSERT_GT(with, 300u);
  ASSERT_FALSE(open_id.empty() || closed_id.empty() || no_contacts.empty());
  Cli_result r = run("compare --json '" + dir_ + "' -", good);
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("\"epsilon\": {\"compared\": " + std::to_string(with) + ", \"agree\": " + std::to_string(with) + ","),
            std::string::npos) << r.out;
  r = run("compare --json '" + dir_ + "' -", bad);
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  const json::Value rep = json::parse(r.out, Input_limits{}, "report");
  EXPECT_EQ(rep.find("fields")->find("epsilon")->find("unsafe")->text, "1");
  EXPECT_EQ(rep.find("fields")->find("epsilon")->find("lost")->text, "1");
  for (const json::Value& d : rep.find("disagreements")->items) {
    const std::string id = d.find("id")->text;
    EXPECT_EQ(d.find("kind")->text, id == open_id ? "falsely closed" : "falsely open") << id;
    EXPECT_EQ(d.find("field")->text, "epsilon");
  }
  r = run("compare '" + dir_ + "' -", "{\"id\": \"" + no_contacts + "\", \"epsilon\": 1}\n");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("has no contacts (no epsilon answer)"), std::string::npos) << r.err;
}

// Issue 33: the pushing families at the end of the corpus land on their stated sides — push_near_tie turns ccw iff
// above, push_motion_cone's contact slides left iff above (else sticks) — certified; and `compare` reads a peer's
// contact mode: sticking where it slides is unsafe ("falsely sticks"), undecided lost, a value it cannot read refused.
TEST_F(Corpus, PushingFamiliesLandOnTheirSidesAndCompareReadsTheContactMode) {
  std::string good, bad, sliding_id, sticking_id;
  std::size_t tie = 0, cone = 0;
  for (const json::Value& v : lines_) {
    const std::string id = v.find("id")->text, family = v.find("family")->text;
    if (family == "push_fence_edge") continue;  // (the next test)
    if (family != "push_near_tie" && family != "push_motion_cone") {
      EXPECT_EQ(v.find("push"), nullptr) << id;  // no other family has a pusher
      continue;
    }
    const bool above = v.find("side")->text == "above";
    const json::Value* push = v.find("push");
    ASSERT_NE(push, nullptr) << id;
    ASSERT_EQ(push->type, json::Type::object) << id;
    ASSERT_NE(v.find("certificates")->find("push"), nullptr) << id;
    const std::string mode = push->find("contact")->find("mode")->text;
    if (family == "push_near_tie") {
      ++tie;
      EXPECT_EQ(push->find("rotation")->text, above ? "ccw" : "cw") << id;
    } else {
      ++cone;
      EXPECT_EQ(mode, above ? "slides left" : "sticks") << id;
      EXPECT_NE(v.find("certificates")->find("push")->find("contact"), nullptr) << id;
      if (above && sliding_id.empty()) sliding_id = id, bad += "{\"id\": \"" + id + "\", \"contact_mode\": \"sticks\"}\n";
      if (!above && sticking_id.empty()) sticking_id = id, bad += "{\"id\": \"" + id + "\", \"contact_mode\": \"undecided\"}\n";
    }
    good += "{\"id\": \"" + id + "\", \"contact_mode\": \"" + mode + "\"}\n";
  }
  ASSERT_EQ(tie, 14u);
  ASSERT_EQ(cone, 14u);
  ASSERT_FALSE(sliding_id.empty() || sticking_id.empty());
  Cli_result r = run("compare --json '" + dir_ + "' -", good);
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("\"contact_mode\": {\"compared\": 28, \"agree\": 28,"), std::string::npos) << r.out;
  r = run("compare --json '" + dir_ + "' -", bad);
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  const json::Value rep = json::parse(r.out, Input_limits{}, "report");
  EXPECT_EQ(rep.find("fields")->find("contact_mode")->find("unsafe")->text, "1");
  EXPECT_EQ(rep.find("fields")->find("contact_mode")->find("lost")->text, "1");
  for (const json::Value& d : rep.find("disagreements")->items) {
    const std::string id = d.find("id")->text;
    EXPECT_EQ(d.find("kind")->text, id == sliding_id ? "falsely sticks" : "an uncertain contact mode") << id;
  }
  r = run("compare '" + dir_ + "' -", "{\"id\": \"" + sliding_id + "\", \"contact_mode\": \"slides\"}\n");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("contact_mode: \"slides\" is not \"sticks\""), std::string::npos) << r.err;
  r = run("compare '" + dir_ + "' -", "{\"id\": \"golden.block_corner_mu_0\", \"contact_mode\": \"sticks\"}\n");
  EXPECT_EQ(r.code, 2);
}

// Issue 33: the fence family at the end of the corpus (push_fence_edge: a line pusher translating 10^-k beside its
// friction cone's left edge) is stable iff below, certified, with no contact mode; and `compare` reads a peer's
// stable_push: "stable" where the contact breaks is unsafe ("falsely stable"), undecided lost, other words refused.
TEST_F(Corpus, TheFenceFamilyIsStableIffBelowAndCompareReadsStablePush) {
  std::string good, bad, unstable_id, stable_id;
  std::size_t fences = 0;
  for (const json::Value& v : lines_) {
    const std::string id = v.find("id")->text;
    if (v.find("family")->text != "push_fence_edge") continue;
    ++fences;
    const bool above = v.find("side")->text == "above";
    const json::Value* push = v.find("push");
    ASSERT_TRUE(push && push->type == json::Type::object) << id;
    EXPECT_EQ(push->find("contact"), nullptr) << id;
    const std::string verdict = push->find("stable")->find("verdict")->text;
    EXPECT_EQ(verdict, above ? "unstable" : "stable") << id;
    ASSERT_NE(v.find("certificates")->find("push"), nullptr) << id;
    EXPECT_NE(v.find("certificates")->find("push")->find("stable"), nullptr) << id;
    if (above && unstable_id.empty()) unstable_id = id, bad += "{\"id\": \"" + id + "\", \"stable_push\": \"stable\"}\n";
    if (!above && stable_id.empty()) stable_id = id, bad += "{\"id\": \"" + id + "\", \"stable_push\": \"undecided\"}\n";
    good += "{\"id\": \"" + id + "\", \"stable_push\": \"" + verdict + "\"}\n";
  }
  ASSERT_EQ(fences, 14u);
  ASSERT_FALSE(unstable_id.empty() || stable_id.empty());
  Cli_result r = run("compare --json '" + dir_ + "' -", good);
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("\"stable_push\": {\"compared\": 14, \"agree\": 14,"), std::string::npos) << r.out;
  r = run("compare --json '" + dir_ + "' -", bad);
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  const json::Value rep = json::parse(r.out, Input_limits{}, "report");
  EXPECT_EQ(rep.find("fields")->find("stable_push")->find("unsafe")->text, "1");
  EXPECT_EQ(rep.find("fields")->find("stable_push")->find("lost")->text, "1");
  for (const json::Value& d : rep.find("disagreements")->items) {
    const std::string id = d.find("id")->text;
    EXPECT_EQ(d.find("kind")->text, id == unstable_id ? "falsely stable" : "an uncertain stable push") << id;
  }
  r = run("compare '" + dir_ + "' -", "{\"id\": \"" + unstable_id + "\", \"stable_push\": \"yes\"}\n");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("stable_push: \"yes\" is not \"stable\""), std::string::npos) << r.err;
  r = run("compare '" + dir_ + "' -", "{\"id\": \"golden.block_corner_mu_0\", \"stable_push\": \"stable\"}\n");
  EXPECT_EQ(r.code, 2);
}

// Issue 32: the polygon parts carry where two and three fingers may go (every pair's exact region, every triple's
// cube or "never", certified), and `compare` reads a peer's sampled placements, decided exactly: a placement claimed
// closed that is open is unsafe (the square's adjacent sides at mu = 1 exactly: the boundary, open), one claimed open
// that closes is lost.
TEST_F(Corpus, PolygonPartsCarryGraspRegionsAndComparePlacements) {
  std::size_t parts = 0;
  for (const json::Value& v : lines_) {
    const std::string id = v.find("id")->text;
    const json::Value* g = v.find("grasp_regions");
    if (v.find("family")->text != "polygon_part") continue;
    ++parts;
    ASSERT_TRUE(g && g->type == json::Type::object) << id;
    ASSERT_NE(v.find("certificates")->find("grasp_regions"), nullptr) << id;
    ASSERT_NE(v.find("certificates")->find("grasp_regions_three"), nullptr) << id;
    const std::size_t n = v.find("scene")->find("body")->find("outline")->items.size();
    EXPECT_EQ(g->find("pairs")->items.size(), n * (n - 1) / 2) << id;
    EXPECT_EQ(g->find("triples")->items.size(), n * (n - 1) * (n - 2) / 6) << id;
    if (id == "polygon_part.square_mu_1") {
      EXPECT_EQ(g->find("pairs")->items[0].find("closed")->items.size(), 0u);  // edges 0, 1: none at mu = 1
    }
    if (id == "polygon_part.square_mu_1_plus_1e-12") {
      EXPECT_EQ(g->find("pairs")->items[0].find("closed")->items.size(), 1u);  // a sliver just above
    }
  }
  ASSERT_EQ(parts, 10u);
  const std::string answers =
      R"({"id": "polygon_part.square_mu_1", "placements": [{"edges": [0, 1], "s": ["1/2", "1/2"], "closed": true}, )"
      R"({"edges": [0, 2], "s": [0.5, 0.5], "closed": true}, {"edges": [0, 2], "s": ["0", "0"], "closed": 0}, )"
      R"({"edges": [0, 2], "s": [0.3, 0.5], "closed": false}, {"edges": [0, 1, 2], "s": [0.5, 0.5, 0.5], "closed": null}]})" "\n"
      R"({"id": "polygon_part.l_part_mu_1", "placements": [{"edges": [1, 2, 3], "s": [0.5, 0.5, 0.5], "closed": false}]})" "\n";
  Cli_result r = run("compare --json '" + dir_ + "' -", answers);
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  const json::Value rep = json::parse(r.out, Input_limits{}, "report");
  const json::Value& f = *rep.find("fields")->find("placements");
  EXPECT_EQ(f.find("compared")->text, "5");
  EXPECT_EQ(f.find("agree")->text, "3");  // (0, 2) at (1/2, 1/2) closes; at (0, 0) — |1 − s − t| = 1 = mu, the boundary — open
  EXPECT_EQ(f.find("unsafe")->text, "1");  // (0, 1) at mu = 1: open
  EXPECT_EQ(f.find("lost")->text, "1");    // (0, 2) at (0.3, 0.5) closes (and the L part's 1, 2, 3 at mu = 1 do not)
  EXPECT_EQ(f.find("no_answer")->text, "1");
  r = run("compare '" + dir_ + "' -", R"({"id": "polygon_part.square", "placements": [{"edges": [0, 4], "s": [0, 0], "closed": true}]})" "\n");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("placements[0].edges: 4 is not an edge of the outline (0 to 3)"), std::string::npos) << r.err;
  r = run("compare '" + dir_ + "' -", R"({"id": "golden.ladder_mu_1_7", "placements": []})" "\n");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("is not a polygon part with fingers' regions"), std::string::npos) << r.err;
}

TEST_F(Corpus, CompareBadInputNamesLineAndField) {
  struct Case {
    std::string name, text, message;
  };
  const std::vector<Case> cases = {
      {"a.jsonl", "{\"id\": \"golden.ladder_mu_1_7\", \"force_closure\": false}\n{\"id\": \"nope\"}\n",
       "a.jsonl:2: id: \"nope\" is not in the corpus"},
      {"b.jsonl", "\n{\"id\": \"golden.ladder_mu_1_7\", \"force_closure\": \"no\"}\n",
       "b.jsonl:2: force_closure: \"no\" is not true, false, 1, 0"},
      {"c.jsonl", "{\"id\": \"golden.ladder_mu_1_7\", \"forceclosure\": true}\n", "c.jsonl:1: \"forceclosure\": unknown field"},
      {"d.jsonl", "{\"id\": \"golden.ladder_mu_1_7\",\n", "d.jsonl:1:"},
      {"e.jsonl", "{\"id\": \"golden.ladder_mu_1_7\"}\n{\"id\": \"golden.ladder_mu_1_7\"}\n", "e.jsonl:2: id: \"golden.ladder_mu_1_7\" is answered twice"},
      {"f.csv", "id,force_closure,grip\n", "f.csv:1: column 3: \"grip\" is not one of"},
      {"g.csv", "id,force_closure\ngolden.ladder_mu_1_7,maybe\n", "g.csv:2: force_closure: \"maybe\" is not true, false (any case), 1, 0 (or 1.0, 0.0) or empty"},
      {"n.jsonl", "{\"id\": \"golden.ladder_mu_1_7\", \"force_closure\": 2}\n", "n.jsonl:1: force_closure: 2 is not true, false, 1, 0"},
      {"o.jsonl", "{\"id\": \"golden.ladder_mu_1_7\", \"force_closure\": 0.5}\n", "o.jsonl:1: force_closure: 0.5 is not true"},
      {"p.csv", "id,force_closure\ngolden.ladder_mu_1_7,-1\n", "p.csv:2: force_closure: \"-1\" is not true"},
      {"q.jsonl", "{\"id\": \"golden.ladder_mu_1_7\", \"motion\": \"sticks\"}\n", "q.jsonl:1: motion: scene \"golden.ladder_mu_1_7\" has no load on a support"},
      {"r.jsonl", "{\"id\": \"golden.limit_surface.barbell\", \"power_range\": []}\n", "r.jsonl:1: power_range: scene \"golden.limit_surface.barbell\" has a known distribution"},
      {"k.csv", "id,force_closure\n\"golden.ladder_mu_1_7,true\n", "k.csv:2: a quoted cell is not closed"},
      {"l.csv", "id,force_closure\n\"golden.ladder_mu_1_7\"x,true\n", "l.csv:2: text after a quoted cell"},
      {"m.csv", "id,force_closure\ngolden.\"ladder,true\n", "m.csv:2: a quote inside an unquoted cell"},
      {"h.csv", "id,force_closure\ngolden.ladder_mu_1_7\n", "h.csv:2: 1 cells, the header has 2"},
      {"i.jsonl", "{\"id\": \"golden.ladder_mu_1_7\", \"equilibrium\": true}\n", "i.jsonl:1: equilibrium: scene \"golden.ladder_mu_1_7\" has no load"},
      {"j.jsonl", "{\"id\": \"golden.limit_surface.barbell\", \"power\": [1, 2]}\n", "j.jsonl:1: power: 2 values, the scene has 5 twists"},
      {"s.jsonl", "{\"id\": \"golden.ladder_mu_1_7\", \"hold\": true}\n", "s.jsonl:1: hold: scene \"golden.ladder_mu_1_7\" has no load (no hold answer)"},
      {"t.jsonl", "{\"id\": \"fixture_pin.1e-2.0\", \"hold\": \"maybe\"}\n", "t.jsonl:1: hold: \"maybe\" is not true, false, 1, 0"},
      {"u.csv", "id,hold\nfixture_pin.1e-2.0,maybe\n", "u.csv:2: hold: \"maybe\" is not true"},
      {"v.csv", "id,force_closure\nfixture_pin.1e-2.0,depends\n", "v.csv:2: force_closure: \"depends\" is not true"},
  };
  for (const Case& c : cases) {
    const fs::path p = scratch() / c.name;
    std::ofstream(p) << c.text;
    const Cli_result r = run("compare '" + dir_ + "' '" + p.string() + "'");
    EXPECT_EQ(r.code, 2) << c.name << ": " << r.out;
    EXPECT_TRUE(r.out.empty()) << c.name;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.name << ": " << r.err;
  }
  EXPECT_EQ(run("compare '" + dir_ + "'").code, 2);
  EXPECT_EQ(run("compare --rtol -1 '" + dir_ + "' x.jsonl").code, 2);
}

TEST(ReferenceCli, RefusesADirectoryThatIsNotACorpusAndWritesNothingOnError) {
  const fs::path d = scratch() / "precious";
  fs::remove_all(d);
  fs::create_directories(d);
  std::ofstream(d / "thesis.tex") << "do not delete";
  const Cli_result r = run("reference --out '" + d.string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("holds no wrenchkit reference corpus"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(d / "thesis.tex"));
  EXPECT_FALSE(fs::exists(d / "reference.jsonl"));
  EXPECT_EQ(run("reference").code, 2);
  EXPECT_EQ(run("reference --out x --sides 5").code, 2);
  EXPECT_EQ(run("reference --out x --cases lots").code, 2);
  const Cli_result h = run("reference --help");
  EXPECT_EQ(h.code, 0);
  EXPECT_NE(h.out.find("--out DIR"), std::string::npos);
}

TEST(ReferenceCli, SmallCorpusReplacesAnEarlierOne) {
  const fs::path d = scratch() / "small";
  fs::remove_all(d);
  Cli_result r = run("reference --out '" + d.string() + "' --cases 1 --random 3 --seed 5 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"command\": \"reference\""), std::string::npos) << r.out;
  r = run("reference --out '" + d.string() + "' --cases 0 --random 1 --seed 5");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string manifest = test::read_text((d / "manifest.json").string());
  EXPECT_NE(manifest.find("\"cases\": 0, \"random\": 1"), std::string::npos) << manifest;
  EXPECT_FALSE(fs::exists(d.string() + ".tmp-wrenchkit"));
}

// ---- reference --scenes: the user's own scenes ------------------------------------------------------

const char* const kOwnScenes =
    R"({"id": "pinch", "family": "pinch", "scene": {"wrenchkit": 1, "contacts": [{"at": [0, 1], "normal": [0, -1], "mu": 0.3}, {"at": [0, -1], "normal": [0, 1], "mu": 0.3}]}})"
    "\n\n"
    R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [1, 0]}], "load": {"wrench": [-2, 0, 0]}, "support": {"mu": 1, "weight": 1, "pressure_center": [0, 0], "points": [{"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}]}})"
    "\n"
    R"({"id": "plate", "scene": {"wrenchkit": 1, "load": {"wrench": ["1/10", 0, 0]}, "support": {"mu": 1, "points": [{"at": [1, 0], "force": 1}, {"at": [-1, 0], "force": 1}]}}, "_note": "ignored"})"
    "\n"
    R"({"id": "edge", "scene": {"wrenchkit": 1, "load": {"wrench": [1, 0, 0]}, "support": {"mu": 1, "weight": 1, "pressure_center": [0, 0], "points": [{"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}]}}})"
    "\n";

TEST(ReferenceScenes, OwnScenesGetTheCorpusFormatAndCompareAgrees) {
  const fs::path d = scratch() / "own";
  fs::remove_all(d);
  fs::create_directories(d);
  std::ofstream(d / "mine.jsonl") << kOwnScenes;
  Cli_result r = run("reference --scenes '" + (d / "mine.jsonl").string() + "' --out '" + (d / "corpus").string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream in(test::read_text((d / "corpus" / "reference.jsonl").string()));
  std::vector<json::Value> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(json::parse(line, Input_limits{}, "own"));
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0].find("id")->text, "pinch");
  EXPECT_EQ(lines[0].find("family")->text, "pinch");
  EXPECT_EQ(lines[1].find("id")->text, "line.3");  // a bare scene: its line number
  EXPECT_EQ(lines[1].find("family")->text, "user");
  EXPECT_TRUE(lines[0].find("force_closure")->boolean);
  // The unknown distribution: power ranges per twist, and the load's motion over every distribution.
  EXPECT_EQ(lines[1].find("limit_surface")->find("distribution")->text, "unknown");
  EXPECT_NE(lines[1].find("limit_surface")->find("twists")->items[0].find("power_range"), nullptr);
  EXPECT_EQ(lines[1].find("motion")->text, "slides");
  EXPECT_EQ(lines[2].find("motion")->text, "sticks");  // |f| = 1/10 < mu·W = 2
  EXPECT_EQ(lines[3].find("motion")->text, "impending");  // |f| = mu·W = 1: a translation, for every distribution
  EXPECT_EQ(lines[3].find("hold")->text, "impending");
  // Per-field distances; nearest doubles; every certificate accepted by the independent checker.
  EXPECT_NE(lines[0].find("boundary")->find("fields")->find("form_closure"), nullptr);
  EXPECT_EQ(json::text_of(*lines[0].find("approx")->find("scene")->find("contacts")->items[0].find("mu")), "0.3");
  for (const json::Value& v : lines)
    for (const auto& [what, cert] : v.find("certificates")->members)
      EXPECT_TRUE(test::checker_accepts(json::text_of(*v.find("scene")), json::text_of(cert))) << what;
  EXPECT_NE(lines[2].find("certificates")->find("motion"), nullptr);
  r = run("compare '" + (d / "corpus").string() + "' '" + (d / "corpus" / "expected.csv").string() + "'");
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  // Motion: "sticks" where the load slides for every distribution is unsafe; the power range over the
  // distributions is compared within the tolerance (here: the corpus' own range, as nearest doubles).
  const json::Value& ranges = *lines[1].find("approx")->find("limit_surface")->find("twists");
  std::string range = "[";
  for (std::size_t i = 0; i < ranges.items.size(); ++i)
    range += (i ? ", " : "") + json::text_of(*ranges.items[i].find("power_range"));
  r = run("compare '" + (d / "corpus").string() + "' -",
          "{\"id\": \"line.3\", \"motion\": \"sticks\", \"power_range\": " + range + "]}\n"
          "{\"id\": \"plate\", \"motion\": \"sticks\"}\n"
          "{\"id\": \"edge\", \"motion\": \"sticks\", \"hold\": false}\n");
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("motion: falsely sticks (unsafe): reference slides, answer sticks"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("power_range              1 compared       1 agree"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("motion                   3 compared       1 agree       1 disagree"), std::string::npos) << r.out;
  // On an impending reference a side is the boundary: neither unsafe nor lost, counted apart.
  EXPECT_NE(r.out.find("(1 on an impending reference answered with a side: the boundary, neither unsafe nor lost)"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hold                     1 compared       0 agree       0 disagree"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no boundary measure for motion"), std::string::npos) << r.out;
  // A directory of scene files: ids from the paths, families from the directories.
  fs::create_directories(d / "dir" / "clamps");
  std::ofstream(d / "dir" / "a.json") << R"({"wrenchkit": 1, "contacts": [{"at": [0, 0], "normal": [1, 0]}]})";
  std::ofstream(d / "dir" / "clamps" / "b.json") << R"({"wrenchkit": 1})";
  std::ofstream(d / "dir" / "notes.txt") << "not a scene";
  r = run("reference --scenes '" + (d / "dir").string() + "' --out '" + (d / "dircorpus").string() + "' --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = test::read_text((d / "dircorpus" / "expected.csv").string());
  EXPECT_NE(csv.find("\na,false,false,,\nclamps.b,false,false,,\n"), std::string::npos) << csv;
  EXPECT_NE(test::read_text((d / "dircorpus" / "reference.jsonl").string()).find("\"family\": \"clamps\""), std::string::npos);
}

// Pushing (docs/pushing.md) in the corpus and compare: docs/pushing's scenes get "push" with the rotation and its
// certificate; a wrong sense is unsafe (also any sense where the truth depends on the distribution), depends where
// the sense is certain is lost.
TEST(ReferenceScenes, PushInTheCorpusAndCompared) {
  const fs::path d = scratch() / "push";
  fs::remove_all(d);
  Cli_result r = run("reference --scenes '" + test::source_dir() + "/docs/pushing' --out '" + (d / "corpus").string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream in(test::read_text((d / "corpus" / "reference.jsonl").string()));
  std::map<std::string, json::Value> lines;
  for (std::string line; std::getline(in, line);) {
    json::Value v = json::parse(line, Input_limits{}, "push");
    const std::string id = v.find("id")->text;
    lines.emplace(id, std::move(v));
  }
  ASSERT_EQ(lines.size(), 6u);
  const auto rotation = [&](const char* id) { return lines.at(id).find("push")->find("rotation")->text; };
  EXPECT_EQ(rotation("legs_depends"), "ccw");
  EXPECT_EQ(lines.at("legs_depends").find("push")->find("contact")->find("mode")->text, "depends");
  EXPECT_EQ(rotation("square_apart"), "ccw");
  EXPECT_EQ(rotation("square_slides"), "ccw");
  EXPECT_EQ(rotation("square_tie"), "none");
  EXPECT_EQ(rotation("two_coefficients"), "depends");
  EXPECT_EQ(rotation("plate"), "ccw");
  for (const auto& [id, v] : lines) {
    const json::Value* cert = v.find("certificates")->find("push");
    ASSERT_NE(cert, nullptr) << id;
    EXPECT_TRUE(test::checker_accepts(json::text_of(*v.find("scene")), json::text_of(*cert))) << id;
  }
  r = run("compare --json '" + (d / "corpus").string() + "' -",
          "{\"id\": \"square_apart\", \"rotation\": \"ccw\"}\n{\"id\": \"plate\", \"rotation\": \"cw\"}\n"
          "{\"id\": \"square_tie\", \"rotation\": \"depends\"}\n{\"id\": \"two_coefficients\", \"rotation\": \"ccw\"}\n");
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  const json::Value rep = json::parse(r.out, Input_limits{}, "report");
  const json::Value& f = *rep.find("fields")->find("rotation");
  EXPECT_EQ(f.find("compared")->text, "4");
  EXPECT_EQ(f.find("agree")->text, "1");
  EXPECT_EQ(f.find("unsafe")->text, "2");  // plate cw (truth ccw); two_coefficients ccw (truth depends)
  EXPECT_EQ(f.find("lost")->text, "1");    // square_tie depends (truth none)
  // the contact mode over forces not given: a certain mode where it depends is unsafe; depends itself agrees
  r = run("compare --json '" + (d / "corpus").string() + "' -",
          "{\"id\": \"legs_depends\", \"contact_mode\": \"sticks\"}\n{\"id\": \"square_apart\", \"contact_mode\": \"depends\"}\n");
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  const json::Value cm = json::parse(r.out, Input_limits{}, "report");
  EXPECT_EQ(cm.find("fields")->find("contact_mode")->find("unsafe")->text, "1");
  EXPECT_EQ(cm.find("fields")->find("contact_mode")->find("lost")->text, "1");
  r = run("compare '" + (d / "corpus").string() + "' -", "{\"id\": \"legs_depends\", \"contact_mode\": \"depends\"}\n");
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  // a simulation's rotation centre against the certified bound (PU-4): the legs' own centre near (−1.3655, 0.8655) is
  // consistent; (5, 5) is no centre any distribution turns the plate about; a centre for the tie that translates is
  // impossible too
  r = run("compare --json '" + (d / "corpus").string() + "' -",
          "{\"id\": \"square_apart\", \"rotation_centre\": [-1.3655, 0.8655]}\n{\"id\": \"plate\", \"rotation_centre\": [5, 5]}\n"
          "{\"id\": \"square_tie\", \"rotation_centre\": [\"0\", \"-1\"]}\n");
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  const json::Value rc = json::parse(r.out, Input_limits{}, "report");
  EXPECT_EQ(rc.find("fields")->find("rotation_centre")->find("compared")->text, "3");
  EXPECT_EQ(rc.find("fields")->find("rotation_centre")->find("agree")->text, "1");
  EXPECT_EQ(rc.find("fields")->find("rotation_centre")->find("unsafe")->text, "2");
  r = run("compare '" + (d / "corpus").string() + "' -", "{\"id\": \"plate\", \"rotation_centre\": 5}\n");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("rotation_centre: 5 is not a point [x, y]"), std::string::npos) << r.err;
  r = run("compare '" + (d / "corpus").string() + "' -", "{\"id\": \"plate\", \"rotation\": \"left\"}\n");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("rotation: \"left\" is not \"ccw\""), std::string::npos) << r.err;
}

TEST(ReferenceScenes, BadScenesNameFileLineAndFieldAndWriteNothing) {
  const fs::path d = scratch() / "own_bad";
  fs::remove_all(d);
  fs::create_directories(d);
  struct Case {
    std::string text, message;
  };
  const std::vector<Case> cases = {
      {"{\"wrenchkit\": 1}\n{\"wrenchkit\": 1, \"contacts\": [{\"at\": [0, 0], \"normal\": [0, 0]}]}\n",
       "s.jsonl:2: contacts[0].normal: zero vector"},
      {"{\"wrenchkit\": 1,\n", "s.jsonl:1:"},
      {"[1]\n", "s.jsonl:1: a scene line must be a JSON object"},
      {"{\"id\": \"x\", \"scene\": {\"wrenchkit\": 1}}\n{\"id\": \"x\", \"scene\": {\"wrenchkit\": 1}}\n",
       "s.jsonl:2: id: \"x\" appears twice"},
      {"{\"id\": \"../x\", \"scene\": {\"wrenchkit\": 1}}\n", "s.jsonl:1: id: \"../x\" is not a corpus id"},
      {"{\"id\": \"x\", \"scene\": {\"wrenchkit\": 1}, \"famly\": \"a\"}\n", "s.jsonl:1: \"famly\": unknown field"},
      {"{\"id\": 3, \"scene\": {\"wrenchkit\": 1}}\n", "s.jsonl:1: id: 3 is not a string"},
      {"\n", "no scenes"},
  };
  for (const Case& c : cases) {
    std::ofstream(d / "s.jsonl") << c.text;
    const Cli_result r = run("reference --scenes '" + (d / "s.jsonl").string() + "' --out '" + (d / "out").string() + "'");
    EXPECT_EQ(r.code, 2) << c.text;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.text << ": " << r.err;
    EXPECT_FALSE(fs::exists(d / "out")) << c.text;
  }
  EXPECT_EQ(run("reference --scenes '" + (d / "missing.jsonl").string() + "' --out '" + (d / "out").string() + "'").code, 2);
}

}  // namespace
}  // namespace wrenchkit
