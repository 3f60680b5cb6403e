#!/usr/bin/env python3
"""Proves generated/ current: compiles every shipped spec into a temporary folder with the
oasisc just built and compares the files with generated/SPEC/ byte for byte. On a difference
it prints a unified diff (text files) and the one command that refreshes them. With
--refresh it writes generated/ instead (what scripts/regen runs): one list of specs and
formats for both."""
import argparse
import difflib
import json
import os
import shutil
import subprocess
import sys
import tempfile

# Discrete catalogs also as DOT. Continuous ones without their SVG pictures (4.4 MB for the
# Go1 spec, redrawn by every compile): the catalog is what a review needs to see change.
FORMATS = {"explicit": "cpp,bin,json,dot", "continuous": "cpp,bin,json"}


# Catalogs compiled with other options, each in its own folder: (folder, spec, options).
# The no-attention baseline of `oasis-go1 sim` partitions the Go1 spec's full 4-D state; 8000
# cells keep its compile at seconds (its error bound is loose: it is a baseline, not a result).
VARIANTS = [("go1_treat_no_attention", "go1_treat",
             ["--no-attention", "--max-cells", "8000", "--format", "bin"])]


def spec_kind(oasisc, root, spec):
    info = subprocess.run([oasisc, "info", spec, "--json"], cwd=root, check=True,
                          capture_output=True, text=True)
    return json.loads(info.stdout)["kind"]


def compile_spec(oasisc, root, spec, out, options=None):
    if options is None:
        options = ["--format", FORMATS.get(spec_kind(oasisc, root, spec), FORMATS["explicit"])]
    subprocess.run([oasisc, "compile", spec, "-o", out, *options, "--progress", "never"],
                   cwd=root, check=True, capture_output=True)


def catalogs(root):
    """Every folder of generated/: (folder, spec path, options or None for the defaults)."""
    specs = sorted(f[:-len(".oasis")] for f in os.listdir(os.path.join(root, "specs"))
                   if f.endswith(".oasis"))
    return ([(name, os.path.join("specs", name + ".oasis"), None) for name in specs] +
            [(folder, os.path.join("specs", spec + ".oasis"), options)
             for folder, spec, options in VARIANTS])


def compare(folder, out, name):
    """The stale files of one spec, with diffs of text files printed."""
    expected, actual = sorted(os.listdir(folder)), sorted(os.listdir(out))
    if expected != actual:
        return [f"{folder}: files {expected} but oasisc writes {actual}"]
    stale = []
    for file in expected:
        old = open(os.path.join(folder, file), "rb").read()
        new = open(os.path.join(out, file), "rb").read()
        if old == new:
            continue
        stale.append(os.path.join(folder, file))
        if file.endswith((".cpp", ".hpp", ".dot")):
            sys.stdout.writelines(list(difflib.unified_diff(
                old.decode().splitlines(True), new.decode().splitlines(True),
                fromfile="generated/" + name + "/" + file, tofile="oasisc output"))[:200])
    return stale


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--oasisc", required=True)
    parser.add_argument("--root", required=True)
    parser.add_argument("--refresh", action="store_true", help="write generated/ instead")
    args = parser.parse_args()
    generated = os.path.join(args.root, "generated")
    if args.refresh:
        for name, spec, options in catalogs(args.root):
            folder = os.path.join(generated, name)
            shutil.rmtree(folder, ignore_errors=True)
            compile_spec(args.oasisc, args.root, spec, folder, options)
            print("wrote", folder)
        return 0
    stale = []
    with tempfile.TemporaryDirectory() as scratch:
        for name, spec, options in catalogs(args.root):
            folder = os.path.join(generated, name)
            if not os.path.isdir(folder):
                stale.append(f"{folder}: missing")
                continue
            out = os.path.join(scratch, name)
            compile_spec(args.oasisc, args.root, spec, out, options)
            stale += compare(folder, out, name)
    if stale:
        print("\nstale generated files:\n  " + "\n  ".join(stale))
        print("refresh them with: scripts/regen")
        return 1
    print("generated/ is current")
    return 0


if __name__ == "__main__":
    sys.exit(main())
