// finite_rotation and finite_rotation_polar: kept_in_block_frame's update, with T carrying
// the secant rotation column (R(r*) - I) / r* at an angle r* that follows the step's own r0
// through the contact loop (docs/paper-errata.md, item 6; secant_angles.hpp), and the
// rotating inertia's spins following the step's own mean rates with it.
#pragma once

#include "solver/rotation/kept_in_block_frame.hpp"

namespace dda {

class SecantColumn : public KeptInBlockFrame {
 public:
  // The secant columns start from the last step's r0.
  void start_step(const World& world, const StepContext& ctx, LoopTerms& terms,
                  RotationIterate& it) const override;
  // Each block's secant angle moves to the r0 just solved, and the spins to the answer's mean
  // rates; a block off by more than its tolerance counts (follow_secant_angles, spin_error).
  Followed follow_solve(const World& world, Eigen::VectorXd& d, const StepContext& ctx,
                        LoopTerms& terms, RotationIterate& it,
                        const SolveFollow& how) const override;

 private:
  Spin mean_spin(const World& world, const StepContext& ctx, std::size_t i, const Vec6& db) const;
  int follow_spins(const World& world, const Eigen::VectorXd& d, const StepContext& ctx,
                   LoopTerms& terms, const std::vector<double>* tolerance = nullptr) const;
  int follow_answer_spins(const World& world, const Eigen::VectorXd& d, const StepContext& ctx,
                          LoopTerms& terms, bool check) const;
  bool settle_free_secants(const World& world, const std::vector<int>& off, bool spinning,
                           std::vector<double>& angles, const StepContext& ctx,
                           LoopTerms& terms, BlockSystem& block_terms, Eigen::VectorXd& d) const;
};

}  // namespace dda
