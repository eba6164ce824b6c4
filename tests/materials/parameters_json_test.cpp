// Material::from_json: every bad input is an acst::InputError whose message says where (the
// JSON path, or the parameter's name) and what is allowed; valid files parse to their values.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <typeinfo>
#include <string>
#include <vector>

#include "test_materials.hpp"

namespace {

using nlohmann::json;

const std::string guide_file = "data/parameters/toyoura_acst_guide.json";

json guide_json() { return json::parse(acst::test::read_text(guide_file)); }

// Parses `text`, expecting an InputError whose message contains every one of `fragments`.
void expect_input_error(const std::string& text, const std::vector<std::string>& fragments) {
  try {
    acst::Material::from_json(text);
    ADD_FAILURE() << "accepted: " << text;
  } catch (const acst::InputError& e) {
    const std::string what = e.what();
    for (const std::string& f : fragments)
      EXPECT_NE(what.find(f), std::string::npos) << "'" << f << "' not in: " << what;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw a " << typeid(e).name() << " instead of acst::InputError: " << e.what();
  }
}

struct RangeCase {
  const char* key;
  json value;
  const char* range;  // the allowed range as the message states it
};

TEST(ParametersJson, OutOfRangeParameterNamesItselfAndItsRange) {
  const RangeCase cases[] = {
      {"c", 0.0, "[0.7, 1]"},        // Me/Mc must be positive, and g convex (c >= ~0.7) ...
      {"c", 0.5, "[0.7, 1]"},        // ... non-convex deviatoric section
      {"c", 1.2, "[0.7, 1]"},        // ... and extension not stronger than compression
      {"nu", 0.5, "[0, 0.5)"},       // K = G 2(1+nu)/(3(1-2nu)) is infinite at 0.5
      {"nu", -0.1, "[0, 0.5)"},
      {"G0", -1.0, "(0, inf)"},
      {"lambda_c", 0.0, "(0, inf)"},  // a flat CSL
      {"xi", 0.0, "(0, 2]"},
      {"e_min", 0.0, "(0, inf)"},
      {"e_min", -0.1, "(0, inf)"},
      {"e_max", 0.5, "(0.597, 2.97)"},    // e_max below e_min = 0.597
      {"e_max", 0.597, "(0.597, 2.97)"},  // e_max equal to e_min: Dr undefined
      {"Mc", 0.0, "(0, 3]"},
      {"p_min", 0.0, "(0, inf)"},
  };
  for (const RangeCase& rc : cases) {
    json j = guide_json();
    j["parameters"][rc.key] = rc.value;
    SCOPED_TRACE(std::string(rc.key) + " = " + rc.value.dump());
    expect_input_error(j.dump(), {std::string("/parameters/") + rc.key, std::string("'") + rc.key + "'", rc.range});
  }
}

TEST(ParametersJson, NonNumbersAreRejectedWithTheirJsonPath) {
  // JSON has no NaN or infinity; whoever tries to pass one writes a string.
  for (const char* text : {"NaN", "nan", "inf", "-Infinity", "125"}) {
    json j = guide_json();
    j["parameters"]["c"] = text;
    SCOPED_TRACE(text);
    expect_input_error(j.dump(), {"/parameters/c", "expected a number"});
  }
  json j = guide_json();
  j["parameters"]["G0"] = json::array({125});
  expect_input_error(j.dump(), {"/parameters/G0", "expected a number"});
  j = guide_json();
  j["parameters"]["G0"] = nullptr;
  expect_input_error(j.dump(), {"/parameters/G0", "expected a number"});
}

TEST(ParametersJson, NaNLiteralIsAJsonSyntaxError) {
  std::string text = acst::test::read_text(guide_file);
  text.replace(text.find("\"c\": 0.75"), 9, "\"c\": NaN");
  expect_input_error(text, {"does not parse"});
}

TEST(ParametersJson, WrongTypesAreRejectedWithTheirJsonPath) {
  json j = guide_json();
  j["parameters"] = json::array();
  expect_input_error(j.dump(), {"/parameters", "expected a JSON object"});
  j = guide_json();
  j["integrator"] = "ME";
  expect_input_error(j.dump(), {"/integrator", "expected a JSON object"});
  j = guide_json();
  j["model"] = 1;
  expect_input_error(j.dump(), {"/model"});
  expect_input_error("[1, 2, 3]", {"expected a JSON object"});
}

TEST(ParametersJson, UnknownKeysAreRejectedWithTheirJsonPath) {
  json j = guide_json();
  j["parameters"]["phi_c"] = 31.0;
  expect_input_error(j.dump(), {"/parameters/phi_c", "unknown key"});
  j = guide_json();
  j["integrator"]["tolerance"] = 1e-4;
  expect_input_error(j.dump(), {"/integrator/tolerance", "unknown key"});
  j = guide_json();
  j["material"] = "sand";
  expect_input_error(j.dump(), {"/material", "unknown key"});
}

TEST(ParametersJson, MissingRequiredKeysAreNamed) {
  for (const char* key : {"Mc", "G0", "e_Gamma", "F0", "k_f"}) {  // fabric keys are required for ACST
    json j = guide_json();
    j["parameters"].erase(key);
    SCOPED_TRACE(key);
    expect_input_error(j.dump(), {std::string("/parameters/") + key, "missing"});
  }
  json j = guide_json();
  j.erase("parameters");
  expect_input_error(j.dump(), {"/parameters", "missing"});
}

TEST(ParametersJson, BadModelAndSchemeNamesAreRejected) {
  json j = guide_json();
  j["model"] = "Drucker-Prager";
  expect_input_error(j.dump(), {"/model", "ACST", "isotropic"});
  for (const json& scheme : {json("RK4"), json("me"), json(45)}) {
    j = guide_json();
    j["integrator"]["scheme"] = scheme;
    SCOPED_TRACE(scheme.dump());
    expect_input_error(j.dump(), {"/integrator/scheme"});
  }
}

TEST(ParametersJson, BadIntegratorOptionsAreRejectedWithTheirJsonPath) {
  const std::pair<const char*, json> cases[] = {
      {"stol", -1.0},     {"stol", 0.0},        {"stol", 2.0},  {"ftol", 0.0},
      {"min_substep", 1.0}, {"fe_substeps", 0}, {"max_substeps", 1.5}, {"max_substeps", "100"},
      {"unload_scan_intervals", 0}, {"reuse_last_substep", "yes"}, {"pressure_floor", "clamp"},
  };
  for (const auto& [key, value] : cases) {
    json j = guide_json();
    j["integrator"][key] = value;
    SCOPED_TRACE(std::string(key) + " = " + value.dump());
    expect_input_error(j.dump(), {std::string("/integrator/") + key});
  }
}

TEST(ParametersJson, SyntaxErrorsAreInputErrors) {
  expect_input_error("{ \"model\": \"ACST\", ", {"does not parse"});
  expect_input_error("", {"does not parse"});
  expect_input_error("{ \"model\": \"ACST\" } trailing", {"does not parse"});
}

// A number outside the double range (1e400) makes nlohmann::json throw out_of_range (406); the
// caller must still get an acst::InputError.
TEST(ParametersJson, NumberOverflowIsAnInputError) {
  std::string text = acst::test::read_text(guide_file);
  text.replace(text.find("\"G0\": 125"), 9, "\"G0\": 1e400");
  expect_input_error(text, {});
}

TEST(ParametersJson, ValidFilesParseToTheirValues) {
  const json j = guide_json();
  const acst::Material mat = acst::Material::from_json(j.dump());
  const acst::Parameters& p = mat.parameters();
  for (int i = 0; i < acst::parameter_count; ++i) {
    const std::string name = acst::parameter_names[i];
    EXPECT_EQ(acst::parameter_by_index(p, i), j["parameters"][name].get<double>()) << name;
  }
  EXPECT_EQ(p.variant, acst::Variant::anisotropic);
  EXPECT_EQ(mat.options().scheme, acst::integration::Scheme::modified_euler);
  EXPECT_EQ(mat.options().stol, 1e-4);
  // Every shipped parameter file parses.
  for (const char* file : {"data/parameters/toyoura_acst_guide.json", "data/parameters/toyoura_acst_literature.json",
                           "data/parameters/toyoura_isotropic_literature.json"}) {
    EXPECT_NO_THROW(acst::Material::from_json(acst::test::read_text(file))) << file;
  }
  // The optional keys: model (defaults to ACST), integrator (defaults), guards.
  json minimal = guide_json();
  minimal.erase("model");
  minimal.erase("integrator");
  minimal["parameters"]["h_min"] = 1e-2;
  minimal["parameters"]["R_tolerance"] = 1e-8;
  const acst::Material m2 = acst::Material::from_json(minimal.dump());
  EXPECT_EQ(m2.parameters().variant, acst::Variant::anisotropic);
  EXPECT_EQ(m2.parameters().h_min, 1e-2);
  EXPECT_EQ(m2.parameters().R_tolerance, 1e-8);
  // Every option key the reader knows, set to a valid value.
  json full = guide_json();
  full["integrator"] = {{"scheme", "RK45"},          {"stol", 1e-6},         {"ftol", 1e-9},
                        {"ltol", 1e-7},              {"min_substep", 1e-7},  {"max_substeps", 5000},
                        {"fe_substeps", 4},          {"unload_scan_intervals", 20},
                        {"reuse_last_substep", false}, {"pressure_floor", "fail"}};
  const acst::Material m3 = acst::Material::from_json(full.dump());
  EXPECT_EQ(m3.options().scheme, acst::integration::Scheme::rk45);
  EXPECT_EQ(m3.options().stol, 1e-6);
  EXPECT_EQ(m3.options().max_substeps, 5000);
  EXPECT_EQ(m3.options().fe_substeps, 4);
  EXPECT_FALSE(m3.options().reuse_last_substep);
  EXPECT_EQ(m3.options().pressure_floor, acst::integration::PressureFloorPolicy::fail);
}

}  // namespace

