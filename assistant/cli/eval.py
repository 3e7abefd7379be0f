"""``assistant eval NAME``: the dissertation's experiments, reproduced on this product.

Each evaluation lives beside the code it measures, in ``assistant/<package>/evaluation.py``,
and exposes ``add_arguments(parser)`` and ``run(args) -> int``. This module only knows their
names, so that ``assistant --help`` stays fast.
"""

from __future__ import annotations

import argparse
import importlib

from assistant.errors import AssistantError

#: evaluation name → module that implements it
EVALUATIONS = {
    "tagging": "assistant.language.evaluation",
    "grounding": "assistant.grounding.evaluation",
    "perception": "assistant.perception.evaluation",
    "policy": "assistant.policy.evaluation",
    "fetch": "assistant.executor.evaluation",
    "generation": "assistant.generation.evaluation",
    "dialogue": "assistant.dialogue.evaluation",
}


def register(subparsers) -> None:
    parser = subparsers.add_parser("eval", help="reproduce the dissertation's experiments")
    evals = parser.add_subparsers(dest="evaluation", metavar="EVALUATION")
    evals.required = True
    for name, module_name in EVALUATIONS.items():
        sub = evals.add_parser(name, help=f"evaluation of {module_name.split('.')[1]}")
        sub.add_argument("--json", action="store_true", help="print one JSON object on stdout")
        try:
            module = importlib.import_module(module_name)
        except ModuleNotFoundError as error:
            if not module_name.startswith(error.name or "\0"):
                raise
            sub.set_defaults(handler=_not_built(name))
            continue
        module.add_arguments(sub)
        sub.set_defaults(handler=module.run)


def _not_built(name: str):
    def handler(args: argparse.Namespace) -> int:
        raise AssistantError(f"the {name} evaluation is not built yet (see the open issues)")

    return handler
