// The fuzz targets' checks (fuzz/fuzz_checks.h) on every input kept in
// tests/data/fuzz/<target>/ (minimized findings of scripts/fuzz.sh) and on
// the hand-written and bundled meshes, so that what the fuzzer once found
// stays fixed and the checks themselves run on every build. A check aborts
// the test program with "fuzz invariant broken: ..." on a broken invariant.

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_checks.h"
#include "subdiv/io/mesh_io.h"

namespace {

namespace fs = std::filesystem;
using Check = void (*)(const std::uint8_t*, std::size_t);

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<fs::path> files_in(const fs::path& dir, const std::string& extension = {}) {
  std::vector<fs::path> files;
  if (!fs::is_directory(dir)) return files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && (extension.empty() || entry.path().extension() == extension))
      files.push_back(entry.path());
  return files;
}

/// Runs `check` on every file; returns how many it ran on.
int run_on(const std::vector<fs::path>& files, Check check, std::uint8_t pipeline_selector = 0,
           bool as_pipeline = false) {
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    std::vector<std::uint8_t> bytes = read_bytes(file);
    if (as_pipeline) bytes.insert(bytes.begin(), pipeline_selector);
    check(bytes.data(), bytes.size());
  }
  return static_cast<int>(files.size());
}

const fs::path kTestData = SUBDIV_TEST_DATA_DIR;
const fs::path kBundled = SUBDIV_BUNDLED_MESH_DIR;
const fs::path kFuzzSeeds = fs::path(SUBDIV_SOURCE_DIR) / "fuzz" / "seeds";

TEST(FuzzRegression, SeedsAreMeshesTheReadersTake) {
  // A seed the reader refuses would start the fuzzer from nothing.
  int seeds = 0;
  for (const char* format : {"ply", "off", "stl", "gltf"})
    for (const fs::path& seed : files_in(kFuzzSeeds / format)) {
      SCOPED_TRACE(seed.string());
      EXPECT_NO_THROW({
        const subdiv::MeshFile file = subdiv::read_mesh(seed);
        EXPECT_GT(file.mesh.face_count(), 0);
      });
      ++seeds;
    }
  EXPECT_GE(seeds, 13);
}

TEST(FuzzRegression, KeptFindingsPassTheirTargetsChecks) {
  run_on(files_in(kTestData / "fuzz" / "obj"), subdiv::fuzz::check_obj_input);
  run_on(files_in(kTestData / "fuzz" / "ply"), subdiv::fuzz::check_ply_input);
  run_on(files_in(kTestData / "fuzz" / "off"), subdiv::fuzz::check_off_input);
  run_on(files_in(kTestData / "fuzz" / "stl"), subdiv::fuzz::check_stl_input);
  run_on(files_in(kTestData / "fuzz" / "gltf"), subdiv::fuzz::check_gltf_input);
  run_on(files_in(kTestData / "fuzz" / "pipeline"), subdiv::fuzz::check_pipeline_input);
}

TEST(FuzzRegression, HandWrittenAndBundledMeshesPassTheReaderChecks) {
  int checked = 0;
  for (const fs::path& dir :
       {kTestData, kBundled, kFuzzSeeds / "ply", kFuzzSeeds / "off", kFuzzSeeds / "stl", kFuzzSeeds / "gltf"}) {
    checked += run_on(files_in(dir, ".obj"), subdiv::fuzz::check_obj_input);
    checked += run_on(files_in(dir, ".ply"), subdiv::fuzz::check_ply_input);
    checked += run_on(files_in(dir, ".off"), subdiv::fuzz::check_off_input);
    checked += run_on(files_in(dir, ".stl"), subdiv::fuzz::check_stl_input);
    checked += run_on(files_in(dir, ".gltf"), subdiv::fuzz::check_gltf_input);
    checked += run_on(files_in(dir, ".glb"), subdiv::fuzz::check_gltf_input);
  }
  EXPECT_GE(checked, 20);
}

TEST(FuzzRegression, HandWrittenAndBundledMeshesPassThePipelineChecks) {
  // Selector 0: OBJ, one level; 3: OBJ, two levels for meshes of up to 16 faces.
  int checked = 0;
  for (const fs::path& dir : {kTestData, kBundled})
    for (std::uint8_t selector : {0, 3}) checked += run_on(files_in(dir, ".obj"), subdiv::fuzz::check_pipeline_input,
                                                           selector, true);
  EXPECT_GE(checked, 30);
}

}  // namespace
