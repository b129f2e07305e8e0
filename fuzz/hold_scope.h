// Which scenes the fuzzers ask `hold` about (scene_checks.h and fuzz_checker.cpp share it).
#pragma once

#include <cstddef>

#include "exact/io/scene.h"

// Hold over regions in the fuzzers: every point force given (else an Input_error by design), at most 4 coarse
// triangles in all (the cells, up to kMaxHoldRegionCells, are the exact LP's support points).
inline bool small_regions_for_hold(const wrenchkit::Support& s) {
  if (s.regions.empty()) return true;
  std::size_t coarse = 0;
  for (const wrenchkit::Support_region& r : s.regions) coarse += r.triangles.size();
  return s.known() && coarse <= 4;
}
