#!/usr/bin/env bash
# The mutation check of docs/validation.md ("Mutants"): which plausible bug would the tests
# miss? Each mutant below is one small edit of the library (a sign, a tolerance times 100, a
# dropped case, an off-by-one, a swapped wall), written as (file, original text, replacement).
# The script copies the source tree to a scratch folder, builds it once, checks that the
# tests of every stage pass unmutated, then for each mutant: applies it to the copy, rebuilds
# the test programs of its stage, runs their tests (ctest, bounded in time) and puts the file
# back. A mutant dies when a test fails (or the run times out); it survives when all pass.
# A mutant whose original text is not found exactly once in its file "does not apply": the
# library changed under it, and the mutant must be rewritten (the script says so and exits 1).
#
# Usage: scripts/mutants.sh [-j JOBS] [-t SECONDS] [-k SCRATCH] [-n] [ID ...]
#   -j  build and test jobs (default 2); -t  time bound of one mutant's tests (default 900 s);
#   -n  no baseline (only right after a run whose baseline passed on the same tree);
#   -k  scratch folder (default build-mutants/ in the tree: under ccache's base_dir, so the
#       copy's build reuses the cache); IDs: run only these mutants.
# Slow (minutes per mutant): not run by CI; run it before a change of the stages it mutates is
# merged, and record its result in docs/validation.md.
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
JOBS=2
TIMEOUT=900
SCRATCH="$ROOT/build-mutants"
BASELINE=1
while getopts "j:t:k:n" opt; do
  case $opt in
    j) JOBS=$OPTARG ;;
    t) TIMEOUT=$OPTARG ;;
    k) SCRATCH=$OPTARG ;;
    n) BASELINE=0 ;;
    *) echo "usage: $0 [-j JOBS] [-t SECONDS] [-k SCRATCH] [-n] [ID ...]" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
ONLY=("$@")

# The test programs of each stage, the tests a mutant of the stage must fail: every program of
# tests/<stage>/, plus tests/optimize/reach_test.cpp (reach) and tests/job/design_job_test.cpp
# (design). Programs are separated by blanks or new lines.
declare -A STAGE_TESTS=(
  [simulate]="simulator_test simulator_chatter_test simulator_energy_test simulator_reuse_test
              segment_force_test cycle_memo_test simulator_pulse_test local_sincos_test"
  [attract]="attractors_test long_run_test periodic_test gait_from_rest_test bifurcation_test
             start_grid_test chatter_settings_test"
  [continue]="neimark_sacker_test continuation_test branch_switch_test grazing_switch_test
              special_curve_test gait_robustness_test branch_edges_test branch_properties_test
              speed_band_test"
  [reach]="reach_test drive_family_test drive_ladder_test reach_frequency_test"
  [design]="design_test design_windows_test design_from_rest_test design_robustness_test
            design_job_test"
)

IDS=() STAGES=() FILES=() ORIGINALS=() REPLACEMENTS=()
mutant() {  # ID STAGE FILE ORIGINAL REPLACEMENT
  IDS+=("$1") STAGES+=("$2") FILES+=("$3") ORIGINALS+=("$4") REPLACEMENTS+=("$5")
}

# --- simulate: impact law, friction, break-away, chattering --------------------------------
mutant S1 simulate src/simulate/simulator.cpp \
  'sg_.u0 = -params_.e * u;' \
  'sg_.u0 = params_.e * u;'
mutant S2 simulate src/simulate/simulator.cpp \
  'sg_.v0 = v + sg_.alpha * (1.0 + params_.e) * u;' \
  'sg_.v0 = v + sg_.alpha * (1.0 - params_.e) * u;'
mutant S3 simulate src/simulate/simulator.cpp \
  'res_.energy.impact_loss += 0.5 * sg_.alpha * (1.0 - sg_.alpha) * (1.0 - e * e) * u * u;' \
  'res_.energy.impact_loss += 0.5 * sg_.alpha * (1.0 - sg_.alpha) * (1.0 - e) * u * u;'
