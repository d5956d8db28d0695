#!/bin/bash
# A real single-node Slurm: starts munged, slurmctld and slurmd on localhost with a minimal configuration written
# here (no systemd; proctrack/pgid, task/none), submits a 6-job curriculum with `batch slurm`, waits for it, checks
# that every package validates and is byte-identical to the local runner's, prints the throughput of both, and
# stops exactly the daemons it started. Skips (exit 77) with the reason when Slurm or munge are missing or the
# daemons cannot start.
#
# Usage: slurm_test.sh CLI CURRICULUM
set -u
CLI=$1
CURRICULUM=$2
SKIP=77

skip() {
    echo "SKIP: $*"
    exit $SKIP
}

for tool in munged slurmctld slurmd sbatch sinfo squeue; do
    command -v "$tool" >/dev/null 2>&1 || skip "$tool is not installed (tools/setup.sh installs slurm-wlm and munge)"
done
[ "$(id -u)" = 0 ] || skip "the single-node Slurm runs its daemons as root; run the test as root"

WORK=$(mktemp -d /tmp/hs-slurm-test-XXXXXX)
STARTED=() # pids of the daemons this test started, and only those

stop_daemons() {
    for pid in "${STARTED[@]}"; do
        kill "$pid" 2>/dev/null
    done
    for pid in "${STARTED[@]}"; do
        for _ in $(seq 50); do
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.1
        done
        kill -9 "$pid" 2>/dev/null
    done
    STARTED=()
}
cleanup() {
    stop_daemons
    rm -rf "$WORK"
}
trap cleanup EXIT

show_logs() {
    for log in "$WORK"/munge/munged.log "$WORK"/slurmctld.log "$WORK"/slurmd.log; do
        [ -f "$log" ] && { echo "--- $log"; tail -n 15 "$log"; }
    done
}

# munge: a key and a socket of our own.
mkdir -p "$WORK/munge" "$WORK/state" "$WORK/spool"
chmod 700 "$WORK/munge"
dd if=/dev/urandom of="$WORK/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$WORK/munge/munge.key"
munged --foreground --force --key-file="$WORK/munge/munge.key" --socket="$WORK/munge/socket" \
    --pid-file="$WORK/munge/munged.pid" --log-file="$WORK/munge/munged.log" --seed-file="$WORK/munge/seed" \
    >/dev/null 2>&1 &
STARTED+=($!)
for _ in $(seq 50); do [ -S "$WORK/munge/socket" ] && break; sleep 0.1; done
[ -S "$WORK/munge/socket" ] || { show_logs; skip "munged did not start"; }

# Slurm: one node (this machine as slurmd -C describes it), one partition, free ports.
NODE_LINE=$(slurmd -C 2>/dev/null | head -n 1)
NODE=$(echo "$NODE_LINE" | sed -n 's/^NodeName=\([^ ]*\).*/\1/p')
[ -n "$NODE" ] || skip "slurmd -C does not describe this machine"
PORT=$((20000 + RANDOM % 20000))
export SLURM_CONF="$WORK/slurm.conf"
cat >"$SLURM_CONF" <<EOF
ClusterName=hstest
SlurmctldHost=localhost
SlurmctldPort=$PORT
SlurmdPort=$((PORT + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$WORK/munge/socket
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$WORK/state
SlurmdSpoolDir=$WORK/spool
SlurmctldPidFile=$WORK/slurmctld.pid
SlurmdPidFile=$WORK/slurmd.pid
SlurmctldLogFile=$WORK/slurmctld.log
SlurmdLogFile=$WORK/slurmd.log
ProctrackType=proctrack/pgid
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
ReturnToService=2
$NODE_LINE NodeHostname=$NODE NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=batch Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
sed -i 's/ UpTime=[^ ]*//' "$SLURM_CONF"
slurmctld -D -i -f "$SLURM_CONF" >"$WORK/slurmctld.out" 2>&1 &
STARTED+=($!)
slurmd -D -f "$SLURM_CONF" -N "$NODE" >"$WORK/slurmd.out" 2>&1 &
STARTED+=($!)
STATE=""
for _ in $(seq 150); do
    STATE=$(sinfo -h -N -o %t 2>/dev/null | head -n 1)
    [ "$STATE" = "idle" ] && break
    sleep 0.2
done
if [ "$STATE" != "idle" ]; then
    show_logs
    cat "$WORK/slurmctld.out" "$WORK/slurmd.out" 2>/dev/null | tail -n 10
    skip "the Slurm daemons did not bring the node up (state \"$STATE\")"
fi
echo "slurm: node $NODE idle on port $PORT"

fail() {
    echo "FAIL: $*"
    show_logs
    exit 1
}

# The same curriculum, planned twice: one run by the local runner, one by Slurm.
"$CLI" batch plan "$CURRICULUM" -o "$WORK/local" >/dev/null || fail "batch plan (local)"
"$CLI" batch plan "$CURRICULUM" -o "$WORK/slurm" >/dev/null || fail "batch plan (slurm)"
JOBS=$(($(wc -l <"$WORK/local/manifest.tsv") - 2))
[ "$JOBS" = 6 ] || fail "expected a 6-job curriculum, got $JOBS jobs"

START=$(date +%s.%N)
"$CLI" batch run "$WORK/local" --jobs 2 || fail "the local runner"
LOCAL_SECONDS=$(echo "$(date +%s.%N) - $START" | bc)

# Two jobs per array task, two array tasks per script: 3 array tasks in 2 sbatch scripts.
START=$(date +%s.%N)
"$CLI" batch slurm "$WORK/slurm" --time 30 --mem 1G --tasks-per-index 2 --array-chunk 2 --threads 1 ||
    fail "batch slurm"
DONE=0
for _ in $(seq 900); do
    QUEUED=$(squeue -h 2>/dev/null | wc -l)
    if [ "$QUEUED" = 0 ]; then
        DONE=1
        break
    fi
    sleep 0.5
done
SLURM_SECONDS=$(echo "$(date +%s.%N) - $START" | bc)
[ "$DONE" = 1 ] || fail "the array tasks did not finish within 450 s"
"$CLI" batch status "$WORK/slurm"
"$CLI" batch status "$WORK/slurm" | grep -q "6 ok, 0 failed, 0 running, 0 pending" || fail "not every job is ok"

# Resubmitting a finished batch submits nothing.
"$CLI" batch slurm "$WORK/slurm" --dry-run | grep -q "every job of" || fail "a finished batch was resubmitted"

for package in "$WORK"/slurm/packages/*; do
    name=$(basename "$package")
    "$CLI" validate "$package" >/dev/null || fail "$name does not validate"
    diff -r "$package" "$WORK/local/packages/$name" >/dev/null || fail "$name differs from the local runner's"
done
printf 'throughput: local runner %.1f s, Slurm %.1f s for %d jobs (Slurm overhead %.1f s per job)\n' \
    "$LOCAL_SECONDS" "$SLURM_SECONDS" "$JOBS" "$(echo "($SLURM_SECONDS - $LOCAL_SECONDS) / $JOBS" | bc -l)"
echo "PASS: 6 packages from Slurm validate and are byte-identical to the local runner's"
stop_daemons
exit 0
