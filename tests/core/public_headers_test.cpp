// The public surface: subdiv/subdiv.h includes every module's umbrella, each
// umbrella includes every public header of its module, and the whole set
// compiles on its own in this translation unit (nothing else included first).

#include "subdiv/subdiv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace subdiv {
namespace {

namespace fs = std::filesystem;

std::string file_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(PublicHeaders, UmbrellasListEveryHeader) {
  const fs::path include = fs::path(SUBDIV_SOURCE_DIR) / "include" / "subdiv";
  const std::string all = file_text(include / "subdiv.h");
  int headers = 0;
  for (const fs::directory_entry& module : fs::directory_iterator(include)) {
    if (!module.is_directory()) continue;
    const std::string name = module.path().filename().string();
    EXPECT_NE(all.find("#include \"subdiv/" + name + ".h\""), std::string::npos) << "subdiv.h lacks " << name << ".h";
    const std::string umbrella = file_text(include / (name + ".h"));
    ASSERT_FALSE(umbrella.empty()) << "no umbrella header subdiv/" << name << ".h";
    for (const fs::directory_entry& header : fs::directory_iterator(module.path())) {
      const std::string file = header.path().filename().string();
      ++headers;
      EXPECT_NE(umbrella.find("#include \"subdiv/" + name + "/" + file + "\""), std::string::npos)
          << "subdiv/" << name << ".h lacks " << file;
    }
  }
  EXPECT_GE(headers, 50);
}

// What a user sees through the umbrella alone.
TEST(PublicHeaders, OneIncludeRefines) {
  PolygonMesh cube;
  cube.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (const auto& f : {std::array{0, 3, 2, 1}, std::array{4, 5, 6, 7}, std::array{0, 1, 5, 4}, std::array{1, 2, 6, 5},
                        std::array{2, 3, 7, 6}, std::array{3, 0, 4, 7}})
    cube.add_face(f);
  RefineOptions options;
  options.levels = 2;
  const Hierarchy h = refine_hierarchy(cube, default_scheme(), options);
  EXPECT_EQ(h.finest().mesh.face_count(), 96);
}

}  // namespace
}  // namespace subdiv
