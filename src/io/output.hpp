// Results out: DIR/summary.json, DIR/history.csv and a VTK XML PolyData series
// (DIR/vtk/step_NNNNNN.vtp indexed by DIR/blocks.pvd). See README "Output files".
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/output_file.hpp"
#include "io/vtk_polydata.hpp"
#include "solver/run.hpp"
#include "solver/scene.hpp"
#include "solver/world.hpp"

namespace dda {

// A monitor's velocity (m/s): Shi's first-order T at the point times its block's velocity
// (u0, v0, r0 and the strain rates, end of step); zero on a fixed block. monitors.csv's vx, vy.
Vec2 monitor_velocity(const World& world, const Monitor& monitor);

// A number as the CSV and VTK files write it: the shortest text that reads back as the same
// double.
std::string format_full_precision(double x);

// The blocks of an output step as a VTK piece (docs/output-format.md): one polygon per
// block, cell i block i, with the cell data block, fixed, (excavated,) area, rotation,
// stress, strain and velocity. io/vtk_polydata.hpp writes it.
VtkPolyData blocks_piece(const World& world);

// A series' frame file name: "vtk/PREFIX_000120.vtp" for step 120.
std::string vtk_frame_name(const char* prefix, int step);

// Where a run's output files stood after a step (a checkpoint keeps it): the frames indexed
// so far and the whole rows of each streamed CSV file, so that a restarted run continues
// them (docs/checkpoint.md, "Output of a restarted run").
struct OutputProgress {
  using Frames = std::vector<std::pair<double, std::string>>;  // (time, relative file name)
  Frames frames, contact_frames, bolt_frames;
  StreamProgress history, monitors, bolts;
};

class OutputWriter {
 public:
  // Creates `dir` (and dir/vtk) if needed, removes an earlier run's files and opens
  // history.csv. Throws std::runtime_error naming the path when it cannot write there, or
  // when one of the run's file names holds something other than a regular file (then
  // before anything is removed or written).
  OutputWriter(std::filesystem::path dir, const Scene& scene);

  // A restarted run's writer. When `dir` holds the files the checkpoint's run had written
  // (history.csv, monitors.csv and bolts.csv begin with the bytes `from` describes), they are
  // cut back to the checkpoint's step, the frames written after it removed, and the run's
  // files continue there; when `dir` has no history.csv, it starts afresh and holds the
  // continuation only. Throws InputError naming the file when `dir` holds another run's
  // history.
  OutputWriter(std::filesystem::path dir, const Scene& scene, const OutputProgress& from);

  // What has been written so far (for a checkpoint).
  OutputProgress progress() const;

  // Appends one history row per block for the world's current step and writes a VTK frame.
  // A write that fails throws naming the file; history.csv and monitors.csv then end with
  // the last whole step written before (io/output_file.hpp, StreamedFile).
  void record(const World& world);

  // Whether the world's step is one the scene records: every control.output_every steps,
  // and the last.
  bool due(const World& world) const;
  // record() when due(): what a run records after each step.
  void record_if_due(const World& world);
  // record() when not due(): a run that stopped early (a signal, a failed step) keeps its
  // last state.
  void record_last(const World& world);

  // Writes summary.json and the .pvd index. Called once at the end, also after divergence,
  // so that what was written is kept and indexed.
  void finish(const World& world, const RunStats& stats);

 private:
  std::filesystem::path dir_;
  const Scene& scene_;
  void record_monitors(const World& world);
  void record_bolts(const World& world);

  std::optional<StreamedFile> history_;
  std::optional<StreamedFile> monitors_;  // open when the scene has monitors
  std::optional<StreamedFile> bolts_;     // open when the scene has bolts
  std::vector<std::pair<double, std::string>> frames_;  // (time, relative file name)
  std::vector<std::pair<double, std::string>> contact_frames_;  // the same for contacts
  std::vector<std::pair<double, std::string>> bolt_frames_;     // and for bolts (with bolts)
};

}  // namespace dda
