#!/bin/bash
# A `gizmo fuzz` campaign as a Slurm job array (docs/fuzzing.md): task K checks shard K/TASKS of
# the campaign into OUT/shard-K; once every task has ended, `gizmo fuzz --merge OUT/shard-*`.
# tests/slurm/run.sh submits this very file to a real single-node cluster.
#
#   sbatch scripts/slurm/fuzz-array.sh                        # the campaign below: 64 tasks
#   sbatch --array=0-3 --export=ALL,FUZZ_TASKS=4,FUZZ_COUNT=200 scripts/slurm/fuzz-array.sh
#   sbatch --array=0-7 --export=ALL,FUZZ_TASKS=8,FUZZ_BOARD=my.txt,FUZZ_EXPECT=my.expect scripts/slurm/fuzz-array.sh
#
# Settings come from the environment (sbatch passes the submitter's on): GIZMO (the binary,
# default gizmo on PATH), FUZZ_SEED (2024), FUZZ_COUNT (640000 cases), FUZZ_TASKS (64: must match
# --array=0-(TASKS-1)), FUZZ_PROPERTY (all), FUZZ_OUT (results), FUZZ_BUDGET (6900: seconds of wall time after which a
# task starts no new case; 5 minutes below --time, so that a task out of time still writes its
# results, marked "complete no", rather than being killed with nothing written), FUZZ_BOARD (a board
# or replay log whose variations to check instead of generated boards; FUZZ_EXPECT, FUZZ_TIME and
# FUZZ_KEYS are its --expect, --time and --keys). Threads per task: --cpus-per-task.
#SBATCH --job-name=gizmo-fuzz
#SBATCH --array=0-63
#SBATCH --cpus-per-task=4
#SBATCH --time=02:00:00
set -euo pipefail
tasks=${FUZZ_TASKS:-64}
task=${SLURM_ARRAY_TASK_ID:?"not a task of a Slurm job array"}
out=${FUZZ_OUT:-results}
board=()
if [ -n "${FUZZ_BOARD:-}" ]; then
  board=("$FUZZ_BOARD")
  [ -n "${FUZZ_EXPECT:-}" ] && board+=(--expect "$FUZZ_EXPECT")
  [ -n "${FUZZ_TIME:-}" ] && board+=(--time "$FUZZ_TIME")
  [ -n "${FUZZ_KEYS:-}" ] && board+=(--keys "$FUZZ_KEYS")
fi
exec "${GIZMO:-gizmo}" fuzz "${board[@]}" --property "${FUZZ_PROPERTY:-all}" --seed "${FUZZ_SEED:-2024}" --count "${FUZZ_COUNT:-640000}" \
  --jobs "${SLURM_CPUS_PER_TASK:-1}" --shard "$task/$tasks" --budget "${FUZZ_BUDGET:-6900}" \
  --out "$out/shard-$task"
