// The case model: parsing the bundled examples, validation (every bad input names its key),
// --set overrides, extent grids sized by Hertz, profile heights, table profiles.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>

#include "case_model.hpp"
#include "errors.hpp"
#include "hertz.hpp"
#include "profile.hpp"

namespace dc {
namespace {

using json = nlohmann::json;

const std::string kExamples = std::string(DYNCONTACT_SOURCE_DIR) + "/examples/";

json sphere_case() {
  return json::parse(R"({
    "schema": "dyncontact/1", "name": "t", "problem": "normal", "dimension": 3,
    "materials": {"body": {"E": 2.1e11, "nu": 0.3}, "base": {"E": 2.1e11, "nu": 0.3}},
    "profile": {"type": "sphere", "radius": 0.01},
    "grid": {"nx": 16, "ny": 16, "x": [-3e-4, 3e-4], "y": [-3e-4, 3e-4]},
    "normal": {"force": 100.0}
  })");
}

json cylinder_2d_case() {
  return json::parse(R"({
    "name": "c2", "problem": "normal", "dimension": 2,
    "materials": {"body": {"E": 2.1e11, "nu": 0.3}, "base": {"E": 2.1e11, "nu": 0.3}},
    "profile": {"type": "cylinder", "radius": 0.02},
    "grid": {"nx": 32, "x": [-3e-4, 3e-4]},
    "normal": {"force": 1e5}
  })");
}

/// Runs `f`, expects an InputError whose key is `key`; returns its message.
std::string expect_input_error(const std::function<void()>& f, const std::string& key) {
  try {
    f();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), key) << e.what();
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError(" << key << "), got " << e.what();
    return {};
  }
  ADD_FAILURE() << "expected InputError(" << key << "), nothing thrown";
  return {};
}

/// build_case of `doc` after the override `assignment` must fail naming `key`.
std::string expect_bad(json doc, const std::string& assignment, const std::string& key) {
  apply_override(doc, assignment);
  return expect_input_error([&] { build_case(doc); }, key);
}

TEST(CaseModel, ParsesEveryBundledExample) {
  for (const char* name : {"hertz-sphere", "hertz-cylinder-2d", "flat-punch", "hertz-ellipse"}) {
    SCOPED_TRACE(name);
    const std::string path = kExamples + name + ".json";
    const Case c = build_case(read_case_file(path), std::filesystem::path(path).parent_path().string());
    EXPECT_EQ(c.name, name);
    EXPECT_EQ(c.problem, ProblemKind::normal);
    EXPECT_GT(c.grid.size(), 0u);
    EXPECT_TRUE(c.source.is_object());
  }
  const Case punch = build_case(read_case_file(kExamples + "flat-punch.json"));
  EXPECT_TRUE(punch.materials.body.rigid);
  EXPECT_EQ(punch.profile.type, ProfileType::flat_punch);
  EXPECT_EQ(punch.normal.control, Control::approach);
  EXPECT_DOUBLE_EQ(punch.normal.value, 1e-6);
  EXPECT_NEAR(punch.grid.x0, -1.2e-3, 1e-15);
  EXPECT_NEAR(punch.grid.x_max(), 1.2e-3, 1e-15);
  const Case cyl = build_case(read_case_file(kExamples + "hertz-cylinder-2d.json"));
  EXPECT_EQ(cyl.dimension, 2);
  EXPECT_EQ(cyl.grid.ny, 1);
  EXPECT_EQ(cyl.grid.nx, 256);
}

TEST(CaseModel, DefaultsAndSolverBlock) {
  json doc = sphere_case();
  doc["solver"] = json::parse(R"({"backend": "native", "tol": 1e-8, "certificate_tol": 1e-5, "max_iter": 50,
    "fallback": false, "accept_unconverged": true, "hessian": "limited-memory", "operator": "fft"})");
  doc["output"] = json::parse(R"({"dir": "somewhere", "fields": false, "plots": false})");
  const Case c = build_case(doc);
  EXPECT_EQ(c.solver.backend, Backend::native);
  EXPECT_DOUBLE_EQ(c.solver.tol, 1e-8);
  EXPECT_DOUBLE_EQ(c.solver.certificate_tol, 1e-5);
  EXPECT_EQ(c.solver.max_iter, 50);
  EXPECT_FALSE(c.solver.fallback);
  EXPECT_TRUE(c.solver.accept_unconverged);
  EXPECT_EQ(c.solver.hessian, Hessian::limited_memory);
  EXPECT_EQ(c.solver.operator_kind, OperatorKind::fft);
  EXPECT_EQ(c.output.dir, "somewhere");
  EXPECT_FALSE(c.output.fields);
  EXPECT_FALSE(c.output.plots);

  const Case d = build_case(sphere_case());
  EXPECT_EQ(d.solver.backend, Backend::automatic);
  EXPECT_TRUE(d.output.fields);
  EXPECT_FALSE(d.friction.has_value());
  EXPECT_EQ(d.grid.nx, 16);
  EXPECT_NEAR(d.grid.dx, 6e-4 / 16, 1e-18);
}

