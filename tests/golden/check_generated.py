#!/usr/bin/env python3
"""Proves generated/ current: compiles every spec that has a folder in generated/ into a
temporary folder with the oasisc just built, and compares the files byte for byte. On a
difference it prints a unified diff (text files) and the one command that refreshes them."""
import argparse
import difflib
import os
import subprocess
import sys
import tempfile


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--oasisc", required=True)
    parser.add_argument("--root", required=True)
    args = parser.parse_args()
    generated = os.path.join(args.root, "generated")
    stale = []
    with tempfile.TemporaryDirectory() as scratch:
        for name in sorted(os.listdir(generated)):
            folder = os.path.join(generated, name)
            if not os.path.isdir(folder):
                continue
            spec = os.path.join("specs", name + ".oasis")
            out = os.path.join(scratch, name)
            subprocess.run([args.oasisc, "compile", spec, "-o", out, "--format", "cpp,bin,json,dot",
                            "--progress", "never"], cwd=args.root, check=True, capture_output=True)
            expected, actual = sorted(os.listdir(folder)), sorted(os.listdir(out))
            if expected != actual:
                stale.append(f"{folder}: files {expected} but oasisc writes {actual}")
                continue
            for file in expected:
                old = open(os.path.join(folder, file), "rb").read()
                new = open(os.path.join(out, file), "rb").read()
                if old == new:
                    continue
                stale.append(os.path.join(folder, file))
                if not file.endswith(".bin"):
                    sys.stdout.writelines(difflib.unified_diff(
                        old.decode().splitlines(True), new.decode().splitlines(True),
                        fromfile="generated/" + name + "/" + file, tofile="oasisc output"))
    if stale:
        print("\nstale generated files:\n  " + "\n  ".join(stale))
        print("refresh them with: scripts/regen")
        return 1
    print("generated/ is current")
    return 0


if __name__ == "__main__":
    sys.exit(main())
