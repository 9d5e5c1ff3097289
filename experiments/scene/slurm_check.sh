#!/bin/bash
# slurm_check.sh - run docs/scene.md's Slurm job array for real on a throw-away
# single-node Slurm and check that the merged shards equal the unsharded run.
#
# Called by `make -f Makefile.paper slurm-check`; see --help. Needs root on a
# Debian machine (installs slurm-wlm and munge when missing). Everything it
# starts (munged, slurmctld, slurmd) and everything it writes lives under one
# temporary folder; both are gone when it exits, whichever way it exits.

set -u

usage() {
	cat <<EOF
usage: slurm_check.sh --mink PATH [--shards N] [--cpus-per-task C] [--timeout S] [--keep]

Starts a private single-node Slurm (munged, slurmctld, slurmd in the foreground,
state, spool, logs and munge key under a temporary folder; ports 6817/6818), then
for a small 2D and a small 3D scene:
  1. submits the job array of docs/scene.md,
       sbatch --wait --array=0-(N-1) with
       mink scene scene.txt --tol T --outer --threads C \\
         --shard \$SLURM_ARRAY_TASK_ID/\$SLURM_ARRAY_TASK_COUNT --out out/part-\$SLURM_ARRAY_TASK_ID.csv
  2. merges the parts in numeric shard order as docs/scene.md says (points and,
     in 3D, faces),
  3. runs the same scene unsharded (without Slurm) and compares byte for byte.
Prints PASS or FAIL per scene; exits 0 only if every scene passes. Stops the
daemons and removes the folder on every exit path.

  --mink PATH          the mink binary (e.g. build/experiments/mink/mink)
  --shards N           array tasks per scene, 1..1000 (default 16, as in the docs)
  --cpus-per-task C    CPUs per array task and mink --threads, 1..nproc (default 1)
  --timeout S          seconds to wait for the node to come up and for each job
                       array to finish, 1..86400 (default 300)
  --keep               keep the temporary folder (logs, parts, outputs) and say
                       where; the daemons are stopped all the same
  --help               this text

Needs: root, Debian (dpkg, apt-get); installs slurm-wlm and munge with apt-get
when missing (apt-get update first). Refuses to run when a slurmctld or slurmd is
already running here. Exit status: 0 all PASS, 1 a FAIL or a Slurm/munge
failure, 2 a bad command line or not root.
EOF
}

die2() { echo "slurm_check: $*" >&2; exit 2; }
fail() { echo "slurm_check: FAIL: $*" >&2; exit 1; }
log() { echo "slurm_check: $*"; }

# ---- command line -----------------------------------------------------------
mink="" shards=16 cpt=1 timeout=300 keep=0
is_int() { case $1 in ''|*[!0-9]*) return 1;; esac; [ ${#1} -le 9 ]; }
while [ $# -gt 0 ]; do
	case $1 in
	--help|-h) usage; exit 0;;
	--keep) keep=1; shift;;
	--mink) [ $# -ge 2 ] || die2 "--mink needs a value: the path of the mink binary"; mink=$2; shift 2;;
	--shards) [ $# -ge 2 ] || die2 "--shards needs a value"; shards=$2; shift 2
		{ is_int "$shards" && [ "$shards" -ge 1 ] && [ "$shards" -le 1000 ]; } ||
			die2 "--shards = '$shards' is out of range: must be an integer in [1, 1000]";;
	--cpus-per-task) [ $# -ge 2 ] || die2 "--cpus-per-task needs a value"; cpt=$2; shift 2;;
	--timeout) [ $# -ge 2 ] || die2 "--timeout needs a value"; timeout=$2; shift 2
		{ is_int "$timeout" && [ "$timeout" -ge 1 ] && [ "$timeout" -le 86400 ]; } ||
			die2 "--timeout = '$timeout' is out of range: must be an integer in [1, 86400]";;
	*) die2 "unknown argument '$1' (see --help)";;
	esac
done
ncpu=$(nproc)
{ is_int "$cpt" && [ "$cpt" -ge 1 ] && [ "$cpt" -le "$ncpu" ]; } ||
	die2 "--cpus-per-task = '$cpt' is out of range: must be an integer in [1, $ncpu] (nproc)"
[ -n "$mink" ] || die2 "--mink is required: the path of the mink binary (see --help)"
[ -x "$mink" ] || die2 "--mink = '$mink' is not an executable file; build it first (cmake --build BUILD --target mink)"
mink=$(readlink -f "$mink")
[ "$(id -u)" = 0 ] || die2 "must run as root: it starts munged and slurmd (uid $(id -u) here)"
{ command -v dpkg-query && command -v apt-get; } >/dev/null 2>&1 ||
	die2 "needs a Debian system (dpkg-query, apt-get): it installs slurm-wlm and munge"

