#!/usr/bin/env python3
"""The ARCH-COMP stochastic benchmarks of specs/arch/ at a small size, run by ctest (-L arch).

Each test takes one shipped spec and copies it to a temporary folder with its `grid ...;`
statement replaced by a small grid (the table SMALL below), everything else byte for byte, so
the spec that ships is the spec that is tested, inputs included. Then:

  compile  `oasisc compile SMALL.oasis -o OUT` exits 0 and writes OUT/NAME.controller.json, an
           oasis-controller whose grid has the small grid's cells and whose lower and upper
           arrays hold one number per cell with 0 <= lower <= upper <= 1 (docs/guarantees.md);
  verify   the same compile, then `oasisc verify SMALL.oasis OUT/NAME.controller.json
           --samples 500 --cells 10` exits 0.

    tests/arch/arch_specs.py --oasisc B/compiler/oasisc --spec specs/arch/van_der_pol.oasis
    tests/arch/arch_specs.py --oasisc B/compiler/oasisc --spec ... --step verify

The full-size compiles are not tests; tests/bench/arch_benchmarks.py times them.
"""

import argparse
import json
import math
import pathlib
import re
import subprocess
import sys
import tempfile

# Per shipped spec (by file stem): the small grid, cells per variable in the spec's order.
# Each test takes well under a second (specs/arch/README.md, "Tests").
SMALL = {
    "van_der_pol": {"x1": 8, "x2": 8},
    "bas4d": {"x1": 3, "x2": 3, "x3": 3, "x4": 3},
    "integrator2": {"x1": 8, "x2": 8},
    "integrator3": {"x1": 4, "x2": 4, "x3": 4},
    "patrol_robot": {"x": 8, "y": 8},
    "vehicle": {"x": 4, "y": 4, "theta": 4},
}

# The grid statement starts a line (after blanks) and ends at the first ';'.
GRID = re.compile(r"(?m)^[ \t]*(grid\b[^;]*;)")


def small_spec(name, text):
    """The shipped spec's text with its grid statement replaced by SMALL[name]'s."""
    if name not in SMALL:
        sys.exit(f"error: no small grid for '{name}': add one to SMALL in {__file__}")
    matches = list(GRID.finditer(text))
    if len(matches) != 1:
        sys.exit(f"error: the spec has {len(matches)} grid statements; the test replaces one")
    start, end = matches[0].span(1)
    grid = ", ".join(f"{variable} : {cells}" for variable, cells in SMALL[name].items())
    return text[:start] + f"grid {grid};" + text[end:]


def run(command, timeout):
    print("$ " + " ".join(str(part) for part in command), flush=True)
    try:
        result = subprocess.run([str(part) for part in command], capture_output=True, text=True,
                                timeout=timeout, check=False)
    except subprocess.TimeoutExpired:
        sys.exit(f"error: no answer within {timeout} s")
    sys.stdout.write(result.stdout)
    sys.stdout.write(result.stderr)
    if result.returncode != 0:
        sys.exit(f"error: exit status {result.returncode}, expected 0")


def number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def check_controller(path, name, grid):
    """Exits with a message unless PATH is NAME's controller over GRID's cells with bounds in
    [0, 1], lower below upper; returns the number of cells and the two bounds' means."""
    try:
        controller = json.loads(path.read_text())
    except (OSError, ValueError) as error:
        sys.exit(f"error: {path}: {error}")
    problems = []
    if controller.get("format") != "oasis-controller":
        problems.append(f"format is {controller.get('format')!r}, not 'oasis-controller'")
    if controller.get("model") != name:
        problems.append(f"model is {controller.get('model')!r}, not {name!r}")
    variables = controller.get("variables")
    if variables != list(grid):
        problems.append(f"variables are {variables!r}, expected {list(grid)!r}")
    axes = controller.get("grid")
    cells = [axis.get("cells") if isinstance(axis, dict) else None
             for axis in (axes if isinstance(axes, list) else [])]
    if cells != list(grid.values()):
        problems.append(f"the grid's cells are {cells!r}, expected {list(grid.values())!r}")
    count = math.prod(grid.values())
    lower, upper = controller.get("lower"), controller.get("upper")
    for key, values in (("lower", lower), ("upper", upper)):
        if not isinstance(values, list) or len(values) != count:
            size = len(values) if isinstance(values, list) else type(values).__name__
            problems.append(f"'{key}' has {size} entries, expected one per cell ({count})")
    if not problems:
        bad = [cell for cell in range(count)
               if not (number(lower[cell]) and number(upper[cell])
                       and 0 <= lower[cell] <= upper[cell] <= 1)]
        if bad:
            problems.append(f"{len(bad)} cell(s) without 0 <= lower <= upper <= 1, the first "
                            f"cell {bad[0]}: lower {lower[bad[0]]!r}, upper {upper[bad[0]]!r}")
    if problems:
        sys.exit(f"error: {path}:\n  " + "\n  ".join(problems))
    return count, sum(lower) / count, sum(upper) / count


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--oasisc", required=True)
    parser.add_argument("--spec", required=True, type=pathlib.Path)
    parser.add_argument("--step", choices=("compile", "verify"), default="compile")
    parser.add_argument("--timeout", type=float, default=300, help="seconds per command")
    args = parser.parse_args()

    name = args.spec.stem
    shipped = args.spec.read_text()
    text = small_spec(name, shipped)
    with tempfile.TemporaryDirectory(prefix=f"arch_{name}_") as folder:
        folder = pathlib.Path(folder)
        spec = folder / f"{name}.oasis"
        spec.write_text(text)
        out = folder / "out"
        run([args.oasisc, "compile", spec, "-o", out], args.timeout)
        controller = out / f"{name}.controller.json"
        cells, lower, upper = check_controller(controller, name, SMALL[name])
        print(f"{name}: {cells} cells, bounds in [0, 1] with lower <= upper "
              f"(lower mean {lower:.6f}, upper mean {upper:.6f})")
        if args.step == "verify":
            run([args.oasisc, "verify", spec, controller, "--samples", "500", "--cells", "10"],
                args.timeout)
            print(f"{name}: verify accepts the controller")
    return 0


if __name__ == "__main__":
    sys.exit(main())
