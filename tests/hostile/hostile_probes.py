#!/usr/bin/env python3
"""Hostile input (issue 28), run as a user would: each probe runs oasisc, oasis-sim or oasis-go1
and asserts its exit status (2 for usage, 1 for a bad input), that the message names the
culprit (the option, the file), that it is a few lines at most, that the program neither crashed
nor hung, and that nothing was written outside the scratch folder. Classes covered so far:
  numbers   every number option of the three programs passes one rule
            (tools/cli/number_options.hpp): NaN, infinities, signs on counts, out of range;
  outputs   file names that would leave the output folder, folders that cannot be made;
  claims    a fit whose fragment `oasisc check` would refuse; an empty log scored.
Run by ctest (-L hostile):

    tests/hostile/hostile_probes.py --oasisc B/compiler/oasisc --oasis-sim B/tools/sim/oasis-sim \
        --oasis-go1 B/hw/app/oasis-go1 --source-dir .
"""

import argparse
import os
import subprocess
import sys
import tempfile

# Values no number option may take, whatever its range; and values that wrap an unsigned one.
NOT_A_NUMBER = ["nan", "NaN", "inf", "-inf", "1e999", "0x10", "", "1,5", "twelve", "5\x01"]
NOT_A_COUNT = ["-1", "-0", "1.5", "1e3", "+3", "18446744073709551616"]


def number_probes(paths):
    """(program arguments, status, text the message names): every one a usage error."""
    spec = os.path.join(paths.source_dir, "specs/discrete_tracking.oasis")
    line = os.path.join(paths.source_dir, "tests/data/gaussian_line.oasis")
    fit_spec = os.path.join(paths.source_dir, "tests/data/fit/tracking.oasis")
    labels = os.path.join(paths.source_dir, "tests/data/fit/labels.csv")
    c, s, g = paths.oasisc, paths.oasis_sim, paths.oasis_go1
    real_options = [
        ([c, "quotient", spec, "--epsilon"], "--epsilon", ["5", "0", "1e-320"]),
        ([c, "compile", line, "-o", paths.scratch, "--epsilon"], "--epsilon", ["5", "0", "-0.1"]),
        ([c, "compile", spec, "-o", paths.scratch, "--robust"], "--robust", ["1.5", "-0.5"]),
        ([c, "verify", spec, spec, "--robust"], "--robust", ["2"]),
        ([c, "fit", "noise", fit_spec, labels, "--matrix", "--pseudo-count"], "--pseudo-count",
         ["1e308", "-1"]),
        ([c, "fit", "switching", fit_spec, labels, "--detection-epsilon"], "--detection-epsilon",
         ["0.6"]),
        ([c, "fit", "switching", fit_spec, labels, "--reward-tolerance"], "--reward-tolerance",
         ["-1"]),
        ([c, "fit", "switching", fit_spec, labels, "--state-noise"], "--state-noise", ["1.01"]),
        ([s, "table1", "--sigma"], "--sigma", ["-0.1", "2"]),
        ([g, "score", "--period"], "--period", ["0", "-1"]),
    ]
    count_options = [
        ([c, "compile", line, "-o", paths.scratch, "--max-cells"], "--max-cells",
         ["0", "1000000000"]),
        ([c, "compile", spec, "-o", paths.scratch, "-j"], "--jobs", ["100000"]),
        ([c, "quotient", spec, "-j"], "--jobs", []),
        ([c, "check", spec, "--max-states"], "--max-states", ["0"]),
        ([c, "check", spec, "--max-errors"], "--max-errors", ["0"]),
        ([c, "check", spec, "--max-number-bits"], "--max-number-bits", ["8"]),
        ([c, "fit", "depth-noise", labels, "--degree"], "--degree", ["3"]),
        ([s, "table1", "--seeds"], "--seeds", ["0"]),
        ([s, "table1", "--steps"], "--steps", ["0", "1000000000"]),
        ([s, "table1", "--fit-switching"], "--fit-switching", ["0"]),
        ([g, "run", "--dry-run", "--source", "synthetic", "--fast", "--steps"], "--steps", []),
        ([g, "run", "--dry-run", "--robot-timeout-ms"], "--robot-timeout-ms", ["5"]),
        ([g, "record", paths.scratch, "--frames"], "--frames", ["0"]),
        ([g, "sim", "--trials"], "--trials", ["0"]),
        ([g, "sim", "--seed"], "--seed", []),
        ([g, "sim", "--steps"], "--steps", ["0"]),
    ]
    for command, option, out_of_range in real_options:
        for value in NOT_A_NUMBER + out_of_range:
            yield command + [value], 2, option
    for command, option, out_of_range in count_options:
        for value in NOT_A_NUMBER + NOT_A_COUNT + out_of_range:
            yield command + [value], 2, option


