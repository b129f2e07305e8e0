// The per-scene commands (cli/common.h, Scene_command): the table that `batch` and other front ends
// look commands up in, and the check of command-specific options.
#include <string>

#include "cli/common.h"

namespace wrenchkit::cli {

namespace {

// In the order of `wrenchkit --help`.
const Scene_command kSceneCommands[] = {
    {"closure", prepare_closure_json},   {"equilibrium", prepare_equilibrium_json},
    {"labels", prepare_labels_json},     {"dual", prepare_dual_json},
    {"reuleaux", prepare_reuleaux_json}, {"limit-surface", prepare_limit_surface_json},
    {"sliding", prepare_sliding_json},   {"analyze", prepare_analyze_json},
};

}  // namespace

const Scene_command* find_scene_command(const std::string& name) {
  for (const Scene_command& c : kSceneCommands)
    if (name == c.name) return &c;
  return nullptr;
}

std::string scene_command_names() {
  std::string s;
  for (const Scene_command& c : kSceneCommands) s += (s.empty() ? "" : "|") + std::string(c.name);
  return s;
}

void only_options(const Options& o, const char* command, std::initializer_list<const char*> allowed) {
  for (const auto& [k, v] : o.values) {
    bool ok = false;
    for (const char* a : allowed) ok |= k == a;
    if (!ok) throw Usage_error(k + " is not an option of " + command);
  }
}

}  // namespace wrenchkit::cli
