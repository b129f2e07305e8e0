#include "exact/statics/cone_lp.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <stdexcept>

#include "exact/numbers/wide_int.h"

namespace wrenchkit {

Cone_membership cone_membership(const std::vector<Vec3q>& gens, const Vec3q& x) {
  const std::size_t n = gens.size();
  const std::size_t cols = n + 3;  // originals, then artificials a_0 … a_2
  // Tableau rows r = 0 … 2: [A' | I | b'] with rows negated where x_r < 0 so that b' ≥ 0.
  std::array<std::vector<Rational>, 3> T;
  std::array<Rational, 3> b;
  std::array<int, 3> flip{};
  const Rational xs[3] = {x[0], x[1], x[2]};
  for (int r = 0; r < 3; ++r) {
    flip[r] = xs[r] < 0 ? -1 : 1;
    T[r].assign(cols, Rational(0));
    for (std::size_t j = 0; j < n; ++j) {
      const Rational& v = r == 0 ? gens[j][0] : (r == 1 ? gens[j][1] : gens[j][2]);
      T[r][j] = flip[r] < 0 ? Rational(-v) : v;
    }
    T[r][n + r] = 1;
    b[r] = flip[r] < 0 ? Rational(-xs[r]) : xs[r];
  }
  std::array<std::size_t, 3> basic = {n, n + 1, n + 2};
  // Reduced costs of the phase-1 objective Σ a_r: c̄_j = c_j − Σ_r T_rj over basic artificials.
  std::vector<Rational> cbar(cols, Rational(0));
  for (std::size_t j = 0; j < n; ++j) cbar[j] = -(T[0][j] + T[1][j] + T[2][j]);

  for (;;) {
    std::size_t enter = cols;
    for (std::size_t j = 0; j < cols; ++j)
      if (cbar[j] < 0) {
        enter = j;  // Bland: smallest index
        break;
      }
    if (enter == cols) break;
    int leave = -1;
    Rational best;
    for (int r = 0; r < 3; ++r) {
      if (T[r][enter] <= 0) continue;
      Rational ratio = b[r] / T[r][enter];
      if (leave < 0 || ratio < best || (ratio == best && basic[r] < basic[leave])) {
        leave = r;
        best = ratio;
      }
    }
    if (leave < 0) throw std::logic_error("cone_membership: unbounded phase 1 (impossible)");
    const Rational piv = T[leave][enter];
    for (std::size_t j = 0; j < cols; ++j) T[leave][j] /= piv;
    b[leave] /= piv;
    for (int r = 0; r < 3; ++r) {
      if (r == leave || T[r][enter] == 0) continue;
      const Rational f = T[r][enter];
      for (std::size_t j = 0; j < cols; ++j)
        if (T[leave][j] != 0) T[r][j] -= f * T[leave][j];
      b[r] -= f * b[leave];
    }
    const Rational f = cbar[enter];
    for (std::size_t j = 0; j < cols; ++j)
      if (T[leave][j] != 0) cbar[j] -= f * T[leave][j];
    basic[leave] = enter;
  }

  Cone_membership out;
  Rational infeasibility = 0;
  for (int r = 0; r < 3; ++r)
    if (basic[r] >= n) infeasibility += b[r];
  if (infeasibility == 0) {
    out.member = true;
    out.weights.assign(n, Rational(0));
    for (int r = 0; r < 3; ++r)
      if (basic[r] < n) out.weights[basic[r]] = b[r];
    return out;
  }
  // Simplex multipliers y_r = c_{a_r} − c̄_{a_r} = 1 − c̄_{n+r}; optimality gives y·A'_j ≤ 0 and
  // y·b' > 0, so z = −(flip ∘ y) has ⟨z, g_j⟩ ≥ 0 and ⟨z, x⟩ < 0.
  for (int r = 0; r < 3; ++r) {
    const Rational y = 1 - cbar[n + r];
    out.twist[r] = flip[r] < 0 ? y : Rational(-y);
  }
  return out;
}

}  // namespace wrenchkit

// ---- [FC-5] The same phase 1 in integers: the revised simplex in Cramer form ----------------------

