#!/bin/bash
# scripts/slurm-bands.sh on a real one-node Slurm cluster that this test starts itself.
#
# Debian's slurm-wlm and munge (scripts/install-deps.sh): munged with a key of its own
# (unless a munged already answers on the default socket), slurmctld and slurmd in the
# foreground (-D) with a slurm.conf written into a temporary folder (this machine's
# hostname and CPU count; proctrack/linuxproc, task/none, select/cons_tres; ports that
# are free now, so that two runs of the suite at once do not meet). The test stops all
# of them on every exit (trap), and every wait has a timeout.
#   1. A 4-band job through the script, 4 tasks, --wait: the merged heights.gsf,
#      preview.png and heights.exr pixels equal a single in-memory run's, byte for byte,
#      and the float64 band files equal those of one process computing all 4 bands.
#   2. The same job again; task 2's scallop is killed while it runs: the script's --wait
#      fails naming task 2, merge refuses (band-2 missing) and writes nothing; the script
#      with --tasks 2 reruns that band only, and the map is the same bits again.
#   3. Usage errors of the script (more tasks than bands, a task that does not exist).
# Needs root (it starts daemons as root); otherwise it is skipped (exit 77, ctest SKIP).
# Usage: slurm_bands_test.sh SCALLOP_BINARY
set -u

scallop=${1:?usage: slurm_bands_test.sh SCALLOP_BINARY}
repo=$(cd "$(dirname "$0")/../.." && pwd -P)
script=$repo/scripts/slurm-bands.sh

if [ "$(id -u)" -ne 0 ]; then
  echo "slurm_bands_test: SKIPPED: needs root to start munged, slurmctld and slurmd (CI runs as root)"
  exit 77
fi
for prog in munged mungekey slurmctld slurmd sbatch scontrol scancel squeue sinfo iinfo; do
  command -v "$prog" >/dev/null 2>&1 || {
    echo "slurm_bands_test: FAIL: '$prog' is missing: run scripts/install-deps.sh (slurm-wlm, munge)"
    exit 1
  }
done

failures=0
fail() { echo "slurm_bands_test: FAIL: $*"; failures=$((failures + 1)); }
note() { echo "slurm_bands_test: $*"; }
# wait_for SECONDS WHAT COMMAND...: polls COMMAND every 0.2 s until it succeeds.
wait_for() {
  local limit=$1 what=$2 start=$SECONDS
  shift 2
  until "$@" >/dev/null 2>&1; do
    if [ $((SECONDS - start)) -ge "$limit" ]; then
      fail "timed out after $limit s waiting for $what"
      return 1
    fi
    sleep 0.2
  done
}

