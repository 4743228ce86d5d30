#include "studies/trial_mechanism.hpp"

#include <algorithm>
#include <cmath>

namespace dda {
namespace {

// Per block: whether a closed contact touches it.
std::vector<char> touched_blocks(const World& w) {
  std::vector<char> touched(w.blocks.size(), 0);
  for (const Contact& c : w.contacts) {
    if (c.state.mode == ContactMode::Open) continue;
    touched[static_cast<std::size_t>(c.key.vertex_block)] = 1;
    touched[static_cast<std::size_t>(c.key.edge_block)] = 1;
  }
  return touched;
}

}  // namespace

double rotation_between(const Block& before, const Block& after) {
  const Vec2 a = before.vertices.front() - before.moments.centroid;
  const Vec2 b = after.vertices.front() - after.moments.centroid;
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}

TrialMechanism trial_mechanism(const World& consolidated, const World& trial_end,
                               const LimitAnalysisSettings& settings) {
  TrialMechanism m;
  double largest = 0.0;
  for (std::size_t i = 0; i < consolidated.blocks.size(); ++i) {
    largest = std::max(largest, (trial_end.blocks[i].moments.centroid -
                                 consolidated.blocks[i].moments.centroid).norm());
  }
  if (largest <= 0.0) {
    m.mode = "none";
    return m;
  }
  const std::vector<char> touched = touched_blocks(trial_end);
  std::vector<int> group;
  int rotating = 0;
  for (std::size_t i = 0; i < consolidated.blocks.size(); ++i) {
    const Block& before = consolidated.blocks[i];
    const Block& after = trial_end.blocks[i];
    if (before.fixed) continue;
    const Vec2 u = after.moments.centroid - before.moments.centroid;
    if (u.norm() <= kMechanismShare * largest) continue;
    BlockMotion b;
    b.block = static_cast<int>(i);
    b.displacement = u;
    b.rotation = rotation_between(before, after);
    // A corner at the block's typical radius moves |rotation| x radius by the rotation.
    const double radius = std::sqrt(before.moments.area);
    if (!touched[i]) {
      b.mode = "falling";
    } else {
      b.mode = std::abs(b.rotation) * radius > u.norm() ? "rotating" : "sliding";
    }
    rotating += b.mode == "rotating" ? 1 : 0;
    m.blocks.push_back(b);
    group.push_back(b.block);
  }
  std::sort(m.blocks.begin(), m.blocks.end(), [](const BlockMotion& a, const BlockMotion& b) {
    return a.displacement.norm() > b.displacement.norm();
  });
  if (m.blocks.size() == 1) {
    m.mode = m.blocks.front().mode;
  } else {
    m.mode = 2 * rotating > static_cast<int>(m.blocks.size()) ? "rotating group" : "sliding group";
  }
  m.group_bound = limit_analysis(consolidated, settings, group);
  return m;
}

}  // namespace dda
