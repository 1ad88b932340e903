#!/usr/bin/env python3
"""The client of bench/serve_cluster_soak.sh: students who sign in through their links and then
submit for a while, through the load balancer, recording every submission the server
acknowledged (202 with its id). Only an acknowledged submission is promised to be kept; a
request that failed (the instance behind it was killed, 502/503) or was refused (429) is
counted, never recorded.

  serve_cluster_client.py login BASE LINKS.csv SESSIONS.txt
  serve_cluster_client.py submit BASE SESSIONS.txt SECONDS THREADS ACKS.txt
"""
import csv
import http.client
import json
import re
import sys
import threading
import time
import urllib.parse


def connect(base):
    u = urllib.parse.urlparse(base)
    return http.client.HTTPConnection(u.hostname, u.port, timeout=30)


def login(base, links, out):
    rows = list(csv.DictReader(open(links)))
    c = connect(base)
    with open(out, "w") as f:
        for row in rows:
            u = urllib.parse.urlparse(row["url"])
            c.request("GET", u.path + "?" + u.query)
            r = c.getresponse()
            r.read()
            cookie = re.search(r"frustum_session=([0-9a-f]{32})", r.getheader("Set-Cookie") or "")
            if not cookie:
                sys.exit("login: no session for %s (HTTP %d)" % (row["student"], r.status))
            c.request("GET", "/set/week1", headers={"Cookie": "frustum_session=" + cookie.group(1)})
            page = c.getresponse().read().decode()
            csrf = re.search(r'name="csrf" (?:value|content)="([0-9a-f]+)"', page)
            if not csrf:
                sys.exit("login: no CSRF token on %s's page" % row["student"])
            f.write("%s %s %s\n" % (row["student"], cookie.group(1), csrf.group(1)))


def submit(base, sessions_file, seconds, threads, acks_file):
    sessions = [line.split() for line in open(sessions_file) if line.strip()]
    out = open(acks_file, "w")
    lock = threading.Lock()
    counts = {"acked": 0, "refused": 0, "failed": 0, "unreachable": 0}
    latencies = []
    end = time.monotonic() + seconds

    def count(what, latency=None):
        with lock:
            counts[what] += 1
            if latency is not None:
                latencies.append(latency)

    def run(mine):
        c = connect(base)
        # Each student at most once a second (the server's per-session rate is 1/s, burst 10).
        due = {s[0]: 0.0 for s in mine}
        n = 0
        while time.monotonic() < end:
            student, cookie, csrf = min(mine, key=lambda s: due[s[0]])
            wait = due[student] - time.monotonic()
            if wait > 0:
                time.sleep(wait)
            due[student] = time.monotonic() + 1.0
            n += 1
            body = urllib.parse.urlencode({
                "csrf": csrf, "problem": "zbuf", "a.normal": "(-1, -1, 1)",
                "a.plane": "-x - y + z = 6", "a.z": str(8 + n % 3)})
            headers = {"Cookie": "frustum_session=" + cookie, "Accept": "application/json",
                       "Content-Type": "application/x-www-form-urlencoded"}
            start = time.monotonic()
            try:
                c.request("POST", "/set/week1/submit", body, headers)
                r = c.getresponse()
                text = r.read()
            except (OSError, http.client.HTTPException):
                count("unreachable")
                c.close()
                c = connect(base)
                continue
            if r.status == 202:
                sid = json.loads(text)["id"]
                with lock:
                    out.write("ack %d %s\n" % (sid, student))
                    out.flush()
                count("acked", time.monotonic() - start)
            elif r.status == 429:
                count("refused")
            else:
                count("failed")

    parts = [sessions[i::threads] for i in range(threads)]
    workers = [threading.Thread(target=run, args=(p,)) for p in parts if p]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    latencies.sort()
    if latencies:
        pick = lambda q: latencies[min(len(latencies) - 1, int(len(latencies) * q))] * 1000
        print("client: %d acknowledged (%.0f/s), %d refused (429), %d failed (5xx), %d unreachable; "
              "acknowledged in p50 %.1f ms, p99 %.1f ms, max %.1f ms"
              % (counts["acked"], counts["acked"] / seconds, counts["refused"], counts["failed"],
                 counts["unreachable"], pick(0.5), pick(0.99), latencies[-1] * 1000))
    else:
        print("client: nothing acknowledged: %s" % counts)


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "login":
        login(sys.argv[2], sys.argv[3], sys.argv[4])
    elif len(sys.argv) == 7 and sys.argv[1] == "submit":
        submit(sys.argv[2], sys.argv[3], float(sys.argv[4]), int(sys.argv[5]), sys.argv[6])
    else:
        sys.exit(__doc__)
