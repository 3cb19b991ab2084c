// Peak memory of one uniform refinement, in a process of its own so that the
// kernel's high-water mark (VmHWM) belongs to that refinement alone:
//
//   subdiv_peak_memory subdiv|opensubdiv catmull-clark|loop TORUS_N LEVELS [THREADS]
//
// prints the resident set before refining (the input mesh), the peak during
// it, and the difference, in MiB, and the refinement's time in this fresh
// process (subdiv with THREADS threads, default all; OpenSubdiv's Far has one). The input is bench_meshes.h's torus of
// TORUS_N x TORUS_N quads (split into triangles for loop).

#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "bench_meshes.h"
#include "subdiv/refine/refine.h"
#ifdef SUBDIV_BENCH_HAVE_OPENSUBDIV
#include "peer_opensubdiv.h"
#endif

namespace {

// A "Vm...:  N kB" line of /proc/self/status, in MiB.
double status_mib(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) return std::stod(line.substr(std::strlen(key))) / 1024.0;
  return -1.0;
}

int usage() {
  std::fprintf(stderr, "usage: subdiv_peak_memory subdiv|opensubdiv catmull-clark|loop TORUS_N LEVELS [THREADS]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace subdiv;
  if (argc != 5 && argc != 6) return usage();
  const std::string library = argv[1], scheme = argv[2];
  int n = 0, levels = 0, threads = 0;
  auto number = [](const char* text, int& value) {
    return std::from_chars(text, text + std::strlen(text), value).ec == std::errc();
  };
  if (!number(argv[3], n) || !number(argv[4], levels) || n < 3 || levels < 1) return usage();
  if (argc == 6 && (!number(argv[5], threads) || threads < 0)) return usage();
  if (scheme != "catmull-clark" && scheme != "loop") return usage();
  const PolygonMesh mesh = scheme == "loop" ? bench::triangulated_torus(n) : bench::torus(n);
  const double before = status_mib("VmRSS:");
  // Clear the high-water mark so that building the input does not count.
  std::ofstream("/proc/self/clear_refs") << "5";
  long long faces = 0;
  const auto start = std::chrono::steady_clock::now();
  if (library == "subdiv") {
    RefineOptions options;
    options.levels = levels;
    options.threads = threads;
    faces = refine(mesh, *find_scheme(scheme), options).face_count();
  } else if (library == "opensubdiv") {
#ifdef SUBDIV_BENCH_HAVE_OPENSUBDIV
    std::vector<bench::OsdVertex> buffer;
    faces = bench::osd_refine_uniform(
        mesh, scheme == "loop" ? OpenSubdiv::Sdc::SCHEME_LOOP : OpenSubdiv::Sdc::SCHEME_CATMARK, levels, buffer);
#else
    std::fprintf(stderr, "subdiv_peak_memory: built without OpenSubdiv (apt-get install libosd-dev)\n");
    return 1;
#endif
  } else {
    return usage();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double peak = status_mib("VmHWM:");
  std::printf("%s %s torus %d level %d: faces %lld, input %.0f MiB, peak %.0f MiB, refinement %.0f MiB, %.3f s\n",
              library.c_str(), scheme.c_str(), n, levels, faces, before, peak, peak - before, seconds);
  return 0;
}
