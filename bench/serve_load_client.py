#!/usr/bin/env python3
"""The parts of bench/serve_load.sh that wrk cannot do: sessions for wrk, idle connections,
a submitter that records every acknowledged submission, and the check that each is stored and
graded exactly once.

  serve_load_client.py sessions BASE LINKS.csv OUT.lua
  serve_load_client.py idle BASE COUNT PROBES
  serve_load_client.py acked BASE SESSIONS.lua SECONDS OUT.txt
  serve_load_client.py verify DB ACKED.txt
"""
import csv
import http.client
import re
import socket
import sqlite3
import sys
import threading
import time
import urllib.parse


def host_port(base):
    u = urllib.parse.urlparse(base)
    return u.hostname, u.port


def login(base, url):
    host, port = host_port(base)
    c = http.client.HTTPConnection(host, port, timeout=30)
    c.request("GET", urllib.parse.urlparse(url).path + "?" + urllib.parse.urlparse(url).query)
    r = c.getresponse()
    r.read()
    cookie = re.search(r"frustum_session=([0-9a-f]{32})", r.getheader("Set-Cookie")).group(1)
    c.request("GET", "/set/week1", headers={"Cookie": "frustum_session=" + cookie})
    page = c.getresponse().read().decode()
    csrf = re.search(r'name="csrf" content="([0-9a-f]+)"', page).group(1)
    return cookie, csrf


def sessions(base, links, out):
    rows = list(csv.DictReader(open(links)))
    with open(out, "w") as f:
        f.write("return {\n")
        for row in rows:
            cookie, csrf = login(base, row["url"])
            f.write('  {cookie="%s", csrf="%s"},\n' % (cookie, csrf))
        f.write("}\n")


def read_sessions(path):
    return re.findall(r'cookie="([0-9a-f]+)", csrf="([0-9a-f]+)"', open(path).read())


def idle(base, count, probes):
    host, port = host_port(base)
    held = []
    for _ in range(count):
        s = socket.create_connection((host, port))
        held.append(s)
    time.sleep(1)
    times = []
    for _ in range(probes):
        c = http.client.HTTPConnection(host, port, timeout=30)
        start = time.perf_counter()
        c.request("GET", "/static/page.css")
        c.getresponse().read()
        times.append((time.perf_counter() - start) * 1000)
        c.close()
    alive = 0
    for s in held:
        s.setblocking(False)
        try:
            alive += s.recv(1) != b""
        except BlockingIOError:
            alive += 1
        s.close()
    times.sort()
    print("idle connections held: %d of %d; a new request with them open: p50 %.1f ms, "
          "p99 %.1f ms, max %.1f ms" % (alive, count, times[len(times) // 2],
                                         times[int(len(times) * 0.99) - 1], times[-1]))


def acked(base, sessions_file, seconds, out):
    host, port = host_port(base)
    pairs = read_sessions(sessions_file)
    lock = threading.Lock()
    deadline = time.time() + seconds
    f = open(out, "a")

    def run(index):
        cookie, csrf = pairs[index % len(pairs)]
        n = 0
        c = None
        while time.time() < deadline:
            n += 1
            body = urllib.parse.urlencode({"csrf": csrf, "problem": "zbuf", "a.z": "%d-%d" % (index, n)})
            try:
                if c is None:
                    c = http.client.HTTPConnection(host, port, timeout=5)
                c.request("POST", "/set/week1/submit", body, {
                    "Cookie": "frustum_session=" + cookie, "Accept": "application/json",
                    "Content-Type": "application/x-www-form-urlencoded"})
                r = c.getresponse()
                text = r.read().decode()
                if r.status == 202:
                    m = re.search(r'"id":(\d+)', text)
                    with lock:
                        f.write(m.group(1) + "\n")
                        f.flush()
            except (OSError, http.client.HTTPException):
                c = None
                time.sleep(0.05)

    threads = [threading.Thread(target=run, args=(i,)) for i in range(16)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()


def verify(db, acked_file):
    ids = [int(x) for x in open(acked_file).read().split()]
    con = sqlite3.connect(db)
    missing = [i for i in ids if not con.execute("SELECT 1 FROM submissions WHERE id = ?", (i,)).fetchone()]
    counts = dict(con.execute("SELECT submission, count(*) FROM grades GROUP BY submission"))
    ungraded = [i for i in ids if counts.get(i, 0) == 0]
    twice = [i for i, n in counts.items() if n > 1]
    pending = con.execute("SELECT count(*) FROM submissions WHERE state = 0").fetchone()[0]
    print("acknowledged %d; missing from the store %d; ungraded %d; graded more than once %d; "
          "pending %d" % (len(ids), len(missing), len(ungraded), len(twice), pending))
    return 0 if ids and not missing and not ungraded and not twice else 1


if __name__ == "__main__":
    a = sys.argv[1:]
    if a[0] == "sessions":
        sessions(a[1], a[2], a[3])
    elif a[0] == "idle":
        idle(a[1], int(a[2]), int(a[3]))
    elif a[0] == "acked":
        acked(a[1], a[2], float(a[3]), a[4])
    elif a[0] == "verify":
        sys.exit(verify(a[1], a[2]))
