#!/usr/bin/env python3
"""Bisimulation benchmark at 10^4, 10^5, 10^6 and 10^7 action transitions, single core, each
run end to end with `oasisc quotient ... -j 1`. Four families, each with a known answer:

  planted  random .aut models from oasis-planted (4 actions, 3 probabilistic edges each) whose
           coarsest bisimulation the generator computes independently; read, refine, write.
           1000 planted blocks (--blocks).
  many     the same generator with many blocks: one per 10 states (250,000 at 10^7) and 2 to
           4 probabilistic edges per action, so that what grows with the block count shows.
  grid     a factored N x N slippery grid (4 actions) rewarded on its last column: y is
           irrelevant, so the answer is N blocks (attention: forget y). Explore and refine.
  queue    two symmetric bounded queues (1 action, 4 outcomes), reward q1 + q2: mirrored
           states merge, so the answer is (N+1)(N+2)/2 blocks. Explore and refine.

Prints seconds, peak RSS, blocks and time / (m log2 n) so growth can be compared with m log n;
fails when a block count differs from the known answer.

    tests/bench/quotient_benchmark.py --build build/default [--family all] [--sizes 4,5,6,7]

`--family planted --sizes 8` is the 10^8-transition run: a 5.3 GB file in the temporary
directory, about 6 GiB of memory and 5 minutes on one core.
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile
import time

from timed_run import run_timed


GRID = """mdp grid {{
  const N = {side};
  var x : [0 .. N-1];
  var y : [0 .. N-1];
  actions left, right, up, down;
  default self;
  [left]  x > 0     -> 0.9: (x' = x - 1) + 0.1: true;
  [right] x < N - 1 -> 0.9: (x' = x + 1) + 0.1: true;
  [down]  y > 0     -> 0.9: (y' = y - 1) + 0.1: true;
  [up]    y < N - 1 -> 0.9: (y' = y + 1) + 0.1: true;
  reward x == N - 1 : 1;
}}
"""

QUEUE = """mdp queues {{
  const N = {side};
  var q1 : [0 .. N];
  var q2 : [0 .. N];
  actions tick;
  [tick] true -> 1/4: (q1' = min(q1 + 1, N)) + 1/4: (q2' = min(q2 + 1, N))
              + 1/4: (q1' = max(q1 - 1, 0)) + 1/4: (q2' = max(q2 - 1, 0));
  reward true : q1 + q2;
}}
"""


def summary_figures(output):
    match = re.search(r"^\s+default\s+(\d+)\s+(\d+)\s+(\d+)", output, re.M)
    return tuple(int(g) for g in match.groups())


def report(family, transitions, states, edges, expected, blocks, prepare, seconds, peak):
    per = seconds / (transitions * math.log2(max(states, 2))) * 1e9
    print(f"{family:>8} {transitions:>12} {states:>10} {edges:>10} {expected:>8} {blocks:>8} "
          f"{prepare:>7.1f} {seconds:>8.2f} {peak:>9.0f} {per:>13.2f}")
    if blocks != expected:
        raise SystemExit(f"{family}: block count {blocks} differs from the known {expected}")


def run_planted(args, oasisc, planted, directory, exponent, many_blocks):
    transitions = 10 ** exponent
    family = "many" if many_blocks else "planted"
    source = os.path.join(directory, f"{family}_{exponent}.aut")
    target = os.path.join(directory, f"quotient_{exponent}.aut")
    if many_blocks:
        shape = ["--blocks", str(max(4, transitions // 40)), "--targets", "2-4"]
    else:
        shape = ["--blocks", str(min(args.blocks, transitions // 8))]
    started = time.perf_counter()
    generated = subprocess.run([planted, "--transitions", str(transitions)] + shape +
                               ["--seed", str(args.seed), "-o", source],
                               capture_output=True, text=True, check=True)
    prepare = time.perf_counter() - started
    seconds, peak, output = run_timed([oasisc, "quotient", source, "--format", "aut", "-o",
                                       target, "-j", "1", "--progress", "never",
                                       "--max-states", "100000000"])
    states, edges, blocks = summary_figures(output)
    report(family, transitions, states, edges, int(generated.stdout.strip()), blocks, prepare,
           seconds, peak)
    os.remove(source)
    os.remove(target)


def run_factored(family, oasisc, directory, exponent):
    transitions = 10 ** exponent
    if family == "grid":
        side = max(2, round(math.sqrt(transitions / 4)))
        text, expected = GRID.format(side=side), side
    else:
        side = max(1, round(math.sqrt(transitions)) - 1)
        text, expected = QUEUE.format(side=side), (side + 1) * (side + 2) // 2
    path = os.path.join(directory, f"{family}_{exponent}.oasis")
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(text)
    seconds, peak, output = run_timed([oasisc, "quotient", path, "-j", "1", "--progress", "never",
                                       "--max-states", "100000000"])
    states, edges, blocks = summary_figures(output)
    actions = 4 if family == "grid" else 1
    report(family, states * actions, states, edges, expected, blocks, 0.0, seconds, peak)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build/default")
    parser.add_argument("--family", default="all",
                        choices=["all", "planted", "many", "grid", "queue"])
    parser.add_argument("--sizes", default="4,5,6,7", help="exponents of 10 (action transitions)")
    parser.add_argument("--blocks", type=int, default=1000, help="planted blocks")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    oasisc = os.path.join(args.build, "compiler", "oasisc")
    planted = os.path.join(args.build, "tests", "oasis-planted")
    families = ["planted", "many", "grid", "queue"] if args.family == "all" else [args.family]
    print(f"# quotient benchmark, {os.cpu_count()} cores, {time.strftime('%Y-%m-%d')}, -j 1, "
          f"planted: {args.blocks} blocks, many: one block per 10 states")
    print(f"{'family':>8} {'transitions':>12} {'states':>10} {'edges':>10} {'known':>8} "
          f"{'blocks':>8} {'prep s':>7} {'total s':>8} {'peak MiB':>9} {'ns/(m log n)':>13}")
    with tempfile.TemporaryDirectory() as directory:
        for family in families:
            for exponent in (int(e) for e in args.sizes.split(",")):
                if family in ("planted", "many"):
                    run_planted(args, oasisc, planted, directory, exponent, family == "many")
                else:
                    run_factored(family, oasisc, directory, exponent)
    return 0


if __name__ == "__main__":
    sys.exit(main())
