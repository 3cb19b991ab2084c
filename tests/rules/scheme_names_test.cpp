// Scheme knowledge lives in the rule files: outside src/rules/ (the surface
// schemes and their registry) and src/curves/ (the curve schemes), no source
// file holds a string literal that is exactly a scheme's name, so no engine,
// analysis, depth, limit or CLI code can test a scheme by name or pick one
// by name. Help texts may mention schemes inside longer sentences.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "subdiv/curves/curve_scheme.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {
namespace {

namespace fs = std::filesystem;

// Files where a name is a file format's keyword or a tag's value, not a
// scheme: OBJ's `t creasemethod chaikin` and the crease method's names.
bool is_keyword_use(const std::string& relative, const std::string& name) {
  return name == "chaikin" && (relative == "src/mesh/tags.cpp" || relative.starts_with("src/io/"));
}

TEST(SchemeNames, NoNameLiteralOutsideTheRuleFiles) {
  std::set<std::string> names;
  for (const Scheme* s : all_schemes()) names.emplace(s->name);
  for (const CurveScheme* s : all_curve_schemes()) names.emplace(s->name);
  ASSERT_GE(names.size(), 19u);

  const fs::path root = SUBDIV_SOURCE_DIR;
  const std::regex literal("\"([a-z0-9-]+)\"");
  int files = 0;
  for (const char* dir : {"src", "include", "tools"}) {
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(root / dir)) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
      const std::string relative = fs::relative(entry.path(), root).generic_string();
      if (relative.starts_with("src/rules/") || relative.starts_with("src/curves/")) continue;
      ++files;
      std::ifstream in(entry.path());
      std::string line;
      for (int number = 1; std::getline(in, line); ++number) {
        const std::string code = line.substr(0, line.find("//"));  // comments may name schemes
        for (std::sregex_iterator it(code.begin(), code.end(), literal), end; it != end; ++it) {
          const std::string name = (*it)[1];
          if (names.count(name) && !is_keyword_use(relative, name))
            ADD_FAILURE() << relative << ":" << number << ": the scheme name \"" << name
                          << "\" as a string; ask the scheme's traits instead";
        }
      }
    }
  }
  EXPECT_GE(files, 100);  // the walk reached the sources
}

}  // namespace
}  // namespace subdiv
