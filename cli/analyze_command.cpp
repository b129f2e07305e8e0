// wrenchkit analyze (and demo): everything the scene's contents call for.
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/common.h"
#include "exact/json.h"

namespace wrenchkit::cli {

// analyze: everything the scene's contents call for, and nothing else — closure of its contacts
// (always: no contacts is an answer too), equilibrium when it has a load. What a scene asks for
// that this version cannot compute yet is listed under "skipped", never silently dropped.
int run_analyze(const Options& o, const std::string& scene_text, const std::string& source, const char* command) {
  if (o.verdict_only) throw Usage_error("--verdict-only is for batch");
  if (!o.certificate_file.empty() || !o.form_certificate_file.empty())
    throw Usage_error("analyze writes its certificates in its JSON output; use closure or equilibrium for files");
  const Closure_result c = compute_closure(o, scene_text, source);
  std::optional<Equilibrium_result> e;
  if (c.scene.load) e = compute_equilibrium(o, c.scene, scene_text);
  std::vector<std::pair<std::string, std::string>> skipped;
  if (c.scene.support)
    skipped.push_back({"limit_surface", "the scene has a support; limit surfaces are not implemented in this version"});
  if (o.json) {
    std::cout << "{\"command\": \"" << command << "\", \"name\": " << json::quote(c.scene.name)
              << ", \"closure\": " << closure_json(o, c, "closure");
    if (e) std::cout << ", \"equilibrium\": " << equilibrium_json(o, c.scene, *e, "equilibrium");
    std::cout << ", \"skipped\": [";
    for (std::size_t i = 0; i < skipped.size(); ++i)
      std::cout << (i ? ", " : "") << "{\"what\": " << json::quote(skipped[i].first)
                << ", \"why\": " << json::quote(skipped[i].second) << "}";
    std::cout << "]}\n";
    return kAnswered;
  }
  std::cout << "scene: " << (c.scene.name.empty() ? source : c.scene.name) << "\n" << closure_human(c);
  if (e) std::cout << equilibrium_human(*e);
  for (const auto& [what, why] : skipped) std::cout << "skipped " << what << ": " << why << "\n";
  std::cout << "decided by: " << decided_by(c.fc, c.fo) << " for closure"
            << (e ? std::string(", ") + e->a.decided_by() + " for equilibrium" : std::string()) << "\n"
            << "every certificate accepted by the independent checker (exact arithmetic)\n";
  return kAnswered;
}

}  // namespace wrenchkit::cli
