#!/usr/bin/python3
"""oasis-ros against a real roscore (roscore_fixture.py): the fail-safe, signals, parameters and
the closed loop over topics. One case per run, so each has its own master and its own rospy node:
  ros_node_test.py CASE --oasis-ros PATH [--sim PATH] [--oasis-go1 PATH] [--work DIR]
Run by ctest (label ros). Needs Debian's python3 (rospy), not a virtualenv's."""

import argparse
import json
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import roscore_fixture  # noqa: E402

FAILURES = []


def check(condition, message):
    print(("ok:   " if condition else "FAIL: ") + message, flush=True)
    if not condition:
        FAILURES.append(message)


class TwistRecorder:
    """Every Twist on a topic, with the monotonic time it arrived."""

    def __init__(self, topic="/cmd_vel"):
        import rospy
        from geometry_msgs.msg import Twist
        self.lock = threading.Lock()
        self.received = []  # (time, forward, lateral, yaw_rate)
        rospy.Subscriber(topic, Twist, self._on_twist, queue_size=1000)

    def _on_twist(self, twist):
        with self.lock:
            self.received.append((time.monotonic(), twist.linear.x, twist.linear.y,
                                  twist.angular.z))

    def snapshot(self):
        with self.lock:
            return list(self.received)


def is_zero(entry):
    return entry[1] == 0.0 and entry[2] == 0.0 and entry[3] == 0.0


class DetectionsPublisher:
    """A tracker that sees two people standing still, at 5 Hz, until stopped."""

    def __init__(self, rate_hz=5.0):
        import rospy
        from geometry_msgs.msg import Pose, PoseArray
        from std_msgs.msg import Float64, Int8
        self.rospy, self.Pose, self.PoseArray = rospy, Pose, PoseArray
        self.positions = rospy.Publisher("/detections", PoseArray, queue_size=10)
        self.reward = rospy.Publisher("/reward", Float64, queue_size=10, latch=True)
        self.holder = rospy.Publisher("/treat_holder", Int8, queue_size=10, latch=True)
        self.period = 1.0 / rate_hz
        self.running = threading.Event()
        self.thread = None
        self.Float64, self.Int8 = Float64, Int8

    def start(self):
        self.reward.publish(self.Float64(0.0))
        self.holder.publish(self.Int8(1))
        self.running.set()
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def stop(self):
        self.running.clear()
        self.thread.join()
        return time.monotonic()

    def _run(self):
        while self.running.is_set():
            message = self.PoseArray()
            message.header.stamp = self.rospy.Time.now()
            message.header.frame_id = "base_link"
            for x, y in ((2.5, 1.2), (3.5, -1.5)):
                pose = self.Pose()
                pose.position.x, pose.position.y, pose.orientation.w = x, y, 1.0
                message.poses.append(pose)
            self.positions.publish(message)
            time.sleep(self.period)


def wait_for_subscriber(publisher, timeout_s=20.0):
    deadline = time.monotonic() + timeout_s
    while publisher.get_num_connections() == 0 and time.monotonic() < deadline:
        time.sleep(0.05)
    return publisher.get_num_connections() > 0


def start_node(args, env, extra=(), log=None):
    command = [args.oasis_ros, "--quiet"]
    if log:
        command += ["--log", log]
    command += list(extra)
    return subprocess.Popen(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)


def init_rospy(env, name):
    os.environ.update(env)
    import rospy
    rospy.init_node(name, anonymous=True, disable_signals=True)
    return rospy


def case_bad_parameter(args, env):
    rospy = init_rospy(env, "oasis_test_bad_parameter")
    recorder = TwistRecorder()
    node = start_node(args, env, ["_loop/rate_hz:=fast", "_ros/mode:=detectoins"])
    out, err = node.communicate(timeout=60)
    sys.stderr.write(err)
    check(node.returncode == 1, "a bad parameter exits with status 1 (got %s)" % node.returncode)
    check("parameter ~loop/rate_hz" in err and "expected a number" in err,
          "the message names ~loop/rate_hz and what it expects")
    check("parameter ~ros/mode" in err and 'did you mean "detections"' in err,
          "every bad parameter is named in one run (~ros/mode, with a suggestion)")
    time.sleep(0.5)
    twists = recorder.snapshot()
    check(len(twists) >= 1 and all(is_zero(t) for t in twists),
          "a zero Twist was sent before exiting (%d received)" % len(twists))
    del rospy


