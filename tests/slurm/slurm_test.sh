#!/bin/bash
# Sharded sweep and render through a real single-node Slurm: starts munged,
# slurmctld and slurmd in a temporary directory (their own ports and socket,
# so nothing of the machine's is touched), submits a 4-shard sweep and a
# 4-shard render each with its merge job (scripts/slurm/submit.sh), waits
# (bounded), and compares the merged results with the same work done on this
# machine in one process. Then a 3-shard sweep with one task cancelled: its
# merge must still run, exit 4 naming that shard and show the resubmit line;
# the resubmit script it wrote, run, must complete the same rows. Stops the
# daemons it started by their pid files.
#
#   tests/slurm/slurm_test.sh path/to/epviz
#
# Exit 77 (skipped) unless run as root with slurmctld, slurmd, sbatch and
# munged installed (scripts/setup.sh installs them).
set -euo pipefail
epviz=$(realpath "${1:?usage: $0 path/to/epviz}")
src=$(cd "$(dirname "$0")/../.." && pwd)
skip() { echo "SKIPPED: $*"; exit 77; }
[ "$(id -u)" = 0 ] || skip "the single-node Slurm runs its daemons as root"
for p in slurmctld slurmd sbatch squeue sacct munged; do
  command -v "$p" >/dev/null || skip "$p not installed (apt-get install slurmctld slurmd slurm-client munge)"
done

