#!/usr/bin/env bash
# Regenerates the pictures of docs/gallery.md from the golden scenes:  ./build.sh gallery
# (or: docs/gallery/make_gallery.sh BUILD_DIR). Each line: output name, --what, scene file.
set -euo pipefail
cd "$(dirname "$0")/../.."
W="${1:-build}/wrenchkit"
G=tests/golden
while read -r name what scene; do
  [ -z "$name" ] && continue
  "$W" render --what "$what" -o "docs/gallery/$name.svg" "$G/$scene.scene.json"
done <<'LIST'
example3_mu_0_labels          labels    triangle_example3_mu_0
example3_mu_1_10_labels       labels    triangle_example3_mu_1_10
block_corner_mu_0_labels      labels    equilibrium/block_corner_mu_0_gravity
block_corner_mu_0_dual        dual      equilibrium/block_corner_mu_0_gravity
block_corner_mu_1_2_labels    labels    equilibrium/block_corner_mu_1_2_gravity
ladder_mu_1_7_labels          labels    equilibrium/ladder_mu_1_7_gravity
ladder_mu_1_7_dual            dual      equilibrium/ladder_mu_1_7_gravity
ladder_mu_1_8_labels          labels    equilibrium/ladder_mu_1_8_gravity
ladder_mu_0_labels            labels    ladder_mu_0
pipe_clamp_labels             labels    pipe_clamp_L4_h1_mu_1_4
single_force_labels           labels    single_force
vertical_walls_labels         labels    vertical_walls_squeeze
square_pinwheel_reuleaux      reuleaux  square_pinwheel
square_crossed_reuleaux       reuleaux  square_crossed_couples
square_aligned_reuleaux       reuleaux  square_aligned
triangle_concurrent_reuleaux  reuleaux  triangle_four_concurrent
two_finger_labels             labels    two_finger_y9_10_mu1_4
barbell_limit_surface         limit-surface limit_surface/barbell
LIST
echo "make_gallery: wrote docs/gallery/*.svg"
