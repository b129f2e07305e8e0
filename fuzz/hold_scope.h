// Which scenes the fuzzers ask `hold` about (scene_checks.h and fuzz_checker.cpp share it).
#pragma once

#include <cstddef>

#include "exact/io/scene.h"

// Hold over regions in the fuzzers: at most 4 coarse triangles in all (the cells, up to kMaxHoldRegionCells, are the
// exact LP's support points) and at most 4 points whose force is not given (each vertex of F runs the decision on the
// cells) [HD-2].
inline bool small_regions_for_hold(const wrenchkit::Support& s) {
  if (s.regions.empty()) return true;
  std::size_t coarse = 0, unknown = 0;
  for (const wrenchkit::Support_region& r : s.regions) coarse += r.triangles.size();
  for (const wrenchkit::Support_point& p : s.points) unknown += p.force ? 0 : 1;
  return coarse <= 4 && unknown <= 4;
}
