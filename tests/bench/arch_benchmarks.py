#!/usr/bin/env python3
"""Times `oasisc compile` on the ARCH-COMP stochastic benchmarks of specs/arch/ at their shipped
size (specs/arch/README.md), each in a fresh process under `/usr/bin/time -v`: wall-clock
seconds and peak resident memory, with the compile's own summary (cells x actions, the interval
entries, the bounds at the centre cell). Results belong in docs/PERFORMANCE.md. Not a ctest
test: tests/arch/arch_specs.py runs the same specs at small grids.

    tests/bench/arch_benchmarks.py --oasisc build/default/compiler/oasisc [NAME ...]

NAME is a spec's file stem (van_der_pol, bas4d, ...); without one, every spec of specs/arch/.
"""
import argparse
import os
import pathlib
import platform
import re
import signal
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
SPECS = ROOT / "specs" / "arch"
TIME = "/usr/bin/time"


def measure(oasisc, spec, out, timeout):
    """(wall seconds, peak RSS in MiB, the compile's summary lines) of one compile of SPEC."""
    command = [TIME, "-v", str(oasisc), "compile", str(spec), "-o", str(out)]
    # A session of its own, so a timeout stops oasisc too, not only time.
    with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          start_new_session=True) as process:
        try:
            stdout, report = process.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.communicate()
            sys.exit(f"{spec.stem}: not done within {timeout} s")
    # /usr/bin/time writes its report last on stderr, after the command's own output.
    wall = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", report)
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", report)
    status = re.search(r"Exit status: (\d+)", report)
    if not (wall and rss and status):
        sys.exit(f"{spec.stem}: no report from {TIME} -v\n{report}")
    if status.group(1) != "0":
        sys.exit(f"{spec.stem}: oasisc compile exited with {status.group(1)}\n{stdout}\n{report}")
    seconds = 0.0
    for part in wall.group(1).split(":"):
        seconds = seconds * 60 + float(part)
    summary = [line.strip() for line in (stdout + report).splitlines()
               if line.lstrip().startswith(("objective:", "bounds:", "at the centre cell"))]
    return seconds, int(rss.group(1)) / 1024, summary


def processor():
    try:
        for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown processor"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--oasisc", required=True)
    parser.add_argument("--timeout", type=float, default=3600, help="seconds per compile")
    parser.add_argument("names", nargs="*", help="spec file stems; default: all of specs/arch/")
    args = parser.parse_args()
    names = args.names or sorted(path.stem for path in SPECS.glob("*.oasis"))
    missing = [name for name in names if not (SPECS / f"{name}.oasis").is_file()]
    if missing:
        sys.exit(f"no such spec in {SPECS}: {', '.join(missing)}")
    if not pathlib.Path(TIME).is_file():
        sys.exit(f"{TIME} is needed (GNU time, package 'time')")

    print(f"# oasisc compile at the shipped size: {processor()}, {os.cpu_count()} CPUs")
    rows = []
    with tempfile.TemporaryDirectory(prefix="arch_bench_") as folder:
        for name in names:
            seconds, mib, summary = measure(args.oasisc, SPECS / f"{name}.oasis",
                                            pathlib.Path(folder) / name, args.timeout)
            print(f"{name}: {seconds:.2f} s wall, peak RSS {mib:.1f} MiB", flush=True)
            for line in summary:
                print(f"  {line}", flush=True)
            rows.append((name, seconds, mib))
    print("\n| spec | wall | peak RSS |\n|---|---:|---:|")
    for name, seconds, mib in rows:
        print(f"| {name} | {seconds:.2f} s | {mib:.1f} MiB |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
