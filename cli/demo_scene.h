// The bundled textbook scene of `wrenchkit demo`: Mason's Example 3 (ch. 6.5), "a triangle made
// secure by friction", with the coordinates of theory.md §8.7. Also shipped as
// tests/golden/triangle_example3_mu_1_10.scene.json (a test keeps the contacts identical), plus
// its weight at the centroid, so that `demo` (analyze) answers closure and equilibrium.
#pragma once

namespace wrenchkit::cli {

inline constexpr const char* kDemoScene = R"scene({
  "wrenchkit": 1,
  "name": "Mason Example 3: triangle made secure by friction (mu = 1/10)",
  "body": { "outline": [[0,0],[6,0],[0,6]], "com": [2,2] },
  "load": { "gravity": 1 },
  "contacts": [
    { "at": [1,0], "normal": [0,1],   "mu": "1/10" },
    { "at": [0,1], "normal": [1,0],   "mu": "1/10" },
    { "at": [3,3], "normal": [-1,-1], "mu": "1/10" }
  ]
}
)scene";

}  // namespace wrenchkit::cli
