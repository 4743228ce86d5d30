#include "materials/material_point.hpp"

#include <algorithm>
#include <cmath>

namespace dda {

namespace {

// The values of the controlled quantities at a converged point.
Vec3 controlled_values(const std::array<Control, 3>& control, const Vec3& strain,
                       const Vec4& stress) {
  const Vec3 s = in_plane(stress);
  Vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = control[i] == Control::Strain ? strain[i] : s[i];
  return v;
}

struct Point {
  Vec3 strain = Vec3::Zero();
  MaterialResult result;  // stress, state and tangent at `strain`
};

class Driver {
 public:
  Driver(const MaterialParameters& params, const Vec4& s0, const MaterialPointSettings& settings)
      : params_(params), s0_(s0), settings_(settings) {}

  // Moves `at` to the controlled values `goal`, halving the increment when it fails.
  bool advance(Point& at, const std::array<Control, 3>& control, const Vec3& goal, int depth,
               std::vector<double>& residuals, std::string& message) const {
    const Vec3 from = controlled_values(control, at.strain, at.result.stress);
    const MixedIncrement inc = solve_mixed_increment(params_, at.result.state, s0_, control, goal,
                                                     predict(at, control, goal), settings_);
    if (inc.converged) {
      at.strain = inc.strain;
      at.result = inc.result;
      residuals = inc.residuals;
      return true;
    }
    if (depth >= settings_.max_halvings) {
      message = inc.message;
      return false;
    }
    const Vec3 mid = 0.5 * (from + goal);
    return advance(at, control, mid, depth + 1, residuals, message) &&
           advance(at, control, goal, depth + 1, residuals, message);
  }

