#!/usr/bin/python3
"""The Python module's overhead over the C++ it calls (issue 42, item 5). Not a test: it
asserts no time; it prints the figures docs/PERFORMANCE.md records ("The Python module").

  filter step   oasis.Filter.step from /usr/bin/python3 against the same filter's step in C++
                (build/PRESET/tests/oasis-filter-benchmark, Google Benchmark): the Go1 catalog
                in paper mode on the same walk of readings as BM_Go1Step/0, and the hedged
                filter on the paper's discrete example (p_correct 0.7) as BM_HedgedDiscrete.
  bisimulate    load_model + bisimulate(jobs=1) of a planted .aut model of 10^6 transitions
                (oasis-planted, as quotient_benchmark.py makes them) against
                `oasisc quotient MODEL -j 1` end to end; best of --repeat runs each.

    tests/bench/python_overhead_benchmark.py --build build/default [--repeat 5] [--exponent 6]

Run it with Debian's interpreter, as the module is built for it.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))


def cxx_step_ns(build, name):
    """ns per step of one Google Benchmark of oasis-filter-benchmark."""
    done = subprocess.run([os.path.join(build, "tests", "oasis-filter-benchmark"),
                           f"--benchmark_filter=^{name}$", "--benchmark_format=json",
                           "--benchmark_repetitions=5", "--benchmark_report_aggregates_only"],
                          capture_output=True, text=True, check=True)
    for entry in json.loads(done.stdout)["benchmarks"]:
        if entry.get("aggregate_name") == "median":
            scale = {"ns": 1, "us": 1e3, "ms": 1e6}[entry["time_unit"]]
            return entry["real_time"] * scale
    raise SystemExit(f"no median for {name}")


def python_step_ns(step, steps):
    """ns per call of step(t), best of 5 runs of `steps` calls."""
    best = math.inf
    for _ in range(5):
        started = time.perf_counter()
        for t in range(steps):
            step(t)
        best = min(best, (time.perf_counter() - started) / steps)
    return best * 1e9


def go1_readings():
    """BM_Go1Step's walk: two people moving in front of the robot, human 1's reward."""
    import numpy
    readings = []
    for t in range(256):
        phase = 0.05 * t
        reading = numpy.array([0.55 + 0.4 * math.sin(phase), 0.3 * math.cos(1.3 * phase),
                               2.0 + 1.5 * math.sin(0.7 * phase), 1.5 * math.cos(0.4 * phase)])
        reward = float(0.3 <= reading[0] <= 0.8 and abs(reading[1]) <= 0.25)
        readings.append((reading, reward))
    return readings


def filter_figures(build, oasis, scratch):
    catalog = oasis.Catalog.load(os.path.join(SOURCE, "generated", "go1_treat", "go1_treat.bin"))
    go1 = oasis.Filter(catalog, mode="paper", guard=True)
    readings = go1_readings()
    go1.start(readings[0][0])

    def go1_step(t):
        reading, reward = readings[t & 255]
        go1.step(reading, reward, 0)

    discrete = oasis.compile(os.path.join(SOURCE, "specs", "discrete_tracking.oasis"),
                             os.path.join(scratch, "tracking"), robust=0.7, formats=["bin"])
    hedged = oasis.Filter(discrete, mode="hedged")
    hedged.start(0)

    def hedged_step(t):
        hedged.step(t % 3, float(t % 3 == 2), t & 1)

    rows = [("Go1 catalog, paper mode (BM_Go1Step/0)", python_step_ns(go1_step, 200000),
             cxx_step_ns(build, "BM_Go1Step/0")),
            ("discrete example, hedged (BM_HedgedDiscrete)", python_step_ns(hedged_step, 200000),
             cxx_step_ns(build, "BM_HedgedDiscrete"))]
    print("filter step                                      Python ns   C++ ns   difference")
    for name, python_ns, cxx_ns in rows:
        print(f"{name:<48} {python_ns:9.0f} {cxx_ns:8.0f} {python_ns - cxx_ns:9.0f} ns")


PYTHON_QUOTIENT = """
import sys, time
import oasis
started = time.perf_counter()
model = oasis.load_model(sys.argv[1], max_states=100000000)
loaded = time.perf_counter()
result = oasis.bisimulate(model, jobs=1)
print(time.perf_counter() - started, time.perf_counter() - loaded, result.nr_blocks)
"""


def bisimulation_figures(build, exponent, repeat, scratch):
    model = os.path.join(scratch, f"planted_{exponent}.aut")
    transitions = 10 ** exponent
    subprocess.run([os.path.join(build, "tests", "oasis-planted"), "--transitions",
                    str(transitions), "--blocks", str(min(1000, transitions // 8)), "--seed", "1",
                    "-o", model], check=True, capture_output=True)
    oasisc = os.path.join(build, "compiler", "oasisc")
    cli, python, refine, blocks = math.inf, math.inf, math.inf, None
    for _ in range(repeat):
        started = time.perf_counter()
        subprocess.run([oasisc, "quotient", model, "-j", "1", "--progress", "never",
                        "--max-states", "100000000"], check=True, capture_output=True)
        cli = min(cli, time.perf_counter() - started)
        env = {**os.environ, "PYTHONPATH": os.path.join(build, "python")}
        done = subprocess.run(["/usr/bin/python3", "-c", PYTHON_QUOTIENT, model], env=env,
                              check=True, capture_output=True, text=True)
        total, bisimulate, blocks = done.stdout.split()
        python, refine = min(python, float(total)), min(refine, float(bisimulate))
    print(f"\nplanted .aut, {transitions} transitions, {blocks} blocks, best of {repeat}:")
    print(f"  oasisc quotient -j 1 (process, end to end)   {cli:7.3f} s")
    print(f"  load_model + bisimulate(jobs=1) from Python  {python:7.3f} s "
          f"({100 * (python - cli) / cli:+.1f} %; bisimulate alone {refine:.3f} s)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(SOURCE, "build", "default"))
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--exponent", type=int, default=6, help="10^E transitions")
    args = parser.parse_args()
    sys.path.insert(0, os.path.join(args.build, "python"))
    import oasis
    with tempfile.TemporaryDirectory() as scratch:
        filter_figures(args.build, oasis, scratch)
        bisimulation_figures(args.build, args.exponent, args.repeat, scratch)
    return 0


if __name__ == "__main__":
    sys.exit(main())
