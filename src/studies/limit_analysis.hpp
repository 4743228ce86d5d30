// Factor of safety by rigid-block limit analysis (`dda fos --method limit-analysis`, and the
// second factor beside every strength-reduction search; docs/limit-analysis.md).
//
// The blocks of a world's present configuration are taken as rigid, its closed contacts as
// the points where neighbours press on each other (Livesley 1978: an interface's forces at
// the ends of the touching length, which DDA's vertex-to-edge contacts are), each carrying a
// normal force N (compression positive) and a shear force S. A factor F is admissible when
// forces exist that hold every free block in equilibrium under its weight and obey the
// joints' strengths divided by F:
//   |S| <= N tan(phi) / F + c l / F,    N >= -t l / F      (c, t only while bonded),
// a linear program in (N, S) for each F. The admissibility is monotone in F, so the factor
// is the largest admissible F, found by bisection. The friction is associative here (the
// static theorem of plasticity): for rigid blocks with Coulomb joints that makes the factor
// an upper bound of the non-associative one where the mechanism dilates (Gilbert, Casapulla
// and Ahmed 2006), and equal to it for pure sliding on planes.
#pragma once

#include <string>
#include <vector>

#include "kinematics/types.hpp"
#include "solver/world.hpp"

namespace dda {

struct LimitAnalysisSettings {
  double min_factor = 0.1;   // the search's range, as dda fos's
  double max_factor = 10.0;
  // The bisection stops when the bracket is no wider than this share of its lower end (a
  // tenth of dda fos's default search tolerance at F = 1).
  double relative_tolerance = 1e-3;
  // An F known to be inadmissible (0: none), in practice the smallest single-block bound's
  // upper end (BlockBound::upper): the search starts just below it.
  double known_inadmissible = 0.0;
};

// A free block's share of the collapse mechanism: its centroid's velocity and its angular
// velocity (counter-clockwise), scaled so that the fastest centroid moves at 1.
struct MechanismMotion {
  int block = -1;
  Vec2 velocity = Vec2::Zero();
  double angular_velocity = 0.0;  // 1/m in the same scaling
};

struct LimitAnalysisResult {
  // False when the world holds what the analysis does not model (point loads, pins, joint
  // water, a free block that touches nothing): `reason` says which.
  bool computed = false;
  std::string reason;
  // True when an admissible and an inadmissible F lie in the range: factor is the bracket's
  // lower end (admissible), upper its upper end.
  bool found = false;
  double factor = 0.0;
  double upper = 0.0;
  // Without a bracket: every F in the range admissible (stable beyond max_factor) or none
  // (not even min_factor).
  bool admissible_at_max = false;
  int free_blocks = 0;
  int contacts = 0;         // closed contacts the program uses
  int programs = 0;         // linear programs solved
  double wall_time_s = 0.0;
  // The collapse mechanism at `upper` (the dual of the equilibrium equations): every free
  // block that moves at more than 1e-3 of the fastest, fastest first.
  std::vector<MechanismMotion> mechanism;
};

// The limit analysis of `world` as it stands (its blocks, closed contacts, their bonds,
// gravity) with the scene's own joint laws (scene_joint_laws: not a stage's replacement). With `free_only` non-empty, only those blocks
// (indices) are free and every other block is held fixed: the factor of that group moving
// on its own, an upper bound of the whole slope's.
LimitAnalysisResult limit_analysis(const World& world, const LimitAnalysisSettings& settings,
                                   const std::vector<int>& free_only = {});

// Each free block alone (every other block held): its limit-analysis factor, the smallest
// first. Blocks that are admissible up to max_factor are left out.
struct BlockBound {
  int block = -1;
  double factor = 0.0;  // the bracket's admissible end
  double upper = 0.0;   // its inadmissible end: the slope is not admissible there either
};
std::vector<BlockBound> single_block_bounds(const World& world,
                                            const LimitAnalysisSettings& settings);

}  // namespace dda
