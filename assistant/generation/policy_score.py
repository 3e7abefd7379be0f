"""``P_Γ(y)`` from the learned policy models (dissertation 6.2 II.D).

The dissertation's content selection reads the probability of an RDT node from the same
policy models the robot follows commands with (chapter 5): a model learned from
demonstrations of "the table in front of the couch" says, through its weight vectors over the
spatial relation variables, how the reference and the target stood whenever a person showed
that relation. :class:`PolicyRelationScore` scores a (reference, target) pair with the kept
reference↔target SRVs of the RDT's model (eq. 5-14 per SRV, their product as in eq. 5-15):
the robot's own SRVs are left out — they say where to *stand*, not where the table is. The
score is read relative to the demonstrations themselves: divided by the model's median score
of its own demonstrations' final frames (0.51–0.65 for the table RDTs of our training home) and
capped at 1, so "as in the demonstrations" is 1. An RDT with no model of its own takes the
library's nearest one (``PolicyLibrary.model``: "chair-front" takes "couch-front"); one with
none at all gets None, and content selection then keeps the spatial relations' probability
alone.
"""

from __future__ import annotations

import numpy as np

from assistant.errors import UnknownNameError

__all__ = ["RELATION_SRVS", "PolicyRelationScore"]

#: the SRVs of a policy model that relate the reference and the target (not the robot)
RELATION_SRVS = ("dir:ref->tar", "dir:tar->ref", "dist:ref->tar", "dist:tar->ref")


class PolicyRelationScore:
    """``score(rdt, srvs) -> float | None``: the policy model's reference↔target score of an
    RDT (in [0, 1]) for the SRVs of one pair (``{name: SRV or None}`` with the names of
    :data:`RELATION_SRVS`). ``library``: a :class:`~assistant.policy.library.PolicyLibrary`
    (default: the repository's demonstrations, trained once and cached, loaded on first use)."""

    def __init__(self, library=None):
        self._library = library
        self.used: dict[str, str] = {}  # RDT → the model that scored it
        self._typical: dict[str, float | None] = {}  # model name → median demonstration score
        self._demos: dict[str, list] | None = None

    @property
    def library(self):
        if self._library is None:
            from assistant.policy.library import PolicyLibrary

            self._library = PolicyLibrary()
        return self._library

    def score(self, rdt: str, srvs: dict) -> float | None:
        try:
            choice = self.library.model(rdt)
        except UnknownNameError:
            return None
        q = _relation_score(choice.model, srvs)
        typical = self._typical_score(choice.used, choice.model)
        if q is None or not typical:
            return None
        self.used[rdt] = choice.used
        return float(min(1.0, q / typical))

    def _typical_score(self, name: str, model) -> float | None:
        """The median reference↔target score of the model's own demonstrations (last frames)."""
        if name not in self._typical:
            if self._demos is None:
                from assistant.policy.demonstration import load_demonstrations

                self._demos = {}
                for demo in load_demonstrations(self.library.directory):
                    self._demos.setdefault(demo.rdt, []).append(demo)
            values = []
            for demo in self._demos.get(name, []):
                _, last = model.demonstration_features(demo)
                q = _relation_score(model, {srv.name: srv for srv in last})
                if q is not None:
                    values.append(q)
            self._typical[name] = float(np.median(values)) if values else None
        return self._typical[name]


def _relation_score(model, srvs: dict) -> float | None:
    """Product of ``model``'s kept reference↔target SRV scores (eq. 5-14) over ``srvs``."""
    parts = [float(np.asarray(weights) @ np.asarray(srvs[name].values, dtype=float))
             for name, weights in model.weights_.items()
             if name in RELATION_SRVS and srvs.get(name) is not None]
    return float(np.clip(np.prod(parts), 0.0, 1.0)) if parts else None
