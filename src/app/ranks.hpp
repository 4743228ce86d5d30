// The processes of a run started by mpirun (`mpirun -n R dda fos ...`), behind one small
// interface: ranks_mpi.cpp implements it with MPI and is compiled only when CMake's DDA_MPI
// is on; ranks_serial.cpp is the one process of every other build, so that no other file
// includes mpi.h and the default build needs no MPI at all (docs/mpi.md).
//
// Every rank reads the same input and runs the same code up to the work it shares; rank 0
// alone writes the outputs and prints. The messages are opaque bytes (io/rank_messages.hpp
// packs them).
#pragma once

#include <string>
#include <vector>

namespace dda {

// Starts the ranks (MPI_Init) for the life of main and ends them (MPI_Finalize) on exit.
// Ranks other than 0 have their standard output and error sent to /dev/null: they print
// nothing, and an error on one of them reaches the user through abort_all_ranks.
class RankSession {
 public:
  RankSession(int& argc, char**& argv);
  ~RankSession();
  RankSession(const RankSession&) = delete;
  RankSession& operator=(const RankSession&) = delete;
};

// While one lives, this rank works as a run of its own, as if alone: rank_index() 0,
// rank_count() 1, the collectives its own message only. A sweep gives each rank whole
// variants so (app/sweep_command.hpp). Not nested.
class SoloRank {
 public:
  SoloRank();
  ~SoloRank();
  SoloRank(const SoloRank&) = delete;
  SoloRank& operator=(const SoloRank&) = delete;
};

int rank_index();  // 0 .. rank_count() - 1
int rank_count();  // 1 without mpirun (or in a build without DDA_MPI)
inline bool is_root_rank() { return rank_index() == 0; }

// Each rank's bytes, on every rank, in rank order. Collective: every rank calls it.
std::vector<std::string> gather_to_all(const std::string& mine);
// Each rank's bytes on rank 0, in rank order; the other ranks get an empty list. Collective.
std::vector<std::string> gather_to_root(const std::string& mine);

// An error that only this rank may have met (one that does not follow from the input, which
// every rank reads alike): the message on this rank's own standard error, and every rank
// ended with `exit_code`, so that none waits for ever for a message that will not come.
// Without other ranks it only returns.
void abort_all_ranks(int exit_code, const std::string& message);

}  // namespace dda
