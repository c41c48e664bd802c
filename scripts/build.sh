#!/usr/bin/env bash
# Installs dependencies if missing, then configures and builds capsubot (Release) in build/.
# Extra arguments go to cmake's configure step (e.g. -DCAPSUBOT_WERROR=ON).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j "$(nproc)"
