// Writes a scene as canonical scene-format JSON (docs/scene-format.md): every number an exact
// rational string in lowest terms, keys in a fixed order, one contact per line. read_scene of the
// text gives back the same scene (the round trip the fuzz targets and tests check); the reference
// corpus and the failure dumps use it.
#pragma once

#include <string>

#include "exact/io/scene.h"

namespace wrenchkit {

std::string write_scene(const Scene& scene);
// The canonical text on one line: newlines (never inside strings, which json::quote escapes) and their indentation
// removed (the corpus' lines, a scene inside a one-line answer).
std::string one_line(const std::string& canonical);

}  // namespace wrenchkit
