#!/usr/bin/env python3
"""oasisc against mCRL2's ltspbisim on the same planted .aut files, in paired runs.

What it does, in order:

  1. Builds mCRL2's `ltspbisim` from mCRL2's public source, at a pinned commit, into a folder
     outside this repository (--prefix, default ~/.cache/oasis-bench/mcrl2): a clone in
     PREFIX/src, a Release build of that one tool (and the libraries it links) in
     PREFIX/build-COMMIT, under `nice -n 19` with at most --build-jobs compilers. GUI tools,
     documentation, tests, benchmarks and Sylvan are switched off, and so are mCRL2's
     "soundness checks" (term-level run-time checks; off is the faster ltspbisim, so the
     comparison favours mCRL2). A finished build is reused: the first run takes a while
     (about 77 compilation steps), later runs start at once.
  2. Generates planted models with oasis-planted (tests/bench/planted_aut.cpp: 4 actions, 3
     probabilistic targets per action, rewards in {0, 1} carried in the labels as
     `a|reward(1)`; it prints the true number of blocks of the coarsest bisimulation).
  3. Runs, on each model, --pairs times in turn (A B A B ...):
       A  oasisc quotient IN.aut --format aut -o OUT_A.aut -j 1 --progress never
       B  ltspbisim -epbisim IN.aut OUT_B.aut
     each end to end (read, reduce, write) as a fresh process, timed from outside: wall
     seconds, CPU seconds (user + system) and peak resident memory (getrusage of the
     child). Each ratio is taken pair by pair (B's figure over A's: "oasisc is N times
     faster"), and the median of the ratios is printed: pairing keeps the ratio meaningful
     when the machine's speed drifts (other work on it), which a ratio of two medians would
     not. On a busy machine the CPU ratio is the steadier one: wall time also counts the
     time a run waited for a core.
  4. Checks that oasisc's output has the generator's known block count (the `des (...)`
     header of its .aut), and that ltspbisim's has as many states as oasisc's quotient has
     blocks reachable from its initial block (below); a difference is reported and makes
     the exit status 1.

Why `-epbisim`. ltspbisim offers two exact strong probabilistic bisimulations: `pbisim`, the
O(m log n) algorithm of Groote, Rivera Verduzco and de Vink (2018), and `pbisim-bem`, the
O(mn (log n + log m)) algorithm of Baier, Engelen and Majster-Cederbaum (2000). `pbisim` is
the fastest of the two (`--equivalence pbisim-bem` runs the other). On these files both
decide the relation oasisc computes: an MDP has one distribution per (state, action) and
the label carries the action and its reward, so "every a-transition is matched by an
a-transition with the same distribution over classes" is Definition 1 (docs/formats.md,
"Rewards in labels"). ltspbisim also drops states unreachable from the initial state
first, oasisc does not. Where a whole block is unreachable from state 0 the counts differ
by that block: with the default seed this happens on the 10^7, 250,000-block model (one
block of 10 unreachable states: ltspbisim 249,999, oasisc and the generator 250,000). So
step 4 compares ltspbisim's count with the blocks reachable in oasisc's quotient: a block
is reachable there exactly when one of its states is reachable in the model (every state
of a block has transitions into the same blocks).

Models (--models, a list of TRANSITIONS/BLOCKS; default below): the benchmarks' planted
family (1,000 blocks) and a many-block family with one block per 10 states (25,000 blocks
at 10^6 action transitions: the 250,000-state model of issue 41; 250,000 blocks at 10^7).

Dependencies (Debian packages; the script says which are missing, it installs nothing):
  git cmake g++ make libboost-dev python3   (ninja-build is used when present)
and this repository's build: `cmake --preset default && cmake --build --preset default
--target oasisc oasis-planted`.

Examples:

  # the default run (builds mCRL2 on first use from a clone of its public repository):
  tests/bench/mcrl2_benchmark.py --build build/default

  # from a local clone or mirror, another commit, three pairs of the 10^6 models only:
  tests/bench/mcrl2_benchmark.py --source ~/src/mCRL2 --commit mcrl2-202507.0 \\
      --models 1e6/1000,1e6/25000 --pairs 3

  # build mCRL2 only (then it prints where ltspbisim is and exits):
  tests/bench/mcrl2_benchmark.py --build-only

  # use an ltspbisim built elsewhere (mCRL2's commit is then only the short one in the
  # version line `ltspbisim --version` prints, which the report shows):
  tests/bench/mcrl2_benchmark.py --ltspbisim /opt/mcrl2/bin/ltspbisim

Time and space: at 10^7 action transitions the input file is about 490 MB, oasisc takes
5 to 8 s and 0.6 to 0.7 GiB and ltspbisim 5 to 15 minutes and 11.4 to 11.7 GiB per run
(2-core VM, 2026-11, loaded): leave 12 GiB free, and about an hour for the default models
at 3 pairs. Model files go
to --workdir (a temporary folder by default, removed at the end unless --keep). Not part of
ctest. Figures and how they were taken: docs/PERFORMANCE.md, "Against mCRL2's ltspbisim".
"""
import argparse
import os
import pathlib
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