tmp=$(mktemp -d /tmp/epviz-slurm.XXXXXX)
chmod 755 "$tmp"
stop() {
  for pid in "$tmp/slurmd.pid" "$tmp/slurmctld.pid" "$tmp/munge/munged.pid"; do
    [ -s "$pid" ] && kill "$(cat "$pid")" 2>/dev/null || true
  done
  sleep 1
  rm -rf "$tmp"
}
trap stop EXIT
fail() {
  echo "FAILED: $*" >&2
  for log in "$tmp"/*.log "$tmp"/work/*.log "$tmp"/work/*.out "$tmp"/work/cancel-out/resubmit.sh; do
    [ -f "$log" ] && { echo "--- $log"; tail -n 20 "$log"; } >&2
  done
  exit 1
}

# munged with its own key, socket and pid file, as the munge user.
mkdir -p "$tmp/munge"
dd if=/dev/urandom bs=1 count=1024 of="$tmp/munge/munge.key" status=none
chown -R munge: "$tmp/munge"
chmod 755 "$tmp/munge"
chmod 400 "$tmp/munge/munge.key"
runuser -u munge -- munged --key-file="$tmp/munge/munge.key" --socket="$tmp/munge/munge.sock" \
  --pid-file="$tmp/munge/munged.pid" --log-file="$tmp/munge/munged.log" \
  --seed-file="$tmp/munge/munged.seed" || fail "munged did not start"

# Ports of our own, so that a Slurm of the machine (or a second test) is not disturbed.
port=$((20000 + ($$ % 5000) * 2))
host=$(hostname)
mkdir -p "$tmp/state" "$tmp/spool" "$tmp/work"
cat >"$tmp/slurm.conf" <<CONF
ClusterName=epviztest
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$tmp/munge/munge.sock
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
MpiDefault=none
ReturnToService=2
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$tmp/slurm.conf
slurmctld -f "$SLURM_CONF" || fail "slurmctld did not start"
slurmd -f "$SLURM_CONF" || fail "slurmd did not start"
for _ in $(seq 1 60); do
  sinfo -h -o %T 2>/dev/null | grep -q idle && break
  sleep 0.5
done
sinfo -h -o %T | grep -q idle || fail "the node did not become idle"

cd "$tmp/work"
cat >grid.sweep.json <<'JSON'
{"simulation": {"case": "generic", "t_end": 20, "samples": 20},
 "axes": [{"field": "method", "values": ["rk4", "gauss4", "dop853"]},
          {"field": "step", "from": 0.05, "to": 1.0, "count": 4, "scale": "log"},
          {"field": "energy", "values": [1.5, 3.0]}],
 "reference": true,
 "atlas": [{"metric": "largest_stable:step", "x": "energy", "y": "method"}]}
JSON
cat >clip.json <<'JSON'
{"simulation": {"case": "generic", "t_end": 6, "method": "dop853", "tol": "auto"},
 "view": "body", "trail": {"length": 3},
 "width": 96, "height": 64, "fps": 6, "duration": 2,
 "output": {"dir": "out", "format": "png", "name": "f"}}
JSON
export EPVIZ=$epviz
# Submitted held, so that the task is cancelled before it can end by itself;
# its merge (afterany) must run all the same.
read -r cancel_array cancel_merge < <(SBATCH_ARGS=--hold "$src/scripts/slurm/submit.sh" \
  sweep grid.sweep.json cancel-out 3)
scancel "${cancel_array}_1" || fail "scancel ${cancel_array}_1 failed"
scontrol release "$cancel_array" || fail "could not release array $cancel_array"
scontrol release "$cancel_merge" || fail "could not release merge $cancel_merge"
read -r sweep_array sweep_merge < <("$src/scripts/slurm/submit.sh" sweep grid.sweep.json sweep-out 4)
read -r render_array render_merge < <("$src/scripts/slurm/submit.sh" render clip.json render-out 4)
echo "submitted: sweep $sweep_array -> merge $sweep_merge, render $render_array -> merge $render_merge"

# The same work on this machine, meanwhile.
"$epviz" sweep grid.sweep.json --out local.jsonl --quiet >/dev/null
"$epviz" render clip.json --out local-frames --quiet >/dev/null

wait_for_empty_queue() {
  local deadline=$((SECONDS + $1))
  while squeue -h 2>/dev/null | grep -q .; do
    [ $SECONDS -lt $deadline ] || fail "jobs still queued or running after $1 s: $(squeue -h)"
    sleep 1
  done
}
# "4:0": a finished job's exit code and signal, as slurmctld keeps it for a while.
exit_code() { scontrol show job -o "$1" | grep -o 'ExitCode=[0-9]*:[0-9]*' | cut -d= -f2; }
wait_for_empty_queue 240
for j in "$sweep_merge" "$render_merge"; do
  state=$(sacct -n -X -j "$j" -o State 2>/dev/null | tr -d ' ' | head -1 || true)
  log=epviz-merge-$j.log
  [ -f "$log" ] || fail "merge job $j left no log (state '$state')"
done

# The rows of MERGED equal the single-machine rows (but for CPU time), in point order.
same_rows() {
  /usr/bin/python3 - "$1" local.jsonl <<'PY'
import json, sys
def rows(path):
    out = {}
    for line in open(path):
        r = json.loads(line)
        r.pop("cpu_seconds")
        out[r["index"]] = r
    return out
merged, local = rows(sys.argv[1]), rows(sys.argv[2])
assert len(local) == 24, len(local)
assert merged == local, "rows differ"
order = [json.loads(l)["index"] for l in open(sys.argv[1])]
assert order == sorted(order), "merged rows not in point order"
PY
}
[ -f sweep-out/grid.jsonl ] || fail "the sweep merge wrote no sweep-out/grid.jsonl"
same_rows sweep-out/grid.jsonl || fail "merged sweep rows differ from the single-machine rows"
[ -f sweep-out/atlas_largest_stable_step_energy_method.png ] || fail "no atlas figure"
n=0
for f in local-frames/*.png; do
  cmp -s "$f" "render-out/$(basename "$f")" || fail "render-out/$(basename "$f") differs from the single-machine frame"
  n=$((n + 1))
done
[ "$n" = 12 ] || fail "expected 12 frames, found $n"
grep -q "12 PNG frames complete" "epviz-merge-$render_merge.log" || fail "the render merge did not check the frames"
echo "PASSED: 4-shard sweep (24 points) and 4-shard render (12 frames) through Slurm equal the single-machine results"

# The cancelled task: its merge ran, failed with 4, named shard 1 alone (no
# manifest: missing; a task killed while running leaves a dead lock) and
# showed the line that submits it again.
log=epviz-merge-$cancel_merge.log
[ -f "$log" ] || fail "the merge after the cancelled task did not run"
[ "$(exit_code "$cancel_merge")" = 4:0 ] || fail "the merge after the cancelled task exited $(exit_code "$cancel_merge"), not 4"
grep -Eq 'shard 1/3: (missing|dead)' "$log" || fail "$log does not name shard 1/3 as missing or dead"
if grep -Eq 'shard [02]/3:' "$log"; then fail "$log names a shard that completed"; fi
grep -Eq '^id=\$\(sbatch .*--array=1 ' "$log" || fail "$log does not show the line that submits shard 1 again"
[ ! -e cancel-out/grid.jsonl ] || fail "the merge wrote rows although shard 1 is missing"
redo_merge=$(bash cancel-out/resubmit.sh | tail -n 1) || fail "cancel-out/resubmit.sh failed"
redo_merge=${redo_merge%%;*}
wait_for_empty_queue 120
[ "$(exit_code "$redo_merge")" = 0:0 ] || fail "the merge after the resubmitted shard exited $(exit_code "$redo_merge")"
same_rows cancel-out/grid.jsonl || fail "rows after the resubmitted shard differ from the single-machine rows"
echo "PASSED: a cancelled task's merge exited 4 naming shard 1/3; its resubmit script completed the same 24 rows"
