#!/usr/bin/python3
"""Cross-check oasisc on PRISM programs against published figures (issue 25, item 5).

For every entry of published.json (tests/data/prism/ by default) this runs

    oasisc info FILE [--const C] --json

and compares the reachable `states`, and the first context's `transitions` and `choices`,
with the published ones; then, for every published quotient size,

    oasisc quotient FILE [--const C] --format json --respect-labels R [--choices unlabelled]

and checks that every context (one per reward structure) has the published number of
blocks, then has `oasisc verify` check the partitions independently (a bisimulation, and the
coarsest). It prints one line per model and figure, ours against the published value, and
exits with status 1 on any mismatch or error (0 when every figure matches).

Usage: cross_check.py --oasisc PATH [--data DIR] [--only NAME[,NAME...]] [--timeout S]
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_DATA = os.path.normpath(os.path.join(HERE, "..", "data", "prism"))


def run_json(command, timeout):
    """Runs `command`; returns (parsed JSON of stdout, None) or (None, error message)."""
    try:
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              text=True, timeout=timeout, check=False)
    except subprocess.TimeoutExpired:
        return None, f"timed out after {timeout} s"
    except OSError as error:
        return None, f"cannot run: {error}"
    if done.returncode != 0:
        lines = (done.stderr.strip() or done.stdout.strip()).splitlines()
        shown = "\n      ".join(lines[:8])
        more = f"\n      ... ({len(lines) - 8} more lines)" if len(lines) > 8 else ""
        return None, f"exit status {done.returncode}:\n      {shown}{more}"
    text = done.stdout
    # The JSON object is the first thing on stdout; anything after its end is ignored.
    try:
        value, _ = json.JSONDecoder().raw_decode(text.lstrip())
    except json.JSONDecodeError as error:
        return None, f"output is not JSON ({error}): {text[:200]!r}"
    return value, None


def constants_args(entry):
    constants = entry.get("constants", "")
    return ["--const", constants] if constants else []


def label(entry):
    constants = entry.get("constants", "")
    return f"{entry['file']}" + (f" [{constants}]" if constants else "")


class Report:
    def __init__(self):
        self.failures = 0
        self.checked = 0

    def figure(self, name, what, ours, published):
        self.checked += 1
        ok = ours == published
        if not ok:
            self.failures += 1
        status = "ok  " if ok else "FAIL"
        relation = "=" if ok else "!="
        print(f"{status} {name:<34} {what:<34} ours {ours!s:>9} {relation} published {published}")
        sys.stdout.flush()

    def error(self, name, what, message):
        self.failures += 1
        print(f"FAIL {name:<34} {what:<34} error: {message}")
        sys.stdout.flush()


def check_info(oasisc, path, entry, report, timeout):
    name = label(entry)
    command = [oasisc, "info", path, *constants_args(entry), "--json"]
    started = time.monotonic()
    info, error = run_json(command, timeout)
    if error:
        report.error(name, "info", f"{' '.join(command)}: {error}")
        return
    seconds = time.monotonic() - started
    report.figure(name, f"states ({seconds:.1f} s)", info.get("states"), entry["states"])
    contexts = info.get("contexts") or []
    if not contexts:
        report.error(name, "info", "the JSON has no contexts")
        return
    first = contexts[0]
    if "transitions" in entry:
        report.figure(name, "transitions", first.get("transitions"), entry["transitions"])
    if "choices" in entry:
        report.figure(name, "choices", first.get("choices"), entry["choices"])


def check_quotient(oasisc, path, entry, quotient, report, timeout):
    name = label(entry)
    respect = quotient["respect_labels"]
    semantics = quotient.get("semantics", "labelled")
    shown = respect if len(respect) <= 24 else f"{respect[:20]}...({respect.count(',') + 1})"
    what = f"blocks, labels {shown}" + (" (unlabelled)" if semantics == "unlabelled" else "")
    command = [oasisc, "quotient", path, *constants_args(entry), "--format", "json",
               "--respect-labels", respect]
    if semantics == "unlabelled":
        command += ["--choices", "unlabelled"]
    elif semantics != "labelled":
        report.error(name, what, f"unknown semantics {semantics!r} in published.json")
        return
    result, error = run_json(command, timeout)
    if error:
        report.error(name, what, f"{' '.join(command)}: {error}")
        return
    contexts = result.get("contexts") or []
    if not contexts:
        report.error(name, what, "the JSON has no contexts")
        return
    for context in contexts:
        context_what = what if len(contexts) == 1 else f"{what}, context {context.get('name')}"
        report.figure(name, context_what, context.get("blocks"), quotient["blocks"])
    verify_partitions(oasisc, path, entry, command, name, what, report, timeout)


def verify_partitions(oasisc, path, entry, quotient_command, name, what, report, timeout):
    """Writes the partitions and has `oasisc verify` check them against the program."""
    with tempfile.TemporaryDirectory(prefix="cross_check.") as directory:
        result = os.path.join(directory, "quotient.json")
        command = [*quotient_command, "--partition", "-o", result]
        try:
            done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                  text=True, timeout=timeout, check=False)
            if done.returncode == 0:
                command = [oasisc, "verify", path, *constants_args(entry), result]
                done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                      text=True, timeout=timeout, check=False)
        except subprocess.TimeoutExpired:
            report.error(name, f"{what}, verify", f"{' '.join(command)}: timed out")
            return
        report.checked += 1
        if done.returncode != 0:
            report.error(name, f"{what}, verify", f"{' '.join(command)}: "
                                                   f"{(done.stdout or done.stderr).strip()}")
            return
        print(f"ok   {name:<34} {what + ', verify':<34} bisimulation and coarsest")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--oasisc", required=True, help="the oasisc executable")
    parser.add_argument("--data", default=DEFAULT_DATA,
                        help="folder with published.json and the PRISM programs "
                             f"(default: {DEFAULT_DATA})")
    parser.add_argument("--only", default="",
                        help="check only these files (comma-separated names, e.g. knuth_die.pm)")
    parser.add_argument("--timeout", type=float, default=900.0,
                        help="seconds allowed to each oasisc run (default: 900)")
    args = parser.parse_args()

    oasisc = os.path.abspath(args.oasisc)
    if not (os.path.isfile(oasisc) and os.access(oasisc, os.X_OK)):
        print(f"cross_check: error: {args.oasisc} is not an executable file", file=sys.stderr)
        return 1
    table = os.path.join(args.data, "published.json")
    try:
        with open(table, encoding="utf-8") as stream:
            entries = json.load(stream)["models"]
    except (OSError, ValueError, KeyError) as error:
        print(f"cross_check: error: cannot read {table}: {error}", file=sys.stderr)
        return 1
    only = {name for name in args.only.split(",") if name}
    if only:
        entries = [entry for entry in entries if entry["file"] in only]
        if not entries:
            print(f"cross_check: error: no entry has file {sorted(only)}", file=sys.stderr)
            return 1

    report = Report()
    for entry in entries:
        path = os.path.join(args.data, entry["file"])
        if not os.path.isfile(path):
            report.error(label(entry), "file", f"{path} does not exist")
            continue
        check_info(oasisc, path, entry, report, args.timeout)
        for quotient in entry.get("quotients", []):
            check_quotient(oasisc, path, entry, quotient, report, args.timeout)

    models = len(entries)
    if report.failures:
        print(f"cross_check: FAILED: {report.failures} figure(s) of {models} model instances "
              f"did not match or could not be computed ({report.checked} compared)")
        return 1
    print(f"cross_check: all {report.checked} figures of {models} model instances match "
          "the published ones")
    return 0


if __name__ == "__main__":
    sys.exit(main())
