#!/usr/bin/python3
"""oasis-ros's latency, from an image's stamp to the Twist its decision publishes, per step, at
640x480: oasis-ros pinned to one core (taskset), the hallway simulator node on another, both on a
private roscore (tests/hw/ros/roscore_fixture.py). Prints oasis-ros's own summary line (median,
p99, max) per trial. A benchmark, run by hand (docs/PERFORMANCE.md has the figures):
  tests/bench/ros_latency.py --build build/default [--trials 3] [--frames 300]"""

import argparse
import os
import signal
import subprocess
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "hw", "ros"))
import roscore_fixture  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build/default")
    parser.add_argument("--trials", type=int, default=3)
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--node-core", type=int, default=0)
    parser.add_argument("--sim-core", type=int, default=1)
    args = parser.parse_args()
    node_program = os.path.join(args.build, "hw", "ros", "oasis-ros")
    sim_program = os.path.join(args.build, "hw", "ros", "oasis-ros-hallway-sim")
    print("oasis-ros latency, image stamp -> cmd_vel publish, 640x480, oasis-ros on core %d"
          % args.node_core)
    for trial in range(args.trials):
        with roscore_fixture.roscore() as env:
            node = subprocess.Popen(["taskset", "-c", str(args.node_core), node_program,
                                     "--quiet"], env=env, stdout=subprocess.PIPE,
                                    stderr=subprocess.PIPE, text=True)
            subprocess.run(["taskset", "-c", str(args.sim_core), sim_program, "--seed",
                            str(1000 + trial), "--steps", str(args.frames)], env=env,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
            time.sleep(0.5)
            node.send_signal(signal.SIGINT)
            _, err = node.communicate(timeout=30)
            line = [l for l in err.splitlines() if "latency" in l]
            print("trial %d (seed %d): %s" % (trial + 1, 1000 + trial,
                                              line[-1].split("cmd_vel: ", 1)[-1] if line else
                                              "no latency line: " + err[-400:]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
