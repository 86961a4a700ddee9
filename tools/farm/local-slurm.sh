#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for radcache's farm tests (docs/farm.md): munged,
# slurmctld and slurmd on 127.0.0.1, the node's CPUs and memory, run as root without systemd.
#
#   tools/farm/local-slurm.sh start    # starts the three daemons, waits until the node is idle
#   tools/farm/local-slurm.sh status   # the daemons' process ids and the node's state
#   tools/farm/local-slurm.sh stop     # stops them by process id
#
# Its files (configuration, logs, state, process ids) live in $RADCACHE_SLURM_DIR (default
# /tmp/radcache-slurm); the configuration is also written to /etc/slurm/slurm.conf, where the
# Slurm commands look for it, unless a configuration that this script did not write is there.
# Packages: slurmctld slurmd slurm-client munge (tools/install-deps.sh).
set -euo pipefail

dir="${RADCACHE_SLURM_DIR:-/tmp/radcache-slurm}"
node="radcache-node"
marker="# written by radcache tools/farm/local-slurm.sh"
system_conf=/etc/slurm/slurm.conf

fail() {
    echo "local-slurm: $*" >&2
    exit 1
}

# The process id in pid file $1 when that process is alive, else nothing.
alive_pid() {
    local pid
    [ -s "$1" ] || return 0
    pid="$(cat "$1")"
    if [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null; then
        echo "$pid"
    fi
}

write_config() {
    local cpus memory
    cpus="$(nproc)"
    memory="$(awk '/MemTotal/ { printf "%d", $2 / 1024 * 0.9 }' /proc/meminfo)"
    mkdir -p "$dir/state" "$dir/spool" "$dir/log"
    cat >"$dir/slurm.conf" <<CONF
$marker
ClusterName=radcache
SlurmctldHost=localhost(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
SlurmdTimeout=60
MinJobAge=3600
NodeName=$node NodeAddr=127.0.0.1 NodeHostname=$(hostname -s) CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP OverSubscribe=NO
CONF
    if [ ! -e "$system_conf" ] || grep -qF "$marker" "$system_conf"; then
        mkdir -p "$(dirname "$system_conf")"
        cp "$dir/slurm.conf" "$system_conf"
    else
        echo "local-slurm: $system_conf is not ours; use SLURM_CONF=$dir/slurm.conf" >&2
    fi
}

start_munge() {
    if [ -n "$(alive_pid "$dir/munged.pid")" ]; then
        return
    fi
    mkdir -p /etc/munge /run/munge /var/lib/munge /var/log/munge
    if [ ! -s /etc/munge/munge.key ]; then
        dd if=/dev/urandom bs=1 count=1024 of=/etc/munge/munge.key status=none
    fi
    chmod 0700 /etc/munge
    chmod 0400 /etc/munge/munge.key
    munged --force --pid-file="$dir/munged.pid" --log-file="$dir/log/munged.log" ||
        fail "munged did not start (see $dir/log/munged.log)"
}

wait_idle() {
    local state=""
    for _ in $(seq 1 120); do
        state="$(sinfo -h -N -n "$node" -o %T 2>/dev/null | head -n 1 || true)"
        case "$state" in
        idle*) echo "local-slurm: node $node idle ($(nproc) CPUs)"; return 0 ;;
        down* | drain*) scontrol update nodename="$node" state=resume >/dev/null 2>&1 || true ;;
        esac
        sleep 0.5
    done
    fail "node $node not idle after 60 s (state '${state:-no answer}'; logs in $dir/log)"
}

start() {
    for command in munged slurmctld slurmd sinfo scontrol; do
        command -v "$command" >/dev/null ||
            fail "$command not found: install slurmctld slurmd slurm-client munge (tools/install-deps.sh)"
    done
    [ "$(id -u)" -eq 0 ] || fail "start needs root (the daemons run as root)"
    write_config
    export SLURM_CONF="$dir/slurm.conf"
    start_munge
    if [ -z "$(alive_pid "$dir/slurmctld.pid")" ]; then
        slurmctld -c -f "$dir/slurm.conf" || fail "slurmctld did not start (see $dir/log)"
    fi
    if [ -z "$(alive_pid "$dir/slurmd.pid")" ]; then
        slurmd -N "$node" -f "$dir/slurm.conf" || fail "slurmd did not start (see $dir/log)"
    fi
    wait_idle
}

stop() {
    local pid
    for daemon in slurmd slurmctld munged; do
        pid="$(alive_pid "$dir/$daemon.pid")"
        if [ -n "$pid" ]; then
            kill "$pid"
            for _ in $(seq 1 50); do
                kill -0 "$pid" 2>/dev/null || break
                sleep 0.2
            done
            if kill -0 "$pid" 2>/dev/null; then
                kill -9 "$pid" 2>/dev/null || true
            fi
            echo "local-slurm: stopped $daemon ($pid)"
        fi
        rm -f "$dir/$daemon.pid"
    done
}

status() {
    local running=0 pid
    for daemon in munged slurmctld slurmd; do
        pid="$(alive_pid "$dir/$daemon.pid")"
        if [ -n "$pid" ]; then
            echo "$daemon: running ($pid)"
            running=$((running + 1))
        else
            echo "$daemon: not running"
        fi
    done
    if [ "$running" -eq 3 ]; then
        sinfo -N -n "$node" 2>/dev/null || true
        return 0
    fi
    return 1
}

case "${1:-}" in
start) start ;;
stop) stop ;;
status) status ;;
*) fail "usage: tools/farm/local-slurm.sh start|stop|status" ;;
esac
