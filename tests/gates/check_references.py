#!/usr/bin/env python3
"""Checks that every file or folder a comment, a README or a doc names exists in the repository.

A reference is a path-like word in a tracked source, build or documentation file:
  - with a slash ("compiler/verify/bisimulation_check.cpp", "hw/app/", "../metrics/"): it must
    name a tracked file or folder, from the repository root, from the referring file's folder,
    or as the tail of a tracked path ("verify/bisimulation_check.cpp");
  - without one, a source or doc file name ("grid_gaussian_axis.hpp", "RELIABILITY.md"): some
    tracked file must have that name.
References outside the repository ("../shared/...") are errors: a fact the code relies on is
written in the repository. The few paths that are not references (where a test looks for an
optional peer, system files, build outputs) are listed below with the reason.

    check_references.py [--root REPO]      exit 1 and one located line per stale reference
    check_references.py --self-test        plant stale references in memory, expect each caught
"""

import argparse
import pathlib
import re
import subprocess
import sys

SCANNED = re.compile(r"(\.(md|hpp|cpp|py|cmake|txt|yaml|oasis|in|sh|json)|/[^./]+)$")
SCANNED_FOLDERS = ("compiler/", "hw/", "common/", "tools/", "runtime/", "tests/", "scripts/",
                   "cmake/", "docs/", "specs/", ".ci/", ".clang", "python/", "examples/")
SKIPPED_FOLDERS = ("tests/data/", "tests/golden/", "tests/specs/", "tests/fuzz/corpus/",
                   "generated/")
EXTENSIONS = r"(?:hpp|cpp|h|py|md|cmake|txt|yaml|oasis|json|tsv|pm|nm|aut|tra|lab|bin|svg|dot)"
WITH_SLASH = re.compile(r"(?<![\w./:$@{<*-])((?:\.\./|\./)*(?:[A-Za-z_][\w.+-]*/)+"
                        r"(?:[\w.+-]+\." + EXTENSIONS + r"|))(?![\w/*{<(-])")
BARE = re.compile(r"(?<![\w./:$@{<*-])([a-z][a-z0-9_]*\.(?:hpp|cpp|py))(?![\w/.-])")

# Paths written in the tree that are not references to the tree.
NOT_REFERENCES = (
    r"\.\./shared/vendor/(unitree_legged_sdk/?)?",  # where the interop test finds Unitree's SDK
    r"(usr|dev|sys|proc|tmp|opt|etc|var|run)/.*",  # the system's files
    r"(build|out|b)/.*",  # build outputs
    r"(oasis|rt)/.*",  # installed header paths, include/oasis/rt
    r"(lib|bin|share|include)/.*",  # the install tree
    r"(actions|annotations|observations|valuations)/.*",  # entries inside a UMB file
    r"(nlohmann|CLI|yaml-cpp|opencv2|CGAL|Eigen|ros|rosbag|cv_bridge|sensor_msgs|std_msgs|"
    r"geometry_msgs|nav_msgs|visualization_msgs|diagnostic_msgs|message_filters|gtest|gmock|"
    r"benchmark|apriltag|linux|sys|unitree_legged_sdk|lib/cpp)/.*",  # outside libraries' headers
)
OUTSIDE = re.compile(r"(?:\.\./)+shared/|(?<![\w/])shared/(?:design|hw|paper|benchmarks)/|"
                     r"\bNOTES (?:§|\")|\b(?:ARCHITECTURE|STYLE)\.md|design (?:repository|notes)")


def tracked(root):
    """The repository's files: tracked or new, not ignored, and present."""
    out = subprocess.run(["git", "-C", str(root), "ls-files", "-z", "--cached", "--others",
                          "--exclude-standard"], capture_output=True, check=True).stdout.decode()
    return sorted({path for path in out.split("\0") if path and (root / path).is_file()})


# What of a file is prose: comments in code (string literals there are paths the programs
# make at run time), everything in docs.
LINE_COMMENT = {"cpp": r"//[^\n]*|/\*.*?\*/", "hpp": r"//[^\n]*|/\*.*?\*/"}
HASH_COMMENT = r"(?m)(?:^|(?<=\s))#[^\n]*"


def prose(path, text):
    """TEXT with everything but its prose blanked (offsets kept, so lines and columns hold)."""
    extension = path.rsplit(".", 1)[-1] if "." in path.rsplit("/", 1)[-1] else ""
    if extension in ("md", "json"):
        return text
    pattern = LINE_COMMENT.get(extension, HASH_COMMENT)
    kept = [" " if ch != "\n" else ch for ch in text]
    for match in re.finditer(pattern, text, re.DOTALL):
        kept[match.start():match.end()] = text[match.start():match.end()]
    return "".join(kept)


class Repository:
    def __init__(self, files):
        self.files = set(files)
        self.folders = {"/".join(path.split("/")[:end]) for path in files
                        for end in range(1, path.count("/") + 1)}
        self.names = {path.rsplit("/", 1)[-1] for path in files}
        self.tails = set()
        for path in self.files | self.folders:
            parts = path.split("/")
            self.tails.update("/".join(parts[start:]) for start in range(len(parts)))

    def exists(self, reference, referrer):
        reference = reference.rstrip("/")
        if not reference or reference in (".", ".."):
            return True
        folder = pathlib.PurePosixPath(referrer).parent
        joined = normalise(folder / reference)
        if joined in self.files or joined in self.folders:
            return True
        return reference.lstrip("./") in self.tails if not reference.startswith("..") else False


