// Contact detection with the pair list carried between steps (solver/contact_detection.hpp,
// contact/carried_pairs.hpp) against the simple full path it replaces in the step loop.
//
// No tolerance anywhere in this file: the carried path must give the full path's contacts
// bit for bit (same contacts, same order, same numbers), because it runs the same
// arithmetic on the same numbers; its only shortcut, the carried pair list, is exact (a
// superset of the overlapping pairs, filtered by the same comparisons). Numbers are therefore
// compared by their bits, so that even -0.0 against 0.0 or a NaN would count as a
// difference.
#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "../../bench/brick_wall.hpp"
#include "contact/broad_phase.hpp"
#include "contact/carried_pairs.hpp"
#include "support/contact_scenes.hpp"
#include "solver/contact_detection.hpp"
#include "solver/step.hpp"

using namespace dda;

namespace {

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool same_bits(const Vec2& a, const Vec2& b) {
  return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y());
}

bool same_state(const ContactState& a, const ContactState& b) {
  const bool same_deferred =
      a.deferred.has_value() == b.deferred.has_value() &&
      (!a.deferred || (a.deferred->mode == b.deferred->mode &&
                       a.deferred->slide_sign == b.deferred->slide_sign &&
                       a.deferred->relock == b.deferred->relock));
  return a.mode == b.mode && a.slide_sign == b.slide_sign && same_bits(a.t_lock, b.t_lock) &&
         a.bonded == b.bonded && same_bits(a.predicted_slip, b.predicted_slip) &&
         same_bits(a.normal_force, b.normal_force) && same_deferred &&
         same_bits(a.rest_shift, b.rest_shift);
}

// Every field of the two contacts, numbers by their bits.
bool identical(const Contact& a, const Contact& b) {
  return a.key == b.key && a.joint == b.joint && same_bits(a.vertex, b.vertex) &&
         same_bits(a.edge_start, b.edge_start) && same_bits(a.edge_end, b.edge_end) &&
         same_bits(a.tangent, b.tangent) && same_bits(a.normal, b.normal) &&
         same_bits(a.gap, b.gap) && same_bits(a.t, b.t) && same_bits(a.length, b.length) &&
         same_state(a.state, b.state) && same_bits(a.iterate.new_gap, b.iterate.new_gap) &&
         same_bits(a.iterate.shear_force, b.iterate.shear_force) &&
         same_bits(a.iterate.slip, b.iterate.slip) &&
         a.iterate.mode_changes == b.iterate.mode_changes;
}

// The index of the first contact in which the two lists differ, or -1 when identical.
int first_difference(const std::vector<Contact>& a, const std::vector<Contact>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  for (std::size_t k = 0; k < n; ++k) {
    if (!identical(a[k], b[k])) return static_cast<int>(k);
  }
  return a.size() == b.size() ? -1 : static_cast<int>(n);
}

// How one run went: the steps compared, the largest motion of a vertex in one step (m), and
// the carried list's record.
struct Comparison {
  int steps = 0;
  int contacts_max = 0;
  double largest_step_motion = 0.0;
  CarriedPairs record;
};

// Runs `steps` steps of the world. Before each, detects the contacts of the configuration
// the step starts from both ways, from the same previous contacts (the world's, with the
// states the last step left them): the full path, and the carried one with a cache kept
// from step to step as the step loop keeps its own; the two lists must be identical.
// Up to `steps` steps, stopping once the world's time reaches `end_time` (s).
Comparison compare_paths(World& world, int steps, double end_time = INFINITY) {
  Comparison result;
  StepWorkspace ws;
  RunStats stats;
  DetectionCache cache;
  for (int step = 0; step < steps && world.time < end_time; ++step) {
    set_reaches(world, time_step_to_try(world));  // as the step will (advance_step)
    std::vector<Contact> full = world.contacts;
    std::vector<Contact> carried = world.contacts;
    detect_contacts_full(world, full);
    detect_contacts(world, carried, cache);
    INFO("step " << world.step << ", " << full.size() << " contacts by the full path, "
                 << carried.size() << " by the carried one");
    REQUIRE(first_difference(full, carried) == -1);
    result.contacts_max = std::max(result.contacts_max, static_cast<int>(full.size()));

    std::vector<Polygon> before;
    for (const Block& b : world.blocks) before.push_back(b.vertices);
    REQUIRE(advance_step(world, ws, stats).ok);
    // The step loop's own detection ran on the same configurations: its list is this one.
    REQUIRE(ws.detection.pairs.pairs == cache.pairs.pairs);
    for (std::size_t i = 0; i < before.size(); ++i) {
      for (std::size_t v = 0; v < before[i].size(); ++v) {
        const double moved = (world.blocks[i].vertices[v] - before[i][v]).cwiseAbs().maxCoeff();
        result.largest_step_motion = std::max(result.largest_step_motion, moved);
      }
    }
    ++result.steps;
  }
  result.record = cache.pairs;
  return result;
}

}  // namespace

