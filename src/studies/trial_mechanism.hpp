// The mechanism a failing strength-reduction trial shows: the blocks that moved, how (their
// displacement, rotation and mode), and the limit-analysis factor of that group moving on its
// own, every other block held (an upper bound of the slope's factor; docs/limit-analysis.md).
#pragma once

#include <string>
#include <vector>

#include "solver/world.hpp"
#include "studies/limit_analysis.hpp"

namespace dda {

struct BlockMotion {
  int block = -1;
  Vec2 displacement = Vec2::Zero();  // of its centroid (m)
  double rotation = 0.0;             // counter-clockwise (rad)
  // "sliding" (its rotation moves its corners less than its centroid moved), "rotating"
  // (more), or "falling" (no closed contact left at the trial's end).
  std::string mode;
};

// What one joint material's contacts on the mechanism's blocks did in the trial: which joints
// the blocks slip on and which open names the mechanism (sliding on the bedding; toppling:
// slip on the cross joints, the bedding opening at the columns' heels).
struct JointActivity {
  int joint = 0;      // index into the scene's joint materials
  long sliding = 0;   // contacts sliding at the trial's end
  long opened = 0;    // contacts closed when it started and open at its end
};

struct TrialMechanism {
  // The blocks whose centroid moved more than kMechanismShare of the largest displacement,
  // largest first.
  std::vector<BlockMotion> blocks;
  // "sliding", "rotating" or "falling" for one block; "sliding group" or "rotating group"
  // (by the mode of most of its blocks) for several; "none" when nothing moved.
  std::string mode;
  // Per joint material that has any, the contacts touching a block of the mechanism that
  // slide or opened, most sliding first.
  std::vector<JointActivity> joints;
  // The limit analysis with only these blocks free.
  LimitAnalysisResult group_bound;
};

// A block belongs to the mechanism when it moved more than this share of the largest.
inline constexpr double kMechanismShare = 0.1;

// A block's rotation from `before` to `after` (rad, counter-clockwise): the turn of its first
// vertex about its centroid (rigid and nearly rigid blocks; a strained block's first vertex
// stands for it).
double rotation_between(const Block& before, const Block& after);

// The blocks whose centroid moved more than kMechanismShare of the largest displacement
// from `consolidated` to `trial_end`, largest first, each with its mode (empty when nothing
// moved). The mechanism's blocks, and what its pictures draw.
std::vector<BlockMotion> moved_blocks(const World& consolidated, const World& trial_end);

// `consolidated`: where the trial started; `trial_end`: where it ended (same blocks).
TrialMechanism trial_mechanism(const World& consolidated, const World& trial_end,
                               const LimitAnalysisSettings& settings);

}  // namespace dda
