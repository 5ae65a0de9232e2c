#!/bin/bash
# The full-scale tunnel study on a Slurm cluster (docs/studies.md):
#   sbatch examples/tunnel_study/slurm.sh
# 64 ranks: rank 0 hands out the 300 cases, the other 63 run them, one case
# at a time each, on one core each (a forward run of a model of fewer than
# 1000 blocks runs on one thread anyway). OUTDIR must be on a filesystem
# every node sees. A job that ends early (time limit, node failure) is
# resumed by submitting it again: finished cases are skipped.
#SBATCH --job-name=tunnel_study
#SBATCH --ntasks=64
#SBATCH --cpus-per-task=1
#SBATCH --time=04:00:00
#SBATCH --output=tunnel_study_%j.log
set -euo pipefail
here="${SLURM_SUBMIT_DIR:-$(pwd)}/examples/tunnel_study"
out="${OUTDIR:-${SLURM_SUBMIT_DIR:-$(pwd)}/tunnel_study_full}"
dda="${DDA:-dda}"
export OMP_NUM_THREADS=1
# srun starts the ranks with Slurm's PMI; `mpirun -n $SLURM_NTASKS` works as well.
srun "$dda" study "$here/study_full.yaml" -o "$out" --yes
