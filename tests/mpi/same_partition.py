#!/usr/bin/env python3
"""The distributed engine computes the sequential engine's partition.

For random models (half of them built around a hidden lumping, so that blocks are large; one
in ten a chain, which needs as many rounds as states; some with probabilities whose common denominator passes 62
bits, which forces exact rational sums), planted models, and every shipped model that can be
written as .aut, runs `oasisc quotient --format json --partition` once and
`mpirun -np P oasisc-mpi` at each P given, all models of one P in one mpirun, and requires
the same partition (both are canonical: blocks in order of their smallest state). At the
largest P the quotient MDP written with `--format aut` must equal `oasisc quotient --format
aut`'s byte for byte. A few results also go through `oasisc verify`, which must accept the MPI
engine's JSON unchanged.
"""

import argparse
import json
import os
import random
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

from mpi_run import mpirun, start_work

DENOMINATORS = [2, 3, 4, 5, 6, 8, 10, 12]
HUGE = [2**61 - 1, 2**63 + 7, 3**41]  # their lcm passes 2^62: rational sums


def random_split(rng, mass, parts, denominators):
    """`mass` cut into `parts` positive fractions."""
    if parts == 1:
        return [mass]
    d = rng.choice(denominators)
    cuts = []
    rest = mass
    for _ in range(parts - 1):
        piece = rest * Fraction(rng.randint(1, d - 1), d)
        cuts.append(piece)
        rest -= piece
    cuts.append(rest)
    return cuts


def aut_line(source, action, reward, row):
    label = action if reward == 0 else f"{action}|reward({reward})"
    targets = []
    for i, (target, p) in enumerate(row):
        targets.append(str(target))
        if i + 1 < len(row):
            targets.append(f"{p.numerator}/{p.denominator}")
    return f'({source},"{label}",{" ".join(targets)})'


def chain_model(rng):
    """A chain whose last state alone has a reward: refinement needs about n rounds, the
    engine's worst case."""
    n = rng.randint(2, 40)
    lines = [(s, "a", 0, [(s + 1, Fraction(1))]) for s in range(n - 1)]
    lines.append((n - 1, "a", 1, [(n - 1, Fraction(1))]))
    rng.shuffle(lines)
    return "\n".join([f"des (0,{n},{n})"] + [aut_line(*line) for line in lines]) + "\n"


def random_model(rng, lumped):
    n = rng.randint(1, 60)
    actions = ["a", "b", "c"][: rng.randint(1, 3)]
    denominators = DENOMINATORS + (HUGE if rng.random() < 0.15 else [])
    lines = []
    if lumped:
        types = rng.randint(1, min(n, 6))
        kind = [rng.randrange(types) for _ in range(n)]
        members = {t: [s for s in range(n) if kind[s] == t] for t in range(types)}
        template = {}
        for t in range(types):
            for a in actions:
                if rng.random() < 0.8:
                    targets = rng.sample(range(types), rng.randint(1, min(types, 3)))
                    masses = random_split(rng, Fraction(1), len(targets), denominators)
                    reward = rng.choice([0, 0, 1, Fraction(1, 2), -2])
                    template[t, a] = (reward, list(zip(targets, masses)))
        for s in range(n):
            for a in actions:
                if (kind[s], a) not in template or not any(members[x] for x, _ in template[kind[s], a][1]):
                    continue
                reward, by_type = template[kind[s], a]
                row = []
                for t, mass in by_type:
                    if not members[t]:
                        continue
                    chosen = rng.sample(members[t], rng.randint(1, min(2, len(members[t]))))
                    row += zip(chosen, random_split(rng, mass, len(chosen), denominators))
                total = sum(p for _, p in row)
                row = [(t, p / total) for t, p in row]
                rng.shuffle(row)
                lines.append((s, a, reward, row))
    else:
        for s in range(n):
            for a in actions:
                if rng.random() < 0.7:
                    targets = [rng.randrange(n) for _ in range(rng.randint(1, 4))]
                    masses = random_split(rng, Fraction(1), len(targets), denominators)
                    lines.append((s, a, rng.choice([0, 1]), list(zip(targets, masses))))
    rng.shuffle(lines)  # owners get lines from every part, in any order
    text = [f"des (0,{len(lines)},{n})"] + [aut_line(*line) for line in lines]
    return "\n".join(text) + "\n"


