#include "tests/test_support.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "proofs/checker/checker.h"

namespace wrenchkit::test {

std::string source_dir() { return WRENCHKIT_SOURCE_DIR; }

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> scene_files(const std::string& folder) {
  std::vector<std::string> out;
  const std::string suffix = ".scene.json";
  for (const auto& e : std::filesystem::directory_iterator(source_dir() + "/" + folder)) {
    const std::string f = e.path().string();
    if (f.size() > suffix.size() && !f.compare(f.size() - suffix.size(), suffix.size(), suffix)) out.push_back(f);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string expected_of(const std::string& scene_file) {
  return read_text(scene_file.substr(0, scene_file.size() - std::string(".scene.json").size()) + ".expected.json");
}

std::string scene_json(const std::vector<Contact_spec>& contacts, const std::string& name) {
  std::string s = "{\"wrenchkit\": 1";
  if (!name.empty()) s += ", \"name\": \"" + name + "\"";
  s += ", \"contacts\": [";
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const Contact_spec& c = contacts[i];
    if (i) s += ", ";
    if (!c.wrench.empty()) {
      s += "{\"wrench\": " + c.wrench + "}";
      continue;
    }
    s += "{\"at\": [\"" + c.ax + "\", \"" + c.ay + "\"], \"normal\": [\"" + c.nx + "\", \"" + c.ny + "\"]";
    if (!c.mu.empty()) s += ", \"mu\": \"" + c.mu + "\"";
    s += "}";
  }
  return s + "]}";
}

std::vector<Near_edge_grasp> near_edge_grasps() {
  std::vector<Near_edge_grasp> out;
  for (int k = 1; k <= 40; ++k)
    for (int side : {-1, 1}) {
      Near_edge_grasp g;
      g.y2 = side < 0 ? "0." + std::string(k - 1, '9') + "9" : "1." + std::string(k - 1, '0') + "1";
      g.text = scene_json({{"0", "0.5", "1", "0", "0.5"}, {"1", g.y2, "-1", "0", "0.5"}});
      g.closed = side < 0;
      const double c[2][5] = {{0, 0.5, 1, 0, 0.5}, {1, std::strtod(g.y2.c_str(), nullptr), -1, 0, 0.5}};
      std::copy(&c[0][0], &c[0][0] + 10, &g.contacts[0][0]);
      out.push_back(g);
    }
  return out;
}

std::uint64_t seed(std::uint64_t fallback) {
  if (const char* e = std::getenv("WRENCHKIT_SEED")) return std::strtoull(e, nullptr, 10);
  return fallback;
}

std::vector<Contact_spec> random_contacts(std::mt19937_64& rng, int max_contacts) {
  static const char* mus[] = {"0", "0", "1/4", "1/2", "1", "2", "1/3"};
  static const int normals[][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, 1},
                                   {1, -1}, {-1, -1}, {2, 1}, {1, 2}, {-2, 3}, {3, -1}};
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const int k = uni(0, max_contacts);
  std::vector<Contact_spec> out;
  for (int i = 0; i < k; ++i) {
    Contact_spec c;
    if (uni(0, 11) == 0) {
      int w[3];
      do {
        for (int& x : w) x = uni(-2, 2);
      } while (w[0] == 0 && w[1] == 0 && w[2] == 0);
      c.wrench = "[" + std::to_string(w[0]) + ", " + std::to_string(w[1]) + ", " + std::to_string(w[2]) + "]";
    } else {
      c.ax = std::to_string(uni(-3, 3));
      c.ay = std::to_string(uni(-3, 3));
      const auto& n = normals[uni(0, 11)];
      const int len = uni(1, 2);  // normals of any length
      c.nx = std::to_string(n[0] * len);
      c.ny = std::to_string(n[1] * len);
      c.mu = mus[uni(0, 6)];
    }
    out.push_back(c);
  }
  return out;
}

std::vector<Contact_spec> decimal_contacts(std::mt19937_64& rng, int k) {
  std::uniform_int_distribution<int> coord(-999, 999), mu(1, 80);
  std::vector<Contact_spec> cs;
  auto dec = [&](int v) { return std::to_string(v / 1000.0).substr(0, 6 + (v < 0)); };
  for (int i = 0; i < k; ++i) {
    int nx = coord(rng), ny = coord(rng);
    if (nx == 0 && ny == 0) nx = 1;
    cs.push_back({dec(coord(rng)), dec(coord(rng)), std::to_string(nx), std::to_string(ny), "0." + std::to_string(mu(rng))});
  }
  return cs;
}

std::string dump_failure(const std::string& scene_text, const std::string& tag) {
  std::filesystem::create_directories("failures");
  const std::string path = std::filesystem::absolute("failures/" + tag + ".json").string();
  std::ofstream(path) << scene_text << "\n";
  return path;
}

namespace {
using V = Vec3q;
}  // namespace

int brute_force_rank(const std::vector<Vec3q>& g) {
  const std::size_t n = g.size();
  int r = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_zero(g[i])) r = std::max(r, 1);
    for (std::size_t j = i + 1; j < n; ++j) {
      const V c = cross(g[i], g[j]);
      if (is_zero(c)) continue;
      r = std::max(r, 2);
      for (std::size_t k = j + 1; k < n; ++k)
        if (dot(c, g[k]) != 0) return 3;
    }
  }
  return r;
}

