#!/usr/bin/env bash
# A throwaway PostgreSQL 15 cluster (Debian's `postgresql` package) for the store tests, the
# benchmarks and CI:
#   tools/postgres_cluster.sh start DIR   creates the cluster in DIR if needed, starts it if it is
#                                         not running, prints its URL (postgresql://…) and
#                                         writes it to DIR/url
#   tools/postgres_cluster.sh url DIR     prints the URL of the cluster in DIR
#   tools/postgres_cluster.sh stop DIR    stops it (nothing to do if it is not running)
# All three are idempotent. The server listens on 127.0.0.1 only, on a port that was free when
# the cluster was created (kept in DIR/port; a new free one if that one has been taken since),
# with no Unix socket. It runs as the invoking user, or — when that is root, as in CI, since
# PostgreSQL refuses to run as root — as the system user frustum-pg (created if missing). The
# URL names the role `frustum` (no superuser; it may create databases, as the tests do) and its
# database `frustum`; the passwords are random and kept in DIR, readable by its owner only.
# Programs are run with argument vectors; nothing read from DIR reaches a shell.
set -euo pipefail

usage() {
  echo "usage: tools/postgres_cluster.sh start|stop|url DIR" >&2
  exit 2
}
[[ $# -eq 2 ]] || usage
action=$1
dir=$2
case "$action" in start | stop | url) ;; *) usage ;; esac

bin=${FRUSTUM_PG_BIN:-/usr/lib/postgresql/15/bin}
pg_user=frustum-pg
if [[ ! -x "$bin/initdb" || ! -x "$bin/pg_ctl" ]]; then
  echo "postgres_cluster: no PostgreSQL 15 in $bin (Debian: apt-get install postgresql)" >&2
  exit 1
fi

as_server() {  # as_server COMMAND...: runs COMMAND as the user the server runs as
  if [[ $(id -u) -eq 0 ]]; then
    runuser -u "$pg_user" -- "$@"
  else
    "$@"
  fi
}

if [[ $action == start ]]; then mkdir -p "$dir"; fi
if [[ ! -d "$dir" ]]; then
  [[ $action == stop ]] && exit 0
  echo "postgres_cluster: no cluster in $dir (run: tools/postgres_cluster.sh start $dir)" >&2
  exit 1
fi
dir=$(cd "$dir" && pwd)

# Where the cluster lives: DIR/cluster, or — when the server's user cannot reach DIR (root's
# checkout under /root is 0700) — a directory under /tmp whose name DIR/home records.
home_of() {
  if [[ -f "$dir/home" ]]; then
    cat "$dir/home"
  else
    echo "$dir/cluster"
  fi
}

read_secret() {  # read_secret FILE: the file's one line
  local value
  IFS= read -r value <"$1"
  printf '%s' "$value"
}

url() {
  [[ -f "$dir/port" && -f "$dir/frustum.password" ]] || {
    echo "postgres_cluster: no cluster in $dir (run: tools/postgres_cluster.sh start $dir)" >&2
    exit 1
  }
  printf 'postgresql://frustum:%s@127.0.0.1:%s/frustum\n' "$(read_secret "$dir/frustum.password")" \
    "$(read_secret "$dir/port")"
}

running() {  # running HOME: true when the cluster in HOME is up
  [[ -f "$1/data/PG_VERSION" ]] && as_server "$bin/pg_ctl" -D "$1/data" status >/dev/null 2>&1
}

free_port() {
  python3 -c 'import socket
s = socket.socket()
s.bind(("127.0.0.1", 0))
print(s.getsockname()[1])'
}

port_taken() {  # port_taken PORT: true when something listens on 127.0.0.1:PORT
  python3 - "$1" <<'EOF'
import socket, sys
s = socket.socket()
try:
    s.bind(("127.0.0.1", int(sys.argv[1])))
except OSError:
    sys.exit(0)
sys.exit(1)
EOF
}

secret() { od -An -N16 -tx1 /dev/urandom | tr -d ' \n'; }

psql_admin() {  # psql_admin SQL: runs SQL as the superuser over loopback
  PGPASSWORD=$(read_secret "$dir/postgres.password") "$bin/psql" -X -q -v ON_ERROR_STOP=1 \
    -h 127.0.0.1 -p "$(read_secret "$dir/port")" -U postgres -d postgres -c "$1"
}

create() {
  local home
  umask 077
  if [[ $(id -u) -eq 0 ]]; then
    if ! id -u "$pg_user" >/dev/null 2>&1; then
      useradd --system --no-create-home --home-dir /nonexistent --shell /usr/sbin/nologin \
        "$pg_user"
    fi
    if ! runuser -u "$pg_user" -- test -x "$dir"; then
      home=$(mktemp -d /tmp/frustum-pg.XXXXXXXX)
      printf '%s\n' "$home" >"$dir/home"
      echo "postgres_cluster: $pg_user cannot reach $dir; the cluster lives in $home" >&2
    fi
  fi
  home=$(home_of)
  mkdir -p "$home/data"
  secret >"$dir/postgres.password"
  secret >"$dir/frustum.password"
  free_port >"$dir/port"
  # initdb reads the superuser's password from a file the server's user can read.
  cp "$dir/postgres.password" "$home/pwfile"
  if [[ $(id -u) -eq 0 ]]; then chown -R "$pg_user:" "$home"; fi
  as_server "$bin/initdb" -D "$home/data" -U postgres --pwfile="$home/pwfile" \
    --auth=scram-sha-256 -E UTF8 --locale=C.UTF-8 >"$dir/initdb.log" 2>&1 || {
    cat "$dir/initdb.log" >&2
    exit 1
  }
  rm -f "$home/pwfile"
  {
    echo "# tools/postgres_cluster.sh: loopback only, no Unix socket"
    echo "listen_addresses = '127.0.0.1'"
    echo "unix_socket_directories = ''"
    echo "max_connections = 200"
    echo "shared_buffers = 64MB"
    echo "include_if_exists = 'frustum_port.conf'"
  } >>"$home/data/postgresql.conf"
}

start() {
  local home port
  home=$(home_of)
  if [[ ! -f "$home/data/PG_VERSION" ]]; then
    create
    home=$(home_of)
  fi
  if ! running "$home"; then
    port=$(read_secret "$dir/port")
    if port_taken "$port"; then
      port=$(free_port)
      printf '%s\n' "$port" >"$dir/port"
    fi
    printf 'port = %s\n' "$port" | as_server tee "$home/data/frustum_port.conf" >/dev/null
    as_server "$bin/pg_ctl" -D "$home/data" -l "$home/postgres.log" -w -t 60 start >/dev/null || {
      echo "postgres_cluster: the server did not start; its log:" >&2
      as_server tail -n 30 "$home/postgres.log" >&2 || true
      exit 1
    }
  fi
  if [[ ! -f "$dir/roles" ]]; then
    local password
    password=$(read_secret "$dir/frustum.password")
    [[ $password =~ ^[0-9a-f]+$ ]] || {
      echo "postgres_cluster: $dir/frustum.password is not the hex this script writes" >&2
      exit 1
    }
    psql_admin "CREATE ROLE frustum LOGIN CREATEDB PASSWORD '$password'"
    psql_admin "CREATE DATABASE frustum OWNER frustum"
    touch "$dir/roles"
  fi
  (
    umask 077
    url >"$dir/url"
  )
  cat "$dir/url"
}

stop() {
  local home
  home=$(home_of)
  if running "$home"; then
    as_server "$bin/pg_ctl" -D "$home/data" -m fast -w -t 60 stop >/dev/null
  fi
}

"$action"
