#!/usr/bin/python3
"""Sweep a constant of a PRISM program, bisimulate, check a property, plot the result.

The bounded retransmission protocol (tests/data/prism/brp.pm) sends a file of N chunks and
retransmits each at most MAX times. For each MAX this builds the model, computes its coarsest
bisimulation respecting the label "error", checks P=? [F "error"] exactly on the model and on
the quotient (they must agree), and writes a plot of the probability against MAX when
matplotlib (Debian's python3-matplotlib) is installed; without it, only the table is printed.

    PYTHONPATH=build/default/python /usr/bin/python3 examples/python/sweep.py \
        [--program tests/data/prism/brp.pm] [--chunks 16] [--max 1,2,3,4] [--plot sweep.png]
"""

import argparse
import pathlib
import sys

import oasis

HERE = pathlib.Path(__file__).resolve().parent
DEFAULT_PROGRAM = HERE.parents[1] / "tests" / "data" / "prism" / "brp.pm"
PROPERTY = 'P=? [F "error"]'


def sweep(program_path, chunks, retries):
    """One row per MAX: (MAX, states, blocks, exact probability of an error)."""
    rows = []
    for max_retries in retries:
        program = oasis.parse_prism_program(program_path,
                                            constants={"N": chunks, "MAX": max_retries})
        model = oasis.build_model(program)
        result = oasis.bisimulate(model, respect_labels=["error"])
        value = oasis.check(model, PROPERTY)
        if oasis.check(result.quotient, PROPERTY) != value:
            raise SystemExit(f"MAX={max_retries}: the quotient disagrees with the model")
        rows.append((max_retries, model.nr_states, result.nr_blocks, value))
    return rows


def plot(rows, path):
    """Writes the plot; False when matplotlib is not installed."""
    try:
        import matplotlib
    except ImportError:
        return False
    matplotlib.use("Agg")  # no display needed
    import matplotlib.pyplot as pyplot

    figure, axes = pyplot.subplots(figsize=(5, 3.5))
    axes.semilogy([r[0] for r in rows], [float(r[3]) for r in rows], marker="o")
    axes.set_xlabel("MAX (retransmissions per chunk)")
    axes.set_ylabel(PROPERTY)
    axes.set_title("bounded retransmission protocol")
    figure.tight_layout()
    figure.savefig(path)
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--program", default=str(DEFAULT_PROGRAM))
    parser.add_argument("--chunks", type=int, default=16, help="the constant N")
    parser.add_argument("--max", default="1,2,3,4", help="values of the constant MAX")
    parser.add_argument("--plot", default="sweep.png", help="where the plot goes")
    args = parser.parse_args()
    rows = sweep(args.program, args.chunks, [int(v) for v in args.max.split(",")])
    print(f"{'MAX':>4} {'states':>8} {'blocks':>7}  {PROPERTY}")
    for max_retries, states, blocks, value in rows:
        # The exact value is a fraction of hundreds of digits: its double, and its length.
        digits = len(str(value.denominator))
        print(f"{max_retries:>4} {states:>8} {blocks:>7}  {float(value):.6e} "
              f"(exact: a fraction over a {digits}-digit denominator)")
    if plot(rows, args.plot):
        print(f"wrote {args.plot}")
    else:
        print("matplotlib is not installed (apt-get install python3-matplotlib): no plot")
    return 0


if __name__ == "__main__":
    sys.exit(main())
