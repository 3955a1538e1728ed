#!/usr/bin/env bash
# scripts/slurm-render.sbatch on a real Slurm cluster: a one-node cluster on
# localhost (slurmctld, slurmd and munged of this test's own, in its private
# folder, on free ports), then job arrays of the script over a small batch:
# a range with a step (0-6:2) and one with an offset (3-5) each render every
# image exactly once (--shard auto: the task's rank in the array), an index
# list (1,3,7) is refused by every task with nothing rendered, a
# resubmitted array renders nothing new (--skip-existing), and a task
# cancelled mid-render leaves neither its image nor a temporary file, and
# renders it when resubmitted. The script's defaults must fit a small node
# (2 CPUs, 2 GB). Needs root (slurmd runs jobs as their user) and the Debian
# packages slurmctld slurmd slurm-client munge, installed when missing;
# exits 77 (skipped) when they cannot be. Every daemon it started is
# stopped by its process ID on exit.
source "$(dirname "$0")/common.sh"
hsb=$(realpath "$hsb")  # the jobs run in another folder
script=$src/scripts/slurm-render.sbatch
skip() { echo "skipped: $*"; exit 77; }
note() { echo "slurm_test: $*"; }
# A Slurm environment around the test (CI inside an allocation) must not
# leak into the commands that talk to the private cluster.
while read -r name; do unset "$name"; done < <(compgen -e | grep -E '^(SLURM|SBATCH|SALLOC|SRUN|SQUEUE|SINFO|SCONTROL|SCANCEL)_')

# --- 1. The packages (as scripts/lib/packages.sh's install_missing, with a
# lock timeout, and a skip when they cannot be had).
[[ $(id -u) -eq 0 ]] || skip "needs root: slurmd runs the jobs as their user"
packages=(slurmctld slurmd slurm-client munge)
missing=()
for p in "${packages[@]}"; do
  [[ $(dpkg-query -W -f='${Status}' "$p" 2>/dev/null) == "install ok installed" ]] || missing+=("$p")
