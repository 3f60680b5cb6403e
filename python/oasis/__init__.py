"""oasis: the abstraction compiler and runtime for Online Attention Switching, from Python.

Shaped like stormpy where the concepts match (docs/python.md has the table):

    import oasis
    program = oasis.parse_prism_program("die.pm")
    model = oasis.build_model(program)
    result = oasis.bisimulate(model, respect_labels=["one"])
    oasis.check(result.quotient, 'P=? [F "one"]')        # Fraction(1, 6)

Built for Debian's /usr/bin/python3 with Debian's pybind11, numpy and scipy.
"""

from ._oasis import (
    Bisimulation,
    Catalog,
    Filter,
    Model,
    PartitionCheck,
    PrismProgram,
    __version__,
    bisimulate,
    build_model,
    check,
    compile,
    load_model,
    parse_prism_program,
    spec_hash,
    verify_partition,
)
from .errors import (
    CatalogError,
    CompileError,
    Diagnostic,
    Error,
    ExactLimitError,
    FilterError,
    PropertyError,
    SpecError,
)
from .results import Interval, Scheduler


def _transition_matrix(self: Model, context=None):
    """A context's transition matrix as a scipy.sparse.csr_matrix of floats: one row per
    choice (state * nr_actions + action; a Markov chain's is square), one column per state.
    model.exact_probabilities(context) gives its entries exactly, in the order of .data."""
    import scipy.sparse  # only when asked: import oasis needs numpy alone

    indptr, indices, data, shape = self._csr(context)
    return scipy.sparse.csr_matrix((data, indices, indptr), shape=shape)


Model.transitions = _transition_matrix
Model.transition_matrix = property(_transition_matrix, doc=_transition_matrix.__doc__)

__all__ = [
    "Bisimulation", "Catalog", "CatalogError", "CompileError", "Diagnostic", "Error",
    "ExactLimitError", "Filter", "FilterError", "Interval", "Model", "PartitionCheck",
    "PrismProgram", "PropertyError", "Scheduler", "SpecError", "__version__", "bisimulate",
    "build_model", "check", "compile", "load_model", "parse_prism_program", "spec_hash",
    "verify_partition",
]
