#!/usr/bin/env python3
"""Checks that every tracked C++ file is formatted as .clang-format says.

    check_format.py [--root REPO] [--clang-format PROGRAM]   list the files that differ, exit 1
    check_format.py --fix                                     format them in place

The generated catalogs (generated/) are left as oasisc writes them: a test proves them
current byte for byte.
"""

import argparse
import pathlib
import subprocess
import sys

SKIPPED = ("generated/",)


def cxx_files(root):
    out = subprocess.run(["git", "-C", str(root), "ls-files", "-z", "--cached", "--others",
                          "--exclude-standard", "*.cpp", "*.hpp", "*.h"],
                         capture_output=True, check=True).stdout.decode()
    return sorted(path for path in set(out.split("\0"))
                  if path and not path.startswith(SKIPPED) and (root / path).is_file())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=pathlib.Path(__file__).resolve().parents[2])
    parser.add_argument("--clang-format", default="clang-format")
    parser.add_argument("--fix", action="store_true", help="format the files in place")
    args = parser.parse_args()
    root = pathlib.Path(args.root)
    files = cxx_files(root)
    if args.fix:
        subprocess.run([args.clang_format, "-i", *files], cwd=root, check=True)
        return 0
    unformatted = []
    for start in range(0, len(files), 200):
        batch = files[start:start + 200]
        result = subprocess.run([args.clang_format, "--dry-run", *batch], cwd=root,
                                capture_output=True, text=True)
        if result.returncode != 0:
            print(result.stderr, end="")
            return 2
        unformatted += sorted({line.split(":", 1)[0] for line in result.stderr.splitlines()
                               if ": warning: code should be clang-formatted" in line})
    for path in unformatted:
        print(f"{path}: error: not formatted as .clang-format says "
              f"(tests/gates/check_format.py --fix, or clang-format -i {path})")
    print(f"{len(files)} C++ files checked, {len(unformatted)} not formatted")
    return 1 if unformatted else 0


if __name__ == "__main__":
    sys.exit(main())
