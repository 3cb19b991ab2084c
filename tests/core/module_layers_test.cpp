// The modules form layers: a module's sources and public headers include
// only its own module and the modules below it, so no module calls back
// into one that builds on it.
//
//   core < mesh < io, topology < curves < rules < refine < analysis < depth < eval

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <string_view>

namespace subdiv {
namespace {

namespace fs = std::filesystem;

const std::map<std::string, int>& layer_of() {
  static const std::map<std::string, int> layers = {
      {"core", 0},   {"mesh", 1},  {"io", 2},       {"topology", 2}, {"curves", 3},
      {"rules", 4},  {"refine", 5}, {"analysis", 6}, {"depth", 7},    {"eval", 8},
  };
  return layers;
}

// The module an include line names: "subdiv/<module>/..." or "../<module>/...";
// empty for a system or same-folder include.
std::string included_module(const std::string& line) {
  for (const std::string_view prefix : {"#include \"subdiv/", "#include \"../"}) {
    if (!line.starts_with(prefix)) continue;
    const std::size_t begin = prefix.size(), slash = line.find('/', begin);
    if (slash != std::string::npos) return line.substr(begin, slash - begin);
  }
  return {};
}

TEST(ModuleLayers, NoModuleIncludesOneAboveIt) {
  const fs::path root = SUBDIV_SOURCE_DIR;
  int includes = 0;
  for (const auto& [module, layer] : layer_of()) {
    for (const fs::path& dir : {root / "src" / module, root / "include" / "subdiv" / module}) {
      ASSERT_TRUE(fs::is_directory(dir)) << dir;
      for (const fs::directory_entry& entry : fs::recursive_directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue;
        std::ifstream in(entry.path());
        std::string line;
        for (int number = 1; std::getline(in, line); ++number) {
          const std::string other = included_module(line);
          if (other.empty() || other == module) continue;
          ++includes;
          const auto it = layer_of().find(other);
          ASSERT_NE(it, layer_of().end()) << entry.path() << ":" << number << ": unknown module " << other;
          EXPECT_LT(it->second, layer)
              << fs::relative(entry.path(), root).generic_string() << ":" << number << ": " << module
              << " includes " << other << ", which is not below it";
        }
      }
    }
  }
  EXPECT_GE(includes, 100);  // the walk read the includes
}

}  // namespace
}  // namespace subdiv
