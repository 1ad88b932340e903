#!/usr/bin/env bash
# Load and faults of `frustum serve` on loopback with SQLite (a benchmark, not a timed test):
#   bash bench/serve_load.sh FRUSTUM [--smoke]
# 1. submissions a second acknowledged (wrk), and graded (until nothing is pending)
# 2. p99 of the parse preview and of a submission (wrk --latency)
# 3. 2,000 idle connections held while a new request is timed
# 4. twice the capacity: the share of 429s and the server's memory before and after
# 5. kill -9 of the server ten times while submissions are being acknowledged, then every
#    acknowledged submission stored and graded exactly once
# --smoke runs each part for about a second (the suite's Bench.ServeLoad) and checks only that
# each works.
set -euo pipefail
ulimit -n "$(ulimit -Hn)" 2>/dev/null || true  # 2,000 idle connections on both sides
frustum=$(realpath "$1")
smoke=${2:-}
here=$(cd "$(dirname "$0")" && pwd)
client="python3 $here/serve_load_client.py"
seconds=10; students=200; idle=2000; kills=10
if [ "$smoke" = --smoke ]; then seconds=1; students=20; idle=200; kills=2; fi

work=$(mktemp -d /tmp/frustum-serve-load-XXXXXX)
server=0
cleanup() { [ "$server" != 0 ] && kill -9 "$server" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT

mkdir "$work/course"
cat > "$work/course/week1.yaml" <<'YAML'
title: "Depth"
problems:
  - id: zbuf
    kind: depth_at_pixel
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1], cross: [AC, AB]}
    ask: [normal, plane, z]
YAML
{ echo student; for i in $(seq 1 "$students"); do echo "s$i"; done; } > "$work/course/roster.csv"
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
base="http://127.0.0.1:$port"
db="$work/course/.frustum/serve.sqlite"
"$frustum" serve "$work/course" --issue-links "$work/links.csv" --public-url "$base" >/dev/null

start_server() {  # extra options…
  "$frustum" serve "$work/course" --listen "127.0.0.1:$port" --submit-rate 100000 \
    --preview-rate 100000 "$@" 2>>"$work/server.log" &
  server=$!
  for _ in $(seq 100); do curl -s -o /dev/null "$base/static/page.css" && return; sleep 0.1; done
  echo "the server did not start" >&2; cat "$work/server.log" >&2; exit 1
}
stop_server() { kill "$server"; wait "$server" 2>/dev/null || true; server=0; }
pending() { python3 -c "import sqlite3,sys; print(sqlite3.connect(sys.argv[1]).execute('SELECT count(*) FROM submissions WHERE state=0').fetchone()[0])" "$db"; }
rss_kb() { ps -o rss= -p "$server" | tr -d ' '; }
wrk_run() {  # mode connections
  FRUSTUM_SESSIONS="$work/sessions.lua" FRUSTUM_MODE=$1 \
    wrk -t2 -c"$2" -d"${seconds}s" --latency -s "$here/serve_wrk.lua" "$base" > "$work/wrk.txt"
  cat "$work/wrk.txt"
}

echo "# frustum serve load, $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
start_server
$client sessions "$base" "$work/links.csv" "$work/sessions.lua"

echo "## 1-2. preview, then submissions (64 connections, ${seconds} s each)"
wrk_run preview 64 | grep -E 'Requests/sec|99%|Non-2xx' | sed 's/^/preview: /'
before=$(date +%s.%N)
wrk_run submit 64 | grep -E 'Requests/sec|99%|Non-2xx' | sed 's/^/submit: /'
acked=$(python3 -c "import sqlite3,sys; print(sqlite3.connect(sys.argv[1]).execute('SELECT count(*) FROM submissions').fetchone()[0])" "$db")
while [ "$(pending)" != 0 ]; do sleep 0.2; done
after=$(date +%s.%N)
python3 -c "import sys; n=int(sys.argv[1]); t=float(sys.argv[3])-float(sys.argv[2]); print('graded: %d submissions acknowledged and graded in %.1f s: %.0f a second' % (n, t, n/t))" "$acked" "$before" "$after"

echo "## 3. ${idle} idle connections"
$client idle "$base" "$idle" 50
stop_server

echo "## 4. overload: 16 requests in flight allowed, 128 connections submitting"
start_server --max-in-flight 16
rss0=$(rss_kb)
wrk_run submit 128 | grep -E 'Requests/sec|Non-2xx' | sed 's/^/overload: /'
rss1=$(rss_kb)
wrk_run submit 128 > /dev/null
rss2=$(rss_kb)
echo "overload: server RSS ${rss0} kB at start, ${rss1} kB after one run, ${rss2} kB after two"
stop_server
while [ "$(pending)" != 0 ]; do start_server; sleep 1; stop_server; done

echo "## 5. kill -9 under load, ${kills} times"
: > "$work/acked.txt"
for i in $(seq "$kills"); do
  start_server
  before=$(wc -l < "$work/acked.txt")
  $client acked "$base" "$work/sessions.lua" 10 "$work/acked.txt" &
  loader=$!
  # Killed mid-stream: once submissions are being acknowledged, a moment later.
  for _ in $(seq 100); do [ "$(wc -l < "$work/acked.txt")" -ge $((before + 50)) ] && break; sleep 0.1; done
  sleep 0.3
  kill -9 "$server"; wait "$server" 2>/dev/null || true; server=0
  kill "$loader"; wait "$loader" 2>/dev/null || true
done
start_server
for _ in $(seq 600); do [ "$(pending)" = 0 ] && break; sleep 0.5; done
stop_server
$client verify "$db" "$work/acked.txt"
