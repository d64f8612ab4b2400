#!/usr/bin/env bash
# A single-node Slurm on loopback for the tests, started and stopped by this shell alone.
#
#   source tests/scale/slurm_fixture.sh
#   slurm_fixture_start DIR     # munged, slurmctld, slurmd with their state in DIR; exports SLURM_CONF
#   ...sbatch, squeue, scancel...
#   slurm_fixture_stop          # stops exactly the daemons started above, by their pids
#
# Containers run no init system and often no cgroups the job could use, so processes are
# tracked by their parent links (proctrack/linuxproc) and tasks are not bound (task/none).
# The ports are picked free on 127.0.0.1 so that concurrent runs do not collide.
# Any failure to start is fatal (exit 1 with the daemon's log): the test must not pass by skipping.

slurm_fixture_pids=()
slurm_fixture_watchdog=""

slurm_fixture_fail() {
    echo "slurm fixture: $*" >&2
    for log in "$SLURM_FIXTURE_DIR"/log/*.log; do
        [ -f "$log" ] && { echo "--- $log" >&2; tail -n 30 "$log" >&2; }
    done
    slurm_fixture_stop
    exit 1
}

slurm_fixture_free_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()'
}

slurm_fixture_start() {
    SLURM_FIXTURE_DIR=$(realpath "$1")
    local d=$SLURM_FIXTURE_DIR
    for tool in munged mungekey slurmctld slurmd sbatch squeue scontrol python3; do
        command -v "$tool" >/dev/null || slurm_fixture_fail "$tool not found (scripts/setup.sh installs slurm-wlm and munge)"
    done
    mkdir -p "$d/munge" "$d/log" "$d/ctld" "$d/slurmd" "$d/run"
    chmod 711 "$d/munge"
    mungekey --create --keyfile="$d/munge/munge.key" --force >/dev/null 2>&1 ||
        dd if=/dev/urandom of="$d/munge/munge.key" bs=1024 count=1 status=none
    chmod 400 "$d/munge/munge.key"
    munged --foreground --force --key-file="$d/munge/munge.key" --socket="$d/munge/munge.socket" \
        --pid-file="$d/munge/munged.pid" --log-file="$d/log/munged.log" --seed-file="$d/munge/munge.seed" \
        >>"$d/log/munged.out" 2>&1 &
    slurm_fixture_pids+=($!)
    local ctld_port slurmd_port
    ctld_port=$(slurm_fixture_free_port) && slurmd_port=$(slurm_fixture_free_port) || slurm_fixture_fail "no free port"
    cat >"$d/slurm.conf" <<CONF
ClusterName=tsfixture
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$d/munge/munge.socket
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/builtin
# Batch jobs are scheduled when submitted, not up to 3 s later (the default, for sites submitting
# at a high rate): the shard test's nine jobs took 39 s, 28-30 s without the delay.
SchedulerParameters=batch_sched_delay=0
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
StateSaveLocation=$d/ctld
SlurmdSpoolDir=$d/slurmd
SlurmctldPidFile=$d/run/slurmctld.pid
SlurmdPidFile=$d/run/slurmd.pid
SlurmctldLogFile=$d/log/slurmctld.log
SlurmdLogFile=$d/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
MaxArraySize=1001
KillWait=2
MinJobAge=300
NodeName=localhost NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF="$d/slurm.conf"
    local i
    for i in $(seq 50); do [ -S "$d/munge/munge.socket" ] && break; sleep 0.1; done
    [ -S "$d/munge/munge.socket" ] || slurm_fixture_fail "munged did not start"
    slurmctld -D -i -f "$SLURM_CONF" >>"$d/log/slurmctld.out" 2>&1 &
    slurm_fixture_pids+=($!)
    slurmd -D -N localhost -f "$SLURM_CONF" >>"$d/log/slurmd.out" 2>&1 &
    slurm_fixture_pids+=($!)
    # If this shell is killed without running its traps (a test runner's timeout sends SIGKILL),
    # a watchdog stops the same daemons by pid once the shell is gone.
    local shell_pid=$$ daemons="${slurm_fixture_pids[*]}"
    (
        trap - EXIT
        while kill -0 "$shell_pid" 2>/dev/null; do sleep 1; done
        # shellcheck disable=SC2086
        kill -TERM $daemons 2>/dev/null
    ) </dev/null >/dev/null 2>&1 &
    slurm_fixture_watchdog=$!
    for i in $(seq 150); do
        if sinfo -h -N -o '%T' 2>/dev/null | grep -Eq '^(idle|mixed|allocated)'; then
            return 0
        fi
        sleep 0.2
    done
    sinfo -N >&2 || true
    slurm_fixture_fail "slurmctld/slurmd did not bring node localhost up within 30 s"
}

slurm_fixture_stop() {
    local pid
    if [ -n "${slurm_fixture_watchdog:-}" ]; then
        kill "$slurm_fixture_watchdog" 2>/dev/null || true
        wait "$slurm_fixture_watchdog" 2>/dev/null || true
        slurm_fixture_watchdog=""
    fi
    for pid in "${slurm_fixture_pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
    for pid in "${slurm_fixture_pids[@]}"; do
        for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -KILL "$pid" 2>/dev/null || true
        wait "$pid" 2>/dev/null || true
    done
    slurm_fixture_pids=()
}
