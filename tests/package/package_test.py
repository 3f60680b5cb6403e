#!/usr/bin/env python3
"""The installed package, tried as a user outside this repository would (issue 15).

  consumer      `cmake --install` the build into a fresh prefix; a project outside the tree
                calls find_package(oasis), oasis_add_catalog() on a shipped spec, links
                oasis::runtime, builds and runs.
  runtime-only  configure this source tree with only the runtime, the compiler's and the
                robot's packages made unfindable (CMAKE_DISABLE_FIND_PACKAGE_*), install it,
                build a robot-side consumer that loads a catalog file; oasis_add_catalog()
                there stops with a message that says why.
  deb           `cpack -G DEB` the build; the package's Depends name the shared libraries,
                and its oasisc, unpacked, prints its version; so does its Python module, when
                the build has one (OASIS_BUILD_PYTHON), imported by Debian's /usr/bin/python3
                from /usr/lib/python3/dist-packages.

Every step's output is shown when it fails. Temporary directories are removed.
"""
import argparse
import os
import subprocess
import sys
import tempfile


def run(command, cwd=None, expect_failure=False, env=None):
    result = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, env=env)
    if (result.returncode == 0) == expect_failure:
        print("$ " + " ".join(command))
        print(result.stdout)
        sys.exit(f"package_test: {'succeeded' if expect_failure else 'failed'}: "
                 + " ".join(command))
    return result.stdout


def configure_and_build(cmake, source, build, prefix, *definitions):
    run([cmake, "-S", source, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
         f"-DCMAKE_PREFIX_PATH={prefix}", *definitions])
    run([cmake, "--build", build])


def consumer(args, scratch):
    prefix = os.path.join(scratch, "prefix")
    run([args.cmake, "--install", args.build, "--prefix", prefix])
    for program in ("oasisc", "oasis-sim", "oasis-go1"):
        path = os.path.join(prefix, "bin", program)
        if not os.access(path, os.X_OK):
            sys.exit(f"package_test: {program} is not installed in {prefix}/bin")
    print(run([os.path.join(prefix, "bin", "oasisc"), "--version"]).strip())
    build = os.path.join(scratch, "consumer")
    spec = os.path.join(prefix, "share", "oasis", "specs", "discrete_tracking.oasis")
    configure_and_build(args.cmake, os.path.join(args.here, "consumer"), build, prefix,
                        f"-DOASIS_SPEC={spec}")
    output = run([os.path.join(build, "consumer")])
    print(output.strip())
    if "2 abstractions, ML object_at_s3" not in output:
        sys.exit("package_test: the consumer did not follow the rewarded context")


UNFINDABLE = ["CGAL", "GMP", "Eigen3", "NLopt", "OpenCV", "apriltag", "yaml-cpp", "CLI11",
              "nlohmann_json", "GTest", "benchmark"]


def runtime_only(args, scratch):
    build = os.path.join(scratch, "oasis-runtime")
    prefix = os.path.join(scratch, "prefix")
    hidden = [f"-DCMAKE_DISABLE_FIND_PACKAGE_{package}=ON" for package in UNFINDABLE]
    run([args.cmake, "-S", args.source, "-B", build, "-G", "Ninja", "-DOASIS_BUILD_COMPILER=OFF",
         "-DOASIS_BUILD_HW=OFF", "--no-warn-unused-cli", *hidden])
    run([args.cmake, "--build", build])
    run([args.cmake, "--install", build, "--prefix", prefix])
    if os.path.exists(os.path.join(prefix, "bin")):
        sys.exit("package_test: a runtime-only install put programs in bin/")
    consumer_build = os.path.join(scratch, "runtime-consumer")
    source = os.path.join(args.here, "runtime_consumer")
    configure_and_build(args.cmake, source, consumer_build, prefix)
    catalog = os.path.join(args.source, "generated", "discrete_tracking", "discrete_tracking.bin")
    print(run([os.path.join(consumer_build, "runtime_consumer"), catalog]).strip())
    refused = run([args.cmake, "-S", source, "-B", os.path.join(scratch, "refused"), "-G", "Ninja",
                   f"-DCMAKE_PREFIX_PATH={prefix}", "-DTRY_CATALOG=ON"], expect_failure=True)
    if "needs oasisc, the compiler" not in refused:
        print(refused)
        sys.exit("package_test: oasis_add_catalog() without a compiler gave no clear message")


def deb(args, scratch):
    output = run([args.cpack, "-G", "DEB", "-B", scratch], cwd=args.build)
    packages = [name for name in os.listdir(scratch) if name.endswith(".deb")]
    if len(packages) != 1:
        print(output)
        sys.exit(f"package_test: expected one .deb, found {packages}")
    package = os.path.join(scratch, packages[0])
    depends = run(["dpkg-deb", "-f", package, "Depends"]).strip()
    print(f"{packages[0]}: Depends: {depends}")
    for library in ("libgmp", "libstdc++"):
        if library not in depends:
            sys.exit(f"package_test: the package does not depend on {library}")
    root = os.path.join(scratch, "root")
    run(["dpkg-deb", "-x", package, root])
    print(run([os.path.join(root, "usr", "bin", "oasisc"), "--version"]).strip())
    packages_dir = os.path.join(root, "usr", "lib", "python3", "dist-packages")
    if os.path.isdir(os.path.join(packages_dir, "oasis")):
        if "python3-numpy" not in depends:
            sys.exit("package_test: the package holds the Python module but does not depend on "
                     "python3-numpy")
        version = run(["/usr/bin/python3", "-c", "import oasis; print(oasis.__version__)"],
                      cwd=scratch, env={**os.environ, "PYTHONPATH": packages_dir}).strip()
        print(f"python3: import oasis: {version}")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("check", choices=["consumer", "runtime-only", "deb"])
    parser.add_argument("--cmake", required=True)
    parser.add_argument("--cpack", required=True)
    parser.add_argument("--source", required=True, help="the oasis source tree")
    parser.add_argument("--build", required=True, help="a built oasis build tree")
    args = parser.parse_args()
    args.here = os.path.dirname(os.path.abspath(__file__))
    checks = {"consumer": consumer, "runtime-only": runtime_only, "deb": deb}
    with tempfile.TemporaryDirectory(prefix="oasis_package_") as scratch:
        checks[args.check](args, scratch)


if __name__ == "__main__":
    main()
