// The parts of proofs/certificate-format.md §6 and §7 that both sections write besides the support forces
// (certificates.h): the regions' stick and slide blocks (§6.4). Internal to exact/certificates/.
#pragma once

#include <vector>

#include "exact/io/json_writer.h"
#include "exact/sliding/motion.h"

namespace wrenchkit {

// "regions": [block, …] when there are blocks (a support with regions has one per region), else nothing. A stick
// block: {"vertices", "triangles", "forces"}; a slide block: {"vertices", "triangles", "speed_bounds"}.
void write_blocks(Json_writer& w, const std::vector<Region_stick_block>& blocks);
void write_blocks(Json_writer& w, const std::vector<Region_slide_block>& blocks);
// A load on the surface (§6.6): per region one block on one set of cells with both, {"vertices", "triangles",
// "forces", "speed_bounds"} (the stick and slide blocks of an impending witness share their cells).
void write_blocks(Json_writer& w, const std::vector<Region_stick_block>& forces,
                  const std::vector<Region_slide_block>& speeds);

}  // namespace wrenchkit
