// The ranks of an MPI run (app/ranks.hpp); compiled only when CMake's DDA_MPI is on.
// MPI's C interface only: OpenMPI's deprecated C++ bindings, which mpi.h would otherwise
// pull in for a C++ file, do not compile clean under -Wextra.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <fcntl.h>
#include <mpi.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <stdexcept>

#include "app/ranks.hpp"

namespace dda {
namespace {

int g_rank = 0;
int g_size = 1;
bool g_solo = false;      // SoloRank: this rank works alone
int g_saved_stderr = -1;  // a non-root rank's own standard error, kept for abort_all_ranks

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

// Sizes first, then the bytes: every rank's message may have its own length.
std::vector<std::string> split(const std::vector<char>& all, const std::vector<int>& sizes) {
  std::vector<std::string> out;
  std::size_t at = 0;
  for (int s : sizes) {
    out.emplace_back(all.data() + at, static_cast<std::size_t>(s));
    at += static_cast<std::size_t>(s);
  }
  return out;
}

std::vector<int> offsets_of(const std::vector<int>& sizes) {
  std::vector<int> offsets(sizes.size(), 0);
  for (std::size_t k = 1; k < sizes.size(); ++k) offsets[k] = offsets[k - 1] + sizes[k - 1];
  return offsets;
}

int message_size(const std::string& mine) {
  if (mine.size() > static_cast<std::size_t>(INT32_MAX)) {
    throw std::runtime_error("MPI: a message of more than 2 GB");
  }
  return static_cast<int>(mine.size());
}

}  // namespace

RankSession::RankSession(int& argc, char**& argv) {
  // Threads run trials and samples, but only the main thread calls MPI.
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_size);
  if (g_rank != 0) {
    std::fflush(stdout);
    std::fflush(stderr);
    g_saved_stderr = dup(STDERR_FILENO);
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0) {
      dup2(null, STDOUT_FILENO);
      dup2(null, STDERR_FILENO);
      close(null);
    }
  }
}

RankSession::~RankSession() { MPI_Finalize(); }

SoloRank::SoloRank() { g_solo = true; }
SoloRank::~SoloRank() { g_solo = false; }

int rank_index() { return g_solo ? 0 : g_rank; }
int rank_count() { return g_solo ? 1 : g_size; }

std::vector<std::string> gather_to_all(const std::string& mine) {
  if (g_solo) return {mine};
  const int size = message_size(mine);
  std::vector<int> sizes(static_cast<std::size_t>(g_size), 0);
  check(MPI_Allgather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, MPI_COMM_WORLD), "Allgather");
  const std::vector<int> offsets = offsets_of(sizes);
  std::vector<char> all(static_cast<std::size_t>(offsets.back() + sizes.back()) + 1);
  check(MPI_Allgatherv(mine.data(), size, MPI_CHAR, all.data(), sizes.data(), offsets.data(),
                       MPI_CHAR, MPI_COMM_WORLD),
        "Allgatherv");
  return split(all, sizes);
}

std::vector<std::string> gather_to_root(const std::string& mine) {
  if (g_solo) return {mine};
  const int size = message_size(mine);
  std::vector<int> sizes(static_cast<std::size_t>(g_size), 0);
  check(MPI_Gather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "Gather");
  const std::vector<int> offsets = offsets_of(sizes);
  std::vector<char> all(g_rank == 0 ? static_cast<std::size_t>(offsets.back() + sizes.back()) + 1 : 1);
  check(MPI_Gatherv(mine.data(), size, MPI_CHAR, all.data(), sizes.data(), offsets.data(), MPI_CHAR,
                    0, MPI_COMM_WORLD),
        "Gatherv");
  if (g_rank != 0) return {};
  return split(all, sizes);
}

void abort_all_ranks(int exit_code, const std::string& message) {
  if (g_size <= 1) return;
  if (g_rank != 0 && g_saved_stderr >= 0) {
    const std::string line = "dda: rank " + std::to_string(g_rank) + ": " + message + "\n";
    [[maybe_unused]] const ssize_t n = write(g_saved_stderr, line.data(), line.size());
  }
  MPI_Abort(MPI_COMM_WORLD, exit_code);
}

}  // namespace dda
