#!/usr/bin/env bash
# The job lists of wtc-study and wtc-mobility through a real Slurm (issue 52, deliverable 3).
#
# usage: tests/study/slurm_cluster_test.sh WTC_STUDY WTC_MOBILITY WTC_SIM
#
# Starts a private cluster on localhost: munged on its own key and socket, slurmctld and one slurmd
# (Debian's slurm-wlm 22.05 and munge), each with its files in a temporary directory and on ports
# no other Slurm uses, so a host that runs its own munged or Slurm is left alone. Then it runs the
# commands of docs/accuracy-study.md, "On a Slurm cluster": the job list written, submitted as a
# job array of tools/slurm-array.sh (sbatch --wait --array=1-N), gathered; for wtc-mobility round
# by round until its report is complete. The gathered results must equal those `wtc-study run` and
# `wtc-mobility run` make on this machine: results.csv row for row without its clock columns
# (wall_time_s, real_time_factor, on_front: the Pareto front is drawn against wall time), and
# report.json without the command line. Runs failing their criteria (wtc-sim's 1) must leave the
# array's exit status 0, an error (2) must be it, and the batch script the docs show must be
# tools/slurm-array.sh. The daemons are stopped at the end (EXIT trap, by their pid files; a
# watchdog if the script is killed), even on a failure; a failure prints their logs. Exit 0:
# passed, or skipped (a line starting "skipped:") when slurmctld, slurmd or munged is not
# installed (tools/install-deps.sh installs slurm-wlm and munge). WTC_SLURM_TEST_KEEP=1 keeps the
# temporary directory.
set -euo pipefail