TEST(CaseModel, MaterialsFromShearModulusAndRigid) {
  json doc = sphere_case();
  apply_override(doc, "materials.body={\"G\": 8e10, \"nu\": 0.25}");
  apply_override(doc, "materials.base={\"rigid\": true}");
  const Case c = build_case(doc);
  EXPECT_DOUBLE_EQ(c.materials.body.E, 2.0 * 8e10 * 1.25);
  EXPECT_TRUE(c.materials.base.rigid);
  EXPECT_NEAR(c.materials.E_star(), 2e11 / (1 - 0.0625), 1.0);
}

TEST(CaseModel, BadMaterialsNameTheirKey) {
  const json d = sphere_case();
  expect_bad(d, "materials.body.E=-1", "materials.body.E");
  expect_bad(d, "materials.body.E=0", "materials.body.E");
  expect_bad(d, "materials.base.nu=0.5", "materials.base.nu");
  expect_bad(d, "materials.base.nu=-1", "materials.base.nu");
  expect_bad(d, "materials.body={\"G\": -3, \"nu\": 0.3}", "materials.body.G");
  expect_bad(d, "materials.body.G=8e10", "materials.body.G");  // both E and G
  expect_bad(d, "materials.body={\"nu\": 0.3}", "materials.body.E");
  expect_bad(d, "materials.body={\"E\": 2e11}", "materials.body.nu");
  expect_bad(d, "materials.body.E=\"steel\"", "materials.body.E");
  expect_bad(d, "materials.body={\"rigid\": true, \"E\": 1}", "materials.body.E");
  expect_bad(d, "materials.body.rigid=1", "materials.body.rigid");
  json both = sphere_case();
  apply_override(both, "materials.body={\"rigid\": true}");
  expect_bad(both, "materials.base={\"rigid\": true}", "materials");
  const std::string msg = expect_bad(d, "materials.body.Ex=1", "materials.body.Ex");
  EXPECT_NE(msg.find("unknown key"), std::string::npos) << msg;
}

TEST(CaseModel, UnknownAndMissingKeys) {
  const json d = sphere_case();
  expect_bad(d, "colour=1", "colour");
  expect_bad(d, "grid.nz=3", "grid.nz");
  expect_bad(d, "profile.radiuss=1", "profile.radiuss");
  expect_bad(d, "normal.forse=1", "normal.forse");
  expect_bad(d, "solver.verbose=true", "solver.verbose");
  expect_bad(d, "output.format=\"png\"", "output.format");
  for (const char* key : {"materials", "profile", "grid", "normal", "problem"}) {
    json doc = sphere_case();
    doc.erase(key);
    SCOPED_TRACE(key);
    expect_input_error([&] { build_case(doc); }, key);
  }
  json no_base = sphere_case();
  no_base["materials"].erase("base");
  expect_input_error([&] { build_case(no_base); }, "materials.base");
  json no_nx = sphere_case();
  no_nx["grid"].erase("nx");
  expect_input_error([&] { build_case(no_nx); }, "grid.nx");
  json no_load = sphere_case();
  no_load["normal"] = json::object();
  expect_input_error([&] { build_case(no_load); }, "normal.force");
  expect_input_error([] { build_case(json::array()); }, "case");
}

TEST(CaseModel, WrongTypesNameTheirKey) {
  const json d = sphere_case();
  expect_bad(d, "grid.nx=\"64\"", "grid.nx");
  expect_bad(d, "grid.nx=12.5", "grid.nx");
  expect_bad(d, "grid.x=[0]", "grid.x");
  expect_bad(d, "grid.x=[1e-3, -1e-3]", "grid.x");
  expect_bad(d, "dimension=\"3\"", "dimension");
  expect_bad(d, "name=3", "name");
  expect_bad(d, "solver.fallback=\"yes\"", "solver.fallback");
  expect_bad(d, "normal=5", "normal");
  expect_bad(d, "tangential=[1]", "tangential");
}

