"""``assistant parse TEXT``: words → tags → nested chunks → a grounded plan of RDT nodes."""

from __future__ import annotations

import argparse

from assistant.cli.common import require_text_or_batch, add_json_flag, emit_json, run_batch


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "parse", help="parse a command into chunks and a plan of RDT nodes",
        description="Parse a spoken or typed command: tokens, POS tags, nested chunks, and the "
                    "grounded plan (target room, reference-direction-target nodes, target object).",
    )
    parser.add_argument("text", nargs="*", help="the command (omit with --batch)")
    parser.add_argument("--batch", metavar="FILE",
                        help="one command per line of FILE ('-' for stdin); one JSON object per line out")
    parser.add_argument("--grounder", choices=("scored", "learned", "combined"), default=None,
                        help="grounding model: scored (WLD templates, 4.3), learned (classifiers, 4.4) or "
                             "combined (their product; the default, measured best — docs/grounding.md)")
    parser.add_argument("--corpus", metavar="PATH", action="append",
                        help="train on these corpus files or folders (*.xml descriptions, *.csv "
                             "chunk groundings) instead of the repository's corpus/; repeatable")
    parser.add_argument("--world", metavar="NAME",
                        help="the home the command is given in (name or file): which room 'on your "
                             "right' means there, and whether an unreferenced target is ambiguous")
    add_json_flag(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from assistant.grounding import CommandParser

    require_text_or_batch(args.text, args.batch, "parse")
    world = None
    if args.world:
        from assistant.world import load_world

        world = load_world(args.world)
    parser = CommandParser.load(args.grounder, args.corpus, world=world)
    if args.batch:
        return run_batch(args.batch, lambda line: parser.parse(line).to_dict(), json_requests=False)
    result = parser.parse(" ".join(args.text))
    if args.json:
        emit_json(result.to_dict())
    else:
        _print(result)
    return 0


def _print(result) -> None:
    from assistant.grounding import FLAG_HELP

    data = result.to_dict()
    plan = data["plan"]
    print(" ".join(f"{t}/{p}" for t, p in zip(data["tokens"], data["pos"])) or "(no words)")
    print(data["bracketed"] or "(no chunks)")
    for chunk in data["chunks"]:
        fields = {k: v for k, v in chunk.items() if k not in ("label", "words") and v}
        shown = ", ".join(f"{k}={v}" for k, v in fields.items()) or "-"
        print(f"  {chunk['label']:<6} {' '.join(chunk['words']):<40} {shown}")
    print(f"room: {plan['room'] or '?'}   object: {plan['object'] or '?'}   "
          f"support: {plan['support'] or '-'}   kind: {plan['kind']}")
    for i, node in enumerate(plan["node_details"], start=1):
        extra = f"  (then {', '.join(node['alternatives'][1:])})" if len(node["alternatives"]) > 1 else ""
        print(f"  node {i}: {node['rdt']}{extra}")
    if data["unused"]:
        print("unused words: " + ", ".join(data["unused"]))
    for flag in data["flags"]:
        name = flag.split(":")[0]
        print(f"note: {flag} — {FLAG_HELP.get(name, '')}")
