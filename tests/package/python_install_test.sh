#!/usr/bin/env bash
# Installs the built project into a temporary prefix and imports the Python module from the
# installed site-packages folder (not from the build tree): `cmake --install` must install it
# where the interpreter looks for a package of that prefix, and it must work from there.
# Usage: python_install_test.sh BUILD_DIR PYTHON SITE_DIR (SITE_DIR relative to the prefix)
set -euo pipefail
build=$1 python=$2 site=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
test -n "$(compgen -G "$work/prefix/$site/capsubot*.so")"
# The type stubs beside it, as the package capsubot-stubs (PEP 561).
test -f "$work/prefix/$site/capsubot-stubs/__init__.pyi"
# Run from the temporary folder: the build tree is not on the path.
out=$(cd "$work" && PYTHONPATH="$work/prefix/$site" "$python" -c "
import capsubot
assert capsubot.__file__.startswith('$work/prefix/'), capsubot.__file__
print(capsubot.__version__, capsubot.solve(A=0.5, c=0.5, phi0=-2.944899971002)['alpha'])
")
echo "$out"
# alpha of the paper's example (README, 'The orbit: capsubot solve').
[[ $out == *" 0.35685746237742"* ]]
echo "python install: 1 passed, 0 failed"