TEST(CaseModel, BadValuesNameTheirKey) {
  const json d = sphere_case();
  expect_bad(d, "profile.radius=0", "profile.radius");
  expect_bad(d, "profile.radius=-0.01", "profile.radius");
  expect_bad(d, "normal.force=-5", "normal.force");
  expect_bad(d, "normal={\"approach\": 0}", "normal.approach");
  expect_bad(d, "normal={\"approach\": -1e-6}", "normal.approach");
  expect_bad(d, "normal.approach=1e-6", "normal.approach");  // both force and approach
  expect_bad(d, "grid.nx=0", "grid.nx");
  expect_bad(d, "grid.ny=0", "grid.ny");
  expect_bad(d, "profile.type=\"cone\"", "profile.type");
  expect_bad(d, "problem=\"static\"", "problem");
  expect_bad(d, "dimension=4", "dimension");
  expect_bad(d, "schema=\"dyncontact/2\"", "schema");
  expect_bad(d, "name=\"a/b\"", "name");
  expect_bad(d, "grid.extent=1.2", "grid.extent");  // both extent and x/y
  for (const char* inner : {"-1e-4", "1e-3", "2e-3"})  // an annular punch: 0 <= inner_radius < radius
    expect_bad(d, std::string("profile={\"type\": \"flat_punch\", \"radius\": 1e-3, \"inner_radius\": ") + inner + "}",
               "profile.inner_radius");
  json ext = sphere_case();
  ext["grid"] = json::parse(R"({"nx": 8, "ny": 8, "extent": 0})");
  expect_input_error([&] { build_case(ext); }, "grid.extent");
  json no_y = sphere_case();
  no_y["grid"].erase("y");
  expect_input_error([&] { build_case(no_y); }, "grid.y");
}

TEST(CaseModel, ThreeDimensionalProfilesAreRejectedIn2D) {
  for (const char* profile : {R"({"type": "sphere", "radius": 0.01})",
                              R"({"type": "ellipsoid", "radius_x": 0.01, "radius_y": 0.02})",
                              R"({"type": "flat_punch", "radius": 1e-4})"}) {
    json doc = cylinder_2d_case();
    doc["profile"] = json::parse(profile);
    SCOPED_TRACE(profile);
    expect_input_error([&] { build_case(doc); }, "profile.type");
  }
  json ny = cylinder_2d_case();
  expect_bad(ny, "grid.ny=4", "grid.ny");
  json ok = cylinder_2d_case();
  apply_override(ok, "grid.ny=1");
  apply_override(ok, "grid.y=\"ignored in 2-D\"");
  EXPECT_NO_THROW(build_case(ok));
  expect_bad(cylinder_2d_case(), "profile.length=0.1", "profile.length");
}

TEST(CaseModel, FrictionLaws) {
  const json d = sphere_case();
  std::string msg = expect_bad(d, "friction={\"law\": \"coulomb\", \"mu\": -0.1}", "friction.mu");
  EXPECT_NE(msg.find("mu must be non-negative"), std::string::npos) << msg;
  expect_bad(d, "friction={\"law\": \"coulomb\"}", "friction.mu");
  expect_bad(d, "friction={\"law\": \"viscous\", \"mu\": 0.1}", "friction.law");
  expect_bad(d, "friction={\"mu\": 0.1}", "friction.law");
  expect_bad(d, "friction={\"law\": \"coulomb\", \"mu\": 0.1, \"bound\": 3}", "friction.bound");
  expect_bad(d, "friction={\"law\": \"tresca\", \"bound\": 0}", "friction.bound");
  expect_bad(d, "friction={\"law\": \"table\", \"pressure\": [0, 1e6], \"bound\": [0]}", "friction.bound");
  expect_bad(d, "friction={\"law\": \"table\", \"pressure\": [0], \"bound\": [0]}", "friction.pressure");
  expect_bad(d, "friction={\"law\": \"table\", \"pressure\": [1e6, 0], \"bound\": [0, 1]}", "friction.pressure");
  expect_bad(d, "friction={\"law\": \"table\", \"pressure\": [0, 1e6], \"bound\": [0, -1]}", "friction.bound");

  json shift = sphere_case();
  apply_override(shift, "problem=tangential");
  apply_override(shift, "tangential={\"regime\": \"shift\", \"force\": [1, 0]}");
  json table = shift;
  apply_override(table, "friction={\"law\": \"table\", \"pressure\": [0, 1e6, 2e6], \"bound\": [0, 3e5, 4e5]}");
  const Case c = build_case(table);
  ASSERT_TRUE(c.friction);
  EXPECT_EQ(c.friction->law, FrictionLawKind::table);
  EXPECT_EQ(c.friction->bound_table.size(), 3u);
  json tresca = shift;
  apply_override(tresca, "friction={\"law\": \"tresca\", \"bound\": 1e6}");
  EXPECT_DOUBLE_EQ(build_case(tresca).friction->bound, 1e6);
}

TEST(CaseModel, SolverBlockValidation) {
  const json d = sphere_case();
  expect_bad(d, "solver.backend=\"cplex\"", "solver.backend");
  expect_bad(d, "solver.tol=0", "solver.tol");
  expect_bad(d, "solver.certificate_tol=-1", "solver.certificate_tol");
  expect_bad(d, "solver.max_iter=0", "solver.max_iter");
  expect_bad(d, "solver.hessian=\"bfgs\"", "solver.hessian");
  expect_bad(d, "solver.operator=\"sparse\"", "solver.operator");
  expect_bad(d, "solver.accept_unconverged=2", "solver.accept_unconverged");
}

