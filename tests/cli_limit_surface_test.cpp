// End-to-end tests of `wrenchkit limit-surface` and `wrenchkit sliding` (docs/limit-surface.md):
// every option, the JSON fields, the exports (OFF/OBJ/PLY/SVG well-formed, counts matching), and every
// bad-input class (exit 2, a message naming the option or field, nothing on stdout).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "exact/numbers/rational.h"
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
  // (0, 0, 1) is a point of LS (theory.md §14.2): the polygons cannot tell at any N, but a twist with exact speeds
  // meets its power, q·p = h(q), beside forces on the discs' circles: impending, certified, in every mode.
  const Cli_result u = run("limit-surface --json --mode exact --sides 8 --load 0,0,1 " + golden("barbell"));
  EXPECT_EQ(u.code, 0) << u.err;
  EXPECT_TRUE(has(u.out, "\"motion\": \"impending\", \"motion_decided_by\": \"certificate\"")) << u.out;
  EXPECT_TRUE(has(u.out, "\"impending_twist\": [")) << u.out;
  const Cli_result h = run("limit-surface --mode exact --sides 8 --load 0,0,1 --twist 0,0,1 " + golden("barbell"));
  EXPECT_TRUE(has(h.out, "impending  (")) << h.out;
  EXPECT_TRUE(has(h.out, "on the limit surface: friction can just hold it, and it may slip with the twist")) << h.out;
  EXPECT_TRUE(has(h.out, "non-smooth point")) << h.out;
  const Cli_result hy = run("limit-surface --json --sides 8 --load 0,0,1 " + golden("barbell"));
  EXPECT_TRUE(has(hy.out, "\"motion\": \"impending\"")) << hy.out;
  EXPECT_TRUE(has(hy.out, "\"certificate\": {\"wrenchkit_certificate\": 3, \"property\": \"motion\", \"load\": [\"0\", "
                          "\"0\", \"1\"], \"motion\": \"impending\"")) << hy.out;
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
  // N = 8 cannot tell 1 % outside; the candidate twists can (a rotation about a support point, exact speeds).
  EXPECT_TRUE(has(ex.out, "\"motion\": \"slides\", \"motion_decided_by\": \"certificate\"")) << ex.out;
  EXPECT_TRUE(has(ex.out, "\"twist\": [\"1\", \"0\", \"-1\"]")) << ex.out;  // small integers
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
  // (1, 0, 0) is on LS and the search meets the exact witness q = (1, 0, 0): impending (the boundary is neither the
  // interior nor outside). 10^-18 inside the load of the twist (1, 0.3, 0.7) is beyond the doubles' resolution: exit 3.
  EXPECT_TRUE(has(run("limit-surface --mode float --load 1,0,0 " + golden("barbell")).out, "impending"));
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

// Support regions [RG-1] [RG-2] (docs/regions.md): the command line end to end.
const std::string kSquareRegion =
    R"({"wrenchkit": 1, "name": "uniform square", "support": {"mu": 1, "regions": [{"outline": [[-1,-1],[1,-1],[1,1],[-1,1]], "pressure": "uniform", "force": 1}]}})";

TEST(CliRegions, SlidingBracketsTheSquaresPowerToTheTolerance) {
  // theory-sliding.md §6: h(0, 0, 1) = (√2 + asinh 1)/3 ≈ 0.7651957165, bracketed to 1e-6 relative, exact centre.
  const Cli_result r = run("sliding --json --twist 0,0,1 -", kSquareRegion);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "\"center_of_friction\": [\"0\", \"0\"]")) << r.out;
  EXPECT_TRUE(has(r.out, "\"tolerance\": \"1/1000000\", \"tolerance_met\": true")) << r.out;
  const auto lower = r.out.find("\"lower\": \""), upper = r.out.find("\"upper\": \"");
  ASSERT_NE(lower, std::string::npos);
  const auto value = [&](std::size_t at) {
    const std::size_t b = r.out.find('"', at + 9) + 1;
    Rational q(r.out.substr(b, r.out.find('"', b) - b));
    q.canonicalize();
    return q.get_d();
  };
  const double truth = (std::sqrt(2.0) + std::asinh(1.0)) / 3;
  EXPECT_LE(value(lower), truth * (1 + 1e-15));  // the double truth is itself within an ulp
  EXPECT_GE(value(upper), truth * (1 - 1e-15));
  EXPECT_LE(value(upper) - value(lower), 1e-6 * truth);
  const Cli_result t = run("sliding --twist 0,0,1 -", kSquareRegion);
  EXPECT_TRUE(has(t.out, "power h in [0.7651957165, 0.7651957165]")) << t.out;
  EXPECT_EQ(run("sliding --mode exact --json --twist 0,0,1 -", kSquareRegion).code, 0);
  // --tolerance: a coarser bracket is allowed, and is still a bracket.
  const Cli_result c = run("sliding --json --twist 0,0,1 --tolerance 1/10 -", kSquareRegion);
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_TRUE(has(c.out, "\"tolerance\": \"1/10\"")) << c.out;
}

