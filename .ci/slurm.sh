#!/usr/bin/env bash
# Real single-node Slurm cluster in CI.
# Installs Slurm + munge if missing, starts munged/slurmctld/slurmd without systemd,
# runs the small workflow (.test/config.yaml) through the slurm executor plugin,
# checks every job went through sbatch, runs the same target locally and compares
# the netCDF results. Daemons are torn down in a trap, also on failure.
#   bash .ci/slurm.sh             (as root; PENCORE_SKIP_SLURM=1 skips)
#   PENCORE_SLURM_TIMEOUT=300     (seconds for each snakemake run)
set -euo pipefail

if [[ "${PENCORE_SKIP_SLURM:-0}" == "1" ]]; then
    echo "slurm.sh: PENCORE_SKIP_SLURM=1, skipping the Slurm cluster test"
    exit 0
fi

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
PY="${PYTHON:-python}"
RUN_TIMEOUT="${PENCORE_SLURM_TIMEOUT:-300}"
# The validation rules and the ensemble (2 chunk jobs + gather + figure) of .test/config.yaml
# run in seconds each; the section-4 parts take minutes on 2 shared cores, too long to run
# twice (Slurm + local) in CI. PENCORE_SLURM_TARGETS=all runs everything.
TARGETS="${PENCORE_SLURM_TARGETS:-table2 fig5 verification table2_figure fig5_figure verification_figure results/ensemble/p2_soil_oblique.nc results/ensemble/p2_soil_oblique.png}"
T0=$(date +%s)
WORK="$(mktemp -d /tmp/pencore-slurm.XXXXXX)"
SLURM_DIR="$WORK/slurm"
SMK_LOG="$WORK/snakemake-slurm.log"
LOCAL_LOG="$WORK/snakemake-local.log"
CTLD_PID="" ; SLURMD_PID="" ; MUNGE_STARTED=0 ; CONF_WRITTEN=0
OWN_HEADER="# written by pencore .ci/slurm.sh (single-node CI cluster)"

log() { echo "slurm.sh [$(( $(date +%s) - T0 ))s]: $*"; }

dump_logs() {
    for f in "$SMK_LOG" "$SLURM_DIR/log/slurmctld.log" "$SLURM_DIR/log/slurmd.log"; do
        if [[ -f "$f" ]]; then
            echo "===== tail -n 40 $f ====="
            tail -n 40 "$f" || true
        fi
    done
}

teardown() {
    local rc=$?
    set +e
    if [[ $rc -ne 0 ]]; then
        log "FAILED (exit $rc)"
        dump_logs
    fi
    if [[ -n "$CTLD_PID" ]]; then
        scancel --quiet -u "$(id -un)" 2>/dev/null
        for _ in $(seq 20); do [[ -z "$(squeue -h 2>/dev/null)" ]] && break; sleep 0.5; done
    fi
    for p in "$SLURMD_PID" "$CTLD_PID"; do
        [[ -n "$p" ]] && kill "$p" 2>/dev/null
    done
    for p in "$SLURMD_PID" "$CTLD_PID"; do
        if [[ -n "$p" ]]; then
            for _ in $(seq 20); do kill -0 "$p" 2>/dev/null || break; sleep 0.5; done
            kill -9 "$p" 2>/dev/null
        fi
    done
    if [[ $CONF_WRITTEN -eq 1 ]]; then   # leave /etc/slurm as it was found
        rm -f /etc/slurm/slurm.conf
        [[ -f /etc/slurm/slurm.conf.pencore-orig ]] \
            && mv /etc/slurm/slurm.conf.pencore-orig /etc/slurm/slurm.conf
    fi
    if [[ $MUNGE_STARTED -eq 1 && -f /run/munge/munged.pid ]]; then
        kill "$(cat /run/munge/munged.pid)" 2>/dev/null
    fi
    if [[ $rc -eq 0 ]]; then rm -rf "$WORK"; else log "kept $WORK for inspection"; fi
    log "total wall time $(( $(date +%s) - T0 )) s"
    exit $rc
}
trap teardown EXIT

# ---- install -----------------------------------------------------------------
if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null \
   || ! command -v sbatch >/dev/null || ! command -v munged >/dev/null; then
    log "installing slurmctld slurmd slurm-client munge"
    apt-get update -q >/dev/null
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
        slurmctld slurmd slurm-client munge >/dev/null
fi
"$PY" -c "import snakemake_executor_plugin_slurm" 2>/dev/null || {
    log "installing snakemake-executor-plugin-slurm"
    "$PY" -m pip install -q snakemake-executor-plugin-slurm
}

# ---- munge -------------------------------------------------------------------
if [[ ! -f /etc/munge/munge.key ]]; then
    log "creating munge key"
    (command -v mungekey >/dev/null && mungekey --create) \
        || dd if=/dev/urandom of=/etc/munge/munge.key bs=1 count=1024 2>/dev/null
    chown munge:munge /etc/munge/munge.key; chmod 400 /etc/munge/munge.key
