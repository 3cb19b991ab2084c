// Every mesh of the shared collection (../shared/data/meshes) loads, and the
// statistics our topology computes agree with the ones its MANIFEST.md lists
// (computed independently, by a Python script of the collection's builders).
// Skipped, with a message, where the collection is absent.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/mesh/mesh_stats.h"
#include "subdiv/mesh/validation.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

namespace fs = std::filesystem;

struct ManifestRow {
  std::string file;
  long long vertices = -1, faces = -1, tri = -1, quad = -1, poly = -1, boundary_loops = -1, nm_edges = -1,
            max_valence = -1;
  std::map<std::string, long long> notes;  // nmv, iso, flip, degen, cc, chi
};

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string cell;
  std::getline(s, cell, '|');  // before the first bar
  while (std::getline(s, cell, '|')) {
    const auto b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
    out.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
  }
  return out;
}

std::vector<ManifestRow> read_manifest(const fs::path& path) {
  std::vector<ManifestRow> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const auto c = cells(line);
    if (c.size() < 11 || c[0].size() < 5 || c[0].substr(c[0].size() - 4) != ".obj") continue;
    ManifestRow r;
    r.file = c[0];
    r.vertices = std::stoll(c[3]);
    r.faces = std::stoll(c[4]);
    std::sscanf(c[5].c_str(), "%lld/%lld/%lld", &r.tri, &r.quad, &r.poly);
    r.boundary_loops = std::stoll(c[6]);
    r.nm_edges = std::stoll(c[7]);
    r.max_valence = std::stoll(c[8]);
    // Notes read like "nmv=2 flip=10 cc=1 chi=-4" after free text.
    std::stringstream words(c[10]);
    std::string word;
    while (words >> word) {
      const auto eq = word.find('=');
      if (eq == std::string::npos) continue;
      const std::string key = word.substr(0, eq);
      if (key == "nmv" || key == "iso" || key == "flip" || key == "degen" || key == "cc" || key == "chi")
        r.notes[key] = std::stoll(word.substr(eq + 1));
    }
    rows.push_back(r);
  }
  return rows;
}

class SharedMeshes : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::shared_mesh_dir();
    if (!fs::exists(dir_ / "MANIFEST.md"))
      GTEST_SKIP() << "shared mesh collection not found at " << dir_ << " (it sits beside the repository)";
  }
  fs::path dir_;
};

TEST_F(SharedMeshes, StatisticsAgreeWithTheManifest) {
  const auto rows = read_manifest(dir_ / "MANIFEST.md");
  ASSERT_GT(rows.size(), 100u);
  for (const ManifestRow& r : rows) {
    SCOPED_TRACE(r.file);
    MeshFile f;
    ASSERT_NO_THROW(f = read_mesh(dir_ / r.file));
    const MeshTopology topo(f.mesh);
    const MeshStats s = compute_stats(f.mesh, topo);
    EXPECT_EQ(s.vertices, r.vertices);
    EXPECT_EQ(s.faces, r.faces);
    EXPECT_EQ(s.triangles, r.tri);
    EXPECT_EQ(s.quads, r.quad);
    EXPECT_EQ(s.polygons, r.poly);
    EXPECT_EQ(s.boundary_loops, r.boundary_loops);
    EXPECT_EQ(s.non_manifold_edges, r.nm_edges);
    EXPECT_EQ(s.max_valence, r.max_valence);
    auto note = [&](const char* key) { return r.notes.count(key) ? r.notes.at(key) : 0; };
    EXPECT_EQ(s.non_manifold_vertices, note("nmv"));
    EXPECT_EQ(s.isolated_vertices, note("iso"));
    EXPECT_EQ(s.flipped_edges, note("flip"));
    EXPECT_EQ(s.degenerate_faces, note("degen"));
    if (r.notes.count("cc")) {
      EXPECT_EQ(s.components, note("cc"));
    }
    if (r.notes.count("chi")) {
      EXPECT_EQ(s.euler_characteristic, note("chi"));
    }
  }
}

// Every file in the directory (listed in the manifest or not) either loads or
// fails with a ParseError; validation then reports exactly the defects the
// statistics count.
TEST_F(SharedMeshes, EveryFileLoadsAndValidationMatchesItsDefects) {
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".obj") continue;
    ++files;
    SCOPED_TRACE(entry.path().string());
    MeshFile f;
    try {
      f = read_mesh(entry.path());
    } catch (const ParseError& e) {
      ADD_FAILURE() << "unexpected parse error: " << e.what();
      continue;
    }
    const MeshTopology topo(f.mesh);
    const MeshStats s = compute_stats(f.mesh, topo);
    const ValidationReport report = validate(f.mesh, topo, &f.lines);
    EXPECT_EQ(report.count(IssueKind::non_manifold_edge), static_cast<std::size_t>(s.non_manifold_edges));
    EXPECT_EQ(report.count(IssueKind::non_manifold_vertex), static_cast<std::size_t>(s.non_manifold_vertices));
    EXPECT_EQ(report.count(IssueKind::isolated_vertex), static_cast<std::size_t>(s.isolated_vertices));
    EXPECT_EQ(report.count(IssueKind::face_too_small) + report.count(IssueKind::repeated_vertex),
              static_cast<std::size_t>(s.degenerate_faces));
    EXPECT_EQ(report.count(IssueKind::index_out_of_range), 0u);
    EXPECT_EQ(report.count(IssueKind::invalid_tag), 0u);
    if (!report.ok()) {
      EXPECT_FALSE(report.first_error().empty());
    }
  }
  EXPECT_GT(files, 200u);
}

}  // namespace
}  // namespace subdiv
