// Input limits: no scene can make wrenchkit allocate without bound or run without end.
// Defaults are those of docs/scene-format.md, "Limits"; every one can be raised on the command line.
#pragma once

#include <cstddef>

namespace wrenchkit {

struct Input_limits {
  std::size_t max_digits = 10000;                // digits in one number
  long max_exponent = 10000;                     // |decimal exponent|
  std::size_t max_file_bytes = 64u << 20;        // 64 MiB
  std::size_t max_depth = 64;                    // JSON nesting
  std::size_t max_contacts = 100000;             // contacts[] entries (and support.points[])
  std::size_t max_region_vertices = 4096;        // vertices of all support regions' rings together
};

}  // namespace wrenchkit
