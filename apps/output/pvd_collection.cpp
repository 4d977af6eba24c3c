#include "pvd_collection.hpp"

#include <sstream>

#include "output_files.hpp"

namespace dc::output {

void write_pvd(const std::string& path, const std::vector<PvdEntry>& entries) {
  std::ostringstream out;
  out.precision(12);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<Collection>\n";
  for (const PvdEntry& e : entries)
    out << "<DataSet timestep=\"" << e.time << "\" group=\"\" part=\"0\" file=\"" << e.file << "\"/>\n";
  out << "</Collection>\n</VTKFile>\n";
  write_file_whole(path, out.str());
}

}  // namespace dc::output
