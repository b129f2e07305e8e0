// An SVG picture of the polygonal limit surfaces of a scene's support (theory.md §12, §14.2):
// the slice f_y = 0 and the projection onto (f_x, m), and the projection onto (f_x, f_y), each with
// LS_in (blue, filled) and LS_out (red outline). For `wrenchkit render --what limit-surface` and
// the hidden `limit-surface --svg FILE`. Coordinates are doubles: a picture, not an answer.
#pragma once

#include <string>

#include "exact/io/scene.h"

namespace wrenchkit::cli {

// Precondition: scene.support is set (throws Input_error otherwise); sides as for limit-surface.
std::string render_limit_surface_svg(const Scene& scene, int sides = 32);

}  // namespace wrenchkit::cli
