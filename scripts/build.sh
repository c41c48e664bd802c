#!/usr/bin/env bash
# Installs dependencies if missing, then configures and builds capsubot (Release) in build/.
# Extra arguments go to cmake's configure step (e.g. -DCAPSUBOT_WERROR=ON).
# --minimal (first argument): only the program and the library, with only the packages they
# need (no tests, benchmarks, Python module, MPI or manual page).
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ "${1:-}" == "--minimal" ]]; then
  shift
  scripts/install-deps.sh --minimal
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCAPSUBOT_BUILD_TESTS=OFF \
    -DCAPSUBOT_BUILD_BENCHMARKS=OFF -DCAPSUBOT_PYTHON=OFF -DCAPSUBOT_MPI=OFF "$@" >/dev/null
  cmake --build build -j "$(nproc)" --target capsubot_cli
  exit 0
fi
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j "$(nproc)"
