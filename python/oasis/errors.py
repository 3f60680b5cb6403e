"""The exceptions of the oasis module. Every failure of a call is one of these (or a plain
ValueError/TypeError/IndexError for an argument of the wrong value or type), never a crash."""

from typing import List, NamedTuple, Sequence


class Diagnostic(NamedTuple):
    """One diagnostic of the compiler: where (line and column are 0 for an error of a whole
    file, file is '' for one of no file) and what."""

    file: str
    line: int
    column: int
    severity: str
    message: str


class Error(Exception):
    """The base of every error the module raises."""

    def __init__(self, message: str, diagnostics: Sequence[Diagnostic] = ()) -> None:
        super().__init__(message)
        #: Every diagnostic reported, located as oasisc prints them.
        self.diagnostics: List[Diagnostic] = list(diagnostics)


class SpecError(Error):
    """A spec, PRISM program or model file that does not read or check. str(error) is the text
    oasisc would print (file:line:col: error: message, the source line and a caret)."""


class PropertyError(SpecError):
    """A property that does not parse or cannot be answered on the model (located in it)."""


class ExactLimitError(PropertyError):
    """The exact solve was refused (too many states in one strongly connected part, or numbers
    too long): ask again with exact=False for a sound interval."""


class CatalogError(Error):
    """A catalog file the runtime refuses (damaged, of another format, compiled from another
    spec)."""


class CompileError(Error):
    """A compile that could not finish (an output directory that is not ours, a model that
    cannot be a catalog). The output directory is left as it was."""


class FilterError(Error, ValueError):
    """A filter that cannot run on its catalog, or an observation or action out of range."""
