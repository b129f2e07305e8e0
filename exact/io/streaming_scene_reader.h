// The one-pass, DOM-free scene reader behind read_scene (exact/io/scene.h): the same acceptance, the same
// Scene and the same errors as the reference reader read_scene_tree, without building a JSON tree.
//
// It walks the text once, following the scene schema (docs/scene-format.md): every value's type is
// known from its key, so no tree is needed. Numbers are validated and read from their digits where
// they stand (exact rationals when eager; certified doubles, exact signs and the kept text when lazy,
// as read_scene does), keys are matched without copying, and the Scene passed in is reused: once warm,
// a scene of short decimals costs no heap allocation at all.
//
// Equivalence with read_scene_tree is by construction on the error side: the fast path only ever
// *accepts*; on anything it does not accept — every invalid text, and the rare valid forms it leaves
// alone (limits.max_depth below the scene's nesting) — it defers to read_scene_tree, which accepts or
// throws its own message. What it accepts, read_scene_tree accepts with the same Scene: that is what
// fuzz/scene_checks.h (every fuzz input, and the committed corpora in CTest) and tests/scene_test.cpp
// check.
#pragma once

#include <string_view>

#include "exact/numbers/limits.h"
#include "exact/io/scene.h"

namespace wrenchkit {

// Reads `text` into `scene`, reusing its storage (contacts, strings, rationals). Accepts exactly the
// texts read_scene_tree(text, limits, source, lazy) accepts and leaves exactly the Scene it returns;
// otherwise throws read_scene_tree's Input_error (then `scene` is valid but unspecified). Returns true
// when the one-pass path read the scene, false when it deferred to read_scene_tree (which then accepted):
// with limits.max_depth ≥ 5 every valid scene takes the one-pass path (the tests check it).
// Complexity: O(|text|) plus the numbers' own reading (see parse_rational).
bool read_scene_into(Scene& scene, std::string_view text, const Input_limits& limits,
                     std::string_view source = "scene", bool lazy = false);
// (read_scene of exact/io/scene.h is this reader into a fresh Scene.)

}  // namespace wrenchkit