from timed_run import run_timed_cpu

# mCRL2's public repository, and the newest release tag of it when this script was written
# (mcrl2-202607.0, tagged 2026-07-13).
DEFAULT_SOURCE = "https://github.com/mCRL2org/mCRL2.git"
DEFAULT_COMMIT = "b3762fd53766475e01a4b37901555328a5f8c107"
DEFAULT_MODELS = "1e6/1000,1e6/25000,1e7/1000,1e7/250000"

# The CMake options that build ltspbisim and as little else as mCRL2's CMake allows.
MCRL2_CMAKE_OPTIONS = [
    "-DCMAKE_BUILD_TYPE=Release",
    "-DMCRL2_ENABLE_GUI_TOOLS=OFF",
    "-DMCRL2_ENABLE_DOCUMENTATION=OFF",
    "-DMCRL2_ENABLE_DOC_MANUAL=OFF",
    "-DMCRL2_ENABLE_DOC_DOXYGEN=OFF",
    "-DMCRL2_ENABLE_DOC_PDFLATEX=OFF",
    "-DMCRL2_ENABLE_TESTS=OFF",
    "-DMCRL2_ENABLE_TOOL_TESTS=OFF",
    "-DMCRL2_ENABLE_BENCHMARKS=OFF",
    "-DMCRL2_ENABLE_SYLVAN=OFF",
    "-DMCRL2_ENABLE_SOUNDNESS_CHECKS=OFF",
]


def missing_packages() -> list[str]:
    """The Debian packages the mCRL2 build needs that this machine lacks."""
    missing = []
    for program, package in (("git", "git"), ("cmake", "cmake"), ("g++", "g++"),
                             ("make", "make")):
        if shutil.which(program) is None:
            missing.append(package)
    if not os.path.exists("/usr/include/boost/version.hpp"):
        missing.append("libboost-dev")
    return missing


def git(arguments: list[str], cwd: pathlib.Path | None = None) -> str:
    result = subprocess.run(["git", *arguments], cwd=cwd, capture_output=True, text=True,
                            check=False)
    if result.returncode != 0:
        raise SystemExit(f"failed: git {' '.join(arguments)}\n{result.stderr}")
    return result.stdout.strip()


def checkout(source: str, commit: str, prefix: pathlib.Path) -> tuple[pathlib.Path, str]:
    """A work tree of mCRL2 at COMMIT in PREFIX/src (cloned from SOURCE on first use, fetched
    from it when COMMIT is not there yet); returns the tree and the full commit hash."""
    tree = prefix / "src"
    if os.path.exists(source):  # a local clone: git fetch runs inside the tree
        source = os.path.abspath(source)
    if not (tree / ".git").exists():
        print(f"# cloning {source} into {tree}", flush=True)
        prefix.mkdir(parents=True, exist_ok=True)
        git(["clone", "--quiet", "--no-checkout", source, str(tree)])
    try:
        full = git(["rev-parse", "--verify", "--quiet", f"{commit}^{{commit}}"], cwd=tree)
    except SystemExit:
        print(f"# fetching {commit} from {source}", flush=True)
        git(["fetch", "--quiet", "--tags", source], cwd=tree)
        full = git(["rev-parse", "--verify", f"{commit}^{{commit}}"], cwd=tree)
    if git(["rev-parse", "HEAD"], cwd=tree) != full or git(["status", "--porcelain"], cwd=tree):
        git(["checkout", "--quiet", "--force", "--detach", full], cwd=tree)
    return tree, full


