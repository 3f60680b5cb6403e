"""stormpy's and Storm's published bisimulation and model-checking cases, answered through the
module as stormpy's users would ask them (parse_prism_program, build_model, bisimulate,
check).

The die's program is written out below (Knuth and Yao's die, as tests/data/prism/knuth_die.pm
has it, written for oasis from the model's description). The published figures of the other
programs are in tests/data/prism/published.json with the exact assertion of Storm's or
stormpy's test behind each one (its "source" field); the programs are in that folder too.
"""

import json
from fractions import Fraction

import pytest

import oasis
from conftest import PRISM_DATA

# Knuth and Yao's die: a fair coin simulates a fair die (node 0 is the root, 7 the faces).
DIE = """dtmc
module die
  node : [0..7] init 0;
  face : [0..6] init 0;
  [] node=0 -> 0.5 : (node'=1) + 0.5 : (node'=2);
  [] node=1 -> 0.5 : (node'=3) + 0.5 : (node'=4);
  [] node=2 -> 0.5 : (node'=5) + 0.5 : (node'=6);
  [] node=3 -> 0.5 : (node'=1) + 0.5 : (node'=7) & (face'=1);
  [] node=4 -> 0.5 : (node'=7) & (face'=2) + 0.5 : (node'=7) & (face'=3);
  [] node=5 -> 0.5 : (node'=7) & (face'=4) + 0.5 : (node'=7) & (face'=5);
  [] node=6 -> 0.5 : (node'=2) + 0.5 : (node'=7) & (face'=6);
  [] node=7 -> 1 : (node'=7);
endmodule
label "one" = face=1;
label "two" = face=2;
label "three" = face=3;
label "four" = face=4;
label "five" = face=5;
label "six" = face=6;
label "done" = node=7;
"""


@pytest.fixture
def die(tmp_path):
    path = tmp_path / "die.pm"
    path.write_text(DIE)
    return oasis.build_model(oasis.parse_prism_program(str(path)))


def test_die_builds_as_storm_builds_it(die):
    # Storm's ExplicitPrismModelBuilderTest, Dtmc (die.pm): 13 states, 20 transitions.
    assert (die.nr_states, die.nr_transitions, die.model_type) == (13, 20, "dtmc")
    assert die.initial_states == [0]
    assert die.transition_matrix.shape == (13, 13)
    assert die.transition_matrix.sum() == pytest.approx(13.0)
    assert all(p == Fraction(1, 2) for p in die.exact_probabilities()[:12])


def test_die_bisimulation_all_labels_and_one(die):
    # Storm's DeterministicModelBisimulationDecompositionTest, Die: 13 states with every label,
    # 5 states (8 transitions) respecting "one" only.
    everything = oasis.bisimulate(die)
    assert everything.nr_blocks == 13
    one = oasis.bisimulate(die, respect_labels=["one"])
    assert one.nr_blocks == 5
    assert (one.quotient.nr_states, one.quotient.nr_transitions) == (5, 8)
    assert one.quotient.labels == ["one"]
    assert one.block_of.shape == (13,) and int(one.block_of.max()) == 4
    assert oasis.verify_partition(die, one.block_of, respect_labels=["one"])
    # Storm's symbolic test, Die, labels one, two, three, done: 11 states.
    assert oasis.bisimulate(die, respect_labels=["one", "two", "three", "done"]).nr_blocks == 11


def test_die_property_on_model_and_quotient(die):
    # Storm's DtmcPrctlModelCheckerTest, Die: P=? [F "one"] = 1/6, exactly.
    assert oasis.check(die, 'P=? [F "one"]') == Fraction(1, 6)
    quotient = oasis.bisimulate(die, respect_labels=["one"]).quotient
    assert oasis.check(quotient, 'P=? [F "one"]') == Fraction(1, 6)
    sound = oasis.check(die, 'P=? [F "one"]', exact=False, precision=1e-9)
    assert Fraction(1, 6) in sound and sound.width <= 1e-9


def test_crowds_as_stormpy_test_bisimulation(tmp_path):
    # stormpy's bisimulation test (test_bisimulation; its address is in published.json):
    # crowds5_5, 7403 states and 13041 transitions; the quotient for P=? [F "observe0Greater1"]
    # has 64 states (Storm's sparse bisimulation for the formula, which respects the states
    # where it holds surely), and its symbolic bisimulation 65 (the label itself).
    program = oasis.parse_prism_program(str(PRISM_DATA / "crowds5_stop.pm"),
                                        constants={"TotalRuns": 5})
    model = oasis.build_model(program)
    assert (model.nr_states, model.nr_transitions) == (7403, 13041)
    assert oasis.bisimulate(model, respect_labels=["observe0Greater1_surely"]).nr_blocks == 64
    symbolic = oasis.bisimulate(model, respect_labels=["observe0Greater1"])
    assert symbolic.nr_blocks == 65
    # The property has one value on the model and on its quotient, as stormpy asserts.
    prop = 'P=? [F "observe0Greater1"]'
    assert oasis.check(model, prop) == oasis.check(symbolic.quotient, prop)


def published_small():
    with open(PRISM_DATA / "published.json") as source:
        models = json.load(source)["models"]
    return [m for m in models if m["states"] <= 10000]


def constants_of(entry):
    result = {}
    for item in filter(None, entry["constants"].split(",")):
        name, value = item.split("=")
        result[name] = int(value)
    return result


@pytest.mark.parametrize("entry", published_small(),
                         ids=lambda e: e["file"] + ":" + e["constants"])
def test_published_figures(entry):
    program = oasis.parse_prism_program(str(PRISM_DATA / entry["file"]),
                                        constants=constants_of(entry))
    assert program.model_type == entry["type"]
    model = oasis.build_model(program, rewards="all")
    assert model.nr_states == entry["states"]
    if "transitions" in entry:
        assert model.nr_transitions == entry["transitions"]
    if "choices" in entry:
        assert model.nr_choices == entry["choices"]
    for quotient in entry.get("quotients", []):
        labels = quotient["respect_labels"]
        respect = labels if labels in ("all", "none") else labels.split(",")
        for context in model.contexts:
            result = oasis.bisimulate(model, respect_labels=respect, context=context,
                                      choices=quotient["semantics"])
            assert result.nr_blocks == quotient["blocks"], (labels, context)
    for prop in entry.get("properties", []):
        if prop["form"] != "fraction":
            continue
        assert oasis.check(model, prop["property"]) == Fraction(prop["published"]), prop