def shipped_models(root, oasisc, work):
    """Every model under specs/ and tests/data that `oasisc export --format aut` writes,
    each context of it."""
    found = []
    candidates = sorted(Path(root, "specs").glob("*")) + sorted(Path(root, "tests/data/formats").glob("*"))
    candidates += sorted(Path(root, "tests/data/prism").glob("*.[pn]m"))
    for path in candidates:
        if path.suffix not in (".oasis", ".nm", ".pm", ".aut", ".tra"):
            continue
        listing = work / "contexts.json"
        info = subprocess.run([oasisc, "quotient", str(path), "--format", "json", "-o", str(listing)],
                              capture_output=True, text=True)
        if info.returncode != 0:
            continue  # continuous, or a program that needs --const: not an explicit MDP as is
        contexts = [c["name"] for c in json.loads(listing.read_text())["contexts"]]
        for context in contexts:
            out = work / f"shipped_{path.stem}_{path.suffix[1:]}_{context}.aut"
            command = [oasisc, "export", str(path), "--format", "aut", "-o", str(out)]
            if len(contexts) > 1:
                command += ["--context", context]
            if subprocess.run(command, capture_output=True).returncode == 0:
                found.append(out)
    return found


def partition_of(path):
    document = json.loads(Path(path).read_text())
    return document["contexts"][0]["partition"]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--oasisc", required=True)
    parser.add_argument("--oasisc-mpi", required=True)
    parser.add_argument("--planted", help="the oasis-planted generator")
    parser.add_argument("--root", help="the source tree: test its shipped models too")
    parser.add_argument("--ranks", default="1,2,4")
    parser.add_argument("--random", type=int, default=200)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--rational-sums", action="store_true", help="also run with --rational-sums")
    parser.add_argument("--work", required=True)
    args = parser.parse_args()

    work = start_work(args.work)
    rng = random.Random(args.seed)
    models = []
    for i in range(args.random):
        path = work / f"random{i:04d}.aut"
        path.write_text(chain_model(rng) if i % 10 == 9 else random_model(rng, lumped=i % 2 == 0))
        models.append(path)
    if args.planted:
        for transitions, blocks in ((20000, 50), (100000, 200)):
            path = work / f"planted{transitions}.aut"
            subprocess.run([args.planted, "--transitions", str(transitions), "--blocks", str(blocks),
                            "--seed", str(args.seed), "-o", str(path)], check=True, capture_output=True)
            models.append(path)
    shipped = shipped_models(args.root, args.oasisc, work) if args.root else []
    if args.root and not shipped:
        sys.exit("no shipped model could be exported to .aut")
    models += shipped

    expected = {}
    for model in models:
        out = model.with_suffix(".seq.json")
        subprocess.run([args.oasisc, "quotient", str(model), "--format", "json", "--partition",
                        "-o", str(out)], check=True, capture_output=True)
        expected[model] = partition_of(out)
        subprocess.run([args.oasisc, "quotient", str(model), "--format", "aut",
                        "-o", str(model.with_suffix(".seq.quotient"))], check=True, capture_output=True)

    runs = [(int(p), []) for p in args.ranks.split(",")]
    if args.rational_sums:
        runs.append((int(args.ranks.split(",")[-1]), ["--rational-sums"]))
    failures = 0
    for ranks, flags in runs:
        out_dir = work / f"mpi{ranks}{'r' if flags else ''}"
        out_dir.mkdir(exist_ok=True)
        result = mpirun(ranks, [args.oasisc_mpi, "quotient", "-q", "-o", str(out_dir)] + flags + [str(m) for m in models])
        if result.returncode != 0:
            print(f"P={ranks} {' '.join(flags)}: mpirun exited {result.returncode}\n{result.stderr}")
            failures += 1
            continue
        for model in models:
            got = partition_of(out_dir / (model.stem + ".json"))
            if got != expected[model]:
                failures += 1
                print(f"P={ranks} {' '.join(flags)}: {model.name}: {len(got)} blocks, "
                      f"the sequential engine {len(expected[model])}")
        print(f"P={ranks} {' '.join(flags)}: {len(models)} models compared")

    ranks = runs[-1][0]
    out_dir = work / f"mpi{ranks}aut"
    out_dir.mkdir()
    result = mpirun(ranks, [args.oasisc_mpi, "quotient", "-q", "--format", "aut", "-o", str(out_dir)] + [str(m) for m in models])
    if result.returncode != 0:
        print(f"P={ranks} --format aut: mpirun exited {result.returncode}\n{result.stderr}")
        failures += 1
    else:
        for model in models:
            if (out_dir / (model.stem + ".aut")).read_bytes() != model.with_suffix(".seq.quotient").read_bytes():
                failures += 1
                print(f"P={ranks} --format aut: {model.name}: the quotient differs from the sequential engine's")
        print(f"P={ranks} --format aut: {len(models)} quotients compared")

    checked = [m for m in models if m in shipped] + models[:4]
    for model in checked:
        result = subprocess.run([args.oasisc, "verify", str(model), str(work / f"mpi{runs[-1][0]}" / (model.stem + ".json"))],
                                capture_output=True, text=True)
        if result.returncode != 0:
            failures += 1
            print(f"oasisc verify rejected the MPI result for {model.name}:\n{result.stdout}{result.stderr}")
    print(f"{len(models)} models ({args.random} random, {len(shipped)} shipped), "
          f"{len(checked)} verified: {failures} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