TEST(CaseModel, SolverOptionsValidateIsTheCaseReadersCheck) {
  SolverOptions s;
  EXPECT_EQ(s.validate(), "");
  s.tol = 0.5;
  EXPECT_EQ(s.validate(), "tol: must be from 1e-16 to 0.1 (relative), got 0.5");
  const std::string msg = expect_bad(sphere_case(), "solver.tol=0.5", "solver.tol");
  EXPECT_EQ(msg, "solver.tol: must be from 1e-16 to 0.1 (relative), got 0.5");
  s = SolverOptions{};
  s.certificate_tol = -1.0;
  EXPECT_EQ(s.validate(), "certificate_tol: must be from 1e-16 to 0.1 (relative), got -1");
  s = SolverOptions{};
  s.max_iter = 0;
  EXPECT_EQ(s.validate(), "max_iter: must be at least 1, got 0");
  for (const Backend b : {Backend::automatic, Backend::ipopt, Backend::nlopt, Backend::native})
    EXPECT_EQ(backend_from_string(to_string(b)), b);
  for (const Hessian h : {Hessian::automatic, Hessian::exact, Hessian::limited_memory})
    EXPECT_EQ(hessian_from_string(to_string(h)), h);
  for (const OperatorKind k : {OperatorKind::automatic, OperatorKind::dense, OperatorKind::fft})
    EXPECT_EQ(operator_kind_from_string(to_string(k)), k);
  EXPECT_STREQ(to_string(Hessian::limited_memory), "limited-memory");
  EXPECT_FALSE(backend_from_string("automatic"));
}

TEST(CaseModel, TangentialProblemNeedsFrictionAndBlock) {
  json t = sphere_case();
  apply_override(t, "problem=tangential");
  expect_input_error([&] { build_case(t); }, "friction");
  apply_override(t, "friction={\"law\": \"coulomb\", \"mu\": 0.3}");
  expect_input_error([&] { build_case(t); }, "tangential");
  apply_override(t, "tangential={\"regime\": \"shift\", \"force\": [20, 0]}");
  const Case c = build_case(t);
  EXPECT_EQ(c.problem, ProblemKind::tangential);
  ASSERT_TRUE(c.tangential.has_value());
  EXPECT_EQ(c.tangential->regime, TangentialRegime::shift);
  EXPECT_EQ(c.tangential->load.modes[0].kind, ModeControl::Kind::resultant);
  EXPECT_EQ(c.tangential->load.modes[0].value, 20.0);
}

TEST(CaseModel, LooselyParsedProblemKinds) {
  const json paper = json::parse(R"({"name": "p", "problem": "paper_cylinder",
    "dimensionless": {"gamma_bar": 0.5, "M0_bar": 0.2, "eta": "inf", "epsilon": 1e-3},
    "traction_model": "carter_poritsky", "sweep": {"dimensionless.gamma_bar": [0.1, 0.5]}})");
  const Case c = build_case(paper);
  EXPECT_EQ(c.problem, ProblemKind::paper_cylinder);
  EXPECT_EQ(c.source["dimensionless"]["eta"], "inf");
  json bad = paper;
  bad["traction_model"] = "magic";
  expect_input_error([&] { build_case(bad); }, "traction_model");
  bad = paper;
  bad["time"] = 3;
  expect_input_error([&] { build_case(bad); }, "time");
  json dyn = sphere_case();
  apply_override(dyn, "problem=dynamic");
  apply_override(dyn, "time={\"dt\": 1e-4, \"t_end\": 0.1}");
  apply_override(dyn, "body={\"mass\": 1}");
  expect_input_error([&] { build_case(dyn); }, "body.inertia");  // the dynamic blocks are read strictly
  apply_override(dyn, "body.inertia=[1e-4, 1e-4, 1e-4]");
  expect_input_error([&] { build_case(dyn); }, "normal");  // the body's motion sets the normal load
  dyn.erase("normal");
  apply_override(dyn, "loads.force.z.value=-10");
  const Case d = build_case(dyn);
  EXPECT_EQ(d.problem, ProblemKind::dynamic);
  ASSERT_TRUE(d.dynamic.has_value());
  EXPECT_EQ(d.dynamic->force[2].value, -10.0);
  EXPECT_EQ(d.dynamic->position[2], d.profile.radius);  // starts touching
}

