// The house's layering, read from the sources: rooms include only the rooms below
// them, no chain of includes comes back to where it started, and the core library needs
// no SUNDIALS (CVODE and KINSOL serve the references in verification/reference only).
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// Each room and the rooms it may include (besides itself): the order of the README's
// "Layout" (common, what every room may use; kinematics, then materials, contact and
// cutting, then solver, the studies that run it many times, io, then the two front ends
// beside each other: app, the command line, and python, the Python module).
const std::map<std::string, std::set<std::string>> kMayInclude = {
    {"common", {}},
    {"kinematics", {"common"}},
    {"materials", {"common", "kinematics"}},
    {"contact", {"common", "kinematics"}},
    {"cutting", {"common", "kinematics"}},
    {"solver", {"common", "kinematics", "materials", "contact"}},
    {"studies", {"common", "kinematics", "materials", "contact", "solver"}},
    {"io", {"common", "kinematics", "materials", "contact", "cutting", "solver", "studies"}},
    {"app", {"common", "kinematics", "materials", "contact", "cutting", "solver", "studies", "io"}},
    {"python", {"common", "kinematics", "materials", "contact", "cutting", "solver", "studies", "io"}},
};

struct Include {
  std::string target;  // as written, e.g. "solver/world.hpp" or "cvode/cvode.h"
  bool quoted = false;
  int line = 0;
};

std::vector<Include> includes_of(const fs::path& file) {
  static const std::regex kInclude(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
  std::vector<Include> out;
  std::ifstream in(file);
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    std::smatch m;
    if (std::regex_search(text, m, kInclude)) out.push_back({m[2].str(), m[1].str() == "\"", line});
  }
  return out;
}

// Every source file of src/, as "room/file" (the form its includes use).
std::vector<std::string> sources(const fs::path& src) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(src)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".hpp" || ext == ".cpp")) {
      out.push_back(fs::relative(e.path(), src).generic_string());
    }
  }
  return out;
}

std::string room_of(const std::string& path) { return path.substr(0, path.find('/')); }

}  // namespace

TEST_CASE("every include of src/ runs downward, with no cycle, and none reaches SUNDIALS",
          "[layout]") {
  const fs::path src = fs::path(DDA_SOURCE_DIR) / "src";
  const std::vector<std::string> files = sources(src);
  // A sanity floor: the tree was read (it has well over a hundred files).
  REQUIRE(files.size() > 100);

  std::map<std::string, std::vector<std::string>> graph;  // file -> project headers it includes
  for (const std::string& file : files) {
    const std::string room = room_of(file);
    REQUIRE(kMayInclude.count(room) == 1);  // a new room must be placed in the order above
    for (const Include& inc : includes_of(src / file)) {
      INFO(file << ":" << inc.line << " includes " << inc.target);
      // SUNDIALS' headers are <cvode/...>, <kinsol/...>, <sundials/...>, <nvector/...>,
      // <sunlinsol/...>, <sunmatrix/...>.
      static const std::regex kSundials(R"(^(cvode|kinsol|sundials|nvector|sunlinsol|sunmatrix)/)");
      CHECK_FALSE(std::regex_search(inc.target, kSundials));
      if (!inc.quoted) continue;
      const std::string target_room = room_of(inc.target);
      if (!kMayInclude.count(target_room)) continue;  // not one of ours
      CHECK((target_room == room || kMayInclude.at(room).count(target_room) == 1));
      graph[file].push_back(inc.target);
    }
  }

  // No cycle in the file graph: a depth-first search that meets a file still on its path
  // has found one (the include guard would hide it from the compiler, not from a reader).
  std::map<std::string, int> state;  // 0 unseen, 1 on the path, 2 done
  std::vector<std::string> path;
  std::vector<std::string> cycles;
  auto visit = [&](auto&& self, const std::string& f) -> void {
    state[f] = 1;
    path.push_back(f);
    for (const std::string& g : graph[f]) {
      if (state[g] == 1) {
        std::string c;
        for (auto it = std::find(path.begin(), path.end(), g); it != path.end(); ++it) c += *it + " -> ";
        cycles.push_back(c + g);
      } else if (state[g] == 0) {
        self(self, g);
      }
    }
    path.pop_back();
    state[f] = 2;
  };
  for (const std::string& f : files) {
    if (state[f] == 0) visit(visit, f);
  }
  for (const std::string& c : cycles) UNSCOPED_INFO("cycle: " << c);
  CHECK(cycles.empty());
}
