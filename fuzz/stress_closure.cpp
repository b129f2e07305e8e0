// Numerical-stability stress test of closure (docs/stability.md): families of scenes at a controlled
// distance ε from a degenerate configuration, written as decimal text as users write them. For
// each family and ε (fuzz/families.h): how often naive floating point (strtod + raw double signs) is wrong, how often
// the certified twin abstains, and that the twin and hybrid are never wrong; times per query. The
// truth is the exact engine (itself verified against brute force in tests/).
//
//   stress_closure [--cases N] [--seed S] [--report DIR]   (DIR: writes stability.md + stability.svg)
// Exit status 1 if a certified twin or hybrid answer was ever wrong.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz/families.h"

namespace {

using namespace wrenchkit;
using families::Family;

struct Row {
  std::string family;
  double eps;
  int cases = 0, naive_wrong = 0, twin_undecided = 0, twin_wrong = 0, hybrid_wrong = 0;
  double t_naive = 0, t_twin = 0, t_hybrid = 0, t_exact = 0;  // seconds in all
};

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void write_svg(const std::vector<Row>& rows, const std::vector<Family>& fams, const std::string& path) {
  // Error rate (%) against −log10 ε, one panel per family: naive wrong (red), twin undecided
  // (orange), twin wrong and hybrid wrong (blue, green: always on the zero line).
  const int W = 300, H = 200, pad = 40;
  std::ostringstream s;
  s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W * int(fams.size()) << "' height='" << H + 60
    << "' font-family='sans-serif' font-size='10'>\n<rect width='100%' height='100%' fill='white'/>\n";
  for (std::size_t f = 0; f < fams.size(); ++f) {
    const int x0 = int(f) * W + pad, y0 = 20, w = W - pad - 10, h = H - 40;
    s << "<text x='" << x0 << "' y='12' font-weight='bold'>" << fams[f].name << "</text>\n";
    s << "<rect x='" << x0 << "' y='" << y0 << "' width='" << w << "' height='" << h
      << "' fill='none' stroke='#888'/>\n";
    for (int pct : {0, 50, 100}) {
      const double y = y0 + h - h * pct / 100.0;
      s << "<text x='" << x0 - 4 << "' y='" << y + 3 << "' text-anchor='end'>" << pct << "%</text>\n";
    }
    auto X = [&](double eps) { return x0 + w * (-std::log10(eps)) / 40.0; };
    for (int e : {0, 10, 20, 30, 40})
      s << "<text x='" << x0 + w * e / 40.0 << "' y='" << y0 + h + 12 << "' text-anchor='middle'>"
        << (e ? "1e-" + std::to_string(e) : std::string("1")) << "</text>\n";
    struct Series {
      const char* color;
      std::function<double(const Row&)> rate;
    };
    const Series series[] = {
        {"#d62728", [](const Row& r) { return 100.0 * r.naive_wrong / r.cases; }},
        {"#ff7f0e", [](const Row& r) { return 100.0 * r.twin_undecided / r.cases; }},
        {"#1f77b4", [](const Row& r) { return 100.0 * r.twin_wrong / r.cases; }},
        {"#2ca02c", [](const Row& r) { return 100.0 * r.hybrid_wrong / r.cases; }},
    };
    for (const Series& se : series) {
      s << "<polyline fill='none' stroke='" << se.color << "' stroke-width='2' points='";
      for (const Row& r : rows)
        if (r.family == fams[f].name) s << X(r.eps) << "," << y0 + h - h * se.rate(r) / 100.0 << " ";
      s << "'/>\n";
    }
  }
  s << "<text x='40' y='" << H + 40 << "'>ε (distance to the degenerate configuration) →   "
    << "<tspan fill='#d62728'>naive double: wrong</tspan>   <tspan fill='#ff7f0e'>certified twin: undecided</tspan>   "
    << "<tspan fill='#1f77b4'>twin: wrong</tspan>   <tspan fill='#2ca02c'>hybrid: wrong</tspan></text>\n</svg>\n";
  std::ofstream(path) << s.str();
}

}  // namespace

