#pragma once
// VTK XML image data (.vti): a regular grid of points with named point arrays, inline binary
// (base64 of a UInt32 byte count, then the little-endian Float32 values), as ParaView and VTK's
// vtkXMLImageDataReader read it. Shared by subsurface.vti and fields.vti.
#include <array>
#include <string>
#include <vector>

#include "grid.hpp"

namespace dc::output {

class VtiImage {
 public:
  /// `points` along x, y, z (each >= 1), the first point's position and the spacing (m).
  VtiImage(std::array<int, 3> points, std::array<double, 3> origin, std::array<double, 3> spacing);
  std::size_t size() const;  ///< points in all
  /// Adds a point array of `components` values per point, x fastest, then y, then z.
  void add(const std::string& name, int components, const std::vector<float>& values);
  /// The file's text.
  std::string text() const;

 private:
  std::array<int, 3> points_;
  std::string head_, arrays_;
};

/// The image of a surface grid: one point per element centre, one layer (2-D: one row), the
/// spacing the element size (fields.vti, wear_<k>.vti).
VtiImage surface_image(const Grid& grid);

}  // namespace dc::output
