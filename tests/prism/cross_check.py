#!/usr/bin/python3
"""Cross-check oasisc on PRISM programs against published figures (issue 25, item 5).

For every entry of published.json (tests/data/prism/ by default) this runs

    oasisc info FILE [--const C] --json

and compares the reachable `states`, and the first context's `transitions` and `choices`,
with the published ones; then, for every published quotient size,

    oasisc quotient FILE [--const C] --format json --respect-labels R [--choices unlabelled]

and checks that every context (one per reward structure) has the published number of
blocks, then has `oasisc verify` check the partitions independently (a bisimulation, and the
coarsest). Then, for every published property value (issue 39, item 7), once per mode
(exact and sound unless the entry says otherwise)

    oasisc query FILE [--const C] --mode M [--precision P] --prop 'PROPERTY; ...'

and checks each answer against the published figure: an exact rational must equal a published
fraction, or lie in the range a published decimal stands for (d printed with n digits after
the point: [d - 0.5*10^-n, d + 0.5*10^-n], or [d - t, d + t] where the source asserts only a
tolerance t); a sound interval must contain the fraction, or meet the decimal's range, and be
at most the entry's sound_precision wide; verdicts and infinity must be the published ones.
A long fraction that oasisc prints only as "about X (an exact fraction of N characters)" is
compared as far as it is printed (its six digits and its length) and reported as partial.
A program written by a generator (an entry's generated_by: the script, relative to the
repository, and its arguments) must be byte for byte what the generator writes now.

It prints one line per model and figure, ours against the published value, and exits with
status 1 on any mismatch or error (0 when every figure matches).

Usage: cross_check.py --oasisc PATH [--data DIR] [--only NAME[,NAME...]] [--timeout S]
                      [--no-properties | --properties-only]
"""

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from fractions import Fraction

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
        self.partial = 0

    def figure(self, name, what, ours, published):
        self.checked += 1
        ok = ours == published
        if not ok:
            self.failures += 1
        status = "ok  " if ok else "FAIL"
        relation = "=" if ok else "!="
        print(f"{status} {name:<34} {what:<34} ours {ours!s:>9} {relation} published {published}")
        sys.stdout.flush()

    def property(self, name, what, status, ours, prop, detail, line):
        """One property answer against its published figure (status ok, partial or FAIL)."""
        self.checked += 1
        if status == "FAIL":
            self.failures += 1
        if status == "partial":
            self.partial += 1
        published = shown(prop["published"])
        if "tolerance" in prop:
            published += f" +- {prop['tolerance']:g}"
        relation = {"ok": "=", "partial": "~", "FAIL": "!="}[status]
        shown_status = {"ok": "ok  ", "partial": "ok~ ", "FAIL": "FAIL"}[status]
        print(f"{shown_status} {name:<34} {what:<34} ours {ours} {relation} published {published}"
              + (f"  ({detail})" if detail else ""))
        if status == "FAIL":
            print(f"     oasisc: {line}")
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


def check_generated(path, entry, report, checked):
    """A generated program (generated_by) must be what its generator writes today: the figures
    checked on the file are then the generator's."""
    command = entry.get("generated_by")
    if not command or (path, tuple(command)) in checked:
        return
    checked.add((path, tuple(command)))
    root = os.path.normpath(os.path.join(HERE, "..", ".."))
    script = os.path.join(root, command[0])
    try:
        done = subprocess.run([sys.executable, script, *command[1:]], stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True, timeout=60, check=False)
        with open(path, encoding="utf-8") as stream:
            current = stream.read()
    except (OSError, subprocess.TimeoutExpired) as error:
        report.error(label(entry), "generated", f"{' '.join(command)}: {error}")
        return
    if done.returncode != 0:
        report.error(label(entry), "generated", f"{' '.join(command)}: {done.stderr.strip()[:300]}")
        return
    report.figure(entry["file"], f"= {os.path.basename(command[0])} output",
                  "same" if done.stdout == current else "differs", "same")


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


# ---- published property values (issue 39, item 7) ------------------------------------------

# `oasisc query` answers one property a line, e.g.
#   P=? [F "one"] = 1/6 (about 0.1666666667)  [exact: ...]
#   P=? [F "one"] = about 3.3288e-1 (an exact fraction of 60 characters)  [exact: ...]
#   Pmin=? [F "two"] in [0.0277777165, 0.0277778133]  [sound: ...]
#   P<0.9 [F "all_coins_equal_1"] is true in the initial state  [...]
#   Rmax=? [F "all_coins_equal_1"] = infinity  [...]
# The property's text comes first, as given; the rest is one of these forms.
ANSWER_FORMS = [
    ("infinity", re.compile(r"^ = infinity  \[(?P<method>.*)\]$")),
    ("rational", re.compile(r"^ = (?P<value>-?\d+(?:/\d+)?)(?: \(about [^)]*\))?  \[(?P<method>.*)\]$")),
    ("long", re.compile(r"^ = about (?P<approx>\S+) \(an exact fraction of (?P<chars>\d+) characters\)"
                        r"  \[(?P<method>.*)\]$")),
    ("interval", re.compile(r"^ in \[(?P<lo>[^,\]]+), (?P<hi>[^\]]+)\]  \[(?P<method>.*)\]$")),
    ("verdict", re.compile(r"^ is (?P<truth>true|false) in the initial state  \[(?P<method>.*)\]$")),
]
MODES = ("exact", "sound")
DEFAULT_SOUND_PRECISION = 1e-6


