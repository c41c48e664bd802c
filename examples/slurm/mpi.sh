#!/usr/bin/env bash
# A sweep, a basin map and a design grid on the ranks of one MPI job (capsubot built with
# CAPSUBOT_MPI): rank 0 hands blocks of grid points (of starts) to the other ranks, each
# computes with its --threads, and rank 0 writes the file, byte-identical to the run on one
# machine.
#
#   sbatch examples/slurm/mpi.sh            # 4 nodes x 1 rank x 16 cores
#
# A rank that dies ends the job (non-zero exit, no final file); the partial file and checkpoint
# of the sweep (of the design grid) stay, and the same command with --resume continues it. Edit
# SWEEP, BASINS, DESIGN.
#SBATCH --job-name=capsubot-mpi
#SBATCH --nodes=4
#SBATCH --ntasks-per-node=1
#SBATCH --cpus-per-task=16
#SBATCH --time=02:00:00
set -euo pipefail

CAPSUBOT=${CAPSUBOT:-capsubot}
THREADS=${SLURM_CPUS_PER_TASK:-1}
SWEEP=(sweep --grid T0=0.01:1:65:log --grid e=0:1:41 --optimize forcing --stability -o p2_T0_e.csv)
BASINS=(basins --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 --alpha 0.2792869076315278
        --max-period 16 --transient 1000 --starts 512x512 -o basins_512.csv)
DESIGN=(design --L 0.02 --mu 0.3 --force-amplitude 0.5 --force-bias 0.1 --frequency 20
        --grid e=0.3:0.9:61 --grid m1=0.05:0.5:91 -o design_e_m1.csv)

# mpirun takes the ranks from the allocation (srun --mpi=pmix works the same); --progress:
# rank 0 writes a line every 5 % with the time elapsed and left into the Slurm log.
mpirun "$CAPSUBOT" "${SWEEP[@]}" --threads "$THREADS" --resume --progress
mpirun "$CAPSUBOT" "${BASINS[@]}" --threads "$THREADS" --progress
mpirun "$CAPSUBOT" "${DESIGN[@]}" --threads "$THREADS" --resume --progress
