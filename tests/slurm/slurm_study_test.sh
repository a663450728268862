#!/usr/bin/env bash
# The Slurm scripts (scripts/slurm/, docs/slurm.md) on a real one-node Slurm cluster that this
# test starts on localhost and stops again: munged on its own key and socket, slurmctld and
# slurmd from a throwaway slurm.conf, everything in one temporary folder.
#
#   tests/slurm/slurm_study_test.sh SIGNSTIM SOURCE_DIR
#
# It submits the small study (tests/app/data/small-study.json) as a 3-task array plus the
# dependent merge + verify job, once into one shared folder with the two sbatch commands of
# docs/slurm.md and once into per-task folders with scripts/slurm/submit-study.sh, waits for
# them, and checks that each merged study equals a single-machine run byte for byte
# (manifest.json) and verifies, and that every task rendered its own units and no unit twice.
# Then it cancels a one-task array after its first unit (Slurm's SIGTERM, as at a time
# limit): no temporary or manifest may be left and the merge job must be cancelled; tasks 1,2
# of 3 submitted again leave a merge job that fails naming the missing units, and task 0 then
# finishes the study to the same manifest.
#
# Exit status: 0 passed; 1 failed (the jobs' logs are printed); 77 skipped, with the reason:
# Slurm or munge not installed (scripts/setup.sh --with-slurm), not root, or a daemon that
# cannot start or run a job in this container. Every wait has a timeout; the daemons and any
# job still running are stopped on every exit. SIGNSTIM_SLURM_TEST_KEEP=1 keeps the folder.
set -uo pipefail