def configure(tree: pathlib.Path, build: pathlib.Path) -> pathlib.Path:
    """Configures mCRL2's build in BUILD once (a build folder per commit)."""
    if not (build / "CMakeCache.txt").exists():
        print(f"# configuring mCRL2 in {build}", flush=True)
        generator = ["-G", "Ninja"] if shutil.which("ninja") else []
        result = subprocess.run(["cmake", "-S", str(tree), "-B", str(build), *generator,
                                 *MCRL2_CMAKE_OPTIONS], capture_output=True, text=True,
                                check=False)
        if result.returncode != 0:
            shutil.rmtree(build, ignore_errors=True)
            raise SystemExit(f"mCRL2's cmake failed:\n{result.stdout[-3000:]}{result.stderr}")
    return build


def build_ltspbisim(source: str, commit: str, prefix: pathlib.Path, jobs: int) -> tuple[str, str]:
    """Builds ltspbisim (reusing a finished build); returns its path and mCRL2's commit."""
    missing = missing_packages()
    if missing:
        raise SystemExit("the mCRL2 build needs these Debian packages: "
                         f"sudo apt-get install {' '.join(missing)}")
    tree, full = checkout(source, commit, prefix)
    build = configure(tree, prefix / f"build-{full[:12]}")
    binary = build / "stage" / "bin" / "ltspbisim"
    print(f"# building ltspbisim (nice -n 19, -j {jobs}); log in {build / 'oasis-build.log'}",
          flush=True)
    started = time.perf_counter()
    with open(build / "oasis-build.log", "w", encoding="utf-8") as log:
        status = subprocess.run(["nice", "-n", "19", "cmake", "--build", str(build), "--target",
                                 "ltspbisim", "-j", str(jobs)], stdout=log,
                                stderr=subprocess.STDOUT, check=False).returncode
    if status != 0 or not binary.exists():
        raise SystemExit(f"the mCRL2 build failed: see {build / 'oasis-build.log'}")
    print(f"# ltspbisim ready in {time.perf_counter() - started:.0f} s: {binary}", flush=True)
    return str(binary), full


def version_of(ltspbisim: str) -> str:
    result = subprocess.run([ltspbisim, "--version"], capture_output=True, text=True,
                            check=False)
    return (result.stdout or result.stderr).strip().splitlines()[0] if result.returncode == 0 \
        else "unknown"


def parse_models(text: str) -> list[tuple[int, int]]:
    """'1e6/1000,1e7/250000' -> [(1000000, 1000), (10000000, 250000)]."""
    models = []
    for item in text.split(","):
        transitions, _, blocks = item.partition("/")
        try:
            models.append((int(float(transitions)), int(blocks)))
        except ValueError:
            raise SystemExit(f"--models: '{item}' is not TRANSITIONS/BLOCKS (e.g. 1e6/1000)")
    return models


def aut_states(path: str) -> int:
    """The state count of an .aut file's header `des (INITIAL, TRANSITIONS, STATES)`."""
    with open(path, encoding="utf-8", errors="replace") as handle:
        header = handle.readline()
    match = re.match(r"\s*des\s*\(.*,\s*\d+\s*,\s*(\d+)\s*\)\s*$", header)
    if match is None:
        raise SystemExit(f"{path}: no .aut header: {header[:80]!r}")
    return int(match.group(1))


def reachable_states(path: str) -> int:
    """The states of an .aut file reachable from its initial state. A probabilistic line is
    `(FROM,"LABEL",T1 P1 T2 P2 ... TN)`: the targets are every other token after the label."""
    with open(path, encoding="utf-8", errors="replace") as handle:
        header = handle.readline()
        initial = int(re.match(r"\s*des\s*\(\s*(\d+)", header).group(1))
        successors: dict[int, list[int]] = {}
        for line in handle:
            source, _, rest = line.strip().strip("()").partition(",")
            targets = rest.rsplit('"', 1)[-1].lstrip(",").split()[::2]
            successors.setdefault(int(source), []).extend(int(t) for t in targets)
    seen, stack = {initial}, [initial]
    while stack:
        for target in successors.get(stack.pop(), []):
            if target not in seen:
                seen.add(target)
                stack.append(target)
    return len(seen)


def humanise(transitions: int) -> str:
    exponent = len(str(transitions)) - 1
    return f"10^{exponent}" if transitions == 10 ** exponent else f"{transitions:,}"