done
if ((${#missing[@]})); then
  command -v apt-get > /dev/null || skip "no apt-get to install ${missing[*]}"
  note "installing ${missing[*]}"
  apt-get update -q -o DPkg::Lock::Timeout=300 > "$work/apt.log" 2>&1 ||
    skip "apt-get update failed (no network?): $(tail -n 3 "$work/apt.log")"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q -o DPkg::Lock::Timeout=300 --no-install-recommends \
    "${missing[@]}" >> "$work/apt.log" 2>&1 || skip "cannot install ${missing[*]}: $(tail -n 3 "$work/apt.log")"
fi
for command in munged mungekey slurmctld slurmd sbatch scontrol sinfo squeue scancel; do
  command -v "$command" > /dev/null || skip "$command not found after installing ${packages[*]}"
done

# --- 2. A one-node cluster on localhost, everything in $work.
# munged wants every folder above its socket searchable by all (0711: no listing).
chmod 711 "$work"
mkdir -p "$work/munge" "$work/slurm/state" "$work/slurm/spool" "$work/logs"
export SLURM_CONF=$work/slurm/slurm.conf
# Every process of this cluster carries this variable (the daemons, the
# slurmstepd they start, the jobs through sbatch), and no other process
# does: whatever is left of it at the end is found by it and ended by ID.
tag="HSB_SLURM_TEST=$work"
daemons=()  # process IDs, in the order started

tagged_pids() {
  local environ pid
  for environ in /proc/[0-9]*/environ; do
    pid=${environ#/proc/}; pid=${pid%/environ}
    { tr '\0' '\n' < "$environ" | grep -qxF "$tag"; } 2> /dev/null && echo "$pid"
  done
}
stop_pid() {  # SIGTERM, then SIGKILL after 10 s
  local pid=$1
  kill -TERM "$pid" 2> /dev/null || return 0
  for _ in $(seq 40); do kill -0 "$pid" 2> /dev/null || return 0; sleep 0.25; done
  echo "slurm_test: $(cat "/proc/$pid/comm" 2>/dev/null) ($pid) ignored SIGTERM; killed"
  kill -KILL "$pid" 2> /dev/null
}
cleanup() {
  local status=$? pid i
  trap - EXIT INT TERM
  if ((${#daemons[@]})); then
    # Jobs first, through Slurm, so that slurmd ends their processes.
    scancel --quiet --user=root 2> /dev/null
    for _ in $(seq 40); do [[ -z $(squeue -h 2> /dev/null) ]] && break; sleep 0.25; done
    for ((i = ${#daemons[@]} - 1; i >= 0; i--)); do stop_pid "${daemons[i]}"; done
    for pid in $(tagged_pids); do  # a slurmstepd or a job's process that outlived them
      echo "slurm_test: left over: $(cat "/proc/$pid/comm" 2>/dev/null) ($pid); stopped"
      stop_pid "$pid"
    done
  fi
  rm -rf "$work"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

start_daemon() {  # start_daemon NAME COMMAND...: in the foreground of a background job
  env "$tag" "${@:2}" > "$work/$1.out" 2>&1 &
  daemons+=($!)
}
show_logs() { tail -n 15 "$work"/*.out "$work"/slurm/*.log 2> /dev/null; }

mungekey --create --keyfile="$work/munge/munge.key" || fail "mungekey"
munge_socket=$work/munge/munge.socket
start_daemon munged munged --foreground --socket="$munge_socket" --key-file="$work/munge/munge.key" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/munge/munged.log" --seed-file="$work/munge/munged.seed"
for _ in $(seq 40); do
  munge -n --socket="$munge_socket" 2> /dev/null | unmunge --socket="$munge_socket" > /dev/null 2>&1 && break
  kill -0 "${daemons[0]}" 2> /dev/null || break
  sleep 0.25
done
munge -n --socket="$munge_socket" | unmunge --socket="$munge_socket" > /dev/null ||
  fail "munged did not start: $(cat "$work/munged.out")"

free_ports() {  # two TCP ports free now on localhost
  if command -v python3 > /dev/null; then
    python3 -c 'import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])'
  else
    local p=$((20000 + RANDOM % 20000)); echo "$p" "$((p + 1))"
  fi
}
# At least 2.5 GB for the node: the script asks 2 GB a task.
memory=$(( $(free -m | awk '/^Mem:/ {print $2}') - 512 ))
((memory >= 2560)) || skip "only $((memory + 512)) MB of memory; the script's tasks ask 2 GB"
write_conf() {
  cat > "$SLURM_CONF" << EOF
ClusterName=hsbtest
SlurmctldHost=localhost
SlurmctldPort=$1
SlurmdPort=$2
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$munge_socket
StateSaveLocation=$work/slurm/state
SlurmdSpoolDir=$work/slurm/spool
SlurmctldPidFile=$work/slurm/slurmctld.pid
SlurmdPidFile=$work/slurm/slurmd.pid
SlurmctldLogFile=$work/slurm/slurmctld.log
SlurmdLogFile=$work/slurm/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
MpiDefault=none
MailProg=/bin/true
ReturnToService=2
KillWait=5
MinJobAge=600
SchedulerParameters=batch_sched_delay=0
NodeName=localhost NodeAddr=127.0.0.1 CPUs=2 RealMemory=$memory State=UNKNOWN
PartitionName=hsbtest Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
}
started=$SECONDS
up=false
for attempt in 1 2 3; do  # another port if one was taken in between
  read -r ctld_port slurmd_port < <(free_ports)
  write_conf "$ctld_port" "$slurmd_port"
  start_daemon slurmctld slurmctld -D -f "$SLURM_CONF"
  ctld=${daemons[-1]}
  for _ in $(seq 80); do
    scontrol ping 2> /dev/null | grep -q "is UP" && break
    kill -0 "$ctld" 2> /dev/null || break
    sleep 0.25
  done
  if scontrol ping 2> /dev/null | grep -q "is UP"; then
    start_daemon slurmd slurmd -D -N localhost -f "$SLURM_CONF"
    slurmd_pid=${daemons[-1]}
    for _ in $(seq 120); do
      [[ $(sinfo -h -n localhost -o %T 2> /dev/null) == idle ]] && { up=true; break; }
      kill -0 "$slurmd_pid" 2> /dev/null || break
      sleep 0.25
    done
  fi
  $up && break
  grep -qi "address already in use" "$work"/slurm*.out "$work"/slurm/*.log 2> /dev/null || break
  note "a port was taken (attempt $attempt); again"
  for ((i = ${#daemons[@]} - 1; i >= 1; i--)); do stop_pid "${daemons[i]}"; done
  daemons=("${daemons[0]}")
done
$up || fail "the node is not idle: $(sinfo 2>&1) $(show_logs)"
note "cluster up in $((SECONDS - started)) s (slurmctld :$ctld_port, slurmd :$slurmd_port)"

# Jobs. submit NAME OPTION... SCRIPT ARGUMENT...: sets job to the array's
# job ID, its tasks' logs in $work/logs/NAME-INDEX.log; HSB, HSB_OUT and
# HSB_SET travel in the environment (sbatch --export=ALL, the default).
submit() {
  local name=$1
  shift
  job=$(cd "$work" && env "$tag" sbatch --parsable --output="$work/logs/$name-%a.log" "$@" 2> "$work/sbatch.err") ||
    fail "sbatch $name ($1 ...): $(cat "$work/sbatch.err")"
  job=${job%%;*}
}
# "INDEX STATE EXITCODE" for each task of an array
task_states() {
  scontrol -o show job "$1" 2> /dev/null |
    sed -nE 's/.* ArrayTaskId=([^ ]*) .* JobState=([^ ]*) .* ExitCode=([^ ]*) .*/\1 \2 \3/p' | sort -n
}
finished='(COMPLETED|FAILED|CANCELLED|TIMEOUT|OUT_OF_MEMORY|NODE_FAIL|BOOT_FAIL|DEADLINE|PREEMPTED)'
wait_jobs() {  # wait_jobs SECONDS JOBID...: every task of these arrays finished
  local deadline=$((SECONDS + $1)) job states
  shift
  for job in "$@"; do
    while :; do
      states=$(task_states "$job")
      [[ -n $states ]] && ! grep -qvE " $finished " <<< "$states" && break
      ((SECONDS < deadline)) || fail "job $job not finished after its deadline: $states $(squeue 2>&1)"
      sleep 0.25
    done
  done
}
# expect_tasks NAME JOBID "STATE EXITCODE" INDEX...: those tasks, each so ended
expect_tasks() {
  local name=$1 job=$2 end=$3 want="" index
  shift 3
  for index in "$@"; do want+="$index $end"$'\n'; done
  [[ $(task_states "$job") == "${want%$'\n'}" ]] ||
    fail "$name (job $job): tasks ended $(task_states "$job" | tr '\n' ';') where $end was expected for $*:
$(tail -n 5 "$work/logs/$name"-*.log)"
}

# A trivial array first: the cluster runs jobs, with the variables --shard
# auto reads (a list's indices come with STEP 1: MAX-MIN+1 is not COUNT).
printf '#!/bin/sh\necho "$SLURM_ARRAY_TASK_ID $SLURM_ARRAY_TASK_MIN $SLURM_ARRAY_TASK_MAX %s $SLURM_ARRAY_TASK_COUNT"\n' \
  '${SLURM_ARRAY_TASK_STEP-unset}' > "$work/trivial.sh"
started=$SECONDS
submit trivial-range --array=0-6:2 --cpus-per-task=1 --mem=64M "$work/trivial.sh"; range=$job
submit trivial-list --array=1,3,7 --cpus-per-task=1 --mem=64M "$work/trivial.sh"; list=$job
wait_jobs 60 "$range" "$list"
expect_tasks trivial-range "$range" "COMPLETED 0:0" 0 2 4 6
expect_tasks trivial-list "$list" "COMPLETED 0:0" 1 3 7
[[ $(cat "$work"/logs/trivial-range-{0,2,4,6}.log | tr '\n' ';') == "0 0 6 2 4;2 0 6 2 4;4 0 6 2 4;6 0 6 2 4;" ]] ||
  fail "array 0-6:2 saw (ID MIN MAX STEP COUNT): $(cat "$work"/logs/trivial-range-*.log | tr '\n' ';')"
[[ $(cat "$work"/logs/trivial-list-{1,3,7}.log | tr '\n' ';') == "1 1 7 1 3;3 1 7 1 3;7 1 7 1 3;" ]] ||
  fail "array 1,3,7 saw (ID MIN MAX STEP COUNT): $(cat "$work"/logs/trivial-list-*.log | tr '\n' ';')"
note "a trivial job array ran ($((SECONDS - started)) s)"

# --- 3. A small batch: six scenes and a 3 x 2 sweep, twelve images, tiny.
sed -n '/^\[sweep\]/q;p' "$src/scenes/fig07_point_load_normalized.toml" > "$work/swept.toml"
printf '\n[sweep]\n"glyphs.scale" = [0.05, 0.1, 0.2]\n"color.map" = ["magma", "cividis"]\n' >> "$work/swept.toml"
batch=("$src"/scenes/fig0{5,6,7,8}_*.toml "$src/scenes/fig10_cylinder_ellipsoids.toml"
       "$src/scenes/fig16_point_load_signed_glyphs.toml" "$work/swept.toml")
small="--set render.width=48 --set render.height=36 --set render.samples=1"
# shellcheck disable=SC2086
"$hsb" render "${batch[@]}" -o "$work/reference" $small --quiet || fail "the batch does not render without Slurm"
images=$(ls -A "$work/reference")
[[ $(wc -l <<< "$images") -eq 12 ]] || fail "the batch is not 12 images: $images"

# --- 4. Arrays of the script: every image once, a list refused, nothing new when resubmitted.
render() {  # render NAME OUT SET ARRAY: submits the script over the batch (sets job)
  HSB=$hsb HSB_OUT=$2 HSB_SET=$3 submit "$1" --array="$4" "$script" "${batch[@]}"
}
started=$SECONDS
render step "$work/out-step" "$small" 0-6:2; step=$job
render offset "$work/out-offset" "$small" 3-5; offset=$job
render list "$work/out-list" "$small" 1,3,7; listed=$job
asked=$(scontrol -o show job "$step" | grep -o 'CPUs/Task=[^ ]*\|MinMemoryNode=[^ ]*' | sort -u | tr '\n' ' ')
[[ $asked == "CPUs/Task=2 MinMemoryNode=2G " ]] || fail "the script's defaults are not --cpus-per-task=2 --mem=2G: $asked"
wait_jobs 150 "$step" "$offset" "$listed"
note "arrays 0-6:2, 3-5 and 1,3,7 ran ($((SECONDS - started)) s)"

# every_image_once NAME OUT TASKS WHAT: the folder holds the batch's images and
# nothing else (no temporary file), and the tasks' logs say WHAT ("sources="
# rendered, "up to date, skipped") of each image exactly once, spread evenly.
every_image_once() {
  local name=$1 out=$2 tasks=$3 what=$4 image log n
  [[ $(ls -A "$out" 2> /dev/null) == "$images" ]] ||
    fail "$name: the folder holds $(ls -A "$out" | tr '\n' ' '), not the batch"
  for image in $images; do
    n=$(cat "$work/logs/$name"-*.log | grep -cF "$out/$image  $what")
    [[ $n -eq 1 ]] || fail "$name: $image $what $n times: $(cat "$work/logs/$name"-*.log)"
  done
  for log in "$work/logs/$name"-*.log; do
    n=$(grep -cF "$out/" "$log")
    [[ $n -eq $((12 / tasks)) ]] || fail "$name: $(basename "$log") has $n images, not $((12 / tasks)): $(cat "$log")"
  done
}
expect_tasks step "$step" "COMPLETED 0:0" 0 2 4 6
every_image_once step "$work/out-step" 4 "sources="
expect_tasks offset "$offset" "COMPLETED 0:0" 3 4 5
every_image_once offset "$work/out-offset" 3 "sources="
# A list of indices has no rank to take: each task refuses (exit 2) and says how to give one.
expect_tasks list "$listed" "FAILED 2:0" 1 3 7
for index in 1 3 7; do
  grep "an index list" "$work/logs/list-$index.log" | grep -q "HSB_SHARD_INDEX" ||
    fail "task $index of 1,3,7 does not say it is an index list, and how to give a rank: $(cat "$work/logs/list-$index.log")"
done
[[ -z $(ls -A "$work/out-list" 2> /dev/null) ]] || fail "the refused list rendered: $(ls -A "$work/out-list")"

# Resubmitted: everything up to date, no file written again.
files() { find "$1" -printf '%P %i %s %T@\n' | sort; }
before_step=$(files "$work/out-step") before_offset=$(files "$work/out-offset")
started=$SECONDS
render step-again "$work/out-step" "$small" 0-6:2; step=$job
render offset-again "$work/out-offset" "$small" 3-5; offset=$job
wait_jobs 120 "$step" "$offset"
expect_tasks step-again "$step" "COMPLETED 0:0" 0 2 4 6
expect_tasks offset-again "$offset" "COMPLETED 0:0" 3 4 5
every_image_once step-again "$work/out-step" 4 "up to date, skipped"
every_image_once offset-again "$work/out-offset" 3 "up to date, skipped"
[[ $(files "$work/out-step") == "$before_step" && $(files "$work/out-offset") == "$before_offset" ]] ||
  fail "a resubmitted array wrote files again"
note "resubmitted, nothing rendered again ($((SECONDS - started)) s)"

# --- 5. A task cancelled mid-render: no image, no temporary file; resubmitted, rendered.
mkdir -p "$work/slow"
cp "$src/scenes/fig05_point_load_linear.toml" "$work/slow/slow.toml"
slow_set="--set render.width=800 --set render.height=600 --set render.samples=8"
started=$SECONDS
HSB=$hsb HSB_OUT=$work/out-cancel HSB_SET=$slow_set submit cancel --array=0 "$script" "$work/slow/slow.toml"
pid=""
deadline=$((SECONDS + 60))
while [[ -z $pid ]]; do  # the task's hsb running (the script execs it)
  for p in $(scontrol listpids "$job" 2> /dev/null | awk 'NR > 1 {print $1}'); do
    [[ $(cat "/proc/$p/comm" 2> /dev/null) == hsb ]] && pid=$p
  done
  ((SECONDS < deadline)) || fail "the slow task's hsb never ran: $(task_states "$job") $(cat "$work"/logs/cancel-0.log)"
  task_states "$job" | grep -qE " $finished " && fail "the slow task ended first: $(cat "$work"/logs/cancel-0.log)"
  sleep 0.2
done
sleep 1  # past reading the scene, into the render (seconds long here, at 2 threads)
[[ -e $work/out-cancel/slow.png ]] && fail "the slow image finished within 1 s: make it slower"
scancel "$job" || fail "scancel $job"
wait_jobs 30 "$job"
expect_tasks cancel "$job" "CANCELLED 143:0" 0  # hsb's own exit on SIGTERM, not a SIGKILL
grep -q "CANCELLED" "$work/logs/cancel-0.log" || fail "the log does not say cancelled: $(cat "$work/logs/cancel-0.log")"
grep -q "interrupted; no partial file left behind" "$work/logs/cancel-0.log" ||
  fail "hsb did not clean up on SIGTERM: $(cat "$work/logs/cancel-0.log")"
[[ -z $(ls -A "$work/out-cancel" 2> /dev/null) ]] || fail "a cancelled task left: $(ls -A "$work/out-cancel")"
[[ -z $(compgen -G "${TMPDIR:-/tmp}/hsb-*-$pid-*") ]] || fail "a cancelled task left its scratch folder"
HSB=$hsb HSB_OUT=$work/out-cancel HSB_SET=$slow_set submit cancel-again --array=0 "$script" "$work/slow/slow.toml"
wait_jobs 120 "$job"
expect_tasks cancel-again "$job" "COMPLETED 0:0" 0
[[ $(ls -A "$work/out-cancel") == slow.png ]] || fail "resubmitted, the folder holds: $(ls -A "$work/out-cancel")"
grep -qF "$work/out-cancel/slow.png  sources=" "$work/logs/cancel-again-0.log" ||
  fail "resubmitted, not rendered: $(cat "$work/logs/cancel-again-0.log")"
note "cancelled mid-render, then rendered ($((SECONDS - started)) s)"

[[ -z $(find "$work" -name '*.partial-*') ]] || fail "temporary files left: $(find "$work" -name '*.partial-*')"
echo PASS