t_start=$(date +%s)

# ---- 1. packages ------------------------------------------------------------
missing=""
for p in slurmctld slurmd slurm-client munge; do
	dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
	log "installing slurm-wlm munge (missing:$missing)"
	apt-get update || fail "apt-get update failed"
	DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends slurm-wlm munge ||
		fail "apt-get install slurm-wlm munge failed"
else
	log "slurm-wlm and munge are installed"
fi
for c in munged munge unmunge slurmctld slurmd sbatch sinfo squeue scontrol scancel; do
	command -v "$c" >/dev/null 2>&1 || fail "'$c' is not on PATH after installing slurm-wlm and munge"
done
for d in slurmctld slurmd; do
	if pgrep -x "$d" >/dev/null 2>&1; then
		fail "a $d is already running on this machine; this check starts its own and would collide with it"
	fi
done

# ---- the temporary folder and the exit trap ------------------------------------
# Short base path: munge's unix socket path must fit in 108 bytes.
tmp=$(mktemp -d "${TMPDIR:-/tmp}/mink-slurm.XXXXXX") || fail "mktemp -d failed"
# munged wants every folder above its socket searchable by all.
chmod 711 "$tmp"
munged_pid="" ctld_pid="" slurmd_pid="" sbatch_pid="" jobs_submitted="" want_tails=1

# Print the last lines of the daemons' logs (on failures).
tails() {
	local f n
	for f in munge/munged.log munge/munged.stderr log/slurmctld.log log/slurmctld.stderr \
		log/slurmd.log log/slurmd.stderr; do
		[ -s "$tmp/$f" ] || continue
		# stderr: what a daemon says before its log file is open (or copies of it)
		case $f in *.log) n=25;; *) n=8;; esac
		echo "---- last lines of $f ----" >&2
		tail -n $n "$tmp/$f" >&2
	done
}

# Stop a daemon we started: TERM, up to 10 s, then KILL.
stop_pid() {
	local pid=$1 i=0
	[ -n "$pid" ] || return 0
	kill -TERM "$pid" 2>/dev/null || return 0
	while kill -0 "$pid" 2>/dev/null && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
	kill -0 "$pid" 2>/dev/null && kill -KILL "$pid" 2>/dev/null
	wait "$pid" 2>/dev/null
	return 0
}