namespace wrenchkit {
namespace {

using wide::i128;
using wide::Int192;
using wide::u128;

// Fixed width. Entries E: int64 (columns |x| ≤ 2^62 − 1, the target |x| ≤ 2^63 − 1); cross products
// of two columns C: __int128 (|·| ≤ 2^125; a sum of three < 2^127); products of a cross product with
// a column or the target D: Int192 (a sum of three < 3·2^189 and one more determinant < 2^189 stay
// below 2^191).
struct Fixed_width {
  using E = std::int64_t;
  using C = i128;
  using D = Int192;
  static C cross(E a1, E a2, E b1, E b2) { return wide::minor2(a1, a2, b1, b2); }
  static C add(C a, C b) { return a + b; }
  static D dot(const C y[3], const E m[3]) {
    return wide::add(wide::add(wide::mul(m[0], y[0]), wide::mul(m[1], y[1])), wide::mul(m[2], y[2]));
  }
  static D neg(const D& d) {
    D r;
    std::uint64_t carry = 1;
    for (int i = 0; i < 3; ++i) {
      r.w[i] = ~d.w[i] + carry;
      carry = carry && r.w[i] == 0;
    }
    return r;
  }
  static D widen(C c) {
    const u128 u = static_cast<u128>(c);
    D r;
    r.w[0] = static_cast<std::uint64_t>(u);
    r.w[1] = static_cast<std::uint64_t>(u >> 64);
    r.w[2] = c < 0 ? ~std::uint64_t(0) : 0;
    return r;
  }
  static D sub(const D& a, const D& b) { return wide::add(a, neg(b)); }
  static int sign(const D& d) { return wide::sign(d); }
  static int sign(C c) { return wide::sign(c); }
  static void magnitude(const D& d, mp_limb_t out[3]) {
    const D m = sign(d) < 0 ? neg(d) : d;
    for (int i = 0; i < 3; ++i) out[i] = static_cast<mp_limb_t>(m.w[i]);
  }
  // sign(a·b − c·d), in 384 bits (GMP's fixed-size mpn layer: no allocation).
  static int compare_products(const D& a, const D& b, const D& c, const D& d) {
    const int s1 = sign(a) * sign(b), s2 = sign(c) * sign(d);
    if (s1 != s2 || s1 == 0) return s1 > s2 ? 1 : (s1 < s2 ? -1 : 0);
    mp_limb_t x[3], y[3], p[6], q[6];
    magnitude(a, x), magnitude(b, y);
    mpn_mul_n(p, x, y, 3);
    magnitude(c, x), magnitude(d, y);
    mpn_mul_n(q, x, y, 3);
    const int m = mpn_cmp(p, q, 6);
    return s1 > 0 ? m : -m;
  }
  static Integer integer(const D& d) {
    mp_limb_t m[3];
    magnitude(d, m);
    Integer r;
    mpz_import(r.get_mpz_t(), 3, -1, sizeof(mp_limb_t), 0, 0, m);
    return sign(d) < 0 ? Integer(-r) : r;
  }
  static Integer integer(C c) { return integer(widen(c)); }
};

// GMP integers, for entries beyond fixed width: the same operations, unbounded.
struct Gmp_width {
  using E = Integer;
  using C = Integer;
  using D = Integer;
  static C cross(const E& a1, const E& a2, const E& b1, const E& b2) { return a1 * b2 - a2 * b1; }
  static C add(const C& a, const C& b) { return a + b; }
  static D dot(const C y[3], const E m[3]) { return y[0] * m[0] + y[1] * m[1] + y[2] * m[2]; }
  static D neg(const D& d) { return -d; }
  static D widen(const C& c) { return c; }
  static D sub(const D& a, const D& b) { return a - b; }
  static int sign(const Integer& x) { return sgn(x); }
  static int compare_products(const D& a, const D& b, const D& c, const D& d) {
    const Integer l = a * b, r = c * d;
    return cmp(l, r) < 0 ? -1 : (cmp(l, r) > 0 ? 1 : 0);
  }
  static Integer integer(const Integer& x) { return x; }
};

// [FC-5] Phase 1 of FC-4 on columns g_j (j < n) and artificial unit columns (n + r), with target x,
// as the revised simplex: the basis B (three columns) is the only state. With B's columns B_0, B_1,
// B_2, B⁻¹ has rows A_i / det B where A_i = B_{i+1} × B_{i+2} (indices mod 3) and det B = A_0 · B_0,
// so every tableau quantity of FC-4 is an integer over det B:
//   reduced cost  c̄_j = (c_j det B − Y · M_j) / det B,  Y = Σ_{i : B_i artificial} A_i  (c_B B⁻¹ = Y / det B)
//   column        T_ij = (A_i · M_j) / det B,           right-hand side  b̄_i = (A_i · b') / det B.
// Bland's rule decides on these signs and on the ratio comparison b̄_i / T_ie < b̄_k / T_ke ⇔
// (A_i·b')(A_k·M_e) < (A_k·b')(A_i·M_e) (both T > 0: the same sign as det B): the pivots of FC-4.
template <class P>
Integer_cone_membership phase1(const std::vector<std::array<typename P::E, 3>>& g, const std::array<typename P::E, 3>& x) {
  using E = typename P::E;
  using C = typename P::C;
  using D = typename P::D;
  const std::size_t n = g.size();
  int flip[3];
  E b[3];
  for (int r = 0; r < 3; ++r) {
    flip[r] = x[r] < 0 ? -1 : 1;
    b[r] = flip[r] < 0 ? E(-x[r]) : x[r];
  }
  // M_j = flip ∘ g_j, then the unit columns.
  std::vector<std::array<E, 3>> M(n + 3);
  for (std::size_t j = 0; j < n; ++j)
    for (int r = 0; r < 3; ++r) M[j][r] = flip[r] < 0 ? E(-g[j][r]) : g[j][r];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) M[n + r][c] = E(r == c ? 1 : 0);
  std::array<std::size_t, 3> basic = {n, n + 1, n + 2};
  C A[3][3], Y[3];
  D det;
  std::vector<char> is_basic(n + 3, 0);
  Integer_cone_membership out;
  for (;;) {
    for (int i = 0; i < 3; ++i) {
      const auto& u = M[basic[(i + 1) % 3]];
      const auto& v = M[basic[(i + 2) % 3]];
      A[i][0] = P::cross(u[1], u[2], v[1], v[2]);
      A[i][1] = P::cross(u[2], u[0], v[2], v[0]);
      A[i][2] = P::cross(u[0], u[1], v[0], v[1]);
    }
    det = P::dot(A[0], M[basic[0]].data());
    const int sdet = P::sign(det);
    if (sdet == 0) throw std::logic_error("cone_membership: singular basis (impossible)");
    for (int c = 0; c < 3; ++c) Y[c] = C(0);
    for (int i = 0; i < 3; ++i)
      if (basic[i] >= n)
        for (int c = 0; c < 3; ++c) Y[c] = P::add(Y[c], A[i][c]);
    std::fill(is_basic.begin(), is_basic.end(), 0);
    for (std::size_t j : basic) is_basic[j] = 1;
    std::size_t enter = n + 3;
    for (std::size_t j = 0; j < n + 3 && enter == n + 3; ++j) {  // Bland: the least index with c̄_j < 0
      if (is_basic[j]) continue;
      const D num = j >= n ? P::sub(det, P::widen(Y[j - n])) : P::neg(P::dot(Y, M[j].data()));
      if (P::sign(num) * sdet < 0) enter = j;
    }
    if (enter == n + 3) break;
    int leave = -1;
    D tau[3], beta[3];
    for (int i = 0; i < 3; ++i) {
      tau[i] = P::dot(A[i], M[enter].data());
      if (P::sign(tau[i]) * sdet <= 0) continue;
      beta[i] = P::dot(A[i], b);
      if (leave < 0) {
        leave = i;
        continue;
      }
      const int c = P::compare_products(beta[i], tau[leave], beta[leave], tau[i]);
      if (c < 0 || (c == 0 && basic[i] < basic[static_cast<std::size_t>(leave)])) leave = i;
    }
    if (leave < 0) throw std::logic_error("cone_membership: unbounded phase 1 (impossible)");
    basic[static_cast<std::size_t>(leave)] = enter;
    ++out.pivots;
  }
  const int sdet = P::sign(det);
  out.member = true;
  D beta[3];
  for (int i = 0; i < 3; ++i) {
    beta[i] = P::dot(A[i], b);
    if (basic[i] >= n && P::sign(beta[i]) != 0) out.member = false;  // b̄_i ≥ 0: the sum is 0 iff each is
  }
  if (out.member) {
    out.numerators.assign(n, Integer(0));
    for (int i = 0; i < 3; ++i)
      if (basic[i] < n) out.numerators[basic[i]] = sdet > 0 ? P::integer(beta[i]) : Integer(-P::integer(beta[i]));
    out.denominator = P::integer(det);
    if (sdet < 0) out.denominator = -out.denominator;
    return out;
  }
  // Optimal with value > 0: y = c_B B⁻¹ = Y / det B; z = −(flip ∘ y), scaled by |det B| > 0.
  std::array<Integer, 3> z;
  for (std::size_t r = 0; r < 3; ++r) {
    z[r] = P::integer(Y[r]);
    if ((flip[r] > 0) == (sdet > 0)) z[r] = -z[r];
  }
  out.twist = primitive(std::move(z));  // ≠ 0 (a Farkas twist); zero would be a logic_error
  return out;
}

}  // namespace

