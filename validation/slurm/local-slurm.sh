#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors
# A one-node Slurm on this machine, for tests and trials: MUNGE, slurmctld and slurmd run as root with a
# configuration written for this host (its real CPU count and memory from `slurmd -C`), plugins that need no
# cgroup set-up (proctrack/linuxproc, task/none), no accounting, all state, logs and keys under one state folder
# (sockets under a short /tmp/stipple-slurm-<hash> beside it). Nothing else is changed except installing Debian's
# packages when missing.
#
# usage: local-slurm.sh start|stop|status [STATE_DIR]
#   STATE_DIR  default: $STIPPLE_SLURM_STATE, else ${TMPDIR:-/tmp}/stipple-slurm
#   start      installs slurm-wlm and munge when missing, writes STATE_DIR/slurm.conf, starts the daemons and
#              waits (up to $STIPPLE_SLURM_WAIT seconds, default 60) until the node is idle; prints the line
#              `export SLURM_CONF=...` that the client commands (sbatch, squeue, scontrol) need
#   stop       stops the daemons this script started (their pid files in STATE_DIR); safe to repeat
#   status     the daemons' pids and `sinfo`
# Ports: $STIPPLE_SLURM_PORT (slurmctld; slurmd uses the next one), default 6817.
# STATE_DIR is this script's alone: start creates it (or reuses one it created: the marker file
# .local-slurm-state) and refuses any other existing folder; stop and status act only on such a folder. Inside it
# only the files named here are written or removed.
# Exit status: 0 done, 1 could not start (the reason and the daemons' log tails on stderr), 2 bad usage or a
# STATE_DIR this script did not create.
set -euo pipefail

cmd=${1:-}
state=$(realpath -m "${2:-${STIPPLE_SLURM_STATE:-${TMPDIR:-/tmp}/stipple-slurm}}")
port=${STIPPLE_SLURM_PORT:-6817}
wait_seconds=${STIPPLE_SLURM_WAIT:-60}
conf=$state/slurm.conf
# Sockets (MUNGE's, slurmstepd's in the spool) live under a short path derived from STATE_DIR: a Unix socket's
# path may not exceed 107 bytes, and STATE_DIR may be deep inside a build folder.
run=/tmp/stipple-slurm-$(printf %s "$state" | md5sum | cut -c1-12)

die() { echo "local-slurm: $*" >&2; exit 1; }
usage_error() { echo "local-slurm: $*" >&2; exit 2; }
marker=$state/.local-slurm-state

# A folder made by this script, or none yet (only `start` may create it).
own_state() { # create?
    if [ ! -e "$state" ] && [ ! -L "$state" ] && [ "$1" = create ]; then
        mkdir -p "$(dirname "$state")" && mkdir -m 700 "$state" || die "cannot create $state"
        echo "state folder of validation/slurm/local-slurm.sh: start, stop and status act on it" > "$marker"
        return 0
    fi
    [ -d "$state" ] && [ ! -L "$state" ] && [ -f "$marker" ] && [ ! -L "$marker" ] && [ -O "$marker" ] \
        || usage_error "$state is not a state folder made by local-slurm.sh (no $marker of this user); refusing to" \
            "touch it (give a new or empty STATE_DIR)"
}

install_packages() {
    local missing=() p
    for p in slurm-wlm slurmctld slurmd slurm-client munge; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    command -v apt-get > /dev/null || die "missing ${missing[*]} and no apt-get to install them"
    echo "local-slurm: installing ${missing[*]}" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq < /dev/null
    apt-get install -y -qq --no-install-recommends "${missing[@]}" < /dev/null
}

pid_alive() { [ -s "$1" ] && kill -0 "$(cat "$1")" 2> /dev/null; }

stop_daemon() { # pid-file name
    local pidfile=$1 name=$2 pid i
    [ -s "$pidfile" ] || return 0
    pid=$(cat "$pidfile")
    if kill -0 "$pid" 2> /dev/null; then
        kill -TERM "$pid" 2> /dev/null || true
        for i in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.2; done
        if kill -0 "$pid" 2> /dev/null; then
            echo "local-slurm: $name ($pid) did not stop in 10 s; killing it" >&2
            kill -KILL "$pid" 2> /dev/null || true
        fi
    fi
    rm -f "$pidfile"
}

stop() {
    # slurmd first: it kills the job steps it started (proctrack/linuxproc follows their process trees).
    stop_daemon "$state/slurmd.pid" slurmd
    stop_daemon "$state/slurmctld.pid" slurmctld
    stop_daemon "$state/munged.pid" munged
    rm -rf "$run"
}

