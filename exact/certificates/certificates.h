// Every certificate the engine writes, from the deciders' witness data (proofs/certificate-format.md; the checker of
// proofs/checker/ reads them back). One file per section of the spec, each readable beside it and beside the checker's
// file for the same section:
//
//   closure.cpp      §3.1–§3.2  force and form closure (combination and independent generators; a twist and its reading)
//   equilibrium.cpp  §3.3       equilibrium of the load (a combination; a twist the load drives)
//   quality.cpp      §3.4       the grasp quality ε (a twist; the closed boundary of the wrench space; a facet normal)
//   critical_mu.cpp  §3.5       the critical friction coefficient (§3.1–§3.3 certificates at a common μ on each side)
//   grasp_regions.cpp §3.6      two-finger force-closure regions on a polygon's edge pairs
//   push.cpp         §8         which way a pushed body turns (the voting theorem over F)
//   motion.cpp       §6         stick / slide / depends on a support (§6.4 regions, §6.5 format 2)
//   hold.cpp         §7         fixtures on a support (§7.4 regions, §7.5 format 2)
//   witnesses.cpp    §6.1 §6.4  the parts §6 and §7 share: support forces, stick and slide witnesses, region blocks
//
// No decider writes JSON: exact/statics, exact/sliding and exact/fixture return witnesses, and these functions
// write them, in the one layout of exact/io/json_writer.h.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "exact/fixture/hold.h"
#include "exact/io/json_writer.h"
#include "exact/sliding/motion.h"
#include "exact/sliding/pushing.h"
#include "exact/statics/closure.h"
#include "exact/statics/equilibrium.h"
#include "exact/statics/critical_mu.h"
#include "exact/statics/grasp_regions.h"
#include "exact/statics/quality.h"

namespace wrenchkit {

// §3.1–§3.2: the certificate object, into `w` (an answer embeds it) or as its own text.
void write_certificate(Json_writer& w, const Closure_certificate& c);
std::string certificate_json(const Closure_certificate& c);
// §3.3
void write_certificate(Json_writer& w, const Equilibrium_certificate& c);
std::string certificate_json(const Equilibrium_certificate& c);

// §3.4 (format 4): the certificate of a decided quality (closure decided).
void write_certificate(Json_writer& w, const Quality_answer& a);
std::string certificate_json(const Quality_answer& a);

// §3.5 (format 4): the certificate of μ* of force closure (`closure`) or of the scene's load's equilibrium.
std::string critical_mu_certificate(const Critical_mu& c, bool closure);

// §3.6 (format 5): the regions of every edge pair asked; write_region_pairs: its "pairs" array (the answer's too).
void write_region_pairs(Json_writer& w, const Grasp_regions& g);
// §3.6 with "fingers": 3: every edge triple asked, with its independent cube and the four wrenches certifying it, or
// "never" (a wrench-space direction, or "frictionless"); the answer's "triples" too.
void write_region_triples(Json_writer& w, const Grasp_regions& g);
std::string grasp_regions_certificate(const Grasp_regions& g);

// §8 (format 6): the certificate of a decided rotation sense (ccw, cw, none or depends; not undecided).
std::string push_certificate(const Push_answer& a);

// §6: the certificate of a decided motion (not undecided) of the load p on the model's support. Format 1, or 2 where
// format 1 has none (regions together with a point force not given, §6.5).
std::string motion_certificate(const Support_model& model, const Vec3q& load, const Motion_answer& answer);

// §7: the certificate of a decided hold (not undecided). Format 1, or 2 for regions with a force not given (§7.5).
std::string hold_certificate(const Hold_answer& answer);

// Parts shared by the writers (and by answers that show a witness): `[{"contact": i, "edge": E, "weight": "p/q"}, …]`
// (§3.1, §3.3, §7.1); the members `"twist": [vx, vy, w], "reading": {…}` (§3.2) and `"support_forces": [[gx, gy], …]`
// (§6.1) into the object `w` has open.
void write_combination(Json_writer& w, const std::vector<std::pair<Generator_ref, Rational>>& terms);
void write_twist(Json_writer& w, const Vec3q& twist);
void write_support_forces(Json_writer& w, const std::vector<Vec2>& forces);

}  // namespace wrenchkit
