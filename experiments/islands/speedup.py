#!/usr/bin/env python3
"""Reads the runs speedup.sh made (DIR/MODE-P-REP: summary.json, .err with the --verbose timing
lines, .work with each process's CPU seconds per stretch between meetings, .time, .load) and prints a
CSV row per run, then the speed-up against P = 1 per mode.

Measured: evaluations / the run's own seconds (summary.json), best of the repetitions.
Per run also: writer_cpu (the store thread's CPU seconds in its transactions), rank_cpu,
rank_work_us_per_eval and rank_wait (each process's CPU seconds; its run loop's CPU without the
waits, per evaluation of its island (MPI; threads: the main thread only); wall seconds blocked in gather,
stop and migrate; rank_end: wall seconds waiting at the end for the slowest island, since the delay).
Idle estimate (what a machine with CORES free cores would give): the islands meet (every stored
generation before 2026-11-25, every migration since) and each stretch between two meetings takes
the longest process's work w[r][g] (CPU seconds of its one thread; every process waits for the
others there), or the stretch's whole CPU (all processes and the writer's commits) spread over
the cores when that is more:
    T = sum_g max(max_r w[r][g], (sum_r w[r][g] + commit_cpu / G) / CORES)
With a migration delay d >= 1 (read from the store's meta; mode lockstep and stores without it:
0) a process only waits at meeting g for the others' meeting g - d (migrants, the writer's stop
and, at the writer, the stretches), so each process's finish time of meeting g is
    F[r][g] = max(F[r][g-1] + w[r][g], max_s F[s][g-d])
and T = max(max_r F[r][G], the whole CPU spread over the cores); idle_wait_fraction is each
process's simulated waiting, sum_g (F[r][g] - F[r][g-1] - w[r][g]) / T (d = 0: the lockstep).
Messages between ranks on one machine take microseconds and are left out. For threads (one
process) every island's work is in one line: T = sum_g max(w[g] / min(P, CORES), ...) is not
separable, so the estimate is process CPU / min(P, CORES) (a lower bound)."""
import glob, json, os, re, sqlite3, sys

root, cores = sys.argv[1], int(sys.argv[2])
rows = []
for run in sorted(p for p in glob.glob(os.path.join(root, "*-*-*")) if os.path.isdir(p)):
    mode, P, rep = os.path.basename(run).split("-")
    P = int(P)
    s = json.load(open(os.path.join(run, "summary.json")))
    evals, wall = s["evaluations"], s["seconds"]
    user, sys_ = map(float, open(run + ".time").read().split()[:2])
    load = float(open(run + ".load").read())
    timing = [dict(zip(t[::2], map(float, t[1::2]))) for t in
              (re.search(r"timing: islands \S+: (.*)", l).group(1).split()
               for l in open(run + ".err") if "timing: islands" in l)]
    work = [list(map(float, l.split())) for l in open(run + ".work") if l.strip()]
    commit_cpu = sum(t.get("commit_cpu", 0) for t in timing)
    commit_wall = sum(t.get("commit_wall", 0) for t in timing)
    run_cpu = sum(t["cpu"] for t in timing)  # the run loops' CPU, every process
    G = max(len(w) for w in work)
    meta = dict(sqlite3.connect(os.path.join(run, "run.sqlite")).execute("select key, value from meta"))
    delay = int(re.search(r"migration_delay: (\d+)", meta.get("islands", "")).group(1)) \
        if "migration_delay" in meta.get("islands", "") else 0
    idle_waits = [0.0] * len(work)
    if mode in ("serial", "lockserial"):  # one thread; the writer beside it on another core
        idle = run_cpu - commit_cpu
    elif mode in ("mpi", "lockstep") and delay == 0:
        idle = sum(max(max(w[g] for w in work), (sum(w[g] for w in work) + commit_cpu / G) / cores) for g in range(G))
        for g in range(G):
            step = max(w[g] for w in work)
            for r, w in enumerate(work):
                idle_waits[r] += step - w[g]
    elif mode in ("mpi", "lockstep"):
        F = [[0.0] * G for _ in work]
        for g in range(G):
            for r, w in enumerate(work):
                before = F[r][g - 1] if g else 0.0
                ready = max(Fs[g - delay] for Fs in F) if g >= delay else 0.0
                F[r][g] = max(before + w[g], ready)
                idle_waits[r] += F[r][g] - before - w[g]
        idle = max(max(Fr[-1] for Fr in F), (sum(map(sum, work)) + commit_cpu) / cores)
    else:
        idle = run_cpu / min(P, cores)
    waits = [(t["gather"] + t["stop"] + t["migrate"]) / t["wall"] for t in timing]
    rows.append(dict(mode=mode, P=P, rep=int(rep), load=load, evaluations=evals, wall=wall, evals_per_s=evals / wall,
                     cpu_us_per_eval=1e6 * run_cpu / evals, evals_per_cpu_s_per_rank=evals / run_cpu,
                     wait_fraction=max(waits), commit_wall_fraction=commit_wall / wall,
                     commit_cpu_fraction=commit_cpu / run_cpu, idle_seconds=idle, idle_evals_per_s=evals / idle,
                     command_cpu=user + sys_, writer_cpu=commit_cpu,
                     rank_cpu=";".join(f"{t['cpu']:.3f}" for t in timing),
                     rank_work_us_per_eval=";".join(f"{1e6 * sum(w) / (evals / P):.1f}" for w in work),
                     rank_wait=";".join(f"{t['gather'] + t['stop'] + t['migrate']:.3f}" for t in timing),
                     rank_wait_fraction=";".join(f"{(t['gather'] + t['stop'] + t['migrate']) / t['wall']:.3f}"
                                                 for t in timing),
                     rank_end=";".join(f"{t.get('end', 0):.3f}" for t in timing), delay=delay, idle_wait_fraction=";".join(f"{x / idle:.3f}" for x in idle_waits)))