logs() {
    local f
    for f in munged.log slurmctld.log slurmd.log; do
        if [ -s "$state/$f" ]; then echo "--- $state/$f (last lines)"; tail -n 15 "$state/$f"
        else echo "--- $state/$f: not written (the daemon failed before logging)"; fi
    done >&2
    return 0
}

write_config() {
    local node_line node
    # The node as slurmd sees it: CPUs, sockets, cores, threads and RealMemory of this machine.
    node_line=$(slurmd -C | head -n 1) || die "slurmd -C failed"
    node=$(sed -E 's/^NodeName=([^ ]+).*/\1/' <<< "$node_line")
    cat > "$conf" <<CONF
# Written by local-slurm.sh for one node, $node; daemons run as root, no cgroups, no accounting.
ClusterName=stipple-local
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$run/munge/munge.socket
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
MinJobAge=600
KillWait=5
InactiveLimit=0
StateSaveLocation=$state/ctld
SlurmdSpoolDir=$run/spool
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
SlurmctldLogFile=$state/slurmctld.log
SlurmdLogFile=$state/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
$node_line NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
    echo "$node" > "$state/node"
}

start() {
    own_state create
    [ "$(id -u)" -eq 0 ] || die "must run as root (slurmd starts jobs as their users; munged and the spool need root)"
    install_packages
    for b in munged slurmctld slurmd sinfo sbatch scontrol; do
        command -v "$b" > /dev/null || die "$b not found after installing slurm-wlm and munge"
    done
    if pid_alive "$state/slurmctld.pid" || pid_alive "$state/slurmd.pid" || pid_alive "$state/munged.pid"; then
        die "daemons of $state are running already (local-slurm.sh stop $state first)"
    fi
    rm -rf "$state/ctld" "$run"
    mkdir -p "$state/ctld" "$run/spool" "$run/munge"
    chmod 700 "$run" "$run/munge"
    rm -f "$state/munged.log" "$state/slurmctld.log" "$state/slurmd.log"
    # A key of our own, so this MUNGE needs nothing from /etc/munge.
    [ -s "$state/munge.key" ] || { dd if=/dev/urandom of="$state/munge.key" bs=1024 count=1 status=none; }
    chmod 400 "$state/munge.key"
    write_config
    local node
    node=$(cat "$state/node")

    munged --force --socket="$run/munge/munge.socket" --key-file="$state/munge.key" \
        --pid-file="$state/munged.pid" --log-file="$state/munged.log" --seed-file="$run/munge/munged.seed" \
        || { logs; die "munged did not start"; }
    # -c: a clean controller state (no jobs of an earlier run); -i: ignore what cannot be recovered.
    slurmctld -f "$conf" -c -i || { logs; stop; die "slurmctld did not start"; }
    slurmd -f "$conf" -N "$node" || { logs; stop; die "slurmd did not start"; }

    export SLURM_CONF=$conf
    local t0=$SECONDS st=""
    while [ $((SECONDS - t0)) -lt "$wait_seconds" ]; do
        st=$(sinfo -h -n "$node" -o %T 2> /dev/null | head -n 1 || true)
        case "$st" in
            idle) break ;;
            down* | drain* | fail*) scontrol update NodeName="$node" State=RESUME > /dev/null 2>&1 || true ;;
        esac
        for d in slurmctld slurmd munged; do
            pid_alive "$state/$d.pid" || { logs; stop; die "$d exited while starting"; }
        done
        sleep 1
    done
    if [ "$st" != idle ]; then
        sinfo -N -l >&2 || true
        logs; stop
        die "node $node not idle after ${wait_seconds} s (state '${st:-none}')"
    fi
    echo "local-slurm: node $node idle after $((SECONDS - t0)) s ($(sed -E 's/.*(CPUs=[0-9]+).*(RealMemory=[0-9]+).*/\1 \2/' <<< "$(grep "^NodeName" "$conf")"))" >&2
    echo "export SLURM_CONF=$conf"
}

status() {
    local d
    for d in munged slurmctld slurmd; do
        if pid_alive "$state/$d.pid"; then echo "$d: running ($(cat "$state/$d.pid"))"; else echo "$d: stopped"; fi
    done
    if pid_alive "$state/slurmctld.pid"; then SLURM_CONF=$conf sinfo; fi
}

case "$cmd" in
    start) start ;;
    stop) if [ -e "$state" ] || [ -L "$state" ]; then own_state existing; stop; fi ;;
    status) own_state existing; status ;;
    *) echo "usage: local-slurm.sh start|stop|status [STATE_DIR]" >&2; exit 2 ;;
esac
