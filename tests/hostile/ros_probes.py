#!/usr/bin/python3
"""Hostile input for oasis-ros (issue 37), run as a user would, against a roscore of its own
(tests/hw/ros/roscore_fixture.py: a free port, its own ROS home, stopped at the end). The same
rules as the other programs (hostile_probes.py, probe_harness.py):
  usage     exit 2 for every usage error (CLI11's own codes 104-109 never leak), an unknown
            option, --params without --bag;
  numbers   --steps and --master-timeout-ms through common/command_line/number_options.hpp: no sign, no
            exponent, nothing past 2^64 - 1, nothing out of range;
  empty     an empty value is refused on every option (-o '' or --log '' never mean "none");
  budget    --memory-budget as in every program;
  reading   --bag given a FIFO (it blocked open() forever), a folder, a device, no bag;
            --params given a FIFO;
  names     a topic parameter that is no ROS name names the parameter, exit 1, never ROS's
            raw text.
Each probe also asserts no crash text and a message of a few lines. Run by ctest
(hostile.ros, label hostile;ros; only where OASIS_BUILD_ROS is on):

    tests/hostile/ros_probes.py --oasis-ros B/hw/ros/oasis-ros --source-dir .
"""

import argparse
import os
import sys
import tempfile

from probe_harness import report, run_probe, write_bytes

NOT_A_NUMBER = ["nan", "inf", "-inf", "1e999", "0x10", "", "1,5", "twelve", "5\x01"]
NOT_A_COUNT = ["-1", "-0", "1.5", "1e3", "+3", "18446744073709551616"]
BUDGETS_REFUSED = ["nan", "-1", "1e999", "0x10", "12Q", "101%", "0%", "1K", ""]


def usage_probes(paths):
    """Refused while parsing the command line: status 2, the option named."""
    r = paths.oasis_ros
    for value in NOT_A_NUMBER + NOT_A_COUNT:
        yield [r, "--steps", value], 2, "--steps"
    for value in NOT_A_NUMBER + NOT_A_COUNT + ["5", "99", "600001"]:
        yield [r, "--master-timeout-ms", value], 2, "--master-timeout-ms"
    for option in ["--log", "--bag", "--params", "--memory-budget", "--steps"]:
        yield [r, option, ""], 2, option
    for value in BUDGETS_REFUSED:
        yield [r, "--bag", paths.text_file, "--memory-budget", value], 2, "--memory-budget"
    yield [r, "--no-such-option"], 2, "--no-such-option"
    yield [r, "--steps"], 2, "--steps"
    yield [r, "--quiet=maybe"], 2, "--quiet"
    yield [r, "--params", paths.params], 2, "--params"
    yield [r, "--bag", paths.missing], 2, paths.missing
    yield [r, "--bag", paths.folder], 2, paths.folder


def reading_probes(paths):
    """Files that are not what they claim: status 1, the path and the option named."""
    r = paths.oasis_ros
    yield [r, "--bag", paths.fifo], 1, "--bag " + paths.fifo
    yield [r, "--bag", "/dev/null"], 1, "--bag /dev/null"
    yield [r, "--bag", paths.text_file], 1, paths.text_file
    yield [r, "--bag", paths.text_file, "--params", paths.fifo], 1, paths.fifo
    yield [r, "--bag", paths.text_file, "--params", paths.bad_topic_params], 1, \
        "ros.topics.colour"


def name_probes(paths):
    """A live node (the roscore fixture's master) given topic parameters that are no ROS
    names: status 1, the parameter named."""
    r = paths.oasis_ros
    yield [r, "_ros/topics/cmd_vel:=bad name"], 1, "~ros/topics/cmd_vel"
    yield [r, "_ros/topics/odom:=9odom"], 1, "~ros/topics/odom"
    yield [r, "_ros/topics/detections:=a-b", "_ros/mode:=detections"], 1, \
        "~ros/topics/detections"


def prepare(root):
    paths = argparse.Namespace()
    paths.fifo = os.path.join(root, "bag.fifo")
    os.mkfifo(paths.fifo)
    paths.folder = os.path.join(root, "folder.bag")
    os.mkdir(paths.folder)
    paths.missing = os.path.join(root, "missing.bag")
    paths.text_file = os.path.join(root, "not_a.bag")
    write_bytes(paths.text_file, b"#ROSBAG V2.0\nthis is no bag\n")
    paths.params = os.path.join(root, "params.yaml")
    write_bytes(paths.params, b"ros: {mode: camera}\n")
    paths.bad_topic_params = os.path.join(root, "bad_topic.yaml")
    write_bytes(paths.bad_topic_params, b"ros:\n  topics:\n    colour: \"bad name\"\n")
    return paths


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--oasis-ros", required=True)
    parser.add_argument("--source-dir", required=True)
    arguments = parser.parse_args()
    sys.path.insert(0, os.path.join(arguments.source_dir, "tests/hw/ros"))
    import roscore_fixture  # noqa: E402 (the fixture lives with the ROS tests)

    failures, count = [], 0
    with tempfile.TemporaryDirectory(prefix="oasis-ros-probes-") as root:
        paths = prepare(root)
        paths.oasis_ros = arguments.oasis_ros
        # Without a master: these never reach ROS (ROS_MASTER_URI points nowhere, so a probe
        # that did would fail on its timeout, not pass).
        offline = {k: v for k, v in os.environ.items() if not k.startswith("ROS_")}
        offline["ROS_MASTER_URI"] = "http://127.0.0.1:9"
        for probe_arguments, status, culprit in list(usage_probes(paths)) + \
                list(reading_probes(paths)):
            count += 1
            failure = run_probe(probe_arguments, status, culprit, env=offline)
            if failure:
                failures.append(failure)
        with roscore_fixture.roscore() as env:
            for probe_arguments, status, culprit in name_probes(paths):
                count += 1
                failure = run_probe(probe_arguments, status, culprit, env=env)
                if failure:
                    failures.append(failure)
    return report(failures, count)


if __name__ == "__main__":
    sys.exit(main())
