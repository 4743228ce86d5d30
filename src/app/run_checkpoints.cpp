#include "app/run_checkpoints.hpp"

#include <utility>

namespace dda {

RunCheckpoints::RunCheckpoints(std::filesystem::path file, int every, const std::string& scene_text,
                               const Scene& scene, double earlier_wall_time)
    : file_(std::move(file)),
      every_(every),
      scene_text_(scene_text),
      scene_(scene),
      earlier_wall_time_(earlier_wall_time) {}

std::string RunCheckpoints::encode(const World& world, const RunStats& stats,
                                   const OutputProgress& output) const {
  if (earlier_wall_time_ == 0.0) return encode_checkpoint({scene_text_, scene_, world, stats, output});
  RunStats whole = stats;
  whole.wall_time_s += earlier_wall_time_;
  return encode_checkpoint({scene_text_, scene_, world, whole, output});
}

void RunCheckpoints::after_step(const World& world, const RunStats& stats, const OutputProgress& output) {
  if (every_ <= 0) return;
  last_ = encode(world, stats, output);
  last_step_ = world.step;
  if (world.step % every_ == 0) write_checkpoint_file(file_, last_);
}

bool RunCheckpoints::at_stop(const World& world, const RunStats& stats, const OutputProgress& output,
                             bool diverged) {
  if (!diverged) {
    // An interrupt comes between steps: the world is the last completed step's. Written
    // again even when after_step has just written it (the same bytes).
    if (last_step_ == world.step && !last_.empty()) {
      write_checkpoint_file(file_, last_);
    } else {
      write_checkpoint_file(file_, encode(world, stats, output));
    }
    return true;
  }
  if (last_.empty()) return false;
  write_checkpoint_file(file_, last_);
  return true;
}

}  // namespace dda