tmp=$(mktemp -d /tmp/scallop-slurm-test.XXXXXX)
chmod 755 "$tmp"
pids=""  # daemons started here, stopped in this order
cleanup() {
  set +e
  if [ -n "${SLURM_CONF:-}" ] && [ -f "$SLURM_CONF" ]; then
    timeout 10 scancel --full --quiet --user=root >/dev/null 2>&1
  fi
  for pid in $pids; do kill -TERM "$pid" 2>/dev/null; done
  for pid in $pids; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
    kill -KILL "$pid" 2>/dev/null
  done
  # Job steps that outlived slurmd (none expected): found by this test's folder.
  for pid in $(grep -lzF -- "$tmp/" /proc/[0-9]*/cmdline 2>/dev/null); do
    pid=${pid#/proc/}
    kill -KILL "${pid%/cmdline}" 2>/dev/null
  done
  if [ "$failures" -gt 0 ]; then
    for log in "$tmp"/*.log; do
      [ -f "$log" ] && { echo "--- $log (tail)"; tail -n 20 "$log"; }
    done
  fi
  rm -rf "$tmp"
}
trap cleanup EXIT
test_start=$SECONDS
trap 'exit 1' INT TERM HUP

# A TCP port no socket of this machine uses now (/proc/net/tcp*: no iproute2 needed).
free_port() {
  local p
  for _ in $(seq 100); do
    p=$((20000 + RANDOM % 40000))
    if ! grep -qi ":$(printf %04X "$p") " /proc/net/tcp /proc/net/tcp6 2>/dev/null; then
      echo "$p"
      return 0
    fi
  done
  return 1
}
# The processes with an argument equal to each of ARGS (/proc: no procps needed).
pids_with() {
  local f pid arg ok
  for f in $(grep -lxzF -- "$1" /proc/[0-9]*/cmdline 2>/dev/null); do
    pid=${f#/proc/}
    pid=${pid%/cmdline}
    [ "$pid" = "$$" ] && continue
    ok=1
    for arg in "$@"; do grep -qxzF -- "$arg" "$f" 2>/dev/null || ok=0; done
    [ $ok -eq 1 ] && echo "$pid"
  done
}

# --- munge: the running one, or our own with its own key.
auth_info=""
if ! (timeout 5 munge -n </dev/null | timeout 5 unmunge) >/dev/null 2>&1; then
  mkdir -m 700 "$tmp/munge"
  mungekey --create --keyfile="$tmp/munge/munge.key" || { fail "mungekey"; exit 1; }
  chmod 400 "$tmp/munge/munge.key"
  munged --foreground --force --socket="$tmp/munge/socket" --key-file="$tmp/munge/munge.key" \
    --pid-file="$tmp/munge/munged.pid" --log-file="$tmp/munged.log" \
    --seed-file="$tmp/munge/seed" >/dev/null 2>&1 &
  pids="$pids $!"
  auth_info="AuthInfo=socket=$tmp/munge/socket"
  wait_for 20 "munged" sh -c "munge -n -S '$tmp/munge/socket' </dev/null | unmunge -S '$tmp/munge/socket'" ||
    exit 1
fi

# --- slurm.conf for this machine, now.
host=$(hostname -s)
cpus=$(nproc)
ctld_port=$(free_port) && slurmd_port=$(free_port) || { fail "no free port"; exit 1; }
mkdir -p "$tmp/state" "$tmp/spool"
cat >"$tmp/slurm.conf" <<EOF
ClusterName=scallop-test
SlurmctldHost=$host
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
$auth_info
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
KillWait=2
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$tmp/slurm.conf
slurmctld -D -f "$SLURM_CONF" >"$tmp/slurmctld.out.log" 2>&1 &
pids="$pids $!"
slurmd -D -f "$SLURM_CONF" -N "$host" >"$tmp/slurmd.out.log" 2>&1 &
pids="$pids $!"
start=$SECONDS
node_idle() { sinfo --noheader --nodes="$host" --format=%t | grep -qx idle; }
wait_for 60 "slurmctld and slurmd (node $host idle)" node_idle || exit 1
note "one-node Slurm up in $((SECONDS - start)) s: $host, $cpus CPUs, slurmctld port $ctld_port"

# --- The job: the default job at 0.003 mm, 6667 x 6667 cells; --tile-rows 1792 makes
# 4 bands (3 of 1792 rows, one of 1291), each computed in about a second or two.
job=$tmp/job.json
"$scallop" simulate --print-default-job | sed 's/"spacing": *[0-9.]*/"spacing": 0.003/' >"$job"
rows=1792
layout=$("$scallop" simulate "$job" --print-bands --tile-rows $rows)
[ "$layout" = "bands=4 band_rows=1792 rows=6667 columns=6667 exr_tile_rows=256" ] ||
  fail "the test job's layout is '$layout', expected 4 bands of 1792 rows"
export SCALLOP=$scallop

start=$SECONDS
"$scallop" simulate "$job" -o "$tmp/single" --threads "$cpus" >/dev/null 2>"$tmp/single.log" ||
  fail "the single in-memory run failed"
"$scallop" simulate "$job" -o "$tmp/oneprocess" --tile-rows $rows --bands 0:4 >/dev/null \
  2>"$tmp/oneprocess.log" || fail "the single-process band run failed"

note "the single runs took $((SECONDS - start)) s"
pixels() { iinfo --hash "$1" | sed -n 's/.*SHA-1: *//p'; }
# same_map DIR: DIR's merged outputs and band files are the single runs' bits.
same_map() {
  local dir=$1 f b
  for f in heights.gsf preview.png; do
    cmp -s "$tmp/single/$f" "$dir/$f" || fail "$dir/$f differs from the single run's"
  done
  [ -n "$(pixels "$tmp/single/heights.exr")" ] &&
    [ "$(pixels "$tmp/single/heights.exr")" = "$(pixels "$dir/heights.exr")" ] ||
    fail "$dir/heights.exr's pixels differ from the single run's"
  for b in 0 1 2 3; do
    cmp -s "$tmp/oneprocess/band-$b.raw" "$dir/band-$b.raw" ||
      fail "$dir/band-$b.raw differs from the single process's float64 heights"
  done
}

# --- 1. Four tasks, merged, the same bits.
start=$SECONDS
timeout 150 "$script" "$job" "$tmp/four" 4 --tile-rows $rows --wait >"$tmp/four.log" 2>&1
status=$?
if [ $status -ne 0 ]; then
  fail "slurm-bands.sh --wait exited $status (log below)"
  cat "$tmp/four.log"
else
  note "4 tasks and the merge took $((SECONDS - start)) s"
  same_map "$tmp/four"
  [ "$(ls "$tmp"/four/slurm-*.out | wc -l)" -eq 5 ] || fail "expected 5 Slurm logs in four/"
fi

# --- 2. Task 2 killed while it runs; only it rerun.
out=$tmp/killed
timeout 150 "$script" "$job" "$out" 4 --tile-rows $rows --wait >"$tmp/killed.log" 2>&1 &
waiter=$!
task_pid() { pids_with "$out" "$scallop" 2:3 | head -n 1; }
victim=""
start=$SECONDS
while [ -z "$victim" ] && [ $((SECONDS - start)) -lt 90 ]; do
  victim=$(task_pid)
  [ -n "$victim" ] || sleep 0.05
done
if [ -z "$victim" ]; then
  fail "task 2's scallop never appeared within 90 s"
else
  kill -KILL "$victim" || fail "could not kill task 2's scallop (pid $victim)"
  note "killed task 2's scallop (pid $victim)"
fi
wait "$waiter"
status=$?
note "the script saw the failure $((SECONDS - start)) s after the submission"
[ $status -eq 1 ] || fail "slurm-bands.sh --wait exited $status after a killed task, expected 1"
grep -q "tasks with missing bands: 2 " "$tmp/killed.log" ||
  fail "the script did not name task 2: $(cat "$tmp/killed.log")"
[ ! -e "$out/band-2.json" ] || fail "band-2.json exists: the task finished before the kill"
for f in heights.exr heights.gsf preview.png report.json; do
  [ ! -e "$out/$f" ] || fail "$out/$f exists after a failed task"
done
merge_err=$("$scallop" merge "$out" 2>&1 >/dev/null)
status=$?
[ $status -eq 1 ] || fail "merge with band 2 missing exited $status, expected 1"
case $merge_err in
  *band-2.json*"--bands 2:3"*) ;;
  *) fail "merge did not name band 2 and its command: $merge_err" ;;