cleanup() {
	local rc=$?
	trap - EXIT INT TERM HUP
	if [ -n "$jobs_submitted" ] && [ -n "$ctld_pid" ] && kill -0 "$ctld_pid" 2>/dev/null; then
		# Cancel what may still run (an interrupt during sbatch --wait) and
		# give the job steps up to 15 s to go.
		for j in $jobs_submitted; do scancel "$j" >/dev/null 2>&1; done
		local i=0
		while [ $i -lt 30 ] && [ -n "$(squeue -h -o %i 2>/dev/null)" ]; do sleep 0.5; i=$((i + 1)); done
	fi
	[ -n "$sbatch_pid" ] && kill -TERM "$sbatch_pid" 2>/dev/null && wait "$sbatch_pid" 2>/dev/null
	[ $rc -ne 0 ] && [ $want_tails = 1 ] && tails
	stop_pid "$slurmd_pid"
	stop_pid "$ctld_pid"
	stop_pid "$munged_pid"
	if [ $keep = 1 ]; then echo "slurm_check: kept $tmp (remove it by hand)" >&2; else rm -rf "$tmp"; fi
	exit $rc
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'exit 129' HUP

mkdir -p "$tmp"/munge "$tmp"/sock "$tmp"/state "$tmp"/spool "$tmp"/log "$tmp"/run
chmod 700 "$tmp"/munge
chmod 755 "$tmp"/sock

# ---- 2. munge -----------------------------------------------------------------
sock=$tmp/sock/munge.socket
if ! { head -c 1024 /dev/urandom > "$tmp"/munge/munge.key && chmod 400 "$tmp"/munge/munge.key; }; then
	fail "cannot write a munge key"
fi
munged --foreground --key-file="$tmp"/munge/munge.key --socket="$sock" \
	--pid-file="$tmp"/munge/munged.pid --seed-file="$tmp"/munge/munged.seed \
	--log-file="$tmp"/munge/munged.log > /dev/null 2> "$tmp"/munge/munged.stderr &
munged_pid=$!
i=0
until munge -n -S "$sock" 2>/dev/null | unmunge -S "$sock" >/dev/null 2>&1; do
	kill -0 "$munged_pid" 2>/dev/null || fail "munged exited at start"
	[ $i -ge 100 ] && fail "munged did not answer on $sock within 10 s"
	sleep 0.1; i=$((i + 1))
done
log "munged up (pid $munged_pid)"

# ---- 3. slurm.conf, slurmctld, slurmd ---------------------------------------------
node=$(hostname -s)
[ -n "$node" ] || fail "hostname -s is empty"
export SLURM_CONF=$tmp/slurm.conf
cat > "$SLURM_CONF" <<EOF
# throw-away single-node cluster of mink's slurm-check
ClusterName=minkcheck
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=6817
SlurmdPort=6818
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$sock
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MailProg=/bin/true
SchedulerParameters=batch_sched_delay=0
NodeName=$node NodeAddr=127.0.0.1 CPUs=$ncpu RealMemory=100 State=UNKNOWN
PartitionName=check Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld -D -i -f "$SLURM_CONF" > "$tmp"/log/slurmctld.stderr 2>&1 &
ctld_pid=$!
slurmd -D -N "$node" -f "$SLURM_CONF" > "$tmp"/log/slurmd.stderr 2>&1 &
slurmd_pid=$!

t0=$(date +%s) state=""
while :; do
	kill -0 "$ctld_pid" 2>/dev/null || fail "slurmctld exited at start"
	kill -0 "$slurmd_pid" 2>/dev/null || fail "slurmd exited at start"
	state=$(sinfo -h -N -n "$node" -o %T 2>/dev/null | head -n 1)
	[ "$state" = idle ] && break
	[ $(( $(date +%s) - t0 )) -ge "$timeout" ] &&
		fail "node $node did not become idle within $timeout s (sinfo state: '${state:-no answer}')"
	sleep 0.5
done
log "node $node idle after $(( $(date +%s) - t0 )) s ($ncpu CPUs, partition check; slurmctld pid $ctld_pid, slurmd pid $slurmd_pid)"

# ---- 4. the scenes ------------------------------------------------------------------
# Small on purpose (a few seconds of work); 16 shards of 50 headings and of 11
# orientations: uneven shards, and in 3D empty ones (header only).
mkdir -p "$tmp"/run/scene2 "$tmp"/run/scene3
cat > "$tmp"/run/scene2/scene.txt <<'EOF'
# slurm-check: a small 2D scene
dim 2
robot superellipse a=2 b=1 eps=0.3
obstacle circle a=3 at=10,0
obstacle box size=6,2 rot=0.3 at=-30,-30
obstacle superellipse a=4 b=2 eps=0.1 rot=1 at=0,30
obstacle ellipse a=5 b=1.5 shear=0.4 at=25,25
headings 50
EOF
cat > "$tmp"/run/scene3/scene.txt <<'EOF'
# slurm-check: a small 3D scene
dim 3
robot box size=1,0.5,0.7
obstacle sphere a=2 at=5,0,0
obstacle cylinder r=1 h=3 quat=0.7,0.7,0,0 at=0,6,0
obstacle superquadric a=2 b=1 c=1.5 eps1=0.3 eps2=0.6 at=-5,0,2
obstacle ellipsoid a=3 b=1 c=2 quat=1,1,1,0 at=0,-6,-1
quaternions 1,0,0,0;1,1,0,0;1,0,1,0;1,0,0,1;1,1,1,1;2,1,0,3;0,1,2,3;3,-1,2,0;1,-2,1,1;0,0,1,1;5,1,1,-1
EOF

# check_scene DIM TOL: the job array, the merge, the unsharded run, cmp.
failures=0 job_failures=0
check_scene() {
	local dim=$1 tol=$2 dir=$tmp/run/scene$1 n=$shards
	local job rc t1 i state
	mkdir -p "$dir"/out
	# docs/scene.md's job script, with this build's mink.
	cat > "$dir"/job.sh <<EOF
#!/bin/sh
#SBATCH --job-name=mink-scene$dim
exec "$mink" scene scene.txt --tol $tol --outer --threads "\$SLURM_CPUS_PER_TASK" \\
  --shard "\$SLURM_ARRAY_TASK_ID/\$SLURM_ARRAY_TASK_COUNT" \\
  --out "out/part-\$SLURM_ARRAY_TASK_ID.csv" --report "out/report-\$SLURM_ARRAY_TASK_ID.csv"
EOF
	t1=$(date +%s)
	timeout "$timeout" sbatch --wait --parsable --array=0-$((n - 1)) --cpus-per-task="$cpt" \
		--chdir="$dir" --output="$dir"/out/slurm-%A_%a.log "$dir"/job.sh > "$dir"/sbatch.out 2> "$dir"/sbatch.err &
	local sb=$!
	sbatch_pid=$sb
	# The job id, as soon as sbatch prints it (so that the trap can cancel it).
	i=0
	while [ ! -s "$dir"/sbatch.out ] && kill -0 $sb 2>/dev/null && [ $i -lt 600 ]; do sleep 0.1; i=$((i + 1)); done
	job=$(head -n 1 "$dir"/sbatch.out | cut -d';' -f1)
	[ -n "$job" ] && jobs_submitted="$jobs_submitted $job"
	wait $sb
	rc=$?
	sbatch_pid=""
	local secs=$(( $(date +%s) - t1 ))
	# Per task, while the controller still holds them: COMPLETED with exit 0:0?
	local tasks done_ok other
	tasks=$(scontrol -o show job "${job:-0}" 2>/dev/null |
		sed -n 's/.*ArrayTaskId=\([0-9]*\) .*JobState=\([A-Z_]*\) .*ExitCode=\([0-9:]*\).*/\1 \2 \3/p' | sort -n)
	done_ok=$(printf '%s\n' "$tasks" | grep -c ' COMPLETED 0:0$')
	other=$(printf '%s\n' "$tasks" | grep -v ' COMPLETED 0:0$' | awk 'NF { printf " %s:%s(%s)", $1, $2, $3 }')
	log "${dim}D: job ${job:-?}, $n array tasks, $done_ok COMPLETED with exit code 0:0${other:+, others:$other}; sbatch --wait returned $rc after $secs s"
	if [ "$done_ok" != "$n" ] && [ $rc -eq 0 ]; then rc=1; fi
	if [ $rc -ne 0 ] || [ -z "$job" ]; then
		[ $rc -eq 124 ] && echo "slurm_check: ${dim}D: job array not done within $timeout s" >&2
		cat "$dir"/sbatch.err >&2
		for f in "$dir"/out/slurm-*.log; do [ -s "$f" ] && { echo "---- ${f##*/} ----" >&2; tail -n 5 "$f" >&2; }; done
		echo "slurm_check: FAIL ${dim}D scene: the job array failed" >&2
		failures=$((failures + 1)) job_failures=$((job_failures + 1)); return
	fi
	# The merge, exactly as docs/scene.md gives it.
	( cd "$dir" &&
	  { cat out/part-0.csv; i=1; while [ $i -lt $n ]; do tail -n +2 out/part-$i.csv; i=$((i+1)); done; } > cobstacles.csv &&
	  if [ "$dim" = 3 ]; then
	    { cat out/part-0.faces.csv; i=1; while [ $i -lt $n ]; do tail -n +2 out/part-$i.faces.csv; i=$((i+1)); done; } > cobstacles.faces.csv
	  fi ) || { echo "slurm_check: FAIL ${dim}D scene: merging the parts failed" >&2; failures=$((failures + 1)); return; }
	# The same scene unsharded, outside Slurm.
	( cd "$dir" && "$mink" scene scene.txt --tol "$tol" --outer --threads "$ncpu" --out one.csv --report one-report.csv ) ||
		{ echo "slurm_check: FAIL ${dim}D scene: the unsharded run failed" >&2; failures=$((failures + 1)); return; }
	local ok=1 f rows
	for f in cobstacles.csv:one.csv cobstacles.faces.csv:one.faces.csv; do
		[ "$dim" = 2 ] && [ "${f%%:*}" = cobstacles.faces.csv ] && continue
		rows=$(( $(wc -l < "$dir/${f#*:}") - 1 ))
		if cmp "$dir/${f%%:*}" "$dir/${f#*:}"; then
			log "${dim}D: cmp ${f%%:*} ${f#*:}: identical ($rows rows)"
		else
			ok=0
		fi
	done
	if [ $ok = 1 ]; then echo "slurm_check: PASS ${dim}D scene (tol $tol, $n shards)"
	else echo "slurm_check: FAIL ${dim}D scene: the merged shards differ from the unsharded run" >&2; failures=$((failures + 1)); fi
}

check_scene 2 0.01
check_scene 3 0.05

log "wall time $(( $(date +%s) - t_start )) s (packages, daemons, both scenes)"
if [ $failures -ne 0 ]; then
	echo "slurm_check: FAIL: $failures of 2 scenes" >&2
	[ $job_failures = 0 ] && want_tails=0   # the daemons worked; the outputs differ
	exit 1
fi
echo "slurm_check: PASS: both scenes' merged job-array output equals the unsharded run byte for byte"
exit 0
