// The joint laws' direct shear tests through `dda run` (docs/scene-format.md,
// joint_materials): a rigid block on a fixed base under a constant normal load, pushed along
// the joint by a constant point load larger than the joint's strength, in static steps. The
// contacts the run writes at its end (vtk/contacts_*.vtp) slide and resist with the law:
// Barton-Bandis, N tan(phi_r + JRC log10(JCS L / N)); slip-weakening Coulomb past its
// residual slip, N tan(phi_res).
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "contact/joint_law.hpp"
#include "io/vtk_reader.hpp"
#include "support/cli_helpers.hpp"

namespace fs = std::filesystem;
using dda::test::run_command;
using dda::test::shell_quote;

namespace {

// The numbers of point-data array `name` of a contacts frame (read by io/vtk_reader: the
// run writes the default, binary encoding).
std::vector<double> vtk_array(const dda::VtkPolyData& frame, const std::string& name) {
  const dda::VtkArray* a = frame.find_point_array(name);
  REQUIRE(a != nullptr);
  return a->values;
}

// A 2 m x 0.5 m rigid block on a fixed base, pressed by 1e5 N/m at its top centre, pushed
// along +x by `push` N/m at its left side's mid-height, `steps` static steps of 0.01 s; the
// base's joint is `joint`. Contacts written at the last step only.
nlohmann::json shear_scene(const nlohmann::json& joint, double push, int steps) {
  return {{"gravity", {0.0, -9.81}},
          {"control", {{"time_step", 0.01}, {"steps", steps}, {"dynamic_coefficient", 0.0},
                       {"output_every", steps}}},
          {"materials", {{"rock", {{"model", "elastic"}, {"density", 2500.0}, {"young", 1e10},
                                   {"poisson", 0.25}, {"rigid", true}}}}},
          {"joint_materials", {{"default", joint}}},
          {"blocks", {{{"vertices", {{-4.0, -1.0}, {4.0, -1.0}, {4.0, 0.0}, {-4.0, 0.0}}},
                       {"material", "rock"}, {"fixed", true}},
                      {{"vertices", {{-1.0, 0.0}, {1.0, 0.0}, {1.0, 0.5}, {-1.0, 0.5}}},
                       {"material", "rock"}}}},
          {"point_loads", {{{"point", {0.0, 0.5}}, {"force", {0.0, -1e5}}},
                           {{"point", {-1.0, 0.25}}, {"force", {push, 0.0}}}}}};
}

struct SlidingContact {
  double normal, shear;
};

// Runs `scene` through dda run; the contacts sliding at its end.
std::vector<SlidingContact> run_shear(const nlohmann::json& scene, const fs::path& dir) {
  const fs::path file = dir / "scene.json";
  dda::test::write_file(file, scene.dump());
  const dda::test::CommandResult r = run_command(shell_quote(DDA_EXE) + " run " +
                                                 shell_quote(file.string()) + " --out " +
                                                 shell_quote((dir / "out").string()));
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  std::string last;
  for (const auto& e : fs::directory_iterator(dir / "out" / "vtk")) {
    const std::string name = e.path().filename().string();
    if (name.rfind("contacts_", 0) == 0 && name > last) last = name;
  }
  const dda::VtkPolyData frame = dda::read_vtp(dir / "out" / "vtk" / last);
  const std::vector<double> mode = vtk_array(frame, "mode"), normal = vtk_array(frame, "normal_force"),
                            shear = vtk_array(frame, "shear_force");
  std::vector<SlidingContact> out;
  for (std::size_t i = 0; i < mode.size(); ++i) {
    if (mode[i] == 1.0) out.push_back({normal[i], std::abs(shear[i])});  // 1: sliding
  }
  return out;
}

}  // namespace

TEST_CASE("dda run: direct shear of a Barton-Bandis joint and of a slip-weakening one past "
          "its residual slip",
          "[cli][joint][barton_bandis][weakening]") {
  const dda::test::TempDir dir("dda_joint_laws_cli_");
  // The block weighs 24.5 kN/m and is pressed by 100 kN/m: about 62 kPa under each half of
  // its base, where phi_r 30, JRC 10, JCS 50 MPa give 59 degrees, a resistance of about
  // 1.66 N; the push, 250 kN/m, exceeds it (2.0 N), so the block slides every step.
  {
    fs::create_directories(dir.path / "bb");
    const nlohmann::json joint = {{"friction_angle", 30.0}, {"cohesion", 0.0}, {"tensile_strength", 0.0},
                                  {"jrc", 10.0}, {"jcs", 5e7}};
    const std::vector<SlidingContact> sliding = run_shear(shear_scene(joint, 2.5e5, 50), dir.path / "bb");
    REQUIRE(sliding.size() == 2);
    for (const SlidingContact& c : sliding) {
      // Each contact stands for 1 m of base. The law is taken at the normal force the step
      // started with and the file holds the step's end: under constant loads the two differ
      // by the last digits (the written numbers are the shortest round-trip text): 1e-9.
      const double angle = dda::barton_bandis_angle(30.0, 10.0, 5e7, c.normal / 1.0);
      INFO("N " << c.normal << ", S " << c.shear << ", law " << angle << " degrees");
      CHECK(c.shear == Approx(c.normal * std::tan(angle * M_PI / 180.0)).epsilon(1e-9));
      CHECK(angle > 55.0);
    }
  }
  // Coulomb with peak 40 and residual 25 degrees over 1 mm of slip: after 50 steps the block
  // has slid centimetres, and each contact resists with N tan 25 exactly.
  {
    fs::create_directories(dir.path / "coulomb");
    const nlohmann::json joint = {{"friction_angle", 40.0}, {"cohesion", 0.0}, {"tensile_strength", 0.0},
                                  {"residual_friction_angle", 25.0}, {"residual_slip", 1e-3}};
    const std::vector<SlidingContact> sliding =
        run_shear(shear_scene(joint, 1.2e5, 50), dir.path / "coulomb");
    REQUIRE(sliding.size() == 2);
    for (const SlidingContact& c : sliding) {
      INFO("N " << c.normal << ", S " << c.shear);
      CHECK(c.shear == Approx(c.normal * std::tan(25.0 * M_PI / 180.0)).epsilon(1e-12));
    }
  }
}
