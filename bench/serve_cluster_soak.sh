#!/usr/bin/env bash
# The multi-instance soak over one PostgreSQL database: submissions under load, one instance
# killed with SIGKILL mid-run and started again, then every acknowledged submission must be
# stored and graded exactly once (grade rows counted per submission in SQL).
#   bench/serve_cluster_soak.sh --store [--submissions N] [--build DIR]
#       three grading processes (bench/store_soak.cpp) claiming from one database while a client
#       submits N (default 3000) through the store; the second process is killed once it has
#       graded a tenth of them, and a new one takes its place; the third is paused past its
#       lease while it holds a claim, then resumed (its grade must be refused)
# PostgreSQL: FRUSTUM_TEST_PG if set, else a cluster of tools/postgres_cluster.sh in
# BUILD/postgres (started if needed, left running). Each run works in a schema of its own,
# dropped at the end. Prints the figures and "soak: PASS", or what failed and exits 1.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mode=""
submissions=3000
build=$root/build
while [[ $# -gt 0 ]]; do
  case "$1" in
    --store) mode=store ;;
    --submissions) submissions=$2; shift ;;
    --build) build=$2; shift ;;
    *) echo "usage: bench/serve_cluster_soak.sh --store [--submissions N] [--build DIR]" >&2; exit 2 ;;
  esac
  shift
done
[[ $submissions =~ ^[0-9]+$ && $submissions -ge 10 ]] || { echo "soak: --submissions needs a number >= 10" >&2; exit 2; }
[[ -n $mode ]] || { echo "soak: say --store" >&2; exit 2; }

server=${FRUSTUM_TEST_PG:-}
if [[ -z $server ]]; then server=$(bash "$root/tools/postgres_cluster.sh" start "$build/postgres"); fi
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

soak=$build/frustum_store_soak
[[ -x $soak ]] || { echo "soak: $soak is not built (cmake --build $build --target frustum_store_soak)" >&2; exit 1; }
lease_ms=1500 grade_ms=20 idle_exit_ms=4000  # a grading takes ~20 ms (the pause)

echo "soak: $(date -u '+%F %T') UTC on $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')), load $(cut -d' ' -f1-3 /proc/loadavg)"
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

# The checks, in SQL.
fail=0
check() {  # check WHAT EXPECTED ACTUAL
  if [[ "$2" == "$3" ]]; then echo "soak: ok   $1: $3"; else echo "soak: FAIL $1: $3 (expected $2)"; fail=1; fi
}
awk '$1 == "ack" { print $2 }' "$work/acks.log" | sort -n >"$work/acked"
sql "SELECT id FROM submissions ORDER BY id" | sort -n >"$work/stored"
acked=$(wc -l <"$work/acked")
check "acknowledged submissions" "$submissions" "$acked"
check "acknowledged but not stored" 0 "$(comm -23 "$work/acked" "$work/stored" | wc -l)"
check "stored submissions not graded" 0 "$(sql "SELECT count(*) FROM submissions s WHERE NOT EXISTS (SELECT 1 FROM grades g WHERE g.submission = s.id)")"
check "submissions with more than one grade row" 0 "$(sql "SELECT count(*) FROM (SELECT submission FROM grades GROUP BY submission HAVING count(*) > 1) x")"
check "submissions still pending" 0 "$(sql "SELECT count(*) FROM submissions WHERE state = 0")"
check "grade rows" "$acked" "$(sql "SELECT count(*) FROM grades")"
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
