#!/usr/bin/env python3
"""`mpirun -np P oasisc-mpi compile` writes the catalog `oasisc compile` writes, file for file
and byte for byte (the marker included), at P = 1, 2 and 4: every shipped discrete spec, and
PRISM programs with their reward structure as their context, and a corridor with six contexts
(more contexts than ranks, and fewer). `oasisc verify` accepts one. A continuous spec and a bad one fail cleanly: status 1,
one report, no output folder."""

import argparse
import filecmp
import os
import subprocess
import sys
from pathlib import Path

from mpi_run import mpirun, start_work

failures = 0


def fail(message):
    global failures
    failures += 1
    print(f"FAILED: {message}")


def same_tree(left, right):
    """Every file of both folders, compared byte for byte; returns the differences."""
    names = sorted(set(os.listdir(left)) | set(os.listdir(right)))
    return [n for n in names
            if not (left / n).exists() or not (right / n).exists()
            or not filecmp.cmp(left / n, right / n, shallow=False)]


def corridor_spec(path, cells=8, contexts=6):
    """A corridor of `cells` cells and one context per rewarded cell: more contexts than
    ranks, each with its own abstraction."""
    states = ", ".join(f"c{i}" for i in range(cells))
    lines = [f"mdp corridor {{", f"  states {states};", "  actions L, R;", "  init c0;"]
    for i in range(cells):
        left, right = max(i - 1, 0), min(i + 1, cells - 1)
        lines.append(f"  c{i}, L -> 3/4: c{left} + 1/4: c{i};")
        lines.append(f"  c{i}, R -> 3/4: c{right} + 1/4: c{i};")
    lines += ["  discount 0.9;", "}", "catalog {"]
    for k in range(contexts):
        lines += [f"  context at_c{k + 1} {{", f"    reward c{k + 1} : 1;", "  }"]
    lines += ["  switching stay 0.8;", "  prior uniform;", "}"]
    path.write_text("\n".join(lines) + "\n")
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--oasisc", required=True)
    parser.add_argument("--oasisc-mpi", required=True)
    parser.add_argument("--root", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    work = start_work(args.work)
    root = Path(args.root)

    cases = [(root / "specs" / name, []) for name in
             ("discrete_tracking.oasis", "discrete_tracking_prism.oasis", "discrete_tracking.nm")]
    cases += [(root / "tests/data/prism" / name, ["--rewards", "all"]) for name in
              ("knuth_die.pm", "two_dice.nm", "leader_async3.nm")]
    cases.append((corridor_spec(work / "corridor.oasis"), []))
    compared = 0
    for spec, flags in cases:
        name = spec.stem + "_" + spec.suffix[1:]
        expected = work / f"{name}.seq"
        result = subprocess.run([args.oasisc, "compile", str(spec), "-o", str(expected),
                                 "--format", "bin,json,dot,cpp"] + flags, capture_output=True, text=True)
        if result.returncode != 0:
            fail(f"oasisc compile {spec.name}: {result.stderr}")
            continue
        contexts = len(list(expected.glob("*.dot")))
        for ranks in (1, 2, 4):
            out = work / f"{name}.mpi{ranks}"
            result = mpirun(ranks, [args.oasisc_mpi, "compile", str(spec), "-o", str(out),
                                    "--format", "bin,json,dot,cpp"] + flags)
            if result.returncode != 0:
                fail(f"P={ranks} {spec.name}: exit {result.returncode}\n{result.stderr}")
                continue
            differing = same_tree(expected, out)
            if differing:
                fail(f"P={ranks} {spec.name}: {differing} differ from oasisc compile's")
            compared += 1
        print(f"{spec.name} {' '.join(flags)}: {contexts} contexts, the same catalog at P = 1, 2, 4")

    spec = root / "specs/discrete_tracking.oasis"
    result = subprocess.run([args.oasisc, "verify", str(spec), str(work / "discrete_tracking_oasis.mpi4/discrete_tracking.bin")],
                            capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"oasisc verify rejected oasisc-mpi's catalog:\n{result.stdout}{result.stderr}")

    for bad, message in ((root / "specs/go1_treat.oasis", "compile it with 'oasisc compile'"),
                         (root / "tests/specs/bad/syntax_missing_semicolon.oasis", "error:")):
        if not bad.exists():
            fail(f"{bad} is missing")
            continue
        out = work / f"{bad.stem}.out"
        result = mpirun(4, [args.oasisc_mpi, "compile", str(bad), "-o", str(out)])
        if result.returncode == 0 or out.exists() or result.stderr.count(message) != 1:
            fail(f"{bad.name}: expected status 1, one report containing {message!r} and no {out.name}; "
                 f"got {result.returncode}, {out.exists()}\n{result.stderr}")
        else:
            print(f"{bad.name}: refused once, nothing written")

    print(f"{compared} catalogs compared: {failures} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
