#pragma once
// The body as a VTK unstructured grid (.vtu, ASCII) for ParaView: quadratic tetrahedra with
// the nodal displacement, and per element the stress (Voigt, Pa) and its von Mises value.
#ifdef DYNCONTACT_WITH_FE
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "body_mesh.hpp"

namespace dc::output {

/// Von Mises equivalent stress of a Voigt stress (11, 22, 33, 23, 13, 12).
double von_mises(const Eigen::Matrix<double, 6, 1>& s);

/// Writes `path` whole; throws OutputError (output_files.hpp) when it cannot be written.
void write_body_vtu(const std::string& path, const fe::BodyMesh& mesh, const Eigen::VectorXd& displacement,
                    const std::vector<Eigen::Matrix<double, 6, 1>>& stress);

}  // namespace dc::output
#endif
