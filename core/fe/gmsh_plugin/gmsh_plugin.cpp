// The Gmsh plugin (libdyncontact_gmsh): builds or reads the body's geometry and mesh through
// Gmsh's C++ API and hands back its vertices and tetrahedra. It is a module of its own, loaded
// by gmsh_mesher.cpp the first time a body is meshed, so that runs which never mesh a body do
// not pay Gmsh's start-up (OpenCASCADE, FLTK: about 0.2 s per process).
#include <csignal>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <mutex>
#include <string>

#include <gmsh.h>

#include "gmsh_tetrahedra.hpp"

namespace dc::fe {

namespace {

std::mutex& gmsh_mutex() {  // Gmsh keeps one global model
  static std::mutex m;
  return m;
}

/// The program's signal handlers, kept across Gmsh's start and end: Gmsh installs its own (for
/// SIGINT and SIGTERM among others), which would swallow an interrupt of the program's for the
/// rest of the run.
class SignalHandlersKept {
 public:
  SignalHandlersKept() {
    for (int s = 1; s < kSignals; ++s) sigaction(s, nullptr, &saved_[s]);
  }
  void restore() const {
    for (int s = 1; s < kSignals; ++s)
      if (s != SIGKILL && s != SIGSTOP) sigaction(s, &saved_[s], nullptr);
  }

 private:
  static constexpr int kSignals = 32;
  struct sigaction saved_[kSignals] {};
};

/// Initialises Gmsh quietly for one mesh and finalises it on every path.
struct GmshSession {
  GmshSession() {
    gmsh::initialize();
    handlers_.restore();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
  }
  ~GmshSession() {
    gmsh::finalize();
    handlers_.restore();
  }
  SignalHandlersKept handlers_;
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

void build_geometry(const FeBodySpec& s) {
  switch (s.shape) {
    case FeShape::block:
      gmsh::model::occ::addBox(-0.5 * s.size[0], -0.5 * s.size[1], 0.0, s.size[0], s.size[1], s.size[2]);
      break;
    case FeShape::cylinder:
      gmsh::model::occ::addCylinder(0.0, 0.0, 0.0, 0.0, 0.0, s.height, s.radius);
      break;
    case FeShape::hemisphere:  // the lower half of the sphere centred at (0, 0, R)
      gmsh::model::occ::addSphere(0.0, 0.0, s.radius, s.radius, -1, -M_PI / 2.0, 0.0, 2.0 * M_PI);
      break;
    case FeShape::mesh:
      break;
  }
  gmsh::model::occ::synchronize();
}

/// Element size fe_contact_element_size over the disk of `refine_radius` about the lowest point
/// (where the contact grid lies: the face resolves the grid's fields there), growing from it at
/// kFaceSizeGrowth per unit distance up to the coarse size (core/fe_body_spec.hpp).

/// A length for Gmsh's expression in full precision (std::to_string keeps six decimals: 0 for a
/// micrometre body).
std::string expression_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void set_size_field(const FeBodySpec& s) {
  const double h = fe_coarse_size(s), h0 = fe_contact_element_size(s);
  const double r0 = s.refine_radius.value_or(0.0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", h);
  gmsh::option::setNumber("Mesh.MeshSizeMin", h0);
  const int field = gmsh::model::mesh::field::add("MathEval");
  // The distance from the disk r <= r0 in the plane z = 0 of the lowest point.
  const std::string distance = "Sqrt(Max(0, Sqrt(x*x + y*y) - " + expression_number(r0) + ")^2 + z*z)";
  const std::string expr = "Min(" + expression_number(h) + ", " + expression_number(h0) + " + " +
                           expression_number(kFaceSizeGrowth) + " * " + distance + ")";
  gmsh::model::mesh::field::setString(field, "F", expr);
  gmsh::model::mesh::field::setAsBackgroundMesh(field);
}

/// Vertices and linear tetrahedra of the current model (first-order and second-order
/// tetrahedra both accepted: only their corners are used).
void read_tetrahedra(std::vector<Eigen::Vector3d>& vertices, std::vector<std::array<int, 4>>& tets,
                     std::vector<std::array<Eigen::Vector3d, 6>>& curved) {
  std::vector<std::size_t> tags;
  std::vector<double> coord, param;
  gmsh::model::mesh::getNodes(tags, coord, param);
  std::size_t max_tag = 0;
  for (std::size_t t : tags) max_tag = std::max(max_tag, t);
  std::vector<int> index(max_tag + 1, -1);
  vertices.resize(tags.size());
  for (std::size_t i = 0; i < tags.size(); ++i) {
    index[tags[i]] = static_cast<int>(i);
    vertices[i] = Eigen::Vector3d(coord[3 * i], coord[3 * i + 1], coord[3 * i + 2]);
  }
  for (int type : {4, 11}) {  // 4-node and 10-node tetrahedra
    std::vector<std::size_t> elem_tags, node_tags;
    gmsh::model::mesh::getElementsByType(type, elem_tags, node_tags);
    const std::size_t per = type == 4 ? 4 : 10;
    for (std::size_t e = 0; e < elem_tags.size(); ++e) {
      std::array<int, 4> t{};
      for (int k = 0; k < 4; ++k) {
        const std::size_t tag = node_tags[e * per + k];
        t[k] = tag <= max_tag ? index[tag] : -1;
      }
      tets.push_back(t);
      if (type == 11) {
        std::array<Eigen::Vector3d, 6> mids;
        for (int k = 0; k < 6; ++k) {
          const std::size_t tag = node_tags[e * per + 4 + k];
          const int i = tag <= max_tag ? index[tag] : -1;
          mids[k] = i >= 0 ? vertices[i] : Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
        }
        curved.push_back(mids);
      }
    }
  }
  // Curved mid-edge points only when every tetrahedron has them.
  if (curved.size() != tets.size()) curved.clear();
}

}  // namespace

}  // namespace dc::fe

/// The plugin's entry point (gmsh_tetrahedra.hpp): the tetrahedra of `spec`'s generated shape or
/// mesh file; false with Gmsh's message in `error` when Gmsh cannot build or read it.
extern "C" bool dyncontact_gmsh_tetrahedra(const dc::FeBodySpec& spec, dc::fe::GmshTetrahedra& out,
                                           std::string& error) {
  using namespace dc::fe;
  const std::lock_guard<std::mutex> lock(gmsh_mutex());
  try {
    GmshSession session;
    if (spec.shape == dc::FeShape::mesh) {
      gmsh::open(spec.mesh_file);
    } else {
      gmsh::model::add("body");
      build_geometry(spec);
      set_size_field(spec);
      gmsh::model::mesh::generate(3);
      gmsh::model::mesh::setOrder(2);  // mid-edge nodes on the true geometry (the contact face)
    }
    read_tetrahedra(out.vertices, out.tets, out.curved);
    return true;
  } catch (const std::exception& e) {
    error = e.what();
  } catch (...) {
    error = "unknown error";
  }
  return false;
}
