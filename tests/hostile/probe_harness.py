"""What every hostile probe script shares (hostile_probes.py, and one script per program whose
surface needs a fixture of its own: a roscore for oasis-ros, mpirun for oasisc-mpi): running one
probe as a user would and judging what it printed, and the snapshot that proves refused commands
changed nothing.

A probe is (program arguments, expected exit status, text the message must name). It fails when
the status differs, when the culprit is not named, when the output holds crash text, when the
message is longer than a few lines, or when it hangs.
"""

import os
import subprocess

# Text that only a crash or a leak of internals prints.
CRASH_TEXT = ["json.exception", "terminate called", "Assertion", "AddressSanitizer",
              "runtime error:", "Segmentation fault", "internal error", "what():",
              "OpenCV(", "Failed to allocate", "[FATAL]", "Backtrace", "Signal:"]


def write_bytes(path, data):
    with open(path, "wb") as out:
        out.write(data)


def shown(arguments):
    """The command as a person would type it, for a failure message."""
    return " ".join(repr(a) if (not a or " " in a or not a.isprintable()) else a
                    for a in [os.path.basename(arguments[0])] + arguments[1:])


def judge(arguments, expected, culprit, status, output):
    """The failure message for a finished probe, or None when it held."""
    if status != expected:
        return f"{shown(arguments)}: status {status}, expected {expected}\n{output[:2000]}"
    if culprit not in output:
        return f"{shown(arguments)}: the message does not name {culprit}\n{output[:2000]}"
    if any(text in output for text in CRASH_TEXT):
        return f"{shown(arguments)}: the output holds crash text\n{output[:600]}"
    if len(output) > 2000 or max(len(l) for l in output.splitlines() or [""]) > 400:
        return f"{shown(arguments)}: the message is longer than a few lines\n{output[:600]}"
    return None


def run_probe(arguments, expected, culprit, timeout=60, env=None):
    """Runs one probe with no input; the failure message, or None when it held."""
    try:
        result = subprocess.run(arguments, capture_output=True, timeout=timeout,
                                stdin=subprocess.DEVNULL, env=env)
    except subprocess.TimeoutExpired:
        return f"{shown(arguments)}: hung ({timeout} s)"
    output = (result.stdout + result.stderr).decode("utf-8", "replace")
    return judge(arguments, expected, culprit, result.returncode, output)


def snapshot(folder):
    """Every file under `folder` with its bytes: what the probes must leave as it was."""
    files = {}
    for directory, _, names in os.walk(folder):
        for name in names:
            path = os.path.join(directory, name)
            if os.path.isfile(path):
                with open(path, "rb") as data:
                    files[path] = data.read()
            else:
                files[path] = None
    return files


def report(failures, count):
    """Prints the failures and the count; the exit status of the script."""
    for failure in failures:
        print("FAILED:", failure)
    print(f"{count} probes, {len(failures)} failed")
    return 1 if failures else 0
