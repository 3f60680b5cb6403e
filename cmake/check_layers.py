#!/usr/bin/env python3
"""Checks that the compiler's layers include only from the layers they link.

The rules come from compiler/CMakeLists.txt, which writes one line per layer at configure
time ("geom: model"), naming the layers it links directly. A file of a layer may include
headers of its own layer and of every layer it reaches through those links; an include of
any other layer's header is a crossing the wrong way (or sideways), and fails the check.

    check_layers.py --rules FILE --root compiler [--layer geom]   check one layer, or all
    check_layers.py --rules FILE --root compiler --self-test      plant a wrong include in a
                                                                  copy and expect a failure
"""

import argparse
import pathlib
import re
import shutil
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s+"([A-Za-z_]+)/[^"]+"', re.MULTILINE)
# "../geom/grid.hpp" would reach another layer past the check: includes name their layer.
RELATIVE = re.compile(r'^\s*#\s*include\s+"\.\./', re.MULTILINE)


def read_rules(path):
    direct = {}
    for line in pathlib.Path(path).read_text().splitlines():
        if not line.strip():
            continue
        layer, _, below = line.partition(":")
        direct[layer.strip()] = below.split()
    return direct


def reachable(direct, layer):
    seen, stack = {layer}, [layer]
    while stack:
        for below in direct.get(stack.pop(), []):
            if below not in seen:
                seen.add(below)
                stack.append(below)
    return seen


def cycles(direct):
    """Layers that reach themselves through their links: the layers must form a ladder."""
    return [layer for layer in sorted(direct)
            if any(layer in reachable(direct, below) for below in direct[layer])]


def crossings(root, direct, layers):
    """(file, line, included layer, layer) for every include that leaves the allowed set."""
    found = []
    for layer in layers:
        allowed = reachable(direct, layer)
        for path in sorted((root / layer).glob("*.[ch]pp")):
            text = path.read_text(errors="replace")
            for match in INCLUDE.finditer(text):
                target = match.group(1)
                if target in direct and target not in allowed:
                    line = text.count("\n", 0, match.start()) + 1
                    found.append((path, line, target, layer))
            for match in RELATIVE.finditer(text):
                line = text.count("\n", 0, match.start()) + 1
                found.append((path, line, "..", layer))
    return found


def report(found, direct):
    for path, line, target, layer in found:
        if target == "..":
            print(f"{path}:{line}: error: a relative include; name the layer "
                  f'(#include "geom/grid.hpp"), so that the layer check sees it')
            continue
        allowed = " ".join(sorted(reachable(direct, layer) - {layer})) or "nothing"
        print(f"{path}:{line}: error: layer '{layer}' includes a header of '{target}', "
              f"which it does not link (it may include: {allowed}; "
              f"compiler/CMakeLists.txt declares the links)")
    return 1 if found else 0


def self_test(root, direct):
    """The check must fail on a verify file that includes a geom or a frontend header, or
    any header by a relative path."""
    with tempfile.TemporaryDirectory() as scratch:
        copy = pathlib.Path(scratch) / "compiler"
        shutil.copytree(root, copy, ignore=shutil.ignore_patterns("*.o", "CMakeFiles"))
        if crossings(copy, direct, sorted(direct)):
            print("self-test: the unmodified copy already fails")
            return 1
        victim = sorted((copy / "verify").glob("*.cpp"))[0]
        planted = 0
        for header, target in (("geom/grid.hpp", "geom"), ("frontend/load_spec.hpp", "frontend"),
                               ("../geom/grid.hpp", "..")):
            original = victim.read_text()
            victim.write_text(f'#include "{header}"\n' + original)
            found = crossings(copy, direct, ["verify"])
            victim.write_text(original)
            if len(found) != 1 or found[0][2] != target:
                print(f"self-test: an include of {header} in {victim.name} was not caught")
                return 1
            report(found, direct)
            planted += 1
        print(f"self-test: {planted} wrong includes planted in verify/{victim.name}, "
              f"{planted} caught")
        return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rules", required=True, help="layer: links, one line per layer")
    parser.add_argument("--root", required=True, help="the compiler folder")
    parser.add_argument("--layer", help="check this layer only (default: all)")
    parser.add_argument("--stamp", help="touch this file when the check passes")
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args()
    direct = read_rules(args.rules)
    root = pathlib.Path(args.root)
    if args.self_test:
        return self_test(root, direct)
    for layer in cycles(direct):
        print(f"{args.rules}: error: layer '{layer}' links a layer that links it back")
    if cycles(direct):
        return 1
    layers = [args.layer] if args.layer else sorted(direct)
    status = report(crossings(root, direct, layers), direct)
    if status == 0 and args.stamp:
        pathlib.Path(args.stamp).touch()
    return status


if __name__ == "__main__":
    sys.exit(main())
