// The reference SAT's stored representation (reference/sat.comp) turned back into the plain
// summed-area table, in double (test-only code; the math is in docs/numerics.md).
//
// reference/sat.comp stores independent kReferenceSatTile² tiles. In local coordinates of a
// tile, with a = m(0,0) of the tile:
//   T(0,0) = a;  T(x,0) = A(x) = Σ_{1<=i<=x} (m(i,0) - a);  T(0,y) = B(y) likewise;
//   T(x,y) = Σ_{1<=i<=x, 1<=j<=y} (m(i,j) - m(0,j) - m(i,0) + a)   for x, y >= 1,
// and the tile's own SAT is S(x,y) = T°(x,y) + (y+1)·A(x) + (x+1)·B(y) + (x+1)·(y+1)·a, where
// T° is T with its first row and column read as 0 (A(0) = B(0) = 0). This rebuilds each
// tile's moments from its S, then the plain table of the whole map from those.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace sl::oracle {

constexpr int kReferenceSatTile = 32;  // SAT_TILE in reference/sat.comp and sat_lookup.glsl

inline std::vector<double> plainSatFromOffsetTable(const std::vector<float>& t, int w, int h) {
  const int K = kReferenceSatTile;
  auto idx = [&](int x, int y, int c) { return (std::size_t(y) * w + x) * 4 + c; };
  std::vector<double> m(t.size());
  for (int y0 = 0; y0 < h; y0 += K)
    for (int x0 = 0; x0 < w; x0 += K) {
      const int tw = std::min(K, w - x0), th = std::min(K, h - y0);
      for (int c = 0; c < 4; ++c) {
        auto T = [&](int x, int y) { return double(t[idx(x0 + x, y0 + y, c)]); };
        const double a = T(0, 0);
        auto S = [&](int x, int y) {  // the tile's own SAT, S(-1, ·) = S(·, -1) = 0
          if (x < 0 || y < 0) return 0.0;
          const double interior = (x > 0 && y > 0) ? T(x, y) : 0.0;
          const double A = x > 0 ? T(x, 0) : 0.0, B = y > 0 ? T(0, y) : 0.0;
          return interior + (y + 1.0) * A + (x + 1.0) * B + (x + 1.0) * (y + 1.0) * a;
        };
        for (int y = 0; y < th; ++y)
          for (int x = 0; x < tw; ++x)
            m[idx(x0 + x, y0 + y, c)] = S(x, y) - S(x - 1, y) - S(x, y - 1) + S(x - 1, y - 1);
      }
    }
  std::vector<double> sat(t.size());
  for (int y = 0; y < h; ++y)
    for (int c = 0; c < 4; ++c) {
      double row = 0.0;
      for (int x = 0; x < w; ++x) {
        row += m[idx(x, y, c)];
        sat[idx(x, y, c)] = row + (y > 0 ? sat[idx(x, y - 1, c)] : 0.0);
      }
    }
  return sat;
}

}  // namespace sl::oracle
