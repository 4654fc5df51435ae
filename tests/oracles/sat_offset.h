// The reference SAT's stored representation (reference/sat.comp) turned back into the plain
// summed-area table, in double (test-only code; the math is in docs/numerics.md).
//
// reference/sat.comp's table is 2W × H texels for a W × H map: entry (x, y) of the summed-area
// table is the float at (2x, y) plus the float at (2x + 1, y) (the nearest float to the sum,
// then the nearest float to the rest).
#pragma once

#include <cstddef>
#include <vector>

namespace sl::oracle {

// `t`: the table's RGBA texels (2w × h), bottom row first; returns w × h RGBA sums.
inline std::vector<double> plainSatFromOffsetTable(const std::vector<float>& t, int w, int h) {
  std::vector<double> sat(std::size_t(w) * h * 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) {
        const std::size_t hi = (std::size_t(y) * 2 * w + 2 * x) * 4 + c;
        sat[(std::size_t(y) * w + x) * 4 + c] = double(t[hi]) + double(t[hi + 4]);
      }
  return sat;
}

}  // namespace sl::oracle
