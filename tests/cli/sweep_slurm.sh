#!/usr/bin/env bash
# The Slurm recipe of docs/scale-out.md against a local single-node Slurm started here (munged,
# slurmctld and slurmd on private ports and files, stopped on exit): a 12-run sweep as a job
# array of 2 tasks (docs/recipes/sweep_array.sbatch), merged, equals the unsharded sweep in
# every CSV column but the frame timings. Skips (exit 77), saying why, where Slurm cannot be
# started: not root, slurm-wlm or munge not installed, or the daemons do not come up.
# Usage: sweep_slurm.sh TRIPTYCH SOURCE_DIR
set -u
bin=$(realpath "$1")
src=$(realpath "$2")
skip() { echo "skipped: $1"; exit 77; }
[ "$(id -u)" -eq 0 ] || skip "a local slurmd must run as root"
for t in munged mungekey slurmctld slurmd sbatch sinfo; do
    command -v "$t" >/dev/null || skip "$t is not installed (apt-get install slurm-wlm munge)"
done
work=$(mktemp -d)
# Our daemons by their pid files (not by name: a machine may run its own), waited for until
# they are gone (they write their pid files as they start).
stop() {
    local pids="" alive
    for f in "$work/run/slurmd.pid" "$work/run/slurmctld.pid" "$work/munged.pid"; do
        [ -s "$f" ] && pids="$pids $(cat "$f")"
    done
    [ -n "$pids" ] && kill $pids 2>/dev/null
    for _ in $(seq 40); do
        alive=""
        for p in $pids; do kill -0 "$p" 2>/dev/null && alive="$alive $p"; done
        [ -z "$alive" ] && break
        sleep 0.25
    done
    [ -n "$alive" ] && kill -9 $alive 2>/dev/null
    rm -rf "$work"
}
trap stop EXIT
mkdir -p "$work"/{state,spool,log,run}
mungekey --create --keyfile="$work/munge.key" --force >/dev/null 2>&1 || skip "mungekey failed"
chmod 600 "$work/munge.key"
munged --key-file="$work/munge.key" --socket="$work/munge.sock" --pid-file="$work/munged.pid" \
    --log-file="$work/munged.log" --seed-file="$work/munge.seed" --force >/dev/null 2>&1 ||
    skip "munged does not start"
port=$((20000 + $$ % 20000))
node=$(hostname)
cat >"$work/slurm.conf" <<CONF
ClusterName=triptych-test
SlurmctldHost=$node
AuthType=auth/munge
AuthInfo=socket=$work/munge.sock
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/run/slurmctld.pid
SlurmdPidFile=$work/run/slurmd.pid
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
NodeName=$node CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$work/slurm.conf
slurmctld -f "$SLURM_CONF" >/dev/null 2>&1 || skip "slurmctld does not start"
slurmd -f "$SLURM_CONF" >/dev/null 2>&1 || skip "slurmd does not start"
for _ in $(seq 30); do
    sinfo -h -o %t 2>/dev/null | grep -q idle && break
    sleep 1
done
sinfo -h -o %t 2>/dev/null | grep -q idle || skip "the node did not become idle in 30 s"
# A job that does nothing must run before the recipe is judged: where this Slurm cannot launch
# a task (a container without what slurmd needs), that is a skip with the reason, not a failure.
# Submitted, then waited for by wait_job: `sbatch --wait` polls every 10 s, which was 20 of this
# test's 34 s on 2 cores.
# wait_job ID SECONDS: polls the controller every 0.2 s until every task of job ID has ended;
# succeeds only if each ended COMPLETED (exit 0), as `sbatch --wait` would.
wait_job() {
    local id=$1 states
    for _ in $(seq $(($2 * 5))); do
        states=$(scontrol -o show job "$id" 2>/dev/null | grep -o 'JobState=[A-Z_]*')
        if [ -n "$states" ] && ! grep -qE '=(PENDING|CONFIGURING|RUNNING|COMPLETING|SUSPENDED)$' <<<"$states"; then
            ! grep -qv '=COMPLETED$' <<<"$states"
            return
        fi
        sleep 0.2
    done
    return 1
}
probe=$(cd "$work" && sbatch --parsable -o "$work/probe.log" --wrap true) && wait_job "$probe" 60 ||
    skip "this Slurm cannot run a job here ($(tail -n 1 "$work/log/slurmd.log" 2>/dev/null))"

args=(builtin:courtyard-small --res 48x27 --lights 4,8 --msaa 1,4 --tile 8,16
      --pipelines forwardplus --frames 1 --warmup 0)
"$bin" sweep "${args[@]}" --out "$work/whole" >/dev/null 2>&1 || { echo "FAIL: the unsharded sweep"; exit 1; }
out=$work/study
mkdir -p "$out"
array=$(cd "$work" && TRIPTYCH=$bin sbatch --parsable --array=0-1 \
    "$src/docs/recipes/sweep_array.sbatch" "$out" "${args[@]}") && wait_job "$array" 240 ||
    { echo "FAIL: the job array"; cat "$work"/*.log 2>/dev/null | tail -5; exit 1; }
"$bin" merge "$out"/shard-* --out "$out/merged" >/dev/null || { echo "FAIL: merge"; exit 1; }

. "$(dirname "$0")/sweep_csv.sh"
if [ "$(strip_timings "$work/whole/sweep.csv")" != "$(strip_timings "$out/merged/sweep.csv")" ]; then
    echo "FAIL: the merged sweep.csv differs from the unsharded one"
    exit 1
fi
echo "ok: $(($(wc -l <"$out/merged/sweep.csv") - 1)) runs as a Slurm job array of 2, merged: the unsharded sweep.csv"
