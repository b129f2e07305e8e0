// [BUDGET] The scene-wide budget on exact arithmetic (docs/scene-format.md "Limits", docs/design.md "Input,
// limits and batch"): the measures of exact/numbers/limits.h (Budget_tally) over a scene's text, and the message of a
// scene over budget. The streaming reader keeps the same tally while it reads (and defers when it goes over);
// read_scene_tree measures the text first, so a scene over budget is refused before any number is built.
#pragma once

#include <string>
#include <string_view>

#include "exact/numbers/limits.h"

namespace wrenchkit {

// The budget measures of a scene text: every number at a place where the scene format has a number (the
// version, body.outline and body.com, contacts, load, support points and regions), counted by number_digits when it is a valid
// number within the per-number limits (an invalid one is the schema's error, counted 0 here); every entry of
// contacts[] and support.points[]. Builds no number and no JSON tree: one pass, memory O(1) beyond a decoded
// string. Tolerant: it walks any JSON text (unknown keys, wrong types, every other value skipped) and on text
// that is not JSON it stops where it cannot follow, with the measures of what it read (a prefix over budget
// means the scene is: the measures only grow).
Budget_tally measure_scene(std::string_view json_text, const Input_limits& limits);

// "" when `measured` is within the budgets of `limits`, else the message of the first budget it exceeds: the
// budget, the measured value and the option that raises it, e.g.
// "scene: its numbers have 5000000000 digits in all, more than the budget of 20000000 (--max-total-digits)".
std::string budget_problem(const Budget_tally& measured, const Input_limits& limits);

}  // namespace wrenchkit
