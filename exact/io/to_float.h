// [FL-4] Handing an exact scene to the float twin: every rational becomes a double with a
// certified bound on its conversion error (0 when the rational is exactly a double, as 1/2 is and
// 0.1 is not). So a certified float answer is the exact answer for the scene as written.
#pragma once

#include <vector>

#include "exact/io/scene.h"
#include "float/closure_twin.h"

namespace wrenchkit {

std::vector<fl::Bounded_contact> to_bounded(const Scene& scene);
// One contact: its twin when read_scene made it (has_twin), else converted from the rationals.
fl::Bounded_contact to_bounded(const Contact& c);

}  // namespace wrenchkit
