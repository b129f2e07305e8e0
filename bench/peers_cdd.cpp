// cddlib with GMP rationals (bench/peers.h). Compiled with -DGMPRATIONAL, linked with -lcddgmp
// only (linking -lcdd too crashes: both export the same symbols).
#include <stdexcept>

#include "bench/peers.h"

extern "C" {
#include <cdd/setoper.h>
#include <cdd/cdd.h>
}

namespace wrenchkit::peers {

Verdict cdd_gmp(const std::vector<Wrench_q>& g) {
  static const bool init = (dd_set_global_constants(), true);
  (void)init;
  // V-representation: the origin (a point) and the rays g_i; P = {0} + pos{g_i}.
  dd_MatrixPtr V = dd_CreateMatrix(static_cast<dd_rowrange>(g.size() + 1), 4);
  V->representation = dd_Generator;
  V->numbtype = dd_Rational;
  dd_set_si(V->matrix[0][0], 1);
  for (std::size_t i = 0; i < g.size(); ++i) {
    dd_set_si(V->matrix[i + 1][0], 0);
    for (int c = 0; c < 3; ++c) dd_set(V->matrix[i + 1][c + 1], g[i][c].get_mpq_t());
  }
  dd_ErrorType err = dd_NoError;
  dd_PolyhedraPtr P = dd_DDMatrix2Poly(V, &err);
  Verdict v = Verdict::failure;
  if (err == dd_NoError && P) {
    dd_MatrixPtr H = dd_CopyInequalities(P);  // rows b + a·x ≥ 0 (or = 0 for linearity rows)
    bool any = false;
    for (dd_rowrange r = 0; r < H->rowsize && !any; ++r)
      for (int c = 1; c < 4; ++c) any = any || mpq_sgn(H->matrix[r][c]) != 0;
    v = any ? Verdict::no_closure : Verdict::closure;
    dd_FreeMatrix(H);
  }
  if (P) dd_FreePolyhedra(P);
  dd_FreeMatrix(V);
  return v;
}

}  // namespace wrenchkit::peers
