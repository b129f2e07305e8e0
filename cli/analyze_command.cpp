// wrenchkit analyze (and demo): everything the scene's contents call for.
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/common.h"
#include "exact/json.h"
#include "exact/limit_surface.h"

namespace wrenchkit::cli {

namespace {

// The support's limit surface at the finest N in {32, 16, 8, 4} whose candidate normals stay within a
// small budget (analyze summarises; `limit-surface` answers any N and tolerance). Empty if none fits.
struct Ls_summary {
  std::string json, human;
};
std::optional<Ls_summary> limit_surface_summary(const Scene& scene) {
  const Ls_support sup = merge_support(*scene.support);
  for (int n : {32, 16, 8, 4}) {
    const Polygonal_ls model(sup, make_directions(n));
    if (model.candidate_count() > 20000 && n > 4) continue;
    if (model.candidate_count() > kMaxCandidates) return std::nullopt;
    const Ls_polytope in = model.build(Side::inner), out = model.build(Side::outer);
    const Vec2 cof{sup.weighted_force_sum.x / sup.total_force, sup.weighted_force_sum.y / sup.total_force};
    const std::string lam = to_string(model.directions().lambda_sq);
    Ls_summary r;
    r.json = "{\"sides\": " + std::to_string(n) + ", \"lambda_squared\": " + json::quote(lam) +
             ", \"center_of_friction\": [" + json::quote(to_string(cof.x)) + ", " + json::quote(to_string(cof.y)) +
             "], \"inner\": {\"facets\": " + std::to_string(in.facets.size()) + ", \"vertices\": " +
             std::to_string(in.vertices.size()) + "}, \"outer\": {\"facets\": " + std::to_string(out.facets.size()) +
             ", \"vertices\": " + std::to_string(out.vertices.size()) + "}}";
    r.human = "limit surface (" + std::to_string(n) + " sides): lambda^2 = " + lam + ", inner " +
              std::to_string(in.facets.size()) + " facets, outer " + std::to_string(out.facets.size()) +
              " facets; centre of friction (" + to_string(cof.x) + ", " + to_string(cof.y) +
              ") — 'wrenchkit limit-surface' for any N, tolerances and queries\n";
    return r;
  }
  return std::nullopt;
}

}  // namespace

// analyze: everything the scene's contents call for, and nothing else — closure of its contacts
// (always: no contacts is an answer too), equilibrium when it has a load, a summary of the limit
// surface when it has a support. What cannot be computed within analyze's budget is listed under
// "skipped", never silently dropped.
int run_analyze(const Options& o, const std::string& scene_text, const std::string& source, const char* command) {
  if (o.verdict_only) throw Usage_error("--verdict-only is for batch");
  if (!o.certificate_file.empty() || !o.form_certificate_file.empty())
    throw Usage_error("analyze writes its certificates in its JSON output; use closure or equilibrium for files");
  const Closure_result c = compute_closure(o, scene_text, source);
  std::optional<Equilibrium_result> e;
  if (c.scene.load) e = compute_equilibrium(o, c.scene, scene_text);
  std::vector<std::pair<std::string, std::string>> skipped;
  std::optional<Ls_summary> ls;
  if (c.scene.support) {
    ls = limit_surface_summary(c.scene);
    if (!ls)
      skipped.push_back({"limit_surface", "too many support points for analyze's summary; use wrenchkit limit-surface"});
  }
  if (o.json) {
    std::cout << "{\"command\": \"" << command << "\", \"name\": " << json::quote(c.scene.name)
              << ", \"closure\": " << closure_json(o, c, "closure");
    if (e) std::cout << ", \"equilibrium\": " << equilibrium_json(o, c.scene, *e, "equilibrium");
    if (ls) std::cout << ", \"limit_surface\": " << ls->json;
    std::cout << ", \"skipped\": [";
    for (std::size_t i = 0; i < skipped.size(); ++i)
      std::cout << (i ? ", " : "") << "{\"what\": " << json::quote(skipped[i].first)
                << ", \"why\": " << json::quote(skipped[i].second) << "}";
    std::cout << "]}\n";
    return kAnswered;
  }
  std::cout << "scene: " << (c.scene.name.empty() ? source : c.scene.name) << "\n" << closure_human(c);
  if (e) std::cout << equilibrium_human(*e);
  if (ls) std::cout << ls->human;
  for (const auto& [what, why] : skipped) std::cout << "skipped " << what << ": " << why << "\n";
  std::cout << "decided by: " << decided_by(c.fc, c.fo) << " for closure"
            << (e ? std::string(", ") + e->a.decided_by() + " for equilibrium" : std::string()) << "\n"
            << "every certificate accepted by the independent checker (exact arithmetic)\n";
  return kAnswered;
}

}  // namespace wrenchkit::cli