def run_with_detections(args, env, name):
    rospy = init_rospy(env, name)
    recorder = TwistRecorder()
    tracker = DetectionsPublisher()
    node = start_node(args, env, ["_ros/mode:=detections", "_ros/use_odom:=false"])
    check(wait_for_subscriber(tracker.positions), "oasis-ros subscribed to /detections")
    tracker.start()
    return rospy, recorder, tracker, node


def case_fail_safe(args, env):
    _, recorder, tracker, node = run_with_detections(args, env, "oasis_test_fail_safe")
    time.sleep(3.0)
    stopped_at = tracker.stop()
    time.sleep(1.5)
    twists = recorder.snapshot()
    node.send_signal(signal.SIGINT)
    out, err = node.communicate(timeout=30)
    sys.stderr.write(err)
    moving = [t for t in twists if not is_zero(t)]
    check(len(moving) >= 5, "the robot was driven while detections came (%d non-zero Twists)" %
          len(moving))
    if not moving:
        return
    last_moving = moving[-1][0]
    zeros_after = [t for t in twists if is_zero(t) and t[0] > last_moving]
    check(bool(zeros_after), "a zero Twist followed the last non-zero one")
    if zeros_after:
        gap_ms = (zeros_after[0][0] - last_moving) * 1000.0
        check(gap_ms <= 250.0, "the zero Twist came %.0f ms after the last non-zero one (<= 250)"
              % gap_ms)
    check(not any(not is_zero(t) for t in twists if t[0] > last_moving),
          "no non-zero Twist after the fail-safe")
    check(last_moving - stopped_at < 0.5,
          "the last non-zero Twist was %.0f ms after the detections stopped (< 500: one period "
          "plus the 200 ms timeout)" % ((last_moving - stopped_at) * 1000.0))
    check("fail-safe stops" in err, "the summary reports the fail-safe")


def case_sigint(args, env):
    _, recorder, tracker, node = run_with_detections(args, env, "oasis_test_sigint")
    time.sleep(2.5)
    signalled_at = time.monotonic()
    node.send_signal(signal.SIGINT)
    out, err = node.communicate(timeout=30)
    time.sleep(0.3)
    tracker.stop()
    sys.stderr.write(err)
    twists = recorder.snapshot()
    check(any(not is_zero(t) for t in twists), "the robot was driven before the signal")
    check(bool(twists) and is_zero(twists[-1]), "the last Twist is zero")
    zeros_after = [t for t in twists if is_zero(t) and t[0] >= signalled_at]
    check(bool(zeros_after) and zeros_after[0][0] - signalled_at < 0.25,
          "a zero Twist came within 250 ms of SIGINT")
    check(node.returncode in (-signal.SIGINT, 130),
          "oasis-ros died of SIGINT, as an interrupted program does (got %s)" % node.returncode)


def accuracy_of(json_text, controller=None):
    data = json.loads(json_text)
    row = data[controller] if controller else data
    return row["accuracy"]["mean"]