TEST(CliRegions, LoadsWithCertificatesAndRefusals) {
  const fs::path d = scratch();
  const std::string scene = (d / "square.json").string(), cert = (d / "square.cert.json").string();
  std::ofstream(scene) << kSquareRegion;
  const Cli_result s = run("limit-surface --json --load 0,0,1/2 --certificate '" + cert + "' '" + scene + "'");
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_TRUE(has(s.out, "\"motion\": \"sticks\"")) << s.out;
  EXPECT_TRUE(has(s.out, "\"certificate_checked\": true"));
  EXPECT_TRUE(has(s.out, "\"polytopes\": false, \"strictly_convex\": true"));
  EXPECT_EQ(run("check '" + scene + "' '" + cert + "'").code, 0);
  const Cli_result l = run("limit-surface --load 0,0,4/5 -", kSquareRegion);
  ASSERT_EQ(l.code, 0) << l.err;
  EXPECT_TRUE(has(l.out, "slides (the twist")) << l.out;
  // Float has no twin of regions: undecided (exit 3), nothing on stdout.
  const Cli_result f = run("limit-surface --mode float --load 0,0,1/2 -", kSquareRegion);
  EXPECT_EQ(f.code, 3) << f.out;
  EXPECT_TRUE(f.out.empty());
  // No exact polytope: --sides, --list are bad input naming the reason; --svg draws the support.
  for (const std::string opt : {"--sides 8", "--list"}) {
    const Cli_result b = run("limit-surface " + opt + " -", kSquareRegion);
    EXPECT_EQ(b.code, 2) << opt;
    EXPECT_TRUE(has(b.err, "strictly convex")) << b.err;
    EXPECT_TRUE(b.out.empty());
  }
  const std::string svg = (d / "square.svg").string();
  ASSERT_EQ(run("limit-surface --svg '" + svg + "' -", kSquareRegion).code, 0);
  EXPECT_TRUE(has(test::read_text(svg), "centre of friction"));
  ASSERT_EQ(run("render --what limit-surface -o '" + svg + "' -", kSquareRegion).code, 0);
  EXPECT_TRUE(has(test::read_text(svg), "</svg>"));
  // A bad region: exit 2 naming it.
  const Cli_result b = run("sliding -", R"({"wrenchkit": 1, "support": {"mu": 1, "regions": [{"outline": [[0,0],[1,0],[1,1],[0,1]], "pressure": {"linear": [-1, 0, 0]}}]}})");
  EXPECT_EQ(b.code, 2);
  EXPECT_TRUE(has(b.err, "support.regions[0].pressure: p = -1 < 0 at outline[0] (0, 0)")) << b.err;
  // analyze: the summary and the load's motion with its checked certificate.
  const Cli_result a = run("analyze -", R"({"wrenchkit": 1, "support": {"mu": 1, "regions": [{"outline": [[-1,-1],[1,-1],[1,1],[-1,1]], "pressure": "uniform", "force": 1}]}, "load": {"wrench": [0, 0, 0.9]}})");
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_TRUE(has(a.out, "the load on the support: slides")) << a.out;
  // batch: a line per scene, the same bytes as the single command's --json.
  const Cli_result one = run("sliding --json --twist 1,2,3 -", kSquareRegion);
  const Cli_result many = run("batch sliding --twist 1,2,3", kSquareRegion + "\n" + kSquareRegion + "\n");
  ASSERT_EQ(many.code, 0) << many.err;
  EXPECT_TRUE(has(many.out, "{\"line\": 2, " + one.out.substr(1, one.out.size() - 2))) << many.out;
}

