// A scheme's behaviour at one configuration, printed as JSON: the leading
// eigenvalues of its local subdivision matrix, Reif's eigenvalue condition,
// the C1 verdict with its reason, and the limit mask (the left eigenvector
// of eigenvalue 1). The same numbers `subdiv analyze --json` prints.
//
//   analyze_scheme loop 5                 interior vertex of valence 5
//   analyze_scheme catmull-clark 3 boundary

#include <cstdio>
#include <cstdlib>
#include <string>

#include "subdiv/analysis/analyze.h"
#include "subdiv/core/error.h"
#include "subdiv/rules/scheme.h"

namespace {

// Writes s as a JSON string: the reasons are plain text, but quotes and
// backslashes must still be escaped.
void print_json_string(const std::string& s) {
  std::putchar('"');
  for (const char c : s) {
    if (c == '"' || c == '\\') std::putchar('\\');
    if (static_cast<unsigned char>(c) < 0x20) {
      std::printf("\\u%04x", c);
    } else {
      std::putchar(c);
    }
  }
  std::putchar('"');
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: analyze_scheme SCHEME K [interior|boundary|corner]\n");
    return 1;
  }
  const subdiv::Scheme* scheme = subdiv::find_scheme(argv[1]);
  if (scheme == nullptr) {
    std::fprintf(stderr, "unknown scheme '%s'\n", argv[1]);
    return 1;
  }
  subdiv::Configuration configuration;
  configuration.k = std::atoi(argv[2]);
  const std::string kind = argc == 4 ? argv[3] : "interior";
  if (kind == "boundary") {
    configuration.kind = subdiv::Configuration::Kind::boundary;
  } else if (kind == "corner") {
    configuration.kind = subdiv::Configuration::Kind::corner;
  } else if (kind != "interior") {
    std::fprintf(stderr, "unknown configuration '%s'\n", kind.c_str());
    return 1;
  }
  try {
    // Spectrum, masks and verdict; the characteristic map's injectivity is
    // part of the C1 verdict, so it stays on.
    const subdiv::ConfigurationAnalysis a = subdiv::analyze(*scheme, configuration);
    std::printf("{\n  \"scheme\": \"%s\",\n  \"configuration\": ", argv[1]);
    print_json_string(configuration.name());
    std::printf(",\n  \"leading_eigenvalues\": [");
    for (std::size_t i = 0; i < a.leading.size(); ++i) {
      std::printf("%s{\"re\": %.15g, \"im\": %.15g}", i ? ", " : "", a.leading[i].real(), a.leading[i].imag());
    }
    std::printf("],\n  \"eigenvalue_condition\": %s,\n", a.eigenvalue_condition ? "true" : "false");
    std::printf("  \"verdict\": \"%s\",\n  \"reason\": ", subdiv::to_string(a.verdict));
    print_json_string(a.reason);
    std::printf(",\n  \"limit_mask\": ");
    if (a.limit_mask) {
      std::printf("[");
      for (Eigen::Index i = 0; i < a.limit_mask->size(); ++i) std::printf("%s%.15g", i ? ", " : "", (*a.limit_mask)[i]);
      std::printf("]\n}\n");
    } else {
      std::printf("null\n}\n");
    }
  } catch (const subdiv::Error& e) {
    std::fprintf(stderr, "analyze_scheme: %s\n", e.what());
    return 1;
  }
  return 0;
}
