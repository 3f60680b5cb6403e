"""Values that oasis.check returns besides Fractions."""

from typing import List, NamedTuple, Optional

import numpy


class Interval(NamedTuple):
    """A sound answer: the true value lies in [lower, upper] (outward-rounded doubles)."""

    lower: float
    upper: float

    def __contains__(self, value: object) -> bool:
        return self.lower <= value <= self.upper  # type: ignore[operator]

    @property
    def width(self) -> float:
        return self.upper - self.lower


class Scheduler(NamedTuple):
    """An optimal scheduler. memoryless[s] is the action index taken in state s (-1 where any
    action will do); a step-bounded property's is by_step[i][s] at step i instead."""

    memoryless: Optional[numpy.ndarray]
    by_step: List[numpy.ndarray]
    actions: List[str]

    def action_name(self, state: int) -> Optional[str]:
        """The name of the action taken in `state` by a memoryless scheduler (None: any)."""
        if self.memoryless is None:
            raise ValueError("a step-bounded property's scheduler depends on the step: use by_step")
        index = int(self.memoryless[state])
        return None if index < 0 else self.actions[index]