TEST(CaseModel, ContactPointOutsideGridIsAnError) {
  json d = sphere_case();
  apply_override(d, "grid.x=[5e-3, 6e-3]");
  const std::string msg = expect_input_error([&] { build_case(d); }, "grid");
  EXPECT_NE(msg.find("the contact point lies outside the grid"), std::string::npos) << msg;
  json y = sphere_case();
  apply_override(y, "grid.y=[1e-3, 2e-3]");
  expect_input_error([&] { build_case(y); }, "grid");
  json c2 = cylinder_2d_case();
  apply_override(c2, "grid.x=[-3e-3, -1e-3]");
  expect_input_error([&] { build_case(c2); }, "grid");
  // A finite cylinder along y: its contact line must meet the grid.
  json cyl = sphere_case();
  apply_override(cyl, "profile={\"type\": \"cylinder\", \"radius\": 0.01, \"length\": 2e-3}");
  apply_override(cyl, "grid.y=[5e-3, 6e-3]");
  expect_input_error([&] { build_case(cyl); }, "grid");
  apply_override(cyl, "grid.y=[-2e-3, 2e-3]");
  EXPECT_NO_THROW(build_case(cyl));
  // A punch smaller than one element: no element centre can touch.
  json punch = sphere_case();
  apply_override(punch, "profile={\"type\": \"flat_punch\", \"radius\": 1e-6}");
  apply_override(punch, "grid.nx=4");
  apply_override(punch, "grid.ny=4");
  expect_input_error([&] { build_case(punch); }, "grid");
}

TEST(CaseModel, ExtentGridIsPlusMinusKHertzSemiAxes) {
  const double E_star = 2.1e11 / (2.0 * (1.0 - 0.09));
  {
    json d = sphere_case();
    d["grid"] = json::parse(R"({"nx": 32, "ny": 32, "extent": 1.3})");
    const Case c = build_case(d);
    const double a = hertz::sphere(0.01, 100.0, E_star).a;
    EXPECT_NEAR(c.grid.x0, -1.3 * a, 1e-9 * a);
    EXPECT_NEAR(c.grid.x_max(), 1.3 * a, 1e-9 * a);
    EXPECT_NEAR(c.grid.y0, -1.3 * a, 1e-9 * a);
    EXPECT_NEAR(c.grid.y_max(), 1.3 * a, 1e-9 * a);
  }
  {  // approach control: the force implied by the approach gives the same grid
    const auto s = hertz::sphere(0.01, 100.0, E_star);
    json d = sphere_case();
    d["grid"] = json::parse(R"({"nx": 32, "ny": 32, "extent": 1.3})");
    d["normal"] = {{"approach", s.approach}};
    const Case c = build_case(d);
    EXPECT_NEAR(c.grid.x_max(), 1.3 * s.a, 1e-8 * s.a);
  }
  {  // ellipsoid: a along x, b along y, from the elliptic Hertz solution
    json d = sphere_case();
    d["profile"] = json::parse(R"({"type": "ellipsoid", "radius_x": 0.01, "radius_y": 0.04})");
    d["grid"] = json::parse(R"({"nx": 32, "ny": 32, "extent": 1.5})");
    const Case c = build_case(d);
    const auto s = hertz::elliptic(0.5 / 0.01, 0.5 / 0.04, 100.0, E_star);
    EXPECT_LT(s.a, s.b);
    EXPECT_NEAR(c.grid.x_max(), 1.5 * s.a, 1e-9 * s.a);
    EXPECT_NEAR(c.grid.y_max(), 1.5 * s.b, 1e-9 * s.b);
    EXPECT_NEAR(c.grid.y0, -1.5 * s.b, 1e-9 * s.b);
    // the same through an approach
    d["normal"] = {{"approach", s.approach}};
    const Case ca = build_case(d);
    EXPECT_NEAR(ca.grid.x_max(), 1.5 * s.a, 1e-6 * s.a);
    EXPECT_NEAR(ca.grid.y_max(), 1.5 * s.b, 1e-6 * s.b);
  }
  {  // quadratic with A != B
    json d = sphere_case();
    d["profile"] = json::parse(R"({"type": "quadratic", "a": 50.0, "b": 20.0})");
    d["grid"] = json::parse(R"({"nx": 8, "ny": 8, "extent": 2})");
    const auto s = hertz::elliptic(50.0, 20.0, 100.0, E_star);
    const Case c = build_case(d);
    EXPECT_NEAR(c.grid.x_max(), 2 * s.a, 1e-9 * s.a);
    EXPECT_NEAR(c.grid.y_max(), 2 * s.b, 1e-9 * s.b);
  }
  {  // 2-D cylinder
    json d = cylinder_2d_case();
    d["grid"] = json::parse(R"({"nx": 64, "extent": 1.5})");
    const Case c = build_case(d);
    const double a = hertz::cylinder2d(0.02, 1e5, E_star).a;
    EXPECT_NEAR(c.grid.x0, -1.5 * a, 1e-9 * a);
    EXPECT_NEAR(c.grid.x_max(), 1.5 * a, 1e-9 * a);
    EXPECT_EQ(c.grid.ny, 1);
    // 2-D approach control has no Hertz width: explicit bounds are required
    d["normal"] = {{"approach", 1e-6}};
    expect_input_error([&] { build_case(d); }, "grid.extent");
  }
  {  // 3-D finite cylinder: line-load half-width along x, half the length along y
    json d = sphere_case();
    d["profile"] = json::parse(R"({"type": "cylinder", "radius": 0.02, "length": 0.01})");
    d["grid"] = json::parse(R"({"nx": 16, "ny": 16, "extent": 1.2})");
    const Case c = build_case(d);
    const double a = hertz::cylinder2d(0.02, 100.0 / 0.01, E_star).a;
    EXPECT_NEAR(c.grid.x_max(), 1.2 * a, 1e-9 * a);
    EXPECT_NEAR(c.grid.y_max(), 1.2 * 0.005, 1e-12);
    d["profile"].erase("length");
    expect_input_error([&] { build_case(d); }, "grid.extent");
  }
  {  // flat punch: its radius
    json d = sphere_case();
    d["profile"] = json::parse(R"({"type": "flat_punch", "radius": 1e-3})");
    d["grid"] = json::parse(R"({"nx": 8, "ny": 8, "extent": 1.25})");
    const Case c = build_case(d);
    EXPECT_NEAR(c.grid.x_max(), 1.25e-3, 1e-15);
    EXPECT_NEAR(c.grid.y0, -1.25e-3, 1e-15);
  }
}

