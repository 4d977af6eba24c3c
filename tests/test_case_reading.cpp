// The case model's readers of the tangential and paper_cylinder blocks and its checked JSON
// parser: every case `solve` rejects is rejected while reading (so `validate` rejects it
// too), naming the key path; hostile documents (deep nesting, duplicate keys, 1e999) too.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "case_model.hpp"
#include "errors.hpp"
#include "json_parse.hpp"

namespace dc {
namespace {

using json = nlohmann::json;

json shift_case() {
  return json::parse(R"({
    "name": "t", "problem": "tangential", "dimension": 3,
    "materials": {"body": {"E": 2.1e11, "nu": 0.3}, "base": {"E": 2.1e11, "nu": 0.3}},
    "profile": {"type": "sphere", "radius": 0.01},
    "grid": {"nx": 16, "ny": 16, "extent": 1.3},
    "normal": {"force": 100.0},
    "friction": {"law": "coulomb", "mu": 0.3},
    "tangential": {"regime": "shift", "force": [10, 0]}
  })");
}

/// build_case after `assignment` fails naming `key` (and the message contains `words`).
void expect_bad_override(json doc, const std::string& assignment, const std::string& key, const std::string& words = "") {
  SCOPED_TRACE(assignment);
  try {
    apply_override(doc, assignment);
    (void)build_case(doc);
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    return;
  }
  ADD_FAILURE() << "expected InputError(" << key << ")";
}

TEST(CaseReading, TangentialBlockIsTyped) {
  const Case c = build_case(shift_case());
  ASSERT_TRUE(c.tangential);
  EXPECT_EQ(c.tangential->regime, TangentialRegime::shift);
  EXPECT_FALSE(c.tangential->has_history);
  EXPECT_EQ(c.tangential->load.modes[0].kind, ModeControl::Kind::resultant);
  EXPECT_EQ(c.tangential->load.modes[0].value, 10.0);
  EXPECT_EQ(c.tangential->load.normal.value, 100.0);

  json h = shift_case();
  apply_override(h, R"(tangential.history=[{"force": [20, 5]}, {"shift": [1e-7, 0], "normal": {"force": 50}}])");
  const Case d = build_case(h);
  ASSERT_EQ(d.tangential->history.size(), 2u);
  EXPECT_EQ(d.tangential->history[0].modes[1].value, 5.0);
  EXPECT_EQ(d.tangential->history[1].modes[0].kind, ModeControl::Kind::amplitude);
  EXPECT_EQ(d.tangential->history[1].modes[1].value, 0.0);  // "shift" sets both components
  const auto normals = d.tangential->step_normals();
  ASSERT_EQ(normals.size(), 2u);
  EXPECT_EQ(normals[0].value, 100.0);
  EXPECT_EQ(normals[1].value, 50.0);

  json r = shift_case();
  apply_override(r, R"(tangential={"regime": "rolling", "creepage": [1e-4, 0], "spin": 0.5, "velocity": 3})");
  const Case e = build_case(r);
  EXPECT_EQ(e.tangential->regime, TangentialRegime::rolling);
  EXPECT_EQ(e.tangential->rolling.velocity, 3.0);
  EXPECT_EQ(e.tangential->rolling.modes[2].value, 0.5);
}

// Everything the tangential solver used to reject only when solving is a reading error now.
TEST(CaseReading, BadTangentialBlocksAreRejectedWhileReading) {
  const json d = shift_case();
  expect_bad_override(d, "tangential.regime=skid", "tangential.regime", "unknown regime");
  expect_bad_override(d, "tangential.regime=3", "tangential.regime", "required");
  expect_bad_override(d, R"(tangential={"regime": "rolling", "creepage": [1e-4, 0], "velocity": 0})", "tangential.velocity",
             "positive");
  expect_bad_override(d, R"(tangential={"regime": "rolling", "creepage": [1e-4, 0], "velocity": -2})", "tangential.velocity");
  expect_bad_override(d, "tangential.history=[]", "tangential.history", "non-empty");
  expect_bad_override(d, "tangential.history=\"steps\"", "tangential.history", "non-empty");
  expect_bad_override(d, "tangential.history=[3]", "tangential.history[0]", "object");
  expect_bad_override(d, R"(tangential.history=[{"force": [1, 0]}, {"forse": [1, 0]}])", "tangential.history[1].forse",
             "unknown key");
  expect_bad_override(d, "tangential.force=[1]", "tangential.force", "two components");
  expect_bad_override(d, "tangential.force=[1, 2, 3]", "tangential.force", "[x, y]");
  expect_bad_override(d, "tangential.force=5", "tangential.force", "two components");
  expect_bad_override(d, "tangential.force=[\"a\", 0]", "tangential.force[0]", "must be a number");
  expect_bad_override(d, R"(tangential={"regime": "shift", "force": [1, 0], "shift": [0, 0]})", "tangential.force", "not both");
  expect_bad_override(d, R"(tangential={"regime": "torsion", "angle": 1e-3, "moment": 1})", "tangential.moment");
  expect_bad_override(d, R"(tangential.history=[{"normal": {"force": -1}}])", "tangential.history[0].normal.force",
             "positive");
  expect_bad_override(d, "tangential.creepage=[0, 0]", "tangential.creepage", "unknown key");
  expect_bad_override(d, R"(tangential={"regime": "rolling", "creepage": [0, 0], "max_steps": 0})", "tangential.max_steps");
}

TEST(CaseReading, BlocksTheProblemDoesNotUseAreErrors) {
  json normal = shift_case();
  normal["problem"] = "normal";
  normal.erase("tangential");
  expect_bad_override(normal, "problem=normal", "friction", "not used by problem 'normal'");
  normal.erase("friction");
  EXPECT_NO_THROW(build_case(normal));
  expect_bad_override(normal, R"(tangential={"regime": "shift", "force": [1, 0]})", "tangential", "not used");
  expect_bad_override(normal, R"(sweep={"normal.force": [1, 2]})", "sweep", "not used");
  expect_bad_override(normal, R"(dimensionless={"gamma_bar": 1})", "dimensionless", "not used");
  // A bad value in an unused block still names its own key first.
  expect_bad_override(normal, R"(friction={"law": "coulomb", "mu": -1})", "friction.mu");
}

TEST(CaseReading, PaperCylinderBlocksAreTyped) {
  const json doc = json::parse(R"({"name": "p", "problem": "paper_cylinder",
    "dimensionless": {"gamma_bar": 0.5, "eta": "inf"}, "time": {"dt": 0.01, "scheme": "bdf2"},
    "sweep": {"dimensionless.gamma_bar": [0.1, 0.5]}})");
  const Case c = build_case(doc);
  ASSERT_TRUE(c.paper_cylinder);
  EXPECT_FALSE(c.paper_cylinder->dimensional);
  EXPECT_EQ(*c.paper_cylinder->gamma_bar, 0.5);
  EXPECT_TRUE(std::isinf(*c.paper_cylinder->eta));
  EXPECT_FALSE(c.paper_cylinder->M0_bar.has_value());
  EXPECT_TRUE(c.paper_cylinder->bdf2);
  EXPECT_EQ(*c.paper_cylinder->dt, 0.01);
  const auto points = sweep_points(c);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].label, "gamma_bar = 0.1");
  EXPECT_EQ(*points[1].run.paper_cylinder->gamma_bar, 0.5);
  expect_bad_override(doc, R"(body={"mass": 1})", "body", "dimensionless");
  expect_bad_override(doc, "time.t_end=3", "time.t_end", "unknown key");
  expect_bad_override(doc, R"(tangential={"regime": "shift"})", "tangential", "not used");
}

