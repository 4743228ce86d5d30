// io/run_pictures: the pictures of a run drawn from made-up frames whose motion is known. A
// block moved along a known vector is drawn moved along it by the automatic exaggeration
// (a round number), with an arrow the way it went; its start is drawn when the drawn motion
// takes it off its place; contacts land as squares of their state's colour; a force chain
// joins two blocks' centroids; the energy chart takes one row per step and the potential's
// change. Pixels are checked against picture_frame.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/colour_maps.hpp"
#include "io/run_pictures.hpp"
#include "support/cli_helpers.hpp"
#include "support/picture_checks.hpp"

using namespace dda;

namespace {

// A fixed 4 x 1 m base and a free unit square on it, moved by u, as a blocks frame.
VtkPolyData frame(const Vec2& u, int second_material = 0) {
  VtkPolyData p;
  p.points = {{0, 0}, {4, 0}, {4, 1}, {0, 1}};
  for (const Vec2& q : {Vec2(1, 1), Vec2(2, 1), Vec2(2, 2), Vec2(1, 2)}) p.points.push_back(q + u);
  VtkCells polys;
  polys.connectivity = {0, 1, 2, 3, 4, 5, 6, 7};
  polys.offsets = {4, 8};
  p.polys = polys;
  p.cell_data.push_back({"fixed", VtkType::UInt8, 1, {}, {1, 0}});
  p.cell_data.push_back({"velocity", VtkType::Float64, 3, {"vx", "vy", "omega"}, {0, 0, 0, 3, 4, 0}});
  p.cell_data.push_back({"material", VtkType::Int32, 1, {}, {0, static_cast<double>(second_material)}});
  return p;
}

Rgb at(const Image& img, const Vec2& p) { return img.at(static_cast<int>(p.x()), static_cast<int>(p.y())); }

constexpr Rgb kArrow{200, 0, 0};

}  // namespace

TEST_CASE("run pictures: a small motion drawn exaggerated by a round number along its vector",
          "[picture][plot]") {
  const Vec2 u(0.002, -0.001);
  const BlocksPicture p = blocks_picture(frame(Vec2::Zero()), frame(u), 1.0, PlotOptions{}, {});
  // |u| = 2.24 mm against a typical block of 1 m: a quarter of it is 112 times |u|, whose
  // round number (1, 2, 5 x 10^k, nearest on a log scale) is 100.
  CHECK(p.exaggeration == 100.0);
  const PictureFrame f = picture_frame(p.blocks, p.options);
  const Image img = draw_blocks(p.blocks, p.options);
  // The free block's drawn place: its start moved by 100 u = (0.2, -0.1). Inside it, off
  // its centre (where the arrow starts): the colour of the largest displacement.
  const Vec2 c = Vec2(1.5, 1.5) + 100.0 * u;
  CHECK(at(img, f.to_pixel(c + Vec2(-0.3, 0.3))) == sequential_colour(1.0));
  // The start, at its top-left corner that the drawn block left: not painted as start (the
  // drawn motion, 0.22 m, is under half a block, so no start is drawn) but background.
  CHECK(at(img, f.to_pixel(Vec2(1.05, 1.95))) == (Rgb{255, 255, 255}));
  // The arrow from the drawn centroid along u, 0.8 m long: red at 0.3 and 0.7 of it.
  for (double share : {0.3, 0.7}) {
    const Vec2 q = f.to_pixel(c + share * 0.8 * u.normalized());
    int red = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) red += at(img, q + Vec2(dx, dy)) == kArrow;
    CHECK(red >= 2);
  }
  CHECK(at(img, f.to_pixel(c - 0.4 * u.normalized())) != kArrow);  // nothing behind it
  // Axes in metres and a colour bar up to the displacement of the centroid.
  CHECK(p.options.axes);
  REQUIRE(p.options.colour_bar);
  CHECK(p.options.colour_bar->max == Approx(u.norm()).epsilon(1e-12));
}

TEST_CASE("run pictures: a large motion drawn true, with the start under it, and the material and "
          "speed colourings",
          "[picture][plot]") {
  const Vec2 u(1.5, 0.0);
  PlotOptions o;
  SECTION("displacement, with the start") {
    const BlocksPicture p = blocks_picture(frame(Vec2::Zero()), frame(u), 2.0, o, {});
    CHECK(p.exaggeration == 1.0);  // 1.5 m is not small against a 1 m block
    const PictureFrame f = picture_frame(p.blocks, p.options);
    const Image img = draw_blocks(p.blocks, p.options);
    CHECK(at(img, f.to_pixel(Vec2(1.3, 1.5))) == (Rgb{246, 246, 246}));  // the start
    CHECK(at(img, f.to_pixel(Vec2(3.2, 1.8))) == sequential_colour(1.0));  // the block now, off its arrow
  }
  SECTION("material") {
    o.field = PlotField::Material;
    const BlocksPicture p = blocks_picture(frame(Vec2::Zero()), frame(u, 1), 2.0, o, {"granite", "sandstone"});
    const PictureFrame f = picture_frame(p.blocks, p.options);
    const Image img = draw_blocks(p.blocks, p.options);
    CHECK(at(img, f.to_pixel(Vec2(3.2, 1.8))) == category_colour(1));
    CHECK(at(img, f.to_pixel(Vec2(0.5, 0.5))) == category_colour(0));
    REQUIRE(p.options.legend.size() >= 2);
    CHECK(p.options.legend[0].label == "granite");
    CHECK(p.options.legend[1].label == "sandstone");
  }
  SECTION("speed: the bar ends at the free block's |v| = 5 m/s") {
    o.field = PlotField::Velocity;
    const BlocksPicture p = blocks_picture(frame(Vec2::Zero()), frame(u), 2.0, o, {});
    REQUIRE(p.options.colour_bar);
    CHECK(p.options.colour_bar->max == 5.0);
  }
  SECTION("plastic strain from frames without it is refused by name") {
    o.field = PlotField::PlasticStrain;
    CHECK_THROWS_WITH(blocks_picture(frame(Vec2::Zero()), frame(u), 2.0, o, {}),
                      Catch::Matchers::Contains("\"plastic_strain\""));
  }
  CHECK_THROWS_WITH(plot_field_from_name("strain"), Catch::Matchers::Contains("displacement, velocity, stress"));
}

