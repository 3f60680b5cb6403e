#!/usr/bin/env python3
"""Golden diagnostics test: run `oasisc check` on a spec and compare its errors with the
expectations written in the spec itself, in the style of clang -verify:

    // expect-error@+1:14: probabilities sum to 9/10 (0.9), not 1
    s2, L -> 1/2: s1 + 2/5: s2;

`@+N` / `@-N` are relative to the comment's line, `@N` is absolute; the number after the
colon is the column. The message must appear in the reported one. Every reported error must
be expected and every expectation met; oasisc must exit with status 1 and print the
source line and a caret after each error.
"""
import argparse
import re
import subprocess
import sys

EXPECT = re.compile(r"expect-error@([+-]?\d+):(\d+):\s*(.*?)\s*$")
REPORTED = re.compile(r"^(.*?):(\d+):(\d+): error: (.*)$")


def read_expectations(path):
    expectations = []
    with open(path, "rb") as handle:
        raw = handle.read()
    text = raw.decode("utf-8", errors="replace")
    for number, line in enumerate(text.splitlines(), start=1):
        match = EXPECT.search(line)
        if not match:
            continue
        where, column, message = match.groups()
        target = number + int(where) if where[0] in "+-" else int(where)
        expectations.append((target, int(column), message))
    # Binary inputs cannot hold comments: a sidecar FILE.expect holds the lines instead.
    try:
        with open(path + ".expect", encoding="utf-8") as handle:
            for line in handle:
                match = EXPECT.search(line)
                if match:
                    where, column, message = match.groups()
                    expectations.append((int(where), int(column), message))
    except FileNotFoundError:
        pass
    return expectations


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--oasisc", required=True)
    parser.add_argument("spec")
    args = parser.parse_args()

    expectations = read_expectations(args.spec)
    if not expectations:
        print(f"{args.spec}: no expect-error lines: a golden file must expect something")
        return 1
    result = subprocess.run([args.oasisc, "check", "--quiet", args.spec],
                            capture_output=True, text=True, errors="replace", timeout=60)
    output = result.stderr
    lines = output.splitlines()
    failures = []
    if result.returncode != 1:
        failures.append(f"exit status {result.returncode}, expected 1")

    reported = []
    for index, line in enumerate(lines):
        match = REPORTED.match(line)
        if not match:
            continue
        path, line_number, column, message = match.groups()
        if path != args.spec:
            failures.append(f"error names file {path!r}, expected {args.spec!r}")
        # clang shape: the source line, then a caret line.
        if index + 2 >= len(lines) + 1 or "^" not in (lines[index + 2] if index + 2 < len(lines) else ""):
            failures.append(f"no caret line after: {line}")
        reported.append((int(line_number), int(column), message))

    unmatched = list(reported)
    for expected in expectations:
        hit = next((r for r in unmatched if r[0] == expected[0] and r[1] == expected[1]
                    and expected[2] in r[3 - 1]), None)
        if hit is None:
            failures.append("missing error at {}:{}: {}".format(*expected))
        else:
            unmatched.remove(hit)
    for extra in unmatched:
        failures.append("unexpected error at {}:{}: {}".format(*extra))

    if failures:
        print("\n".join(failures))
        print("--- oasisc output ---")
        print(output)
        return 1
    print(f"{args.spec}: {len(expectations)} expected error(s) reported")
    return 0


if __name__ == "__main__":
    sys.exit(main())