keys = list(rows[0].keys())
print(",".join(keys))
for r in rows:
    print(",".join(f"{r[k]:.4g}" if isinstance(r[k], float) else str(r[k]) for k in keys))
print()
# The same evaluations (P islands) on one thread against P ranks or threads: the speed-up of the same work.
serial = {}
for r in rows:
    if r["mode"] in ("serial", "lockserial"):
        b = serial.setdefault((r["mode"], r["P"]), dict(evals_per_s=0, idle_evals_per_s=0, cpu=[]))
        b["evals_per_s"] = max(b["evals_per_s"], r["evals_per_s"])
        b["idle_evals_per_s"] = max(b["idle_evals_per_s"], r["idle_evals_per_s"])
        b["cpu"].append(r["cpu_us_per_eval"])
for r_mode, s_mode in (("mpi", "serial"), ("threads", "serial"), ("lockstep", "lockserial")):
    for (m_, P) in sorted(serial):
        if P == 1 or m_ != s_mode:
            continue
        runs = [r for r in rows if r["mode"] == r_mode and r["P"] == P]
        if not runs:
            continue
        s = serial[(s_mode, P)]
        m = max(r["evals_per_s"] for r in runs)
        i = max(r["idle_evals_per_s"] for r in runs)
        print(f"{r_mode} P={P} against the same {P} islands in one thread ({s_mode}): measured {m / s['evals_per_s']:.2f},"
              f" idle estimate {i / s['idle_evals_per_s']:.2f}; one thread's CPU {min(s['cpu']):.0f}-{max(s['cpu']):.0f}"
              f" us/eval")
print()
for mode in sorted({r["mode"] for r in rows}):
    best = {}
    for r in rows:
        if r["mode"] != mode:
            continue
        b = best.setdefault(r["P"], dict(evals_per_s=0, idle_evals_per_s=0, loads=[], cpu=[]))
        b["evals_per_s"] = max(b["evals_per_s"], r["evals_per_s"])
        b["idle_evals_per_s"] = max(b["idle_evals_per_s"], r["idle_evals_per_s"])
        b["loads"].append(r["load"])
        b["cpu"].append(r["cpu_us_per_eval"])
    if 1 not in best:
        continue
    for P in sorted(best):
        b, one = best[P], best[1]
        print(f"{mode} P={P}: measured {b['evals_per_s']:.0f} evals/s, ratio {b['evals_per_s'] / one['evals_per_s']:.2f}"
              f" (load {min(b['loads']):.1f}-{max(b['loads']):.1f}); idle estimate {b['idle_evals_per_s']:.0f} evals/s,"
              f" ratio {b['idle_evals_per_s'] / one['idle_evals_per_s']:.2f}; CPU {min(b['cpu']):.0f}-{max(b['cpu']):.0f}"
              f" us/eval")