usage="usage: ${0##*/} WTC_STUDY WTC_MOBILITY WTC_SIM"
(($# == 3)) || { echo "$usage" >&2; exit 2; }
study_exe=$(realpath "$1")
mobility_exe=$(realpath "$2")
sim_exe=$(realpath "$3")
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
array_script=$root/tools/slurm-array.sh
study_file=$root/tests/study/tiny_study.yaml
vehicle_file=$root/vehicles/six_wheel_robot.yaml

log() { printf 'slurm_cluster_test: [%3ds] %s\n' "$SECONDS" "$*"; }
fail() { printf 'slurm_cluster_test: FAILED: %s\n' "$*" >&2; exit 1; }

# slurmd 22.05 initialises its cgroup plugin whatever the process tracking, and stops when its cgroup mount
# point (/sys/fs/cgroup) holds no cgroup file system: a fresh chroot (tools/fresh-debian-check, and so CI) has
# none mounted. There the test mounts a tmpfs of its own (root may) and names it in a cgroup.conf beside
# slurm.conf as a cgroup v1 mount point: with proctrack/linuxproc and task/none, slurmd makes no cgroup in
# it. Without root there, the test is skipped, saying so. WTC_SLURM_TEST_OWN_CGROUP=1 takes this path on a
# machine that has a cgroup file system, to try it there.
own_cgroup=0
if [[ ${WTC_SLURM_TEST_OWN_CGROUP:-0} == 1 ]] || ! grep -qs " /sys/fs/cgroup " /proc/mounts; then
  if (($(id -u) != 0)); then
    echo "skipped: no cgroup file system at /sys/fs/cgroup (a chroot?) and not root to mount one for slurmd 22.05"
    exit 0
  fi
  own_cgroup=1
fi
for daemon in slurmctld slurmd munged; do
  if ! command -v "$daemon" >/dev/null; then
    echo "skipped: $daemon is not installed (tools/install-deps.sh installs slurm-wlm and munge)"
    exit 0
  fi
done
for program in sbatch sinfo squeue scancel munge unmunge python3 timeout; do
  command -v "$program" >/dev/null || fail "$program is not installed (slurm-wlm and munge bring it)"
done
for exe in "$study_exe" "$mobility_exe" "$sim_exe"; do [[ -x $exe ]] || fail "$exe: not an executable"; done

# The batch script docs/accuracy-study.md shows is tools/slurm-array.sh but for its comments.
python3 - "$root/docs/accuracy-study.md" "$array_script" <<'EOF' || fail "docs/accuracy-study.md does not show tools/slurm-array.sh as it is"
import re, sys
doc = open(sys.argv[1]).read()
shown = re.search(r"The batch script, but for its comments:\n\n```bash\n(.*?)```", doc, re.S)
code = "".join(l for l in open(sys.argv[2]).read().splitlines(True)
               if not l.startswith("#") or l.startswith(("#!", "#SBATCH")))
if not shown or shown.group(1) != code:
    sys.exit("the block after 'The batch script, but for its comments:' differs from the script without its comments")
EOF

# No setting of an outer Slurm (this test run inside a Slurm job, a user's SBATCH_* defaults) reaches ours.
while read -r name; do unset "$name"; done < <(compgen -e | grep -E '^(SLURM|SBATCH|SALLOC|SRUN|SQUEUE|SINFO|SCANCEL|SCONTROL)_' || true)

# munged wants every directory above its socket searchable by all, and a unix socket's path is short.
base=${TMPDIR:-/tmp}
((${#base} <= 60)) || base=/tmp
tmp=$(mktemp -d "$base/wtc-slurm.XXXXXX")
socket=$tmp/munge-run/munge.socket
conf=$tmp/slurm/slurm.conf

user=$(id -un)
export SLURM_CONF=$conf

pid_of() { [[ -s $1 ]] && cat "$1"; }
# A daemon is ours when its pid file names a live process of that program.
alive() {
  local pid
  pid=$(pid_of "$2") || return 1
  [[ $(cat "/proc/$pid/comm" 2>/dev/null) == "$1" ]]
}
stop_daemon() {
  local name=$1 pidfile=$2 pid i
  alive "$name" "$pidfile" || return 0
  pid=$(pid_of "$pidfile")
  kill -TERM "$pid" 2>/dev/null || return 0
  for ((i = 0; i < 100; ++i)); do
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.1
  done
  echo "slurm_cluster_test: $name (pid $pid) did not stop in 10 s: killed" >&2
  kill -KILL "$pid" 2>/dev/null || true
}
# Jobs left by a failure cancelled (every job of this private cluster is ours), so that no slurmstepd
# outlives its slurmd; then the daemons stopped, each by its pid file.
stop_cluster() {
  local i
  if alive slurmctld "$tmp/slurm/slurmctld.pid" && [[ -n $(squeue -h -o %A 2>/dev/null) ]]; then
    echo "slurm_cluster_test: cancelling the jobs left: $(squeue -h -o %A | sort -u | tr '\n' ' ')" >&2
    scancel --user="$user" 2>/dev/null
    for ((i = 0; i < 100; ++i)); do
      [[ -z $(squeue -h -o %A 2>/dev/null) ]] && break
      sleep 0.1
    done
  fi
  stop_daemon slurmd "$tmp/slurm/slurmd.pid"
  stop_daemon slurmctld "$tmp/slurm/slurmctld.pid"
  stop_daemon munged "$tmp/munge-run/munged.pid"
}
remove_tmp() {
  if mountpoint -q "$tmp/cgroup" 2>/dev/null; then umount "$tmp/cgroup" || umount -l "$tmp/cgroup"; fi
  if [[ ${WTC_SLURM_TEST_KEEP:-0} == 1 ]]; then
    echo "slurm_cluster_test: kept $tmp" >&2
  else
    rm -rf "$tmp"
  fi
}
cleanup() {
  local status=$? f
  set +e
  [[ -n ${watchdog:-} ]] && kill "$watchdog" 2>/dev/null
  stop_cluster
  if ((status != 0)); then
    for f in "$tmp/slurm/slurmctld.log" "$tmp/slurm/slurmd.log" "$tmp/munge-key/munged.log" "$tmp"/shared/*/slurm/*.out; do
      [[ -f $f ]] || continue
      echo "----- ${f#"$tmp"/} (last 40 lines)" >&2
      tail -n 40 "$f" >&2
    done
  fi
  remove_tmp
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
chmod 755 "$tmp"
mkdir -m 755 "$tmp/munge-run" "$tmp/slurm" "$tmp/shared" "$tmp/local"
mkdir -m 700 "$tmp/munge-key" "$tmp/slurm/state" "$tmp/slurm/spool"
# The daemons detach from this script: should it be killed where no trap runs (SIGKILL: ctest's timeout), a
# watchdog in a session of its own stops them once the script is gone.
tmp=$tmp user=$user setsid bash -c "$(declare -f pid_of alive stop_daemon stop_cluster remove_tmp)
  while kill -0 $$ 2>/dev/null; do sleep 1; done
  stop_cluster
  remove_tmp" </dev/null >/dev/null 2>&1 &
watchdog=$!
if ((own_cgroup)); then
  mkdir -m 755 "$tmp/cgroup"
  mount -t tmpfs -o size=1m,mode=755 wtc-slurm-cgroup "$tmp/cgroup" || fail "cannot mount a tmpfs at $tmp/cgroup for slurmd"
  printf '%s\n' "# slurmd's cgroup mount point: a tmpfs of the test's own (no cgroup file system here)" \
    "CgroupMountpoint=$tmp/cgroup" "CgroupPlugin=cgroup/v1" >"$tmp/slurm/cgroup.conf"
  log "no cgroup file system at /sys/fs/cgroup: slurmd's cgroup mount point is a tmpfs at $tmp/cgroup"
fi

# ---- munge: its own key and socket, whatever munged the host runs ----
head -c 1024 /dev/urandom >"$tmp/munge-key/munge.key"
chmod 400 "$tmp/munge-key/munge.key"
munged --socket="$socket" --key-file="$tmp/munge-key/munge.key" --pid-file="$tmp/munge-run/munged.pid" \
  --seed-file="$tmp/munge-key/munged.seed" --log-file="$tmp/munge-key/munged.log" ||
  fail "munged did not start"
munge -n -S "$socket" | unmunge -S "$socket" >/dev/null || fail "munge credentials do not round-trip through $socket"

# ---- Slurm: one controller, one node, on the first pair of free ports from 16817 ----
port_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
ctld_port=
for ((p = 16817; p < 17817; p += 10)); do
  if port_free "$p" && port_free "$((p + 1))"; then ctld_port=$p; break; fi
done
[[ -n $ctld_port ]] || fail "no free pair of ports in 16817-17817"
cpus=$(nproc)
memory=$(awk '/^MemAvailable:/ {m = int($2 / 1024 * 0.9); print (m > 1 ? m : 1)}' /proc/meminfo)
cat >"$conf" <<EOF
# A one-node cluster on localhost for tests/study/slurm_cluster_test.sh; everything in $tmp.
ClusterName=wtctest
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$((ctld_port + 1))
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$tmp/slurm/state
SlurmdSpoolDir=$tmp/slurm/spool
SlurmctldPidFile=$tmp/slurm/slurmctld.pid
SlurmdPidFile=$tmp/slurm/slurmd.pid
SlurmctldLogFile=$tmp/slurm/slurmctld.log
SlurmdLogFile=$tmp/slurm/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
MinJobAge=4
SchedulerParameters=batch_sched_delay=0
MailProg=/bin/true
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld -f "$conf" || fail "slurmctld did not start"
slurmd -f "$conf" -N localhost || fail "slurmd did not start"
log "munged, slurmctld and slurmd started (ports $ctld_port, $((ctld_port + 1)); $cpus CPUs, ${memory} MB)"
state=
for ((i = 0; i < 120; ++i)); do
  state=$(sinfo -h -n localhost -o %t 2>/dev/null || true)
  [[ $state == idle ]] && break
  alive slurmctld "$tmp/slurm/slurmctld.pid" || fail "slurmctld died"
  alive slurmd "$tmp/slurm/slurmd.pid" || fail "slurmd died"
  sleep 0.5
done
[[ $state == idle ]] || fail "the node is not idle after 60 s (sinfo: '${state}')"
log "the node is idle"

# One job list through the cluster as docs/accuracy-study.md gives it: one task of tools/slurm-array.sh a line,
# its output in <out>/slurm/ (--parsable: the test learns the job's id); the tasks' outputs checked to be one a
# line, each from its own task.
submit() {
  local jobs=$1 name=$2 n id out dir
  dir=$(dirname "$jobs")
  n=$(wc -l <"$jobs")
  ((n > 0)) || fail "$jobs is empty"
  mkdir -p "$dir/slurm"
  out=$(timeout 120 sbatch --wait --parsable --array=1-"$n" --output="$dir/slurm/%A_%a.out" \
    "$array_script" "$jobs") || fail "sbatch --wait --array=1-$n $jobs failed or timed out: $out"
  id=${out%%;*}
  id=${id##*$'\n'}
  for ((i = 1; i <= n; ++i)); do
    grep -q "^slurm-array.sh: task $i, line $i of $jobs" "$dir/slurm/${id}_$i.out" ||
      fail "array job $id task $i did not run line $i of $jobs"
  done
  log "$name: array job $id, $n tasks, done"
}

# ---- wtc-study: the tiny study's job list against `wtc-study run` ----
"$study_exe" run "$study_file" --out "$tmp/local/study" --no-plots --workers 2 --wtc-sim "$sim_exe" \
  >"$tmp/local/study.log" 2>&1 || fail "wtc-study run: $(tail -n 5 "$tmp/local/study.log")"
log "wtc-study run: $(tail -n 1 "$tmp/local/study.log")"
"$study_exe" jobs "$study_file" --out "$tmp/shared/study" --no-plots --wtc-sim "$sim_exe"
submit "$tmp/shared/study/jobs.txt" wtc-study
"$study_exe" gather "$study_file" --out "$tmp/shared/study" --no-plots || fail "wtc-study gather"

python3 - "$tmp/local/study/results.csv" "$tmp/shared/study/results.csv" <<'EOF' || fail "the gathered study differs from wtc-study run's"
import csv, sys
clock = {"wall_time_s", "real_time_factor", "on_front"}
def rows(path):
    with open(path, newline="") as f:
        table = list(csv.DictReader(f))
    if not table:
        sys.exit(f"{path}: no runs")
    return sorted(tuple((k, v) for k, v in r.items() if k not in clock) for r in table)
local, cluster = rows(sys.argv[1]), rows(sys.argv[2])
if local != cluster:
    for a, b in zip(local, cluster):
        if a != b:
            print("run:     ", dict(a), "\ncluster: ", dict(b), file=sys.stderr)
            break
    sys.exit(f"{len(local)} runs locally, {len(cluster)} gathered from the cluster; not the same")
failed = sum(dict(r)["success"] == "0" for r in local)
if not failed:
    sys.exit("no run failed its criteria: the array's exit status for them (wtc-sim's 1) went untested")
print(f"slurm_cluster_test: study: the {len(local)} runs gathered from Slurm equal wtc-study run's, "
      f"{len(local[0])} columns each (not compared: {', '.join(sorted(clock))}); {failed} failed their "
      "criteria (wtc-sim exit 1) and the array still exited 0")
EOF

# An error in a line (wtc-sim's 2: a scene that does not load) is the array's exit status.
mkdir -p "$tmp/shared/bad/slurm"
printf '%q %q --out %q --skip-done --quiet --no-plots\n' "$sim_exe" "$tmp/no_such_scene.yaml" \
  "$tmp/shared/bad/runs/x" >"$tmp/shared/bad/jobs.txt"
status=0
timeout 120 sbatch --wait --array=1-1 --output="$tmp/shared/bad/slurm/%A_%a.out" "$array_script" \
  "$tmp/shared/bad/jobs.txt" >/dev/null || status=$?
((status == 2)) || fail "a line that exits 2 gave sbatch --wait exit status $status, not 2"
log "a line exiting 2 (a scene that does not load): sbatch --wait exits 2"

# ---- wtc-mobility: one vehicle, one engine and mode, a one-run event and a three-round search ----
settings=$tmp/mobility_settings.yaml
cat >"$settings" <<'EOF'
engines: [bullet]
modes: [force]
events: [coast, grade]
coast: {duration: 1.0}
grade: {degrees: [0, 40, 10], duration: 3}
EOF
"$mobility_exe" run "$vehicle_file" --settings "$settings" --out "$tmp/local/mobility" --no-plots --workers 2 \
  --wtc-sim "$sim_exe" >"$tmp/local/mobility.log" 2>&1 || fail "wtc-mobility run: $(tail -n 5 "$tmp/local/mobility.log")"
local_rounds=$(grep -c '^wtc-mobility: round ' "$tmp/local/mobility.log" || true)
log "wtc-mobility run: $local_rounds rounds"
mobility_jobs() {
  "$mobility_exe" jobs "$vehicle_file" --settings "$settings" --out "$tmp/shared/mobility" --no-plots --wtc-sim "$sim_exe"
}
mobility_jobs
rounds=0
while grep -q '"complete": false' "$tmp/shared/mobility/report.json"; do
  ((++rounds <= local_rounds)) || fail "wtc-mobility jobs: not complete after $local_rounds rounds (wtc-mobility run's)"
  submit "$tmp/shared/mobility/jobs.txt" "wtc-mobility-round-$rounds"
  mobility_jobs
done
((rounds == local_rounds)) || fail "$rounds rounds through Slurm, $local_rounds in wtc-mobility run"

python3 - "$tmp/local/mobility/report.json" "$tmp/shared/mobility/report.json" <<'EOF' || fail "the mobility report through Slurm differs from wtc-mobility run's"
import json, sys
def report(path):
    with open(path) as f:
        r = json.load(f)
    r.pop("command")
    return r
local, cluster = report(sys.argv[1]), report(sys.argv[2])
if not local["complete"] or not local["results"]:
    sys.exit("wtc-mobility run's report is incomplete or empty")
if local != cluster:
    print(json.dumps(local, indent=1, sort_keys=True), "\n--- through Slurm:\n",
          json.dumps(cluster, indent=1, sort_keys=True), file=sys.stderr)
    sys.exit(1)
trials = sum(len(r["trials"]) or 1 for r in local["results"])
print(f"slurm_cluster_test: mobility: {len(local['results'])} events, {trials} runs: "
      "the report through Slurm equals wtc-mobility run's (all but its command line)")
EOF
log "passed"
