#!/usr/bin/env bash
# Installs swarmpath's build and test dependencies from Debian's archive (bookworm), skipping the
# packages already present. Idempotent; needs root or sudo only when something is missing.
set -euo pipefail

packages=(
  build-essential g++ make cmake ninja-build git clang-format
  python3                 # scripts/hostile_user.py, run by the tests
  libbox2d-dev            # Box2D 2.4: the physics
  libeigen3-dev           # CMA-ES linear algebra
  libnlopt-cxx-dev        # NLopt derivative-free optimisers
  libgtest-dev libgmock-dev
  libbenchmark-dev        # Google Benchmark
  libcli11-dev            # command line
  libtomlplusplus-dev     # TOML scenario / params / config files
  nlohmann-json3-dev      # JSON output
  zlib1g-dev              # recordings (.swrec) are zlib-compressed
  chromium nodejs         # the browser tests of the viewer and report (headless, DevTools protocol)
  libopenmpi-dev openmpi-bin  # the MPI backend: evolve, table and evaluate across a cluster (docs/mpi.md)
  python3-dev pybind11-dev python3-pybind11   # the Python module
  python3-pytest          # its tests
  r-cran-irace            # irace, for `swarmpath irace` and its test
  python3-optuna          # Optuna, for examples/optuna_tune.py and its test
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
