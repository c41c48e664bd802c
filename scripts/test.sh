#!/usr/bin/env bash
# The README's test command: installs dependencies if missing, builds, runs the whole suite.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck disable=SC2086
scripts/build.sh ${CAPSUBOT_CMAKE_ARGS:-}
ctest --test-dir build --output-on-failure -j "$(nproc)"
