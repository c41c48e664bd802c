#!/usr/bin/env bash
# `pip install .` into a fresh virtual environment (with the system's site packages, offline,
# no build isolation: Debian's setuptools and wheel), then imports the installed module from
# outside the source tree, runs the installed command, and checks that the source folder is
# left as it was. The build folder given is reused, so the test builds nothing new.
# Usage: pip_install_test.sh SOURCE_DIR BUILD_DIR PYTHON
set -euo pipefail
source_dir=$1 build=$2 python=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$python" -m venv --system-site-packages "$work/venv"
# A copy of the source folder (without build folders), so that what pip leaves in it is seen:
# nothing (setuptools' build and egg-info folders go to temporary folders).
mkdir "$work/src"
tar -C "$source_dir" --exclude='./build*' --exclude=./.git --exclude='./*.egg-info' -cf - . |
  tar -C "$work/src" -xf -
before=$(cd "$work/src" && find . | sort)
# With the program too (CAPSUBOT_PIP_CLI=1): the environment's `capsubot` command.
CAPSUBOT_CMAKE_BUILD_DIR="$build" CAPSUBOT_PIP_CLI=1 "$work/venv/bin/python" -m pip install \
  --no-build-isolation --no-index --no-deps -q "$work/src" >"$work/pip.log" 2>&1 ||
  { cat "$work/pip.log"; exit 1; }
after=$(cd "$work/src" && find . | sort)
if [[ $before != "$after" ]]; then
  echo "FAIL: pip install changed the source folder:"
  diff <(echo "$before") <(echo "$after") || true
  exit 1
fi
"$work/venv/bin/capsubot" --version | grep -qx "0.2.0" ||
  { echo "FAIL: no capsubot command in the environment"; exit 1; }
out=$(cd "$work" && "$work/venv/bin/python" -c "
import capsubot, sys
assert capsubot.__file__.startswith(sys.prefix), (capsubot.__file__, sys.prefix)
print(capsubot.__version__, capsubot.solve(A=0.5, c=0.5, phi0=-2.944899971002)['alpha'])
")
echo "$out"
[[ $out == *" 0.35685746237742"* ]]  # the paper's example (README, 'capsubot solve')
version=$("$work/venv/bin/python" -m pip show -f capsubot)
[[ $version == *"Version: 0.2.0"* ]]
# The type stubs, installed as the package capsubot-stubs beside the module.
location=$(sed -n 's/^Location: //p' <<<"$version")
cmp "$location/capsubot-stubs/__init__.pyi" "$source_dir/python/capsubot.pyi"
[[ $version == *"capsubot-stubs/__init__.pyi"* ]]
echo "pip install: 1 passed, 0 failed"
