// The JSON parts of the constructions' answers that several front ends write (docs/cli.md: labels, dual, REGION):
// the CLI's commands, batch, and the reference corpus write them with these, in the one layout of
// exact/io/json_writer.h. (Certificates: exact/certificates/certificates.h.)
#pragma once

#include <string>

#include "exact/io/json_writer.h"
#include "exact/statics/force_dual.h"
#include "exact/statics/moment_labels.h"
#include "exact/statics/planar_region.h"

namespace wrenchkit {

// JSON (docs/cli.md, REGION): a REGION {"empty", "shape", "vertices", "directions"}; the labeled points
// at infinity as [{"from", "to"}] arcs (counter-clockwise; a full circle has "full": true and
// from = to) or [{"direction"}] single directions; a point [x, y]. Each as a value written into `w`
// (exact/io/json_writer.h), or as its own text (for messages and tests).
void write_region(Json_writer& w, const Region& r);
void write_infinity(Json_writer& w, const Cone2& c);
void write_point(Json_writer& w, const Vec2& p);
std::string region_json(const Region& r);
std::string infinity_json(const Cone2& c);
std::string point_json(const Vec2& p);

// JSON per docs/cli.md (labels): the members "plus": REGION, "minus": REGION, "both": [...],
// "infinity": [...] written into the object `w` has open (the command adds its own members around
// them); labels_json: those members alone as one object's text (tests compare answers with it). And
// the "both" set as a value.
void write_labels(Json_writer& w, const Moment_labels& l);
std::string labels_json(const Moment_labels& l);
void write_both(Json_writer& w, const Both_set& b);

// A dual point as JSON (docs/cli.md, dual): {"sheet": "+"|"-", "point": [x, y]}, {"sheet":
// "infinity", "direction": [dx, dy]} or {"sheet": "none", "zero": true}, written into `w`.
void write_dual_point(Json_writer& w, const Dual_point& p);

}  // namespace wrenchkit
