#!/bin/sh
# Runs one scallop job as a Slurm job array: NTASKS tasks each compute their share of
# the job's bands (`scallop simulate JOB -o OUTDIR --tile-rows R --bands K:M`), then a
# job that depends on all of them (afterok) runs `scallop merge OUTDIR`. docs/cluster.md
# is the recipe.
#
# Usage: scripts/slurm-bands.sh JOB OUTDIR NTASKS [--wait] [--tile-rows R] [--tasks LIST]
#                               [sbatch options...]
#   JOB         the job file (JSON); it and its tool-path file must be readable on every node
#   OUTDIR      the output folder: it MUST be on a filesystem that every node shares
#               (NFS, Lustre, GPFS, ...); the bands, the merged outputs and the Slurm
#               logs (slurm-ARRAYID_TASK.out, slurm-MERGEID.out) go there
#   NTASKS      array tasks; task I computes bands I*B/NTASKS .. (I+1)*B/NTASKS - 1 of B
#   --wait      block until the merge is done; exit 0 only if it succeeded
#   --tile-rows R  rows per band (default: scallop's bands of <= 256 MB, made smaller
#               when there would be fewer bands than tasks)
#   --tasks LIST   submit only these array tasks (e.g. 2 or 1,3): reruns the bands of a
#               failed task with the same JOB, OUTDIR and NTASKS, then merges again
#   other options go to both sbatch calls (e.g. --partition=P --cpus-per-task=4 --time=1:00:00)
# Each task runs scallop with --threads set to the CPUs Slurm gave it (--cpus-per-task,
# default 1). The scallop run is $SCALLOP if set, else `scallop` on PATH, else this
# repository's build/scallop; it must be at the same path on every node.
# Exit status: 0 submitted (with --wait: merged), 1 a task or the merge failed or the
# job is bad input, 2 usage error. Nothing here names a machine: it runs unchanged on a
# one-node test cluster and on a real one.
set -eu

say() { echo "slurm-bands: $*" >&2; }
usage() {
  say "$*"
  say "usage: $0 JOB OUTDIR NTASKS [--wait] [--tile-rows R] [--tasks LIST] [sbatch options...]"
  exit 2
}
# One shell word, quoted for the batch scripts written below.
quote() { printf "'%s'" "$(printf '%s' "$1" | sed "s/'/'\\\\''/g")"; }
absolute() { (cd "$(dirname "$1")" && printf '%s/%s' "$(pwd -P)" "$(basename "$1")"); }
# The field NAME=value of scontrol's one-line job record.
field() { printf '%s\n' "$2" | tr ' ' '\n' | sed -n "s/^$1=//p" | head -n 1; }

[ $# -ge 3 ] || usage "needs JOB, OUTDIR and NTASKS"
job=$1 outdir=$2 ntasks=$3
shift 3
case $ntasks in '' | *[!0-9]*) usage "NTASKS '$ntasks': expected a whole number >= 1" ;; esac
[ "$ntasks" -ge 1 ] || usage "NTASKS '$ntasks': expected a whole number >= 1"
wait=0 tile_rows="" tasks="" sbatch_options=""
while [ $# -gt 0 ]; do
  case $1 in
    --wait) wait=1 ;;
    --tile-rows) [ $# -ge 2 ] || usage "--tile-rows needs a number"; tile_rows=$2; shift ;;
    --tile-rows=*) tile_rows=${1#--tile-rows=} ;;
    --tasks) [ $# -ge 2 ] || usage "--tasks needs a list"; tasks=$2; shift ;;
    --tasks=*) tasks=${1#--tasks=} ;;
    --array* | -a* | --dependency* | -d* | --wrap*) usage "'$1' is set by this script" ;;
    *) sbatch_options="$sbatch_options $(quote "$1")" ;;
  esac
  shift
done
case $tile_rows in *[!0-9]*) usage "--tile-rows '$tile_rows': expected a whole number >= 1" ;; esac
[ "$tile_rows" != 0 ] || usage "--tile-rows '$tile_rows': expected a whole number >= 1"

# The scallop that every task runs, as an absolute path.
repo=$(cd "$(dirname "$0")/.." && pwd -P)
if [ -n "${SCALLOP:-}" ]; then
  scallop=$SCALLOP
elif command -v scallop >/dev/null 2>&1; then
  scallop=$(command -v scallop)
else
  scallop=$repo/build/scallop
fi
[ -x "$scallop" ] || { say "$scallop: no scallop program there (set SCALLOP, or build it)"; exit 1; }
scallop=$(absolute "$scallop")

[ -f "$job" ] && [ -r "$job" ] || { say "$job: no readable job file"; exit 1; }
job=$(absolute "$job")
mkdir -p "$outdir" || { say "$outdir: cannot create the output folder"; exit 1; }
outdir=$(cd "$outdir" && pwd -P)

