#!/usr/bin/env bash
# The library's stages form a one-way flow: a stage includes only itself and the stages that its
# row of the table of stages names, through their public headers include/capsubot/<stage>/; a
# private header src/<stage>/*.hpp is included only inside its stage, and never from a public
# header. The command line (apps/, every subfolder) and the Python module (python/) include
# public headers and their own files only.
#
# The table is read from docs/architecture.md ("## The stages"), the one place it is written:
# one row per stage, bottom of the flow first, whose last cell says what the stage may include:
# `nothing`, `every stage above` (every row before it) or stage names separated by commas, each
# a row before it (so the flow cannot loop). Every folder src/<stage>/ and
# include/capsubot/<stage>/ has a row, and every row a folder.
#
# Every file is checked; each broken rule prints one line naming the file, the include and the
# rule, and the script exits non-zero. Usage: layering_test.sh SOURCE_DIR
set -euo pipefail
cd "$1"
doc=docs/architecture.md

checked=0 failed=0
fail() {
  echo "FAIL: $*"
  failed=$((failed + 1))
}

# The table of stages: allowed[stage] = the stages it may include besides itself.
declare -A allowed=()
order=()
trim() {  # trim TEXT: REPLY is TEXT without its leading and trailing blanks
  REPLY=${1#"${1%%[![:space:]]*}"}
  REPLY=${REPLY%"${REPLY##*[![:space:]]}"}
}
read_table() {
  local row stage may name cells names
  while IFS= read -r row; do
    IFS='|' read -r -a cells <<<"$row"
    trim "${cells[1]:-}"
    stage=$REPLY
    trim "${cells[${#cells[@]} - 1]}"
    may=$REPLY
    if [[ ! $stage =~ ^[a-z_]+$ ]]; then
      fail "$doc: the table of stages has a row for '$stage': expected a folder name"
      continue
    fi
    if [[ -n ${allowed[$stage]+set} ]]; then
      fail "$doc: the table of stages has two rows for stage $stage"
      continue
    fi
    case $may in
      "")
        allowed[$stage]=""
        fail "$doc: stage $stage has no 'may include' cell: expected nothing, every stage above" \
          "or stage names"
        ;;
      nothing) allowed[$stage]="" ;;
      "every stage above") allowed[$stage]="${order[*]}" ;;
      *)
        allowed[$stage]=""
        IFS=',' read -r -a names <<<"$may"
        for name in "${names[@]}"; do
          trim "$name"
          name=$REPLY
          if [[ -z ${allowed[$name]+set} || $name == "$stage" ]]; then
            fail "$doc: stage $stage may include '$name', which is not a stage above it in the" \
              "table"
          else
            allowed[$stage]+="${allowed[$stage]:+ }$name"
          fi
        done
        ;;
    esac
    order+=("$stage")
  done < <(awk '/^## /{in_section = ($0 == "## The stages")} in_section && /^\|---/{rows = 1; next}
                rows && !/^\|/{rows = 0} in_section && rows' "$doc")
}
[[ -f $doc ]] || { echo "FAIL: $doc is missing: it holds the table of stages"; exit 1; }
read_table
[[ ${#order[@]} -gt 0 ]] || fail "$doc: no table of stages under '## The stages'"

# Every stage folder is in the table, and the table names no folder that is missing.
for dir in src/*/ include/capsubot/*/; do
  [[ -d $dir ]] || continue
  stage=$(basename "$dir")
  [[ -n ${allowed[$stage]+set} ]] || fail "${dir%/}/ is not in the table of stages ($doc)"
done
for stage in "${order[@]}"; do
  [[ -d src/$stage || -d include/capsubot/$stage ]] || fail "stage $stage of $doc has no folder"
done

# The files checked: owner[file] is the stage of a file of the library, or front_end:FOLDER for
# a file of a front end whose own headers live in FOLDER.
declare -A owner=()
files=()
for stage in "${order[@]}"; do
  while IFS= read -r file; do
    owner[$file]=$stage
    files+=("$file")
  done < <(find "src/$stage" "include/capsubot/$stage" -name '*.[ch]pp' 2>/dev/null | sort)
done
# The front ends, every subfolder: public headers and their own files only.
for front_end in apps python; do
  while IFS= read -r file; do
    owner[$file]=front_end:$front_end
    files+=("$file")
  done < <(find "$front_end" -name '*.[ch]pp' 2>/dev/null | sort)
done
checked=${#files[@]}

# check FILE LINE: one include line of a file.
check() {
  local file=$1 line=$2 stage=${owner[$1]} home=${1%/*} target to quoted public=0
  local pattern='^[[:space:]]*#[[:space:]]*include[[:space:]]*(["<])([^">]*)'
  [[ $line =~ $pattern ]] || return 0
  target=${BASH_REMATCH[2]}
  quoted=0
  [[ ${BASH_REMATCH[1]} == '"' ]] && quoted=1
  [[ $file == include/* ]] && public=1
  if [[ $stage == front_end:* ]]; then
    home=${stage#front_end:}
    stage=front_end
  fi
  if [[ /$target/ == */../* || /$target == */src/* ]]; then
    fail "$file includes $target: a path into the sources (include capsubot/<stage>/...)"
  elif [[ $target == capsubot/*/* ]]; then
    to=${target#capsubot/}
    to=${to%%/*}
    if [[ -z ${allowed[$to]+set} ]]; then
      fail "$file includes $target: no stage $to"
    elif [[ $stage != front_end && $stage != "$to" && " ${allowed[$stage]} " != *" $to "* ]]; then
      fail "$file includes $target: stage $stage may include only ${allowed[$stage]:-itself}"
    fi
  elif [[ $target == capsubot/* ]]; then
    fail "$file includes $target: public headers live in include/capsubot/<stage>/"
  elif [[ $target == */* ]]; then
    to=${target%%/*}
    if [[ -z ${allowed[$to]+set} && $quoted -eq 0 ]]; then
      :  # a library's header (<fmt/format.h>)
    elif [[ $stage == front_end ]]; then
      fail "$file includes $target: a front end includes public headers only (capsubot/<stage>/...)"
    elif [[ $to != "$stage" ]]; then
      fail "$file includes $target: a private header of stage $to (use its public header)"
    elif [[ $public -eq 1 ]]; then
      fail "$file includes $target: a public header includes public headers only"
    fi
  elif [[ $quoted -eq 1 && ! -f ${file%/*}/$target && ! -f $home/$target ]]; then
    fail "$file includes \"$target\": no such file beside it (another folder's header?)"
  fi
}
if [[ $checked -gt 0 ]]; then
  while IFS= read -r hit; do
    check "${hit%%:*}" "${hit#*:}"
  done < <(grep -HE '^[[:space:]]*#[[:space:]]*include[[:space:]]*["<]' "${files[@]}" || true)
fi

echo "$checked files checked, $failed rules broken"
[[ $checked -gt 100 && $failed -eq 0 ]]
