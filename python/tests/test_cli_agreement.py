"""The module gives the CLI's answers: the same catalog bytes as `oasisc compile` on every
shipped spec, the same blocks as `oasisc quotient`, the same values as `oasisc query`."""

import filecmp
import json
import os
import re
import subprocess
from fractions import Fraction

import pytest

import oasis
from conftest import OASISC, PRISM_DATA, SOURCE_DIR

SPECS = sorted((SOURCE_DIR / "specs").rglob("*.oasis"))


def has_objective(spec):
    return re.search(r"^\s*objective\b", spec.read_text(), re.MULTILINE) is not None


def run(*args):
    return subprocess.run([OASISC, *map(str, args)], check=True, capture_output=True,
                          text=True).stdout


@pytest.mark.parametrize("spec", SPECS, ids=lambda p: str(p.relative_to(SOURCE_DIR)))
def test_compile_writes_the_cli_bytes(spec, tmp_path):
    ours = tmp_path / "python"
    if has_objective(spec):
        # A controller is compiled by oasisc alone (docs/python.md): refused, nothing written.
        with pytest.raises(oasis.CompileError, match="oasisc compile"):
            oasis.compile(str(spec), str(ours))
        assert not ours.exists()
        return
    theirs = tmp_path / "cli"
    catalog = oasis.compile(str(spec), str(ours), jobs=2)
    run("compile", spec, "-o", theirs, "-j", "2", "--progress", "never")
    names = sorted(os.listdir(theirs))
    assert sorted(os.listdir(ours)) == names
    match, mismatch, errors = filecmp.cmpfiles(ours, theirs, names, shallow=False)
    assert (mismatch, errors) == ([], [])
    assert catalog.path == str(ours / (catalog.name + ".bin"))


def blocks_of(partition, state_names):
    index = {name: s for s, name in enumerate(state_names)}
    block_of = [0] * len(state_names)
    for b, members in enumerate(partition):
        for name in members:
            block_of[index[name]] = b
    return block_of


@pytest.mark.parametrize("path,labels", [
    (SOURCE_DIR / "specs" / "discrete_tracking.oasis", "all"),
    (SOURCE_DIR / "specs" / "discrete_tracking_prism.oasis", "all"),
    (PRISM_DATA / "knuth_die.pm", "one"),
    (PRISM_DATA / "two_dice.nm", "two"),
])
def test_quotient_blocks(path, labels):
    model = oasis.load_model(str(path))
    cli = json.loads(run("quotient", path, "--format", "json", "--partition",
                         "--respect-labels", labels))
    names = [model.state_name(s) for s in range(model.nr_states)]
    respect = labels if labels == "all" else [labels]
    for context in cli["contexts"]:
        ours = oasis.bisimulate(model, respect_labels=respect, context=context["name"])
        assert ours.nr_blocks == context["blocks"]
        assert list(ours.block_of) == blocks_of(context["partition"], names)


def cli_value(path, prop, mode):
    line = run("query", path, "--mode", mode, "--prop", prop, "--whole-fractions")
    if mode == "exact":
        return Fraction(re.search(r" = ([-0-9/]+)", line).group(1))
    lower, upper = re.search(r" in \[([^,]+), ([^\]]+)\]", line).groups()
    return oasis.Interval(float(lower), float(upper))


@pytest.mark.parametrize("path,prop", [
    (PRISM_DATA / "knuth_die.pm", 'P=? [F "two"]'),
    (PRISM_DATA / "two_dice.nm", 'Pmin=? [F "two"]'),
    (PRISM_DATA / "leader_async3.nm", 'Pmax=? [F "elected"]'),
    (SOURCE_DIR / "specs" / "discrete_tracking.nm", 'Pmax=? [F<=3 s=3]'),
])
def test_property_values(path, prop):
    model = oasis.load_model(str(path))
    assert oasis.check(model, prop) == cli_value(path, prop, "exact")
    assert oasis.check(model, prop, exact=False) == cli_value(path, prop, "sound")
