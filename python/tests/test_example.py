"""examples/python/sweep.py runs, without matplotlib (no plot, said so) and with it (a PNG)."""

import importlib.util
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

EXAMPLE = SOURCE_DIR / "examples" / "python" / "sweep.py"
# Runs the example with `import matplotlib` failing, as on a machine without it.
WITHOUT = ("import runpy, sys; sys.modules['matplotlib'] = None; sys.argv = sys.argv[1:]; "
           "runpy.run_path(sys.argv[0], run_name='__main__')")


def rows(output):
    return [line.split() for line in output.splitlines() if line.strip()[:1].isdigit()]


def test_without_matplotlib(tmp_path):
    plot = tmp_path / "sweep.png"
    done = subprocess.run([sys.executable, "-c", WITHOUT, str(EXAMPLE), "--max", "1,2,3",
                           "--plot", str(plot)], capture_output=True, text=True, check=True)
    table = rows(done.stdout)
    assert [r[0] for r in table] == ["1", "2", "3"]
    assert [int(r[1]) for r in table] == [468, 677, 886]  # brp N=16: 677 states at MAX=2
    probabilities = [float(r[3]) for r in table]
    assert probabilities == sorted(probabilities, reverse=True)  # more retries, fewer errors
    assert "no plot" in done.stdout and not plot.exists()


@pytest.mark.skipif(importlib.util.find_spec("matplotlib") is None,
                    reason="python3-matplotlib is not installed (optional)")
def test_with_matplotlib(tmp_path):
    plot = tmp_path / "sweep.png"
    subprocess.run([sys.executable, str(EXAMPLE), "--max", "1,2", "--plot", str(plot)],
                   check=True, capture_output=True)
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
