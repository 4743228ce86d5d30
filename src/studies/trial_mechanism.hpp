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
  // "toppling" when it turns about a point of its own (the instantaneous centre of its motion
  // within 1.5 radii of its centroid) that lies below the centroid, within 45 degrees of the
  // gravity direction (tipping on its toe); "rotating" about a point of its own elsewhere;
  // "sliding" otherwise (the centre far off); "falling" when no closed contact is left at
  // the trial's end.
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

// How the mechanism's sliding contacts slip relative to the way their blocks move: along
// the motion (a slide on its base, or layers sliding past each other down the slope) or
// across it (columns that lean out and slip on the joints between them: flexural toppling).
struct SlipDirections {
  long along = 0;   // sliding contacts whose edge lies within 30 degrees of the motion
  long across = 0;  // beyond 60 degrees
  long between = 0;
};

struct TrialMechanism {
  // The blocks whose centroid moved more than kMechanismShare of the largest displacement,
  // largest first.
  std::vector<BlockMotion> blocks;
  // For one block, its mode ("sliding", "toppling", "rotating", "falling"). For several:
  // "toppling group", "rotating group" or "falling group" when most of its blocks topple,
  // rotate or fall; else by its sliding contacts: "toppling group" when at least twice as
  // many slip across the motion as along it, "sliding group" when at least twice as many
  // slip along it, "sliding and toppling group" otherwise. "none" when nothing moved.
  std::string mode;
  // The sliding contacts touching a block of the mechanism (the motion of a contact: that of
  // its block in the mechanism, the mean when both are).
  SlipDirections slip;
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

// The mode of a group of blocks from the modes of its blocks and its slip directions (the
// rule of TrialMechanism::mode).
std::string group_mode(const std::vector<BlockMotion>& blocks, const SlipDirections& slip);

// `consolidated`: where the trial started; `trial_end`: where it ended (same blocks).
TrialMechanism trial_mechanism(const World& consolidated, const World& trial_end,
                               const LimitAnalysisSettings& settings);

}  // namespace dda
