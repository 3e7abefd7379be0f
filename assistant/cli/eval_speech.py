"""``assistant eval speech``: options and printed tables of :mod:`assistant.eval.speech`."""

from __future__ import annotations

import argparse

from assistant.cli.common import emit_json, percent, print_table, progress_for, whole_number

#: what ``--quick`` stands for (see assistant.cli.eval): one clean sentence of each kind
QUICK = ("--per-kind", "1", "--clean-only")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--asr", choices=("pocketsphinx", "vosk"), default="pocketsphinx",
                        help="recogniser to measure (default pocketsphinx)")
    parser.add_argument("--asr-model", metavar="DIR", help="the vosk model folder (with --asr vosk)")
    parser.add_argument("--per-kind", type=whole_number(1, 10**6), metavar="N",
                        help="only the first N sentences of each kind (4: 36 utterances with the noise levels)")
    parser.add_argument("--all-voices", action="store_true",
                        help="every sentence in every voice and rate (8x longer); default: in rotation")
    parser.add_argument("--kind", action="append", choices=("command", "where", "chat"),
                        help="only these kinds of sentence (repeatable)")
    parser.add_argument("--clean-only", action="store_true", help="no noisy copies")
    parser.add_argument("--no-open", action="store_true", help="pocketsphinx: no general-English fallback")
    parser.add_argument("--no-home", action="store_true",
                        help="do not tell the recogniser each utterance's home (its rooms win near n-best ties)")
    parser.add_argument("--no-vtln", action="store_true",
                        help="pocketsphinx: no vocal tract length normalisation (no warp to the voice's pitch)")
    parser.add_argument("--enrol", type=whole_number(10, 1000), metavar="N",
                        help="pocketsphinx: enrol each voice first with N sentences of the enrolment script "
                             "(assistant enrol), then decode it with its adapted model (needs SphinxTrain)")
    parser.add_argument("--rows", action="store_true", help="print every utterance")
    parser.add_argument("--shard", metavar="I/N", default="1/1",
                        help="only every N-th utterance from the I-th: run N processes in parallel, each "
                             "with --json to a file, then join them with --merge")
    parser.add_argument("--merge", nargs="+", metavar="REPORT.json",
                        help="print one report joined from the --json reports of the shards of one run")


def run(args: argparse.Namespace) -> int:
    from assistant.eval.speech import evaluate_speech

    if args.asr_model and args.asr != "vosk":
        from assistant.errors import AssistantError

        raise AssistantError("--asr-model is the folder of a vosk model: add --asr vosk")
    if args.merge:
        report = _merged(args.merge)
    else:
        report = evaluate_speech(args.asr, args.asr_model, per_kind=args.per_kind, all_voices=args.all_voices,
                                 kinds=args.kind, snrs_db=(None,) if args.clean_only else None,
                                 open_fallback=not args.no_open, shard=_shard(args.shard),
                                 home=not args.no_home, vtln=not args.no_vtln, enrol=args.enrol,
                                 progress=progress_for(args))
    if args.json:
        emit_json(report)
        return 0
    if args.rows:
        print_table([[r["id"], r["errors"], r["confidence"], r["plan_equal"], r["reference"], r["transcript"]]
                     for r in report["rows"]], ["utterance", "err", "conf", "plan=", "said", "heard"])
        print()
    header = ["", "utterances", "WER", "plan = text", "intent = text", "would confirm", "median decode s", "RTF"]

    def line(name, s):
        return [name, s["utterances"], percent(s["wer"]), percent(s["plan_equal"]), percent(s["intent_equal"]),
                percent(s["would_confirm"]), s["median_decode_s"], s["real_time_factor"]]

    for factor, groups in report["groups"].items():
        print_table([line(value, s) for value, s in groups.items()], [factor, *header[1:]])
        print()
    print_table([line(k, s) for k, s in report["noise_and_kind"].items()], ["noise / kind", *header[1:]])
    s = report["summary"]
    print(f"\n{report['engine']}: {s['utterances']} utterances, WER {percent(s['wer'])}, plan = typed plan "
          f"{percent(s['plan_equal'])} of {s['planned']}, RTF {s['real_time_factor']}, open model used "
          f"{s['open_used']}x; {report['wall_seconds']} s")
    return 0


def _shard(text: str) -> tuple[int, int]:
    from assistant.errors import AssistantError

    try:
        i, n = (int(p) for p in text.split("/"))
    except ValueError:
        raise AssistantError(f"--shard {text}: expected I/N, e.g. 2/4") from None
    if not 1 <= i <= n:
        raise AssistantError(f"--shard {text}: I must be between 1 and N")
    return i, n


def _merged(paths) -> dict:
    import json

    from assistant.errors import AssistantError
    from assistant.eval.speech import merge_reports

    reports = []
    for path in paths:
        try:
            with open(path, encoding="utf-8") as handle:
                reports.append(json.loads(handle.read()))
        except (OSError, ValueError) as error:
            raise AssistantError(f"--merge {path}: not a report of assistant eval speech --json ({error})") from None
        if "rows" not in reports[-1]:
            raise AssistantError(f"--merge {path}: has no rows; write it with assistant eval speech --json")
    return merge_reports(reports)
