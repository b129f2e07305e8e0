// proofs/certificate-format.md §6.1 and §6.4: the witness parts §6 (motion) and §7 (hold) share.
#include "exact/certificates/witnesses.h"

#include "exact/certificates/certificates.h"

namespace wrenchkit {

namespace {

// [[x, y], …]
void write_pairs(Json_writer& w, const std::vector<Vec2>& v) {
  w.array();
  for (const Vec2& p : v) w.array().rational(p.x).rational(p.y).end_array();
  w.end_array();
}

void write_cells(Json_writer& w, const Region_cells& c) {
  write_pairs(w.key("vertices"), c.vertices);
  w.key("triangles").array();
  for (const auto& t : c.triangles) w.array().integer(t[0]).integer(t[1]).integer(t[2]).end_array();
  w.end_array();
}

}  // namespace

void write_support_forces(Json_writer& w, const std::vector<Vec2>& forces) {
  write_pairs(w.key("support_forces"), forces);
}

void write_blocks(Json_writer& w, const std::vector<Region_stick_block>& blocks) {
  if (blocks.empty()) return;
  w.key("regions").array();
  for (const Region_stick_block& b : blocks) {
    write_cells(w.object(), b.cells);
    write_pairs(w.key("forces"), b.forces);
    w.end_object();
  }
  w.end_array();
}

void write_blocks(Json_writer& w, const std::vector<Region_stick_block>& forces,
                  const std::vector<Region_slide_block>& speeds) {
  if (forces.empty()) return;
  w.key("regions").array();
  for (std::size_t k = 0; k < forces.size(); ++k) {
    write_cells(w.object(), forces[k].cells);
    write_pairs(w.key("forces"), forces[k].forces);
    w.key("speed_bounds").rationals(speeds[k].speed_bounds).end_object();
  }
  w.end_array();
}

void write_blocks(Json_writer& w, const std::vector<Region_slide_block>& blocks) {
  if (blocks.empty()) return;
  w.key("regions").array();
  for (const Region_slide_block& b : blocks) {
    write_cells(w.object(), b.cells);
    w.key("speed_bounds").rationals(b.speed_bounds).end_object();
  }
  w.end_array();
}

}  // namespace wrenchkit