 private:
  // Strain guess: the strain-controlled components at their goal, the others from the last
  // tangent (exact while the step stays elastic).
  static Vec3 predict(const Point& at, const std::array<Control, 3>& control, const Vec3& goal) {
    Vec3 guess = at.strain;
    const Vec3 s = in_plane(at.result.stress);
    Vec3 ds = Vec3::Zero();
    std::vector<int> free_components;
    for (int i = 0; i < 3; ++i) {
      if (control[i] == Control::Strain) {
        guess[i] = goal[i];
      } else {
        free_components.push_back(i);
        ds[i] = goal[i] - s[i];
      }
    }
    if (free_components.empty()) return guess;
    const Mat3& d = at.result.tangent;
    // ds_free = D_ff de_free + D_fc de_controlled.
    const int n = static_cast<int>(free_components.size());
    Eigen::MatrixXd dff(n, n);
    Eigen::VectorXd rhs(n);
    for (int a = 0; a < n; ++a) {
      rhs[a] = ds[free_components[a]];
      for (int j = 0; j < 3; ++j)
        if (control[j] == Control::Strain)
          rhs[a] -= d(free_components[a], j) * (guess[j] - at.strain[j]);
      for (int b = 0; b < n; ++b) dff(a, b) = d(free_components[a], free_components[b]);
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(dff);
    if (!lu.isInvertible()) return guess;
    const Eigen::VectorXd de = lu.solve(rhs);
    for (int a = 0; a < n; ++a) guess[free_components[a]] += de[a];
    return guess;
  }

  const MaterialParameters& params_;
  Vec4 s0_;
  MaterialPointSettings settings_;
};

}  // namespace

MixedIncrement solve_mixed_increment(const MaterialParameters& params, const MaterialState& start,
                                     const Vec4& initial_stress,
                                     const std::array<Control, 3>& control, const Vec3& target,
                                     const Vec3& guess, const MaterialPointSettings& settings) {
  MixedIncrement inc;
  std::vector<int> free_components;
  inc.strain = guess;
  for (int i = 0; i < 3; ++i) {
    if (control[i] == Control::Strain)
      inc.strain[i] = target[i];
    else
      free_components.push_back(i);
  }
  const int n = static_cast<int>(free_components.size());
  for (int it = 0; it <= settings.max_iterations; ++it) {
    inc.result = integrate(params, start, inc.strain, initial_stress);
    if (!inc.result.status.converged) {
      inc.message = inc.result.status.reason;
      return inc;
    }
    if (n == 0) {
      inc.converged = true;
      return inc;
    }
    const Vec3 s = in_plane(inc.result.stress);
    Eigen::VectorXd r(n);
    double scale =
        std::max(in_plane(inc.result.stress).cwiseAbs().maxCoeff(), 1e-12 * params.young);
    for (int a = 0; a < n; ++a) {
      r[a] = s[free_components[a]] - target[free_components[a]];
      scale = std::max(scale, std::abs(target[free_components[a]]));
    }
    inc.residuals.push_back(r.norm());
    if (r.norm() <= settings.relative_tolerance * scale) {
      inc.converged = true;
      return inc;
    }
    Eigen::MatrixXd j(n, n);
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        j(a, b) = inc.result.tangent(free_components[a], free_components[b]);
    Eigen::FullPivLU<Eigen::MatrixXd> lu(j);
    if (!lu.isInvertible()) {
      inc.message =
          "the stress-controlled components have no stiffness left (a stress "
          "target at or beyond the strength?)";
      return inc;
    }
    const Eigen::VectorXd de = lu.solve(-r);
    for (int a = 0; a < n; ++a) inc.strain[free_components[a]] += de[a];
  }
  inc.message =
      "Newton did not converge in " + std::to_string(settings.max_iterations) + " iterations";
  return inc;
}

MaterialPointOutcome run_material_point(const MaterialParameters& params,
                                        const Vec4& initial_stress,
                                        std::span<const PathSegment> path,
                                        const MaterialPointSink& sink,
                                        const MaterialPointSettings& settings) {
  MaterialPointOutcome run;
  std::array<Control, 3> control = {Control::Strain, Control::Strain, Control::Strain};
  Vec3 target = Vec3::Zero();

  Point at;
  at.result = integrate(params, MaterialState{}, at.strain, initial_stress);
  auto record = [&](int step, std::vector<double> residuals) {
    MaterialPointRow row;
    row.step = step;
    row.strain = at.strain;
    row.stress = at.result.stress;
    row.state = at.result.state;
    row.branch = at.result.branch;
    row.active_planes = at.result.active_planes;
    row.residuals = std::move(residuals);
    run.increments = step;
    if (!sink(row)) run.stopped = true;
    return !run.stopped;
  };
  const bool go_on = record(0, {});
  if (!at.result.status.converged) {
    run.ok = false;
    run.message = "the initial stress: " + at.result.status.reason;
    return run;
  }
  if (!go_on) return run;

  const Driver driver(params, initial_stress, settings);
  int step = 0;
  for (std::size_t seg = 0; seg < path.size(); ++seg) {
    const PathSegment& segment = path[seg];
    for (int i = 0; i < 3; ++i) {
      if (!segment.targets[i]) continue;
      control[i] = segment.targets[i]->control;
      target[i] = segment.targets[i]->value;
    }
    const Vec3 from = controlled_values(control, at.strain, at.result.stress);
    const int n = std::max(segment.steps, 1);
    for (int k = 1; k <= n; ++k) {
      const Vec3 goal = from + (target - from) * (static_cast<double>(k) / n);
      std::vector<double> residuals;
      std::string message;
      if (!driver.advance(at, control, goal, 0, residuals, message)) {
        run.ok = false;
        run.message =
            "segment " + std::to_string(seg) + ", increment " + std::to_string(k) + ": " + message;
        return run;
      }
      if (!record(++step, std::move(residuals))) return run;
    }
  }
  return run;
}

MaterialPointRun run_material_point(const MaterialParameters& params, const Vec4& initial_stress,
                                    std::span<const PathSegment> path,
                                    const MaterialPointSettings& settings) {
  MaterialPointRun run;
  const MaterialPointOutcome outcome = run_material_point(
      params, initial_stress, path,
      [&run](const MaterialPointRow& row) {
        run.rows.push_back(row);
        return true;
      },
      settings);
  run.ok = outcome.ok;
  run.message = outcome.message;
  return run;
}

}  // namespace dda
