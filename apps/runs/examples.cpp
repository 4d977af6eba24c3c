// Bundled example cases: names and one-line summaries here; the texts are the files in
// examples/, embedded at build time (apps/CMakeLists.txt), so they cannot drift apart.
#include "examples.hpp"

#include <stdexcept>
#include <string>

namespace dc::runs {

const char* embedded_example_text(const std::string& name);  // generated: example_texts.cpp

const std::vector<BundledExample>& bundled_examples() {
  static const std::vector<BundledExample> examples = [] {
    std::vector<BundledExample> list = {
        {"hertz-sphere", "steel sphere on steel, 100 N: Hertz (3-D, force control)"},
        {"hertz-cylinder-2d", "steel cylinder on steel, plane strain, 100 kN/m: 2-D Hertz"},
        {"flat-punch", "rigid flat punch on aluminium, approach 1 um: Boussinesq (approach control)"},
        {"hertz-ellipse", "steel ellipsoid Rx = 10 mm, Ry = 40 mm on steel: elliptic Hertz"},
        {"bearing-accuracy", "a ball-bearing contact asked for 1e-3 instead of a grid: the grid is chosen (3-D, accuracy target)"},
        {"bearing-subsurface", "a ball on a bearing race, 1.5 kN: von Mises field to subsurface.vti, first yield (3-D, subsurface)"},
        {"cattaneo-sphere", "Cattaneo-Mindlin: steel sphere, 100 N, tangential force 0.5 mu P (3-D, shift)"},
        {"fretting-wear", "Mindlin-Deresiewicz fretting: steel sphere at +-0.5 mu P for 1e5 cycles, Archard wear: the ring scar (3-D, wear)"},
        {"torsion-sphere", "Lubkin: steel sphere, 100 N, twisting moment half the full-slip value (3-D, torsion)"},
        {"carter-2d", "Carter: steel cylinder rolling on steel, 100 kN/m, force 0.5 mu P (2-D, rolling)"},
        {"rail-shakedown", "a wheel rolling on a rail with traction 0.2 P: shakedown map point, Dang Van, first yield (2-D, subsurface)"},
        {"rolling-sphere", "steady rolling of a steel sphere, 100 N, creepage 1e-3 (3-D, rolling)"},
        {"spence-sphere", "Spence: rigid sphere pressed into aluminium in 3 load steps, mu = 0.2 (3-D, history)"},
        {"cattaneo-carter-2d", "Cattaneo to Carter: a cylinder under 0.5 mu P starts rolling, 5 steps (2-D, rolling history)"},
        {"paper-cylinder", "the paper's Section 5: cylinder under a growing driving moment, sweep of its rate (Figs 4-6)"},
        {"paper-cylinder-si", "the paper's Section 5 cylinder in SI units: steel, R = 0.5 m, 10 m/s, until it slides"},
        {"bowling-ball", "a bowling ball launched sliding at 3 m/s: rolls after 2v0/(7 mu g) at 5/7 v0 (3-D, dynamic)"},
        {"paper-fig5", "the paper's Fig. 5: the Section 5 cylinder for three initial moments M0_bar"},
        {"paper-fig6", "the paper's Fig. 6: the Section 5 cylinder for a ring, a solid cylinder and eta = inf"},
        {"wheel-drive", "a 3-D wheel under a growing driving moment: rolls, then slides at F = mu P (Section 5 in 3-D)"},
        {"wheel-wear", "the wheel of wheel-drive with Archard wear and the flash temperature: the track worn along x, the wheel round its circumference (3-D, dynamic, wear)"},
        {"cylinder-dynamic-2d", "the paper's Section 5 cylinder through the general dynamic solver, until it slides (2-D)"},
        {"ball-impact", "a steel ball dropped at 1 m/s on steel: Hertz impact, 69 us, 1.74 kN, rebound (3-D, dynamic)"},
        {"ball-impact-adaptive", "the same ball released 50 um above, adaptive time steps: flight, touch, contact, release (3-D, dynamic)"},
        {"ball-impact-speeds", "the same ball dropped at 0.5, 1 and 2 m/s: a sweep of three impacts (3-D, dynamic)"},
        {"finite-hemisphere", "FE steel hemisphere (R = 10 mm) on steel, 3.3 kN: Hertz for the pair (finite)"},
        {"finite-torsion", "FE steel hemisphere on steel, 100 N, twisting moment, mu = 0.3 (finite, torsion)"},
        {"fe-hemisphere-drop", "FE steel hemisphere dropped at 1 m/s on steel: Hertz impact of the pair, body_*.vtu (dynamic)"},
    };
    for (auto& e : list) {
      e.text = embedded_example_text(e.name);
      if (e.text == nullptr) throw std::logic_error(std::string("example file missing: ") + e.name);
    }
    return list;
  }();
  return examples;
}

const BundledExample* find_example(const std::string& name) {
  for (const auto& e : bundled_examples())
    if (name == e.name) return &e;
  return nullptr;
}

}  // namespace dc::runs
