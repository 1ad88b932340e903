#!/usr/bin/env bash
# The multi-instance soak over one PostgreSQL database: submissions under load, one instance
# killed with SIGKILL mid-run and started again, then every acknowledged submission must be
# stored and graded exactly once (grade rows counted per submission in SQL).
#   bench/serve_cluster_soak.sh [--seconds S] [--students N] [--build DIR]
#       three `frustum serve` instances (one grading worker each) behind a local haproxy
#       (loopback only, its configuration generated here); N students (default 300) submit
#       through it for S seconds (default 60), each at most once a second (the server's rate);
#       halfway the second instance and its worker are killed with SIGKILL, and it is started
#       again two seconds later
#   bench/serve_cluster_soak.sh --store [--submissions N] [--build DIR]
#       the same promise one level down: three grading processes (bench/store_soak.cpp)
#       claiming from one database while a client submits N (default 3000) through the store;
#       the second process is killed once it has graded a tenth of them, and a new one takes its
#       place; the third is paused past its lease while it holds a claim, then resumed (its
#       grade must be refused)
# PostgreSQL: FRUSTUM_TEST_PG if set, else a cluster of tools/postgres_cluster.sh in
# BUILD/postgres (started if needed, left running). Each run works in a schema of its own,
# dropped at the end. Prints the figures and "soak: PASS", or what failed and exits 1.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mode=http
submissions=3000
seconds=60
students=300
build=$root/build
usage() {
  echo "usage: bench/serve_cluster_soak.sh [--seconds S] [--students N] [--build DIR]" >&2
  echo "       bench/serve_cluster_soak.sh --store [--submissions N] [--build DIR]" >&2
  exit 2
}
while [[ $# -gt 0 ]]; do
  case "$1" in
    --store) mode=store ;;
    --submissions) submissions=${2:-}; shift ;;
    --seconds) seconds=${2:-}; shift ;;
    --students) students=${2:-}; shift ;;
    --build) build=${2:-}; shift ;;
    *) usage ;;
  esac
  shift
done
[[ $submissions =~ ^[0-9]+$ && $submissions -ge 10 ]] || usage
[[ $seconds =~ ^[0-9]+$ && $seconds -ge 4 ]] || usage
[[ $students =~ ^[0-9]+$ && $students -ge 3 ]] || usage

