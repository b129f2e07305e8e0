// [CG-2] The limit-surface polytopes as mesh files (wrenchkit limit-surface --off, --obj, --ply), written by CGAL's
// writers (CGAL::IO::write_OFF, write_OBJ, write_PLY: those CGAL::IO::write_polygon_mesh dispatches to by file
// extension; the options name the format, so the writer is chosen by the option). No CGAL in this header: the
// command links wrenchkit_mesh_io and never sees CGAL's headers or flags.
//
// One mesh holds both polytopes: the inner polytope's vertices and faces first, then the outer's (two connected
// components), in the orders of Ls_polytope (vertex i, facet k), each face counter-clockwise seen from outside.
//   OFF  face colours: inner (51, 102, 230), outer (230, 51, 51)
//   OBJ  no colours, no groups (CGAL's OBJ writer writes one object); the first inner.vertices vertices and
//        inner.facets faces are the inner polytope
//   PLY  binary; face colours with alpha (the outer translucent: 89) and a face property `polytope` (uchar: 0 inner,
//        1 outer); header comments say what the file holds
// Coordinates (fx, fy, m) of loads (theory.md §1.5). By default each is the nearest double to the exact rational
// (correctly rounded, exact/numbers/rational.h nearest_double), written with 17 significant digits, so a reader gets
// back exactly those doubles. With exact coordinates: OFF writes every vertex exactly as homogeneous integer
// coordinates X Y Z W (the OFF format's "4OFF" variant: x = X/W, …; W > 0 the least common denominator of the
// vertex), which CGAL's OFF reader reads (dividing in double: the nearest double of each coordinate when |X|, |W|
// < 2^53); CGAL's own OFF writer converts every coordinate to double, so this variant is written here from the same
// mesh. OBJ and PLY have no exact numbers (decimal or binary floating point only): doubles as above.
#pragma once

#include <string>

#include "exact/sliding/limit_surface.h"

namespace wrenchkit {

enum class Mesh_format { off, obj, ply };
const char* mesh_format_name(Mesh_format f);  // "OFF", "OBJ", "PLY"

// Whether `exact_coordinates` writes exact rationals in this format (OFF only), and the text that says how the
// coordinates of a file in this format are written ("exact (homogeneous integers, 4OFF)" or "doubles (…)").
bool exact_coordinates_possible(Mesh_format f);
std::string coordinates_note(Mesh_format f, bool exact_coordinates);

// The file's bytes (PLY is binary). Throws Input_error when a coordinate is beyond the double range and the format
// holds doubles.
std::string polytopes_mesh(const Ls_polytope& inner, const Ls_polytope& outer, Mesh_format f, bool exact_coordinates);

}  // namespace wrenchkit
