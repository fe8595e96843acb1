#!/usr/bin/env bash
# Campaigns on a real cluster (docs/fuzzing.md, "Large campaigns on a cluster"): starts a
# single-node Slurm cluster on this machine (munged, slurmctld and slurmd from Debian's packages,
# with a configuration written here, in a temporary folder, on free ports), submits
# scripts/slurm/fuzz-array.sh (the docs' script) as a job array of 4 shards of 50 cases, waits for
# it with squeue, and checks that `gizmo fuzz --merge` of the shards prints the line one unsharded
# run prints. Then a task that fails, one cancelled while it runs and one whose --budget runs out:
# the merge must refuse the first two (exit 2, naming what is missing) and mark the third.
# Every daemon it started is stopped on exit, by the pid in its pid file.
#   tests/slurm/run.sh [BUILD_DIR]   (default build/release; as root, through sudo if need be)
# Installs Debian's slurm-wlm and munge when they are missing (scripts/setup.sh); their own
# services are not used.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build/release}
gizmo=$(realpath "$build/cli/gizmo")
script=$(realpath scripts/slurm/fuzz-array.sh)
[ "$(id -u)" -eq 0 ] || exec sudo "$0" "$build"  # root: the cluster's SlurmUser, and munged's start
scripts/setup.sh slurm-wlm munge
for program in munged slurmctld slurmd sbatch squeue scontrol scancel sinfo ss; do
  command -v "$program" >/dev/null || { echo "slurm test: $program is missing" >&2; exit 2; }
done

# Measured: 17 s of CPU time for the 200 cases, no failure (a failing case would be shrunk, at
# up to 100 more checks each).
seed=11 count=200 tasks=4 property=event-queue
fail() { echo "slurm test: FAILED: $*" >&2; exit 1; }

work=$(mktemp -d -t gizmo-slurm.XXXXXX)
chmod 755 "$work"  # the munge user reaches its own folder inside
jobs_submitted=()
stop_daemon() {  # PIDFILE: SIGTERM, then up to 10 s for it to end
  [ -s "$1" ] || return 0
  local pid
  pid=$(cat "$1")
  kill "$pid" 2>/dev/null || return 0
  for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || return 0; sleep 0.1; done
  echo "slurm test: pid $pid ($1) did not end on SIGTERM; killing it" >&2
  kill -9 "$pid" 2>/dev/null || true
}
cleanup() {
  local code=$?
  trap - EXIT
  for id in "${jobs_submitted[@]}"; do scancel "$id" 2>/dev/null || true; done
  stop_daemon "$work/slurmd.pid"
  stop_daemon "$work/slurmctld.pid"
  stop_daemon "$work/munge/munged.pid"
  if [ "$code" -ne 0 ]; then
    for log in slurmctld.log slurmd.log munge/munged.log; do
      [ -f "$work/$log" ] && { echo "--- $log (last lines)" >&2; tail -n 15 "$work/$log" >&2; }
    done
  fi
  rm -rf "$work"
  exit "$code"
}
trap cleanup EXIT
trap "exit 143" INT TERM  # through cleanup

# Two free TCP ports for slurmctld and slurmd, from 16817 up.
free_port() {
  local p=$1
  while [ -n "$(ss -Hltn "sport = :$p")" ]; do p=$((p + 1)); done
  echo "$p"
}
ctld_port=$(free_port 16817)
slurmd_port=$(free_port $((ctld_port + 1)))
host=$(hostname -s)

# munge, as the munge user, on a socket of its own (a machine's own munged may be running).
mkdir -p "$work/munge"
chown munge:munge "$work/munge"
chmod 711 "$work/munge"  # munged: only its user writes here; every client must reach the socket
su -s /bin/sh munge -c "munged --socket=$work/munge/socket --pid-file=$work/munge/munged.pid \
  --log-file=$work/munge/munged.log --seed-file=$work/munge/munged.seed"

mkdir -p "$work/state" "$work/spool" "$work/out"
export SLURM_CONF=$work/slurm.conf
cat > "$SLURM_CONF" <<CONF
ClusterName=gizmotest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge/socket
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
MinJobAge=3600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=1000 State=UNKNOWN
PartitionName=gizmo Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF" -N "$host"

# SECONDS_LIMIT COMMAND...: until COMMAND succeeds, or fail.
wait_until() {
  local limit=$1 start=$SECONDS
  shift
  until "$@"; do
    ((SECONDS - start < limit)) || fail "still not true after ${limit}s: $*"
    sleep 0.5
  done
}
node_idle() { [ "$(sinfo -h -n "$host" -o %T 2>/dev/null)" = idle ]; }
wait_until 60 node_idle

# Submits the docs' script as an array (ARRAY: the --array spec) with the campaign's settings and
# the extra environment given (NAME=VALUE...); prints the job id.
submit() {
  local array=$1 env="ALL,GIZMO=$gizmo,FUZZ_SEED=$seed,FUZZ_COUNT=$count,FUZZ_TASKS=$tasks,FUZZ_PROPERTY=$property"
  shift
  for setting in "$@"; do env+=",$setting"; done
  sbatch --parsable --array="$array" --cpus-per-task=1 --time=10 --chdir="$work" \
    --output="$work/out/%A_%a.log" --export="$env" "$script"
}
job_done() { [ -z "$(squeue -h -j "$1" -t all 2>/dev/null | grep -Ev ' (CD|F|CA|TO|NF|OOM|PR|BF|DL) ')" ]; }
# The state of each task of job $1, one "TASK STATE EXIT" a line.
task_states() {
  scontrol -o show job "$1" | sed -n 's/.*ArrayTaskId=\([0-9]*\) .*JobState=\([A-Z_]*\) .*ExitCode=\([0-9:]*\).*/\1 \2 \3/p' | sort -n
}
merge() {  # DIR...: sets merge_out, merge_err, merge_exit
  merge_exit=0
  "$gizmo" fuzz --merge "$@" >"$work/merge.out" 2>"$work/merge.err" || merge_exit=$?
  merge_out=$(cat "$work/merge.out") merge_err=$(cat "$work/merge.err")
}
summary() { grep -m1 '^fuzz: ' <<<"$1" || true; }

