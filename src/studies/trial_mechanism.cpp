#include "studies/trial_mechanism.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>

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

std::uint64_t key_of(const ContactKey& k) {
  // Block and vertex/edge indices each below 2^16 in any scene dda runs in reasonable time;
  // a collision would only miscount an opened contact.
  const auto part = [](int v) { return static_cast<std::uint64_t>(v) & 0xffffU; };
  return part(k.vertex_block) << 48 | part(k.vertex) << 32 | part(k.edge_block) << 16 | part(k.edge);
}

std::vector<JointActivity> joint_activity(const World& before, const World& after,
                                          const std::vector<int>& group) {
  std::vector<char> in_group(after.blocks.size(), 0);
  for (int b : group) in_group[static_cast<std::size_t>(b)] = 1;
  std::unordered_map<std::uint64_t, ContactMode> start;
  for (const Contact& c : before.contacts) start[key_of(c.key)] = c.state.mode;
  std::map<int, JointActivity> by_joint;
  for (const Contact& c : after.contacts) {
    if (!in_group[static_cast<std::size_t>(c.key.vertex_block)] &&
        !in_group[static_cast<std::size_t>(c.key.edge_block)]) {
      continue;
    }
    const auto was = start.find(key_of(c.key));
    const bool opened = c.state.mode == ContactMode::Open && was != start.end() &&
                        was->second != ContactMode::Open;
    const bool sliding = c.state.mode == ContactMode::Slide;
    if (!opened && !sliding) continue;
    JointActivity& a = by_joint[c.joint];
    a.joint = c.joint;
    a.sliding += sliding ? 1 : 0;
    a.opened += opened ? 1 : 0;
  }
  std::vector<JointActivity> out;
  for (const auto& [joint, a] : by_joint) out.push_back(a);
  std::stable_sort(out.begin(), out.end(), [](const JointActivity& a, const JointActivity& b) {
    return a.sliding > b.sliding;
  });
  return out;
}

}  // namespace

double rotation_between(const Block& before, const Block& after) {
  const Vec2 a = before.vertices.front() - before.moments.centroid;
  const Vec2 b = after.vertices.front() - after.moments.centroid;
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
}

std::vector<BlockMotion> moved_blocks(const World& consolidated, const World& trial_end) {
  double largest = 0.0;
  for (std::size_t i = 0; i < consolidated.blocks.size(); ++i) {
    largest = std::max(largest, (trial_end.blocks[i].moments.centroid -
                                 consolidated.blocks[i].moments.centroid).norm());
  }
  std::vector<BlockMotion> out;
  if (largest <= 0.0) return out;
  const std::vector<char> touched = touched_blocks(trial_end);
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
    out.push_back(b);
  }
  std::sort(out.begin(), out.end(), [](const BlockMotion& a, const BlockMotion& b) {
    return a.displacement.norm() > b.displacement.norm();
  });
  return out;
}

TrialMechanism trial_mechanism(const World& consolidated, const World& trial_end,
                               const LimitAnalysisSettings& settings) {
  TrialMechanism m;
  m.blocks = moved_blocks(consolidated, trial_end);
  if (m.blocks.empty()) {
    m.mode = "none";
    return m;
  }
  std::vector<int> group;
  int rotating = 0;
  for (const BlockMotion& b : m.blocks) {
    group.push_back(b.block);
    rotating += b.mode == "rotating" ? 1 : 0;
  }
  std::sort(group.begin(), group.end());
  if (m.blocks.size() == 1) {
    m.mode = m.blocks.front().mode;
  } else {
    m.mode = 2 * rotating > static_cast<int>(m.blocks.size()) ? "rotating group" : "sliding group";
  }
  m.joints = joint_activity(consolidated, trial_end, group);
  m.group_bound = limit_analysis(consolidated, settings, group);
  return m;
}

}  // namespace dda