if (($# != 2)); then
  echo "usage: $0 SIGNSTIM SOURCE_DIR" >&2
  exit 1
fi
signstim=$(realpath -e "$1") || exit 1
source_dir=$(realpath -e "$2") || exit 1
small=$source_dir/tests/app/data/small-study.json
scenes=$source_dir/scenes
submit=$source_dir/scripts/slurm/submit-study.sh

say() { echo "slurm-test: $*"; }
fail() { say "FAILED: $*"; exit 1; }
skip() {
  say "SKIPPED: $*"
  exit 77
}

# ---- can it run here? --------------------------------------------------------------------
missing=()
for tool in slurmctld slurmd slurmstepd sbatch scontrol squeue scancel munged munge unmunge; do
  command -v "$tool" >/dev/null 2>&1 || missing+=("$tool")
done
((${#missing[@]} == 0)) || skip "not installed: ${missing[*]} (Debian: slurm-wlm munge;" \
  "scripts/setup.sh --with-slurm installs them)"
# slurmd starts each job's processes as the job's user, which needs root; a test cluster of
# one unprivileged user is not what a lab runs.
[[ $(id -u) -eq 0 ]] || skip "slurmd needs root to start jobs (run the test as root)"

# This may itself run inside a Slurm job: nothing of the outer cluster may leak into ours.
while read -r name; do unset "$name"; done < <(compgen -e | grep -E '^(SLURM|SBATCH|SALLOC|SRUN)_')

start=$SECONDS
deadline=$((SECONDS + ${SIGNSTIM_SLURM_TEST_SECONDS:-300}))
work=$(mktemp -d "${TMPDIR:-/tmp}/signstim-slurm.XXXXXX") || fail "cannot create a temporary folder"
chmod 755 "$work"
# Marks the environment of every process of our cluster (the daemons, slurmstepd, the jobs):
# cleanup finds them by it, never by a program's name (another cluster may run here).
marker="SIGNSTIM_SLURM_TEST_CLUSTER=$work"
daemons=()

ours() {  # pids whose environment carries the marker (zombies have none)
  grep -lzxF "$marker" /proc/[0-9]*/environ 2>/dev/null | cut -d/ -f3
}

cleanup() {
  local status=$? pid i until
  trap - EXIT INT TERM HUP
  # Jobs still queued or running (a failure, an interruption): Slurm ends them itself, with
  # SIGTERM and then SIGKILL after KillWait, while its daemons are still there.
  if ((${#daemons[@]} == 3)) && kill -0 "${daemons[1]}" 2>/dev/null &&
    [[ -n $(squeue -h -o %i 2>/dev/null) ]]; then
    timeout 10 scancel --quiet --user=root 2>/dev/null
    until=$((SECONDS + 15))
    while ((SECONDS < until)) && [[ -n $(timeout 5 squeue -h -o %i 2>/dev/null) ]]; do sleep 0.5; done
  fi
  for ((i = ${#daemons[@]} - 1; i >= 0; i--)); do kill -TERM "${daemons[i]}" 2>/dev/null; done
  until=$((SECONDS + 10))
  while ((SECONDS < until)) && [[ -n $(ours) ]]; do sleep 0.2; done
  for pid in $(ours); do kill -KILL "$pid" 2>/dev/null; done
  wait 2>/dev/null
  if [[ ${SIGNSTIM_SLURM_TEST_KEEP:-0} == 1 ]]; then say "kept $work"; else rm -rf "$work"; fi
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'exit 129' HUP

# Waits until the command succeeds, every 0.2 s, at most $1 seconds (and never past the deadline).
wait_for() {
  local seconds=$1 until
  shift
  until=$((SECONDS + seconds))
  ((until > deadline)) && until=$deadline
  while ((SECONDS < until)); do
    "$@" >/dev/null 2>&1 && return 0
    sleep 0.2
  done
  "$@" >/dev/null 2>&1
}

tail_of() {  # the last lines of each log, indented
  local f
  for f in "$@"; do
    [[ -s $f ]] || continue
    echo "  --- $f (last lines) ---"
    tail -n 15 "$f" | sed 's/^/  | /'
  done
}

# ---- munge: its own key and socket -------------------------------------------------------
mkdir -m 700 "$work/munge-key" && mkdir -m 755 "$work/munge" "$work/log"
key=$work/munge-key/munge.key
if command -v mungekey >/dev/null 2>&1; then
  mungekey --create --keyfile="$key" >/dev/null 2>&1
else
  head -c 1024 /dev/urandom >"$key"
fi
[[ -s $key ]] || skip "could not create a munge key in $work"
chmod 400 "$key"
env "$marker" munged --foreground --force --socket="$work/munge/socket" --key-file="$key" \
  --pid-file="$work/munge/munged.pid" --seed-file="$work/munge/munged.seed" \
  --log-file="$work/log/munged.log" >"$work/log/munged.out" 2>&1 &
daemons+=($!)
munge_works() { munge -n -S "$work/munge/socket" | unmunge -S "$work/munge/socket"; }
munge_settled() { munge_works || ! kill -0 "${daemons[0]}"; }  # up, or gone: no use waiting
wait_for 10 munge_settled
munge_works >/dev/null 2>&1 || {
  tail_of "$work/log/munged.out" "$work/log/munged.log"
  skip "munged does not start or does not answer on its own socket in this container (its output above)"
}

# ---- slurmctld and slurmd on free ports --------------------------------------------------
listening() {  # local TCP ports in LISTEN state, decimal
  local file address state
  for file in /proc/net/tcp /proc/net/tcp6; do
    [[ -r $file ]] || continue
    while read -r _ address _ state _; do
      [[ $state == 0A ]] && echo $((16#${address##*:}))
    done <"$file"
  done
}
busy=" $(listening | tr '\n' ' ') "
for _ in $(seq 1 50); do
  port=$((20000 + RANDOM % 30000))
  [[ $busy != *" $port "* && $busy != *" $((port + 1)) "* ]] && break
done
cpus=$(nproc)
mkdir -p "$work/state" "$work/spool" "$work/jobs"
export SLURM_CONF=$work/slurm.conf
cat >"$SLURM_CONF" <<EOF
# Throwaway one-node cluster of tests/slurm/slurm_study_test.sh; no cgroups, no accounting.
ClusterName=signstim-test
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge/socket
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
MailProg=/bin/true
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
KillWait=5
MinJobAge=600
InactiveLimit=0
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=signstim-test Nodes=localhost Default=YES MaxTime=30 State=UP
EOF
env "$marker" slurmctld -D -i -f "$SLURM_CONF" >"$work/log/slurmctld.out" 2>&1 &
daemons+=($!)
env "$marker" slurmd -D -N localhost -f "$SLURM_CONF" >"$work/log/slurmd.out" 2>&1 &
daemons+=($!)
node_idle() { [[ $(sinfo -h -n localhost -o %T 2>/dev/null) == idle ]]; }
slurm_settled() { node_idle || ! kill -0 "${daemons[1]}" || ! kill -0 "${daemons[2]}"; }
wait_for 40 slurm_settled
node_idle || {
  tail_of "$work"/log/slurm*.out
  if ! kill -0 "${daemons[1]}" 2>/dev/null; then why="slurmctld exited"
  elif ! kill -0 "${daemons[2]}" 2>/dev/null; then why="slurmd exited"
  else why="the node is not idle after 40 s (sinfo: $(sinfo -h -n localhost -o '%T %E' 2>&1))"; fi
  skip "Slurm does not come up in this container: $why; the daemons' output above"
}
say "Slurm up in $((SECONDS - start)) s (ports $port and $((port + 1)), $cpus CPUs)"

# A trivial job first: a container where slurmstepd cannot run a job is a skip, not a failure
# of our scripts.
smoke=$(env "$marker" sbatch --parsable --output="$work/jobs/smoke.out" --wrap 'echo ran' 2>&1) ||
  skip "sbatch refused a trivial job: $smoke"
job_state() { scontrol show job "$1" -o 2>/dev/null | grep -o 'JobState=[A-Z_]*' | head -n 1 | cut -d= -f2; }
smoke_done() { [[ $(job_state "$smoke") =~ ^(COMPLETED|FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY)$ ]]; }
wait_for 40 smoke_done
if [[ $(job_state "$smoke") != COMPLETED ]] || ! grep -qx ran "$work/jobs/smoke.out" 2>/dev/null; then
  tail_of "$work/jobs/smoke.out" "$work"/log/slurm*.log
  skip "Slurm is up but cannot run a trivial batch job here (state $(job_state "$smoke")); logs above"
fi
say "a trivial job ran in $((SECONDS - start)) s"

# ---- the reference: one machine, one run -------------------------------------------------
reference=$work/reference
"$signstim" study "$small" --scenes "$scenes" --shard 0/1 --quiet --out "$reference" >"$work/jobs/reference.out" 2>&1 ||
  { tail_of "$work/jobs/reference.out"; fail "the single-machine run failed"; }
say "single-machine run in $((SECONDS - start)) s"

# ---- the array and the merge job, in both layouts ----------------------------------------
submit_study() {  # $1: OUT, $2: tasks, rest: submit-study options; sets array_id, merge_id
  local out=$1 tasks=$2 ids
  shift 2
  ids=$(env "$marker" "$submit" --cpus 1 --signstim "$signstim" "$@" "$small" "$out" "$tasks" -- --scenes "$scenes" \
    2>"$work/jobs/submit.err") || { cat "$work/jobs/submit.err"; fail "submit-study.sh failed"; }
  array_id=$(awk '$1 == "array" {print $2}' <<<"$ids")
  merge_id=$(awk '$1 == "merge" {print $2}' <<<"$ids")
  [[ $array_id =~ ^[0-9]+$ && $merge_id =~ ^[0-9]+$ ]] || fail "submit-study.sh printed no job ids: $ids"
}
submit_by_hand() {  # $1: OUT; the two sbatch commands of docs/slurm.md; sets array_id, merge_id
  local out=$1 logs=$1.slurm-logs
  mkdir -p "$logs"
  array_id=$(env "$marker" sbatch --parsable --array=0-2 --cpus-per-task=1 --output="$logs/array-%A_%a.out" \
    "--export=ALL,SIGNSTIM=$signstim" "$source_dir/scripts/slurm/study-array.sbatch" "$small" "$out" \
    --scenes "$scenes" 2>&1) || fail "sbatch of study-array.sbatch failed: $array_id"
  merge_id=$(env "$marker" sbatch --parsable --dependency="afterok:$array_id" --kill-on-invalid-dep=yes \
    --output="$logs/merge-%j.out" "--export=ALL,SIGNSTIM=$signstim" "$source_dir/scripts/slurm/study-merge.sbatch" \
    "$out" 2>&1) || fail "sbatch of study-merge.sbatch failed: $merge_id"
}
finished() { [[ $(job_state "$1") =~ ^(COMPLETED|FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY|PREEMPTED)$ ]]; }
all_finished() { local id; for id in "$@"; do finished "$id" || return 1; done; }

tasks_ran() {  # $1: label, $2: OUT, $3: array id, $4: task ids; sets rendered (their sum)
  local label=$1 logs=$2.slurm-logs array=$3 task state n
  rendered=0
  for task in $4; do
    state=$(job_state "${array}_$task")
    [[ $state == COMPLETED ]] || {
      tail_of "$logs"/*
      fail "$label: array task ${array}_$task ended $state"
    }
    # signstim's summary: "OUT: K of M units rendered, S already complete (shard I/3), ..."
    grep -q "(shard $task/3)" "$logs/array-${array}_$task.out" ||
      { tail_of "$logs/array-${array}_$task.out"; fail "$label: task $task did not run shard $task/3"; }
    n=$(grep -o '[0-9]* of [0-9]* units rendered' "$logs/array-${array}_$task.out" | tail -n 1 | cut -d' ' -f1)
    rendered=$((rendered + ${n:-0}))
  done
}

check_run() {  # $1: label, $2: OUT, $3: array id, $4: merge id, $5: expected "rendered" total, $6: task ids
  local label=$1 out=$2 array=$3 merge=$4 expect_rendered=$5 logs=$2.slurm-logs state
  tasks_ran "$label" "$out" "$array" "${6:-0 1 2}"
  state=$(job_state "$merge")
  [[ $state == COMPLETED ]] || { tail_of "$logs"/*; fail "$label: the merge job ended $state"; }
  grep -q "verified" "$logs/merge-$merge.out" || { tail_of "$logs/merge-$merge.out"; fail "$label: merge job did not verify"; }
  ((rendered == expect_rendered)) || { tail_of "$logs"/*; fail "$label: the tasks rendered $rendered units, expected $expect_rendered"; }
  cmp -s "$out/manifest.json" "$reference/manifest.json" ||
    fail "$label: $out/manifest.json differs from the single-machine run's"
  "$signstim" study verify "$out" >"$work/jobs/verify.out" 2>&1 ||
    { tail_of "$work/jobs/verify.out"; fail "$label: signstim study verify $out failed"; }
  say "$label: tasks ${6:-0 1 2} rendered $rendered units, merged, verified; manifest equals the single-machine run's"
}

units=$(grep -o '[0-9]* of [0-9]* units rendered' "$work/jobs/reference.out" | cut -d' ' -f1)
[[ -n $units ]] || { tail_of "$work/jobs/reference.out"; fail "the single-machine run printed no unit count"; }
# Into one shared folder by hand (signstim takes its shard from Slurm's array variables), and
# into per-task folders with submit-study.sh.
shared=$work/shared-study
per_task=$work/per-task-study
submit_by_hand "$shared"
shared_array=$array_id shared_merge=$merge_id
submit_study "$per_task" 3 --per-task-folders
per_task_array=$array_id per_task_merge=$merge_id
say "submitted: shared folder $shared_array + $shared_merge (by hand), per-task folders $per_task_array + $per_task_merge"
wait_for 240 all_finished "$shared_merge" "$per_task_merge" ||
  { squeue; tail_of "$shared.slurm-logs"/* "$per_task.slurm-logs"/*; fail "the jobs did not finish within the time limit"; }
say "both arrays and merge jobs done in $((SECONDS - start)) s"
check_run "shared folder, by hand" "$shared" "$shared_array" "$shared_merge" "$units"
check_run "per-task folders" "$per_task" "$per_task_array" "$per_task_merge" "$units"

# ---- Slurm's SIGTERM mid-run leaves no broken file; submitting again finishes the rest -----
# One task renders all units; it is cancelled once its first unit is complete. Slurm sends
# SIGTERM as at a time limit (then SIGKILL after KillWait).
interrupted=$work/interrupted-study
submit_study "$interrupted" 1
first_unit_done() { compgen -G "$interrupted/.signstim/units/*.json"; }
wait_for 120 first_unit_done || fail "interrupted: no unit completed within 120 s"
scancel "$array_id"
wait_for 60 all_finished "${array_id}_0" "$merge_id" || { squeue; fail "interrupted: the jobs did not end after scancel"; }
logs=$interrupted.slurm-logs
done_before=$(compgen -G "$interrupted/.signstim/units/*.json" | wc -l)
state=$(job_state "${array_id}_0")
[[ $state == CANCELLED ]] ||
  { tail_of "$logs"/*; fail "interrupted: the task ended $state before it could be cancelled (it had $done_before of $units units)"; }
grep -q "interrupted by SIGTERM" "$logs/array-${array_id}_0.out" ||
  { tail_of "$logs"/*; fail "interrupted: signstim did not report Slurm's SIGTERM"; }
state=$(job_state "$merge_id")
[[ $state == CANCELLED ]] || fail "interrupted: the merge job ended $state, not cancelled by its failed dependency"
broken=$(find "$interrupted" -name '*.tmp-*' | head -n 5)
[[ -z $broken ]] || fail "interrupted: temporaries left behind: $broken"
[[ ! -e $interrupted/manifest.json ]] || fail "interrupted: a manifest, with units missing"
((done_before < units)) || fail "interrupted: every unit was complete, nothing was interrupted"
say "interrupted: Slurm's SIGTERM stopped the task with $done_before of $units units complete, no temporary left"
# Some tasks again (--tasks 1,2 of 3: their ids stay their shards): the merge job must fail,
# naming the units of shard 0 that are still missing; then task 0 finishes the study.
submit_study "$interrupted" 3 --tasks 1,2
wait_for 120 all_finished "$merge_id" || { squeue; fail "the resubmission of tasks 1,2 did not finish in time"; }
tasks_ran "tasks 1,2 of 3" "$interrupted" "$array_id" "1 2"
some=$rendered
state=$(job_state "$merge_id")
if [[ $state != FAILED ]] || ! grep -q "units are in none of the folders" "$logs/merge-$merge_id.out"; then
  tail_of "$logs/merge-$merge_id.out"
  fail "tasks 1,2 of 3: the merge job ended $state, not failed naming the missing units"
fi
say "tasks 1,2 of 3: rendered $some units; the merge job failed, naming the units still missing"
submit_study "$interrupted" 3 --tasks 0
wait_for 120 all_finished "$merge_id" || { squeue; fail "the resubmission of task 0 did not finish in time"; }
check_run "task 0 of 3" "$interrupted" "$array_id" "$merge_id" $((units - done_before - some)) 0

say "passed in $((SECONDS - start)) s"
