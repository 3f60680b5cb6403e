"""Long calls release the GIL and stop on Ctrl-C with KeyboardInterrupt, leaving nothing half
written. Each case runs in a child interpreter that signals itself while the call runs; a call
that did not stop would run for hours (the counter's 10^9 states), so ctest's timeout is the
failure, and no wall-clock time is asserted."""

import os
import subprocess
import sys
import textwrap

from conftest import SOURCE_DIR

CHILD = textwrap.dedent("""
    import os, signal, sys, threading
    import oasis
    def interrupt():
        os.kill(os.getpid(), signal.SIGINT)
    threading.Timer(float(sys.argv[2]), interrupt).start()
    try:
        {call}
    except KeyboardInterrupt:
        print("interrupted")
        sys.exit(0)
    print("finished")
""")

COUNTER = """dtmc
module counter
  x : [0..1000000000] init 0;
  [] x < 1000000000 -> (x'=x+1);
endmodule
"""


def run_child(call, delay, *arguments):
    done = subprocess.run([sys.executable, "-c", CHILD.format(call=call), "-", str(delay),
                           *arguments], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return done.stdout.strip()


def test_exploration_stops(tmp_path):
    program = tmp_path / "counter.pm"
    program.write_text(COUNTER)
    call = ("oasis.build_model(oasis.parse_prism_program(sys.argv[3]), "
            "max_states=2000000000)")
    assert run_child(call, 0.5, str(program)) == "interrupted"


def test_other_threads_run_meanwhile(tmp_path):
    # The GIL is released: a Python thread counts while the model is explored.
    program = tmp_path / "counter.pm"
    program.write_text(COUNTER)
    call = textwrap.dedent("""
        ticks = []
        stop = threading.Event()
        def count():
            while not stop.is_set():
                ticks.append(1)
                stop.wait(0.01)
        threading.Thread(target=count, daemon=True).start()
        try:
            oasis.build_model(oasis.parse_prism_program(sys.argv[3]), max_states=2000000000)
        finally:
            stop.set()
            print("ticks", len(ticks) > 5)
    """).replace("\n", "\n        ")
    assert run_child(call, 1.0, str(program)).splitlines() == ["ticks True", "interrupted"]


def test_compile_leaves_nothing(tmp_path):
    out = tmp_path / "catalog"
    spec = SOURCE_DIR / "specs" / "go1_treat.oasis"
    assert run_child("oasis.compile(sys.argv[3], sys.argv[4], jobs=1)", 1.0, str(spec),
                     str(out)) == "interrupted"
    assert os.listdir(tmp_path) == []  # no catalog, no staging directory left beside it
