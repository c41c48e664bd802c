#!/usr/bin/env bash
# The library's stages form a one-way flow: a stage includes only itself and the stages its
# line below names (docs/architecture.md), through their public headers
# include/capsubot/<stage>/; a private header src/<stage>/*.hpp is included only inside its
# stage. The command line (apps/) and the Python module (python/) include public headers only.
# Every file is checked, and the test fails on the first rule a file breaks, naming the file,
# the include and the rule. Usage: layering_test.sh SOURCE_DIR
set -euo pipefail
cd "$1"

# stage: the stages it may include (besides itself), bottom of the flow first.
declare -A allowed=(
  [numerics]=""
  [model]="numerics"
  [parallel]=""
  [io]=""
  [orbit]="numerics model"
  [simulate]="numerics model"
  [attract]="numerics model parallel orbit simulate"
  [continue]="numerics model parallel orbit simulate attract"
  [optimize]="numerics model orbit"
  [reach]="numerics model parallel orbit simulate attract optimize"
  [design]="numerics model parallel orbit simulate attract optimize reach"
  [sweep]="numerics model parallel io orbit simulate attract optimize reach design"
  [job]="numerics model parallel io orbit simulate attract continue optimize reach design sweep"
  [report]="numerics model parallel io orbit simulate attract continue optimize reach design sweep job"
)
# The front ends may use every stage, through its public headers.
front_ends="${!allowed[*]}"

checked=0 failed=0
fail() {
  echo "FAIL: $*"
  failed=$((failed + 1))
}

# Every stage folder is in the table, and the table names no folder that is missing.
for dir in src/*/; do
  stage=$(basename "$dir")
  [[ -n ${allowed[$stage]+set} ]] || fail "src/$stage/ is not in the table of stages"
done
for stage in "${!allowed[@]}"; do
  [[ -d src/$stage || -d include/capsubot/$stage ]] || fail "stage $stage has no folder"
done

may_include() { if [[ $1 == front_end ]]; then echo "$front_ends"; else echo "${allowed[$1]}"; fi; }

# check FILE STAGE: the includes of one file of a stage.
check() {
  local file=$1 stage=$2 line target to
  checked=$((checked + 1))
  while IFS= read -r line; do
    target=${line#*\"}
    target=${target%%\"*}
    if [[ $target == capsubot/*/* ]]; then
      to=${target#capsubot/}
      to=${to%%/*}
      if [[ -z ${allowed[$to]+set} ]]; then
        fail "$file includes $target: no stage $to"
      elif [[ $stage != "$to" && " $(may_include "$stage") " != *" $to "* ]]; then
        fail "$file includes $target: stage $stage may include only $(may_include "$stage")"
      fi
    elif [[ $target == capsubot/* ]]; then
      fail "$file includes $target: public headers live in include/capsubot/<stage>/"
    elif [[ $target == */* ]]; then
      to=${target%%/*}
      [[ $to == "$stage" ]] ||
        fail "$file includes $target: a private header of stage $to (use its public header)"
    fi
  done < <(grep -E '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$file" || true)
}

for stage in "${!allowed[@]}"; do
  for file in $(find "src/$stage" "include/capsubot/$stage" -name '*.[ch]pp' 2>/dev/null); do
    check "$file" "$stage"
  done
done
# The front ends: public headers and their own files only.
for file in apps/*.[ch]pp python/*.[ch]pp; do
  check "$file" front_end
done

echo "$checked files checked, $failed rules broken"
[[ $checked -gt 100 && $failed -eq 0 ]]
