#!/usr/bin/env bash
# One line of a WTC job list (`wtc-study jobs`, `wtc-mobility jobs`: one wtc-sim command a line)
# as one task of a Slurm job array: task i runs line i.
#
#   sbatch --array=1-"$(wc -l < /shared/study/jobs.txt)" tools/slurm-array.sh /shared/study/jobs.txt
#
# sbatch copies this script when the job is submitted: it need not be on the shared file system,
# but the job list, the runs' directory and wtc-sim must be, at the paths the list names.
# A list longer than the cluster's MaxArraySize (default 1001: indices 0-1000) goes in pieces,
# the second argument added to the index: --array=1-1000 ... jobs.txt 1000 runs lines 1001-2000.
#
# Exit status: 0 when the run succeeded or its scene's criterion failed (wtc-sim's 1: a result,
# gathered like any other), else the line's own (2: an error), so Slurm marks only errors FAILED
# and `sbatch --wait` exits non-zero only for them. Docs: docs/accuracy-study.md, "On a Slurm
# cluster"; tests/study/slurm_cluster_test.sh runs it against a real Slurm on localhost.
#SBATCH --job-name=wtc-jobs
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
set -euo pipefail
usage="usage: sbatch --array=1-N tools/slurm-array.sh JOBS.txt [OFFSET]"
if (($# < 1)) || [[ -z ${SLURM_ARRAY_TASK_ID:-} ]]; then
  echo "$usage (a Slurm array task: SLURM_ARRAY_TASK_ID)" >&2
  exit 2
fi
jobs=$1
offset=${2:-0}
task=$SLURM_ARRAY_TASK_ID
n=$((task + offset))
line=$(sed -n "${n}p" "$jobs")
if [[ -z $line ]]; then
  echo "slurm-array.sh: $jobs has no line $n (array task $task, offset $offset)" >&2
  exit 2
fi
echo "slurm-array.sh: task $task, line $n of $jobs on $(hostname)"
status=0
bash -c "$line" || status=$?
if ((status == 1)); then status=0; fi
exit "$status"
