// Contact output: the contacts of an output step as VTK points with their mode,
// forces and joint material, the count of each mode per joint material, and both through a
// real run (contacts.pvd, summary.json's contacts.modes_by_joint_material).
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>
#include <cmath>
#include <string>

#include "support/cli_helpers.hpp"
#include "io/contact_output.hpp"
#include "io/vtk_reader.hpp"
#include "support/scene_builders.hpp"
#include "solver/world.hpp"

using namespace dda;

namespace {

// Two squares side by side on a base, and three contacts written by hand: block 1's vertex
// 0 on block 0 (locked, bonded, joint 1), block 2's vertex 1 on block 0 (sliding) and block
// 2's vertex 0 on block 1 (open).
World world_with_contacts() {
  Scene s = test::base_scene(1, 0.01);
  s.joint_materials = {JointMaterial{"default", 30.0, 0.0, 0.0},
                       JointMaterial{"bedding", 25.0, 1e4, 0.0}};
  s.blocks.push_back(test::block(test::rectangle(0, 0, 4, 1)));
  s.blocks.push_back(test::block(test::rectangle(0, 1, 1, 1)));
  s.blocks.push_back(test::block(test::rectangle(2, 1, 1, 1)));
  World w = make_world(s);
  auto contact = [](int vb, int v, int eb, int joint, ContactMode mode) {
    Contact c;
    c.key = {vb, v, eb, 2};
    c.joint = joint;
    c.state.mode = mode;
    c.normal = Vec2(0, 1);
    return c;
  };
  Contact a = contact(1, 0, 0, 1, ContactMode::Lock);
  a.state.bonded = true;
  a.state.normal_force = 1234.5;
  a.iterate.shear_force = -67.25;
  a.iterate.new_gap = -2e-5;
  Contact b = contact(2, 1, 0, 0, ContactMode::Slide);
  b.iterate.slip = 3e-4;
  Contact c = contact(2, 0, 1, 0, ContactMode::Open);
  c.iterate.new_gap = 0.01;
  w.contacts = {a, b, c};
  return w;
}

}  // namespace

TEST_CASE("contacts are written as VTK points at their vertices with mode and forces",
          "[output][contacts]") {
  const World w = world_with_contacts();
  const std::string text = contacts_vtp_text(w, VtkEncoding::Ascii);
  CHECK(test::contains(text, "NumberOfPoints=\"3\" NumberOfVerts=\"3\""));
  // The points: block 1's vertex 0 (0, 1), block 2's vertex 1 (3, 1), block 2's vertex 0 (2, 1).
  CHECK(test::contains(text, "          0 1 0\n          3 1 0\n          2 1 0\n"));
  CHECK(test::contains(text, "Name=\"mode\" NumberOfComponents=\"1\" format=\"ascii\">\n          2\n          1\n          0\n"));
  CHECK(test::contains(text, "Name=\"bonded\" NumberOfComponents=\"1\" format=\"ascii\">\n          1\n          0\n          0\n"));
  CHECK(test::contains(text, "Name=\"joint\" NumberOfComponents=\"1\" format=\"ascii\">\n          1\n          0\n          0\n"));
  CHECK(test::contains(text, "Name=\"normal_force\" NumberOfComponents=\"1\" format=\"ascii\">\n          1234.5\n"));
  CHECK(test::contains(text, "Name=\"shear_force\" NumberOfComponents=\"1\" format=\"ascii\">\n          -67.25\n"));
  CHECK(test::contains(text, "Name=\"slip\" NumberOfComponents=\"1\" format=\"ascii\">\n          0\n          3e-04\n"));
  CHECK(test::contains(text, "Name=\"gap\" NumberOfComponents=\"1\" format=\"ascii\">\n          -2e-05\n"));
  CHECK(test::contains(text, "Name=\"normal\" NumberOfComponents=\"3\" format=\"ascii\">\n          0 1 0\n"));
  CHECK(contact_frame_name(42) == "vtk/contacts_000042.vtp");

  const std::vector<ContactModeCounts> counts = contact_modes_by_joint(w, 2);
  REQUIRE(counts.size() == 2);
  CHECK(counts[0].open == 1);
  CHECK(counts[0].slide == 1);
  CHECK(counts[0].lock == 0);
  CHECK(counts[0].bonded == 0);
  CHECK(counts[1].open == 0);
  CHECK(counts[1].slide == 0);
  CHECK(counts[1].lock == 1);
  CHECK(counts[1].bonded == 1);
}

TEST_CASE("a run writes contacts.pvd and counts contact modes per joint material",
          "[output][contacts][cli]") {
  // A square resting on a fixed base under gravity, friction 30 degrees: its two bottom
  // corners touch the base and stay locked (no tangential load), so the summary counts two
  // locked "default" contacts and the last contact frame has two points.
  test::TempDir dir("dda_contact_output_");
  test::write_file(dir.path / "scene.json", R"json({
    "gravity": [0, -9.81],
    "control": {"time_step": 0.01, "steps": 20, "output_every": 10},
    "materials": {"rock": {"model": "elastic", "density": 2500, "young": 1e9, "poisson": 0.2}},
    "joint_materials": {"default": {"friction_angle": 30, "cohesion": 0, "tensile_strength": 0},
                        "unused": {"friction_angle": 20, "cohesion": 0, "tensile_strength": 0}},
    "blocks": [
      {"vertices": [[-2, -1], [2, -1], [2, 0], [-2, 0]], "material": "rock", "fixed": true},
      {"vertices": [[-0.5, 0], [0.5, 0], [0.5, 1], [-0.5, 1]], "material": "rock"}
    ]
  })json");
  const test::CommandResult result =
      test::run_command(test::shell_quote(DDA_EXE) + " run " +
                        test::shell_quote((dir.path / "scene.json").string()) + " --out " +
                        test::shell_quote((dir.path / "out").string()));
  INFO(result.output);
  REQUIRE(result.exit_code == 0);
  const std::string pvd = test::read_file(dir.path / "out" / "contacts.pvd");
  CHECK(test::contains(pvd, "file=\"vtk/contacts_000000.vtp\""));
  CHECK(test::contains(pvd, "file=\"vtk/contacts_000020.vtp\""));
  // The run's default, binary frame, read back: the two locked corners at the base's top.
  const VtkPolyData last = read_vtp(dir.path / "out" / "vtk" / "contacts_000020.vtp");
  REQUIRE(last.points.size() == 2);
  REQUIRE(last.verts.has_value());
  CHECK(last.verts->size() == 2);
  for (const Vec2& p : last.points) {
    // Within the allowed penetration of the base's top (y = 0); 1e-3 m is far above it.
    CHECK(std::abs(p.y()) < 1e-3);
    CHECK(std::abs(std::abs(p.x()) - 0.5) < 1e-3);
  }
  CHECK(last.find_point_array("mode")->values == std::vector<double>{2, 2});  // both locked
  const nlohmann::json summary =
      nlohmann::json::parse(test::read_file(dir.path / "out" / "summary.json"));
  const nlohmann::json& modes = summary["contacts"]["modes_by_joint_material"];
  CHECK(modes["default"]["lock"] == 2);
  CHECK(modes["default"]["slide"] == 0);
  CHECK(modes["default"]["open"] == 0);
  CHECK(modes["unused"]["lock"] == 0);
}
