// Checkpoints (docs/checkpoint.md): the whole state of a run in one versioned binary file,
// so that `dda run --restart FILE` continues it as if it had never stopped. The file holds
// the scene's own JSON text (a restart needs no scene path and cannot be paired with the
// wrong scene), the world's state, the run's counts so far and where its output files
// stood. Doubles are stored as their bytes: the state read back is the state written, bit
// for bit.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "io/output.hpp"
#include "solver/run_stats.hpp"
#include "solver/scene.hpp"
#include "solver/workspace_record.hpp"
#include "solver/world.hpp"
#include "studies/strength_reduction.hpp"

namespace dda {

// The file's format version: raised whenever what it holds or how changes. A file of
// another version is refused (a restart is exact only within one version of the program's
// state).
// 2: the step loop's workspace (the linear solver's kept factor) is stored.
inline constexpr std::uint32_t kCheckpointVersion = 2;

// The usual file names: a run's (dda run --checkpoint-every) and a fos consolidation's.
inline constexpr const char* kRunCheckpointName = "checkpoint.ddack";
inline constexpr const char* kConsolidationCheckpointName = "consolidated.ddack";

// What a checkpoint holds, ready to continue: the scene rebuilt from its text, the world as
// it was, the counts so far and the output files' progress.
struct Checkpoint {
  std::string scene_text;  // the scene file's JSON (or the built-in default scene's)
  Scene scene;             // parsed from scene_text, with the run's VTK format
  World world;
  RunStats stats;
  OutputProgress output;
  // The step loop's workspace (its kept factor), when the run that wrote it had one to
  // store; restore_workspace puts it into the StepWorkspace the continued run steps with.
  std::optional<WorkspaceRecord> workspace;
};

// The state to store: the scene's text and name, and what the run has reached.
struct CheckpointSource {
  const std::string& scene_text;
  const Scene& scene;  // its source (file name) and the VTK format the run writes
  const World& world;
  const RunStats& stats;
  const OutputProgress& output;
  // The workspace the run steps with (nullptr: none stored; the continued run then starts
  // with a fresh factor and agrees with the unbroken run to the solver's tolerance).
  const StepWorkspace* workspace = nullptr;
};

// The file's bytes (header, payload, checksum).
std::string encode_checkpoint(const CheckpointSource& source);

// Writes the bytes to `path` whole: a temporary name beside it, renamed over it when
// complete, so that a run stopped while writing keeps the checkpoint before. Throws
// std::runtime_error naming the path when it cannot write there.
void write_checkpoint_file(const std::filesystem::path& path, const std::string& bytes);

// Reads a checkpoint. Throws InputError naming the file for a file that is not a
// checkpoint, is of another format version or another machine's byte order, is cut short
// or damaged (its checksum), or holds a scene that no longer reads.
Checkpoint read_checkpoint(const std::filesystem::path& path);

// The same from bytes; `name` is what the errors call them.
Checkpoint decode_checkpoint(const std::string& bytes, const std::string& name);

// ---- dda fos: the consolidated state the trials start from ----

// What a fos consolidation is made from besides its scene: the strength factor it
// consolidated at and the seismic coefficient its gravity carries.
struct ConsolidationSettings {
  double factor = 1.0;
  double seismic_coefficient = 0.0;
};

// The file's bytes for a consolidation of the scene read from `scene_text`.
std::string encode_consolidation(const std::string& scene_text, const Scene& scene,
                                 const ConsolidationSettings& settings,
                                 const Consolidation& consolidation);

// Reads the consolidation that `dda fos` wrote. `scene` is the scene read from `scene_text`
// as the fos command has it (its seismic coefficient applied): the file must hold the same
// text and have been consolidated with the same settings, else InputError naming the file
// says which differs. The world is rebuilt from `scene` and the stored state.
Consolidation read_consolidation(const std::filesystem::path& path, const std::string& scene_text,
                                 const Scene& scene, const ConsolidationSettings& settings);

}  // namespace dda