fi
mkdir -p /run/munge; chown munge:munge /run/munge; chmod 755 /run/munge
if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
    log "starting munged"
    runuser -u munge -- /usr/sbin/munged
    MUNGE_STARTED=1
    for _ in $(seq 20); do munge -n 2>/dev/null | unmunge >/dev/null 2>&1 && break; sleep 0.5; done
fi
munge -n | unmunge >/dev/null

# ---- slurm.conf --------------------------------------------------------------
if pgrep -x slurmctld >/dev/null || pgrep -x slurmd >/dev/null; then
    echo "slurm.sh: a slurmctld/slurmd is already running on this machine; refusing to start another" >&2
    exit 1
fi
HOST="$(hostname -s)"
NODE_LINE="$(slurmd -C | head -n 1)"      # NodeName=... CPUs=... RealMemory=...
CPUS="$(sed -n 's/.* CPUs=\([0-9]*\).*/\1/p' <<<"$NODE_LINE")"
MEM="$(sed -n 's/.* RealMemory=\([0-9]*\).*/\1/p' <<<"$NODE_LINE")"
MEM=$(( MEM * 95 / 100 ))                 # full RealMemory drains the node ("Low RealMemory")
mkdir -p "$SLURM_DIR"/{state,spool,log}
chown -R slurm:slurm "$SLURM_DIR" 2>/dev/null || true
# The configuration goes where every Slurm command and the jobs' srun look for it,
# /etc/slurm/slurm.conf (srun inside a batch job does not see a SLURM_CONF set here), and
# the teardown puts back what was there. Older versions of this script left theirs
# behind: every later Snakemake process on the machine then waited ~9 s at start, as
# the Slurm executor plugin runs `scontrol show config` when imported and scontrol waits
# for the stopped controller. Such a leftover (recognised by its first line) is removed.
CONF_DIR=/etc/slurm
mkdir -p "$CONF_DIR"
for f in "$CONF_DIR/slurm.conf" "$CONF_DIR/slurm.conf.pencore-orig"; do
    if [[ -f "$f" && "$(head -n 1 "$f")" == "$OWN_HEADER" ]]; then
        log "removing $f left by an older version of this script"
        rm -f "$f"
    fi
done
[[ -f "$CONF_DIR/slurm.conf" ]] && mv "$CONF_DIR/slurm.conf" "$CONF_DIR/slurm.conf.pencore-orig"
CONF_WRITTEN=1
cat > "$CONF_DIR/slurm.conf" <<EOF
$OWN_HEADER
ClusterName=pencoreci
SlurmctldHost=$HOST
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$SLURM_DIR/state
SlurmdSpoolDir=$SLURM_DIR/spool
SlurmctldPidFile=$SLURM_DIR/slurmctld.pid
SlurmdPidFile=$SLURM_DIR/slurmd.pid
SlurmctldLogFile=$SLURM_DIR/log/slurmctld.log
SlurmdLogFile=$SLURM_DIR/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
MinJobAge=300
SlurmctldTimeout=30
SlurmdTimeout=30
NodeName=$HOST CPUs=$CPUS RealMemory=$MEM State=UNKNOWN
PartitionName=ci Nodes=$HOST Default=YES MaxTime=INFINITE State=UP
EOF
log "node $HOST CPUs=$CPUS RealMemory=$MEM"

# ---- daemons -----------------------------------------------------------------
slurmctld -D -i > "$SLURM_DIR/log/slurmctld.stdout" 2>&1 &
CTLD_PID=$!
for _ in $(seq 30); do scontrol ping 2>/dev/null | grep -q UP && break; sleep 0.5; done
slurmd -D > "$SLURM_DIR/log/slurmd.stdout" 2>&1 &
SLURMD_PID=$!
log "waiting for node $HOST to be idle"
ok=0
for _ in $(seq 60); do
    state="$(sinfo -h -n "$HOST" -o %T 2>/dev/null | head -n 1 || true)"
    if [[ "$state" == idle ]]; then ok=1; break; fi
    if [[ "$state" == drain* || "$state" == down* ]]; then
        scontrol update NodeName="$HOST" State=RESUME 2>/dev/null || true
    fi
    sleep 1
done
if [[ $ok -ne 1 ]]; then
    echo "slurm.sh: node never became idle (state '${state:-?}')" >&2
    sinfo -N -l || true
    exit 1
fi
sinfo

# ---- scratch copies ----------------------------------------------------------
copy_workflow() {
    mkdir -p "$1"
    # -L: config/ links the paper data shipped in the package (src/pencore/paper/data)
    cp -rL "$REPO/Snakefile" "$REPO/workflow" "$REPO/config" "$REPO/.test" "$1/"
}
copy_workflow "$WORK/slurm-run"
copy_workflow "$WORK/local-run"
export PYTHONPATH="$REPO/src${PYTHONPATH:+:$PYTHONPATH}"   # jobs inherit it (--export=ALL)

