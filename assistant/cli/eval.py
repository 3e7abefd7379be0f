"""``assistant eval NAME``: the dissertation's experiments, reproduced on this product.

Each experiment lives in ``assistant/eval/NAME.py``: functions that take plain arguments and
return the report (rows and summary figures), never printing. Its command-line side lives in
``assistant/cli/eval_NAME.py``: ``add_arguments(parser)`` registers the options, ``run(args)
-> int`` calls the experiment and prints its tables, or its report as one JSON object with
``--json``, and ``QUICK`` lists the options ``--quick`` stands for. This module only knows their
names; the chosen evaluation's module is imported when it runs, so neither ``assistant --help``
nor one evaluation pays for importing the others.

``--quick`` (every evaluation): a small sample of the evaluation — a few cases of each part it
runs, under a minute with the models trained — to see that it works on this machine (the
README's examples use it; ``tests/test_readme.py`` runs them). Its figures are not the reported
ones: the README's table gives the full commands. The options it stands for come before the
ones given, so a given option wins (one that may be repeated, such as ``--rdt``, adds to them).
"""

from __future__ import annotations

import argparse
import importlib

from assistant.errors import AssistantError

#: evaluation name → module that implements it
EVALUATIONS = {
    "tagging": "assistant.cli.eval_tagging",
    "grounding": "assistant.cli.eval_grounding",
    "perception": "assistant.cli.eval_perception",
    "policy": "assistant.cli.eval_policy",
    "fetch": "assistant.cli.eval_fetch",
    "generation": "assistant.cli.eval_generation",
    "dialogue": "assistant.cli.eval_dialogue",
    "speech": "assistant.cli.eval_speech",
}


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "eval", help="reproduce the dissertation's experiments",
        description="Reproduce the dissertation's experiments on this product. "
                    "`assistant eval NAME --help` lists the options of one evaluation.",
    )
    parser.add_argument("evaluation", choices=sorted(EVALUATIONS), metavar="EVALUATION",
                        help=", ".join(sorted(EVALUATIONS)))
    parser.add_argument("options", nargs=argparse.REMAINDER, help="options of that evaluation")
    parser.set_defaults(handler=run)


def build_evaluation_parser(name: str) -> tuple[argparse.ArgumentParser, object]:
    """The parser of one evaluation and its module (imported now)."""
    module_name = EVALUATIONS[name]
    try:
        module = importlib.import_module(module_name)
    except ModuleNotFoundError as error:
        if not module_name.startswith(error.name or "\0"):
            raise
        raise AssistantError(f"the {name} evaluation is not built yet (see the open issues)") from None
    parser = argparse.ArgumentParser(prog=f"assistant eval {name}")
    parser.add_argument("--json", action="store_true", help="print one JSON object on stdout")
    parser.add_argument("--quick", action="store_true",
                        help=f"a small sample to check that the evaluation runs (stands for: {' '.join(module.QUICK)}); "
                             "its figures are not the reported ones")
    module.add_arguments(parser)
    return parser, module


def run(args: argparse.Namespace) -> int:
    parser, module = build_evaluation_parser(args.evaluation)
    options = parser.parse_args(args.options)
    if options.quick:
        options = parser.parse_args([*module.QUICK, *args.options])
    options.command = "eval"
    status = module.run(options)
    if options.quick and not options.json:
        print(f"(--quick: a small sample, not the reported figures; for those: assistant eval {args.evaluation} "
              "without --quick)")
    return status
