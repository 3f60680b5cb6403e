#!/usr/bin/env python3
"""Hostile input for oasisc-mpi (issue 37), run as a user would: `mpirun -np 2 oasisc-mpi ...`.
Each probe asserts the job's exit status (2 for usage, 1 for a bad input), that the message
names the culprit, that it is a few lines at most and holds no crash text (no OpenMPI
backtrace), and that nothing was written outside the scratch folder. Classes:
  numbers   every number option passes common/command_line/number_options.hpp: NaN, infinities, signs
            on counts, out of range (CLI11's own exit codes 104-109 never reach the shell);
  empty     no option takes an empty value;
  usage     a missing command or option, an unknown one;
  outputs   --basename that would leave the output folder; several models whose outputs
            would have one name; a context named like a path;
  reading   an input cut short while the ranks read it (a test hook cuts it at a known
            point); it was a SIGBUS on every rank;
  resources --memory-budget: a clear "out of memory" on a model too large for it, and
            bad budgets refused.
Run by ctest (hostile.mpi, -L hostile, when OASIS_BUILD_MPI is on):

    tests/hostile/mpi_probes.py --oasisc-mpi B/compiler/oasisc-mpi --source-dir .
"""

import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "mpi"))

from mpi_run import chain_aut, mpi_environment  # noqa: E402  (tests/mpi: how the tests run mpirun)
from probe_harness import judge, report, shown, snapshot  # noqa: E402

NOT_A_NUMBER = ["nan", "inf", "-inf", "1e999", "0x10", "1,5", "twelve", "5\x01"]
NOT_A_COUNT = ["-1", "1.5", "1e3", "+3", "18446744073709551616"]
RANKS = 2
# Text only OpenMPI's own signal handler prints (a rank killed by SIGBUS or SIGSEGV).
MPI_CRASH_TEXT = ["Caught signal", "[ 0]", "mpirun noticed that process rank"]


def prepare_inputs(paths):
    root = paths.root
    for folder in ["a", "b", "outs"]:
        os.mkdir(os.path.join(root, folder))
    paths.small = os.path.join(root, "a", "x.aut")
    chain_aut(paths.small, 50)
    chain_aut(os.path.join(root, "b", "x.aut"), 60)
    paths.big = os.path.join(root, "big.aut")
    chain_aut(paths.big, 400000)  # about 7 MB: many pages, and far past a 16 MiB budget
    paths.big_size = os.path.getsize(paths.big)
    paths.outs = os.path.join(root, "outs")
    paths.prism = os.path.join(root, "walk.nm")
    with open(paths.prism, "w", encoding="utf-8") as out:
        out.write("mdp\nconst int N;\nmodule m\n  x : [0..3] init 0;\n"
                  "  [go] x < 3 -> 0.5 : (x'=x+1) + 0.5 : true;\n  [stay] true -> true;\n"
                  "endmodule\nrewards \"far\" x = 3 : 1; endrewards\n"
                  "rewards \"a/../../escaped\" x = 0 : 1; endrewards\n")


def number_probes(paths):
    q = ["quotient", paths.small, "-o", os.path.join(paths.scratch, "p.json")]
    c = ["compile", paths.spec, "-o", paths.scratch]
    for value in NOT_A_NUMBER + ["1.5", "-0.5"]:
        yield c + ["--robust", value], 2, "--robust"
    for value in NOT_A_NUMBER + NOT_A_COUNT + ["100000"]:
        yield c + ["-j", value], 2, "--jobs"
    for value in NOT_A_NUMBER + NOT_A_COUNT + ["0", "4294967295"]:  # past 32-bit state numbers
        yield c + ["--max-states", value], 2, "--max-states"
        yield q + ["--max-states", value], 2, "--max-states"
    for value in ["nan", "-1", "+5", "twelve", "1.5.5", "8G!"]:
        yield q + ["--max-input-size", value], 2, "--max-input-size"
    for value in ["nan", "-1", "1K", "101%", "0%", "lots"]:
        yield q + ["--memory-budget", value], 2, "--memory-budget"
        yield c + ["--memory-budget", value], 2, "--memory-budget"