TEST_CASE("run pictures: contacts as squares of their state, force chains between centroids",
          "[picture][plot]") {
  const VtkPolyData blocks = frame(Vec2::Zero());
  VtkPolyData contacts;
  contacts.points = {{1.0, 1.0}, {2.0, 1.0}, {1.5, 1.0}};
  contacts.point_data.push_back({"mode", VtkType::Int32, 1, {}, {2, 1, 0}});  // locked, sliding, open
  contacts.point_data.push_back({"bonded", VtkType::Int32, 1, {}, {0, 0, 1}});  // the third bonded
  contacts.point_data.push_back({"normal_force", VtkType::Float64, 1, {}, {1e4, 3e4, -5.0}});
  contacts.point_data.push_back({"vertex_block", VtkType::Int32, 1, {}, {1, 1, 1}});
  contacts.point_data.push_back({"edge_block", VtkType::Int32, 1, {}, {0, 0, 0}});

  const BlocksPicture states = joint_states_picture(blocks, contacts, 1.0, 1600);
  const PictureFrame f = picture_frame(states.blocks, states.options);
  const Image img = draw_blocks(states.blocks, states.options);
  CHECK(at(img, f.to_pixel({1.0, 1.0})) == (Rgb{31, 119, 180}));  // locked: blue
  CHECK(at(img, f.to_pixel({2.0, 1.0})) == (Rgb{214, 39, 40}));   // sliding: red
  CHECK(at(img, f.to_pixel({1.5, 1.0})) == (Rgb{44, 160, 44}));   // bonded: green
  CHECK(states.options.legend[2].label == "locked 1");

  const BlocksPicture chain = force_chain_picture(blocks, contacts, 1.0, 1600);
  const PictureFrame g = picture_frame(chain.blocks, chain.options);
  const Image chains = draw_blocks(chain.blocks, chain.options);
  // One pair (0, 1) carrying 4e4 N/m in compression (the tensile -5 left out): a line from
  // the base's centroid (2, 0.5) to the square's (1.5, 1.5), 10 px wide (the largest).
  REQUIRE(chain.options.lines.size() == 1);
  CHECK(chain.options.lines[0].width_px == 10.0);
  const Vec2 mid = g.to_pixel({1.75, 1.0});
  int dark = 0;
  for (int dx = -8; dx <= 8; ++dx) dark += chains.at(static_cast<int>(mid.x()) + dx, static_cast<int>(mid.y())) == (Rgb{60, 60, 60});
  // Across a 10 px line at 63 degrees to the horizontal: 10 / sin(63.4) = 11.2 px of a row.
  CHECK(dark >= 10);
  CHECK(dark <= 13);
}

TEST_CASE("run pictures: the energy chart takes one row per step and the potential's change",
          "[picture][plot]") {
  dda::test::TempDir dir("dda_test_energy_chart_");
  const std::filesystem::path csv = dir.path / "history.csv";
  std::string text =
      "step,time,block,xc,yc,rotation,area,exx,eyy,gxy,sxx,syy,sxy,vx,vy,omega,"
      "kinetic,potential,strain_energy,contact_energy,load_work,friction_dissipation,"
      "plastic_dissipation,damping_dissipation,energy_remainder,multiplier_work\n";
  for (int step = 0; step < 3; ++step)
    for (int block = 0; block < 2; ++block)
      text += std::to_string(step) + "," + std::to_string(0.1 * step) + "," + std::to_string(block) +
              ",0,0,0,1,0,0,0,0,0,0,0,0,0," + std::to_string(5.0 * step) + "," + std::to_string(100.0 - 5.0 * step) +
              ",0,0,0,0,0,0,1e-9,0\n";
  dda::test::write_file(csv, text);
  const ChartOptions o = energy_chart(csv);
  // Kinetic, the potential's change and the remainder; the terms zero throughout are left out.
  REQUIRE(o.series.size() == 3);
  CHECK(o.series[0].label == "kinetic");
  CHECK(o.series[1].label == "potential change");
  CHECK(o.series[2].label == "energy_remainder");
  CHECK(o.series[1].x == std::vector<double>{0.0, 0.1, 0.2});
  CHECK(o.series[1].y == std::vector<double>{0.0, -5.0, -10.0});
  CHECK(o.series[0].y == std::vector<double>{0.0, 5.0, 10.0});
  dda::test::write_file(dir.path / "bad.csv", "step,time\n0,x\n");
  CHECK_THROWS_WITH(energy_chart(dir.path / "bad.csv"), Catch::Matchers::Contains("no column \"kinetic\""));
}
