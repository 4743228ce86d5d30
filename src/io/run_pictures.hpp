// Pictures of a run drawn from its output files alone (dda plot DIR, and the end of dda run):
// the blocks at a chosen time with exaggerated displacement, vectors and a chosen colouring;
// the contacts as joint states and as force chains; the energy account and the monitors'
// displacements against time. Reads DIR/blocks.pvd and its frames, DIR/contacts.pvd,
// DIR/history.csv, DIR/monitors.csv and DIR/summary.json as docs/output-format.md defines
// them; no Python, no solver.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/block_picture.hpp"
#include "io/chart.hpp"
#include "io/run_charts.hpp"
#include "io/vtk_polydata.hpp"

namespace dda {

// What the blocks are coloured by.
enum class PlotField { Displacement, Velocity, Stress, PlasticStrain, Material };

// "displacement", "velocity", "stress", "plastic-strain", "material": the names dda plot
// --field takes. Throws std::invalid_argument listing them for another name.
PlotField plot_field_from_name(const std::string& name);

struct PlotOptions {
  // s: for each, the last frame at or before it; none: the last frame. With several, the
  // pictures of each frame are named after its time (blocks_t1.5.png) and drawn with one
  // exaggeration (the last frame's automatic one unless given).
  std::vector<double> times;
  PlotField field = PlotField::Displacement;
  std::optional<double> exaggeration;  // displacements drawn times this; none: automatic
  int width_px = 1600;
};

// A frame of the run: its time and the file (relative to the run's directory) of the blocks
// and, when the run wrote them, of the contacts.
struct RunFrame {
  double time = 0.0;
  std::string blocks_file;
  std::string contacts_file;  // empty when there is none for this time
};

// The frames listed in DIR/blocks.pvd (and DIR/contacts.pvd), in order. Throws
// std::runtime_error naming the file when an index is missing or malformed.
std::vector<RunFrame> run_frames(const std::filesystem::path& run_dir);

// The blocks of frame `now` against the first frame `start` (same blocks, same vertices):
// each block's polygon at start + X (now - start), X the exaggeration, and its colour by the
// field; an arrow along each of the largest displacements; axes. The automatic exaggeration
// is 1 unless the largest vertex displacement is below a twentieth of the typical block size
// (the square root of the median free block area), then the round number (1, 2, 5 x 10^k)
// that draws it nearest a quarter of that size. `material_names` name the material indices
// (from summary.json) for the legend.
struct BlocksPicture {
  std::vector<PictureBlock> blocks;
  PictureOptions options;
  double exaggeration = 1.0;
};
BlocksPicture blocks_picture(const VtkPolyData& start, const VtkPolyData& now, double time,
                             const PlotOptions& options, const std::vector<std::string>& material_names);

// The blocks of `now` (pale, fixed ones grey) with each contact of `contacts` as a square
// coloured by its state: open, sliding, locked, bonded (any mode with its bond acting).
BlocksPicture joint_states_picture(const VtkPolyData& now, const VtkPolyData& contacts, double time,
                                   int width_px);

// The blocks of `now` with a force chain: a line between the centroids of each pair of
// blocks in contact, as wide as the sum of their contacts' normal forces (1 px up to 10 px
// for the largest pair's), compression only.
BlocksPicture force_chain_picture(const VtkPolyData& now, const VtkPolyData& contacts, double time,
                                  int width_px);

// Draws every picture the run's files allow into `out_dir` (created if needed): blocks.png,
// joint_states.png and force_chains.png (when the run wrote contacts at that time; with
// several times, blocks_tT.png and so on for each frame's time T), energy.png, monitors.png
// (when the run had monitors). Returns the files written. Throws
// std::runtime_error naming the file when one cannot be read or written, and
// std::invalid_argument for options the run cannot satisfy (a plastic-strain field of a run
// whose frames do not carry one, a time before the first frame).
std::vector<std::filesystem::path> plot_run(const std::filesystem::path& run_dir,
                                            const std::filesystem::path& out_dir, const PlotOptions& options);

}  // namespace dda