TEST(CaseModel, ProfileHeightsAtElementCentres) {
  const Grid g = Grid::make(3, 4, 2, -2e-3, 2e-3, -1e-3, 1e-3);  // centres x = -1.5, -0.5, 0.5, 1.5 mm; y = -0.5, 0.5 mm
  auto h_at = [&](const ProfileSpec& p, int i, int j) { return profile_heights(p, g)[g.index(i, j)]; };
  const double x3 = 1.5e-3, x1 = 0.5e-3, y = 0.5e-3;

  ProfileSpec sphere;
  sphere.type = ProfileType::sphere;
  sphere.radius = 0.01;
  EXPECT_NEAR(h_at(sphere, 0, 0), (x3 * x3 + y * y) / 0.02, 1e-18);
  EXPECT_NEAR(h_at(sphere, 2, 1), (x1 * x1 + y * y) / 0.02, 1e-18);

  ProfileSpec ell;
  ell.type = ProfileType::ellipsoid;
  ell.radius_x = 0.01;
  ell.radius_y = 0.04;
  EXPECT_NEAR(h_at(ell, 3, 1), x3 * x3 / 0.02 + y * y / 0.08, 1e-18);

  ProfileSpec quad;
  quad.type = ProfileType::quadratic;
  quad.a = 3.0;
  quad.b = 7.0;
  EXPECT_NEAR(h_at(quad, 1, 0), 3.0 * x1 * x1 + 7.0 * y * y, 1e-18);
  double A = 0, B = 0;
  quad.quadratic_coefficients(A, B);
  EXPECT_EQ(A, 3.0);
  EXPECT_EQ(B, 7.0);
  sphere.quadratic_coefficients(A, B);
  EXPECT_DOUBLE_EQ(A, 50.0);
  EXPECT_DOUBLE_EQ(B, 50.0);

  ProfileSpec cyl;
  cyl.type = ProfileType::cylinder;
  cyl.radius = 0.01;
  EXPECT_NEAR(h_at(cyl, 0, 1), x3 * x3 / 0.02, 1e-18);  // no y dependence
  cyl.length = 0.8e-3;                                  // |y| = 0.5 mm > L/2: cannot touch
  EXPECT_TRUE(std::isinf(h_at(cyl, 0, 1)));
  cyl.length = 1.2e-3;
  EXPECT_NEAR(h_at(cyl, 1, 0), x1 * x1 / 0.02, 1e-18);

  ProfileSpec punch;
  punch.type = ProfileType::flat_punch;
  punch.radius = 1e-3;
  EXPECT_EQ(h_at(punch, 1, 0), 0.0);                 // r = 0.71 mm
  EXPECT_TRUE(std::isinf(h_at(punch, 0, 0)));        // r = 1.58 mm
  EXPECT_THROW(punch.quadratic_coefficients(A, B), InputError);
  punch.inner_radius = 0.75e-3;                      // an annulus 0.75 mm <= r < 1 mm
  EXPECT_TRUE(std::isinf(h_at(punch, 1, 0)));        // r = 0.71 mm: in the hole
  punch.inner_radius = 0.7e-3;
  EXPECT_EQ(h_at(punch, 1, 0), 0.0);

  const Grid g2 = Grid::make(2, 4, 1, -2e-3, 2e-3, 0, 0);
  ProfileSpec cyl2;
  cyl2.type = ProfileType::cylinder;
  cyl2.radius = 0.02;
  const auto h2 = profile_heights(cyl2, g2);
  ASSERT_EQ(h2.size(), 4u);
  EXPECT_NEAR(h2[0], x3 * x3 / 0.04, 1e-18);
  EXPECT_NEAR(h2[2], x1 * x1 / 0.04, 1e-18);
}

