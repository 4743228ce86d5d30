// What the ranks of an MPI run send one another (app/ranks.hpp): a trial's result without
// its world, and a sample's outcome, as bytes. Numbers travel as their bytes, so that a
// result gathered from another rank is the same to the last bit as one run here (the ranks
// of one run share a machine type).
#pragma once

#include <string>
#include <vector>

#include "studies/probabilistic_fos.hpp"
#include "studies/strength_reduction.hpp"

namespace dda {

// Every field but `world` (the state the trial ended in, which stays where the trial ran).
std::string pack_trials(const std::vector<TrialResult>& trials);
std::vector<TrialResult> unpack_trials(const std::string& bytes);

std::string pack_samples(const std::vector<SampleOutcome>& samples);
std::vector<SampleOutcome> unpack_samples(const std::string& bytes);

}  // namespace dda
