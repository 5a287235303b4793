#!/bin/bash
# A Slurm job array that runs a sweep in 4 shards; the same script merges them in a dependent job.
#
#   jid=$(sbatch --parsable sweeps/slurm.sh)                   # the bundled example, 4 array tasks
#   sbatch --dependency=afterany:$jid --array=0 --export=ALL,MERGE_ONLY=1 sweeps/slurm.sh
#
# For another sweep: SWEEP=my-sweep.toml OUT=reports/my-sweep sbatch ... (both commands; sbatch passes the
# environment on). Run from the repository folder (the sweep file names the hull and sea files relative to
# itself).
#
# Each array task runs `slamtool sweep` without --shard: the shard is read from SLURM_ARRAY_TASK_ID,
# SLURM_ARRAY_TASK_COUNT and SLURM_ARRAY_TASK_MIN (task 0..3 of 4 here) and its results go to
# $OUT/shard-<i>-of-4/. Keep the array contiguous (0-3, not 0-6:2). OUT must be on a file system every node
# sees. A task that is killed (time limit, pre-emption) resumes where it stopped when it is run again
# (`scontrol requeue` or a new sbatch): finished cases are kept in its shard's cache.
#SBATCH --job-name=slamtool-sweep
#SBATCH --array=0-3
#SBATCH --cpus-per-task=2
#SBATCH --time=01:00:00
#SBATCH --output=slamtool-sweep-%A_%a.log

set -euo pipefail
SWEEP=${SWEEP:-sweeps/ochi-speed-flare.toml}
OUT=${OUT:-reports/sweeps/ochi-speed-flare}
SLAMTOOL=${SLAMTOOL:-slamtool}

if [ -z "${MERGE_ONLY:-}" ]; then
    # Exit status 3 (some cases failed) still leaves the shard's results to merge.
    "$SLAMTOOL" sweep "$SWEEP" -o "$OUT" -j "${SLURM_CPUS_PER_TASK:-1}" -q || [ $? -eq 3 ]
else
    "$SLAMTOOL" merge "$OUT"   # merges the shard-<i>-of-4 folders inside $OUT
fi
