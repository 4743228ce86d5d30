// A sweep file (io/sweep_spec.hpp): a grid's variants are every combination in reading order,
// a list's are as given, a variant's scene holds its values at their places, and a bad place
// or value is refused naming the file and the place.
#include <catch2/catch.hpp>

#include "io/input_error.hpp"
#include "io/sweep_spec.hpp"

namespace {

using dda::InputError;
using dda::parse_sweep;
using nlohmann::json;

json base() {
  return json::parse(R"({"scene": "s.json", "command": "fos",
                         "fos": {"jobs": 1, "samples": 10, "at_factor": 1}})");
}

std::string refusal(const json& doc) {
  try {
    parse_sweep(doc, "sweep.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("a sweep grid gives every combination with the last place fastest", "[sweep][io]") {
  json doc = base();
  doc["grid"] = {{"/a/x", {1, 2, 3}}, {"/b", {"p", "q"}}};
  const dda::SweepSpec s = parse_sweep(doc, "sweep.json");
  CHECK(s.command == "fos");
  CHECK(s.fos.samples == 10);
  CHECK(s.fos.at_factor == 1.0);
  REQUIRE(s.pointers == std::vector<std::string>{"/a/x", "/b"});
  REQUIRE(s.variants.size() == 6);
  CHECK(s.variants[0] == std::vector<json>{1.0, "p"});
  CHECK(s.variants[1] == std::vector<json>{1.0, "q"});
  CHECK(s.variants[5] == std::vector<json>{3.0, "q"});
  // The variant's scene: the values put at their places, the rest as it was.
  const json scene = {{"a", {{"x", 0.5}, {"y", 7}}}, {"b", "o"}, {"c", {1, 2}}};
  const json v4 = dda::variant_scene(scene, s, 4);
  CHECK(v4["a"]["x"] == 3.0);
  CHECK(v4["a"]["y"] == 7);
  CHECK(v4["b"] == "p");
  CHECK(v4["c"] == scene["c"]);
  CHECK(dda::variant_name(4) == "variant-004");
}

TEST_CASE("a sweep list gives its variants as listed", "[sweep][io]") {
  json doc = base();
  doc["list"] = {{{"/a/x", 10}, {"/c/1", 4}}, {{"/a/x", 20}, {"/c/1", 5}}};
  const dda::SweepSpec s = parse_sweep(doc, "sweep.json");
  REQUIRE(s.variants.size() == 2);
  CHECK(s.variants[1] == std::vector<json>{20.0, 5.0});
  const json scene = {{"a", {{"x", 0.5}}}, {"c", {1, 2}}};
  CHECK(dda::variant_scene(scene, s, 1)["c"] == json({1, 5.0}));
}

TEST_CASE("a sweep refuses bad places and values naming them", "[sweep][io]") {
  json grid = base();
  grid["grid"] = {{"a/x", {1}}};
  CHECK_THAT(refusal(grid), Catch::Contains("sweep.json: grid[\"a/x\"]") && Catch::Contains("not a JSON pointer"));
  json empty = base();
  empty["grid"] = {{"/a", json::array()}};
  CHECK_THAT(refusal(empty), Catch::Contains("grid[\"/a\"]") && Catch::Contains("a value"));
  json list_value = base();
  list_value["list"] = {{{"/a", {1, 2}}}};
  CHECK_THAT(refusal(list_value), Catch::Contains("list[0]") && Catch::Contains("expected a number"));
  json uneven = base();
  uneven["list"] = {{{"/a", 1}}, {{"/b", 2}}};
  CHECK_THAT(refusal(uneven), Catch::Contains("list[1]") && Catch::Contains("same places"));
  json both = base();
  both["grid"] = {{"/a", {1}}};
  both["list"] = {{{"/a", 1}}};
  CHECK_THAT(refusal(both), Catch::Contains("\"grid\" or as \"list\""));
  json command = base();
  command["command"] = "dance";
  command["grid"] = {{"/a", {1}}};
  CHECK_THAT(refusal(command), Catch::Contains("command") && Catch::Contains("unknown command"));
  json option = base();
  option["fos"]["jobz"] = 2;
  option["grid"] = {{"/a", {1}}};
  CHECK_THAT(refusal(option), Catch::Contains("jobz"));
  // A place the scene does not have: the variant and the pointer named.
  json ok = base();
  ok["grid"] = {{"/joint_materials/defualt/friction_angle", {30}}};
  const dda::SweepSpec s = parse_sweep(ok, "sweep.json");
  const json scene = {{"joint_materials", {{"default", {{"friction_angle", 32}}}}}};
  try {
    dda::variant_scene(scene, s, 0);
    FAIL("accepted a place the scene does not have");
  } catch (const InputError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("sweep.json: variant-000") &&
                                          Catch::Contains("/joint_materials/defualt/friction_angle") &&
                                          Catch::Contains("names no value"));
  }
  // A key into a list is no value either.
  json into_list = base();
  into_list["grid"] = {{"/c/x", {1}}};
  CHECK_THROWS_AS(dda::variant_scene(json{{"c", {1, 2}}}, parse_sweep(into_list, "sweep.json"), 0), InputError);
}
