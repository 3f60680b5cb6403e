#!/usr/bin/env python3
"""Times the crowds protocol's cases of issue 39, item 8: exploration, the bisimulation step
alone, and the property on the quotient, with each run's peak memory. Prints the figures;
they belong in docs/PERFORMANCE.md ("Properties").

    tests/bench/crowds_benchmark.py --oasisc build/default/compiler/oasisc [--runs 3]
                                    [--cases crowds10-10,stormpy5-5,crowds5-20,exact]

Cases (programs written by crowds_program.py, beside this file):

  crowds10-10  Storm's pull request 1049 ("New Sparse Bisimulation"): the PRISM suite's crowds
               model, CrowdSize=10, TotalRuns=10, built as Storm builds it for
               P=? [F "observe0Greater1"] (exploration stops at the targets): published
               10,647,781 states and 25,622,741 transitions, a quotient of 181 states and 271
               transitions respecting the property's label. Storm: 0.896 s new, 2.046 s old
               (its author's machine).
  stormpy5-5   stormpy's bisimulation test: Storm's crowds5_5 (phases), built for the same
               property: 7,403 states and 13,041 transitions; 64 states and 104 transitions
               (Storm's sparse bisimulation for the formula, which lumps the states of
               probability 1 with the targets: our label observe0Greater1_surely), 65 and 105
               respecting the label alone (its symbolic bisimulation).
  crowds5-20   a P=? in sound mode on 2,061,951 states (the suite's CrowdSize=20,
               TotalRuns=5, whole model, as the suite's log), against the exact value Storm
               printed for it (tquatmann/umb-benchmarking, storm --exact).
  exact        what exact mode does without a quotient on the large crowds: the 10-10 model,
               and 5-20 (given a time bound: --exact-timeout).
  csma3-4      Storm's other case of pull request 1049: tests/data/prism/csma3.nm, K=4: the
               PRISM suite's 1,460,287 states, 1,471,059 choices, 2,396,727 transitions;
               Storm's quotient 30,422 states, 30,870 choices, 64,996 transitions (1.021 s
               new, 14.421 s old). Storm's MDP semantics (--choices unlabelled), respecting the
               three labels of the suite's csma3_4.nm (all_delivered, one_delivered,
               collision_max_backoff); the quotient's choices and transitions are counted here
               from the partition and the exported model (a block's distinct distributions
               over blocks), since the .aut writer needs labelled choices.

The bisimulation step alone is the context's `seconds` of `oasisc quotient --format json -j 1`
(refinement and the quotient's construction; its phases: initial partition, reverse edges,
splitting), the exploration is `oasisc info`, and the property on the quotient is
`oasisc query --bisimulation` less the exploration (the query prints no phases of its own:
the difference is labels, quotient and solve). --smoke runs the stormpy case only (for ctest).
"""
import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from crowds_program import program  # noqa: E402
from timed_run import run_timed  # noqa: E402

PROPERTY = 'P=? [F "observe0Greater1"]'
# Storm 1.11.1 (dev), storm --buildfull --prism crowds.5-20 --exact, P=? [F "target"] (target:
# observe0 > 1), 2061951 states, 7374951 transitions:
# https://github.com/tquatmann/umb-benchmarking/blob/57aa696332950d4104d1164457ad134bcc92d4eb/storm_import_time/logs/crowds.5-20_storm_from-prism_check_exact.md
STORM_CROWDS_5_20 = Fraction(317474548144042278373095748974301,
                             3688602718160800000000000000000000)


def write(directory, name, crowd_size, structure, stop):
    path = os.path.join(directory, name)
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(program(crowd_size, structure, stop))
    return path


def info(oasisc, path, runs):
    """Exploration alone (`oasisc info`), median of runs."""
    results = []
    for _ in range(runs):
        seconds, peak, output = run_timed([oasisc, "info", "--json", "--progress", "never",
                                           "--max-states", "40000000", path, *runs_const(path)])
        data = json.loads(output)
        results.append((seconds, peak, data["states"], data["contexts"][0]["transitions"]))
    return (statistics.median(r[0] for r in results), statistics.median(r[1] for r in results),
            results[0][2], results[0][3])


CONSTANTS = {}


def runs_const(path):
    return ["--const", CONSTANTS[path]]