int main(int argc, char** argv) {
  int cases = 200;
  std::uint64_t seed = 20261121;
  std::string report;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--cases" && i + 1 < argc) cases = std::atoi(argv[++i]);
    else if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--report" && i + 1 < argc) report = argv[++i];
    else {
      std::fprintf(stderr, "usage: stress_closure [--cases N] [--seed S] [--report DIR]\n");
      return 2;
    }
  }
  const std::vector<double> epsilons = {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-13, 1e-14, 1e-15, 1e-16, 1e-20, 1e-30, 1e-40};
  const std::vector<Family>& fams = families::all();
  std::vector<Row> rows;
  bool failed = false;
  for (const Family& fam : fams) {
    stress::Rng rng(seed);
    for (double eps : epsilons) {
      Row row;
      row.family = fam.name;
      row.eps = eps;
      for (int c = 0; c < cases; ++c) {
        const families::Case k = families::make_case(fam, eps, rng);
        const Scene scene = read_scene(k.text, Input_limits{});
        double t = now();
        const families::Verdict exact = families::decide(scene, fam.question, Mode::exact);
        row.t_exact += now() - t;
        t = now();
        const families::Verdict twin = families::decide(scene, fam.question, Mode::float_only);
        row.t_twin += now() - t;
        t = now();
        const families::Verdict hybrid = families::decide(scene, fam.question, Mode::hybrid);
        row.t_hybrid += now() - t;
        t = now();
        const bool naive = families::naive_verdict(k);
        row.t_naive += now() - t;
        ++row.cases;
        row.naive_wrong += naive != exact.holds;
        row.twin_undecided += !twin.decided;
        row.twin_wrong += twin.decided && twin.holds != exact.holds;
        row.hybrid_wrong += hybrid.holds != exact.holds;
        if (exact.holds != k.expected || (twin.decided && twin.holds != exact.holds) || hybrid.holds != exact.holds) {
          std::fprintf(stderr, "WRONG certified answer, family %s eps %g seed %llu case %d:\n%s\n", fam.name, eps,
                       static_cast<unsigned long long>(seed), c, k.text.c_str());
          failed = true;
        }
      }
      rows.push_back(row);
    }
  }
  std::ostringstream md;
  md << "| family | ε | cases | naive wrong | twin undecided | twin wrong | hybrid wrong | naive µs | twin µs | hybrid µs | exact µs |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows) {
    char b[512];
    std::snprintf(b, sizeof b, "| %s | %g | %d | %.1f%% | %.1f%% | %d | %d | %.2f | %.2f | %.2f | %.2f |\n",
                  r.family.c_str(), r.eps, r.cases, 100.0 * r.naive_wrong / r.cases, 100.0 * r.twin_undecided / r.cases,
                  r.twin_wrong, r.hybrid_wrong, 1e6 * r.t_naive / r.cases, 1e6 * r.t_twin / r.cases,
                  1e6 * r.t_hybrid / r.cases, 1e6 * r.t_exact / r.cases);
    md << b;
  }
  std::fputs(md.str().c_str(), stdout);
  if (!report.empty()) {
    std::ofstream out(report + "/stability.md");
    out << "# Numerical stability of closure: naive double vs certified twin vs hybrid vs exact\n\n"
        << "Regenerate with `./build.sh stability` (runs `stress_closure --cases " << cases << " --seed " << seed
        << " --report docs`).\n"
        << "Each family builds scenes at distance ε from a degenerate configuration and writes them as decimal text\n"
        << "(17 significant digits), as a user would; the truth is the exact engine. *naive*: the same doubles with raw\n"
        << "double signs (what tolerance-free float code does). *twin*: the certified float twin alone (it abstains when\n"
        << "a sign is within its error bound). *hybrid*: the default mode (twin, exact where the twin abstains).\n"
        << "Times are per query, verdict only (no certificate), on a noisy shared 2-core machine.\n\n"
        << "| family | what |\n|---|---|\n";
    for (const Family& f : fams) out << "| " << f.name << " | " << f.what << " |\n";
    out << "\n![error rates against ε](stability.svg)\n\n" << md.str()
        << "\nReading: naive double signs start to go wrong when ε approaches the rounding level of the input (about\n"
        << "1e-16 relative, earlier with large offsets) and are wrong about half the time below it. The certified twin\n"
        << "abstains on exactly those cases and is never wrong; hybrid is never wrong and costs the exact price only\n"
        << "there.\n";
    write_svg(rows, fams, report + "/stability.svg");
  }
  return failed ? 1 : 0;
}
