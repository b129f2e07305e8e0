// libFuzzer target: structured scenes built from the fuzzer's bytes, biased toward the degenerate
// and near-degenerate configurations where floating point goes wrong (theory.md §5.6, §8.5, §9):
// grid contacts (parallel, concurrent, coincident), two-finger grasps at Nguyen's threshold ± ε,
// normals concurrent up to ε, the ladder at μ* = 1/7 ± ε under gravity, pure wrench generators,
// everything scaled by 10^k, small supports (coincident, collinear points) under loads, and support regions
// (rectangles with holes, triangles, uniform and linear pressures, with a point) under loads. ε = ±10^-j with j up to 60. Every promise of fuzz/scene_checks.h must
// hold on every scene (float-vs-exact differential, engine → checker, round trip, labels vs closure).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz/scene_checks.h"

namespace {

struct Bytes {
  const std::uint8_t* p;
  std::size_t n;
  int next(int mod) {  // 0 … mod−1, 0 once the bytes run out
    if (n == 0) return 0;
    --n;
    return *p++ % mod;
  }
  int small(int lo, int hi) { return lo + next(hi - lo + 1); }
};

std::string pow10(int k) { return k >= 0 ? "1" + std::string(k, '0') : "1/1" + std::string(-k, '0'); }

std::string frac(long p, long q, Bytes& b) {
  const int j = b.small(1, 60), s = b.next(3) - 1;
  mpq_class v(p, q);
  v.canonicalize();
  if (s != 0) {
    mpz_class ten;
    mpz_ui_pow_ui(ten.get_mpz_t(), 10, static_cast<unsigned long>(j));
    v += mpq_class(s) / mpq_class(ten);
  }
  if (v < 0) v = -v;  // a friction coefficient or a coordinate that must stay ≥ 0
  return "\"" + v.get_str() + "\"";
}
std::string num(long p, long q = 1) {
  mpq_class v(p, q);
  v.canonicalize();
  return "\"" + v.get_str() + "\"";
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes b{data, size};
  const int family = b.next(8);
  std::string contacts, load;
  const auto point = [&](const std::string& x, const std::string& y, const std::string& nx, const std::string& ny,
                         const std::string& mu) {
    if (!contacts.empty()) contacts += ", ";
    contacts += "{\"at\": [" + x + ", " + y + "], \"normal\": [" + nx + ", " + ny + "], \"mu\": " + mu + "}";
  };
  const char* mus[] = {"0", "\"1/10\"", "\"1/4\"", "\"1/2\"", "1", "2"};
  switch (family) {
    case 0: {  // grid contacts: parallel, concurrent and coincident configurations are frequent
      const int n = b.small(1, 7);
      for (int i = 0; i < n; ++i) {
        int nx = b.small(-2, 2), ny = b.small(-2, 2);
        if (nx == 0 && ny == 0) ny = 1;
        point(num(b.small(-4, 4)), num(b.small(-4, 4)), num(nx), num(ny), mus[b.next(6)]);
      }
      break;
    }
    case 1: {  // two fingers facing along x, offset dy: closure iff |dy|/dx ≤ μ (Nguyen); μ at it ± ε
      const int dx = b.small(1, 9), dy = b.small(-9, 9);
      point("0", "0", "1", "0", frac(dy < 0 ? -dy : dy, dx, b));
      point(num(dx), num(dy), "-1", "0", frac(dy < 0 ? -dy : dy, dx, b));
      break;
    }
    case 2: {  // normals concurrent at G = (1, 1), one contact moved by ε
      point("1", "0", "0", "1", mus[b.next(2)]);
      point("0", frac(1, 1, b), "1", "0", mus[b.next(2)]);
      point("3", "3", "-1", "-1", mus[b.next(2)]);
      if (b.next(2)) point("2", "0", "0", "1", "0");
      break;
    }
    case 3: {  // the ladder (theory.md §9): equilibrium iff μ ≥ 1/7; μ = 1/7 ± ε
      const std::string mu = frac(1, 7, b);
      point("0", "0", "0", "1", mu);
      point("-4", "3", "1", "0", mu);
      load = ", \"body\": {\"com\": [\"-1/2\", \"7/2\"]}, \"load\": {\"gravity\": " + num(b.small(1, 5)) + "}";
      break;
    }
    case 4: {  // a grid scene scaled by 10^k
      const int k = b.small(-40, 40), n = b.small(2, 5);
      for (int i = 0; i < n; ++i) {
        const std::string s = pow10(k);
        mpq_class x(b.small(-3, 3)), y(b.small(-3, 3)), f(s);
        f.canonicalize();
        x *= f;
        y *= f;
        int nx = b.small(-1, 1), ny = b.small(-1, 1);
        if (nx == 0 && ny == 0) nx = 1;
        point("\"" + x.get_str() + "\"", "\"" + y.get_str() + "\"", num(nx), num(ny), mus[b.next(4)]);
      }
      break;
    }
    case 6: {  // a small support (coincident and collinear points frequent) under a load near its limit surface
      const int k = b.small(1, 4);
      std::string pts;
      for (int i = 0; i < k; ++i)
        pts += std::string(i ? ", " : "") + "{\"at\": [" + num(b.small(-2, 2)) + ", " + num(b.small(-2, 2)) +
               "], \"force\": " + num(b.small(0, 3) + (i == 0)) + "}";
      load = ", \"support\": {\"mu\": " + std::string(mus[1 + b.next(5)]) + ", \"points\": [" + pts +
             "]}, \"load\": {\"wrench\": [" + frac(b.small(0, 3), 2, b) + ", " + num(b.small(-3, 3)) + ", " +
             frac(b.small(0, 5), 3, b) + "]}";
      point("0", "0", "1", "0", "0");
      break;
    }
    case 7: {  // support regions [RG-1]: a rectangle or a triangle on a grid, maybe a hole, a uniform or linear
               // pressure, maybe a point; a load whose motion must come with a certificate the checker accepts
      const int x0 = b.small(-4, 2), y0 = b.small(-4, 2), w = b.small(1, 4), h = b.small(1, 4);
      std::string outline, holes;
      mpq_class cx, cy;  // the outline's centroid (the centre of a uniform pressure without a hole)
      if (b.next(2)) {
        cx = mpq_class(2 * x0 + w, 2), cy = mpq_class(2 * y0 + h, 2);
        outline = "[[" + num(x0) + ", " + num(y0) + "], [" + num(x0 + w) + ", " + num(y0) + "], [" + num(x0 + w) + ", " +
                  num(y0 + h) + "], [" + num(x0) + ", " + num(y0 + h) + "]]";
        if (w >= 2 && h >= 2 && b.next(2))  // a hole strictly inside, written either way round
          holes = b.next(2) ? ", \"holes\": [[[" + num(2 * x0 + 1, 2) + ", " + num(2 * y0 + 1, 2) + "], [" + num(2 * x0 + 3, 2) + ", " +
                                  num(2 * y0 + 1, 2) + "], [" + num(2 * x0 + 3, 2) + ", " + num(2 * y0 + 3, 2) + "]]]"
                            : ", \"holes\": [[[" + num(2 * x0 + 3, 2) + ", " + num(2 * y0 + 3, 2) + "], [" + num(2 * x0 + 3, 2) + ", " +
                                  num(2 * y0 + 1, 2) + "], [" + num(2 * x0 + 1, 2) + ", " + num(2 * y0 + 1, 2) + "]]]";
      } else {  // a triangle, either orientation; a flat one becomes a right triangle
        const int x1 = b.small(-4, 4), y1 = b.small(-4, 4), x2 = b.small(-4, 4), y2 = b.small(-4, 4);
        const bool flat = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0) == 0;
        cx = flat ? mpq_class(3 * x0 + w, 3) : mpq_class(x0 + x1 + x2, 3);
        cy = flat ? mpq_class(3 * y0 + h, 3) : mpq_class(y0 + y1 + y2, 3);
        outline = flat ? "[[" + num(x0) + ", " + num(y0) + "], [" + num(x0 + w) + ", " + num(y0) + "], [" + num(x0) + ", " +
                             num(y0 + h) + "]]"
                       : "[[" + num(x0) + ", " + num(y0) + "], [" + num(x1) + ", " + num(y1) + "], [" + num(x2) + ", " +
                             num(y2) + "]]";
      }
      const int gx = b.small(-2, 2), gy = b.small(-2, 2);
      const bool uniform = b.next(2), legs = uniform && holes.empty() && b.next(2);
      const int force = b.small(1, 4);
      const std::string pressure = uniform ? "\"pressure\": \"uniform\", \"force\": " + (legs ? num(force) : frac(force, 1, b))
                                           : "\"pressure\": {\"linear\": [" + num(12 * (std::abs(gx) + std::abs(gy)) + b.small(1, 3)) +
                                                 ", " + num(gx) + ", " + num(gy) + "]}";
      std::string pts;
      mpq_class weight = force, moment[2] = {force * cx, force * cy};  // with legs: W and W c
      if (b.next(2)) {
        const int px = b.small(-4, 4), py = b.small(-4, 4), f = b.small(0, 2);
        pts = "{\"at\": [" + num(px) + ", " + num(py) + "], \"force\": " + num(f) + "}";
        weight += f, moment[0] += f * px, moment[1] += f * py;
      }
      // [HD-2] Legs whose forces are not given (a uniform region without a hole: its moment is F times its
      // centroid): they carry R about a rational point q of their triangle, so F is not empty.
      std::string extra;
      if (legs) {
        static const int at[3][2] = {{-6, -6}, {6, -6}, {0, 6}};
        const int rest = b.small(1, 3), l[3] = {b.small(1, 3), b.small(1, 3), b.small(1, 3)};
        for (int i = 0; i < 3; ++i) {
          pts += std::string(pts.empty() ? "" : ", ") + "{\"at\": [" + num(at[i][0]) + ", " + num(at[i][1]) + "]}";
          moment[0] += mpq_class(rest * l[i] * at[i][0], l[0] + l[1] + l[2]);
          moment[1] += mpq_class(rest * l[i] * at[i][1], l[0] + l[1] + l[2]);
        }
        weight += rest;
        moment[0] /= weight, moment[1] /= weight;
        moment[0].canonicalize(), moment[1].canonicalize();
        extra = "\"weight\": \"" + weight.get_str() + "\", \"pressure_center\": [\"" + moment[0].get_str() + "\", \"" +
                moment[1].get_str() + "\"], ";
      }
      if (!pts.empty()) pts = extra + "\"points\": [" + pts + "], ";
      load = ", \"support\": {\"mu\": " + std::string(mus[1 + b.next(5)]) + ", " + pts + "\"regions\": [{\"outline\": " +
             outline + holes + ", " + pressure + "}]}, \"load\": {\"wrench\": [" + frac(b.small(0, 6), 2, b) + ", " +
             num(b.small(-3, 3)) + ", " + frac(b.small(0, 9), 3, b) + "]}";
      point("0", "0", "1", "0", "0");
      break;
    }
    default: {  // pure wrench generators, pure moments among them
      const int n = b.small(1, 6);
      for (int i = 0; i < n; ++i) {
        int fx = b.small(-2, 2), fy = b.small(-2, 2), m = b.small(-2, 2);
        if (fx == 0 && fy == 0 && m == 0) m = 1;
        if (!contacts.empty()) contacts += ", ";
        contacts += "{\"wrench\": [" + num(fx) + ", " + num(fy) + ", " + num(m) + "]}";
      }
      break;
    }
  }
  if (load.empty() && b.next(2))
    load = ", \"load\": {\"wrench\": [" + num(b.small(-3, 3)) + ", " + num(b.small(-3, 3)) + ", " +
           num(b.small(-3, 3)) + "]}";
  // [PU-1] A pusher on a support (families 6 and 7): grid points, normals and velocities, so that its lines pass
  // through the centre of friction often, and a velocity ε beside one of its cone's edges.
  if ((family == 6 || family == 7) && b.next(2)) {
    int nx = b.small(-2, 2), ny = b.small(-2, 2);
    if (nx == 0 && ny == 0) ny = 1;
    const std::string mu = mus[b.next(6)];
    int vx = b.small(-2, 2), vy = b.small(-2, 2);
    if (vx * nx + vy * ny <= 0) vx += 3 * nx, vy += 3 * ny;
    std::string vxs = num(vx);
    if (vx > 0 && b.next(2)) vxs = frac(vx, 1, b);  // near a tie: vx ± ε (v · n stays > 0: |ε nx| < 1)
    const int ax = b.small(-4, 4), ay = b.small(-4, 4);
    if (b.next(3) == 0) {  // [PU-3] a line pusher along rot90(n), translating or turning at a small rate
      const int t = 1 + b.small(0, 3);
      const std::string omega = b.next(2) ? "0" : frac(b.small(-3, 3), 1 + b.next(20), b);
      load += ", \"pusher\": {\"segment\": [[" + num(ax) + ", " + num(ay) + "], [" + num(ax - t * ny) + ", " +
              num(ay + t * nx) + "]], \"normal\": [" + num(nx) + ", " + num(ny) + "], \"mu\": " + mu +
              ", \"velocity\": [" + num(vx) + ", " + num(vy) + "], \"omega\": " + omega + "}";
    } else {
      load += ", \"pusher\": {\"at\": [" + num(ax) + ", " + num(ay) + "], \"normal\": [" + num(nx) + ", " +
              num(ny) + "], \"mu\": " + mu + ", \"velocity\": [" + vxs + ", " + num(vy) + "]}";
    }
  }
  const std::string text = "{\"wrenchkit\": 1, \"contacts\": [" + contacts + "]" + load + "}";
  if (!check_scene_text(text)) {
    std::cerr << "structured scene rejected:\n" << text << "\n";
    std::abort();
  }
  return 0;
}
