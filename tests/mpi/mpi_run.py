"""Running oasisc-mpi under mpirun from the tests: the environment OpenMPI 4.1 needs on a CI
machine (root, fewer cores than ranks) and a bounded wait."""

import os
import shutil
import subprocess
from pathlib import Path

_session_root = None


def start_work(path):
    """Empties the test's work folder and keeps OpenMPI's session files in it, not in TMPDIR
    (which the suite checks is left empty)."""
    global _session_root
    work = Path(path)
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    _session_root = work / "mpi-session"
    _session_root.mkdir()
    return work


def mpi_environment():
    env = dict(os.environ)
    if _session_root is not None:
        env["TMPDIR"] = str(_session_root)
    # CI runs as root; OpenMPI refuses that unless told twice.
    env["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
    env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    # Under the asan preset: OpenMPI never frees what MPI_Init allocates, from components it
    # dlopens and unloads again, so LeakSanitizer reports them with no library name a
    # suppression could match. Address and undefined-behaviour checks stay on.
    if "ASAN_OPTIONS" in env:
        env["ASAN_OPTIONS"] += ":detect_leaks=0"
    # More ranks than cores: let ranks that wait give the core away instead of spinning.
    env["OMPI_MCA_mpi_yield_when_idle"] = "1"
    env["OMPI_MCA_rmaps_base_oversubscribe"] = "1"
    return env


def mpirun(ranks, command, timeout=600, extra_env=None):
    env = mpi_environment()
    env.update(extra_env or {})
    return subprocess.run(["mpirun", "-np", str(ranks), "--oversubscribe"] + command,
                          capture_output=True, text=True, env=env, timeout=timeout)


def chain_aut(path, states):
    """A chain of `states` states, one transition each (a few bytes per state): a model whose
    size the tests choose, to read a large file or to cut one."""
    with open(path, "w", encoding="utf-8") as out:
        out.write(f"des (0,{states},{states})\n")
        for s in range(states - 1):
            out.write(f'({s},"a",{s + 1})\n')
        out.write(f'({states - 1},"a|reward(1)",{states - 1})\n')