def empty_probes(paths):
    q = ["quotient", paths.small]
    c = ["compile", paths.spec]
    for command, option in [(q + ["-o"], "--output"), (q + ["-o", paths.scratch, "--format"],
                            "--format"), (q + ["-o", paths.scratch, "--max-input-size"],
                            "--max-input-size"), (c + ["-o"], "--output"),
                            (c + ["--basename"], "--basename"), (c + ["--const"], "--const"),
                            (c + ["--rewards"], "--rewards"), (c + ["--format"], "--format"),
                            (c + ["--memory-budget"], "--memory-budget")]:
        yield command + [""], 2, option
    yield ["quotient", "", "-o", paths.scratch], 2, "models"
    yield ["compile", ""], 2, "spec"


def usage_probes(paths):
    yield [], 2, "A subcommand is required"
    yield ["frobnicate"], 2, "subcommand"  # CLI11, as in oasisc: the name is not repeated
    yield ["quotient", paths.small], 2, "--output"
    yield ["quotient", paths.small, "-o", paths.scratch, "--format", "dot"], 2, "--format"
    yield ["compile", paths.spec, "--no-such-option"], 2, "--no-such-option"
    yield ["compile"], 2, "spec"


def output_probes(paths):
    cpp = ["compile", paths.spec, "-o", paths.scratch, "--format", "cpp", "--basename"]
    for name in ["../mine", os.path.join(paths.root, "mine"), "..", ".", "a/b"]:
        yield cpp + [name], 2, "--basename"
    other = os.path.join(paths.root, "b", "x.aut")
    yield ["quotient", paths.small, other, "-o", paths.outs], 2, other
    yield ["quotient", paths.small, paths.small, "-o", paths.outs], 2, paths.small
    yield ["quotient", paths.small, os.path.join(paths.root, "a", ".", "x.aut"), "-o",
           paths.outs], 2, paths.small
    # A PRISM reward structure names a context, and its .dot file: never a path.
    yield (["compile", paths.prism, "--const", "N=1", "--rewards", "a/../../escaped", "-o",
            paths.scratch, "--format", "dot"], 1, "not a plain file name")
    yield ["compile", paths.prism, "--const", "N", "-o", paths.scratch], 1, "oasisc-mpi: error: --const"


def reading_probes(paths):
    # Cut to nothing once every rank has mapped it: both ranks' parts are gone.
    yield (["quotient", paths.big, "-o", os.path.join(paths.scratch, "p.json")], 1,
           "big.aut: error: the file changed size while being read", {"OASIS_TEST_SHRINK_INPUT": "0"})
    # Cut after its first page: rank 0 reads its part to the end of that page, rank 1 finds
    # its part gone.
    yield (["quotient", paths.big, "-o", os.path.join(paths.scratch, "p.json")], 1,
           "the file changed size while being read (rank 1)", {"OASIS_TEST_SHRINK_INPUT": "4096"})
    yield ["quotient", paths.folder + ".aut", "-o", paths.scratch], 1, paths.folder + ".aut"


def resource_probes(paths):
    if not paths.budget_enforced:
        return
    yield (["quotient", paths.big, "-o", os.path.join(paths.scratch, "p.json"),
            "--memory-budget", "16M"], 1, "out of memory")


def probes(paths):
    for generator in [number_probes, empty_probes, usage_probes, output_probes, reading_probes,
                      resource_probes]:
        for probe in generator(paths):
            arguments, status, culprit = probe[:3]
            yield arguments, status, culprit, (probe[3] if len(probe) > 3 else {})