// [RG-3] Regions together with points whose force is not given (the mat and legs of proofs/examples/mat_legs.*).
TEST(CliRegions, RegionsWithForcesNotGivenEndToEnd) {
  const std::string mat = R"({"wrenchkit": 1, "name": "mat and legs", "support": {"mu": "1/2", "weight": 5, "pressure_center": [0, 0], "points": [{"at": [-2, 0]}, {"at": [0, 0]}, {"at": [2, 0]}], "regions": [{"outline": [["-1/2", "-1/2"], ["1/2", "-1/2"], ["1/2", "1/2"], ["-1/2", "1/2"]], "pressure": "uniform", "force": 1}]}})";
  const fs::path d = scratch();
  const std::string scene = (d / "mat.json").string(), cert = (d / "mat.cert.json").string();
  std::ofstream(scene) << mat;
  struct Case {
    const char* load;
    const char* motion;
  };
  for (const Case& c : {Case{"2,0,0", "sticks"}, Case{"3,0,0", "slides"}, Case{"0,0,1", "depends"}}) {
    const Cli_result r = run(std::string("limit-surface --json --load ") + c.load + " --certificate '" + cert + "' '" +
                             scene + "'");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(has(r.out, std::string("\"motion\": \"") + c.motion + "\"")) << r.out;
    EXPECT_TRUE(has(r.out, "\"distribution\": \"unknown\"")) << r.out;
    EXPECT_TRUE(has(r.out, "\"extreme_distributions\": [[\"0\", \"4\", \"0\"], [\"2\", \"0\", \"2\"]]")) << r.out;
    EXPECT_TRUE(has(r.out, "\"support\": {\"points\": 3, \"regions\": [{\"area\": \"1\", \"force\": \"1\"")) << r.out;
    EXPECT_TRUE(has(r.out, "\"certificate_checked\": true")) << r.out;
    EXPECT_TRUE(has(test::read_text(cert), "\"wrenchkit_certificate\": 3, \"property\": \"motion\""));
    EXPECT_EQ(run("check '" + scene + "' '" + cert + "'").code, 0) << c.load;
  }
  const Cli_result t = run("limit-surface --load 0,0,1 -", mat);
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_TRUE(has(t.out, "depends on the distribution: it sticks with f = (2, 0, 2) and slides with f = (0, 4, 0)")) << t.out;
  EXPECT_TRUE(has(t.out, "1 region(s) with a known pressure (given in F)")) << t.out;
  // The power over F: the points' range [0, 4] plus the mat's (√2 + asinh 1)/12 ≈ 0.1913, with its bracket.
  const Cli_result s = run("sliding --json --twist 0,0,1 -", mat);
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_TRUE(has(s.out, "\"min_distribution\": [\"0\", \"4\", \"0\"], \"max_distribution\": [\"2\", \"0\", \"2\"], \"regions\": {\"lower\": ")) << s.out;
  const Cli_result st = run("sliding --twist 0,0,1 -", mat);
  EXPECT_TRUE(has(st.out, "of which the regions' power (every distribution alike) lies in [0.1912989291, 0.1912989291]")) << st.out;
  // No one limit surface to draw or list; float has no twin of regions.
  for (const std::string opt : {"--svg x.svg --load 1,0,0", "--list"}) {
    const Cli_result b = run("limit-surface " + opt + " -", mat);
    EXPECT_EQ(b.code, 2) << opt << b.out;
    EXPECT_TRUE(b.out.empty());
  }
  EXPECT_EQ(run("limit-surface --mode float --load 1,0,0 -", mat).code, 3);
  // batch: the same bytes as the single command's --json.
  const Cli_result one = run("limit-surface --json --load 0,0,1 -", mat);
  const Cli_result many = run("batch limit-surface --load 0,0,1", mat + "\n" + mat + "\n");
  ASSERT_EQ(many.code, 0) << many.err;
  EXPECT_TRUE(has(many.out, "{\"line\": 2, " + one.out.substr(1, one.out.size() - 2))) << many.out;
}

}  // namespace
}  // namespace wrenchkit
