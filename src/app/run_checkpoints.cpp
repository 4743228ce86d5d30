#include "app/run_checkpoints.hpp"

#include <utility>

namespace dda {

RunCheckpoints::RunCheckpoints(std::filesystem::path file, int every, const std::string& scene_text,
                               const Scene& scene, double earlier_wall_time,
                               const StepWorkspace& workspace)
    : file_(std::move(file)),
      every_(every),
      scene_text_(scene_text),
      scene_(scene),
      earlier_wall_time_(earlier_wall_time),
      workspace_(workspace) {}

std::string RunCheckpoints::encode(const World& world, const RunStats& stats,
                                   const OutputProgress& output, bool with_workspace) const {
  const StepWorkspace* workspace = with_workspace ? &workspace_ : nullptr;
  if (earlier_wall_time_ == 0.0) {
    return encode_checkpoint({scene_text_, scene_, world, stats, output, workspace});
  }
  RunStats whole = stats;
  whole.wall_time_s += earlier_wall_time_;
  return encode_checkpoint({scene_text_, scene_, world, whole, output, workspace});
}

void RunCheckpoints::after_step(const World& world, const RunStats& stats, const OutputProgress& output) {
  if (every_ <= 0) return;
  // Every step's state is kept for a divergence in the next one (which leaves the world and
  // the workspace the failed step's); the kept factor only in the files written (it is a
  // copy of the system matrix, which on the 40-polygon hopper cost 10 % of a step).
  const bool write = world.step % every_ == 0;
  last_ = encode(world, stats, output, write);
  if (write) write_checkpoint_file(file_, last_);
}

bool RunCheckpoints::at_stop(const World& world, const RunStats& stats, const OutputProgress& output,
                             bool diverged) {
  if (!diverged) {
    // An interrupt comes between steps: the world and the workspace are the last completed
    // step's, the kept factor with them.
    write_checkpoint_file(file_, encode(world, stats, output, true));
    return true;
  }
  if (last_.empty()) return false;
  write_checkpoint_file(file_, last_);
  return true;
}

}  // namespace dda
