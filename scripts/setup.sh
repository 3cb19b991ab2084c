#!/usr/bin/env bash
# Installs the Debian packages subdiv needs to build, test and benchmark.
# Idempotent: when everything is present it only runs dpkg-query and exits.
# Usage: scripts/setup.sh [--fuzz] [--docs] [--browser]
#   --fuzz: also clang and libFuzzer, for scripts/fuzz.sh
#   --docs: also doxygen, for scripts/docs.sh (the API reference)
#   --browser: also chromium and Node.js with npm (where no npm is on the
#              PATH), for the comparison page's browser test
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libtbb-dev libcli11-dev libfmt-dev libfast-float-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libcairo2-dev libfontconfig-dev  # subdiv analyze: --json output, plots
  libosmesa6-dev  # subdiv render: Mesa's off-screen renderer
  libtinygltf-dev  # glTF 2.0 reading and writing
  libassimp-dev libosd-dev  # peers in bench/ (Assimp import, OpenSubdiv topology)
  python3  # the CLI test reads the --json documents
  python3-dev pybind11-dev python3-numpy python3-scipy python3-pytest  # the Python module and its tests
  python3-dask python3-distributed  # the Python example on a Dask cluster (and its test)
)

for option in "$@"; do
  case "$option" in
    --fuzz) packages+=(clang-14 libclang-rt-14-dev) ;;
    --docs) packages+=(doxygen) ;;
    --browser)
      packages+=(chromium)
      if ! command -v npm >/dev/null 2>&1; then packages+=(nodejs npm); fi
      ;;
    *) echo "setup: unknown option $option (--fuzz, --docs, --browser)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