class TableProfile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("dc_table_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    // h = 10 + x^2 + 2 y^2 on a regular 11 x 11 lattice over [-1e-3, 1e-3]^2 (shuffled rows);
    // the reader shifts the minimum to 0.
    std::ofstream out(dir_ / "h.csv");
    out << "# a regular table\nx, y, h\n";
    for (int j = 10; j >= 0; --j)
      for (int i = 0; i <= 10; ++i) {
        const double x = -1e-3 + 2e-4 * i, y = -1e-3 + 2e-4 * j;
        out.precision(17);
        out << x << "," << y << "," << 10.0 + x * x + 2.0 * y * y << "\n";
      }
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  json table_case(const std::string& file) const {
    json d = sphere_case();
    d["profile"] = {{"type", "table"}, {"file", file}};
    d["grid"] = json::parse(R"({"nx": 8, "ny": 4, "x": [-8e-4, 8e-4], "y": [-8e-4, 8e-4]})");
    return d;
  }

  std::filesystem::path dir_;
};

TEST_F(TableProfile, ReadsAndInterpolates) {
  const Case c = build_case(table_case("h.csv"), dir_.string());
  EXPECT_EQ(c.profile.type, ProfileType::table);
  EXPECT_EQ(c.profile.table_h.size(), 121u);
  const auto h = profile_heights(c.profile, c.grid);
  for (int j = 0; j < c.grid.ny; ++j)
    for (int i = 0; i < c.grid.nx; ++i) {
      const double x = c.grid.xc(i), y = c.grid.yc(j);
      // a quadratic is interpolated exactly: round-off of the heights 10 + ... (bilinear: off by 3e-8)
      EXPECT_NEAR(h[c.grid.index(i, j)], x * x + 2 * y * y, 1e-14) << i << "," << j;
    }
  // read_case_file resolves the table against the case file's folder
  std::ofstream(dir_ / "case.json") << table_case("h.csv").dump();
  const json doc = read_case_file((dir_ / "case.json").string());
  EXPECT_EQ(std::filesystem::path(doc["profile"]["file"].get<std::string>()), dir_ / "h.csv");
  EXPECT_NO_THROW(build_case(doc));
}

TEST_F(TableProfile, CoversHalfASpacingBeyondItsNodesAndKeepsStepsSharp) {
  // The table's nodes at the centres of a 10 x 10 grid over [-1.1e-3, 1.1e-3]^2 (spacing 2e-4, as
  // a table written from a grid is): a finer grid over the same bounds reaches 1e-4 beyond the
  // outer nodes and gets the quadratic exactly there too.
  json fine = table_case("h.csv");
  fine["grid"] = json::parse(R"({"nx": 40, "ny": 40, "x": [-1.1e-3, 1.1e-3], "y": [-1.1e-3, 1.1e-3]})");
  const Case c = build_case(fine, dir_.string());
  const auto h = profile_heights(c.profile, c.grid);
  for (int j = 0; j < c.grid.ny; ++j)
    for (int i = 0; i < c.grid.nx; ++i) {
      const double x = c.grid.xc(i), y = c.grid.yc(j);
      EXPECT_NEAR(h[c.grid.index(i, j)], x * x + 2 * y * y, 1e-14) << i << "," << j;
    }
  json beyond = table_case("h.csv");
  beyond["grid"]["x"] = {-1.2e-3, 1.2e-3};  // centres 1.5e-4 beyond the outer nodes
  beyond["grid"]["nx"] = 24;
  expect_input_error([&] { build_case(beyond, dir_.string()); }, "profile.file");
  // A step (a sharp edge: 0 on x <= 0, 1e-3 beyond) stays within its heights between the nodes:
  // no dip below the face (a cubic through four nodes dips by 7 % of the step) or rise above it.
  std::ofstream step(dir_ / "step.csv");
  step << "x,y,h\n";
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 10; ++i) step << -1e-3 + 2e-4 * i << "," << -4e-4 + 2e-4 * j << "," << (i > 5 ? 1e-3 : 0.0) << "\n";
  step.close();
  json sharp = table_case("step.csv");
  sharp["grid"] = json::parse(R"({"nx": 88, "ny": 4, "x": [-1.1e-3, 1.1e-3], "y": [-4e-4, 4e-4]})");
  const Case cs = build_case(sharp, dir_.string());
  const auto hs = profile_heights(cs.profile, cs.grid);
  for (int i = 0; i < cs.grid.nx; ++i) {
    const double v = hs[cs.grid.index(i, 1)], x = cs.grid.xc(i);
    EXPECT_GE(v, 0.0) << x;
    EXPECT_LE(v, 1e-3) << x;
    if (x <= 0.0) {
      EXPECT_EQ(v, 0.0) << x;  // the face stays flat up to its last node
    }
  }
}