def quotient(oasisc, path, labels, runs, directory):
    """The bisimulation step: the context's seconds and phases from the JSON, median of runs;
    then the quotient's size from its .aut (`oasisc info`)."""
    rows = []
    for _ in range(runs):
        wall, peak, output = run_timed([oasisc, "quotient", path, *runs_const(path), "--format",
                                        "json", "-j", "1", "--progress", "never",
                                        "--max-states", "40000000", "--respect-labels", labels])
        data = json.loads(output)
        context = data["contexts"][0]
        rows.append({"wall": wall, "peak": peak, "seconds": context["seconds"],
                     "phases": context.get("phase_seconds", {}), "blocks": context["blocks"],
                     "load": data.get("load_seconds")})
    aut = os.path.join(directory, "quotient.aut")
    subprocess.run([oasisc, "quotient", path, *runs_const(path), "--format", "aut", "-o", aut,
                    "-j", "1", "--progress", "never", "--max-states", "40000000",
                    "--respect-labels", labels], check=True, capture_output=True)
    data = json.loads(subprocess.run([oasisc, "info", "--json", aut], check=True,
                                     capture_output=True, text=True).stdout)
    median = statistics.median
    phases = {name: median(r["phases"].get(name, 0.0) for r in rows) for name in rows[0]["phases"]}
    return {"seconds": median(r["seconds"] for r in rows),
            "seconds_range": (min(r["seconds"] for r in rows), max(r["seconds"] for r in rows)),
            "phases": phases, "blocks": rows[0]["blocks"],
            "quotient_transitions": data["contexts"][0]["transitions"],
            "wall": median(r["wall"] for r in rows), "peak": median(r["peak"] for r in rows),
            "load": median(r["load"] for r in rows if r["load"] is not None)}


def query(oasisc, path, mode, bisimulation, timeout=None, extra=()):
    command = [oasisc, "query", path, *runs_const(path), "--prop", PROPERTY, "--mode", mode,
               "--progress", "never", "--max-states", "40000000", *extra]
    if bisimulation:
        command.append("--bisimulation")
    if timeout is None:
        seconds, peak, output = run_timed(command)
        return seconds, peak, output.strip()
    probe = ("import resource,subprocess,sys,time;t=time.perf_counter();"
             "r=subprocess.run(sys.argv[2:],capture_output=True,text=True,timeout=float(sys.argv[1]));"
             "print(r.returncode,time.perf_counter()-t,"
             "resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss);"
             "print((r.stdout+r.stderr).strip())")
    try:
        done = subprocess.run([sys.executable, "-c", probe, str(timeout), *command],
                              capture_output=True, text=True, timeout=timeout + 60)
    except subprocess.TimeoutExpired:
        return timeout, float("nan"), f"no answer within {timeout:.0f} s"
    first, _, rest = done.stdout.partition("\n")
    if not first:
        return timeout, float("nan"), f"no answer within {timeout:.0f} s (stopped)"
    status, seconds, rss = first.split()
    return float(seconds), int(rss) / 1024, f"(exit {status}) {rest.strip()}"


def show_quotient(name, q, published):
    print(f"  bisimulation ({name}): {q['blocks']} blocks, {q['quotient_transitions']} transitions "
          f"(published {published}); step {q['seconds']:.4f} s (runs {q['seconds_range'][0]:.4f}"
          f" to {q['seconds_range'][1]:.4f}); phases " +
          ", ".join(f"{k} {v:.4f}" for k, v in sorted(q["phases"].items())) +
          f"; whole process {q['wall']:.2f} s (exploration {q['load']:.2f} s), peak {q['peak']:.0f} MiB")


def case_crowds10(oasisc, directory, runs):
    path = write(directory, "crowds10_stop.pm", 10, "suite", True)
    CONSTANTS[path] = "TotalRuns=10"
    print("crowds10-10 (suite structure, CrowdSize=10, TotalRuns=10, stopped at the targets)")
    seconds, peak, states, transitions = info(oasisc, path, runs)
    print(f"  exploration: {states} states, {transitions} transitions (published 10647781, "
          f"25622741); {seconds:.2f} s, peak {peak:.0f} MiB")
    q = quotient(oasisc, path, "observe0Greater1", runs, directory)
    show_quotient("observe0Greater1", q, "181, 271")
    for mode in ("exact", "sound"):
        wall, qpeak, answer = query(oasisc, path, mode, True)
        print(f"  query --bisimulation --mode {mode}: {wall:.2f} s whole, {wall - seconds:.2f} s "
              f"past exploration, peak {qpeak:.0f} MiB\n    {answer}")
    wall, qpeak, answer = query(oasisc, path, "sound", False)
    print(f"  query --mode sound (no quotient): {wall:.2f} s whole, peak {qpeak:.0f} MiB\n    {answer}")