# ---- Slurm run ---------------------------------------------------------------
# The site's partition and account as docs/user-guide/cluster.md gives them: two
# environment variables the profile adds to its own resources. Every sbatch call is
# recorded (a wrapper ahead of the real sbatch on PATH) to check that each job got them
# and kept the profile's memory and run time. This cluster has no accounting database,
# so a stand-in sacctmgr answers the plugin's check of the account with it, as a site's
# accounting would.
export PENCORE_SLURM_PARTITION=ci PENCORE_SLURM_ACCOUNT=pencore_ci
SHIMS="$WORK/bin"; SBATCH_CALLS="$WORK/sbatch-calls.txt"
mkdir -p "$SHIMS"
REAL_SBATCH="$(command -v sbatch)"
printf '#!/usr/bin/env bash\nprintf "%%s\\n" "$*" >> %q\nexec %q "$@"\n' \
    "$SBATCH_CALLS" "$REAL_SBATCH" > "$SHIMS/sbatch"
printf '#!/usr/bin/env bash\necho %q\n' "$PENCORE_SLURM_ACCOUNT" > "$SHIMS/sacctmgr"
chmod +x "$SHIMS/sbatch" "$SHIMS/sacctmgr"
log "snakemake through Slurm (timeout ${RUN_TIMEOUT}s; partition $PENCORE_SLURM_PARTITION, account $PENCORE_SLURM_ACCOUNT)"
cd "$WORK/slurm-run"
# shellcheck disable=SC2086
if ! PATH="$SHIMS:$PATH" timeout -k 10 "$RUN_TIMEOUT" "$PY" -m snakemake \
        --workflow-profile workflow/profiles/slurm --configfile .test/config.yaml \
        --jobs 4 --slurm-init-seconds-before-status-checks 5 \
        $TARGETS > "$SMK_LOG" 2>&1; then
    echo "slurm.sh: snakemake via Slurm failed or hung (timeout ${RUN_TIMEOUT}s)" >&2
    squeue || true
    exit 1
fi
n_jobs="$(sed -n 's/^\([0-9][0-9]*\) of \1 steps (100%) done.*/\1/p' "$SMK_LOG" | tail -n 1)"
n_local="$(grep -c '^localrule ' "$SMK_LOG" || true)"
n_sub="$(grep -c 'submitted with SLURM jobid' "$SMK_LOG" || true)"
n_ctld="$(grep -c '_slurm_job_submit\|sched: Allocate JobId' "$SLURM_DIR/log/slurmctld.log" || true)"
log "steps=$n_jobs localrules=$n_local sbatch=$n_sub slurmctld-allocations=$n_ctld"
if [[ -z "$n_jobs" || "$n_jobs" -eq 0 ]]; then
    echo "slurm.sh: could not find 'N of N steps (100%) done' in the snakemake log" >&2
    exit 1
fi
if [[ $(( n_sub + n_local )) -ne "$n_jobs" || "$n_sub" -eq 0 ]]; then
    echo "slurm.sh: $n_sub sbatch submissions + $n_local localrules != $n_jobs jobs" >&2
    exit 1
fi
# each submission with the site's partition and account and the profile's default memory
# and cpus per task, and a run time (the rule's, or the profile's default): the profile's
# numbers, read from it; a --default-resources on the command line would have dropped them
# (the ensemble's gather is a local rule, so every submitted rule sets its own run time)
read -r prof_mem prof_cpus < <("$PY" -c '
import yte
with open("workflow/profiles/slurm/config.yaml") as f:
    d = yte.process_yaml(f, require_use_yte=True)["default-resources"]
print(d["mem_mb"], d["cpus_per_task"])')
n_calls="$(wc -l < "$SBATCH_CALLS")"
n_site="$(grep -c -- "-A pencore_ci -p ci .*--mem $prof_mem\b" "$SBATCH_CALLS" || true)"
n_kept="$(grep -c -- " -t [0-9][0-9]* .*--cpus-per-task=$prof_cpus\b" "$SBATCH_CALLS" || true)"
log "sbatch calls=$n_calls, with partition, account and --mem $prof_mem: $n_site; with a run time and --cpus-per-task=$prof_cpus: $n_kept"
if [[ "$n_calls" -ne "$n_sub" || "$n_site" -ne "$n_calls" || "$n_kept" -ne "$n_calls" ]]; then
    echo "slurm.sh: the jobs did not get the site's partition and account with the profile's resources:" >&2
    cat "$SBATCH_CALLS" >&2
    exit 1
fi

# ---- local run ---------------------------------------------------------------
log "same target locally"
cd "$WORK/local-run"
# shellcheck disable=SC2086
if ! timeout -k 10 "$RUN_TIMEOUT" "$PY" -m snakemake \
        --workflow-profile workflow/profiles/default --configfile .test/config.yaml \
        --cores 2 $TARGETS > "$LOCAL_LOG" 2>&1; then
    SMK_LOG="$LOCAL_LOG"
    echo "slurm.sh: local snakemake run failed" >&2
    exit 1
fi

# ---- compare -----------------------------------------------------------------
log "comparing netCDF results"
"$PY" "$REPO/.ci/compare_results.py" "$WORK/slurm-run/results" "$WORK/local-run/results"
log "OK: $n_sub jobs went through sbatch, results identical to the local run"
