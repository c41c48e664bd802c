#!/usr/bin/env bash
# The documentation ships with the repository and points nowhere outside it:
#  1. every relative link [text](target) in README.md, docs/*.md and results/*.md names a file
#     or folder of the repository, and a #fragment into a markdown file names one of its
#     headings (GitHub's anchors: lower case, punctuation dropped, spaces as hyphens);
#  2. no tracked file points to the model's former location outside the repository (the
#     model's page is docs/model.md);
#  3. the unit of length L has one meaning: the inner body's free gap between the walls
#     (docs/model.md), never the shell's length.
# Links inside fenced code blocks are not links. Usage: links_test.sh SOURCE_DIR
set -euo pipefail
root=$(cd "$1" && pwd)
cd "$root"

# Targets written on branches that are merged together with this one: accepted while missing.
# Once they exist they are checked like every other file, and this list can be emptied.
pending=()

passed=0 failed=0
fail() {
  echo "FAIL: $*"
  failed=$((failed + 1))
}

# Whether markdown file $1 has a heading whose GitHub anchor is $2. The anchors of each file
# are computed once (no process per link: the test stays fast on a loaded machine).
declare -A anchor_cache
has_anchor() {
  if [[ -z ${anchor_cache[$1]+set} ]]; then
    anchor_cache[$1]=$'\n'$(awk '/^```/ { fenced = !fenced; next }
                                 !fenced && /^#+ / { sub(/^#+ +/, ""); print }' "$1" |
      tr '[:upper:]' '[:lower:]' | sed -e 's/[^a-z0-9 _-]//g' -e 's/ /-/g')$'\n'
  fi
  [[ ${anchor_cache[$1]} == *$'\n'"$2"$'\n'* ]]
}

# Sets `normalized` to dir/path with "." and ".." segments resolved, relative to the root
# (starting with "../" if it leaves it).
normalize() {
  local -a parts out=()
  local part
  IFS=/ read -r -a parts <<< "$1"
  for part in "${parts[@]}"; do
    case $part in
      '' | .) ;;
      ..) if [[ ${#out[@]} -gt 0 && ${out[-1]} != .. ]]; then unset 'out[-1]'; else out+=(..); fi ;;
      *) out+=("$part") ;;
    esac
  done
  local IFS=/
  normalized="${out[*]}"
}

is_pending() {
  local p
  for p in "${pending[@]}"; do [[ $1 == "$p" ]] && return 0; done
  return 1
}

docs=(README.md docs/*.md results/*.md)
checked_files=0
for doc in "${docs[@]}"; do
  [[ -f $doc ]] || continue
  checked_files=$((checked_files + 1))
  dir=$(dirname "$doc")
  # "line<TAB>target" for every [text](target) outside fenced code blocks.
  while IFS=$'\t' read -r line target; do
    target=${target%% *}  # drop a "title"
    target=${target#<}
    target=${target%>}
    case $target in
      http://* | https://* | mailto:*) continue ;;
    esac
    path=${target%%#*}
    fragment=
    [[ $target == *#* ]] && fragment=${target#*#}
    if [[ -z $path ]]; then
      file=$doc
    else
      normalize "$dir/$path"
      file=$normalized
    fi
    where="$doc:$line: ($target)"
    if [[ $file == ../* || $file == /* ]]; then
      fail "$where points outside the repository"
    elif [[ ! -e $file ]]; then
      if is_pending "$file"; then
        passed=$((passed + 1))
      else
        fail "$where: $file does not exist"
      fi
    elif [[ -n $fragment && $file == *.md ]] && ! has_anchor "$file" "$fragment"; then
      fail "$where: $file has no heading with anchor #$fragment"
    else
      passed=$((passed + 1))
    fi
  done < <(awk '/^```/ { fenced = !fenced; next }
                !fenced { s = $0
                  while (match(s, /\]\([^)]+\)/)) {
                    print NR "\t" substr(s, RSTART + 2, RLENGTH - 3)
                    s = substr(s, RSTART + RLENGTH) } }' "$doc")
done
[[ $checked_files -ge 3 ]] || fail "only $checked_files markdown files found under $root"

# No file may refer to the working copy of the equations outside the repository. The
# patterns are spelled in pieces so that this file does not match itself.
outside_dir='\.\./'"shared"
outside_doc='MODEL'"\.md"
if git -C "$root" rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  mapfile -t files < <(git -C "$root" ls-files)
else
  mapfile -t files < <(find . -path ./build -prune -o -path ./.git -prune -o -type f -print)
fi
regular=()
for f in "${files[@]}"; do [[ -f $f ]] && regular+=("$f"); done
[[ ${#regular[@]} -gt 0 ]] || fail "no files found under $root"
mapfile -t offending < <(grep -IlE -- "$outside_dir|$outside_doc" "${regular[@]}" || true)
for f in "${offending[@]}"; do
  fail "$f mentions a document outside the repository:"
  grep -InE -- "$outside_dir|$outside_doc" "$f" | head -3
done
passed=$((passed + ${#regular[@]} - ${#offending[@]}))

# One meaning of L: no tracked file calls it the shell's length (spelled in pieces, as above).
shell_length='shell'" length|length of the "'shell'
mapfile -t offending < <(grep -IliE -- "$shell_length" "${regular[@]}" || true)
for f in "${offending[@]}"; do
  fail "$f calls L the shell's length (L is the inner body's free gap):"
  grep -IniE -- "$shell_length" "$f" | head -3
done

echo "links: $passed passed, $failed failed"
[[ $failed -eq 0 ]]
