#!/usr/bin/env python3
"""The distributed engine fails cleanly: a rank killed mid-run makes mpirun exit non-zero
with a message that says so, a bad line in any rank's part of the file is reported once as
file:line:col, problems only the whole file shows (a repeated (state, action) in two parts,
a wrong transition count) are reported, and in every case no output is left behind."""

import argparse
import os
import subprocess
import sys
from pathlib import Path

from mpi_run import mpirun, start_work

failures = 0


def check(condition, what, result=None):
    global failures
    if condition:
        print(f"ok: {what}")
        return
    failures += 1
    print(f"FAILED: {what}")
    if result is not None:
        print(f"  exit {result.returncode}\n  stdout: {result.stdout}\n  stderr: {result.stderr}")


def chain_text(n, bad_line=None, repeat=None, declared=None):
    lines = [f'({s},"a",{s + 1})' for s in range(n - 1)] + [f'({n - 1},"a|reward(1)",{n - 1})']
    if bad_line is not None:
        lines[bad_line] = f'({bad_line},"a",{bad_line + 1} 3/2 0)'
    if repeat is not None:
        lines.append(f'({repeat},"a",0)')
    count = len(lines) if declared is None else declared
    return "\n".join([f"des (0,{count},{n})"] + lines) + "\n"


def expect_clean_failure(out_dir, result, what):
    check(result.returncode != 0, f"{what}: non-zero exit", result)
    left = sorted(os.listdir(out_dir))
    check(not left, f"{what}: nothing left in the output folder ({left})")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--oasisc-mpi", required=True)
    parser.add_argument("--planted", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    work = start_work(args.work)
    out_dir = work / "out"
    out_dir.mkdir(exist_ok=True)
    output = str(out_dir / "partition.json")

    model = work / "planted.aut"
    subprocess.run([args.planted, "--transitions", "100000", "--blocks", "100", "--seed", "3",
                    "-o", str(model)], check=True, capture_output=True)
    result = mpirun(4, [args.oasisc_mpi, "quotient", str(model), "-o", output], extra_env={"OASIS_MPI_KILL": "2:1"})
    expect_clean_failure(out_dir, result, "rank 2 killed in round 1")
    said = result.stdout + result.stderr
    check("rank 2" in said and ("signal 9" in said or "Killed" in said),
          "mpirun names the lost rank and its signal", result)

    result = mpirun(4, [args.oasisc_mpi, "quotient", str(model), "-o", output, "--progress"])
    check(result.returncode == 0 and Path(output).exists(), "the same run without the kill writes the partition", result)
    check("read planted in" in result.stderr and "round 0: " in result.stderr and "round 1: " in result.stderr,
          "--progress reports the reading and each round", result)
    os.remove(output)

    n = 4000
    bad = work / "bad_line.aut"
    bad.write_text(chain_text(n, bad_line=3 * n // 4))  # in the last rank's part
    result = mpirun(4, [args.oasisc_mpi, "quotient", str(bad), "-o", output])
    expect_clean_failure(out_dir, result, "a bad line in rank 3's part")
    line = 3 * n // 4 + 2
    check(result.stderr.count(f"bad_line.aut:{line}:") == 1 and "error:" in result.stderr,
          f"the bad line is reported once, as bad_line.aut:{line}:col", result)

    header = work / "bad_header.aut"
    header.write_text("des (0,1)\n(0,\"a\",0)\n")
    result = mpirun(4, [args.oasisc_mpi, "quotient", str(header), "-o", output])
    expect_clean_failure(out_dir, result, "a bad header")
    check(result.stderr.count("bad_header.aut:1:") == 1, "the header's error is reported once, not per rank", result)

    # Issue 41: the memory budget is each rank's. A header that 4 ranks cannot hold within
    # 64 MiB each is refused at once, before any rank reads its part, once, naming the option.
    huge = work / "huge_header.aut"
    huge.write_text("des (0,100000000,25000000)\n(0,\"a\",1)\n")
    result = mpirun(4, [args.oasisc_mpi, "quotient", str(huge), "-o", output, "--memory-budget", "64M"])
    expect_clean_failure(out_dir, result, "a header beyond the budget per rank")
    check(result.stderr.count("huge_header.aut:1:8: error: the header declares 100000000 transitions") == 1
          and "more than the memory budget of 64.0 MiB per rank (raise it with --memory-budget, or run on more ranks)"
          in result.stderr, "the header's size is refused once, naming --memory-budget", result)

    repeated = work / "repeated.aut"
    repeated.write_text(chain_text(n, repeat=1))  # state 1's second line is in the last part
    result = mpirun(4, [args.oasisc_mpi, "quotient", str(repeated), "-o", output])
    expect_clean_failure(out_dir, result, "a (state, action) given in two parts")
    check("state 1 has more than one distribution for action 'a'" in result.stderr,
          "the repeated distribution is named", result)

    count = work / "count.aut"
    count.write_text(chain_text(n, declared=n + 5))
    result = mpirun(4, [args.oasisc_mpi, "quotient", str(count), "-o", output])
    expect_clean_failure(out_dir, result, "a wrong transition count")
    check(f"declares {n + 5} transitions but the file has {n}" in result.stderr,
          "the count is checked over all parts", result)

    result = mpirun(2, [args.oasisc_mpi, "quotient", str(work / "model.tra"), "-o", output])
    expect_clean_failure(out_dir, result, "a .tra file")
    check("reads mCRL2 .aut files" in result.stderr, "other formats are refused with a hint", result)

    print(f"{failures} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
