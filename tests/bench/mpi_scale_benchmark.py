#!/usr/bin/env python3
"""Scale of the distributed engine: planted .aut models (oasis-planted, the quotient
benchmark's family) of 10^k action transitions, each run once by the sequential engine
(`oasisc quotient -j 1`) and by `mpirun -np P oasisc-mpi` for each P given. Prints wall-clock
seconds, the MPI engine's read and refinement seconds and rounds, and peak memory: the
sequential engine's, and the largest rank's (each rank measures its own getrusage peak and
rank 0 writes them all to the JSON). Fails when a block count differs from the planted one.

Then fits the per-rank memory model  M(P) = fixed + per_edge * edges / P + per_state * states
(the last term: a rank keeps the blocks of every state its edges lead to, which in a random
model with several edges per state is nearly every state) to the points by least squares and
prints it, with its prediction for a larger model on more machines.

    tests/bench/mpi_scale_benchmark.py --build build/default [--sizes 7] [--ranks 1,2,4]
        [--predict-transitions 1e9 --predict-ranks 16]

On one machine the ranks share its cores, so times show the cost of the exchange, not a
speed-up; memory per rank is what P divides.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

from timed_run import run_timed

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "mpi"))
from mpi_run import mpi_environment  # noqa: E402


def planted(build, directory, exponent):
    path = os.path.join(directory, f"planted{exponent}.aut")
    if not os.path.exists(path):
        result = subprocess.run([os.path.join(build, "tests", "oasis-planted"), "--transitions",
                                 str(10 ** exponent), "--blocks", "1000", "--seed", "1", "-o", path],
                                capture_output=True, text=True, check=True)
        with open(path + ".blocks", "w") as out:
            out.write(result.stdout.strip())
    with open(path + ".blocks") as blocks:
        return path, int(blocks.read())


def run_mpi(build, model, ranks, output):
    command = ["mpirun", "-np", str(ranks), "--oversubscribe",
               os.path.join(build, "compiler", "oasisc-mpi"), "quotient", model, "-q", "--max-states", "40000000",
               "-o", output]
    start = time.perf_counter()
    result = subprocess.run(command, capture_output=True, text=True, env=mpi_environment())
    wall = time.perf_counter() - start
    if result.returncode != 0:
        raise SystemExit(f"failed: {' '.join(command)}\n{result.stdout}{result.stderr}")
    with open(output) as file:
        document = json.load(file)
    os.remove(output)
    return wall, document


def fit(points):
    """Least squares for M = a + b * x + c * y over points (x, y, M)."""
    sums = [[0.0] * 4 for _ in range(3)]
    for x, y, m in points:
        row = (1.0, x, y)
        for i in range(3):
            for j in range(3):
                sums[i][j] += row[i] * row[j]
            sums[i][3] += row[i] * m
    for i in range(3):  # Gauss-Jordan on the 3 x 4 system
        pivot = max(range(i, 3), key=lambda r: abs(sums[r][i]))
        sums[i], sums[pivot] = sums[pivot], sums[i]
        for r in range(3):
            if r != i and sums[i][i] != 0:
                factor = sums[r][i] / sums[i][i]
                sums[r] = [a - factor * b for a, b in zip(sums[r], sums[i])]
    return [sums[i][3] / sums[i][i] if sums[i][i] else 0.0 for i in range(3)]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", required=True)
    parser.add_argument("--sizes", default="7", help="exponents: 6,7,8")
    parser.add_argument("--ranks", default="1,2,4")
    parser.add_argument("--no-sequential", action="store_true")
    parser.add_argument("--predict-transitions", type=float, default=1e9)
    parser.add_argument("--predict-ranks", type=int, default=16)
    args = parser.parse_args()
    directory = tempfile.mkdtemp(prefix="oasis-mpi-scale-")
    try:
        ok, points = measure(args, directory)
    finally:
        shutil.rmtree(directory)  # a 10^8 model is 5.3 GB
    if len(points) >= 3:
        print_model(args, points)
    sys.exit(0 if ok else 1)


def measure(args, directory):
    points = []
    print(f"{'model':>10} {'engine':>10} {'P':>3} {'wall s':>8} {'read s':>8} {'refine s':>9} "
          f"{'rounds':>6} {'blocks':>7} {'peak MiB':>9} {'x seq':>6}")
    ok = True
    for exponent in (int(e) for e in args.sizes.split(",")):
        model, expected = planted(args.build, directory, exponent)
        sequential_peak = None
        if not args.no_sequential:
            seconds, peak, output = run_timed([os.path.join(args.build, "compiler", "oasisc"), "quotient",
                                               model, "--format", "aut", "-j", "1", "--max-states", "40000000",
                                               "-o", os.path.join(directory, "quotient.aut")])
            sequential_peak = peak
            print(f"{'10^%d' % exponent:>10} {'sequential':>10} {1:>3} {seconds:8.2f} {'':>8} {'':>9} "
                  f"{'':>6} {'':>7} {peak:9.1f} {1.0:6.2f}")
        for ranks in (int(p) for p in args.ranks.split(",")):
            wall, document = run_mpi(args.build, model, ranks, os.path.join(directory, "partition.json"))
            context = document["contexts"][0]
            peak = max(document["peak_memory_mib_per_rank"])
            ratio = f"{peak / sequential_peak:6.2f}" if sequential_peak else f"{'':>6}"
            print(f"{'10^%d' % exponent:>10} {'mpi':>10} {ranks:>3} {wall:8.2f} {document['load_seconds']:8.2f} "
                  f"{context['seconds']:9.2f} {context['rounds']:>6} {context['blocks']:>7} {peak:9.1f} {ratio}")
            points.append((context["transitions"] / ranks, context["states"], peak))
            if context["blocks"] != expected:
                print(f"  wrong: {context['blocks']} blocks, planted {expected}")
                ok = False
        os.remove(model)
    return ok, points


def print_model(args, points):
    fixed, per_edge, per_state = fit(points)
    print(f"\nper-rank peak (MiB) = {fixed:.1f} + {per_edge * 2**20:.2f} B x edges/P "
          f"+ {per_state * 2**20:.2f} B x states")
    for edges_per_rank, states, measured in points:
        model_value = fixed + per_edge * edges_per_rank + per_state * states
        print(f"  edges/P {edges_per_rank:12.0f}  states {states:10d}: measured {measured:8.1f}, model {model_value:8.1f}")
    # planted models: 3 edges per transition, 4 transitions per state
    edges = 3 * args.predict_transitions
    states = args.predict_transitions / 4
    predicted = fixed + per_edge * edges / args.predict_ranks + per_state * states
    print(f"predicted for {args.predict_transitions:.0e} transitions ({edges:.0e} edges, {states:.1e} states) "
          f"on {args.predict_ranks} ranks: {predicted / 1024:.1f} GiB per rank")


if __name__ == "__main__":
    main()