def case_closed_loop(args, env, trials=3, seed=1):
    """oasis-ros in camera mode against the hallway simulator node, over topics, on the seeds
    of `oasis-go1 sim --seed 1 --trials 3 --perception rendered`: the same accuracy within 0.03.
    """
    work = args.work
    logs = []
    for trial in range(trials):
        log = os.path.join(work, "ros_trial%02d.jsonl" % (trial + 1))
        node = start_node(args, env, log=log)
        # Twice real time: the world still steps 0.2 s per frame, and oasis-ros decides on each
        # frame as it comes (about 20 ms); the test takes half as long.
        sim = subprocess.run([args.sim, "--seed", str(seed * 1000 + trial), "--rate-hz", "10"],
                             env=env,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             timeout=600)
        time.sleep(0.5)
        node.send_signal(signal.SIGINT)
        out, err = node.communicate(timeout=30)
        sys.stderr.write(sim.stderr.splitlines()[-1] + "\n" + err.splitlines()[-1] + "\n")
        check(sim.returncode == 0, "trial %d: the simulator ran to the end" % (trial + 1))
        frames = sum(1 for _ in open(log))
        with open(log) as steps:
            truths = sum(1 for line in steps if '"truth"' in line)
        check(frames >= 295 and truths == frames,
              "trial %d: %d steps logged, each with its ground truth (%d)" %
              (trial + 1, frames, truths))
        logs.append(log)
    scored = subprocess.run([args.oasis_go1, "score", "--json"] + logs, stdout=subprocess.PIPE,
                            text=True, check=True)
    ros_accuracy = accuracy_of(scored.stdout)
    simulated = subprocess.run(
        [args.oasis_go1, "sim", "--perception", "rendered", "--seed", str(seed), "--trials",
         str(trials), "--controllers", "ours", "--json", "--quiet", "--logs",
         os.path.join(work, "sim")], stdout=subprocess.PIPE, text=True, check=True)
    sim_accuracy = accuracy_of(simulated.stdout, "ours")
    same = total = 0
    for trial in range(trials):
        ours = decisions(logs[trial])
        theirs = decisions(os.path.join(work, "sim", "ours_trial%02d.jsonl" % (trial + 1)))
        same += sum(a[:2] == b[:2] for a, b in zip(ours, theirs))
        total += len(theirs)
    print("decisions equal to oasis-go1 sim's, step for step: %d of %d" % (same, total))
    print("accuracy over %d trials: oasis-ros over topics %.4f, oasis-go1 sim %.4f" %
          (trials, ros_accuracy, sim_accuracy))
    check(abs(ros_accuracy - sim_accuracy) <= 0.03,
          "oasis-ros reaches oasis-go1 sim's accuracy within 0.03 (%.4f vs %.4f)" %
          (ros_accuracy, sim_accuracy))


def case_launch(args, env, steps=25):
    """roslaunch of the shipped hallway_sim.launch (simulator + oasis.launch) runs the loop."""
    work = args.work
    log = os.path.join(work, "launch_steps.jsonl")
    launch_env = dict(env)
    launch_env["ROS_PACKAGE_PATH"] = args.package_path + ":/usr/share"
    run = subprocess.run(["roslaunch", "oasis_ros", "hallway_sim.launch", "steps:=%d" % steps,
                          "log:=" + log], env=launch_env, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, timeout=180)
    sys.stderr.write("\n".join(run.stdout.splitlines()[-12:]) + "\n")
    check(run.returncode == 0, "roslaunch ran and ended with the trial (status %d)" %
          run.returncode)
    lines = open(log).read().splitlines() if os.path.exists(log) else []
    check(len(lines) == steps and all('"truth"' in line for line in lines),
          "the launched oasis-ros logged %d steps with their truth (expected %d)" %
          (len(lines), steps))


def decisions(log):
    with open(log) as steps:
        return [(r["abstraction"], r["action"], r["belief"]) for r in map(json.loads, steps)]