def normalise(path):
    parts = []
    for part in str(path).split("/"):
        if part == "..":
            if not parts:
                return None
            parts.pop()
        elif part not in ("", "."):
            parts.append(part)
    return "/".join(parts)


def scanned(path):
    return (path.startswith(SCANNED_FOLDERS) or "/" not in path) and SCANNED.search(path) \
        and not path.startswith(SKIPPED_FOLDERS)


PLACEHOLDERS = {"NAME", "PART", "DIR", "CONTROLLER", "SPEC_NAME", "FILE", "OUT", "MODEL", "SPEC",
                "LAYER", "NN", "PREFIX", "P", "N", "X", "trialNN"}
# Names that are not the repository's files, and why.
OUTSIDE_NAMES = {
    "example_walk.cpp",  # Unitree's SDK example, which the interop test follows
    "robot.cpp",  # the consumer project's program in the install example
    "shipped_profiles.cpp",  # generated in the build folder from hw/config/controllers/
    "calibration.cpp",  # a librealsense user's source, where hw/FACTS.md's intrinsics come from
}
EXAMPLES = (
    r"a/x\.aut",  # an input path in an example of colliding outputs
    r"run1/.*",  # a recording folder in an example
    r"package/oasis_ros/",  # oasis-ros's package folder in the build folder
    r"libraries/lts/source/.*",  # mCRL2's source, where its .aut reader is
    r"ucl/\w+\.py",  # free-dog-sdk's Python sources, which hw/FACTS.md cross-checks
    r"modules/videoio/src/.*",  # OpenCV's source, where hw/FACTS.md's V4L2 facts come from
)


def placeholder(reference):
    words = re.split(r"[^A-Za-z0-9_]+", reference)
    return any(word in PLACEHOLDERS or word.endswith("NN") for word in words)


def stale(repository, path, text):
    """(line, column, message) for each stale reference in TEXT, the contents of PATH."""
    text = prose(path, text)
    found = []
    for match in OUTSIDE.finditer(text):
        rest = text[match.start():match.start() + 60].split()[0].strip("`'\"()").rstrip(".,;:")
        if any(re.fullmatch(pattern, rest) for pattern in NOT_REFERENCES):
            continue
        found.append((match.start(), f"'{rest}' is outside the repository: write the fact "
                                      f"here instead"))
    for match in WITH_SLASH.finditer(text):
        reference = match.group(1)
        if OUTSIDE.match(reference) or placeholder(reference) or any(
                re.fullmatch(pattern, reference.lstrip("./")) for pattern in NOT_REFERENCES):
            continue
        if re.fullmatch(r"[\w.+-]+/", reference) or any(re.fullmatch(example, reference)
                                                         for example in EXAMPLES):
            continue  # a lone folder name ("rec/", "logs/"): an example, or too common to tell
        if reference.endswith("/") and "." in reference:
            continue  # test names (Suite/Fixture.Case/), not folders
        if not repository.exists(reference, path):
            found.append((match.start(1), f"'{reference}' names no file or folder of the "
                                          f"repository"))
    for match in BARE.finditer(text):
        if match.group(1) not in repository.names | OUTSIDE_NAMES:
            found.append((match.start(1), f"'{match.group(1)}' names no file of the repository"))
    return [(text.count("\n", 0, offset) + 1,
             offset - text.rfind("\n", 0, offset), message) for offset, message in found]


def check(root, files, read):
    repository = Repository(files)
    messages = []
    for path in sorted(files):
        if scanned(path):
            for line, column, message in stale(repository, path, read(path)):
                messages.append(f"{path}:{line}:{column}: error: {message}")
    return messages


PLANTS = (
    ("README.md", "see `tools/sim/` for the simulator", "tools/sim/"),
    ("compiler/README.md", "the checker (program_checker.cpp) does it", "program_checker.cpp"),
    ("hw/README.md", "facts from ../shared/hw/NOTES.md", "outside the repository"),
)


def self_test(root, files, read):
    if check(root, files, read):
        print("self-test: the tree already fails; run the check without --self-test")
        return 1
    for victim, line, expected in PLANTS:
        planted = lambda path: read(path) + "\n" + line + "\n" if path == victim else read(path)
        found = check(root, files, planted)
        if len(found) != 1 or expected not in found[0]:
            print(f"self-test: '{line}' in {victim} was not caught alone: {found}")
            return 1
        print(f"self-test: caught {found[0]}")
    print(f"self-test: {len(PLANTS)} stale references planted, {len(PLANTS)} caught")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", default=pathlib.Path(__file__).resolve().parents[2])
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args()
    root = pathlib.Path(args.root)
    files = tracked(root)
    read = lambda path: (root / path).read_text(errors="replace")
    if args.self_test:
        return self_test(root, files, read)
    messages = check(root, files, read)
    for message in messages:
        print(message)
    if messages:
        print(f"{len(messages)} stale reference(s)")
    return 1 if messages else 0


if __name__ == "__main__":
    sys.exit(main())