esac
[ ! -e "$out/heights.exr" ] || fail "merge left heights.exr with band 2 missing"
start=$SECONDS
timeout 120 "$script" "$job" "$out" 4 --tile-rows $rows --tasks 2 --wait >"$tmp/rerun.log" 2>&1
status=$?
if [ $status -ne 0 ]; then
  fail "rerunning task 2 exited $status: $(cat "$tmp/rerun.log")"
else
  note "task 2 rerun and merged in $((SECONDS - start)) s"
  same_map "$out"
  [ "$(ls "$out"/slurm-*_2.out | wc -l)" -eq 2 ] || fail "expected task 2 to have run twice"
fi

# --- 3. Usage errors: nothing is submitted.
timeout 30 "$script" "$job" "$tmp/usage" 5 --tile-rows $rows >"$tmp/usage.log" 2>&1
[ $? -eq 2 ] && grep -q "more than the job's 4 bands" "$tmp/usage.log" ||
  fail "5 tasks over 4 bands: $(cat "$tmp/usage.log")"
timeout 30 "$script" "$job" "$tmp/usage" 4 --tasks 4 >"$tmp/usage.log" 2>&1
[ $? -eq 2 ] && grep -q "task 4 does not exist" "$tmp/usage.log" ||
  fail "--tasks 4 of 4: $(cat "$tmp/usage.log")"
[ -z "$(squeue --noheader --name=scallop-bands 2>/dev/null)" ] ||
  fail "a usage error submitted a job"

if [ "$failures" -gt 0 ]; then
  echo "slurm_bands_test: $failures failure(s)"
  exit 1
fi
note "passed in $((SECONDS - test_start)) s"