TEST_F(TableProfile, Errors) {
  json outside = table_case("h.csv");
  outside["grid"]["x"] = {-2e-3, 0.5e-3};
  const std::string msg = expect_input_error([&] { build_case(outside, dir_.string()); }, "profile.file");
  EXPECT_NE(msg.find("grid extends outside the table"), std::string::npos) << msg;
  expect_input_error([&] { build_case(table_case("missing.csv"), dir_.string()); }, "profile.file");
  std::ofstream(dir_ / "irregular.csv") << "x,y,h\n0,0,1\n1,0,2\n0,1,3\n";
  expect_input_error([&] { build_case(table_case("irregular.csv"), dir_.string()); }, "profile.file");
  std::ofstream(dir_ / "garbage.csv") << "x,y,h\n0,0,1\n1,zero,2\n";
  expect_input_error([&] { build_case(table_case("garbage.csv"), dir_.string()); }, "profile.file");
  std::ofstream(dir_ / "noheader.csv") << "0,0,1\n1,0,2\n";
  expect_input_error([&] { build_case(table_case("noheader.csv"), dir_.string()); }, "profile.file");
  json ext = table_case("h.csv");
  ext["grid"] = json::parse(R"({"nx": 8, "ny": 4, "extent": 1.2})");
  expect_input_error([&] { build_case(ext, dir_.string()); }, "grid.extent");
}

TEST(CaseModel, OverridesCreateAndReplaceKeys) {
  json d = sphere_case();
  apply_override(d, "materials.body.E=2e11");
  EXPECT_DOUBLE_EQ(d["materials"]["body"]["E"].get<double>(), 2e11);
  apply_override(d, "solver.backend=ipopt");  // not JSON: a string
  EXPECT_EQ(d["solver"]["backend"], "ipopt");
  apply_override(d, "tangential.force=[100,0]");
  EXPECT_EQ(d["tangential"]["force"], json::array({100, 0}));
  apply_override(d, "a.b.c.d=true");  // intermediate objects are created
  EXPECT_EQ(d["a"]["b"]["c"]["d"], true);
  apply_override(d, "output.dir=out/x=y");  // only the first '=' separates
  EXPECT_EQ(d["output"]["dir"], "out/x=y");
  apply_override(d, "tangential.force.1=5");  // array index
  EXPECT_EQ(d["tangential"]["force"][1], 5);
  apply_override(d, "name=\"quoted\"");
  EXPECT_EQ(d["name"], "quoted");

  json e = sphere_case();
  apply_override(e, "grid.nx=8");
  apply_override(e, "grid.ny=8");
  EXPECT_EQ(build_case(e).grid.nx, 8);
}

TEST(CaseModel, BadOverrideSyntax) {
  json d = sphere_case();
  for (const char* bad : {"materials.body.E", "=3", "a..b=1", "a.=1", ".a=1", "grid.nx=",
                          "materials.body.E.x=1", "grid.x.7=1"}) {
    SCOPED_TRACE(bad);
    expect_input_error([&] { apply_override(d, bad); }, "--set");
  }
}

TEST(CaseModel, MalformedJsonReportsLineAndColumn) {
  const std::string text = "{\n  \"name\": \"x\",\n  \"grid\": {\"nx\": 4,, \"ny\": 4}\n}\n";
  const std::string msg = expect_input_error([&] { parse_case_text(text, "case.json"); }, "case.json");
  EXPECT_NE(msg.find("line 3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("column"), std::string::npos) << msg;
  const std::string msg2 = expect_input_error([&] { parse_case_text("{\"a\": 1", "f.json"); }, "f.json");
  EXPECT_NE(msg2.find("line 1"), std::string::npos) << msg2;
  // comments are allowed
  EXPECT_EQ(parse_case_text("{\n // comment\n \"a\": 1 /* two */\n}", "c.json")["a"], 1);
}

TEST(CaseModel, MissingFile) {
  const std::string msg =
      expect_input_error([] { read_case_file("/nonexistent/dir/case.json"); }, "/nonexistent/dir/case.json");
  EXPECT_NE(msg.find("cannot open"), std::string::npos) << msg;
}

TEST(CaseModel, ToStringNames) {
  EXPECT_STREQ(to_string(ProblemKind::paper_cylinder), "paper_cylinder");
  EXPECT_STREQ(to_string(ProfileType::flat_punch), "flat_punch");
}

}  // namespace
}  // namespace dc