TEST_CASE("carried_overlapping_pairs gives a new sweep's pairs while boxes creep, jump and "
          "change in number",
          "[contact][detection]") {
  // 400 boxes with corners on a grid of 1/8 m (exact binary fractions: many touch exactly,
  // where touching counts as overlapping, decided by exact comparisons), moved at random
  // every round: most by a step of the grid or not at all (creeping: they stay inside their
  // grown boxes, margin 1/2 m), a few by several metres (they leave theirs), and now and
  // then all of them (a new sweep). Twice the number of boxes changes.
  std::mt19937 rng(20261123u);
  std::uniform_int_distribution<int> pos(0, 320);  // 0 .. 40 m in eighths
  std::uniform_int_distribution<int> size(0, 12);  // 0 .. 1.5 m
  std::uniform_int_distribution<int> creep(-1, 1);
  std::uniform_int_distribution<int> pick(0, 399);
  const auto random_box = [&] {
    const int x = pos(rng), y = pos(rng), w = size(rng), h = size(rng);
    return Box{Vec2(0.125 * x, 0.125 * y), Vec2(0.125 * (x + w), 0.125 * (y + h))};
  };
  std::vector<Box> boxes(400);
  for (Box& b : boxes) b = random_box();
  CarriedPairs carried;
  std::vector<std::pair<int, int>> got;
  const double margin = 0.5;  // m: four grid steps
  for (int round = 0; round < 200; ++round) {
    if (round == 80) boxes.resize(350);
    if (round == 120) boxes.resize(420, Box{Vec2(1.0, 1.0), Vec2(2.0, 2.0)});
    const int n = static_cast<int>(boxes.size());
    if (round % 50 == 49) {
      for (Box& b : boxes) b = random_box();  // everything moves
    } else {
      for (int k = 0; k < n / 10; ++k) {  // a tenth creep by one grid step
        Box& b = boxes[static_cast<std::size_t>(pick(rng) % n)];
        const Vec2 d(0.125 * creep(rng), 0.125 * creep(rng));
        b.min += d;
        b.max += d;
      }
      for (int k = 0; k < round % 4; ++k) {  // 0 to 3 jump away
        boxes[static_cast<std::size_t>(pick(rng) % n)] = random_box();
      }
    }
    carried_overlapping_pairs(boxes, margin, carried, got);
    INFO("round " << round);
    REQUIRE(got == overlapping_pairs(boxes));
  }
  // Every way of keeping the list up was taken, several times.
  CHECK(carried.full_sweeps >= 5);      // the first round, every 50th, the count changes
  CHECK(carried.partial_sweeps >= 50);  // rounds where a few jumped
  CHECK(carried.kept >= 10);            // rounds where only creepers moved, within margin
}

TEST_CASE("detect_contacts with the carried pairs gives the full path's contacts bit for bit "
          "while blocks fall into a box, collide and come to rest",
          "[contact][detection]") {
  // 30 squares in six rows dropped into a box: the rows fall 0.3 to 2 m (up to 6 m/s,
  // 1.3 cm a step at dt 2 ms, ten times a square's step limit, so steps are cut and redone),
  // land on corners, tumble and pile up; 1.4 s (about 1800 steps) takes them to rest.
  World world = make_world(test::blocks_into_box(30));
  const Comparison c = compare_paths(world, 100000, 1.4);
  // Compared on a pile, not on a few blocks: at rest each square touches its neighbours
  // and the box at two or more vertices (measured 81 contacts at most).
  CHECK(c.contacts_max > 50);
  // The falling blocks move up to their step limit a step (ratio x half a square's box,
  // 1.3 mm, a third of the carried list's margin), so within a few steps they move beyond the
  // margin, leave their grown boxes and are swept again; once the pile rests the list is
  // kept. (Measured: 156 new sweeps, 211 partial ones, 1466 kept.) The fastest step moves a
  // vertex by more than half that limit in one coordinate (measured 0.99 of it: falling
  // straight down, the cut aims at 0.9 of the limit and gravity adds the rest; only the
  // order of magnitude is what this test needs: motion at the scale of the limit).
  const double displacement_limit = world.blocks[3].step_limit;
  CHECK(c.largest_step_motion > 0.5 * displacement_limit);
  CHECK(c.record.full_sweeps + c.record.partial_sweeps > 10);
  CHECK(c.record.kept > 100);
}

TEST_CASE("detect_contacts with the carried pairs gives the full path's contacts bit for bit "
          "on the benchmark's brick wall as it settles",
          "[contact][detection]") {
  // The running-bond wall of the contact benchmarks at 100 bricks, from the first step (all
  // contacts new, bonded where the joint could be) through 300 steps of settling: the list
  // made at the first step is kept throughout (bricks creep by micrometres).
  World world = make_world(
      bench::brick_wall_scene(100, elastic_material("rock", 2700.0, 1e9, 0.25)));
  const Comparison c = compare_paths(world, 300);
  CHECK(c.contacts_max > 500);
  CHECK(c.record.full_sweeps == 1);
  CHECK(c.record.kept == 299);
}
