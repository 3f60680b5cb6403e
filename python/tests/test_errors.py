"""Every way a call can fail leaves as an exception of the package, located where the compiler
locates it; none crashes."""

import os

import numpy
import pytest

import oasis
from conftest import PRISM_DATA, SOURCE_DIR

DISCRETE = str(SOURCE_DIR / "specs" / "discrete_tracking.oasis")


def test_hierarchy():
    for cls in (oasis.SpecError, oasis.CatalogError, oasis.CompileError, oasis.FilterError):
        assert issubclass(cls, oasis.Error)
    assert issubclass(oasis.PropertyError, oasis.SpecError)
    assert issubclass(oasis.ExactLimitError, oasis.PropertyError)
    assert issubclass(oasis.FilterError, ValueError)


def test_spec_error_is_located(tmp_path):
    bad = tmp_path / "bad.pm"
    bad.write_text("dtmc\nmodule m\n  x : [0..1] init 0;\n  [] x=0 -> 0.5 : (x'=1);\nendmodule\n")
    with pytest.raises(oasis.SpecError) as raised:
        oasis.build_model(oasis.parse_prism_program(str(bad)))
    first = raised.value.diagnostics[0]
    assert first.file == str(bad) and first.line == 4 and first.column > 0
    assert first.severity == "error" and "0.5" in first.message
    assert str(bad) + ":4:" in str(raised.value)  # the text oasisc prints


def test_header_beyond_the_memory_budget(tmp_path):
    # As oasisc's default --memory-budget: refused in the header, before the body is read.
    huge = tmp_path / "huge.aut"
    huge.write_text("des (0, 1000000000000000, 1000000)\n(0, \"a\", 0)\n")
    with pytest.raises(oasis.SpecError) as raised:
        oasis.load_model(str(huge))
    first = raised.value.diagnostics[0]
    assert first.line == 1 and "memory budget" in first.message


def test_several_errors_in_one_run(tmp_path):
    bad = tmp_path / "two.pm"
    bad.write_text("dtmc\nmodule m\n  x : [0..1] init y;\n  [] x=0 -> (z'=1);\nendmodule\n")
    with pytest.raises(oasis.SpecError) as raised:
        oasis.parse_prism_program(str(bad))
    assert len([d for d in raised.value.diagnostics if d.severity == "error"]) >= 2


def test_missing_file_and_bad_spec(tmp_path):
    with pytest.raises(oasis.SpecError) as raised:
        oasis.parse_prism_program(str(tmp_path / "absent.pm"))
    assert raised.value.diagnostics[0].line == 0  # a file's error, at no place in it
    spec = tmp_path / "bad.oasis"
    spec.write_text("mdp m {\n  states s1 s2;\n}\n")
    with pytest.raises(oasis.SpecError) as raised:
        oasis.load_model(str(spec))
    assert raised.value.diagnostics[0].file == str(spec)


def test_undefined_constant():
    with pytest.raises(oasis.SpecError, match="N"):
        oasis.build_model(oasis.parse_prism_program(str(PRISM_DATA / "brp.pm")))
    with pytest.raises(TypeError):
        oasis.parse_prism_program(str(PRISM_DATA / "brp.pm"), constants={"N": "sixteen"})


def test_property_errors():
    model = oasis.load_model(str(PRISM_DATA / "knuth_die.pm"))
    with pytest.raises(oasis.PropertyError) as raised:
        oasis.check(model, 'P=? [F "nine"]')
    assert (raised.value.diagnostics[0].line, raised.value.diagnostics[0].column) == (1, 8)
    with pytest.raises(oasis.PropertyError):
        oasis.check(model, "P=? [F")
    with pytest.raises(oasis.PropertyError):
        oasis.check(model, 'Pmax=? [F "one"]')  # a Markov chain has no choices
    with pytest.raises(oasis.ExactLimitError):
        oasis.check(model, 'P=? [F "one"]', max_exact_states=1)
    with pytest.raises(ValueError):
        oasis.check(model, 'P=? [F "one"]', exact="maybe")


