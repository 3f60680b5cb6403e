#!/usr/bin/env python3
"""Runs clang-tidy (.clang-tidy: every finding an error) on the C++ sources changed since a base.

The whole tree takes about an hour of one core, more than CI has to spare, so CI checks what
of compiler/, hw/, common/ and tools/ changed since the base commit in tests/gates/tidy_base: each changed .cpp, and for each changed
header the .cpp of the same name beside it (the header is checked through it). `--all` checks
every source; run it before moving the base forward.

    check_tidy.py --build build/default [--since REV] [--all] [-j N]
"""

import argparse
import concurrent.futures
import json
import os
import pathlib
import re
import subprocess
import sys
import tempfile

# The product's code (and, through it, runtime/'s headers). Tests are left out: they follow
# their frameworks' names (GoogleTest's, Google Benchmark's BM_, libFuzzer's entry point).
CHECKED = ("compiler/", "hw/", "common/", "tools/", "python/")


def changed_since(root, base):
    out = subprocess.run(["git", "-C", str(root), "diff", "--name-only", base, "--"],
                         capture_output=True, text=True, check=True).stdout
    new = subprocess.run(["git", "-C", str(root), "ls-files", "--others", "--exclude-standard"],
                         capture_output=True, text=True, check=True).stdout
    return set(out.split()) | set(new.split())


def sources(root, database, changed):
    compiled = {}
    for entry in database:
        path = pathlib.Path(entry["directory"], entry["file"]).resolve()
        try:
            compiled[path.relative_to(root).as_posix()] = entry
        except ValueError:
            continue
    wanted = set()
    for path in (compiled if changed is None else changed):
        stem_source = path[:-4] + ".cpp" if path.endswith(".hpp") else path
        if stem_source in compiled and stem_source.startswith(CHECKED):
            wanted.add(stem_source)
    return sorted(wanted)


def without_precompiled_headers(database):
    """The database with CMake's precompiled-header flags taken out: the .gch files are g++'s,
    which clang cannot read. Our sources include what they use (the clang-release preset
    builds them without precompiled headers), so nothing else changes."""
    pch = re.compile(r"\s-include\s+\S*cmake_pch\.hxx|\s-Winvalid-pch")
    for entry in database:
        entry["command"] = pch.sub("", entry["command"])  # CMake writes "command" entries
    return database


def tidy(root, build, path):
    # The database is g++'s: clang does not know some of its warning options.
    result = subprocess.run(["clang-tidy", "-p", str(build), "--quiet",
                             "--extra-arg=-Wno-unknown-warning-option", path], cwd=root,
                            capture_output=True, text=True)
    findings = [line for line in result.stdout.splitlines()
                if ": error: " in line or ": warning: " in line]
    return path, result.returncode, findings, result.stdout


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", required=True, help="a build folder with compile_commands.json")
    parser.add_argument("--root", default=pathlib.Path(__file__).resolve().parents[2])
    parser.add_argument("--since", help="the base commit (default: tests/gates/tidy_base)")
    parser.add_argument("--all", action="store_true", help="every source, not only the changed")
    parser.add_argument("-j", type=int, default=os.cpu_count() or 1)
    args = parser.parse_args()
    root = pathlib.Path(args.root).resolve()
    build = pathlib.Path(args.build).resolve()
    database = json.loads((build / "compile_commands.json").read_text())
    base = args.since or (root / "tests/gates/tidy_base").read_text().split()[0]
    files = sources(root, database, None if args.all else changed_since(root, base))
    scratch = tempfile.TemporaryDirectory(prefix="oasis-tidy-")
    (pathlib.Path(scratch.name) / "compile_commands.json").write_text(
        json.dumps(without_precompiled_headers(database)))
    build = pathlib.Path(scratch.name)
    print(f"clang-tidy on {len(files)} sources" + ("" if args.all else f" changed since {base}"),
          flush=True)
    failed = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.j) as pool:
        for path, status, findings, output in pool.map(lambda p: tidy(root, build, p), files):
            if status != 0 or findings:
                failed += 1
                print(output, end="")
                print(f"{path}: clang-tidy found {len(findings)} problem(s)", flush=True)
    print(f"{len(files)} sources checked, {failed} with findings")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