// The documented parameter table is the library's own (acst::parameter_table), so the two
// cannot drift apart: docs/model.md section 9 holds it between two markers.
TEST(ParameterTable, DocsShowTheLibrarysTable) {
  const std::string doc = acst::test::read_text("docs/model.md");
  const std::string begin = "<!-- parameter table: generated from acst::parameter_table -->\n";
  const std::string end = "<!-- end of parameter table -->";
  const auto a = doc.find(begin), b = doc.find(end);
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  EXPECT_EQ(doc.substr(a + begin.size(), b - a - begin.size()), acst::parameter_table_markdown())
      << "paste acst::parameter_table_markdown() into docs/model.md";
}

// Every row reaches its own member, PROPS entries come first and match parameter_names.
TEST(ParameterTable, RowsAreDistinctMembersAndPropsComeFirst) {
  acst::Parameters p;
  for (int i = 0; i < acst::parameter_table_size; ++i) {
    p.*acst::parameter_table[i].member = 1000.0 + i;
    if (i < acst::parameter_count) {
      EXPECT_TRUE(acst::parameter_table[i].props);
      EXPECT_STREQ(acst::parameter_names[i], acst::parameter_table[i].name);
    } else {
      EXPECT_FALSE(acst::parameter_table[i].props) << acst::parameter_table[i].name;
    }
  }
  for (int i = 0; i < acst::parameter_table_size; ++i) EXPECT_EQ(p.*acst::parameter_table[i].member, 1000.0 + i);
  EXPECT_EQ(acst::parameter_count, 18);
}
