// The strength-reduction search of `dda fos` over the ranks of an MPI run (app/ranks.hpp):
// every rank runs the same search (find_factor_of_safety), each round's trials shared out
// over the ranks, each rank's share on its own threads, and the verdicts gathered to every
// rank, so that all of them take the same next round (docs/mpi.md).
#pragma once

#include <functional>
#include <vector>

#include "studies/strength_reduction.hpp"

namespace dda {

// `per_rank.jobs` trials at once on each rank: the search's rounds are per_rank.jobs x
// rank_count() trials wide, and its trials, verdicts and factor those of
// find_factor_of_safety at that width (and so those of `dda fos --jobs` that width on one
// process, whose search on threads follows the same path). A trial's `world` is kept on the
// rank that ran it only; the others' trials carry an empty world (see trial_worlds_on_root).
// `done` is called on every rank for every trial of a round, in the round's order, once the
// round is gathered.
FosResult search_over_ranks(const World& consolidated, const FosSettings& per_rank,
                            const std::function<void(const TrialResult&)>& done,
                            const StopQuery& stop);

// On rank 0: the trials of `result` at `factors` whose world another rank kept are run again
// here (on per_rank.jobs threads), so that their worlds can be drawn and analysed; their
// gathered numbers stay. Returns how many were run again. Other ranks: nothing.
int trial_worlds_on_root(FosResult& result, const World& consolidated, const FosSettings& per_rank,
                         const std::vector<double>& factors, const StopQuery& stop);

}  // namespace dda