def test_argument_errors():
    model = oasis.load_model(str(PRISM_DATA / "knuth_die.pm"))
    with pytest.raises(ValueError, match="no label"):
        oasis.bisimulate(model, respect_labels=["seven"])
    with pytest.raises(ValueError):
        oasis.bisimulate(model, choices="sometimes")
    with pytest.raises(ValueError):
        oasis.bisimulate(model, context="nothing")
    with pytest.raises(IndexError):
        model.state_name(13)
    with pytest.raises(KeyError):
        model.states_with_label("seven")


def test_verify_partition_reports_violations():
    model = oasis.load_model(str(PRISM_DATA / "knuth_die.pm"))
    one = ["one"]
    check = oasis.verify_partition(model, numpy.zeros(13, dtype=numpy.int64), respect_labels=one)
    assert not check.bisimulation and "labels differ" in check.message
    fine = oasis.bisimulate(model, respect_labels=one)
    assert oasis.verify_partition(model, numpy.array(fine.block_of), respect_labels=one)
    split = oasis.verify_partition(model, numpy.arange(13), respect_labels=one)
    assert split.bisimulation and not split.coarsest and split.message
    short = oasis.verify_partition(model, numpy.zeros(12, dtype=numpy.int64))
    assert not short.bisimulation and short.message


def test_continuous_spec_has_no_explicit_model():
    with pytest.raises(oasis.Error, match="continuous"):
        oasis.load_model(str(SOURCE_DIR / "specs" / "go1_treat.oasis"))


def test_catalog_errors(tmp_path):
    with pytest.raises(oasis.CatalogError, match="cannot open"):
        oasis.Catalog.load(str(tmp_path / "absent.bin"))
    catalog = oasis.compile(DISCRETE, str(tmp_path / "out"))
    data = bytearray(open(catalog.path, "rb").read())
    data[len(data) // 2] ^= 0xFF
    damaged = tmp_path / "damaged.bin"
    damaged.write_bytes(bytes(data))
    with pytest.raises(oasis.CatalogError):
        oasis.Catalog.load(str(damaged))
    with pytest.raises(oasis.CatalogError, match="another spec"):
        oasis.Catalog.load(catalog.path, spec_hash=catalog.spec_hash ^ 1)
    assert oasis.Catalog.load(catalog.path, spec_hash=catalog.spec_hash).name == catalog.name


def test_compile_errors(tmp_path):
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "notes.txt").write_text("a user's file")
    with pytest.raises(oasis.CompileError):
        oasis.compile(DISCRETE, str(mine))
    assert os.listdir(mine) == ["notes.txt"]  # left as it was
    with pytest.raises(oasis.CompileError, match="svg"):
        oasis.compile(DISCRETE, str(tmp_path / "x"), formats=["svg"])
    with pytest.raises(oasis.SpecError):
        oasis.compile(str(tmp_path / "absent.oasis"), str(tmp_path / "y"))
    with pytest.warns(UserWarning, match="epsilon"):
        oasis.compile(DISCRETE, str(tmp_path / "z"), epsilon=0.1)


def test_filter_errors(tmp_path):
    plain = oasis.compile(str(PRISM_DATA / "knuth_die.pm"), str(tmp_path / "die"))
    assert not plain.has_robust_section
    with pytest.raises(oasis.FilterError, match="observation model"):
        oasis.Filter(plain, mode="hedged")
    catalog = oasis.compile(DISCRETE, str(tmp_path / "out"))
    with pytest.raises(ValueError):
        oasis.Filter(catalog, mode="psychic")
    f = oasis.Filter(catalog)
    with pytest.raises(oasis.FilterError, match="start"):
        f.step(0, 0.0)
    with pytest.raises(oasis.FilterError, match="not a state"):
        f.start(3)
    f.start(0)
    with pytest.raises(oasis.FilterError, match="not a state"):
        f.step(7, 0.0)
    with pytest.raises(oasis.FilterError, match="action"):
        f.step(0, 0.0, action=9)
