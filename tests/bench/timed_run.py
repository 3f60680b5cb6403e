"""Runs one command and measures it, for the benchmark scripts beside this file.

The command runs under a fresh Python process, so that RUSAGE_CHILDREN of that process holds
the command's own peak resident memory and CPU time and nothing else the benchmark ran before.
"""
import subprocess
import sys

_PROBE = ("import resource,subprocess,sys,time;t=time.perf_counter();"
          "r=subprocess.run(sys.argv[1:],capture_output=True,text=True);e=time.perf_counter()-t;"
          "u=resource.getrusage(resource.RUSAGE_CHILDREN);"
          "print(r.returncode,e,u.ru_maxrss,u.ru_utime+u.ru_stime);"
          "print(r.stdout,end='');sys.stderr.write(r.stderr)")


def run_timed_cpu(command):
    """Returns (wall-clock seconds, CPU seconds (user + system), peak RSS in MiB, the command's
    stdout); exits the benchmark with the command's output when it fails."""
    result = subprocess.run([sys.executable, "-c", _PROBE] + [str(c) for c in command],
                            capture_output=True, text=True, check=False)
    first, _, output = result.stdout.partition("\n")
    status, seconds, rss_kb, cpu = first.split()
    if status != "0":
        raise SystemExit(f"failed: {' '.join(map(str, command))}\n{output}\n{result.stderr}")
    return float(seconds), float(cpu), int(rss_kb) / 1024, output


def run_timed(command):
    """Returns (wall-clock seconds, peak RSS in MiB, the command's stdout); exits the
    benchmark with the command's output when it fails."""
    seconds, _, peak, output = run_timed_cpu(command)
    return seconds, peak, output