def case_stormpy(oasisc, directory, runs):
    path = write(directory, "crowds5_stop.pm", 5, "phases", True)
    CONSTANTS[path] = "TotalRuns=5"
    print("stormpy crowds5_5 (phases, CrowdSize=5, TotalRuns=5, stopped at the targets)")
    seconds, peak, states, transitions = info(oasisc, path, runs)
    print(f"  exploration: {states} states, {transitions} transitions (published 7403, 13041); "
          f"{seconds:.3f} s, peak {peak:.0f} MiB")
    ok = (states, transitions) == (7403, 13041)
    for labels, published in (("observe0Greater1_surely", (64, 104)),
                              ("observe0Greater1", (65, 105))):
        q = quotient(oasisc, path, labels, runs, directory)
        show_quotient(labels, q, f"{published[0]}, {published[1]}")
        ok = ok and (q["blocks"], q["quotient_transitions"]) == published
    wall, qpeak, answer = query(oasisc, path, "exact", True)
    print(f"  query --bisimulation --mode exact: {wall:.3f} s, peak {qpeak:.0f} MiB\n    {answer}")
    return ok


def case_crowds5_20(oasisc, directory, runs):
    path = write(directory, "crowds20.pm", 20, "suite", False)
    CONSTANTS[path] = "TotalRuns=5"
    print("crowds5-20 (suite structure, CrowdSize=20, TotalRuns=5, whole model)")
    seconds, peak, states, transitions = info(oasisc, path, runs)
    print(f"  exploration: {states} states, {transitions} transitions (published 2061951, "
          f"7374951); {seconds:.2f} s, peak {peak:.0f} MiB")
    wall, qpeak, answer = query(oasisc, path, "sound", False)
    print(f"  query --mode sound: {wall:.2f} s whole, {wall - seconds:.2f} s past exploration, "
          f"peak {qpeak:.0f} MiB\n    {answer}")
    print(f"    Storm --exact: {STORM_CROWDS_5_20} (about {float(STORM_CROWDS_5_20):.12f})")
    try:
        interval = answer.split(" in [", 1)[1].split("]", 1)[0].split(", ")
        low, high = Fraction(float(interval[0])), Fraction(float(interval[1]))
        print(f"    Storm's exact value {'lies' if low <= STORM_CROWDS_5_20 <= high else 'DOES NOT lie'}"
              f" in our interval (width {float(high - low):.2e})")
    except (IndexError, ValueError):
        print("    (no interval to compare)")
    wall, qpeak, answer = query(oasisc, path, "exact", True)
    print(f"  query --bisimulation --mode exact: {wall:.2f} s, peak {qpeak:.0f} MiB\n    {answer}")


def case_exact(oasisc, directory, timeout):
    print(f"exact mode without a quotient (bound {timeout:.0f} s per run)")
    for name, n, structure, stop, runs_total in (("crowds5-20", 20, "suite", False, 5),
                                                 ("crowds10-10", 10, "suite", True, 10)):
        path = write(directory, f"exact_{name}.pm", n, structure, stop)
        CONSTANTS[path] = f"TotalRuns={runs_total}"
        wall, peak, answer = query(oasisc, path, "exact", False, timeout)
        print(f"  {name}: {wall:.1f} s, peak {peak:.0f} MiB\n    {answer[:400]}")


def quotient_mdp_size(partition_json, base):
    """Choices and transitions of an unlabelled MDP quotient: for each block, the distinct
    distributions over blocks of its first state's choices (the partition is stable, so any
    state of the block has the same set). base: `oasisc export --format prism` output."""
    index = {}
    with open(base + ".sta", encoding="utf-8") as stream:
        next(stream)
        for line in stream:
            number, _, values = line.rstrip("\n").partition(":")
            index[values] = int(number)

    def state_number(text):  # "(a=1,b=2)" -> the .sta line "(1,2)"
        return index["(" + ",".join(part.split("=", 1)[1] for part in text.strip("()").split(",")) + ")"]

    with open(partition_json, encoding="utf-8") as stream:
        blocks = json.load(stream)["contexts"][0]["partition"]
    block_of = {}
    first = set()
    for number, states in enumerate(blocks):
        for state in states:
            block_of[state_number(state)] = number
        first.add(state_number(states[0]))
    choices = {}
    with open(base + ".tra", encoding="utf-8") as stream:
        next(stream)
        for line in stream:
            fields = line.split()
            source = int(fields[0])
            if source in first:
                target = block_of[int(fields[2])]
                distribution = choices.setdefault(source, {}).setdefault(int(fields[1]), {})
                distribution[target] = distribution.get(target, 0) + Fraction(fields[3])
    distinct = [set(tuple(sorted(d.items())) for d in by_choice.values())
                for by_choice in choices.values()]
    return (len(blocks), sum(len(d) for d in distinct),
            sum(len(x) for d in distinct for x in d))


