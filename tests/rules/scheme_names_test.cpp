// Scheme knowledge lives in the rule files: outside src/rules/ (the surface
// schemes and their registry) and src/curves/ (the curve schemes), no source
// file holds a string literal that is exactly a scheme's name, so no engine,
// analysis, depth, limit or CLI code can test a scheme by name or pick one
// by name. Help texts may mention schemes inside longer sentences.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "subdiv/curves/curve_scheme.h"
#include "subdiv/rules/scheme.h"

namespace subdiv {
namespace {

namespace fs = std::filesystem;

// The contents of every double-quoted literal made only of [a-z0-9-].
// (A hand scanner, not std::regex: gcc 12 warns inside <regex> at -O1.)
std::vector<std::string> name_like_literals(const std::string& code) {
  std::vector<std::string> found;
  for (std::size_t open = code.find('"'); open != std::string::npos;) {
    const std::size_t close = code.find('"', open + 1);
    if (close == std::string::npos) break;
    const std::string inside = code.substr(open + 1, close - open - 1);
    const bool name_like = !inside.empty() && std::all_of(inside.begin(), inside.end(), [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
    });
    if (name_like) found.push_back(inside);
    open = code.find('"', close + 1);
  }
  return found;
}

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
        for (const std::string& name : name_like_literals(code)) {
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
