// The world a scene makes: the "auto" penalty of solver/world.hpp.
#include <catch2/catch.hpp>

#include "support/scene_builders.hpp"
#include "solver/world.hpp"

using namespace dda;

TEST_CASE("the auto penalty is 50 E of the stiffest material a block uses", "[world][penalty]") {
  Scene s = test::base_scene(1, 0.01);  // material 0: rock, E = 1 GPa
  s.blocks.push_back(test::block(test::rectangle(0.0, 0.0, 1.0, 1.0)));
  s.materials.push_back(elastic_material("spare", 2700.0, 1e11, 0.25));
  // The spare 100 GPa material is defined but no block takes it: Shi's 50 E of the rock.
  CHECK(resolve_penalty(s) == 50.0 * 1e9);
  CHECK(make_world(s).penalty == 50.0 * 1e9);
  // Once a block takes it, it sets the penalty.
  s.blocks.push_back(test::block(test::rectangle(2.0, 0.0, 1.0, 1.0)));
  s.blocks.back().material = 1;
  CHECK(resolve_penalty(s) == 50.0 * 1e11);
  // A scene's own penalty is kept whatever its materials.
  s.control.penalty = 3e9;
  CHECK(resolve_penalty(s) == 3e9);
}