def case_csma(oasisc, directory, runs):
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "prism", "csma3.nm")
    path = os.path.normpath(path)
    CONSTANTS[path] = "K=4"
    print("csma3-4 (tests/data/prism/csma3.nm, K=4; Storm's MDP semantics: --choices unlabelled)")
    seconds, peak, states, transitions = info(oasisc, path, runs)
    print(f"  exploration: {states} states, {transitions} transitions (published 1460287, "
          f"2396727); {seconds:.2f} s, peak {peak:.0f} MiB")
    rows = []
    for labels in ("all_delivered,one_delivered,collision_max_backoff",
                   "all_delivered,collision_max_backoff"):
        times = []
        for _ in range(runs):
            wall, qpeak, output = run_timed([oasisc, "quotient", path, *runs_const(path),
                                             "--choices", "unlabelled", "--respect-labels", labels,
                                             "--format", "json", "-j", "1", "--progress", "never"])
            context = json.loads(output)["contexts"][0]
            times.append((context["seconds"], context.get("phase_seconds", {}), wall, qpeak,
                          context["blocks"]))
        rows.append((labels, times))
        if labels.count(",") == 2:
            partition = os.path.join(directory, "csma_partition.json")
            subprocess.run([oasisc, "quotient", path, *runs_const(path), "--choices", "unlabelled",
                            "--respect-labels", labels, "--format", "json", "-j", "1",
                            "--progress", "never", "--partition", "-o", partition],
                           check=True, capture_output=True)
            base = os.path.join(directory, "csma34")
            subprocess.run([oasisc, "export", path, *runs_const(path), "--format", "prism", "-o",
                            base, "--progress", "never"], check=True, capture_output=True)
            size = quotient_mdp_size(partition, base)
            print(f"  quotient respecting {labels}: {size[0]} states, {size[1]} choices, "
                  f"{size[2]} transitions (published 30422, 30870, 64996)")
    for labels, times in rows:
        median = statistics.median
        print(f"  bisimulation ({labels}): {times[0][4]} blocks; step "
              f"{median(t[0] for t in times):.2f} s (runs {min(t[0] for t in times):.2f} to "
              f"{max(t[0] for t in times):.2f}); splitting "
              f"{median(t[1].get('splitting', 0.0) for t in times):.2f} s; whole process "
              f"{median(t[2] for t in times):.2f} s, peak {median(t[3] for t in times):.0f} MiB")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--oasisc", required=True)
    parser.add_argument("--runs", type=int, default=3, help="runs per timed step (median)")
    parser.add_argument("--cases", default="crowds10-10,stormpy5-5,crowds5-20",
                        help="comma-separated: crowds10-10, stormpy5-5, crowds5-20, exact, csma3-4")
    parser.add_argument("--exact-timeout", type=float, default=600.0)
    parser.add_argument("--smoke", action="store_true", help="the stormpy case once (for ctest)")
    args = parser.parse_args()
    cases = ["stormpy5-5"] if args.smoke else [c for c in args.cases.split(",") if c]
    runs = 1 if args.smoke else max(1, args.runs)
    print(f"# crowds benchmark, {platform.node()}, {os.cpu_count()} cores, "
          f"{time.strftime('%Y-%m-%d')}, {runs} run(s) per step")
    ok = True
    with tempfile.TemporaryDirectory(prefix="crowds_benchmark.") as directory:
        for case in cases:
            if case == "crowds10-10":
                case_crowds10(args.oasisc, directory, runs)
            elif case == "stormpy5-5":
                ok = case_stormpy(args.oasisc, directory, runs) and ok
            elif case == "crowds5-20":
                case_crowds5_20(args.oasisc, directory, runs)
            elif case == "csma3-4":
                case_csma(args.oasisc, directory, runs)
            elif case == "exact":
                case_exact(args.oasisc, directory, args.exact_timeout)
            else:
                parser.error(f"unknown case {case!r}")
    if args.smoke and not ok:
        print("crowds_benchmark: the stormpy case does not have the published sizes")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
