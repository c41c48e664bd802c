#!/usr/bin/env bash
# The layering check (layering_test.sh) fails on every rule it enforces: on a copy of what it
# reads (src/, include/, apps/, python/ and the table of stages in docs/architecture.md), one
# violation is made at a time, and the check must exit non-zero and name it. The clean copy
# must pass. Usage: layering_violations_test.sh SOURCE_DIR
set -euo pipefail
source_dir=$(cd "$1" && pwd)
check_script=$(cd "$(dirname "$0")" && pwd)/layering_test.sh
work=$(mktemp -d "${TMPDIR:-/tmp}/capsubot-layering.XXXXXX")
trap 'rm -rf "$work"' EXIT

mkdir -p "$work/clean/docs"
cp -R "$source_dir/src" "$source_dir/include" "$source_dir/apps" "$source_dir/python" \
  "$work/clean/"
cp "$source_dir/docs/architecture.md" "$work/clean/docs/"

failures=0 cases=0
bad() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# expect NAME MESSAGE COMMAND...: COMMAND, run in a fresh copy, makes one violation; the check
# must then fail with the line "FAIL: MESSAGE".
expect() {
  local name=$1 message=$2 output status=0
  shift 2
  cases=$((cases + 1))
  rm -rf "$work/tree"
  cp -R "$work/clean" "$work/tree"
  (cd "$work/tree" && "$@") || { bad "$name: could not make the violation"; return; }
  output=$(bash "$check_script" "$work/tree" 2>&1) || status=$?
  if [[ $status -eq 0 ]]; then
    bad "$name: the check passed"
  elif ! grep -qxF "FAIL: $message" <<<"$output"; then
    bad "$name: the check failed without the line 'FAIL: $message'; it printed:"
    echo "$output"
  fi
}

# write FILE LINE: a new file FILE (its folder made) holding LINE.
write() {
  mkdir -p "$(dirname "$1")"
  printf '%s\n' "$2" >"$1"
}
# row STAGE SED_SCRIPT: edits the row of STAGE in the doc's table of stages.
row() {
  grep -q "^| $1 |" docs/architecture.md && sed -i "/^| $1 |/$2" docs/architecture.md
}

# The clean copy passes: the cases below fail because of what they change.
if output=$(bash "$check_script" "$work/clean" 2>&1); then
  grep -q ', 0 rules broken$' <<<"$output" || bad "clean copy: no count of broken rules"
else
  bad "clean copy: the check failed:"
  echo "$output"
fi

# The rules' words, as the check prints them.
front='a front end includes public headers only (capsubot/<stage>/...)'
sources='a path into the sources (include capsubot/<stage>/...)'
no_row='is not in the table of stages (docs/architecture.md)'
doc=docs/architecture.md
model_rule='stage model may include only numerics'

# (a) A stage includes a stage above it, in quotes and in angle brackets.
expect upward-quoted \
  "src/model/injected.cpp includes capsubot/job/design_job.hpp: $model_rule" \
  write src/model/injected.cpp '#include "capsubot/job/design_job.hpp"'
expect upward-angle \
  "src/model/injected.cpp includes capsubot/job/design_job.hpp: $model_rule" \
  write src/model/injected.cpp '#include <capsubot/job/design_job.hpp>'
expect upward-public-header \
  "include/capsubot/orbit/injected.hpp includes capsubot/simulate/simulator.hpp: stage orbit \
may include only numerics model" \
  write include/capsubot/orbit/injected.hpp '#  include "capsubot/simulate/simulator.hpp"'
expect unknown-stage \
  'src/model/injected.cpp includes capsubot/ghost/ghost.hpp: no stage ghost' \
  write src/model/injected.cpp '#include "capsubot/ghost/ghost.hpp"'
expect public-header-outside-stage \
  "src/model/injected.cpp includes capsubot/version.hpp: public headers live in \
include/capsubot/<stage>/" \
  write src/model/injected.cpp '#include "capsubot/version.hpp"'

# A stage includes another stage's private header, or a public header a private one.
expect private-of-other-stage \
  "src/sweep/injected.cpp includes design/search.hpp: a private header of stage design (use its \
public header)" \
  write src/sweep/injected.cpp '#include "design/search.hpp"'
expect private-from-public-header \
  "include/capsubot/design/injected.hpp includes design/search.hpp: a public header includes \
public headers only" \
  write include/capsubot/design/injected.hpp '#include "design/search.hpp"'
expect relative-path-in-stage \
  "src/sweep/injected.cpp includes ../design/search.hpp: $sources" \
  write src/sweep/injected.cpp '#include "../design/search.hpp"'

# (c) A front end includes a private header: in quotes, in angle brackets, by a relative path
# into src/, by its bare name, from apps/, a subfolder of apps/ and python/.
expect front-end-quoted "apps/injected.cpp includes design/search.hpp: $front" \
  write apps/injected.cpp '#include "design/search.hpp"'
expect front-end-subfolder "apps/cluster/injected.cpp includes design/search.hpp: $front" \
  write apps/cluster/injected.cpp '#include "design/search.hpp"'
expect front-end-new-subfolder \
  "apps/more/deeper/injected.hpp includes simulate/chatter.hpp: $front" \
  write apps/more/deeper/injected.hpp '#include <simulate/chatter.hpp>'
expect front-end-angle "python/injected.cpp includes design/search.hpp: $front" \
  write python/injected.cpp '#include <design/search.hpp>'
expect front-end-relative "python/injected.cpp includes ../src/design/search.hpp: $sources" \
  write python/injected.cpp '#include "../src/design/search.hpp"'
expect front-end-bare-name \
  "apps/cluster/injected.cpp includes \"search.hpp\": no such file beside it (another folder's \
header?)" \
  write apps/cluster/injected.cpp '#include "search.hpp"'

# (d) The folders and the table of stages agree.
expect stage-folder-not-in-table "src/ghost/ $no_row" \
  write src/ghost/ghost.cpp '#include <vector>'
expect public-folder-not-in-table "include/capsubot/ghost/ $no_row" \
  write include/capsubot/ghost/ghost.hpp '#pragma once'
expect row-missing "src/io/ $no_row" \
  row io d
expect row-without-folder "stage ghost of $doc has no folder" \
  row report 'a| ghost | nothing yet | every stage above |'
expect row-names-stage-not-above-it \
  "$doc: stage model may include 'job', which is not a stage above it in the table" \
  row model 's/| numerics |$/| numerics, job |/'
expect row-twice "$doc: the table of stages has two rows for stage io" \
  row io 'p'
expect row-without-rule \
  "$doc: stage io has no 'may include' cell: expected nothing, every stage above or stage names" \
  row io 's/| nothing |$/| |/'
expect no-table "$doc: no table of stages under '## The stages'" \
  sed -i 's/^## The stages$/## Stages/' $doc
# The table is the rule: a row that allows less makes the includes it no longer allows fail.
expect row-allows-less \
  "include/capsubot/orbit/orbit.hpp includes capsubot/model/params.hpp: stage orbit may include \
only numerics" \
  row orbit 's/| numerics, model |$/| numerics |/'

echo "$cases violations made, $failures not caught as expected"
[[ $cases -gt 0 && $failures -eq 0 ]]
