// The one process of a build without DDA_MPI (app/ranks.hpp).
#include "app/ranks.hpp"

namespace dda {

RankSession::RankSession(int&, char**&) {}
RankSession::~RankSession() = default;
SoloRank::SoloRank() = default;
SoloRank::~SoloRank() = default;

int rank_index() { return 0; }
int rank_count() { return 1; }

std::vector<std::string> gather_to_all(const std::string& mine) { return {mine}; }
std::vector<std::string> gather_to_root(const std::string& mine) { return {mine}; }

void abort_all_ranks(int, const std::string&) {}

}  // namespace dda
