#!/usr/bin/env python3
"""Times reading and writing mCRL2 .aut files: `oasisc export IN.aut --format aut -o OUT.aut`
reads, checks and writes a random MDP with S states, 4 actions and 3 probabilistic targets
per action (1/2, 1/4 and the remaining 1/4). Sizes: 10^5 and 10^6 action transitions
(10^7 with --large, ~480 MB of text). Prints seconds and peak RSS per size.

    tests/bench/aut_io_benchmark.py --oasisc build/default/compiler/oasisc [--large]
"""
import argparse
import os
import random
import sys
import tempfile
import time

from timed_run import run_timed

ACTIONS = ["a", "b", "c", "d"]


def write_model(path, transitions, seed=1):
    states = transitions // len(ACTIONS)
    rng = random.Random(seed)
    with open(path, "w", encoding="ascii", buffering=1 << 22) as out:
        out.write(f"des (0,{transitions},{states})\n")
        lines = []
        for s in range(states):
            for action in ACTIONS:
                t = rng.randrange(states), rng.randrange(states), rng.randrange(states)
                lines.append(f'({s},"{action}",{t[0]} 1/2 {t[1]} 1/4 {t[2]})\n')
            if len(lines) >= 65536:
                out.writelines(lines)
                lines.clear()
        out.writelines(lines)


def measure(oasisc, source, target):
    seconds, peak_mib, _ = run_timed([oasisc, "export", source, "--format", "aut", "-o", target,
                                      "--progress", "never", "--max-states", "100000000"])
    return seconds, peak_mib


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--oasisc", required=True)
    parser.add_argument("--large", action="store_true")
    parser.add_argument("--smoke", action="store_true", help="10^4 transitions only (ctest)")
    args = parser.parse_args()
    sizes = [10**4] if args.smoke else [10**5, 10**6] + ([10**7] if args.large else [])
    print(f"# .aut read+write benchmark, {os.cpu_count()} cores, {time.strftime('%Y-%m-%d')}")
    print(f"{'transitions':>12} {'MB':>8} {'seconds':>9} {'peak MiB':>9}")
    with tempfile.TemporaryDirectory() as directory:
        for size in sizes:
            source = os.path.join(directory, f"in_{size}.aut")
            target = os.path.join(directory, f"out_{size}.aut")
            write_model(source, size)
            megabytes = os.path.getsize(source) / 1e6
            seconds, peak = measure(args.oasisc, source, target)
            if os.path.getsize(target) == 0:
                raise SystemExit("empty output")
            print(f"{size:>12} {megabytes:>8.1f} {seconds:>9.3f} {peak:>9.1f}")
            os.remove(source)
            os.remove(target)
    return 0


if __name__ == "__main__":
    sys.exit(main())