def other_probes(paths):
    """(program arguments, status, text the message names) of the other classes."""
    spec = os.path.join(paths.source_dir, "specs/discrete_tracking.oasis")
    fit_spec = os.path.join(paths.source_dir, "tests/data/fit/tracking.oasis")
    all_wrong = os.path.join(paths.source_dir, "tests/data/fit/all_wrong.csv")
    c, s, g = paths.oasisc, paths.oasis_sim, paths.oasis_go1
    compile_cpp = [c, "compile", spec, "-o", paths.scratch, "--format", "cpp", "--basename"]
    for name in ["../evil", "/tmp/oasis-hostile-evil", "..", ".", "", "a/b"]:
        yield compile_cpp + [name], 2, "--basename"
    yield [g, "sim", "--trials", "1", "--steps", "1", "--logs", "/proc/oasis-x"], 1, "--logs"
    yield [g, "sim", "--trials", "1", "--steps", "1", "--plots", "/proc/oasis-x"], 1, "--plots"
    yield [g, "score", paths.empty_log], 1, paths.empty_log
    yield [c, "fit", "noise", fit_spec, all_wrong], 1, "every label is wrong"
    line = os.path.join(paths.source_dir, "tests/data/gaussian_line.oasis")
    yield [c, "quotient", line], 1, "oasisc compile"
    # An empty value never means the default (it did for every string option).
    empty = [
        ([c, "quotient", spec, "-o"], "--output"),
        ([c, "compile", spec, "-o"], "--output"),
        ([c, "export", spec, "--format", "aut", "-o"], "--output"),
        ([c, "quotient", spec, "--context"], "--context"),
        ([c, "check", spec, "--memory-budget"], "--memory-budget"),
        ([c, "check"], "files"),
        ([s, "table1", "--json"], "--json"),
        ([s, "table1", "--spec"], "--spec"),
        ([s, "table1", "--filters"], "--filters"),
        ([g, "run", "--dry-run", "--catalog"], "--catalog"),
        ([g, "run", "--dry-run", "--controller"], "--controller"),
        ([g, "run", "--dry-run", "--log"], "--log"),
        ([g, "run", "--dry-run", "--robot"], "--robot"),
        ([g, "sim", "--logs"], "--logs"),
        ([g, "sim", "--controllers"], "--controllers"),
        ([g, "config", "--controller"], "--controller"),
    ]
    for command, option in empty:
        yield command + [""], 2, option
    # Inputs that are not files: a FIFO nobody writes to (it blocked open() forever) and a
    # directory, wherever a program reads a file.
    # (score checks its arguments are files while parsing: a folder is a usage error there)
    for odd, score_status in [(paths.fifo, 1), (paths.folder, 2)]:
        yield [c, "check", odd], 1, odd
        yield [c, "fit", "noise", fit_spec, odd], 1, odd
        yield [c, "verify", spec, odd], 1, odd
        yield [g, "run", "--dry-run", "--source", "synthetic", "--fast", "--steps", "1",
               "--catalog", odd], 1, odd
        yield [g, "run", "--dry-run", "--source", "synthetic", "--fast", "--steps", "1",
               "--catalog-spec", odd], 1, odd
        yield [g, "score", odd], score_status, odd
        yield [g, "sim", "--trials", "1", "--steps", "1", "--controllers", odd + ".yaml"], 1, odd
    yield [g, "run", "--dry-run", "--config", paths.fifo], 1, paths.fifo
    yield [g, "sim", "--trials", "1", "--steps", "1", "--scenario", paths.fifo], 1, paths.fifo
    yield [s, "table1", "--no-such-option"], 2, "--no-such-option"
    yield [s, "nonsense"], 2, "A subcommand is required"


def probes(paths):
    yield from number_probes(paths)
    yield from other_probes(paths)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--oasisc", required=True)
    parser.add_argument("--oasis-sim", required=True)
    parser.add_argument("--oasis-go1", required=True)
    parser.add_argument("--source-dir", required=True)
    paths = parser.parse_args()
    failures = []
    count = 0
    with tempfile.TemporaryDirectory() as scratch:
        paths.scratch = os.path.join(scratch, "out")
        paths.empty_log = os.path.join(scratch, "empty.jsonl")
        open(paths.empty_log, "w", encoding="utf-8").close()
        paths.fifo = os.path.join(scratch, "nobody_writes")
        os.mkfifo(paths.fifo)
        os.mkfifo(paths.fifo + ".yaml")
        paths.folder = os.path.join(scratch, "a_folder")
        os.mkdir(paths.folder)
        os.mkdir(paths.folder + ".yaml")
        before = sorted(os.listdir(scratch))
        for arguments, expected, culprit in probes(paths):
            count += 1
            shown = " ".join(repr(a) if (not a or " " in a or not a.isprintable()) else a
                             for a in [os.path.basename(arguments[0])] + arguments[1:])
            try:
                result = subprocess.run(arguments, capture_output=True, timeout=60,
                                        stdin=subprocess.DEVNULL)
            except subprocess.TimeoutExpired:
                failures.append(f"{shown}: hung (60 s)")
                continue
            output = (result.stdout + result.stderr).decode("utf-8", "replace")
            if result.returncode != expected:
                failures.append(f"{shown}: status {result.returncode}, expected {expected}\n"
                                f"{output}")
            elif culprit not in output:
                failures.append(f"{shown}: the message does not name {culprit}\n{output}")
            elif len(output) > 2000 or max(len(l) for l in output.splitlines() or [""]) > 400:
                failures.append(f"{shown}: the message is longer than a few lines\n{output[:600]}")
        after = sorted(os.listdir(scratch))
        if after != before:
            failures.append(f"refused commands left {sorted(set(after) - set(before))} behind")
    for outside in ["/tmp/oasis-hostile-evil.cpp", "/tmp/oasis-hostile-evil.hpp"]:
        if os.path.exists(outside):
            failures.append(f"--basename wrote {outside}, outside the output folder")
    for failure in failures:
        print("FAILED:", failure)
    print(f"{count} probes, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