mutant S4 simulate src/simulate/simulator.cpp \
  'double Position(Wall wall) { return wall == Wall::kRight ? 1.0 : 0.0; }' \
  'double Position(Wall wall) { return wall == Wall::kRight ? 0.0 : 1.0; }'
mutant S5 simulate src/simulate/simulator.cpp \
  'sg.b = sg.sgn * sg.alpha * sg.T0;' \
  'sg.b = -sg.sgn * sg.alpha * sg.T0;'
mutant S6 simulate src/simulate/simulator.cpp \
  'if (F > T0 + tol) return Slide::kBackward;' \
  'if (F > T0 + tol) return Slide::kForward;'
mutant S7 simulate src/simulate/chatter.cpp \
  'for (int j = 0; j < kPoints - 1; ++j) sum += w[j] * (get(rec[j]) - last);' \
  'for (int j = 0; j < kPoints - 2; ++j) sum += w[j] * (get(rec[j]) - last);'
mutant S8 simulate src/simulate/chatter.cpp \
  'if (!(r > 0.0 && r < 1.0)) return est;' \
  'if (!(r > 0.0 && r < 0.01)) return est;'

# --- attract: grouping, period detection, impact counts, orbit matching --------------------
mutant A1 attract src/attract/attractors.cpp \
  'return std::abs(a.mean_velocity - b.mean_velocity) <= velocity_tolerance * scale;' \
  'return std::abs(a.mean_velocity - b.mean_velocity) <= 100.0 * velocity_tolerance * scale;'
mutant A2 attract src/attract/attractors.cpp \
  'if (i == 0 || !(std::abs(v - prev) <= tolerance * std::max(std::abs(v), std::abs(prev)))) {' \
  'if (i == 0 || !(std::abs(v - prev) <= 100.0 * tolerance * std::max(std::abs(v), std::abs(prev)))) {'
mutant A3 attract src/attract/attractors.cpp \
  'phi -= kTau * std::floor(phi / kTau);' \
  ''
mutant A4 attract src/attract/stroboscopic.cpp \
  'for (int p = 1; p <= max_period && 2 * p < n; ++p) {' \
  'for (int p = 1; p < max_period && 2 * p < n; ++p) {'
mutant A5 attract src/attract/stroboscopic.cpp \
  '++(is_right ? right : left)[static_cast<std::size_t>(k)];' \
  '++(is_right ? left : right)[static_cast<std::size_t>(k)];'
mutant A6 attract src/attract/stroboscopic.cpp \
  'std::abs(a.v - b.v) <= tol;' \
  'true;'

# --- continue: the test functions and their confirmation ------------------------------------
mutant C1 continue src/continue/special_points.cpp \
  '{SpecialPointType::kNeimarkSacker, [](const Node& n) { return n.neimark_sacker; }},' \
  ''
mutant C2 continue src/continue/special_points.cpp \
  'if (type == SpecialPointType::kPeriodDoubling && std::abs(mu + 1.0) <= tolerance) return true;' \
  'if (type == SpecialPointType::kPeriodDoubling && std::abs(mu - 1.0) <= tolerance) return true;'
mutant C3 continue src/continue/special_points.cpp \
  'constexpr double kOnCircle = 1e-5;' \
  'constexpr double kOnCircle = 1e-7;'
mutant C4 continue src/continue/special_points.cpp \
  'if (!SameEvents(a, b)) {' \
  'if (false) {'
mutant C5 continue src/continue/special_points.cpp \
  'if (type == SpecialPointType::kNeimarkSacker && std::abs(mu.imag()) > kComplexPair &&' \
  'if (type == SpecialPointType::kNeimarkSacker &&'
mutant C6 continue src/continue/branch_system.cpp \
  'for (std::size_t j = i + 1; j < mu.size(); ++j) ns *= (mu[i] * mu[j] - 1.0).real();' \
  'for (std::size_t j = i + 1; j < mu.size(); ++j) ns *= (mu[i] * mu[j] + 1.0).real();'