// Carathéodory: some ≤ 3 generators with a non-negative exact solution.
std::string scratch_dir(const std::string& tag) {
  namespace fs = std::filesystem;
  const fs::path d = fs::temp_directory_path() / ("wrenchkit_" + tag + "_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d.string();
}

Cli_result run_cli(const std::string& exe, const std::string& env, const std::string& args,
                   const std::string& stdin_text, const std::string& tag) {
  const std::string d = scratch_dir(tag);
  const std::string in = d + "/stdin", out = d + "/stdout", err = d + "/stderr";
  std::ofstream(in, std::ios::binary) << stdin_text;
  const std::string cmd = env + (env.empty() ? "" : " ") + "'" + exe + "' " + args + " < '" + in + "' > '" + out +
                          "' 2> '" + err + "'";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(out), read_text(err)};
}

bool brute_force_in_cone(const std::vector<Vec3q>& g, const std::array<Rational, 3>& x) {
  using V = Vec3q;
  if (is_zero(x)) return true;
  auto det = [](const V& a, const V& b, const V& c) -> Rational {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  };
  const std::size_t n = g.size();
  for (std::size_t i = 0; i < n; ++i) {  // x = λ g_i
    const V a = g[i];
    const V c = cross(a, x);
    if (is_zero(c) && dot(a, x) > 0) return true;
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {  // x = λ g_i + μ g_j in their plane
      const V a = g[i], b = g[j], nrm = cross(a, b);
      if (is_zero(nrm)) continue;
      if (dot(nrm, x) != 0) continue;
      // λ = (x × b)·n / |n|², μ = (a × x)·n / |n|²: signs of the numerators decide.
      const V xb = cross(x, b), ax = cross(a, x);
      const Rational l = dot(xb, nrm);
      const Rational m = dot(ax, nrm);
      if (l >= 0 && m >= 0) return true;
    }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k) {  // Cramer
        const V a = g[i], b = g[j], c = g[k];
        const Rational d = det(a, b, c);
        if (d == 0) continue;
        const Rational l1 = det(x, b, c) / d, l2 = det(a, x, c) / d, l3 = det(a, b, x) / d;
        if (l1 >= 0 && l2 >= 0 && l3 >= 0) return true;
      }
  return false;
}

bool brute_force_closure(const std::vector<Vec3q>& g) {
  if (brute_force_rank(g) < 3) return false;
  for (std::size_t i = 0; i < g.size(); ++i)
    for (std::size_t j = i + 1; j < g.size(); ++j) {
      const V c = cross(g[i], g[j]);
      if (is_zero(c)) continue;
      for (int s : {1, -1}) {
        bool all = true;
        for (const Vec3q& w : g) all = all && s * sgn(dot(c, w)) >= 0;
        if (all) return false;
      }
    }
  return true;
}

::testing::AssertionResult checker_accepts(const std::string& scene_text, const std::string& cert) {
  const auto r = wrenchkit_checker::check(scene_text, cert);
  if (r.outcome == wrenchkit_checker::Outcome::accepted) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "checker: " << r.message << "\ncertificate: " << cert
                                       << "\nscene: " << scene_text;
}

::testing::AssertionResult checker_refuses_edit(const std::string& scene_text, std::string cert, const std::string& from,
                                                const std::string& to, const std::string& reason) {
  const std::size_t at = cert.find(from);
  if (at == std::string::npos) return ::testing::AssertionFailure() << from << " is not in " << cert;
  cert.replace(at, from.size(), to);
  const auto r = wrenchkit_checker::check(scene_text, cert);
  if (r.outcome != wrenchkit_checker::Outcome::rejected)
    return ::testing::AssertionFailure() << "accepted: " << cert;
  if (r.message.find(reason) == std::string::npos)
    return ::testing::AssertionFailure() << "rejected for another reason: " << r.message << " (expected " << reason << ")";
  return ::testing::AssertionSuccess();
}

}  // namespace wrenchkit::test