server=${FRUSTUM_TEST_PG:-}
if [[ -z $server ]]; then server=$(bash "$root/tools/postgres_cluster.sh" start "$build/postgres"); fi
# The password goes to libpq through the environment, not the command lines of the instances
# and their workers, which every user of the machine can read (ps).
if [[ $server =~ ^(postgres(ql)?://[^:/@?]+):([0-9A-Za-z_.~-]+)@(.*)$ ]]; then
  export PGPASSWORD=${BASH_REMATCH[3]}
  server="${BASH_REMATCH[1]}@${BASH_REMATCH[4]}"
fi
schema=soak_$$_$RANDOM
url="$server$([[ $server == *\?* ]] && echo '&' || echo '?')options=-csearch_path%3D$schema"
psql_server() { psql -X -q -At -v ON_ERROR_STOP=1 "$server" -c "$1"; }
sql() { psql -X -q -At -v ON_ERROR_STOP=1 "$url" -c "$1"; }
work=$(mktemp -d /tmp/frustum-soak.XXXXXX)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill -9 "$pid" 2>/dev/null || true; done
  psql_server "DROP SCHEMA IF EXISTS $schema CASCADE" >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT
psql_server "CREATE SCHEMA $schema"
echo "soak: $(date -u '+%F %T') UTC on $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')), load $(cut -d' ' -f1-3 /proc/loadavg)"

fail=0
check() {  # check WHAT EXPECTED ACTUAL
  if [[ "$2" == "$3" ]]; then echo "soak: ok   $1: $3"; else echo "soak: FAIL $1: $3 (expected $2)"; fail=1; fi
}
# Every acknowledged submission (ids in $work/acked) stored and graded exactly once.
check_exactly_once() {
  sql "SELECT id FROM submissions" | sort >"$work/stored"  # comm's order
  check "acknowledged but not stored" 0 "$(comm -23 "$work/acked" "$work/stored" | wc -l)"
  check "stored submissions not graded" 0 "$(sql "SELECT count(*) FROM submissions s WHERE NOT EXISTS (SELECT 1 FROM grades g WHERE g.submission = s.id)")"
  check "submissions with more than one grade row" 0 "$(sql "SELECT count(*) FROM (SELECT submission FROM grades GROUP BY submission HAVING count(*) > 1) x")"
  check "submissions still pending" 0 "$(sql "SELECT count(*) FROM submissions WHERE state = 0")"
  check "grade rows = stored submissions" "$(wc -l <"$work/stored")" "$(sql "SELECT count(*) FROM grades")"
}

if [[ $mode == http ]]; then
  frustum=$build/frustum
  [[ -x $frustum ]] || { echo "soak: $frustum is not built" >&2; exit 1; }
  command -v haproxy >/dev/null || { echo "soak: no haproxy (Debian: apt-get install haproxy)" >&2; exit 1; }
  free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
  mkdir "$work/course"
  cat >"$work/course/week1.yaml" <<'YAML'
title: "Depth"
problems:
  - id: zbuf
    kind: depth_at_pixel
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1], cross: [AC, AB]}
    ask: [normal, plane, z]
YAML
  { echo student; for i in $(seq 1 "$students"); do echo "s$i"; done; } >"$work/course/roster.csv"
  front=$(free_port)
  base=http://127.0.0.1:$front
  ports=("$(free_port)" "$(free_port)" "$(free_port)")
  "$frustum" serve "$work/course" --db "$url" --issue-links "$work/links.csv" --public-url "$base" >/dev/null
  instance=()
  start_instance() {  # start_instance I: instance I (0-2) on its port, one grading worker
    "$frustum" serve "$work/course" --db "$url" --listen "127.0.0.1:${ports[$1]}" --workers 1 \
      --grade-seconds 5 2>>"$work/instance-$1.log" &
    instance[$1]=$!
    pids+=($!)
    for _ in $(seq 200); do
      curl -s -o /dev/null "http://127.0.0.1:${ports[$1]}/static/page.css" && return
      sleep 0.05
    done
    echo "soak: FAIL instance $1 did not start" >&2
    cat "$work/instance-$1.log" >&2
    exit 1
  }
  for i in 0 1 2; do start_instance $i; done
  {
    echo "global"
    echo "  maxconn 4096"
    echo "defaults"
    echo "  mode http"
    echo "  timeout connect 2s"
    echo "  timeout client 30s"
    echo "  timeout server 30s"
    echo "  retries 2"
    echo "  option redispatch"
    echo "frontend soak"
    echo "  bind 127.0.0.1:$front"
    echo "  default_backend serve"
    echo "backend serve"
    echo "  balance roundrobin"
    echo "  option httpchk GET /static/page.css"
    for i in 0 1 2; do echo "  server i$i 127.0.0.1:${ports[$i]} check inter 500 fall 2 rise 1"; done
  } >"$work/haproxy.cfg"
  haproxy -f "$work/haproxy.cfg" -db >"$work/haproxy.log" 2>&1 &
  pids+=($!)
  for _ in $(seq 100); do curl -s -o /dev/null "$base/static/page.css" && break; sleep 0.05; done

  python3 "$root/bench/serve_cluster_client.py" login "$base" "$work/links.csv" "$work/sessions"
  start=$(date +%s%N)
  python3 "$root/bench/serve_cluster_client.py" submit "$base" "$work/sessions" "$seconds" 16 \
    "$work/acks.log" >"$work/client.out" &
  client=$!
  pids+=($client)
  sleep $((seconds / 2))
  # The kill: instance 1 and its grading worker, as a machine lost.
  victims=("${instance[1]}" $(ps -o pid= --ppid "${instance[1]}"))
  kill -9 "${victims[@]}"
  killed_at=$((($(date +%s%N) - start) / 1000000))
  wait "${instance[1]}" 2>/dev/null || true
  held=$(sql "SELECT count(*) FROM submissions WHERE state = 0 AND claimed_by IS NOT NULL")
  sleep 2
  start_instance 1
  restarted_at=$((($(date +%s%N) - start) / 1000000))
  wait "$client" || { echo "soak: FAIL the client failed" >&2; exit 1; }
  cat "$work/client.out"
  # Then everything graded: a claim of the killed worker runs out after its lease (5 s + 5 s).
  for _ in $(seq 600); do
    [[ $(sql "SELECT count(*) FROM submissions WHERE state = 0") == 0 ]] && break
    sleep 0.2
  done
  graded_at=$((($(date +%s%N) - start) / 1000000))
  awk '$1 == "ack" { print $2 }' "$work/acks.log" | sort >"$work/acked"
  acked=$(wc -l <"$work/acked")
  ((acked > 0)) || { echo "soak: FAIL nothing was acknowledged" >&2; tail "$work"/instance-*.log >&2; exit 1; }
  check_exactly_once
  echo "soak: instance 1 killed at ${killed_at} ms (${held} submissions claimed by some worker and not yet graded just after), started again at ${restarted_at} ms; all graded by ${graded_at} ms"
  echo "soak: ${acked} acknowledged, $(wc -l <"$work/stored") stored; graded by worker: $(sql "SELECT string_agg(graded_by || '=' || n, ' ') FROM (SELECT graded_by, count(*) n FROM grades GROUP BY graded_by ORDER BY graded_by) x")"
  echo "soak: submissions claimed more than once (a claim taken over): $(sql "SELECT count(*) FROM submissions WHERE claims > 1")"
  if ((fail)); then echo "soak: FAIL"; exit 1; fi
  echo "soak: PASS"
  exit 0
fi

soak=$build/frustum_store_soak
[[ -x $soak ]] || { echo "soak: $soak is not built (cmake --build $build --target frustum_store_soak)" >&2; exit 1; }
lease_ms=1500 grade_ms=20 idle_exit_ms=4000  # a grading takes ~20 ms (the pause)

start=$(date +%s%N)
for w in 1 2 3; do
  "$soak" work "$url" "worker-$w" $lease_ms $grade_ms $idle_exit_ms >"$work/worker-$w.log" &
  pids+=($!)
done
"$soak" submit "$url" "$submissions" 8 >"$work/acks.log" &
submitter=$!
pids+=($submitter)

# The kill: once worker 2 has graded a tenth of the submissions, at a moment it holds a claim.
victim=${pids[1]}
until (($(grep -c '^graded' "$work/worker-2.log" || true) >= submissions / 10)); do
  kill -0 "$victim" 2>/dev/null || { echo "soak: FAIL worker 2 died on its own" >&2; cat "$work/worker-2.log" >&2; exit 1; }
  sleep 0.05
done
for _ in $(seq 200); do
  [[ $(tail -n1 "$work/worker-2.log") == claim* ]] && break
  sleep 0.002
done
kill -9 "$victim"
wait "$victim" 2>/dev/null || true
killed_at=$(( ($(date +%s%N) - start) / 1000000 ))
held=$(awk '$1 == "claim" { c[$2] = 1 } $1 == "graded" || $1 == "late" { delete c[$2] } END { for (i in c) print i }' "$work/worker-2.log")
"$soak" work "$url" "worker-2-restarted" $lease_ms $grade_ms $idle_exit_ms >"$work/worker-2b.log" &
pids+=($!)

# A worker that stalls (paused past its lease while holding a claim) and wakes up: its grade must
# be refused, since another has taken the claim by then.
stalled=${pids[2]}
for _ in $(seq 500); do
  [[ $(tail -n1 "$work/worker-3.log") == claim* ]] && break
  sleep 0.002
done
kill -STOP "$stalled"
stalled_claim=$(awk '$1 == "claim" { c[$2] = 1 } $1 == "graded" || $1 == "late" { delete c[$2] } END { for (i in c) print i }' "$work/worker-3.log")
sleep $(((lease_ms + 1000) / 1000))
kill -CONT "$stalled"

wait "$submitter" || { echo "soak: FAIL the submitting client failed" >&2; exit 1; }
acked_at=$(( ($(date +%s%N) - start) / 1000000 ))
for pid in "${pids[@]:2}"; do [[ $pid == "$submitter" ]] || wait "$pid" || true; done
wait "${pids[0]}" || true
done_at=$(( ($(date +%s%N) - start) / 1000000 - idle_exit_ms ))

awk '$1 == "ack" { print $2 }' "$work/acks.log" | sort >"$work/acked"
acked=$(wc -l <"$work/acked")
check "acknowledged submissions" "$submissions" "$acked"
check_exactly_once
for id in $held; do
  # Its grade may have been committed just before the kill (graded_by worker-2); else another
  # worker took the claim once its lease ran out. Either way: one row.
  check "grade rows of submission $id, claimed by the killed worker" 1 \
    "$(sql "SELECT count(*) FROM grades WHERE submission = $id")"
  echo "soak: submission $id was graded by $(sql "SELECT string_agg(graded_by, ',') FROM grades WHERE submission = $id")"
done
for id in $stalled_claim; do
  check "grade rows of submission $id, claimed by the stalled worker" 1 \
    "$(sql "SELECT count(*) FROM grades WHERE submission = $id")"
  echo "soak: submission $id was graded by $(sql "SELECT string_agg(graded_by, ',') FROM grades WHERE submission = $id"); worker 3 said: $(grep " $id\$" "$work/worker-3.log" | tr '\n' ' ')"
done
[[ -n $held ]] || echo "soak: note: the kill found worker 2 between claims (no claim was left to take over)"
late=$(cat "$work"/worker-*.log | grep -c '^late' || true)
echo "soak: killed worker 2 at ${killed_at} ms holding ${held:-no} claim; ${late} late record_grade calls refused"
echo "soak: ${acked} submissions acknowledged in ${acked_at} ms ($((acked * 1000 / (acked_at > 0 ? acked_at : 1)))/s), all graded by ~${done_at} ms; graded per worker: $(for f in "$work"/worker-*.log; do printf '%s=%s ' "$(basename "$f" .log)" "$(grep -c '^graded' "$f" || true)"; done)"
if ((fail)); then echo "soak: FAIL"; exit 1; fi
echo "soak: PASS"
