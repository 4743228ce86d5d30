#include "studies/recent_motion.hpp"

#include <algorithm>
#include <cassert>
#include <utility>

namespace dda {

double farthest_motion(const std::vector<Vec2>& from, const std::vector<Vec2>& to) {
  assert(from.size() == to.size());
  double d = 0.0;
  for (std::size_t i = 0; i < from.size(); ++i) d = std::max(d, (to[i] - from[i]).norm());
  return d;
}

std::vector<Vec2> free_block_centroids(const World& world) {
  std::vector<Vec2> out;
  for (const Block& b : world.blocks) {
    if (!b.fixed) out.push_back(b.moments.centroid);
  }
  return out;
}

RecentMotion::RecentMotion(std::size_t window, MotionMark start)
    : start_(std::move(start)), ring_(window) {
  assert(window > 0);
}

const MotionMark& RecentMotion::window_start(long step) const {
  const auto n = static_cast<long>(ring_.size());
  if (step <= n) return start_;
  const MotionMark& m = ring_[static_cast<std::size_t>(step % n)];
  return m.step == step ? ring_[static_cast<std::size_t>((step + 1) % n)] : m;
}

void RecentMotion::record(MotionMark mark) {
  const auto n = static_cast<long>(ring_.size());
  ring_[static_cast<std::size_t>(mark.step % n)] = std::move(mark);
}

}  // namespace dda
