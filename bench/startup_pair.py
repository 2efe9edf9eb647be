#!/usr/bin/env python3
"""Start-up of two sim_node binaries against each other (docs/benchmarks.md, "Start-up").

  bench/startup_pair.py BEFORE AFTER [--duration S] [--runs N] [--scene FILE]

Runs `B --scene FILE --mode offline --duration S` for both binaries, alternated run by run
(the order swapped every pair, so both see the same machine load), output to /dev/null, and
prints the child's CPU time (user + system, from wait4) of each: minimum, first quartile and
median over N runs. Defaults: Case 1, --duration 0 (everything but the steps), 300 runs.
"""
import argparse
import os
import statistics


def cpu_ms(argv):
    pid = os.posix_spawn(argv[0], argv, os.environ,
                         file_actions=[(os.POSIX_SPAWN_OPEN, 1, os.devnull, os.O_WRONLY, 0)])
    _, status, usage = os.wait4(pid, 0)
    if status != 0:
        raise SystemExit(f"{' '.join(argv)}: exit status {status}")
    return (usage.ru_utime + usage.ru_stime) * 1e3


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("before")
    p.add_argument("after")
    p.add_argument("--duration", default="0")
    p.add_argument("--runs", type=int, default=300)
    p.add_argument("--scene", default=os.path.join(root, "config/scenes/case1_forward.yaml"))
    a = p.parse_args()
    binaries = [("before", a.before), ("after", a.after)]
    times = {name: [] for name, _ in binaries}
    for i in range(a.runs):
        for name, binary in (binaries if i % 2 == 0 else binaries[::-1]):
            times[name].append(cpu_ms([binary, "--scene", a.scene, "--mode", "offline",
                                       "--duration", a.duration]))
    for name, _ in binaries:
        t = sorted(times[name])
        print(f"{name:6s} --duration {a.duration}: CPU min {t[0]:.3f} ms, p25 {t[len(t) // 4]:.3f} ms, "
              f"median {statistics.median(t):.3f} ms ({a.runs} runs)")


if __name__ == "__main__":
    main()
