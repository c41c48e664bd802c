#!/usr/bin/env bash
# Installs the built project into a temporary prefix, builds examples/consumer against the
# installed CMake package and runs it: find_package(capsubot CONFIG) must work for a
# downstream project, and the installed program must report the version. The manual page
# (when MAN_PAGE is 1: help2man was found) and the bash completion are installed, and the
# installed completion completes a command.
# Usage: consumer_test.sh BUILD_DIR SOURCE_DIR VERSION MAN_PAGE
set -euo pipefail
build=$1 source=$2 version=$3 man_page=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$source/examples/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/consumer" >/dev/null
out=$("$work/consumer/paper_example")
echo "$out"
# phi1 = 2.748... is the root of 3 phi1 = 2 pi + 2 sin(phi1/2) (docs/model.md, section 6).
[[ $out == "capsubot $version: phi1 = 2.7482072884"* ]]
[[ $("$work/prefix/bin/capsubot" --version) == "$version" ]]
test -f "$work/prefix/include/capsubot/orbit/validity.hpp"
completion=$work/prefix/share/bash-completion/completions/capsubot
test -f "$completion"
# shellcheck disable=SC2016
[[ $(bash -c 'source "$1"; COMP_WORDS=(capsubot swe); COMP_CWORD=1; _capsubot
               echo "${COMPREPLY[*]}"' _ "$completion") == sweep ]]
if [[ $man_page == 1 ]]; then
  grep -q '^\.TH CAPSUBOT "1"' "$work/prefix/share/man/man1/capsubot.1"
fi
echo "consumer: 1 passed, 0 failed"