def parse_answer(rest):
    """The part of an answer line after the property: (form, fields) or (None, None)."""
    for form, pattern in ANSWER_FORMS:
        match = pattern.match(rest)
        if match:
            return form, match.groupdict()
    return None, None


def published_range(prop):
    """The values the published figure stands for, as exact bounds (lo, hi); None if not a number."""
    form = prop["form"]
    text = prop["published"]
    if form == "fraction":
        value = Fraction(text)
        return value, value
    if form == "decimal":
        value = Fraction(text)  # exact: Fraction reads the decimal text, not a double
        if "tolerance" in prop:
            half = Fraction(str(prop["tolerance"]))
        else:
            digits = len(text.split(".", 1)[1]) if "." in text else 0
            half = Fraction(1, 2 * 10 ** digits)
        return value - half, value + half
    return None


def shown(value, limit=40):
    """A fraction or figure for the report: a long exact fraction as its leading digits, its
    length and a decimal approximation."""
    text = str(value)
    if len(text) <= limit:
        return text
    approximate = f", about {float(Fraction(text)):.15g}" if "/" in text else ""
    return f"{text[:limit - 14]}...({len(text)} chars{approximate})"


def judge(prop, mode, precision, form, fields):
    """Compares one answer with the published figure: (status, ours, detail); status is 'ok',
    'partial' (agrees as far as oasisc prints it) or 'FAIL'."""
    kind = prop["form"]
    if form is None:
        return "FAIL", "?", "the answer line has an unknown form"
    if kind == "verdict":
        if form != "verdict":
            return "FAIL", form, "expected a verdict (true or false in the initial state)"
        ok = fields["truth"] == prop["published"]
        return ("ok" if ok else "FAIL"), fields["truth"], ""
    if kind == "infinity":
        return ("ok" if form == "infinity" else "FAIL"), ("infinity" if form == "infinity" else form), ""
    if form in ("infinity", "verdict"):
        return "FAIL", form, "expected a number"
    low, high = published_range(prop)
    if form == "rational":
        value = Fraction(fields["value"])
        ok = low <= value <= high
        return ("ok" if ok else "FAIL"), shown(value), (printed_digits_note(prop, value, value) if ok
                                                       else "outside the published figure's range")
    if form == "long":
        # oasisc prints a long fraction to six digits only: compare what it prints.
        approx = Fraction(fields["approx"])
        exponent = int(fields["approx"].lower().split("e")[1]) if "e" in fields["approx"].lower() else 0
        unit = Fraction(10) ** (exponent - 5)  # one unit in the sixth significant digit
        ours = f"about {fields['approx']} ({fields['chars']} chars)"
        if not (approx - unit <= high and low <= approx + unit):
            return "FAIL", ours, "its six digits are outside the published figure's range"
        if kind == "fraction" and int(fields["chars"]) != len(str(Fraction(prop["published"]))):
            return "FAIL", ours, (f"the published fraction has {len(str(Fraction(prop['published'])))} "
                                  "characters")
        return "partial", ours, "oasisc prints six digits and the length of the exact fraction"
    # an interval [lo, hi] (sound mode)
    lo, hi = Fraction(float(fields["lo"])), Fraction(float(fields["hi"]))
    ours = f"[{fields['lo']}, {fields['hi']}]"
    if mode == "exact":
        return "FAIL", ours, "exact mode gave an interval"
    if hi - lo > Fraction(str(precision)):
        return "FAIL", ours, f"wider than the precision {precision}"
    if kind == "fraction" and not lo <= low <= hi:
        return "FAIL", ours, "does not contain the published value"
    if not (lo <= high and low <= hi):
        return "FAIL", ours, "does not meet the published figure's range"
    return "ok", ours, printed_digits_note(prop, lo, hi)


def printed_digits_note(prop, lo, hi):
    """Where a decimal is checked to the source's tolerance: how far ours is from the range its
    printed digits stand for (empty when ours meets that range too)."""
    if prop["form"] != "decimal" or "tolerance" not in prop:
        return ""
    text = prop["published"]
    half = Fraction(1, 2 * 10 ** (len(text.split(".", 1)[1]) if "." in text else 0))
    low, high = Fraction(text) - half, Fraction(text) + half
    if lo <= high and low <= hi:
        return "within the source's tolerance and its printed digits"
    gap = low - hi if hi < low else lo - high
    return f"within the source's tolerance; {float(gap):.3g} outside the range of its printed digits"


