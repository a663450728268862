#!/usr/bin/env bash
# Submits a study to Slurm as N array tasks plus a merge-and-verify job that runs once they
# all succeed (docs/slurm.md), and prints both job ids.
#
# Usage: scripts/slurm/submit-study.sh [OPTIONS] STUDY.json OUT N [-- SIGNSTIM-STUDY-OPTIONS]
#   STUDY.json        the study file (checked here first, before anything is queued)
#   OUT               the study folder (on a file system every node sees)
#   N                 number of array tasks (shards); more than the study's units is no use
#   --cpus C          CPUs per task: encoders beside the renderer (default 4; see docs/slurm.md)
#   --time T          time limit per task (sbatch --time; default: the partition's)
#   --partition P     partition of the array tasks (sbatch --partition)
#   --gpu             one GPU per task (--gres=gpu:1); signstim renders on it with Vulkan
#   --per-task-folders  each task writes OUT.shards/task-I; the merge job copies them into OUT
#   --tasks LIST      submit only these tasks of the N (sbatch --array syntax: 3,7 or 2-4), e.g.
#                     those that failed; the merge job then needs the others' units complete
#   --logs DIR        where Slurm writes the jobs' output (default OUT.slurm-logs)
#   --sbatch ARG      one more sbatch option for both jobs (repeatable: --sbatch --account=lab)
#   --signstim PATH   the binary (default: $SIGNSTIM, else build/signstim of this checkout,
#                     else signstim on PATH)
# Everything after -- goes to each task's `signstim study` (e.g. -- --quick, -- --frames).
# Re-running the same command resumes: complete units are skipped.
# Prints "array JOBID" and "merge JOBID" on stdout, the rest on stderr.
set -euo pipefail

say() { echo "submit-study: $*" >&2; }
usage() { sed -n '5,22p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 1; }

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
cpus=4 time='' partition='' gpu=0 per_task=0 logs='' only='' signstim=${SIGNSTIM:-}
extra_sbatch=() positional=() study_options=()
while (($# > 0)); do
  case "$1" in
    --cpus) cpus=${2:?--cpus needs a number}; shift 2 ;;
    --time) time=${2:?--time needs a value}; shift 2 ;;
    --partition) partition=${2:?--partition needs a name}; shift 2 ;;
    --gpu) gpu=1; shift ;;
    --per-task-folders) per_task=1; shift ;;
    --tasks) only=${2:?--tasks needs a list of task ids}; shift 2 ;;
    --logs) logs=${2:?--logs needs a folder}; shift 2 ;;
    --sbatch) extra_sbatch+=("${2:?--sbatch needs an option}"); shift 2 ;;
    --signstim) signstim=${2:?--signstim needs a path}; shift 2 ;;
    -h|--help) usage ;;
    --) shift; study_options=("$@"); break ;;
    -*) say "unknown option '$1' (see --help)"; exit 1 ;;
    *) positional+=("$1"); shift ;;
  esac
done
((${#positional[@]} == 3)) || usage
study=${positional[0]} out=${positional[1]} tasks=${positional[2]}
[[ $tasks =~ ^[1-9][0-9]*$ ]] || { say "N must be a whole number of tasks, 1 or more, got '$tasks'"; exit 1; }
[[ $cpus =~ ^[1-9][0-9]*$ ]] || { say "--cpus must be a whole number, 1 or more, got '$cpus'"; exit 1; }
if [[ -n $only ]]; then
  [[ $only =~ ^[0-9]+(-[0-9]+)?(,[0-9]+(-[0-9]+)?)*$ ]] ||
    { say "--tasks takes task ids like 3,7 or 2-4, got '$only'"; exit 1; }
  for id in $(tr ',-' '  ' <<<"$only"); do
    ((10#$id < tasks)) || { say "--tasks: task $id is not one of the $tasks (0 to $((tasks - 1)))"; exit 1; }
  done
fi
[[ -f $study ]] || { say "no study file '$study'"; exit 1; }
command -v sbatch >/dev/null || { say "sbatch is not on PATH: run this on a Slurm login node"; exit 1; }

if [[ -z $signstim ]]; then
  if [[ -x $here/../../build/signstim ]]; then signstim=$here/../../build/signstim
  else signstim=$(command -v signstim) || { say "no signstim: build it, or give --signstim PATH"; exit 1; }
  fi
fi
# The jobs run elsewhere and later: every path they get is absolute.
signstim=$(realpath -e "$signstim")
study=$(realpath -e "$study")
out=$(realpath -m "$out")
logs=$(realpath -m "${logs:-$out.slurm-logs}")

# A mistake in the study file is found now, not by N tasks in the queue.
"$signstim" study "$study" --check "${study_options[@]}" >&2 ||
  { say "the study does not check (above); nothing submitted"; exit 1; }

mkdir -p "$logs"  # Slurm does not create the folder of --output; a job without it fails
# SIGNSTIM_SHARDS: the task id is the shard of N, whichever tasks are submitted (--tasks).
common=(--parsable "--export=ALL,SIGNSTIM=$signstim,SIGNSTIM_SHARDS=$tasks" "${extra_sbatch[@]}")
array=(--array="${only:-0-$((tasks - 1))}" --cpus-per-task="$cpus" --output="$logs/array-%A_%a.out")
[[ -n $time ]] && array+=(--time="$time")
[[ -n $partition ]] && array+=(--partition="$partition")
((gpu)) && array+=(--gres=gpu:1)

if ((per_task)); then
  array_out=$out.shards/task-%i
  shards=()
  for ((i = 0; i < tasks; i++)); do shards+=("$out.shards/task-$i"); done
else
  array_out=$out
  shards=()
fi

array_id=$(sbatch "${common[@]}" "${array[@]}" "$here/study-array.sbatch" "$study" "$array_out" "${study_options[@]}")
array_id=${array_id%%;*}  # --parsable prints "JOBID" or "JOBID;CLUSTER"
merge_id=$(sbatch "${common[@]}" --dependency="afterok:$array_id" --kill-on-invalid-dep=yes \
  --output="$logs/merge-%j.out" "$here/study-merge.sbatch" "$out" "${shards[@]}")
merge_id=${merge_id%%;*}

if [[ -n $only ]]; then what="array tasks $only of $tasks"; else what="$tasks array tasks"; fi
say "$what of $(basename "$study") into $out; logs in $logs"
say "watch: squeue -j $array_id,$merge_id   result: $logs/merge-$merge_id.out"
echo "array $array_id"
echo "merge $merge_id"