Integer_cone_membership cone_membership(const Exact_kernel& k, const std::vector<std::size_t>& columns,
                                        const std::vector<std::size_t>& negated, bool fixed_width) {
  std::vector<std::array<std::int64_t, 3>> g(columns.size());
  bool fixed = fixed_width;
  for (std::size_t j = 0; j < columns.size() && fixed; ++j) fixed = k.small_row(columns[j], g[j].data());
  i128 x[3] = {0, 0, 0};
  for (std::size_t t = 0; t < negated.size() && fixed; ++t) {
    std::int64_t s[3] = {0, 0, 0};
    fixed = k.small_row(negated[t], s);
    for (int r = 0; r < 3; ++r) x[r] -= s[r];
  }
  const i128 max63 = static_cast<i128>(INT64_MAX);
  for (int r = 0; r < 3 && fixed; ++r) fixed = x[r] <= max63 && x[r] >= -max63;
  if (fixed) {
    Integer_cone_membership m =
        phase1<Fixed_width>(g, {static_cast<std::int64_t>(x[0]), static_cast<std::int64_t>(x[1]), static_cast<std::int64_t>(x[2])});
    m.fixed_width = true;
    return m;
  }
  std::vector<std::array<Integer, 3>> G;
  G.reserve(columns.size());
  for (std::size_t c : columns) G.push_back(k.row(c));
  std::array<Integer, 3> X = {Integer(0), Integer(0), Integer(0)};
  for (std::size_t t : negated) {
    const std::array<Integer, 3> s = k.row(t);
    for (int r = 0; r < 3; ++r) X[r] -= s[r];
  }
  return phase1<Gmp_width>(G, X);
}

bool four_spanning_weights(const Exact_kernel& k, const std::size_t (&rows)[4], std::array<Integer, 4>& lambda) {
  std::int64_t r[4][3];
  for (int i = 0; i < 4; ++i)
    if (!k.small_row(rows[i], r[i])) return false;
  Int192 d[4];
  for (int i = 0; i < 4; ++i) {  // λ_i = (−1)^i det of the other three rows, each < 2^189
    const std::int64_t* m[3];
    for (int j = 0, t = 0; j < 4; ++j)
      if (j != i) m[t++] = r[j];
    const Int192 det = wide::det3(m[0], m[1], m[2]);
    d[i] = i % 2 ? Fixed_width::neg(det) : det;
  }
  const int s = Fixed_width::sign(d[0]);
  for (const Int192& x : d)
    if (Fixed_width::sign(x) != s || s == 0) return false;  // not positively spanning
  for (int i = 0; i < 4; ++i) lambda[static_cast<std::size_t>(i)] = Fixed_width::integer(s > 0 ? d[i] : Fixed_width::neg(d[i]));
  return true;
}

}  // namespace wrenchkit
