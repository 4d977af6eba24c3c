#pragma once
// Closed-form solutions used to size grids and to validate the solvers (docs: VALIDATION).
namespace dc::hertz {

/// Sphere (h = r^2/(2R)) pressed by P: contact radius, approach, peak pressure.
struct SphereSolution { double a, approach, p0; };
SphereSolution sphere(double R, double P, double E_star);

/// Elliptic Hertz contact, h = A x^2 + B y^2 (Johnson, Contact Mechanics, 4.2):
/// semi-axes a (along x) and b (along y), approach and peak pressure; A = B gives the sphere.
struct EllipticSolution { double a, b, approach, p0; };
EllipticSolution elliptic(double A, double B, double P, double E_star);

/// 2-D cylinder, h = x^2/(2R), force per unit length P: half-width and peak pressure.
struct CylinderSolution { double a, p0; };
CylinderSolution cylinder2d(double R, double P, double E_star);

/// Elastic impact of a sphere (radius R, mass m) at normal speed v (Johnson, Contact Mechanics,
/// 11.4): deepest approach (15 m v^2 / (16 E* sqrt R))^(2/5), peak force 4/3 E* sqrt(R)
/// approach^(3/2), contact time (4/5) B(2/5, 1/2) approach / v = 2.9432752 approach / v.
struct ImpactSolution { double approach, force, duration; };
ImpactSolution sphere_impact(double R, double m, double v, double E_star);

/// Rigid flat circular punch of radius a on an elastic half-space (Boussinesq):
/// force for approach d, P = 2 a E* d, and the pressure p(r) = P / (2 pi a sqrt(a^2 - r^2)).
double flat_punch_force(double a, double approach, double E_star);
double flat_punch_pressure(double a, double P, double r);

/// Complete elliptic integrals K(m) and E(m) with parameter m = e^2 (AGM, round-off accurate).
double ellipk(double m);
double ellipe(double m);

}  // namespace dc::hertz
