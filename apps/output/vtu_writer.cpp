#ifdef DYNCONTACT_WITH_FE
#include "vtu_writer.hpp"

#include <cmath>
#include <sstream>

#include "output_files.hpp"

namespace dc::output {

double von_mises(const Eigen::Matrix<double, 6, 1>& s) {
  const double d = (s(0) - s(1)) * (s(0) - s(1)) + (s(1) - s(2)) * (s(1) - s(2)) + (s(2) - s(0)) * (s(2) - s(0));
  return std::sqrt(0.5 * d + 3.0 * (s(3) * s(3) + s(4) * s(4) + s(5) * s(5)));
}

void write_body_vtu(const std::string& path, const fe::BodyMesh& mesh, const Eigen::VectorXd& displacement,
                    const std::vector<Eigen::Matrix<double, 6, 1>>& stress) {
  std::ostringstream out;  // written whole at the end (output_files.hpp)
  out.precision(10);
  const std::size_t np = mesh.nodes.size(), nc = mesh.elements.size();
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << np << "\" NumberOfCells=\"" << nc << "\">\n";
  out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& x : mesh.nodes) out << x.x() << ' ' << x.y() << ' ' << x.z() << '\n';
  out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  // VTK_QUADRATIC_TETRA (24) orders the mid-edge nodes (0,1), (1,2), (2,0), (0,3), (1,3), (2,3): ours.
  for (const auto& e : mesh.elements) {
    for (int i = 0; i < 10; ++i) out << e[i] << (i == 9 ? '\n' : ' ');
  }
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t k = 1; k <= nc; ++k) out << 10 * k << '\n';
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < nc; ++k) out << "24\n";
  out << "</DataArray>\n</Cells>\n<PointData Vectors=\"displacement\">\n"
      << "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < np; ++k)
    out << displacement(3 * k) << ' ' << displacement(3 * k + 1) << ' ' << displacement(3 * k + 2) << '\n';
  out << "</DataArray>\n</PointData>\n<CellData Scalars=\"von_mises\">\n"
      << "<DataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"6\" format=\"ascii\">\n";
  for (const auto& s : stress) out << s(0) << ' ' << s(1) << ' ' << s(2) << ' ' << s(3) << ' ' << s(4) << ' ' << s(5) << '\n';
  out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"von_mises\" format=\"ascii\">\n";
  for (const auto& s : stress) out << von_mises(s) << '\n';
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"region\" format=\"ascii\">\n";
  for (int r : mesh.region) out << r << '\n';
  out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  write_file_whole(path, out.str());
}

}  // namespace dc::output
#endif