def run_model(args: argparse.Namespace, oasisc: str, planted: str, ltspbisim: str,
              directory: str, transitions: int, blocks: int) -> bool:
    """Generates one model and runs the pairs on it; returns whether every pair ran and gave
    the known block count from both tools."""
    source = os.path.join(directory, f"planted_{transitions}_{blocks}.aut")
    out_a = os.path.join(directory, "oasisc_out.aut")
    out_b = os.path.join(directory, "ltspbisim_out.aut")
    started = time.perf_counter()
    generated = subprocess.run([planted, "--transitions", str(transitions), "--blocks",
                                str(blocks), "--seed", str(args.seed), "-o", source],
                               capture_output=True, text=True, check=False)
    if generated.returncode != 0:
        raise SystemExit(f"oasis-planted failed:\n{generated.stderr}")
    known = int(generated.stdout.strip())
    states = aut_states(source)
    size = os.path.getsize(source) / 1e6
    print(f"\n## {humanise(transitions)} action transitions, {states:,} states, {blocks:,} "
          f"planted blocks ({known:,} in the coarsest bisimulation), {size:.0f} MB, "
          f"generated in {time.perf_counter() - started:.1f} s; load {load()}", flush=True)
    print(f"{'pair':>4} {'oasisc s':>9} {'cpu s':>7} {'MiB':>6} {'ltspbisim s':>12} "
          f"{'cpu s':>8} {'MiB':>6} {'wall ratio':>11} {'cpu ratio':>10} {'RSS ratio':>10}  "
          "blocks A/B", flush=True)
    command_a = [oasisc, "quotient", source, "--format", "aut", "-o", out_a, "-j", "1",
                 "--progress", "never"]
    command_b = [ltspbisim, f"-e{args.equivalence}", source, out_b]
    rows, agreed = [], True
    for pair in range(1, args.pairs + 1):
        try:
            wall_a, cpu_a, peak_a, _ = run_timed_cpu(command_a)
            wall_b, cpu_b, peak_b, _ = run_timed_cpu(command_b)
        except SystemExit as failure:  # run_timed_cpu's report of a failed command
            print(f"!! pair {pair}: {failure}", flush=True)
            agreed = False
            break
        blocks_a, blocks_b = aut_states(out_a), aut_states(out_b)
        reachable_a = reachable_states(out_a) if blocks_b != blocks_a else blocks_a
        os.remove(out_a)
        os.remove(out_b)
        same = blocks_a == known and blocks_b == reachable_a
        agreed = agreed and same
        row = (wall_a, cpu_a, peak_a, wall_b, cpu_b, peak_b)
        rows.append(row)
        unreachable = "" if reachable_a == blocks_a else f" ({blocks_a - reachable_a} unreachable)"
        print(f"{pair:>4} {format_row(row)}  {blocks_a}/{blocks_b}{unreachable}"
              f"{'' if same else ' DIFFER'}", flush=True)
    if rows:
        medians = [statistics.median(row[i] for row in rows) for i in range(6)]
        ratios = [statistics.median(row[i + 3] / row[i] for row in rows) for i in range(3)]
        print(f"{'med':>4} {format_row(medians, ratios)}  (medians; a ratio's is the median "
              "of the per-pair ratios)", flush=True)
    if not agreed:
        print(f"!! not every pair ran, or the block counts differ (known {known})", flush=True)
    if not args.keep:
        os.remove(source)
    print(f"# load average after this model {load()}", flush=True)
    return agreed


def format_row(row: list[float] | tuple, ratios: list[float] | None = None) -> str:
    """wall, cpu, MiB of A and of B, then B/A of each (the given ratios, or this row's)."""
    wall_a, cpu_a, peak_a, wall_b, cpu_b, peak_b = row
    wall, cpu, peak = ratios or (wall_b / wall_a, cpu_b / max(cpu_a, 1e-3), peak_b / peak_a)
    return (f"{wall_a:>9.2f} {cpu_a:>7.2f} {peak_a:>6.0f} {wall_b:>12.2f} {cpu_b:>8.2f} "
            f"{peak_b:>6.0f} {wall:>10.1f}x {cpu:>9.1f}x {peak:>9.1f}x")


