// The run loop and its hook (solver/run.hpp), the pins' moving anchors
// (solver/moving_anchors.hpp) and the schedule's round-off (solver/schedule.hpp).
#include <catch2/catch.hpp>

#include <vector>

#include "support/scene_builders.hpp"
#include "solver/moving_anchors.hpp"
#include "solver/run.hpp"
#include "solver/schedule.hpp"
#include "solver/world.hpp"

using namespace dda;

TEST_CASE("a run hook sees the start once, and each step before and after it", "[run]") {
  Scene s = test::base_scene(3, 0.01);
  s.blocks.push_back(test::block(test::rectangle(-0.5, -0.5, 1, 1)));
  World world = make_world(s);
  std::vector<int> starts, befores, afters;
  RunHook hook;
  hook.at_start = [&](const World& w, const RunStats&) {
    starts.push_back(w.step);
    return true;
  };
  hook.before_step = [&](World& w) { befores.push_back(w.step); };
  hook.after_step = [&](const World& w, const RunStats& stats) {
    afters.push_back(stats.steps);
    return w.step == stats.steps;
  };
  const RunStats stats = run(world, hook);
  CHECK_FALSE(stats.diverged);
  CHECK_FALSE(stats.interrupted);
  CHECK(stats.steps == 3);
  CHECK(starts == std::vector<int>{0});
  CHECK(befores == std::vector<int>{0, 1, 2});
  CHECK(afters == std::vector<int>{1, 2, 3});
}

TEST_CASE("a hook that stops the run before its end marks it interrupted", "[run]") {
  Scene s = test::base_scene(5, 0.01);
  s.blocks.push_back(test::block(test::rectangle(-0.5, -0.5, 1, 1)));
  World world = make_world(s);
  RunHook hook;
  hook.after_step = [](const World& w, const RunStats&) { return w.step < 2; };
  const RunStats stats = run(world, hook);
  CHECK(stats.interrupted);
  CHECK(stats.steps == 2);
  CHECK(world.step == 2);
}

TEST_CASE("moving a pin's anchor books the work its spring takes as load work", "[run]") {
  Scene s = test::base_scene(1, 0.01);
  s.blocks.push_back(test::block(test::rectangle(-0.5, -0.5, 1, 1)));
  s.pins.push_back(PinSpec{Vec2(0.1, 0.2), 0});
  World world = make_world(s);
  Pin& pin = world.pins[0];
  pin.current = Vec2(0.1, 0.25);  // the pinned point 5 cm above its anchor
  const double work_before = world.energy.load_work;
  move_pin_anchors(world, Vec2(0.0, -0.1));
  CHECK(pin.anchor == Vec2(0.1, 0.2 - 0.1));
  // p/2 (|x - a'|^2 - |x - a|^2) with |x - a| = 0.05, |x - a'| = 0.15.
  const double expected = 0.5 * world.penalty * (0.15 * 0.15 - 0.05 * 0.05);
  CHECK_THAT(world.energy.load_work - work_before,
             Catch::Matchers::WithinRel(expected, 1e-12));
}

TEST_CASE("the schedule's end is reached within 1e-9 of its shortest step", "[run]") {
  const std::vector<double> steps{0.02, 0.01};
  CHECK(shortest_time_step(steps) == 0.01);
  CHECK(reached_time(1.0, 1.0, steps));
  CHECK(reached_time(1.0 - 0.5e-11, 1.0, steps));  // half of 1e-9 x 0.01
  CHECK_FALSE(reached_time(1.0 - 2e-11, 1.0, steps));
}