def write_detections_bag(camera_log, camera_bag, out_bag):
    """The detections a tracker would publish if it saw what our perception saw in each step of
    `camera_log` (a replay of `camera_bag`): positions (NaN when unseen), the reward the filter
    was given (NaN when not known) and the holder, stamped as the frames; odometry and the
    ground truth copied."""
    import rosbag
    import rospy
    from geometry_msgs.msg import Pose, PoseArray
    from std_msgs.msg import Float64, Int8
    with open(camera_log) as steps:
        records = [json.loads(line) for line in steps]
    with rosbag.Bag(camera_bag) as source, rosbag.Bag(out_bag, "w") as out:
        stamps = []
        for topic, message, t in source.read_messages():
            if topic in ("odom", "ground_truth"):
                out.write(topic, message, t)
            if topic == "camera/color/image_raw":
                stamps.append((message.header.stamp, t))
        for (stamp, t), record in zip(stamps, records):
            # The reward and holder count as the latest before the positions (a bag orders
            # messages of one time as it likes): a microsecond earlier.
            before = t - rospy.Duration(0, 1000)
            reward = record["reward"]
            out.write("reward", Float64(float("nan") if reward is None else reward), before)
            out.write("treat_holder", Int8(record["holder"]), before)
            positions = PoseArray()
            positions.header.stamp = stamp
            positions.header.frame_id = "base_link"
            for human in record["humans"]:
                pose = Pose()
                pose.position.x = human["x_m"] if human["seen"] else float("nan")
                pose.position.y = human["y_m"] if human["seen"] else float("nan")
                pose.orientation.w = 1.0
                positions.poses.append(pose)
            out.write("detections", positions, t)
    return len(records)


def case_replay(args, env, steps=40):
    """A live run over topics, with the simulator recording its bag; the bag replayed offline
    gives the live decisions step for step; and perception's own output of that replay, fed as
    detections, gives them again."""
    work = args.work
    live_log, bag = os.path.join(work, "live.jsonl"), os.path.join(work, "hallway.bag")
    node = start_node(args, env, log=live_log)
    sim = subprocess.run([args.sim, "--seed", "2001", "--steps", str(steps), "--bag", bag],
                         env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         timeout=300)
    time.sleep(0.5)
    node.send_signal(signal.SIGINT)
    node.communicate(timeout=30)
    check(sim.returncode == 0 and os.path.exists(bag), "the simulator wrote its bag")

    def replay(bag_path, log, params=None):
        command = [args.oasis_ros, "--bag", bag_path, "--log", log, "--quiet"]
        if params:
            command += ["--params", params]
        run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             timeout=300, env={k: v for k, v in os.environ.items()
                                               if not k.startswith("ROS_")})
        sys.stderr.write(run.stderr)
        check(run.returncode == 0, "oasis-ros --bag %s ran without a master" %
              os.path.basename(bag_path))
        return decisions(log) if os.path.exists(log) else []

    live = decisions(live_log)
    replayed_log = os.path.join(work, "replay.jsonl")
    replayed = replay(bag, replayed_log)
    check(len(live) == steps and replayed == live,
          "the replay's %d decisions equal the live run's %d, step for step" %
          (len(replayed), len(live)))

    detections_bag = os.path.join(work, "detections.bag")
    write_detections_bag(replayed_log, bag, detections_bag)
    params = os.path.join(work, "detections.yaml")
    with open(params, "w") as out:
        out.write("ros: {mode: detections}\n")
    detected = replay(detections_bag, os.path.join(work, "detections.jsonl"), params)
    check(len(detected) == steps and detected == replayed,
          "fed perception's own output, the detections mode decides as the camera mode (%d of "
          "%d steps equal)" % (sum(a == b for a, b in zip(detected, replayed)), len(replayed)))


CASES = {
    "replay": case_replay,
    "launch": case_launch,
    "closed_loop": case_closed_loop,
    "bad_parameter": case_bad_parameter,
    "fail_safe": case_fail_safe,
    "sigint": case_sigint,
}


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("case", choices=sorted(CASES))
    parser.add_argument("--oasis-ros", required=True)
    parser.add_argument("--sim")
    parser.add_argument("--oasis-go1")
    parser.add_argument("--package-path", help="the folder holding the oasis_ros package")
    parser.add_argument("--work", default=None)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="oasis-ros-test-") as scratch:
        args.work = args.work or scratch  # logs and bags, removed at the end unless --work
        with roscore_fixture.roscore() as env:
            CASES[args.case](args, env)
    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
