#!/usr/bin/env python3
"""The wrong-camera matrix (issue 22): `oasis-go1 sim` when the camera is not the one the catalog
declares.

The Go1 catalog declares the camera's depth noise sigma(d) = 2 mm + 0.2% d + 0.5% d^2 and a
detection probability of 0.9 (specs/go1_treat.oasis), and the noise-aware filter trusts them.
This runs the paper's filter and the robot's default controller (loop.controller, `ours`) on the
same seeded trials of the hallway, with the simulated camera's true sigma(d) at 1/3, 1, 3 and 10
times the declared one, and with a true detection probability of 0.6 (a person in view is missed
40% of the time), and prints the accuracy of both and their difference as a Markdown table.

    tests/bench/wrong_camera_matrix.py --oasis-go1 build/default/hw/app/oasis-go1 --trials 48

--check exits with status 1 when the default controller falls more than --margin (0.02) below
the paper's filter in any cell: the acceptance rule of issue 22, which ctest runs.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

# The declared sigma(d) = a + b d + c d^2 of specs/go1_treat.oasis, which the simulated camera
# also uses by default (hw/config/hallway.yaml).
DECLARED_SIGMA = (0.002, 0.002, 0.005)

# (label, sigma factor, true detection probability)
CELLS = [
    ("sigma x 1/3", 1.0 / 3.0, 1.0),
    ("sigma x 1 (declared)", 1.0, 1.0),
    ("sigma x 3", 3.0, 1.0),
    ("sigma x 10", 10.0, 1.0),
    ("detection 0.6 (declared 0.9)", 1.0, 0.6),
]


def scenario_text(factor, detection):
    a, b, c = (factor * x for x in DECLARED_SIGMA)
    return (
        "camera:\n"
        f"  depth_noise_a_m: {a!r}\n"
        f"  depth_noise_b: {b!r}\n"
        f"  depth_noise_c_per_m: {c!r}\n"
        f"  miss_probability: {1.0 - detection!r}\n"
    )


def default_controller(go1):
    """loop.controller of the settings oasis-go1 runs with by default."""
    text = subprocess.run([go1, "config"], check=True, capture_output=True, text=True).stdout
    for line in text.splitlines():
        stripped = line.strip()
        if stripped.startswith("controller:"):
            return stripped.split(":", 1)[1].split("#", 1)[0].strip()
    raise SystemExit("oasis-go1 config printed no loop.controller")


def paper_mode_variant(go1, name, folder):
    """A profile file: `name` with filter.mode paper, everything else the same. It tells what the
    noise-aware filter itself adds under each camera, apart from the tag evidence."""
    text = subprocess.run([go1, "config", "--controller", name], check=True, capture_output=True,
                          text=True).stdout
    lines = []
    for line in text.splitlines():
        if line.strip().startswith("mode:"):
            line = line.split("mode:", 1)[0] + "mode: paper"
        lines.append(line)
    path = os.path.join(folder, f"{name}-paper-mode.yaml")
    with open(path, "w", encoding="utf-8") as out:
        out.write("\n".join(lines) + "\n")
    return path


def accuracy_of(go1, scenario, controllers, trials, seed):
    command = [go1, "sim", "--scenario", scenario, "--controllers", ",".join(controllers),
               "--trials", str(trials), "--seed", str(seed), "--json", "--quiet"]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        raise SystemExit(f"{' '.join(command)} failed:\n{result.stdout}{result.stderr}")
    table = json.loads(result.stdout)
    return [table[os.path.splitext(os.path.basename(name))[0]]["accuracy"]["mean"]
            for name in controllers]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--oasis-go1", required=True, help="the oasis-go1 program")
    parser.add_argument("--trials", type=int, default=48, help="seeded trials per cell")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--margin", type=float, default=0.02,
                        help="how far below the paper's filter the default may fall")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 if the default falls more than --margin below paper")
    args = parser.parse_args()

    ours = default_controller(args.oasis_go1)
    print(f"{args.trials} trials per cell, seed {args.seed}, fast path; default controller: {ours}")
    print()
    print(f"| true camera | paper | {ours} | {ours} - paper | {ours} with filter.mode paper |")
    print("|---|---|---|---|---|")
    failures = []
    with tempfile.TemporaryDirectory() as folder:
        variant = paper_mode_variant(args.oasis_go1, ours, folder)
        for label, factor, detection in CELLS:
            scenario = os.path.join(folder, "scenario.yaml")
            with open(scenario, "w", encoding="utf-8") as out:
                out.write(scenario_text(factor, detection))
            paper, default, same_in_paper_mode = accuracy_of(
                args.oasis_go1, scenario, ["paper", ours, variant], args.trials, args.seed)
            difference = default - paper
            print(f"| {label} | {paper:.3f} | {default:.3f} | {difference:+.3f} | "
                  f"{same_in_paper_mode:.3f} |", flush=True)
            if difference < -args.margin:
                failures.append(label)
    if failures:
        print(f"\n{ours} falls more than {args.margin} below paper in: {', '.join(failures)}")
    return 1 if args.check and failures else 0


if __name__ == "__main__":
    sys.exit(main())