# --- reach: the ranking of candidates and the spread test -----------------------------------
mutant R1 reach src/reach/optimize_reach.cpp \
  'return sa > sb || (sa == sb && a.is_seed && !b.is_seed);' \
  'return sa < sb || (sa == sb && a.is_seed && !b.is_seed);'
mutant R2 reach src/reach/optimize_reach.cpp \
  'if (spread.max_relative_deviation <= options.max_spread) {' \
  'if (spread.max_relative_deviation <= 100.0 * options.max_spread) {'
mutant R3 reach src/reach/optimize_reach.cpp \
  'if (params.e == 1.0) {' \
  'if (params.e != 1.0) {'

# --- design: the best gait, the windows, the ends of the range ------------------------------
mutant D1 design src/design/design.cpp \
  '} else if (!best.gait.ok() || f.gait.speed_mm_s > best.gait.speed_mm_s) {' \
  '} else if (!best.gait.ok() || f.gait.speed_mm_s < best.gait.speed_mm_s) {'
mutant D2 design src/design/design.cpp \
  'constexpr double kWindowResolution = 1e-6;' \
  'constexpr double kWindowResolution = 1e-4;'
mutant D3 design src/design/design.cpp \
  '{at(std::max(w.first - 1, 0)), at(w.first), at(w.last), at(std::min(w.last + 1, last))});' \
  '{at(w.first), at(w.first), at(w.last), at(w.last)});'
mutant D4 design src/design/design.cpp \
  'if (best_value == lo) best.gait.binding.emplace_back(lo_name);' \
  'if (best_value == lo) best.gait.binding.emplace_back(hi_name);'
mutant D5 design src/design/gait.cpp \
  'const bool robust = s.validity.valid() && st.computed && st.spectral_radius <= input.rho_max;' \
  'const bool robust = s.validity.valid() && st.computed;'

SRC="$SCRATCH/src"
BUILD="$SRC/build"

# Prints how often ORIGINAL occurs in FILE; with a REPLACEMENT, replaces it (exactly once).
substitute() {  # FILE ORIGINAL [REPLACEMENT]
  /usr/bin/python3 - "$@" <<'PY'
import sys
path, original = sys.argv[1], sys.argv[2]
text = open(path).read()
count = text.count(original)
if len(sys.argv) > 3 and count == 1:
    open(path, "w").write(text.replace(original, sys.argv[3]))
print(count)
PY
}

