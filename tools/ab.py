#!/usr/bin/env python3
"""Interleaved whole-process CPU/wall A/B (how docs/performance.md measures each change).
usage: tools/ab.py ROUNDS 'cmdA' 'cmdB' ['cmdC' ...]
Runs one warm-up of each, then ROUNDS rounds, alternating order; prints CPU (user+sys of the child
and its threads) and wall per command, and each command's ratio to the first: median [min-max], IQR."""
import os, resource, subprocess, sys, time, statistics as st
def run(cmd):
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN); t0 = time.time()
    p = subprocess.run(cmd, shell=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    t1 = time.time(); r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode: sys.exit("failed (%d): %s\n%s" % (p.returncode, cmd, p.stderr.decode()[-2000:]))
    return (r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime), t1 - t0
n = int(sys.argv[1]); cmds = sys.argv[2:]
for c in cmds: run(c)
cpu = [[] for _ in cmds]; wall = [[] for _ in cmds]
for r in range(n):
    order = list(range(len(cmds))) if r % 2 == 0 else list(reversed(range(len(cmds))))
    for i in order:
        c, w = run(cmds[i]); cpu[i].append(c); wall[i].append(w)
def q(xs):
    xs = sorted(xs); k = len(xs)
    return xs[k // 4], xs[(3 * k) // 4]
print("load %.1f" % os.getloadavg()[0])
for i, c in enumerate(cmds):
    line = "%-60s cpu %.3f wall %.3f" % (c[-60:], st.median(cpu[i]), st.median(wall[i]))
    if i:
        rc = [a / b for a, b in zip(cpu[i], cpu[0])]; rw = [a / b for a, b in zip(wall[i], wall[0])]
        lo, hi = q(rc)
        line += "  cpu ratio %.3f [%.3f-%.3f] IQR %.3f-%.3f  wall ratio %.3f" % (st.median(rc), min(rc), max(rc), lo, hi, st.median(rw))
    print(line)
