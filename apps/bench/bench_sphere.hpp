#pragma once
// The benchmarks' Hertz sphere: steel (E = 210 GPa, nu = 0.3) on steel, R = 10 mm, 100 N, on
// a grid of +-kExtent x Hertz's contact radius (dyncontact_bench, dyncontact_subsurface_bench).
#include "grid.hpp"
#include "hertz.hpp"
#include "material.hpp"
#include "normal_spec.hpp"
#include "profile.hpp"

namespace dc::bench {

constexpr double kE = 2.1e11, kNu = 0.3, kRadius = 0.01, kForce = 100.0, kExtent = 1.3;

inline MaterialPair steel_on_steel() {
  MaterialPair m;
  m.body = Elastic::from_E_nu(kE, kNu, "materials.body");
  m.base = Elastic::from_E_nu(kE, kNu, "materials.base");
  return m;
}

struct BenchSphere {
  MaterialPair materials = steel_on_steel();
  hertz::SphereSolution hertz = hertz::sphere(kRadius, kForce, materials.E_star());
  ProfileSpec profile{};
  NormalSpec normal{Control::force, kForce};

  BenchSphere() {
    profile.type = ProfileType::sphere;
    profile.radius = kRadius;
  }
  /// n x n elements over +-extent x the contact radius.
  Grid grid(int n, double extent = kExtent) const {
    const double half = extent * hertz.a;
    return Grid::make(3, n, n, -half, half, -half, half);
  }
};

}  // namespace dc::bench
