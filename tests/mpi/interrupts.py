#!/usr/bin/env python3
"""oasisc-mpi ended from outside (issue 37, items 8, 9 and 15).

Signals: `mpirun -np 2 oasisc-mpi compile` is sent SIGTERM or SIGINT at points spread over its
run, as a person (Ctrl-C reaches mpirun alone: the ranks have their own process groups) or a
service manager would; some runs signal every process of the job at once, as a control group's
kill does. After each, the folder holding the output has the output folder and nothing beside
it (no staging folder: the ranks install oasisc's cleanup handlers), and the output folder, if
there, is the whole catalog, byte for byte. mpirun does not forward the signal at once: it
sends the ranks SIGCONT, SIGTERM one second later and SIGKILL a second after that (OpenMPI
4.1's odls_base_sigkill_timeout); the runs that finished in that second are counted and shown.

A shrinking input: the .aut model is cut once every rank has mapped it (the test hook
OASIS_TEST_SHRINK_INPUT) to nothing, or to its first page: each rank whose part is gone says
"PATH: error: the file changed size while being read" (rank 0 without a note, the others with
their rank), the job exits 1, no OpenMPI crash report is printed and nothing is written.
"""

import argparse
import filecmp
import os
import random
import signal
import subprocess
import sys
import time
from pathlib import Path

from mpi_run import chain_aut, mpi_environment, mpirun, start_work

failures = 0


def check(condition, what, detail=""):
    global failures
    if condition:
        print(f"ok: {what}")
        return
    failures += 1
    print(f"FAILED: {what}\n{detail[:3000]}")


def grid_spec(path, n):
    """A discrete grid of n*n states and three contexts: a compile of a few seconds whose
    catalog is some megabytes, so that the signals land in every stage."""
    lines = [f"mdp grid {{", f"  const N = {n};", "  var x : [0 .. N-1] init 0;",
             "  var y : [0 .. N-1] init 0;", "  actions left, right, up, down;", "  default self;",
             "  [right] x < N-1 -> 0.9: (x' = x + 1) + 0.1: true;",
             "  [up]    y < N-1 -> 0.9: (y' = y + 1) + 0.1: true;",
             "  [left]  x > 0   -> 0.9: (x' = x - 1) + 0.1: true;",
             "  [down]  y > 0   -> 0.9: (y' = y - 1) + 0.1: true;",
             "  discount 0.9;", "}", "catalog {"]
    for k, (cx, cy) in enumerate([(0, 0), (n - 1, n - 1), (n // 2, 0)]):
        lines += [f"  context corner{k} {{", f"    reward x == {cx} & y == {cy} : 1;", "  }"]
    lines += ["  switching stay 0.8;", "  prior uniform;", "}"]
    path.write_text("\n".join(lines) + "\n")


def job_processes(root_pid):
    """mpirun and every process below it (the ranks), from /proc."""
    children = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", encoding="utf-8") as stat:
                fields = stat.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        children.setdefault(int(fields[1]), []).append(int(entry))
    found, stack = [], [root_pid]
    while stack:
        pid = stack.pop()
        found.append(pid)
        stack += children.get(pid, [])
    return found


def start_compile(args, spec, out):
    env = mpi_environment()
    return subprocess.Popen(["mpirun", "-np", "2", "--oversubscribe", args.oasisc_mpi, "compile",
                             str(spec), "-o", str(out)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env,
                            start_new_session=True, text=True)


def catalog_whole(out, reference):
    names = sorted(os.listdir(out))
    if names != sorted(os.listdir(reference)):
        return False
    return all(filecmp.cmp(out / n, reference / n, shallow=False) for n in names)


def signal_runs(args, work):
    spec = work / "grid.oasis"
    grid_spec(spec, args.grid)
    reference = work / "reference"
    start = time.monotonic()
    result = mpirun(2, [args.oasisc_mpi, "compile", str(spec), "-o", str(reference)])
    seconds = time.monotonic() - start
    check(result.returncode == 0, f"the uninterrupted compile takes {seconds:.1f} s",
          result.stdout + result.stderr)
    if result.returncode != 0:
        return
    folder = work / "runs"
    folder.mkdir()
    out = folder / "grid"
    rng = random.Random(args.seed)
    finished_anyway = 0
    for run in range(args.runs):
        which = [signal.SIGTERM, signal.SIGINT][run % 2]
        everyone = run % 4 == 3  # now and then the whole job at once
        delay = rng.uniform(0.2, seconds + 0.5)
        before = out.stat().st_ino if out.exists() else None
        job = start_compile(args, spec, out)
        time.sleep(delay)
        targets = job_processes(job.pid) if everyone else [job.pid]
        for pid in targets:
            try:
                os.kill(pid, which)
            except ProcessLookupError:
                pass
        stdout, stderr = job.communicate(timeout=120)
        left = sorted(n for n in os.listdir(folder) if n != "grid")
        what = (f"run {run}: {signal.Signals(which).name} to "
                f"{'every process' if everyone else 'mpirun'} after {delay:.2f} s, exit "
                f"{job.returncode}")
        check(not left, f"{what}: nothing beside the output folder ({left})",
              stderr + "".join(f"{name} holds {sorted(os.listdir(folder / name))}\n"
                               for name in left if (folder / name).is_dir()))
        if out.exists():
            check(catalog_whole(out, reference), f"{what}: the output folder is the whole catalog",
                  stderr)
            replaced = out.stat().st_ino != before
            if job.returncode != 0 and replaced:
                finished_anyway += 1
    print(f"{finished_anyway} of {args.runs} signalled jobs exited non-zero with the new catalog "
          f"in place (they finished before mpirun forwarded the signal)")


def crash_report(text):
    return any(t in text for t in ["Caught signal", "Backtrace", "Signal:", "Bus error",
                                   "mpirun noticed that process rank"])


def shrink_runs(args, work):
    model = work / "chain.aut"
    out = work / "shrink-out"
    out.mkdir()
    for cut, expected in [("0", ["", " (rank 1)"]), ("4096", [" (rank 1)"])]:
        chain_aut(model, 300000)
        result = mpirun(2, [args.oasisc_mpi, "quotient", str(model), "-o",
                            str(out / "p.json")], extra_env={"OASIS_TEST_SHRINK_INPUT": cut})
        said = result.stdout + result.stderr
        what = f"quotient of an input cut to {cut} bytes at -np 2"
        check(result.returncode == 1, f"{what}: exit 1 ({result.returncode})", said)
        for note in expected:
            line = f"{model}: error: the file changed size while being read{note}\n"
            check(line in said, f"{what}: says {line.strip()!r}", said)
        check(not crash_report(said), f"{what}: no crash report", said)
        check(not os.listdir(out), f"{what}: nothing written", said)
    chain_aut(model, 300000)
    result = mpirun(2, [args.oasisc_mpi, "compile", str(model), "-o", str(out / "catalog")],
                    extra_env={"OASIS_TEST_SHRINK_INPUT": "0"})
    said = result.stdout + result.stderr
    check(result.returncode == 1 and "the file changed size while being read" in said
          and not crash_report(said) and not os.listdir(out),
          "compile of an input cut to nothing at -np 2: exit 1, the message, nothing written", said)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--oasisc-mpi", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--runs", type=int, default=12)
    parser.add_argument("--grid", type=int, default=200)
    parser.add_argument("--seed", type=int, default=37)
    args = parser.parse_args()
    work = start_work(args.work)
    shrink_runs(args, work)
    signal_runs(args, work)
    print(f"{failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