def load() -> str:
    return " ".join(f"{value:.2f}" for value in os.getloadavg())


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     epilog="\n\n".join(__doc__.split("\n\n")[1:]),
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build/default",
                        help="this repository's build folder, with compiler/oasisc and "
                        "tests/oasis-planted (default: build/default)")
    parser.add_argument("--oasisc", help="oasisc to run (default: BUILD/compiler/oasisc)")
    parser.add_argument("--planted", help="generator (default: BUILD/tests/oasis-planted)")
    parser.add_argument("--source", default=DEFAULT_SOURCE,
                        help="mCRL2's git repository: a local clone, a mirror or a URL "
                        f"(default: {DEFAULT_SOURCE})")
    parser.add_argument("--commit", default=DEFAULT_COMMIT,
                        help="mCRL2 commit, tag or branch to build (default: mcrl2-202607.0, "
                        f"{DEFAULT_COMMIT[:12]})")
    parser.add_argument("--prefix", default=os.path.expanduser("~/.cache/oasis-bench/mcrl2"),
                        help="where mCRL2's clone and build go, outside this repository "
                        "(default: ~/.cache/oasis-bench/mcrl2)")
    parser.add_argument("--build-jobs", type=int, default=2,
                        help="parallel compilers for the mCRL2 build (default 2)")
    parser.add_argument("--build-only", action="store_true",
                        help="build ltspbisim, print its path and commit, and stop")
    parser.add_argument("--ltspbisim", help="use this ltspbisim instead of building one")
    parser.add_argument("--equivalence", default="pbisim", choices=["pbisim", "pbisim-bem"],
                        help="ltspbisim's -e: pbisim (Groote, Rivera Verduzco and de Vink, "
                        "O(m log n), the default) or pbisim-bem (Baier et al.)")
    parser.add_argument("--models", default=DEFAULT_MODELS,
                        help=f"TRANSITIONS/BLOCKS,... (action transitions = 4 x states; "
                        f"default {DEFAULT_MODELS})")
    parser.add_argument("--pairs", type=int, default=3, help="A B pairs per model (default 3)")
    parser.add_argument("--seed", type=int, default=1, help="oasis-planted's seed (default 1)")
    parser.add_argument("--workdir", help="where the model files go (default: a temporary "
                        "folder)")
    parser.add_argument("--keep", action="store_true", help="keep the generated models")
    args = parser.parse_args()
    if args.pairs < 1:
        parser.error("--pairs must be at least 1")
    models = parse_models(args.models)

    if args.ltspbisim:
        ltspbisim, commit = args.ltspbisim, "unknown (given with --ltspbisim)"
    else:
        ltspbisim, commit = build_ltspbisim(args.source, args.commit,
                                            pathlib.Path(args.prefix).expanduser(),
                                            args.build_jobs)
    version = version_of(ltspbisim)
    if args.build_only:
        print(f"ltspbisim: {ltspbisim}\nmCRL2 commit: {commit}\nversion: {version}")
        return 0
    oasisc = args.oasisc or os.path.join(args.build, "compiler", "oasisc")
    planted = args.planted or os.path.join(args.build, "tests", "oasis-planted")
    for program in (oasisc, planted):
        if not os.access(program, os.X_OK):
            raise SystemExit(f"{program} is missing: cmake --build --preset default --target "
                             "oasisc oasis-planted")
    oasis_commit = subprocess.run(["git", "rev-parse", "--short=12", "HEAD"],
                                  cwd=os.path.dirname(os.path.abspath(__file__)),
                                  capture_output=True, text=True, check=False).stdout.strip()

    print(f"# oasisc against mCRL2's ltspbisim, {time.strftime('%Y-%m-%d %H:%M %Z')}, "
          f"{os.cpu_count()} cores, "
          f"{os.sysconf('SC_PAGE_SIZE') * os.sysconf('SC_PHYS_PAGES') / 2**30:.0f} GiB")
    print(f"# oasisc: {oasisc} (oasis {oasis_commit or 'unknown'}), -j 1")
    print(f"# ltspbisim: {ltspbisim} -e{args.equivalence}; mCRL2 commit {commit}; {version}")
    print(f"# {args.pairs} pairs per model, A = oasisc then B = ltspbisim; ratios are B/A; "
          f"load average at start {load()}")
    agreed = True
    if args.workdir:
        os.makedirs(args.workdir, exist_ok=True)
    directory = args.workdir or tempfile.mkdtemp(prefix="oasis-mcrl2-")
    try:
        for transitions, blocks in models:
            agreed = run_model(args, oasisc, planted, ltspbisim, directory, transitions,
                               blocks) and agreed
    finally:
        if not args.workdir and not args.keep:
            shutil.rmtree(directory, ignore_errors=True)
    print(f"\n# load average at end {load()}")
    return 0 if agreed else 1


if __name__ == "__main__":
    sys.exit(main())
