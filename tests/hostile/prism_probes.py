#!/usr/bin/env python3
"""Hostile PRISM input (issue 37), run as a user would: PRISM programs and explicit .lab files
that PRISM itself refuses, each given to oasisc check, quotient and export. Every probe asserts
exit status 1, a located message (FILE:LINE:COL) naming the culprit, a few lines at most, no
crash text, and that nothing was written:
  programs  two synchronised writes of one global; mod by a negative divisor, in a constant
            and over the state; an empty and a comment-only file; a renamed formula;
  labels    a .lab with two "init"s, a repeated label name, a NUL in a name, an empty name.
Run by ctest (-L hostile):

    tests/hostile/prism_probes.py --oasisc B/compiler/oasisc
"""

import argparse
import os
import sys
import tempfile

from probe_harness import report, run_probe, snapshot, write_bytes

GLOBAL_WRITES = b"""mdp
global g : [0..2] init 0;
module a
  x : [0..1] init 0;
  [s] x = 0 -> (x'=1) & (g'=1);
endmodule
module b
  y : [0..1] init 0;
  [s] y = 0 -> (y'=1) & (g'=2);
endmodule
"""

MOD_CONSTANT = b"""dtmc
module m
  x : [0..3] init 0;
  [] x = 0 -> (x'=mod(7, -3));
endmodule
"""

MOD_STATE = b"""dtmc
module m
  x : [0..3] init 0;
  [] true -> (x'=mod(7, x - 2));
endmodule
"""

RENAMED_FORMULA = b"""mdp
formula f = x = 0;
module m1
  x : [0..1] init 0;
  [] f -> (x'=1);
endmodule
module m2 = m1 [x=y, f=g] endmodule
"""

# (file name, contents, the text the message must hold)
PROGRAMS = [
    ("globals.nm", GLOBAL_WRITES, "globals.nm:5:26: error: global variable 'g'"),
    ("mod_constant.pm", MOD_CONSTANT, "mod_constant.pm:4:19: error: mod(7, -3)"),
    ("mod_state.pm", MOD_STATE, "mod(7, -2): the divisor must be positive"),
    ("empty.pm", b"", "empty.pm:1:1: error: the program declares no module"),
    ("comments.pm", b"// nothing\n// here\n", "comments.pm:1:1: error: the program declares no"),
    ("renamed_formula.nm", RENAMED_FORMULA, "renamed_formula.nm:7:22: error: formula 'f'"),
]

TRANSITIONS = b"2 2 2\n0 0 1 1\n1 0 1 1\n"

LABELS = [
    ("two_inits", b'0="init" 1="init"\n0: 0 1\n', "two_inits.lab:1:13: error: label 'init'"),
    ("repeated", b'0="init" 1="a" 2="a"\n0: 0\n', "repeated.lab:1:19: error: label 'a'"),
    ("nul", b'0="init" 1="a\0b"\n0: 0\n', "nul.lab:1:14: error: a label name cannot hold a NUL"),
    ("empty_name", b'0="init" 1=""\n0: 0\n', "empty_name.lab:1:13: error: empty label name"),
]


def probes(oasisc, scratch):
    """(program arguments, status, text the message names), the inputs written to `scratch`."""
    out = os.path.join(scratch, "out")
    commands = [
        lambda path: [oasisc, "check", path],
        lambda path: [oasisc, "quotient", path],
        lambda path: [oasisc, "export", path, "--format", "prism", "-o", out],
        lambda path: [oasisc, "export", path, "--format", "aut", "-o", out + ".aut"],
    ]
    result = []
    for name, text, culprit in PROGRAMS:
        path = os.path.join(scratch, name)
        write_bytes(path, text)
        result += [(command(path), 1, culprit) for command in commands]
    for name, text, culprit in LABELS:
        base = os.path.join(scratch, name)
        write_bytes(base + ".tra", TRANSITIONS)
        write_bytes(base + ".lab", text)
        result += [(command(base + ".tra"), 1, culprit) for command in commands]
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--oasisc", required=True)
    args = parser.parse_args()
    failures = []
    with tempfile.TemporaryDirectory(prefix="prism_probes.") as scratch:
        cases = probes(os.path.abspath(args.oasisc), scratch)
        before = snapshot(scratch)
        for arguments, status, culprit in cases:
            failure = run_probe(arguments, status, culprit)
            if failure:
                failures.append(failure)
        if snapshot(scratch) != before:
            failures.append("a refused command wrote into " + scratch)
    return report(failures, len(cases))


if __name__ == "__main__":
    sys.exit(main())
