#include "vti_image.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace dc::output {
namespace {

void append_base64(std::string& out, const unsigned char* bytes, std::size_t size) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  for (std::size_t k = 0; k < size; k += 3) {
    const unsigned v = (unsigned{bytes[k]} << 16) | (k + 1 < size ? unsigned{bytes[k + 1]} << 8 : 0u) |
                       (k + 2 < size ? unsigned{bytes[k + 2]} : 0u);
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += k + 1 < size ? table[(v >> 6) & 63] : '=';
    out += k + 2 < size ? table[v & 63] : '=';
  }
}

}  // namespace

VtiImage::VtiImage(std::array<int, 3> points, std::array<double, 3> origin, std::array<double, 3> spacing)
    : points_(points) {
  char head[512];
  std::snprintf(head, sizeof head,
                "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                "<ImageData WholeExtent=\"0 %d 0 %d 0 %d\" Origin=\"%.9g %.9g %.9g\" Spacing=\"%.9g %.9g %.9g\">\n"
                "<Piece Extent=\"0 %d 0 %d 0 %d\">\n<PointData>\n",
                points[0] - 1, points[1] - 1, points[2] - 1, origin[0], origin[1], origin[2], spacing[0], spacing[1],
                spacing[2], points[0] - 1, points[1] - 1, points[2] - 1);
  head_ = head;
}

std::size_t VtiImage::size() const {
  return static_cast<std::size_t>(points_[0]) * static_cast<std::size_t>(points_[1]) *
         static_cast<std::size_t>(points_[2]);
}

void VtiImage::add(const std::string& name, int components, const std::vector<float>& values) {
  if (values.size() != size() * static_cast<std::size_t>(components))
    throw std::logic_error("VtiImage::add: " + name + " has " + std::to_string(values.size()) + " values, not " +
                           std::to_string(size() * static_cast<std::size_t>(components)));
  arrays_ += "<DataArray type=\"Float32\" Name=\"" + name + "\" NumberOfComponents=\"" + std::to_string(components) +
             "\" format=\"binary\">\n";
  const std::uint32_t bytes = static_cast<std::uint32_t>(values.size() * sizeof(float));
  unsigned char header[4];
  std::memcpy(header, &bytes, 4);
  append_base64(arrays_, header, 4);
  append_base64(arrays_, reinterpret_cast<const unsigned char*>(values.data()), bytes);
  arrays_ += "\n</DataArray>\n";
}

std::string VtiImage::text() const {
  return head_ + arrays_ + "</PointData>\n</Piece>\n</ImageData>\n</VTKFile>\n";
}

VtiImage surface_image(const Grid& g) {
  const bool three_d = g.dimension == 3;
  return VtiImage({g.nx, three_d ? g.ny : 1, 1}, {g.xc(0), three_d ? g.yc(0) : 0.0, 0.0},
                  {g.dx, three_d ? g.dy : g.dx, g.dx});
}

}  // namespace dc::output
