#!/usr/bin/env python3
"""Bisimulation benchmark: planted-structure .aut models (oasis-planted) at 10^4, 10^5,
10^6 and 10^7 action transitions (4 actions, 3 probabilistic edges each), each run end to end
as `oasisc quotient IN.aut --format aut -o OUT.aut -j 1`: read, refine, write the quotient.
Checks that the block count equals the planted one, and prints seconds, peak RSS, blocks and
time / (m log2 n) so growth can be compared with m log n.

    tests/bench/quotient_benchmark.py --build build/default [--sizes 4,5,6,7] [--blocks 1000]
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile
import time


def run_timed(command):
    probe = ("import resource,subprocess,sys,time;t=time.perf_counter();"
             "r=subprocess.run(sys.argv[1:],capture_output=True,text=True);e=time.perf_counter()-t;"
             "print(r.returncode,e,resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss);"
             "print(r.stdout);sys.stderr.write(r.stderr)")
    result = subprocess.run([sys.executable, "-c", probe] + command, capture_output=True, text=True)
    first, _, rest = result.stdout.partition("\n")
    status, seconds, rss_kb = first.split()
    if status != "0":
        raise SystemExit(f"failed: {' '.join(command)}\n{rest}\n{result.stderr}")
    return float(seconds), int(rss_kb) / 1024, rest


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build/default")
    parser.add_argument("--sizes", default="4,5,6,7", help="exponents of 10 (action transitions)")
    parser.add_argument("--blocks", type=int, default=1000)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    oasisc = os.path.join(args.build, "compiler", "oasisc")
    planted = os.path.join(args.build, "tests", "oasis-planted")
    print(f"# quotient benchmark (planted .aut), {os.cpu_count()} cores, {time.strftime('%Y-%m-%d')}, "
          f"-j 1, {args.blocks} planted blocks")
    print(f"{'transitions':>12} {'states':>10} {'edges':>10} {'planted':>8} {'blocks':>8} "
          f"{'gen s':>7} {'total s':>8} {'peak MiB':>9} {'ns/(m log n)':>13}")
    with tempfile.TemporaryDirectory() as directory:
        for exponent in (int(e) for e in args.sizes.split(",")):
            transitions = 10 ** exponent
            source = os.path.join(directory, f"planted_{exponent}.aut")
            target = os.path.join(directory, f"quotient_{exponent}.aut")
            started = time.perf_counter()
            generated = subprocess.run([planted, "--transitions", str(transitions), "--blocks",
                                        str(min(args.blocks, transitions // 8)), "--seed",
                                        str(args.seed), "-o", source],
                                       capture_output=True, text=True, check=True)
            generate_seconds = time.perf_counter() - started
            expected = int(generated.stdout.strip())
            seconds, peak, output = run_timed([oasisc, "quotient", source, "--format", "aut", "-o",
                                               target, "-j", "1", "--progress", "never",
                                               "--max-states", "100000000"])
            match = re.search(r"^\s+default\s+(\d+)\s+(\d+)\s+(\d+)", output, re.M)
            states, edges, blocks = (int(g) for g in match.groups())
            per = seconds / (transitions * math.log2(max(states, 2))) * 1e9
            print(f"{transitions:>12} {states:>10} {edges:>10} {expected:>8} {blocks:>8} "
                  f"{generate_seconds:>7.1f} {seconds:>8.2f} {peak:>9.0f} {per:>13.2f}")
            if blocks != expected:
                raise SystemExit(f"block count {blocks} differs from the planted {expected}")
            os.remove(source)
            os.remove(target)
    return 0


if __name__ == "__main__":
    sys.exit(main())
