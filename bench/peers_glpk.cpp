// GLPK's exact simplex (bench/peers.h).
#include <glpk.h>

#include <vector>

#include "bench/peers.h"

namespace wrenchkit::peers {

Verdict glpk_exact(const std::vector<Wrench_d>& g) {
  static const bool quiet = (glp_term_out(GLP_OFF), true);
  (void)quiet;
  // Block k (k = 0..3): Σ_i λ_ki g_i = d_k, λ ≥ 0, with d = e1, e2, e3, −(1, 1, 1).
  static const double d[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, -1, -1}};
  const int n = static_cast<int>(g.size());
  glp_prob* lp = glp_create_prob();
  glp_add_rows(lp, 12);
  glp_add_cols(lp, 4 * n);
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c) glp_set_row_bnds(lp, 3 * k + c + 1, GLP_FX, d[k][c], d[k][c]);
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0};
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < n; ++i) {
      const int col = k * n + i + 1;
      glp_set_col_bnds(lp, col, GLP_LO, 0, 0);
      for (int c = 0; c < 3; ++c)
        if (g[i][c] != 0) {
          ia.push_back(3 * k + c + 1);
          ja.push_back(col);
          ar.push_back(g[i][c]);
        }
    }
  glp_load_matrix(lp, static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());
  glp_std_basis(lp);
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  Verdict v = Verdict::failure;
  if (glp_exact(lp, &parm) == 0) {
    const int status = glp_get_status(lp);
    if (status == GLP_OPT || status == GLP_FEAS) v = Verdict::closure;
    if (status == GLP_NOFEAS) v = Verdict::no_closure;
  }
  glp_delete_prob(lp);
  return v;
}

}  // namespace wrenchkit::peers
