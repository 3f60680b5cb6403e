"""Type stubs of the extension module oasis._oasis (re-exported by oasis)."""

from fractions import Fraction
from typing import Dict, List, Literal, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy
import numpy.typing
import scipy.sparse

from .results import Interval, Scheduler

__version__: str

Context = Union[int, str, None]
Labels = Union[bool, str, Sequence[str]]
Value = Union[Fraction, Interval, bool, float]

class PrismProgram:
    path: str
    name: str
    model_type: Literal["dtmc", "mdp"]
    constants: str
    labels: List[str]
    reward_models: List[str]
    variables: List[str]

class Model:
    name: str
    model_type: Literal["dtmc", "mdp"]
    nr_states: int
    nr_actions: int
    actions: List[str]
    nr_choices: int
    nr_transitions: int
    initial_states: List[int]
    contexts: List[str]
    labels: List[str]
    variables: List[str]
    state_valuations: Optional[numpy.ndarray]
    transition_matrix: scipy.sparse.csr_matrix
    def transitions(self, context: Context = None) -> scipy.sparse.csr_matrix: ...
    def states_with_label(self, label: str) -> List[int]: ...
    def labels_of_state(self, state: int) -> List[str]: ...
    def state_name(self, state: int) -> str: ...
    def exact_probabilities(self, context: Context = None) -> List[Fraction]: ...
    def probability(self, state: int, action: Union[int, str], target: int,
                    context: Context = None) -> Fraction: ...
    def state_rewards(self, context: Context = None) -> numpy.ndarray: ...
    def state_action_rewards(self, context: Context = None) -> Optional[numpy.ndarray]: ...
    def reward(self, state: int, action: Union[int, str], context: Context = None) -> Fraction: ...

class Bisimulation:
    quotient: Optional[Model]
    block_of: numpy.ndarray
    nr_blocks: int
    context: str

class PartitionCheck:
    bisimulation: bool
    coarsest: bool
    message: str
    def __bool__(self) -> bool: ...

class Catalog:
    path: str
    name: str
    spec_hash: int
    compiler_version: str
    nr_states: int
    nr_actions: int
    actions: List[str]
    state_names: List[str]
    nr_abstractions: int
    contexts: List[str]
    is_continuous: bool
    has_robust_section: bool
    switching: numpy.ndarray
    prior: numpy.ndarray
    @staticmethod
    def load(path: str, spec_hash: Optional[int] = None) -> "Catalog": ...
    def abstraction(self, index: int) -> Dict[str, object]: ...

Observation = Union[int, Sequence[float], numpy.ndarray]

class Filter:
    def __init__(self, catalog: Catalog,
                 mode: Literal["paper", "joint", "noise_aware", "hedged"] = "paper",
                 guard: bool = False, detection_epsilon: float = 0.0,
                 reward_tolerance: float = 1e-9, tie: Literal["keep", "random"] = "keep",
                 seed: int = 0) -> None: ...
    def start(self, observation: Observation) -> None: ...
    def step(self, observation: Observation, reward: float,
             action: Optional[int] = None) -> Tuple[Optional[int], numpy.ndarray]: ...
    decision: Optional[int]
    belief: numpy.ndarray
    ml_abstraction: int
    robust_weight: Optional[float]
    status: str
    mode: str

def parse_prism_program(path: str,
                        constants: Optional[Mapping[str, Union[bool, int, float, Fraction]]] = None
                        ) -> PrismProgram: ...
def build_model(program: PrismProgram, rewards: Union[None, str, Sequence[str]] = None,
                max_states: int = ...) -> Model: ...
def load_model(path: str,
               constants: Optional[Mapping[str, Union[bool, int, float, Fraction]]] = None,
               rewards: Union[None, str, Sequence[str]] = None, max_states: int = ...) -> Model: ...
def bisimulate(model: Model, respect_labels: Labels = True,
               choices: Literal["labelled", "unlabelled"] = "labelled", context: Context = None,
               epsilon: Optional[float] = None, jobs: int = 0) -> Bisimulation: ...
def verify_partition(model: Model, blocks: numpy.typing.ArrayLike, respect_labels: Labels = True,
                     choices: Literal["labelled", "unlabelled"] = "labelled",
                     context: Context = None) -> PartitionCheck: ...
@overload
def check(model: Model, property: str, exact: Union[bool, Literal["auto"]] = True,
          precision: float = 1e-6, scheduler: Literal[False] = False, bisimulation: bool = False,
          max_exact_states: int = 1000000) -> Value: ...
@overload
def check(model: Model, property: str, exact: Union[bool, Literal["auto"]] = True,
          precision: float = 1e-6, *, scheduler: Literal[True], bisimulation: bool = False,
          max_exact_states: int = 1000000) -> Tuple[Value, Optional[Scheduler]]: ...
def compile(spec: str, out_dir: Optional[str] = None, epsilon: Optional[float] = None,
            jobs: int = 0, formats: Optional[Sequence[str]] = None,
            robust: Optional[float] = None) -> Optional[Catalog]: ...
def spec_hash(text: bytes) -> int: ...
