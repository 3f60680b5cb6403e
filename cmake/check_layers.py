#!/usr/bin/env python3
"""Checks every #include of the tree against the links of the target its file belongs to.

The rules are the build's own links, which cmake/OasisLayers.cmake writes to a table at the
end of configuring (one line per target: its sources, links and interface links). A file of
compiler/, hw/, common/, tools/ or runtime/ belongs to the targets that compile it (a header:
to the targets that own its folder). It may include:
  - headers of its own targets and of every target they reach through their links, following
    a dependency's interface links only (CMake's usage requirements: PRIVATE stays private);
  - headers of an outside library (CGAL, OpenCV, yaml-cpp, ...) only if it reaches that
    library's target the same way;
  - headers of the folders its target names in OASIS_HEADER_ONLY_USES (deliberate crossings).
And a target links nothing it does not use: each outside library and each of our targets it
links directly must have a header included by one of its files.
Further, an include path means one file: "cli/x.hpp" must not name files in two folders, and
the links between our targets have no cycle.

    check_layers.py --table FILE --root REPO [--stamp FILE]   check the tree
    check_layers.py --table FILE --root REPO --self-test      plant wrong includes in memory and
                                                              expect each to be caught
"""

import argparse
import functools
import pathlib
import re
import sys

CHECKED = ("compiler", "hw", "common", "tools", "runtime")
INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]*([<"])([^>"]+)[>"]', re.MULTILINE)

# Outside libraries: the first part of an include path (or the whole file name) -> a pattern
# of the link names that provide it.
OUTSIDE = {
    "nlohmann": r"nlohmann_json::nlohmann_json",
    "CLI": r"CLI11::CLI11",
    "yaml-cpp": r"yaml-cpp(::yaml-cpp)?",
    "opencv2": r"opencv_\w+",
    "apriltag": r"apriltag::apriltag(-utils)?",
    "tag36h11.h": r"apriltag::apriltag",
    "apriltag.h": r"apriltag::apriltag",
    "gmpxx.h": r"GMP::gmpxx",
    "gmp.h": r"GMP::gmp(xx)?",
    "CGAL": r"CGAL::CGAL",
    "Eigen": r"Eigen3::Eigen",
    "nlopt.hpp": r"NLopt::nlopt",
    "mpi.h": r"MPI::MPI_CXX",
    "ros": r"ROS1::\w+",
    "std_msgs": r"ROS1::\w+",
    "sensor_msgs": r"ROS1::\w+",
    "geometry_msgs": r"ROS1::\w+",
    "nav_msgs": r"ROS1::\w+",
    "visualization_msgs": r"ROS1::\w+",
    "diagnostic_msgs": r"ROS1::\w+",
    "message_filters": r"ROS1::\w+",
    "cv_bridge": r"ROS1::cv_bridge",
    "rosbag": r"ROS1::rosbag",
    "benchmark": r"benchmark::benchmark(_main)?",
    "archive.h": r"LibArchive::LibArchive",
    "archive_entry.h": r"LibArchive::LibArchive",
}


class Target:
    def __init__(self, fields):
        (self.name, self.type, self.folder, sources, links, interface_links, header_folders,
         header_only_uses) = (fields + [""] * 8)[:8]
        split = lambda value: [item for item in value.split("|") if item]
        self.sources = split(sources)
        self.links = [] if self.type == "INTERFACE_LIBRARY" else clean_links(split(links))
        self.interface_links = clean_links(split(interface_links))
        self.header_folders = split(header_folders)
        self.header_only_uses = split(header_only_uses)


def clean_links(items):
    """Link names without CMake's decorations; link-only entries are not usage, so dropped."""
    names = []
    for item in items:
        if item.startswith("::@") or item.startswith("$<LINK_ONLY:"):
            continue
        build = re.fullmatch(r"\$<BUILD_INTERFACE:(.*)>", item)
        item = build.group(1) if build else item
        if "$<" in item or item.startswith("-"):
            continue
        names.append(item)
    return names


def read_table(path):
    targets = {}
    for line in pathlib.Path(path).read_text().splitlines():
        if line.strip():
            target = Target(line.split("\t"))
            targets[target.name] = target
    return targets


def relative(root, path):
    try:
        return pathlib.Path(path).resolve().relative_to(root).as_posix()
    except ValueError:
        return None


class Tree:
    """Who owns each file and folder, what each target reaches, and how includes resolve."""

    def __init__(self, root, targets):
        self.root, self.targets = root, targets
        self.owners_of_file, self.owners_of_folder = {}, {}
        for target in targets.values():
            for source in target.sources:
                path = relative(root, pathlib.Path(target.folder) / source)
                if path and path.split("/")[0] in CHECKED:
                    self.owners_of_file.setdefault(path, set()).add(target.name)
                    folder = path.rsplit("/", 1)[0]
                    self.owners_of_folder.setdefault(folder, set()).add(target.name)
            for folder in target.header_folders:
                folder = relative(root, pathlib.Path(target.folder) / folder)
                self.owners_of_folder.setdefault(folder, set()).add(target.name)
        self.include_roots = sorted({parent for folder in self.owners_of_folder
                                     for parent in parents(folder)})

    def owners(self, path):
        """The targets a file belongs to: those that compile it; for a header, those that
        compile the source of the same name beside it, or else those that own its folder."""
        if path in self.owners_of_file:
            return self.owners_of_file[path]
        source = re.sub(r"\.hpp$", ".cpp", path)
        return self.owners_of_file.get(source) or self.owners_of_folder.get(
            path.rsplit("/", 1)[0], set())

    def folders_of(self, name):
        return [folder for folder, owners in self.owners_of_folder.items() if name in owners]

    @functools.lru_cache(maxsize=None)
    def reach(self, name):
        """Every target and outside library NAME's files may use: its links, and theirs
        through their interface links."""
        target = self.targets.get(name)
        if target is None:
            return frozenset({name})
        seen = {name}
        stack = target.links + target.interface_links
        while stack:
            link = stack.pop()
            if link in seen:
                continue
            seen.add(link)
            if link in self.targets:
                stack.extend(self.targets[link].interface_links)
        return frozenset(seen)  # cached: shared by every file of the target

    def resolve(self, includer, text):
        """The repository files an include names: beside the includer, or under an include
        root of the tree."""
        found = []
        beside = (self.root / includer).parent / text
        if beside.is_file():
            found.append(relative(self.root, beside))
        for root in self.include_roots:
            candidate = self.root / root / text
            if candidate.is_file():
                path = relative(self.root, candidate)
                if path not in found:
                    found.append(path)
        return found


def parents(folder):
    parts = folder.split("/")
    return ["/".join(parts[:end]) for end in range(1, len(parts))]


def outside_pattern(text):
    first = text.split("/")[0]
    return OUTSIDE.get(first) or OUTSIDE.get(text)


def checked_files(root, tree):
    files = set(tree.owners_of_file)
    for folder in tree.owners_of_folder:
        files.update(relative(root, header) for header in (root / folder).glob("*.hpp"))
    return sorted(path for path in files if path and path.split("/")[0] in CHECKED)


def crossings(tree, read):
    """One message per include that leaves what its file's targets reach, and per include
    path that names two files."""
    messages, used = [], {}
    for path in checked_files(tree.root, tree):
        owners = tree.owners(path)
        if not owners:
            continue
        allowed = set().union(*(tree.reach(owner) for owner in owners))
        crossing_folders = {relative(tree.root, pathlib.Path(tree.targets[o].folder) / f)
                            for o in owners for f in tree.targets[o].header_only_uses}
        text = read(path)
        for match in INCLUDE.finditer(text):
            line = text.count("\n", 0, match.start()) + 1
            problem = check_include(tree, path, match.group(2), allowed, crossing_folders, owners,
                                    used)
            if problem:
                messages.append(f"{path}:{line}: error: {problem}")
    return messages, used


def check_include(tree, path, text, allowed, crossing_folders, owners, used):
    resolved = tree.resolve(path, text)
    if text.startswith("../"):
        return f'"{text}" is a relative include: name the folder, so that this check sees it'
    if len(resolved) > 1:
        return f'"{text}" names {len(resolved)} files ({", ".join(resolved)}): a folder name ' \
               f"on the include path must mean one folder"
    if resolved:
        folder = resolved[0].rsplit("/", 1)[0]
        providers = tree.owners_of_folder.get(folder, set())
        for owner in owners:
            used.setdefault(owner, Used()).targets.update(providers)
        if folder in crossing_folders or not providers or providers & allowed:
            return None
        return (f'{describe(owners)} includes "{text}" ({folder}/, of {describe(providers)}), '
                f"which it does not link")
    pattern = outside_pattern(text)
    if pattern is None:
        return None
    providers = {name for name in allowed if re.fullmatch(pattern, name)}
    for owner in owners:
        used.setdefault(owner, Used()).outside.add(pattern)
    if providers:
        return None
    return f"{describe(owners)} includes <{text}> of a library it does not link ({pattern})"


def describe(names):
    return " and ".join(f"'{name}'" for name in sorted(names))


class Used:
    """What one target's files include: our targets, and outside libraries' link patterns."""

    def __init__(self):
        self.targets, self.outside = set(), set()

    def any_of(self, names):
        return bool(self.targets & names) or any(
            re.fullmatch(pattern, name) for pattern in self.outside for name in names)


def unused_links(tree, used):
    """Direct links of our targets of which none of their files includes a header (for a
    link to one of ours: a header of it or of what it passes on)."""
    messages = []
    for target in sorted(tree.targets.values(), key=lambda t: t.name):
        if not tree.folders_of(target.name):
            continue  # an aggregate (oasis_compiler) or a target outside the checked folders
        includes = used.get(target.name, Used())
        for link in sorted(set(target.links + target.interface_links)):
            ours = link in tree.targets and tree.folders_of(link)
            outside = any(re.fullmatch(pattern, link) for pattern in OUTSIDE.values())
            if (ours or outside) and not includes.any_of(tree.reach(link)):
                messages.append(f"{relative(tree.root, target.folder)}: error: '{target.name}' "
                                f"links '{link}' but includes none of its headers")
    return messages


def cycles(tree):
    """Our targets that reach themselves through their links."""
    found = []
    for name, target in sorted(tree.targets.items()):
        for link in target.links + target.interface_links:
            if link != name and link in tree.targets and name in tree.reach(link):
                found.append(f"error: '{name}' links '{link}', which links it back")
                break
    return found


def check(tree, read):
    messages, used = crossings(tree, read)
    return cycles(tree) + messages + unused_links(tree, used)


PLANTS = (
    # (file to plant in: the first file of this folder, include, what must be reported)
    ("hw/go1", '#include "settings/settings.hpp"', "settings/settings.hpp"),
    ("hw/perception", '#include "pipeline/discrete_catalog.hpp"', "pipeline/discrete_catalog.hpp"),
    ("compiler/verify", '#include "geom/grid.hpp"', "geom/grid.hpp"),
    ("compiler/model", "#include <opencv2/core.hpp>", "opencv2/core.hpp"),
    ("common/files", '#include "../geom/grid.hpp"', "../geom/grid.hpp"),
)


def self_test(tree, read):
    if check(tree, read):
        print("self-test: the tree already fails; run the check without --self-test")
        return 1
    for folder, line, expected in PLANTS:
        victims = [path for path in checked_files(tree.root, tree)
                   if path.rsplit("/", 1)[0] == folder]
        if not victims:
            print(f"self-test: no file in {folder}/ to plant in")
            return 1
        victim = victims[0]
        planted = lambda path: line + "\n" + read(path) if path == victim else read(path)
        found = check(tree, planted)
        if len(found) != 1 or expected not in found[0] or not found[0].startswith(victim):
            print(f"self-test: {line} planted in {victim} was not caught alone: {found}")
            return 1
        print(f"self-test: caught {found[0]}")
    print(f"self-test: {len(PLANTS)} wrong includes planted, {len(PLANTS)} caught")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--table", required=True, help="the link table oasis_check_layers() wrote")
    parser.add_argument("--root", required=True, help="the repository")
    parser.add_argument("--stamp", help="touch this file when the check passes")
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args()
    root = pathlib.Path(args.root).resolve()
    tree = Tree(root, read_table(args.table))
    read = lambda path: (root / path).read_text(errors="replace")
    if args.self_test:
        return self_test(tree, read)
    messages = check(tree, read)
    for message in messages:
        print(message)
    if messages:
        print(f"{len(messages)} layer error(s): fix the include, or the target's links in its "
              f"CMakeLists.txt (cmake/OasisLayers.cmake says how the check works)")
        return 1
    if args.stamp:
        stamp = pathlib.Path(args.stamp)
        stamp.parent.mkdir(parents=True, exist_ok=True)  # Makefiles do not create it
        stamp.touch()
    return 0


if __name__ == "__main__":
    sys.exit(main())