main() {
# Every mutant applies to the tree as it is (else nothing is built).
stale=0
for i in "${!IDS[@]}"; do
  n=$(substitute "$ROOT/${FILES[$i]}" "${ORIGINALS[$i]}")
  if [[ $n != 1 ]]; then
    echo "mutant ${IDS[$i]} does not apply: its original text occurs $n times in ${FILES[$i]}:" >&2
    echo "    ${ORIGINALS[$i]}" >&2
    stale=1
  fi
done
if [[ $stale == 1 ]]; then
  echo "rewrite the mutants above for the current source (scripts/mutants.sh)" >&2
  exit 1
fi

selected() {  # ID
  [[ ${#ONLY[@]} == 0 ]] && return 0
  local x
  for x in "${ONLY[@]}"; do [[ $x == "$1" ]] && return 0; done
  return 1
}

echo "scratch copy: $SRC"
mkdir -p "$SRC"
# The tree as it is (uncommitted changes too), without build folders and git's data; times kept,
# so that a second run rebuilds only what changed.
tar -C "$ROOT" --exclude='./build*' --exclude='./.git' -cf - . | tar -C "$SRC" -xf -
# ... but a mutated file's object may be newer than the file put back (a run's last mutant, or
# one a stopped run left, is never rebuilt unmutated, and tar keeps the tree's older time): the
# files that mutants edit are rebuilt.
for file in $(printf '%s\n' "${FILES[@]}" | sort -u); do touch "$SRC/$file"; done
cmake -S "$SRC" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
  -DCAPSUBOT_BUILD_BENCHMARKS=OFF >"$SCRATCH/configure.log"

# The ctest regular expression of a stage: the test suites of its programs.
stage_regex() {  # STAGE
  local exe suites=""
  for exe in ${STAGE_TESTS[$1]}; do
    suites+=$("$BUILD/tests/$exe" --gtest_list_tests | sed -n 's/^\([A-Za-z0-9_/]*\)\..*/\1/p' |
      sed 's#^.*/##' | sort -u | tr '\n' '|')
  done
  echo "(^|/)(${suites%|})\\."
}

# Builds the stage's programs and runs its tests; prints "pass", "FAIL: names" or "timeout".
run_stage() {  # STAGE LOG
  local stage=$1 log=$2
  # shellcheck disable=SC2086
  if ! cmake --build "$BUILD" -j "$JOBS" --target ${STAGE_TESTS[$stage]} >"$log.build" 2>&1; then
    echo "build failed"
    return
  fi
  local regex status=0
  regex=$(stage_regex "$stage")
  # A mutant is killed by its first failing test: the rest need not run (--stop-on-failure).
  local stop=()
  [[ $2 != */baseline-* ]] && stop=(--stop-on-failure)
  timeout "$TIMEOUT" ctest --test-dir "$BUILD" -j "$JOBS" -R "$regex" --timeout "$TIMEOUT" \
    "${stop[@]}" >"$log" 2>&1 || status=$?
  if [[ $status == 0 ]]; then
    echo "pass"
  elif [[ $status == 124 ]]; then
    echo "timeout"
  else
    echo "FAIL: $(sed -n 's/^[[:space:]]*[0-9]* - \([^ ]*\) (.*/\1/p' "$log" | head -3 | tr '\n' ' ')"
  fi
}

mkdir -p "$SCRATCH/logs"
# The stages of the selected mutants, each once, in the table's order.
stages=()
for i in "${!IDS[@]}"; do
  selected "${IDS[$i]}" || continue
  [[ " ${stages[*]} " == *" ${STAGES[$i]} "* ]] || stages+=("${STAGES[$i]}")
done
[[ $BASELINE == 1 ]] && echo "baseline: the tests of ${stages[*]} on the unmutated copy"
for stage in "${stages[@]}"; do
  [[ $BASELINE == 1 ]] || break
  result=$(run_stage "$stage" "$SCRATCH/logs/baseline-$stage")
  echo "  $stage: $result"
  if [[ $result != pass ]]; then
    echo "the unmutated tests of $stage do not pass: see $SCRATCH/logs/baseline-$stage" >&2
    exit 1
  fi
done

survivors=0
printf '%-4s %-9s %-38s %s\n' id stage file result
for i in "${!IDS[@]}"; do
  selected "${IDS[$i]}" || continue
  file="$SRC/${FILES[$i]}"
  cp "$ROOT/${FILES[$i]}" "$file"
  substitute "$file" "${ORIGINALS[$i]}" "${REPLACEMENTS[$i]}" >/dev/null
  start=$SECONDS
  result=$(run_stage "${STAGES[$i]}" "$SCRATCH/logs/${IDS[$i]}")
  cp "$ROOT/${FILES[$i]}" "$file"
  case $result in
    pass) verdict="SURVIVED"; survivors=$((survivors + 1)) ;;
    "build failed") verdict="does not build (see logs/${IDS[$i]}.build)" ;;
    timeout) verdict="killed (timeout)" ;;
    *) verdict="killed (${result#FAIL: })" ;;
  esac
  printf '%-4s %-9s %-38s %s [%ds]\n' "${IDS[$i]}" "${STAGES[$i]}" "${FILES[$i]}" "$verdict" \
    $((SECONDS - start))
done
# The copy is left as the source: a later run rebuilds only what changed.
echo "survivors: $survivors"
[[ $survivors == 0 ]]
}

# Parsed whole before it runs: an edit of this file during a run does not reach the run.
main