def check_properties(oasisc, path, entry, report, timeout):
    """Answers every published property of the entry with `oasisc query`, once per mode (one run
    per mode for all of them), and compares each answer with the published figure."""
    name = label(entry)
    properties = entry.get("properties", [])
    precision = entry.get("sound_precision", DEFAULT_SOUND_PRECISION)
    for mode in MODES:
        chosen = [prop for prop in properties if mode in prop.get("modes", MODES)]
        if not chosen:
            continue
        command = [oasisc, "query", path, *constants_args(entry), "--mode", mode,
                   "--prop", "; ".join(prop["property"] for prop in chosen)]
        if mode == "sound":
            command += ["--precision", repr(precision)]
        started = time.monotonic()
        try:
            done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                  text=True, timeout=timeout, check=False)
        except subprocess.TimeoutExpired:
            report.error(name, f"query ({mode})", f"timed out after {timeout} s")
            continue
        except OSError as error:
            report.error(name, f"query ({mode})", f"cannot run: {error}")
            continue
        seconds = time.monotonic() - started
        lines = [line for line in done.stdout.splitlines() if line.strip()]
        for prop in chosen:
            text = prop["property"].strip()
            what = f"{text} ({mode})"
            line = next((line for line in lines if line.startswith(text + " ")), None)
            if line is None:
                problem = (done.stderr.strip() or f"exit status {done.returncode}, no answer")
                report.error(name, what, f"no answer: {problem.splitlines()[0] if problem else ''}")
                continue
            lines.remove(line)
            form, fields = parse_answer(line[len(text):])
            status, ours, detail = judge(prop, mode, precision, form, fields)
            report.property(name, what, status, ours, prop, detail, line)
        if done.returncode != 0:
            report.error(name, f"query ({mode}, {seconds:.1f} s)",
                         f"exit status {done.returncode}: {done.stderr.strip()[:300]}")


def answers_by_property(lines, chosen):
    """Each chosen property's answer without its method: what two runs must agree on."""
    found = {}
    for prop in chosen:
        text = prop["property"].strip()
        line = next((line for line in lines if line.startswith(text + " ")), None)
        if line is not None:
            lines.remove(line)
            found[text] = line[len(text):].split("  [", 1)[0].strip()
    return found


def check_quotient_answers(oasisc, path, entry, report, timeout):
    """Issue 39, item 3: every property answered on the bisimulation quotient (--bisimulation)
    equals its answer on the model, rational for rational (exact mode, fractions printed whole)."""
    name = label(entry)
    chosen = [prop for prop in entry.get("properties", []) if "exact" in prop.get("modes", MODES)]
    if not chosen:
        return
    base = [oasisc, "query", path, *constants_args(entry), "--mode", "exact", "--whole-fractions",
            "--prop", "; ".join(prop["property"] for prop in chosen)]
    runs = []
    for extra in ([], ["--bisimulation"]):
        try:
            done = subprocess.run(base + extra, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                  text=True, timeout=timeout, check=False)
        except (subprocess.TimeoutExpired, OSError) as error:
            report.error(name, "query --bisimulation", f"cannot run: {error}")
            return
        runs.append(answers_by_property([l for l in done.stdout.splitlines() if l.strip()], chosen))
    on_model, on_quotient = runs
    for text, answer in on_model.items():
        ours = on_quotient.get(text, "no answer")
        if ours == answer and len(answer) > 40:  # a fraction printed whole: shown shortened
            ours = answer = answer[:37] + "..."
        report.figure(name, f"{text} on the quotient", ours, answer)


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
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--no-properties", action="store_true",
                       help="check the model figures only, not the published property values")
    group.add_argument("--properties-only", action="store_true",
                       help="check the published property values only")
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
    generated = set()
    for entry in entries:
        path = os.path.join(args.data, entry["file"])
        if not os.path.isfile(path):
            report.error(label(entry), "file", f"{path} does not exist")
            continue
        check_generated(path, entry, report, generated)
        if not args.properties_only:
            check_info(oasisc, path, entry, report, args.timeout)
            for quotient in entry.get("quotients", []):
                check_quotient(oasisc, path, entry, quotient, report, args.timeout)
        if not args.no_properties:
            check_properties(oasisc, path, entry, report, args.timeout)
            check_quotient_answers(oasisc, path, entry, report, args.timeout)

    models = len(entries)
    if report.partial:
        print(f"cross_check: {report.partial} property answer(s) compared only as far as oasisc "
              "prints them (a long exact fraction: six digits and its length)")
    if report.failures:
        print(f"cross_check: FAILED: {report.failures} figure(s) of {models} model instances "
              f"did not match or could not be computed ({report.checked} compared)")
        return 1
    print(f"cross_check: all {report.checked} figures of {models} model instances match "
          "the published ones")
    return 0


if __name__ == "__main__":
    sys.exit(main())