# The band layout: B bands of R rows. With fewer bands than tasks, smaller bands.
layout() {
  "$scallop" simulate "$job" --print-bands ${1:+--tile-rows "$1"} ||
    { say "$job: scallop refused the job (message above)"; exit 1; }
}
line=$(layout "$tile_rows")
bands=$(printf '%s\n' "$line" | sed -n 's/.*bands=\([0-9]*\) .*/\1/p')
rows=$(printf '%s\n' "$line" | sed -n 's/.* rows=\([0-9]*\) .*/\1/p')
if [ -z "$tile_rows" ]; then
  # Even shares: k bands per task for the smallest k whose bands are no larger than the
  # default ones (whole 256-row EXR tiles above 256 rows); smaller bands if the
  # rounding left fewer bands than tasks.
  default_rows=$(printf '%s\n' "$line" | sed -n 's/.*band_rows=\([0-9]*\) .*/\1/p')
  k=1
  while :; do
    share=$(((rows + ntasks * k - 1) / (ntasks * k)))
    [ "$share" -le 256 ] || share=$(((share + 255) / 256 * 256))
    effective=$share
    [ "$effective" -le "$rows" ] || effective=$rows
    [ "$effective" -gt "$default_rows" ] || break
    k=$((k + 1))
  done
  for tile_rows in "$share" $(((rows + ntasks - 1) / ntasks)); do
    line=$(layout "$tile_rows")
    bands=$(printf '%s\n' "$line" | sed -n 's/.*bands=\([0-9]*\) .*/\1/p')
    [ "$bands" -lt "$ntasks" ] || break
  done
fi
[ "$bands" -ge "$ntasks" ] ||
  usage "NTASKS $ntasks is more than the job's $bands bands ($rows rows, --tile-rows $tile_rows)"

# The array's task indices: all, or the --tasks LIST to run again.
if [ -n "$tasks" ]; then
  case $tasks in *[!0-9,-]* | ,* | *, | -* | *-) usage "--tasks '$tasks': expected indices like 2 or 1,3 or 0-2" ;; esac
  for i in $(printf '%s' "$tasks" | tr ',-' '  '); do
    [ "$i" -lt "$ntasks" ] || usage "--tasks '$tasks': task $i does not exist (tasks 0..$((ntasks - 1)))"
  done
  array=$tasks
else
  array=0-$((ntasks - 1))
fi

# The task's script: its share of the bands from SLURM_ARRAY_TASK_ID.
task_script() {
  cat <<EOF
#!/bin/sh
set -eu
i=\$SLURM_ARRAY_TASK_ID n=$ntasks b=$bands
k=\$((i * b / n)) m=\$(((i + 1) * b / n))
threads=\${SLURM_CPUS_PER_TASK:-\${SLURM_CPUS_ON_NODE:-1}}
echo "slurm-bands: task \$i of \$n: bands \$k..\$((m - 1)) of \$b, \$threads threads, on \$(hostname)"
start=\$(date +%s)
status=0
$(quote "$scallop") simulate $(quote "$job") -o $(quote "$outdir") --tile-rows $tile_rows --bands "\$k:\$m" --threads "\$threads" || status=\$?
echo "slurm-bands: task \$i: exit status \$status after \$((\$(date +%s) - start)) s"
exit \$status
EOF
}
merge_script() {
  cat <<EOF
#!/bin/sh
start=\$(date +%s)
status=0
$(quote "$scallop") merge $(quote "$outdir") || status=\$?
echo "slurm-bands: merge: exit status \$status after \$((\$(date +%s) - start)) s"
exit \$status
EOF
}

# shellcheck disable=SC2086
array_id=$(task_script | eval sbatch --parsable --job-name=scallop-bands --array="$array" \
  --output="$(quote "$outdir/slurm-%A_%a.out")" $sbatch_options) ||
  { say "sbatch refused the array (message above)"; exit 1; }
array_id=${array_id%%;*}
# shellcheck disable=SC2086
merge_id=$(merge_script | eval sbatch --parsable --job-name=scallop-merge \
  --dependency=afterok:"$array_id" --kill-on-invalid-dep=yes \
  --output="$(quote "$outdir/slurm-%j.out")" $sbatch_options) ||
  { say "sbatch refused the merge job (message above); cancelling the array"; scancel "$array_id"; exit 1; }
merge_id=${merge_id%%;*}
say "job array $array_id: tasks $array of $ntasks over $bands bands of $tile_rows rows"
say "merge job $merge_id runs after all of them succeed; logs: $outdir/slurm-*.out"
echo "$array_id $merge_id"
[ "$wait" -eq 1 ] || exit 0

# --wait: poll the merge job until it ends (scontrol, or sacct once scontrol forgot it).
state=""
while :; do
  if record=$(scontrol show job --oneliner "$merge_id" 2>/dev/null); then
    state=$(field JobState "$record")
  elif command -v sacct >/dev/null 2>&1; then
    state=$(sacct --noheader --allocations --jobs "$merge_id" --format=State 2>/dev/null |
      head -n 1 | tr -d ' ')
  else
    state=""
  fi
  case $state in
    PENDING | RUNNING | CONFIGURING | COMPLETING | SUSPENDED | REQUEUED | RESIZING) sleep 2 ;;
    *) break ;;
  esac
done
if [ "$state" = COMPLETED ]; then
  say "merged: $outdir/heights.exr, heights.gsf, preview.png, report.json"
  exit 0
fi
say "the merge job $merge_id ended ${state:-in an unknown state}; the map is not merged"
# Which tasks left bands unfinished: rerun those with --tasks.
failed=""
i=0
while [ "$i" -lt "$ntasks" ]; do
  k=$((i * bands / ntasks)) m=$(((i + 1) * bands / ntasks))
  while [ "$k" -lt "$m" ]; do
    if [ ! -f "$outdir/band-$k.json" ]; then
      failed="$failed${failed:+,}$i"
      break
    fi
    k=$((k + 1))
  done
  i=$((i + 1))
done
if [ -n "$failed" ]; then
  say "tasks with missing bands: $failed (logs $outdir/slurm-${array_id}_*.out); rerun them with"
  say "  $0 $job $outdir $ntasks --tile-rows $tile_rows --tasks $failed --wait"
else
  say "every band is there: see $outdir/slurm-$merge_id.out, or run \`scallop merge $outdir\`"
fi
exit 1
