#!/usr/bin/env python3
"""A user's plain build, without the presets: configure with CMake's default generator (Unix
Makefiles on Linux) in Release, then build the layer check and the bottom compiler layer.

The presets use Ninja, which creates the folders of a custom command's outputs; Make does not,
and a build step that assumed otherwise once stopped every plain build at its first step. This
builds enough to pass through the steps that run before any compiler (the layer check) and one
library, in a temporary folder that is removed afterwards.

    plain_build.py --source REPO [--keep]
"""

import argparse
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile


def run(command, cwd):
    print("+ " + " ".join(command), flush=True)
    environment = {name: value for name, value in os.environ.items()
                   if name not in ("CMAKE_GENERATOR", "CMAKE_BUILD_PARALLEL_LEVEL")}
    return subprocess.run(command, cwd=cwd, env=environment).returncode


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True)
    parser.add_argument("--keep", action="store_true", help="keep the build folder")
    args = parser.parse_args()
    folder = pathlib.Path(tempfile.mkdtemp(prefix="oasis-plain-build-"))
    try:
        configure = ["cmake", "-S", args.source, "-B", str(folder), "-DCMAKE_BUILD_TYPE=Release",
                     "-DOASIS_BUILD_TESTS=OFF", "-DOASIS_BUILD_BENCHMARKS=OFF"]
        if run(configure, folder) != 0:
            return 1
        cache = (folder / "CMakeCache.txt").read_text()
        if "CMAKE_GENERATOR:INTERNAL=Unix Makefiles" not in cache:
            print("plain build: the default generator is not Unix Makefiles here")
            return 1
        if run(["cmake", "--build", str(folder), "--target", "oasis_support", "--", "-j2"],
               folder) != 0:
            return 1
        if not (folder / "layers" / "tree.checked").is_file():
            print("plain build: the layer check did not run before the library")
            return 1
        print("plain build: configured with Unix Makefiles, layer check and oasis_support built")
        return 0
    finally:
        if args.keep:
            print(f"kept {folder}")
        else:
            shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
