"""A private ROS master for one test: roscore on a free port, with ROS_HOME, ROS_LOG_DIR and
ROS_MASTER_URI pointing into the test's own temporary folder, stopped (SIGINT, then SIGKILL)
when the test ends. Nothing of the user's ROS environment is read or written."""

import contextlib
import os
import signal
import socket
import subprocess
import tempfile
import time


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def _master_answers(port):
    with contextlib.suppress(OSError), socket.create_connection(("127.0.0.1", port), 0.2):
        return True
    return False


@contextlib.contextmanager
def roscore(timeout_s=30.0):
    """Yields the environment (a dict) under which processes talk to this master."""
    with tempfile.TemporaryDirectory(prefix="oasis-roscore-") as home:
        port = free_port()
        env = {k: v for k, v in os.environ.items() if not k.startswith("ROS_")}
        env.update({
            "ROS_HOME": home,
            "ROS_LOG_DIR": os.path.join(home, "log"),
            "ROS_MASTER_URI": "http://127.0.0.1:%d" % port,
            "ROS_IP": "127.0.0.1",
            "PYTHONPATH": "",
        })
        log = open(os.path.join(home, "roscore.log"), "w")
        core = subprocess.Popen(["roscore", "-p", str(port)], env=env, stdout=log,
                                stderr=subprocess.STDOUT, start_new_session=True)
        try:
            deadline = time.monotonic() + timeout_s
            while not _master_answers(port):
                if core.poll() is not None or time.monotonic() > deadline:
                    log.flush()
                    raise RuntimeError("roscore did not start on port %d:\n%s" %
                                       (port, open(log.name).read()))
                time.sleep(0.1)
            # The master answers before rosout is up; give it a moment to register.
            time.sleep(1.0)
            yield env
        finally:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(core.pid, signal.SIGINT)
            try:
                core.wait(10)
            except subprocess.TimeoutExpired:
                os.killpg(core.pid, signal.SIGKILL)
                core.wait()
            log.close()
