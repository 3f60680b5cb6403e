#!/usr/bin/env python3
"""Table II on the Go1 as a unicycle (specs/go1_unicycle.oasis): compiles its catalog and the
no-attention baseline's as scripts/regen does for go1_treat.oasis, runs `oasis-go1 sim` on them
(12 seeded trials, every shipped controller), and requires ours to reach an accuracy of at
least 0.95, the goal the linked Go1 catalog meets (docs/RESULTS.md), and the compile to report
its epsilon.

    go1_unicycle_table2.py --oasisc OASISC --oasis-go1 OASIS_GO1 --spec SPEC
"""

import argparse
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

GOAL = 0.95


def run(command):
    result = subprocess.run(command, capture_output=True, text=True, check=False)
    if result.returncode != 0:
        sys.exit(f"{' '.join(command)} failed ({result.returncode}):\n{result.stdout}{result.stderr}")
    return result.stdout


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--oasisc", required=True)
    parser.add_argument("--oasis-go1", required=True)
    parser.add_argument("--spec", required=True)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        catalog_dir = Path(scratch) / "attention"
        baseline_dir = Path(scratch) / "no_attention"
        summary = run([args.oasisc, "compile", args.spec, "-f", "bin", "-o", str(catalog_dir)])
        epsilons = re.findall(r"epsilon ([0-9.e-]+)", summary)
        if len(epsilons) != 2:
            sys.exit(f"expected an epsilon per context in the compile's summary:\n{summary}")
        print(summary, end="")
        run([args.oasisc, "compile", args.spec, "--no-attention", "--max-cells", "8000", "-f",
             "bin", "-o", str(baseline_dir)])
        name = Path(args.spec).stem + ".bin"
        table = json.loads(run([args.oasis_go1, "sim", "--trials", "12", "--seed", "1", "--quiet",
                                "--json", "--catalog", str(catalog_dir / name), "--catalog-spec",
                                args.spec, "--no-attention-catalog", str(baseline_dir / name)]))
    for controller, row in table.items():
        print(f"{controller}: accuracy {row['accuracy']['mean']:.4f}, "
              f"reward {row['normalized_reward']['mean']:.4f}")
    accuracy = table["ours"]["accuracy"]["mean"]
    if accuracy < GOAL:
        sys.exit(f"ours: accuracy {accuracy:.4f} is below the goal {GOAL}")
    print(f"ours meets the goal: accuracy {accuracy:.4f} >= {GOAL}")


if __name__ == "__main__":
    main()