def run_mpi_probe(paths, arguments, status, culprit, extra_env):
    """Runs one probe under mpirun; the failure message, or None when it held. mpirun adds its
    own lines to every failed job ("Primary job terminated normally, but 1 process returned a
    non-zero exit code"), which are not counted against the message's length."""
    env = mpi_environment()
    env["TMPDIR"] = paths.session
    env.update(extra_env)
    command = ["mpirun", "-np", str(RANKS), "--oversubscribe", paths.oasisc_mpi] + arguments
    try:
        result = subprocess.run(command, capture_output=True, timeout=120,
                                stdin=subprocess.DEVNULL, env=env)
    except subprocess.TimeoutExpired:
        return f"{shown(command)}: hung (120 s)"
    output = (result.stdout + result.stderr).decode("utf-8", "replace")
    ours = without_mpirun_notice(output)
    failure = judge(command, status, culprit, result.returncode, ours)
    if failure is None and any(text in output for text in MPI_CRASH_TEXT):
        failure = f"{shown(command)}: OpenMPI reports a crashed rank\n{output[:1500]}"
    return failure


def without_mpirun_notice(output):
    """The output without mpirun's boxed notices (lines between rows of dashes)."""
    kept, boxed = [], False
    for line in output.splitlines(keepends=True):
        if line.startswith("-" * 20):
            boxed = not boxed
            continue
        if not boxed:
            kept.append(line)
    return "".join(kept)


def checks_after(paths, before, inputs_before):
    failures = []
    after = sorted(os.listdir(paths.root))
    if after != before:
        failures.append(f"refused commands left {sorted(set(after) - set(before))} behind")
    changed = [path for path, data in snapshot(paths.root).items()
               if inputs_before.get(path, b"") != data and not path.startswith(paths.scratch)
               and not path.startswith(paths.session) and path != paths.big]
    if changed:
        failures.append(f"refused commands changed {sorted(changed)[:5]}")
    for outside in [os.path.join(paths.root, "mine.cpp"), os.path.join(paths.root, "mine.hpp"),
                    os.path.join(os.path.dirname(paths.root), "escaped.dot")]:
        if os.path.exists(outside):
            failures.append(f"oasisc-mpi wrote {outside}, outside the output folder")
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--oasisc-mpi", required=True)
    parser.add_argument("--source-dir", required=True)
    paths = parser.parse_args()
    paths.spec = os.path.join(paths.source_dir, "specs/discrete_tracking.oasis")
    failures = []
    count = 0
    with tempfile.TemporaryDirectory() as scratch:
        paths.root = os.path.join(scratch, "probes")
        os.mkdir(paths.root)
        paths.scratch = os.path.join(paths.root, "out")
        paths.session = os.path.join(scratch, "mpi-session")  # OpenMPI's session files
        os.mkdir(paths.session)
        paths.folder = os.path.join(paths.root, "a_folder")
        os.mkdir(paths.folder + ".aut")
        prepare_inputs(paths)
        help_text = run_help(paths)
        paths.budget_enforced = "not enforced in this sanitizer build" not in help_text
        if not paths.budget_enforced:
            print("a sanitizer build: the probe that needs an enforced --memory-budget is left out")
        before = sorted(os.listdir(paths.root))
        inputs_before = snapshot(paths.root)
        for arguments, status, culprit, extra_env in probes(paths):
            count += 1
            if os.path.getsize(paths.big) != paths.big_size:
                chain_aut(paths.big, 400000)  # whole again after a cut
            failure = run_mpi_probe(paths, arguments, status, culprit, extra_env)
            if failure:
                failures.append(failure)
        failures += checks_after(paths, before, inputs_before)
    return report(failures, count)


def run_help(paths):
    env = mpi_environment()
    env["TMPDIR"] = paths.session
    return subprocess.run(["mpirun", "-np", "1", paths.oasisc_mpi, "quotient", "--help"],
                          capture_output=True, env=env, check=False).stdout.decode("utf-8", "replace")


if __name__ == "__main__":
    sys.exit(main())
