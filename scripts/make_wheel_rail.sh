#!/usr/bin/env bash
# Writes the wheel/rail gap table of the benchmark (examples/bench/wheel-rail-profile.csv):
# a circular wheel of radius R = 0.46 m along x (rolling direction) on a worn-rail-like
# lateral profile along y, h(x, y) = x^2 / (2 R) + g(y), with the lateral gap
#   g(y) = y^2 / (2 * 0.5 m) - 2 y^3 + 1.2e4 y^4   (m; y in m)
# (a crown of 0.5 m flattened and tilted by wear: not a quadratic, so no Hertz contact).
# 41 points along x in [-8, 8] mm, 271 along y in [-8, 8] mm, as the CSV columns x,y,h (m).
#   scripts/make_wheel_rail.sh [output.csv]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
out="${1:-examples/bench/wheel-rail-profile.csv}"
LC_ALL=C awk 'BEGIN {
  R = 0.46; nx = 41; ny = 271; half = 0.008;
  print "x,y,h";
  for (j = 0; j < ny; ++j) {
    y = -half + 2 * half * j / (ny - 1);
    g = y * y / (2 * 0.5) - 2 * y * y * y + 1.2e4 * y * y * y * y;
    for (i = 0; i < nx; ++i) {
      x = -half + 2 * half * i / (nx - 1);
      printf "%.9e,%.9e,%.9e\n", x, y, x * x / (2 * R) + g;
    }
  }
}' > "$out"
echo "wrote $out"
