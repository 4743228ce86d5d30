#include "studies/trial_mechanism.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>

namespace dda {
namespace {

// A block turns about a point of its own (toppling or rotating) when the instantaneous centre
// of its motion lies within this many radii of its centroid: a column tipping on its toe
// turns about a corner, one radius away; a sliding block's centre lies far off.
constexpr double kPivotReach = 1.5;
// A group's sliding contacts name its mode when one direction of slip (along or across its
// motion) is at least this many times as frequent as the other. On the cut slopes of
// verification/slope-cut the two lie within a factor of 2 of each other as often as not
// (a staggered slope: 146 along, 149 across; a toppling one: 6 and 8), and such a group is
// both.
constexpr long kSlipDominance = 2;

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

// The sliding contacts touching the group at the trial's end, by the angle between their edge
// and the motion of their block in the group.
SlipDirections slip_directions(const World& after, const std::vector<BlockMotion>& blocks) {
  std::vector<const BlockMotion*> motion(after.blocks.size(), nullptr);
  for (const BlockMotion& b : blocks) motion[static_cast<std::size_t>(b.block)] = &b;
  SlipDirections out;
  const double along = std::cos(M_PI / 6.0), across = std::cos(M_PI / 3.0);
  for (const Contact& c : after.contacts) {
    if (c.state.mode != ContactMode::Slide) continue;
    const BlockMotion* a = motion[static_cast<std::size_t>(c.key.vertex_block)];
    const BlockMotion* e = motion[static_cast<std::size_t>(c.key.edge_block)];
    if (a == nullptr && e == nullptr) continue;
    Vec2 u = Vec2::Zero();
    if (a != nullptr) u += a->displacement;
    if (e != nullptr) u += e->displacement;
    if (u.norm() <= 0.0 || c.tangent.norm() <= 0.0) continue;
    const double cosine = std::abs(c.tangent.dot(u)) / (c.tangent.norm() * u.norm());
    if (cosine >= along) {
      ++out.along;
    } else if (cosine <= across) {
      ++out.across;
    } else {
      ++out.between;
    }
  }
  return out;
}

}  // namespace

std::string group_mode(const std::vector<BlockMotion>& blocks, const SlipDirections& slip) {
  if (blocks.empty()) return "none";
  if (blocks.size() == 1) return blocks.front().mode;
  const auto most = [&](const char* mode) {
    const auto n = std::count_if(blocks.begin(), blocks.end(),
                                 [&](const BlockMotion& b) { return b.mode == mode; });
    return 2 * n > static_cast<long>(blocks.size());
  };
  if (most("toppling")) return "toppling group";
  if (most("rotating")) return "rotating group";
  if (most("falling")) return "falling group";
  // By how its contacts slip: one way at least kSlipDominance times as often as the other
  // names it; neither, both.
  if (slip.across > 0 && slip.across >= kSlipDominance * slip.along) return "toppling group";
  if (slip.along >= kSlipDominance * slip.across) return "sliding group";
  return "sliding and toppling group";
}

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
  // Down: the gravity direction (the toppling test below).
  const Vec2 down = consolidated.gravity.norm() > 0.0 ? Vec2(consolidated.gravity.normalized())
                                                      : Vec2(0.0, -1.0);
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
    // The block's radius: its farthest vertex from the centroid.
    double radius = 0.0;
    for (const Vec2& v : before.vertices) radius = std::max(radius, (v - before.moments.centroid).norm());
    if (!touched[i]) {
      b.mode = "falling";
    } else if (std::abs(b.rotation) * kPivotReach * radius <= u.norm()) {
      b.mode = "sliding";
    } else {
      // The instantaneous centre p of a small rigid motion (u, rotation r) about the
      // centroid c: u = r z x (c - p), so p - c = (-u_y, u_x) / r; it lies within
      // kPivotReach x radius of c (the test above).
      const Vec2 to_pivot = Vec2(-u.y(), u.x()) / b.rotation;
      b.mode = to_pivot.dot(down) > std::cos(M_PI / 4.0) * to_pivot.norm() ? "toppling" : "rotating";
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
  for (const BlockMotion& b : m.blocks) group.push_back(b.block);
  std::sort(group.begin(), group.end());
  m.slip = slip_directions(trial_end, m.blocks);
  m.mode = group_mode(m.blocks, m.slip);
  m.joints = joint_activity(consolidated, trial_end, group);
  m.group_bound = limit_analysis(consolidated, settings, group);
  return m;
}

}  // namespace dda
