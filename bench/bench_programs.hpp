// Programs for the benchmarks, made in memory (same shapes as the peer kit's
// gen_motion.py and gen_expr.py: lines, arcs, rapids, parameters in words;
// parameter arithmetic with nested brackets and functions).
#pragma once

#include <cstdio>
#include <random>
#include <string>

namespace skipnc::bench {

inline std::string motion_program(int blocks, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-100000, 100000);
  std::string s = "G17 G21 G90 G94\nF1000.\n#5=1.5\n";
  char buf[128];
  for (int i = 0; i < blocks; ++i) {
    const double x = coord(rng) / 1000.0, y = coord(rng) / 1000.0;
    switch (i % 4) {
      case 0:
        std::snprintf(buf, sizeof buf, "G1 X%.3f Y%.3f\n", x, y);
        break;
      case 1:
        std::snprintf(buf, sizeof buf, "G0 X%.3f Y%.3f\n", x, y);
        break;
      case 2:
        std::snprintf(buf, sizeof buf, "G1 X[#5+%.3f] Y%.3f\n", x, y);
        break;
      default:
        std::snprintf(buf, sizeof buf, "G91 G1 X1. Y-1.\nG90\n");
        ++i;
        break;
    }
    s += buf;
  }
  s += "M30\n";
  return s;
}

inline std::string expr_program(int blocks) {
  std::string s = "G17 G21 G90 G94\nF1000.\n";
  for (int p = 1; p <= 33; ++p) s += "#" + std::to_string(p) + "=" + std::to_string(p) + ".5\n";
  char buf[160];
  for (int i = 0; i < blocks; ++i) {
    const int a = 1 + i % 33, b = 1 + (i * 7) % 33, c = 1 + (i * 13) % 33;
    switch (i % 4) {
      case 0:
        std::snprintf(buf, sizeof buf, "#%d=[[#%d*0.9]+SIN[#%d]]\n", a, a, b);
        break;
      case 1:
        std::snprintf(buf, sizeof buf, "#%d=SQRT[ABS[#%d]]+[#%d/[1.+ABS[#%d]]]\n", a, b, c, a);
        break;
      case 2:
        std::snprintf(buf, sizeof buf, "#%d=COS[#%d]*[#%d*0.5]\n", a, c, b);
        break;
      default:
        std::snprintf(buf, sizeof buf, "G1 X[#%d*0.25] Y[#%d*0.25]\n", b, c);
        break;
    }
    s += buf;
  }
  s += "M30\n";
  return s;
}

}  // namespace skipnc::bench
