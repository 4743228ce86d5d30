// The pictures of a factor-of-safety search (dda fos): the mechanism of a trial and of the
// limit analysis drawn over the slope with exaggerated motion, and the trials' verdicts
// against F with the bracket. Each writes one PNG, whole or not at all, and throws
// std::runtime_error naming the path when it cannot.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "io/block_picture.hpp"
#include "io/chart.hpp"
#include "solver/world.hpp"
#include "studies/limit_analysis.hpp"
#include "studies/strength_reduction.hpp"

namespace dda {

// What a slope picture draws: the blocks and the options (title, arrows, labels, legend),
// built apart from the file so that tests can find where things land (picture_frame).
struct SlopePicture {
  std::vector<PictureBlock> blocks;
  PictureOptions options;
  std::size_t moving_from = 0;  // blocks[moving_from..] are the moving ones, drawn moved
  double typical_size = 1.0;    // m: the square root of the median free block's area
};

// The same picture around its moving blocks, when they cover less than 40 % of the slope's
// width and height: the box of the moving blocks grown on every side by its own size or
// three typical blocks, whichever is more; the slope's blocks whose
// vertices' mean lies in it, the moving ones, and the arrows and labels starting in it.
// Nothing when there are no moving blocks or they are not small on the slope.
std::optional<SlopePicture> close_up(const SlopePicture& whole);

// Each writer below also writes NAME_close.png beside NAME.png when close_up gives one.

// One trial's mechanism: every block where the consolidation left it (fixed grey, free
// pale); each block that moved (studies/trial_mechanism, moved_blocks) drawn again,
// displaced rigidly by its centroid's displacement u and rotation theta, both multiplied by
// one factor X that makes the largest move a quarter of a typical block's size, coloured by
// |u| and outlined; an arrow from its centroid along u (the 60 largest), its block number
// (the 25 largest, as report.json numbers blocks) on its moved place; axes in metres. `what`
// opens the title.
SlopePicture mechanism_picture(const World& consolidated, const TrialResult& trial, const std::string& what);
void write_mechanism_picture(const std::filesystem::path& path, const World& consolidated,
                             const TrialResult& trial, const std::string& what);

// The limit analysis's mechanism: each moving block moved rigidly along its mechanism
// velocity so that the fastest moves a quarter of a typical block's size, coloured by its
// speed and outlined. Writes nothing when the analysis found no mechanism.
SlopePicture limit_analysis_picture(const World& world, const LimitAnalysisResult& la);
void write_limit_analysis_picture(const std::filesystem::path& path, const World& world,
                                  const LimitAnalysisResult& la);

// The trials' largest displacement against F on a log axis, stable ones blue, failing ones
// red; the failure displacement as a horizontal line, the bracket shaded and the factor of
// safety (and the limit analysis's upper bound, when given) as vertical lines. Writes nothing
// when there were no trials.
ChartOptions trials_chart(const FosResult& result, double failure_displacement, const LimitAnalysisResult* la);
void write_trials_chart(const std::filesystem::path& path, const FosResult& result,
                        double failure_displacement, const LimitAnalysisResult* la);

}  // namespace dda
