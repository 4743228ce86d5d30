// The material-point driver (the core of `dda material-point`): a strain or
// stress path applied to one material point, each in-plane component under strain or
// stress control, mixed control solved by Newton with the consistent tangent.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "materials/material.hpp"

namespace dda {

enum class Control { Strain, Stress };

struct ComponentTarget {
  Control control = Control::Strain;
  double value = 0.0;  // exx, eyy, gxy (engineering) or sxx, syy, sxy (Pa)
};

// One segment moves each named component linearly from its value at the segment's start to
// its target over `steps` equal increments. Components: 0 = xx, 1 = yy, 2 = xy. A component
// not named keeps its last control and target (strain control with target 0 at the start).
struct PathSegment {
  int steps = 1;  // >= 1
  std::array<std::optional<ComponentTarget>, 3> targets;
};

struct MaterialPointSettings {
  // Newton stops when the stress residual is below this times the stress scale (the larger
  // of the stresses and targets): 1e-10, a hundred times above what round-off allows in a
  // return, far below any plotted digit.
  double relative_tolerance = 1e-10;
  int max_iterations = 25;
  int max_halvings = 12;  // an increment that fails is halved, at most this deep
};

struct MaterialPointRow {
  int step = 0;                // 0: the start, before any increment
  Vec3 strain = Vec3::Zero();  // exx, eyy, gxy
  Vec4 stress = Vec4::Zero();  // sxx, syy, szz, sxy
  MaterialState state;
  Branch branch = Branch::Elastic;
  unsigned active_planes = 0;
  std::vector<double> residuals;  // Newton residual norms (Pa) of the step's last solve
};

struct MaterialPointRun {
  std::vector<MaterialPointRow> rows;
  bool ok = true;
  std::string message;  // why it stopped early, when !ok
};

// One increment under mixed control from `start` (state, converged at the previous step):
// components with Control::Strain take their strain from `target`, the others are solved
// for so that their stress equals `target`, starting from `guess`.
struct MixedIncrement {
  bool converged = false;
  Vec3 strain = Vec3::Zero();
  MaterialResult result;
  std::vector<double> residuals;
  std::string message;
};
MixedIncrement solve_mixed_increment(const MaterialParameters& params, const MaterialState& start,
                                     const Vec4& initial_stress,
                                     const std::array<Control, 3>& control, const Vec3& target,
                                     const Vec3& guess, const MaterialPointSettings& settings = {});

// What a streamed run ended with (run_material_point with a sink).
struct MaterialPointOutcome {
  bool ok = true;        // false: an increment could not be followed (message says which)
  bool stopped = false;  // the sink asked to stop (dda material-point: SIGINT or SIGTERM)
  std::string message;
  int increments = 0;    // increments completed (rows given to the sink, less the start)
};

// Receives each row as it is made: the start, then the end of every increment. Returns
// false to stop the run there.
using MaterialPointSink = std::function<bool(const MaterialPointRow&)>;

// Runs the whole path, handing each row to `sink` and keeping none: memory does not grow
// with the number of increments (a path of 1e9 increments kept every row: 2.6 GB in 10 s).
MaterialPointOutcome run_material_point(const MaterialParameters& params,
                                        const Vec4& initial_stress,
                                        std::span<const PathSegment> path,
                                        const MaterialPointSink& sink,
                                        const MaterialPointSettings& settings = {});

// Runs the whole path; rows hold the start and the end of every increment.
MaterialPointRun run_material_point(const MaterialParameters& params, const Vec4& initial_stress,
                                    std::span<const PathSegment> path,
                                    const MaterialPointSettings& settings = {});

}  // namespace dda
