"""The libFuzzer corpus (tests/fuzz/corpus/) replayed through the Python entry points: each
input gives a result or an exception of the package (or ValueError), and never crashes the
interpreter (a crash would end this test's process, which ctest reports as a failure)."""

import pytest

import oasis
from conftest import SOURCE_DIR

CORPUS = SOURCE_DIR / "tests" / "fuzz" / "corpus"
# Which loader reads each target's inputs, by the extension the CLI would see.
EXTENSION = {"aut_reader": ".aut", "drn_reader": ".drn", "umb_reader": ".umb", "spec": ".oasis"}
EXPECTED = (oasis.Error, ValueError)

PROPERTY_MODEL = """mdp
const int N = 4;
formula far = x >= N - 1;
module m
  x : [0..4] init 0;
  b : bool init false;
  [stay] x < 4 -> (x'=x);
  [go] x < 4 -> 1/3 : (x'=x+1) + 2/3 : (x'=0) & (b'=!b);
  [jump] x = 0 -> 1/2 : (x'=2) + 1/2 : (x'=4);
  [] x = 4 -> true;
endmodule
label "goal" = x = 4;
label "odd" = b;
rewards "time" true : 1; endrewards
rewards "cost" [go] true : 2; [jump] x = 0 : 5; endrewards
"""


def inputs(target):
    folder = CORPUS / target
    return sorted(folder.iterdir()) if folder.is_dir() else []


def exercise(model):
    """What a user reads of a model that loaded."""
    assert model.nr_states >= 1
    model.transition_matrix
    model.exact_probabilities()
    for context in model.contexts:
        oasis.bisimulate(model, context=context)


@pytest.mark.parametrize("target", sorted(EXTENSION))
def test_model_readers(target, tmp_path):
    seen = inputs(target)
    assert seen, "the corpus of " + target + " is empty"
    for number, source in enumerate(seen):
        path = tmp_path / f"input{number}{EXTENSION[target]}"
        path.write_bytes(source.read_bytes())
        try:
            exercise(oasis.load_model(str(path)))
        except EXPECTED:
            pass


def test_prism_explicit_files(tmp_path):
    # One input holds .tra, .sta, .lab, .srew and .trew separated by NUL bytes.
    for number, source in enumerate(inputs("prism_reader")):
        parts = source.read_bytes().split(b"\0")
        for part, extension in zip(parts, (".tra", ".sta", ".lab", ".srew", ".trew")):
            if part:
                (tmp_path / f"m{number}{extension}").write_bytes(part)
        try:
            exercise(oasis.load_model(str(tmp_path / f"m{number}.tra")))
        except EXPECTED:
            pass


def test_properties(tmp_path):
    program = tmp_path / "model.nm"
    program.write_text(PROPERTY_MODEL)
    model = oasis.build_model(oasis.parse_prism_program(str(program)), rewards="all")
    answered = 0
    for source in inputs("property"):
        text = source.read_bytes().decode("utf-8", errors="replace")
        for prop in [text] + text.split(";"):
            for exact in (True, False):
                try:
                    oasis.check(model, prop, exact=exact, scheduler=True)
                    answered += 1
                except EXPECTED:
                    pass
    assert answered > 0  # the seeds hold good properties too


def test_catalogs(tmp_path):
    seen = inputs("catalog_loader")
    assert seen
    for source in seen:
        data = source.read_bytes()
        # The seed, and cut or flipped copies of it.
        for variant in (data, data[: len(data) // 2], bytes(b ^ 0x55 for b in data[:64]) + data[64:]):
            path = tmp_path / "catalog.bin"
            path.write_bytes(variant)
            try:
                catalog = oasis.Catalog.load(str(path))
            except oasis.CatalogError:
                continue
            f = oasis.Filter(catalog)
            start = [0.0] * 8 if catalog.is_continuous else 0
            f.start(start)
            decision, belief = f.step(start, 0.0)
            assert abs(belief.sum() - 1.0) < 1e-9