started=$SECONDS
# The campaign, unsharded.
whole_exit=0
"$gizmo" fuzz --property "$property" --seed "$seed" --count "$count" --jobs "$(nproc)" --out "$work/whole" \
  >"$work/whole.out" 2>/dev/null || whole_exit=$?
[ "$whole_exit" -le 1 ] || fail "the unsharded campaign exited $whole_exit"
whole=$(summary "$(cat "$work/whole.out")")
echo "slurm test: unsharded: $whole (exit $whole_exit, $((SECONDS - started)) s)"

# The same campaign as a job array of 4 tasks, one shard each.
t=$SECONDS
array=$(submit "0-$((tasks - 1))" "FUZZ_OUT=$work/results")
jobs_submitted+=("$array")
wait_until 900 job_done "$array"
states=$(task_states "$array")
echo "slurm test: job $array, tasks (task state exit):" $states
[ "$(grep -c . <<<"$states")" -eq "$tasks" ] || fail "expected $tasks tasks, scontrol shows: $states"
for k in $(seq 0 $((tasks - 1))); do
  grep -q '^complete yes$' "$work/results/shard-$k/results.txt" 2>/dev/null || fail "shard $k did not complete"
done
merge "$work"/results/shard-*
merged=$(summary "$merge_out")
echo "slurm test: merged:    $merged (exit $merge_exit, the array took $((SECONDS - t)) s)"
[ "$merged" = "$whole" ] || fail "the merged line differs from the unsharded one"
[ "$merge_exit" -eq "$whole_exit" ] || fail "the merge exits $merge_exit, the unsharded run $whole_exit"

# A task that fails (its program is missing): no folder, and the merge of the shards that are
# there says which shard is missing (exit 2).
t=$SECONDS
failed=$(submit 3 "FUZZ_OUT=$work/failed" "GIZMO=$work/no-such-gizmo")
jobs_submitted+=("$failed")
wait_until 120 job_done "$failed"
grep -q '^3 FAILED ' <<<"$(task_states "$failed")" || fail "task 3 should have FAILED: $(task_states "$failed")"
[ ! -e "$work/failed/shard-3" ] || fail "a failed task left a folder"
merge "$work"/results/shard-{0,1,2}
[ "$merge_exit" -eq 2 ] && grep -q "shard 3 of 4 is missing" <<<"$merge_err" ||
  fail "a merge without shard 3 should exit 2 naming it (exit $merge_exit: $merge_err)"
echo "slurm test: a failed task: $merge_err (exit 2, $((SECONDS - t)) s)"

# A task cancelled while it runs (as Slurm does at its time limit): no results.txt, and its
# folder is refused by name (exit 2).
t=$SECONDS
cancelled=$(submit 2 "FUZZ_OUT=$work/cancelled")
jobs_submitted+=("$cancelled")
running() { grep -q '^2 RUNNING ' <<<"$(task_states "$cancelled")"; }
wait_until 120 running
sleep 1  # into the cases
scancel "$cancelled"
wait_until 60 job_done "$cancelled"
grep -q '^2 CANCELLED ' <<<"$(task_states "$cancelled")" ||
  fail "task 2 ended before it could be cancelled: $(task_states "$cancelled")"
[ ! -e "$work/cancelled/shard-2/results.txt" ] || fail "a cancelled task left a results.txt"
merge "$work"/results/shard-{0,1,3} "$work/cancelled/shard-2"
[ "$merge_exit" -eq 2 ] && grep -q "cancelled/shard-2/results.txt: cannot read" <<<"$merge_err" ||
  fail "the merge with a cancelled shard should exit 2 naming it (exit $merge_exit: $merge_err)"
echo "slurm test: a cancelled task: $merge_err (exit 2, $((SECONDS - t)) s)"

# A task whose --budget runs out before its first case: it writes "complete no", and the merged
# line says "(stopped early)" and names the shard.
t=$SECONDS
early=$(submit 1 "FUZZ_OUT=$work/early" "FUZZ_BUDGET=1e-9")
jobs_submitted+=("$early")
wait_until 120 job_done "$early"
grep -q '^complete no$' "$work/early/shard-1/results.txt" || fail "a task out of budget should write 'complete no'"
merge "$work"/results/shard-{0,2,3} "$work/early/shard-1"
grep -q '(stopped early)$' <<<"$(summary "$merge_out")" && grep -q "^INCOMPLETE $work/early/shard-1: 0 of 50 cases ran" <<<"$merge_out" ||
  fail "the merge with a shard stopped early should say so: $merge_out"
[ "$(summary "$merge_out")" != "$whole" ] || fail "a merge with a shard stopped early printed the whole campaign's line"
echo "slurm test: a task out of budget: $(summary "$merge_out"); $(grep '^INCOMPLETE' <<<"$merge_out") ($((SECONDS - t)) s)"
echo "slurm test: passed in $((SECONDS - started)) s after the cluster started"
