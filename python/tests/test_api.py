"""The module's surface: what import gives, the model's arrays and matrices, the catalog and
the filter."""

from fractions import Fraction

import numpy
import pytest
import scipy.sparse

import oasis
from conftest import PRISM_DATA, SOURCE_DIR


def test_import():
    assert oasis.__version__.count(".") == 2
    for name in oasis.__all__:
        assert hasattr(oasis, name), name
    assert oasis.check.__doc__ and oasis.Model.__doc__


def test_model_arrays_are_read_only_views_and_exact():
    model = oasis.load_model(str(PRISM_DATA / "two_dice.nm"))
    values = model.state_valuations
    assert values.shape == (model.nr_states, len(model.variables))
    assert not values.flags.writeable and values.base is not None  # a view, not a copy
    with pytest.raises(ValueError):
        values[0, 0] = 1
    matrix = model.transition_matrix
    assert isinstance(matrix, scipy.sparse.csr_matrix)
    assert matrix.shape == (model.nr_states * model.nr_actions, model.nr_states)
    assert matrix.nnz == model.nr_transitions
    exact = model.exact_probabilities()
    assert len(exact) == matrix.nnz
    assert numpy.allclose(matrix.data, [float(p) for p in exact])
    # Every enabled choice is a distribution, exactly.
    for row in range(matrix.shape[0]):
        begin, end = matrix.indptr[row], matrix.indptr[row + 1]
        if begin != end:
            assert sum(exact[begin:end]) == 1
    state, action = 0, 0
    target = matrix.indices[matrix.indptr[0]]
    assert model.probability(state, action, int(target)) == exact[matrix.indptr[0]]


def test_labels_rewards_and_schedulers():
    program = oasis.parse_prism_program(str(PRISM_DATA / "consensus2.nm"), constants={"K": 2})
    assert program.model_type == "mdp" and program.reward_models
    model = oasis.build_model(program, rewards="all")
    assert model.contexts == program.reward_models
    rewards = model.state_rewards(0)
    assert rewards.shape == (model.nr_states,)
    initial = model.initial_states[0]
    assert set(model.labels_of_state(initial)) <= set(model.labels)
    value, scheduler = oasis.check(model, 'Pmin=? [F "finished"]', scheduler=True)
    assert value == 1
    assert scheduler.memoryless.shape == (model.nr_states,)
    assert scheduler.action_name(initial) in model.actions + [None]


def test_quotient_is_a_model():
    model = oasis.load_model(str(PRISM_DATA / "knuth_die.pm"))
    result = oasis.bisimulate(model, respect_labels=["one", "done"])
    quotient = result.quotient
    assert quotient.nr_states == result.nr_blocks
    assert quotient.model_type == "dtmc"
    assert oasis.check(quotient, 'P=? [F "one"]') == Fraction(1, 6)
    assert sorted(quotient.states_with_label("one")) == sorted(
        {int(result.block_of[s]) for s in model.states_with_label("one")})


def test_catalog_and_filter(tmp_path):
    catalog = oasis.compile(str(SOURCE_DIR / "specs" / "discrete_tracking.oasis"),
                            str(tmp_path / "out"))
    assert catalog.contexts == ["object_at_s3", "object_at_s1"]
    assert numpy.allclose(catalog.switching.sum(axis=1), 1.0)
    first = catalog.abstraction(0)
    assert list(first["block_of"]) == [0, 0, 1]  # the paper's {s1, s2}, {s3}
    for mode in ("paper", "joint", "hedged"):
        f = oasis.Filter(catalog, mode=mode)
        f.start(0)
        decision, belief = f.step(2, 1.0)  # at s3 the reward is 1: the object is at s3
        assert decision in range(catalog.nr_actions)
        assert belief is f.belief and not belief.flags.writeable
        assert belief.sum() == pytest.approx(1.0)
        assert f.ml_abstraction == 0 and belief[0] > belief[1]
        if mode == "paper":  # Algorithm 1 takes the reading as true
            before = belief.copy()
            f.step(0, 1.0)  # s1 rewarded: the other context
            assert not numpy.array_equal(before, belief)  # the same view, updated in place
            assert f.ml_abstraction == 1
    assert oasis.Filter(catalog, mode="hedged").robust_weight is not None
