#!/usr/bin/env bash
# A sweep (or, with KIND=basins, a basin map; KIND=attractors, the per-start motions of the
# starts from rest; KIND=bifurcation, a two-parameter bifurcation study with its summary)
# split over a Slurm job array: task K of N
# computes shard K/N, a last job that depends on the array merges the N files into the file
# the command gives on one machine.
#
#   sbatch --array=0-15 examples/slurm/sweep_array.sh          # the 16 shards
#   sbatch --dependency=afterok:<array job id> --export=ALL,MERGE=1 examples/slurm/sweep_array.sh
#
# or both at once:  examples/slurm/sweep_array.sh submit
#   KIND=basins OUT=basins.csv examples/slurm/sweep_array.sh submit    # a basin map
#   KIND=attractors OUT=starts.csv examples/slurm/sweep_array.sh submit
#   KIND=bifurcation OUT=impacts.csv N=8 examples/slurm/sweep_array.sh submit  # + summary_<OUT>
# A killed or requeued task continues its shard from its checkpoint (--resume; a bifurcation
# task from the checkpoints of both its files). Edit SWEEP, BASINS, ATTRACTORS or BIFURCATION,
# OUT, N (a bifurcation study: N <= its continuations, 2 per value of --over).
#SBATCH --job-name=capsubot-sweep
#SBATCH --cpus-per-task=2
#SBATCH --time=02:00:00
#SBATCH --requeue
set -euo pipefail

CAPSUBOT=${CAPSUBOT:-capsubot}
N=${N:-16}
OUT=${OUT:-p2_T0_e.csv}
KIND=${KIND:-sweep}
SWEEP=(sweep --grid T0=0.01:1:65:log --grid e=0:1:41 --optimize forcing --stability --resume)
BASINS=(basins --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 --alpha 0.2792869076315278
  --starts 512x512 --resume)
ATTRACTORS=(attractors --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5
  --alpha 0.2792869076315278 --starts 256x256 --resume)
BIFURCATION=(bifurcation --A 0.05 --c 0.02 --phi0 -2.842 --e 0.5 --alpha 0.2792869076315278
  --param T0 --from 0.05 --to 0.2 --steps 301 --over e=0.2:0.9:8 --resume)
SUMMARY="$(dirname "$OUT")/summary_$(basename "$OUT")"
case "$KIND" in
  sweep) RUN=("${SWEEP[@]}") ;;
  basins) RUN=("${BASINS[@]}") ;;
  attractors) RUN=("${ATTRACTORS[@]}") ;;
  bifurcation) RUN=("${BIFURCATION[@]}") ;;
  *) echo "KIND = $KIND is invalid: expected sweep, basins, attractors or bifurcation" >&2; exit 2 ;;
esac

if [[ "${1:-}" == "submit" ]]; then
  array=$(sbatch --parsable --array=0-$((N - 1)) --export=ALL,N="$N",OUT="$OUT",KIND="$KIND" "$0")
  sbatch --dependency=afterok:"$array" --export=ALL,MERGE=1,N="$N",OUT="$OUT",KIND="$KIND" "$0"
  exit 0
fi

shard_file() { echo "${2%.csv}.shard$1of$N.csv"; }

if [[ "${MERGE:-0}" == 1 ]]; then
  outs=("$OUT")
  if [[ "$KIND" == bifurcation ]]; then outs+=("$SUMMARY"); fi
  for out in "${outs[@]}"; do
    files=()
    for ((k = 0; k < N; ++k)); do files+=("$(shard_file "$k" "$out")"); done
    "$CAPSUBOT" merge "$out" "${files[@]}"   # checks: same run, none missing, none truncated
  done
  exit 0
fi

K=${SLURM_ARRAY_TASK_ID:?run as a job array (sbatch --array=0-$((N - 1)))}
EXTRA=()
if [[ "$KIND" == bifurcation ]]; then EXTRA=(--summary "$(shard_file "$K" "$SUMMARY")"); fi
# --progress: a line every 5 % with the time elapsed and left, into the task's Slurm log.
"$CAPSUBOT" "${RUN[@]}" --shard "$K/$N" --threads "${SLURM_CPUS_PER_TASK:-1}" --progress \
  -o "$(shard_file "$K" "$OUT")" "${EXTRA[@]}"