// ---------------------------------------------------------------- the checked parser

std::string nested_arrays(int depth, const std::string& inner = "1") {
  return std::string(static_cast<std::size_t>(depth), '[') + inner + std::string(static_cast<std::size_t>(depth), ']');
}

void expect_parse_error(const std::string& text, const std::string& key, const std::string& words) {
  try {
    (void)parse_case_text(text, "case.json");
  } catch (const InputError& e) {
    EXPECT_EQ(e.key().substr(0, key.size()), key) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    return;
  }
  ADD_FAILURE() << "expected InputError(" << key << ")";
}

TEST(CaseReading, DeepNestingIsRejectedWhileParsing) {
  // A million levels under an unknown key: rejected at level 65 (it once overflowed the stack).
  expect_parse_error("{\"junk\": " + nested_arrays(1000000) + "}", "junk[0][0]", "nested more than 64");
  expect_parse_error(nested_arrays(100000), "[0][0]", "nested more than 64");
  std::string objects;
  for (int k = 0; k < 100; ++k) objects += "{\"a\": ";
  expect_parse_error(objects + "1" + std::string(100, '}'), "a.a.a", "nested more than 64");
  EXPECT_NO_THROW((void)parse_case_text("{\"x\": " + nested_arrays(case_json::kMaxJsonDepth - 1) + "}", "case.json"));
  json doc = json::object();
  try {
    apply_override(doc, "grid.x=" + nested_arrays(500));
    ADD_FAILURE() << "deep --set value accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.key()).rfind("grid.x[0]", 0), 0u) << e.what();
  }
}

TEST(CaseReading, DuplicateKeysAndOutOfRangeNumbersNameTheKey) {
  expect_parse_error(R"({"grid": {"nx": 16, "ny": 8, "nx": 32}})", "grid.nx", "duplicate key");
  expect_parse_error(R"({"a": 1, "a": 1})", "a", "duplicate key");
  expect_parse_error(R"({"normal": {"force": 1e999}})", "normal.force", "1e999");
  expect_parse_error(R"({"grid": {"x": [0, -1e400]}})", "grid.x[1]", "outside the range");
  EXPECT_NO_THROW((void)parse_case_text(R"({"a": {"k": 1}, "b": {"k": 2}, "c": [{"k": 1}, {"k": 2}]})", "c.json"));
  json doc = json::object();
  try {
    apply_override(doc, "normal.force=1e999");
    ADD_FAILURE() << "1e999 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.key()), "normal.force") << e.what();
  }
  // Malformed JSON keeps its line and column.
  try {
    (void)parse_case_text("{\n  \"a\": [1,\n}", "case.json");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dc
