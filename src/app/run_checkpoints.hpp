// dda run's checkpoints (docs/checkpoint.md): the state after every N-th step written to
// DIR/checkpoint.ddack (each replacing the last, whole), and the last completed step's when
// the run is interrupted or diverges, so that `dda run --restart` continues from there.
#pragma once

#include <filesystem>
#include <string>

#include "io/checkpoint.hpp"
#include "io/output.hpp"
#include "solver/step.hpp"

namespace dda {

class RunCheckpoints {
 public:
  // `every` 0: none on the way, and only an interrupted run leaves one.
  // `earlier_wall_time`: the seconds the run had taken before this process (a restart's),
  // added to the wall time stored.
  // `workspace`: the step loop's, whose kept factor each checkpoint stores with the world.
  RunCheckpoints(std::filesystem::path file, int every, const std::string& scene_text,
                 const Scene& scene, double earlier_wall_time, const StepWorkspace& workspace);

  // After each completed step, once its output is recorded: keeps the step's state (when
  // checkpoints are taken on the way) and writes it every `every` steps.
  void after_step(const World& world, const RunStats& stats, const OutputProgress& output);

  // The run stopped: writes the last completed step's state. `world`, `stats` and the
  // workspace are that step's when the run was interrupted (the step ended whole); after a
  // divergence they are the failed step's, and the state kept after the last completed step
  // is written instead (nothing when checkpoints are not taken on the way), without the
  // kept factor: a run continued from there starts with a new one. Returns whether one
  // was written.
  bool at_stop(const World& world, const RunStats& stats, const OutputProgress& output,
               bool diverged);

  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  int every_;
  const std::string& scene_text_;
  const Scene& scene_;
  double earlier_wall_time_;
  const StepWorkspace& workspace_;
  std::string encode(const World& world, const RunStats& stats, const OutputProgress& output,
                     bool with_workspace) const;
  std::string last_;  // the encoded state of the last completed step (with `every` > 0)
};

}  // namespace dda
