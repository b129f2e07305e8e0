// End-to-end tests of `wrenchkit limit-surface` and `wrenchkit sliding` (docs/limit-surface.md):
// every option, the JSON fields, the exports (OFF/OBJ/PLY/SVG well-formed, counts matching), and every
// bad-input class (exit 2, a message naming the option or field, nothing on stdout).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/test_support.h"

namespace wrenchkit {
namespace {

namespace fs = std::filesystem;

using test::Cli_result;

fs::path scratch() { return test::scratch_dir("cli_ls_test"); }

Cli_result run(const std::string& args, const std::string& stdin_text = "") {
  return test::run_cli(WRENCHKIT_CLI, "", args, stdin_text, "cli_ls_test");
}

std::string golden(const std::string& name) {
  return "'" + test::source_dir() + "/tests/golden/limit_surface/" + name + ".scene.json'";
}

// The integer after "key": in a JSON text (first occurrence after `from`).
long field(const std::string& json, const std::string& key, std::size_t from = 0) {
  const std::size_t p = json.find("\"" + key + "\": ", from);
  if (p == std::string::npos) return -1;
  return std::stol(json.substr(p + key.size() + 4));
}

bool has(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

TEST(CliLimitSurface, BarbellJsonCountsAndCertificate) {
  const Cli_result r = run("limit-surface --json --sides 8 " + golden("barbell"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "\"sides\": 8, \"lambda_squared\": \"")) << r.out;
  const std::size_t in = r.out.find("\"inner\": "), out = r.out.find("\"outer\": ");
  EXPECT_EQ(field(r.out, "facets", in), 22);  // theory.md §12.4: octagons, 22 facets
  EXPECT_EQ(field(r.out, "rotation_facets", in), 4);
  EXPECT_EQ(field(r.out, "dimension", out), 3);
  EXPECT_TRUE(has(r.out, "\"collinear\": true"));
  EXPECT_TRUE(has(r.out, "the slider applies to the support"));  // the sign convention is stated
  EXPECT_TRUE(r.err.empty());
  const Cli_result h = run("limit-surface --sides 8 " + golden("barbell"));
  EXPECT_EQ(h.code, 0);
  EXPECT_TRUE(has(h.out, "inner: 22 facets")) << h.out;
  EXPECT_TRUE(has(h.out, "certificate: lambda^2 = "));
}

TEST(CliLimitSurface, TwistAndLoadQueries) {
  const Cli_result r = run("limit-surface --json --sides 8 --twist -1,0,1 --load 0,0,1/2 " + golden("barbell"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "\"load_for_twist\": {\"inner\": {\"dimension\": 2")) << r.out;  // a facet
  EXPECT_TRUE(has(r.out, "\"kind\": \"facet\""));
  EXPECT_TRUE(has(r.out, "\"motion\": \"sticks\""));
  const Cli_result s = run("limit-surface --json --sides 8 --load 0,0,2 " + golden("barbell"));
  EXPECT_TRUE(has(s.out, "\"motion\": \"slides\"")) << s.out;
  EXPECT_TRUE(has(s.out, "\"twist_cone\": {\"outer\": {\"generators\": [["));
  // (0, 0, 1) is a point of LS (theory.md §14.2): the polygons cannot tell at any N (--mode exact)…
  const Cli_result u = run("limit-surface --json --mode exact --sides 8 --load 0,0,1 " + golden("barbell"));
  EXPECT_TRUE(has(u.out, "\"motion\": \"undecided\"")) << u.out;
  const Cli_result h = run("limit-surface --mode exact --sides 8 --load 0,0,1 --twist 0,0,1 " + golden("barbell"));
  EXPECT_TRUE(has(h.out, "undecided: refine")) << h.out;
  EXPECT_TRUE(has(h.out, "non-smooth point")) << h.out;
  // … while the default (hybrid) search finds a twist q with h(q) = q·p exactly: the boundary slides.
  const Cli_result hy = run("limit-surface --json --sides 8 --load 0,0,1 " + golden("barbell"));
  EXPECT_TRUE(has(hy.out, "\"motion\": \"slides\", \"motion_decided_by\": \"float\"")) << hy.out;
}

TEST(CliLimitSurface, ToleranceAndListAndDegenerateScenes) {
  const Cli_result r = run("limit-surface --json --tolerance 1/100 " + golden("coincident_collinear"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "\"tolerance\": \"1/100\"")) << r.out;
  EXPECT_GT(field(r.out, "sides"), 4);
  EXPECT_EQ(field(r.out, "points"), 3);  // (0,0) given twice is merged; (5,1) has mu 0 and is dropped
  const Cli_result one = run("limit-surface --json --sides 6 --list " + golden("single_point"));
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_EQ(field(one.out, "dimension"), 2);
  EXPECT_TRUE(has(one.out, "\"vertex_list\": [["));
  const Cli_result z = run("limit-surface --json --load 1,0,0 " + golden("zero_friction"));
  ASSERT_EQ(z.code, 0) << z.err;
  EXPECT_EQ(field(z.out, "dimension"), 0);
  EXPECT_TRUE(has(z.out, "\"motion\": \"slides\""));
}

// The mesh files are written by CGAL's writers (exact/cgal/mesh_io.h; tests/cgal_face_test.cpp reads every format back
// with CGAL's reader): here their shape as a viewer sees it and the counts against the JSON answer.
TEST(CliLimitSurface, ExportsAreWellFormedAndMatchTheCounts) {
  const fs::path d = scratch();
  const std::string off = (d / "ls.off").string(), obj = (d / "ls.obj").string(), ply = (d / "ls.ply").string(),
                    svg = (d / "ls.svg").string();
  const Cli_result r = run("limit-surface --json --sides 6 --off '" + off + "' --obj '" + obj + "' --ply '" + ply +
                           "' --svg '" + svg + "' " + golden("barbell"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(has(r.out, "mesh_coordinates"));  // only with --exact-coordinates
  const std::size_t in = r.out.find("\"inner\": "), out = r.out.find("\"outer\": ");
  const long fi = field(r.out, "facets", in), vi = field(r.out, "vertices", in);
  const long fo = field(r.out, "facets", out), vo = field(r.out, "vertices", out);
  // OFF (COFF: CGAL's keyword when faces carry colours): counts, then vertices, then faces "k i… r g b".
  std::istringstream o(test::read_text(off));
  std::string line;
  std::getline(o, line);
  EXPECT_EQ(line, "COFF");
  long nv = 0, nf = 0;
  o >> nv >> nf >> line;
  EXPECT_EQ(nv, vi + vo);
  EXPECT_EQ(nf, fi + fo);
  double x = 0;
  for (long i = 0; i < 3 * nv; ++i) ASSERT_TRUE(o >> x) << "vertex coordinate " << i;
  long flines = 0;
  while (std::getline(o, line)) {
    if (line.empty()) continue;
    std::istringstream f(line);
    long k = 0, idx = 0, got = 0;
    f >> k;
    while (got < k && f >> idx) {
      EXPECT_GE(idx, 0);
      EXPECT_LT(idx, nv);
      ++got;
    }
    EXPECT_EQ(got, k);
    int rgb[3] = {0, 0, 0};
    EXPECT_TRUE(f >> rgb[0] >> rgb[1] >> rgb[2]) << line;
    EXPECT_EQ(rgb[2], flines < fi ? 230 : 51) << "inner faces blue first, then outer red";
    ++flines;
  }
  EXPECT_EQ(flines, nf);
  // OBJ: one object, the inner polytope's vertices and faces first.
  const std::string objt = test::read_text(obj);
  long ov = 0, of = 0;
  std::istringstream ob(objt);
  while (std::getline(ob, line)) {
    ov += line.rfind("v ", 0) == 0;
    of += line.rfind("f ", 0) == 0;
  }
  EXPECT_EQ(ov, vi + vo);
  EXPECT_EQ(of, fi + fo);
  // PLY: binary, with the counts and the face property `polytope` in its header.
  const std::string plyt = test::read_text(ply);
  EXPECT_EQ(plyt.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
  EXPECT_TRUE(has(plyt, "element vertex " + std::to_string(vi + vo) + "\n")) << plyt.substr(0, 600);
  EXPECT_TRUE(has(plyt, "element face " + std::to_string(fi + fo) + "\n"));
  EXPECT_TRUE(has(plyt, "property uchar polytope\n") && has(plyt, "property double x\n"));
  const std::string s = test::read_text(svg);
  EXPECT_EQ(s.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_EQ(s.substr(s.size() - 7), "</svg>\n");
  EXPECT_TRUE(has(s, "slice f_y = 0") && has(s, "projection onto (f_x, f_y)") && has(s, "<polygon points="));
  EXPECT_FALSE(fs::exists(off + ".tmp-wrenchkit"));
}

// --exact-coordinates: OFF holds every vertex exactly (homogeneous integers, 4OFF), OBJ and PLY doubles, and the
// answer says which (JSON "mesh_coordinates", a text line per file); without a mesh file it is a usage error.
TEST(CliLimitSurface, ExactCoordinatesAreSaid) {
  const fs::path d = scratch();
  const std::string off = (d / "exact.off").string(), ply = (d / "exact.ply").string();
  const Cli_result j = run("limit-surface --json --sides 6 --exact-coordinates --off '" + off + "' --ply '" + ply + "' " +
                           golden("barbell"));
  ASSERT_EQ(j.code, 0) << j.err;
  EXPECT_TRUE(has(j.out, "\"mesh_coordinates\": {\"off\": \"exact: homogeneous integers X Y Z W (4OFF)\", "
                         "\"ply\": \"nearest doubles (PLY has no exact numbers)\"}")) << j.out;
  const std::string text = test::read_text(off);
  EXPECT_EQ(text.rfind("4OFF\n", 0), 0u);
  // The barbell's inner vertex (3807/8770, 6561/8770, −3807/8770) (N = 6) is in it exactly.
  EXPECT_TRUE(has(text, "\n3807 6561 -3807 8770\n")) << text.substr(0, 400);
  const Cli_result t = run("limit-surface --sides 6 --exact-coordinates --obj '" + (d / "e.obj").string() + "' " +
                           golden("barbell"));
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_TRUE(has(t.out, "OBJ " + (d / "e.obj").string() + ": coordinates nearest doubles (OBJ has no exact numbers)\n"))
      << t.out;
  for (const char* bad : {"limit-surface --exact-coordinates ", "limit-surface --mode float --ply x.ply "}) {
    const Cli_result r = run(std::string(bad) + golden("barbell"));
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_TRUE(has(r.err, "usage error")) << r.err;
  }
}

TEST(CliSliding, CentreOfFrictionAndLoads) {
  const Cli_result r = run("sliding --json --twist 3,4,0 " + golden("barbell"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "\"center_of_friction\": [\"0\", \"0\"]")) << r.out;
  EXPECT_TRUE(has(r.out, "\"load\": [\"3/5\", \"4/5\", \"0\"]"));
  const Cli_result f = run("sliding --json --sides 16 --twist -1,0,1 " + golden("barbell"));
  ASSERT_EQ(f.code, 0) << f.err;
  EXPECT_TRUE(has(f.out, "\"kind\": \"facet\"")) << f.out;
  EXPECT_TRUE(has(f.out, "\"facet_disc\": {\"at\": [\"0\", \"-1\"], \"radius\": \"1/2\"}"));
  EXPECT_TRUE(has(f.out, "\"load_box\": {\"lower\": [\"-1/2\", \"0\", \"1/2\"], \"upper\": [\"-1/2\", \"0\", \"1/2\"]"));
  const Cli_result c = run("sliding " + golden("ten_points"));
  EXPECT_EQ(c.code, 0);
  EXPECT_TRUE(has(c.out, "centre of friction: ("));
  const Cli_result h = run("sliding --twist 1,1,0 " + golden("single_point"));
  EXPECT_TRUE(has(h.out, "(mu*f0/|v|) * (1, 1, ")) << h.out;
}

TEST(CliLimitSurface, HelpTexts) {
  const Cli_result a = run("limit-surface --help");
  EXPECT_EQ(a.code, 0);
  EXPECT_TRUE(has(a.out, "--tolerance EPS") && has(a.out, "theory.md §1.5"));
  const Cli_result b = run("sliding --help");
  EXPECT_EQ(b.code, 0);
  EXPECT_TRUE(has(b.out, "--twist vx,vy,w"));
  const Cli_result c = run("--help");
  EXPECT_TRUE(has(c.out, "limit-surface") && has(c.out, "sliding"));
}

TEST(CliLimitSurface, BadInputExitsTwoWithAClearMessageAndNoOutput) {
  const std::string b = golden("barbell");
  const struct {
    std::string args, message;
  } cases[] = {
      {"limit-surface --sides 3 " + b, "--sides: 3"},
      {"limit-surface --sides 7 " + b, "--sides: 7"},
      {"limit-surface --sides 5000 " + b, "--sides: 5000"},
      {"limit-surface --sides abc " + b, "--sides: \"abc\""},
      {"limit-surface --sides " , "--sides needs a value"},
      {"limit-surface --twist 1,2 " + b, "--twist: \"1,2\""},
      {"limit-surface --twist a,0,1 " + b, "--twist: \"a\""},
      {"limit-surface --twist 0,0,0 " + b, "zero twist"},
      {"limit-surface --load 1,2,3,4 " + b, "--load: \"1,2,3,4\""},
      {"limit-surface --tolerance 0 " + b, "--tolerance: \"0\""},
      {"limit-surface --tolerance -1 " + b, "--tolerance: \"-1\""},
      {"limit-surface --tolerance 1e-30 " + b, "--tolerance: 1e-30 needs more than 4096"},
      {"limit-surface --sides 8 --tolerance 0.1 " + b, "exclude each other"},
      {"limit-surface --bogus " + b, "unknown option --bogus"},
      {"limit-surface " + golden("no_support"), "support"},
      {"limit-surface --sides 4096 " + golden("ten_points"), "candidate normals"},
      {"limit-surface", "exactly one SCENE.json"},
      {"sliding --twist 0,0,0 " + b, "zero twist"},
      {"sliding --twist 1,x,0 " + b, "--twist: \"x\""},
      {"sliding --sides 9 " + b, "--sides: 9"},
      {"sliding " + golden("no_support"), "support"},
      {"limit-surface --off /nonexistent-dir/x.off " + b, "/nonexistent-dir/x.off"},
      {"limit-surface --ply /nonexistent-dir/x.ply " + b, "/nonexistent-dir/x.ply"},
  };
  for (const auto& c : cases) {
    const Cli_result r = run(c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << c.args << "\n" << r.out;
    EXPECT_TRUE(has(r.err, c.message)) << c.args << "\n" << r.err;
  }
  // Bad scene text is reported with its JSON path.
  const Cli_result j = run("limit-surface -",
                           "{\"wrenchkit\": 1, \"support\": {\"mu\": 1, \"points\": [{\"at\": [0,0], \"force\": \"abc\"}]}}");
  EXPECT_EQ(j.code, 2);
  EXPECT_TRUE(has(j.err, "support.points[0].force")) << j.err;
  EXPECT_TRUE(j.out.empty());
}

}  // namespace
}  // namespace wrenchkit

namespace wrenchkit {
namespace {

// Modes: hybrid's motion equals every decided exact motion and decides where N sides cannot; float
// answers without polytopes or exits 3 on a load exactly on the limit surface; the true power lies in
// the exact bracket.
TEST(CliLimitSurfaceModes, MotionByModeAndTheTrueSurface) {
  // Barbell: (1, 0, 0) is a (non-smooth) point of LS; ±1 % of it.
  const Cli_result ex = run("limit-surface --json --mode exact --sides 8 --load 1.01,0,0 " + golden("barbell"));
  const Cli_result hy = run("limit-surface --json --sides 8 --load 1.01,0,0 " + golden("barbell"));
  ASSERT_EQ(ex.code, 0) << ex.err;
  ASSERT_EQ(hy.code, 0) << hy.err;
  EXPECT_TRUE(has(ex.out, "\"motion\": \"undecided\"")) << ex.out;  // N = 8 cannot tell 1 % outside
  EXPECT_TRUE(has(hy.out, "\"motion\": \"slides\", \"motion_decided_by\": \"float\"")) << hy.out;
  EXPECT_TRUE(has(hy.out, "\"witness_twist\"")) << hy.out;
  const Cli_result in = run("limit-surface --json --sides 8 --load 0.99,0,0 " + golden("barbell"));
  EXPECT_TRUE(has(in.out, "\"motion\": \"sticks\", \"motion_decided_by\": \"float\"")) << in.out;
  const Cli_result far = run("limit-surface --json --mode exact --sides 8 --load 0,3,1 " + golden("barbell"));
  const Cli_result far_h = run("limit-surface --json --sides 8 --load 0,3,1 " + golden("barbell"));
  EXPECT_TRUE(has(far.out, "\"motion\": \"slides\", \"motion_decided_by\": \"polygons\"")) << far.out;
  EXPECT_TRUE(has(far_h.out, "\"motion\": \"slides\"")) << far_h.out;
  // Float: no polytopes; a load on LS cannot be decided (exit 3, nothing on stdout).
  const Cli_result fl = run("limit-surface --json --mode float --sides 8 --load 0.99,0,0 --twist 1,0,2 " + golden("barbell"));
  ASSERT_EQ(fl.code, 0) << fl.err;
  EXPECT_FALSE(has(fl.out, "\"facets\"")) << fl.out;
  EXPECT_TRUE(has(fl.out, "\"motion\": \"sticks\"")) << fl.out;
  EXPECT_TRUE(has(fl.out, "\"true_power\": {\"value\": 2, \"bound\": 0}")) << fl.out;  // ½|(3, 0)| + ½|(−1, 0)|
  // (1, 0, 0) is on LS and the search meets the exact witness q = (1, 0, 0): slides (the boundary is not the
  // interior). 10^-18 inside the load of the twist (1, 0.3, 0.7) is beyond the doubles' resolution: exit 3.
  EXPECT_TRUE(has(run("limit-surface --mode float --load 1,0,0 " + golden("barbell")).out, "slides"));
  const Cli_result on = run(
      "limit-surface --mode float --load 0.84594517000224216553149590029074925480005609593367,"
      "0.44044605754779759779121475101766813932871231275802,0.13883838881569464183775831937244773991606452035004 " +
      golden("barbell"));
  EXPECT_EQ(on.code, 3) << on.out;
  EXPECT_TRUE(on.out.empty());
  EXPECT_TRUE(has(on.err, "could not tell")) << on.err;
  EXPECT_EQ(run("limit-surface --mode float --list " + golden("barbell")).code, 2);
  // Exact mode uses no float: no true_power field.
  const Cli_result tw = run("limit-surface --json --mode exact --twist 1,1,2 " + golden("ten_points"));
  EXPECT_FALSE(has(tw.out, "true_power")) << tw.out;
}

TEST(CliSlidingModes, TruePowerInsideTheExactBracket) {
  for (const char* twist : {"1,1,2", "0.3,-2,0.7", "1,0,0"}) {
    const Cli_result h = run(std::string("sliding --json --twist ") + twist + " " + golden("ten_points"));
    ASSERT_EQ(h.code, 0) << h.err;
    const std::size_t p = h.out.find("\"true_power\": {\"value\": ");
    ASSERT_NE(p, std::string::npos) << h.out;
    const double v = std::strtod(h.out.c_str() + p + 24, nullptr);
    EXPECT_GT(v, 0) << twist;
    const Cli_result f = run(std::string("sliding --json --mode float --twist ") + twist + " " + golden("ten_points"));
    ASSERT_EQ(f.code, 0) << f.err;
    EXPECT_TRUE(has(f.out, "\"mode\": \"float\"")) << f.out;
    EXPECT_FALSE(has(f.out, "\"load_box\"")) << f.out;  // no exact brackets in float mode
    EXPECT_TRUE(has(f.out, std::string("\"true_power\": {\"value\": ") + h.out.substr(p + 24, 10))) << f.out;
  }
}

}  // namespace
}  // namespace wrenchkit

namespace wrenchkit {
namespace {

// analyze: --tolerance picks the fewest sides meeting it; a force load on a support gets its motion;
// a gravity load's motion on a horizontal support is listed as skipped, not computed.
TEST(CliAnalyzeSupport, ToleranceAndTheLoadsMotion) {
  const auto write = [](const std::string& name, const std::string& text) {
    const fs::path p = scratch() / name;
    std::ofstream(p) << text;
    return "'" + p.string() + "'";
  };
  const std::string pushed = write("pushed.json", R"({"wrenchkit": 1, "load": {"force": ["0.9", 0], "at": [0, "-1/2"]},
    "support": {"mu": "1/2", "points": [{"at": [0, -1], "force": 1}, {"at": [0, 1], "force": 1}]}})");
  const Cli_result a = run("analyze --json --tolerance 0.01 " + pushed);
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_TRUE(has(a.out, "\"sides\": 24")) << a.out;  // the smallest N with 1/λ − 1 ≤ 1/100 (LS-1)
  EXPECT_TRUE(has(a.out, "\"load_motion\": {\"load\": [\"9/10\", \"0\", \"9/20\"], \"motion\": \"slides\"")) << a.out;
  const Cli_result light = run("analyze --json " + write("light.json", R"({"wrenchkit": 1, "load": {"force": ["0.1", 0], "at": [0, 0]},
    "support": {"mu": "1/2", "points": [{"at": [0, -1], "force": 1}, {"at": [0, 1], "force": 1}]}})"));
  EXPECT_TRUE(has(light.out, "\"motion\": \"sticks\"")) << light.out;
  const Cli_result heavy = run("analyze --json " + write("gravity.json", R"({"wrenchkit": 1, "body": {"com": [0, 0]},
    "load": {"gravity": 1}, "support": {"mu": "1/2", "points": [{"at": [0, -1], "force": 1}]}})"));
  EXPECT_TRUE(has(heavy.out, "{\"what\": \"load_motion\"")) << heavy.out;
  EXPECT_FALSE(has(heavy.out, "\"load_motion\": {")) << heavy.out;
  EXPECT_EQ(run("analyze --tolerance 0 " + pushed).code, 2);
  EXPECT_EQ(run("analyze --tolerance abc " + pushed).code, 2);
  const Cli_result none = run("analyze --json --tolerance 0.1 '" + test::source_dir() + "/tests/golden/single_force.scene.json'");
  EXPECT_TRUE(has(none.out, "the scene has no support")) << none.out;
}

}  // namespace
// Unknown forces (docs/theory-sliding.md §1–§2): sliding answers the power over every admissible distribution
// (the four-legged table: rotation about a leg ranges over [√2, 2]); float mode has no LP over F (exit 3);
// limit-surface --load sticks / slides / depends; an empty F is bad input with the reason.
TEST(CliSliding, UnknownDistributionsOfTheTable) {
  const std::string table = R"({"wrenchkit": 1, "name": "table", "support": {"mu": 1, "weight": 1,
      "pressure_center": [0, 0], "points": [{"at": [1, 1]}, {"at": [-1, 1]}, {"at": [-1, -1]}, {"at": [1, -1]}]}})";
  const Cli_result r = run("sliding --json --twist 1,-1,1 -", table);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "\"distribution\": \"unknown\", \"unknown_points\": [0, 1, 2, 3], \"weight\": \"1\"")) << r.out;
  EXPECT_TRUE(has(r.out, "\"extreme_distributions\": [[\"1/2\", \"0\", \"1/2\", \"0\"], [\"0\", \"1/2\", \"0\", \"1/2\"]]"))
      << r.out;
  EXPECT_TRUE(has(r.out, "\"min_distribution\": [\"1/2\", \"0\", \"1/2\", \"0\"], \"max_distribution\": [\"0\", "
                         "\"1/2\", \"0\", \"1/2\"]"))
      << r.out;
  const Cli_result b = run("batch sliding --twist 1,-1,1", table.substr(0, 0) + R"({"wrenchkit": 1, "support": {"mu": 1, "weight": 1, "pressure_center": [0, 0], "points": [{"at": [1, 1]}, {"at": [-1, -1]}]}})" "\n");
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_TRUE(has(b.out, "{\"line\": 1, \"command\": \"sliding\"")) << b.out;
  const Cli_result f = run("sliding --mode float --twist 0,0,1 -", table);
  EXPECT_EQ(f.code, 3);
  EXPECT_TRUE(has(f.err, "no LP over the admissible distributions")) << f.err;
  EXPECT_TRUE(f.out.empty());
  // limit-surface --load: sticks / slides / depends over every admissible distribution (the table's three cases).
  const Cli_result d = run("limit-surface --json --load 0.5,0.5,0.9 -", table);
  ASSERT_EQ(d.code, 0) << d.err;
  EXPECT_TRUE(has(d.out, "\"motion\": \"depends\", \"motion_decided_by\": \"vertices\", \"per_extreme_distribution\": "
                         "[\"sticks\", \"slides\"], \"witnesses\": {\"sticks\": {\"distribution\": [\"1/2\", \"0\", "
                         "\"1/2\", \"0\"]}, \"slides\": {\"distribution\": [\"0\", \"1/2\", \"0\", \"1/2\"]}}"))
      << d.out;
  EXPECT_TRUE(has(run("limit-surface --json --load 0.5,0,0 -", table).out, "\"motion\": \"sticks\""));
  const Cli_result sl = run("limit-surface --json --load 0,0,1.5 -", table);
  EXPECT_TRUE(has(sl.out, "\"motion\": \"slides\", \"motion_decided_by\": \"twist\"")) << sl.out;
  EXPECT_TRUE(has(sl.out, "\"separating_twist\": [")) << sl.out;
  const Cli_result l = run("limit-surface --list --load 0.5,0.5,0.9 -", table);
  EXPECT_EQ(l.code, 2);
  EXPECT_TRUE(has(l.err, "no one limit surface to list or draw")) << l.err;
  EXPECT_TRUE(l.out.empty());
  std::string tipped = table;
  tipped.replace(tipped.find("[0, 0]"), 6, "[2, 0]");
  const Cli_result e = run("sliding --twist 0,0,1 -", tipped);
  EXPECT_EQ(e.code, 2);
  EXPECT_TRUE(has(e.err, "outside the convex hull of the points whose force is not given")) << e.err;
}

// Gravity with a support: a centre of mass away from the support's centre of pressure is reported (text and
// JSON), not refused; at the centre, nothing is said.
TEST(CliAnalyze, GravityAwayFromTheCentreOfPressureIsReported) {
  const std::string off = R"({"wrenchkit": 1, "body": {"com": [1, 0]}, "load": {"gravity": 1},
      "support": {"mu": 1, "points": [{"at": [0, 1], "force": "1/2"}, {"at": [0, -1], "force": "1/2"}]}})";
  const Cli_result t = run("analyze -", off);
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_TRUE(has(t.out, "warning: the weight acts at body.com (1, 0) but the support's centre of pressure is (0, 0)"))
      << t.out;
  const Cli_result j = run("analyze --json -", off);
  EXPECT_TRUE(has(j.out, "\"warnings\": [{\"what\": \"gravity_off_pressure_center\", \"com\": [\"1\", \"0\"], "
                         "\"pressure_center\": [\"0\", \"0\"]}]"))
      << j.out;
  std::string on = off;
  on.replace(on.find("[1, 0]"), 6, "[0, 0]");
  const Cli_result k = run("analyze --json -", on);
  EXPECT_FALSE(has(k.out, "warnings")) << k.out;
}

}  // namespace wrenchkit
