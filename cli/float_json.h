// JSON and text of the float twin's constructions (`--mode float`): coordinates as JSON numbers with
// their certified error bounds beside them (docs/cli.md, "--mode float"). The REGION and infinity
// formats are those of exact/statics/planar_region.h with numbers instead of exact rationals, plus
// "vertex_bounds" / "direction_bounds": per coordinate, a bound on the distance from the PRINTED decimal
// to the exact value — the twin's bound plus the printing error (computed exactly), rounded up — so the
// promise holds for the numbers a reader sees, not only for the doubles behind them. Human text
// shows 12 digits with a bound widened the same way and rounded up to 2 significant digits.
#pragma once

#include <string>

#include "exact/io/json_writer.h"
#include "exact/pipeline/labels_answer.h"   // the twin's values the pipeline answers with
#include "exact/pipeline/support_answer.h"

namespace wrenchkit::cli {

std::string float_number(double x);  // shortest round-trip decimal (%.17g), finite
// Each written into `w` (exact/io/json_writer.h) as one value.
void write_float_point(Json_writer& w, const fl::Point2& p);    // [x, y]
void write_float_bounds(Json_writer& w, const fl::Point2& p);   // [ex, ey]
void write_float_region(Json_writer& w, const fl::Region2& r);  // REGION with numbers and bounds
void write_float_infinity(Json_writer& w, const fl::Arc2& a);   // [] | [{"direction"}] | [{"from", "to"}] | full circle
void write_float_dual_point(Json_writer& w, const fl::Dual_point_twin& p);
std::string float_region_text(const fl::Region2& r);  // for people: x ± e
std::string float_infinity_text(const fl::Arc2& a);
// One value: {"value": v, "bound": e} (e covering the printing of v too), or null without a finite bound;
// and "v ± e" for people.
void write_float_value(Json_writer& w, const fl::Bounded& b);
std::string float_value_text(const fl::Bounded& b);
// The true load of a twist: {"load": [VALUE, VALUE, VALUE], "facet_points": [i, …]} (the load is then the
// facet's centre) or null when the twin could not decide it; and its text.
void write_float_load(Json_writer& w, const fl::Load_twin& l);
std::string float_load_text(const fl::Load_twin& l);

}  // namespace wrenchkit::cli
