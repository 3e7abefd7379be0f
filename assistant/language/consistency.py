"""How consistent an annotated corpus is with itself: the ceiling of any chunk labeller on it.

Real annotation (the CSISL real descriptions, dissertation 4.2.4) was made without
cross-annotator agreement: the same words in the same context are often labelled differently.
No labeller can be right on both labellings, so these measures bound what any chunker —
trained on any corpus — can reach per word on such a file:

* :func:`window_ceiling` — for each word, its context is the ``±k`` words *and* their POS
  tags (padded at the ends). Among all words sharing one context, a labeller that decides from
  that context alone gives them all one label, at best the most frequent one. The ceiling is
  ``Σ_context max_label count / words``: the best per-word accuracy of *any* such labeller,
  even one trained on this very file (it is the accuracy of the file's own majority table).
  Reported with the share of words whose context occurs more than once (only those can
  disagree) and the agreement among them. As ``k`` grows, contexts become unique and the
  ceiling tends to 100 % — the figures of interest are the agreement among repeated contexts
  and how they fall with ``k``.
* :func:`ngram_agreement` — for each word n-gram (with POS) that occurs at least twice, the
  share of its occurrences whose n nested labels equal its most frequent labelling.
* :func:`duplicate_agreement` — descriptions whose words are identical: pairwise per-word
  agreement of their nested labels.
* :func:`conventions` — counts of how a corpus annotates the constructions where corpora
  differ (leading motion inside or outside the room phrase, the first turn, hedges, fillers,
  descriptions without an object phrase, several object sentences, …), so a training corpus
  can be compared with a test file construction by construction.
"""

from __future__ import annotations

from collections import Counter, defaultdict
from collections.abc import Sequence

from assistant.language.tree import OUTSIDE, ChunkTree

__all__ = ["window_ceiling", "leave_one_out_context", "ngram_agreement", "duplicate_agreement",
           "conventions", "consistency_report", "construction_of", "errors_by_construction"]

_PAD = ("<s>", "<s>")
_END = ("</s>", "</s>")


def _contexts(tree: ChunkTree, k: int) -> list[tuple]:
    items = list(zip(tree.words, tree.pos_tags))
    padded = [_PAD] * k + items + [_END] * k
    return [tuple(padded[i:i + 2 * k + 1]) for i in range(len(items))]


def window_ceiling(trees: Sequence[ChunkTree], k: int) -> dict:
    """Best per-word nested-label accuracy of any labeller deciding from the ±k words and
    their POS tags (see the module doc). Keys: ``k``, ``words``, ``ceiling``,
    ``repeated_word_share`` (words whose context occurs ≥ 2 times), ``repeated_agreement``
    (majority agreement among those), ``contexts``."""
    groups: dict[tuple, Counter] = defaultdict(Counter)
    for tree in trees:
        for ctx, label in zip(_contexts(tree, k), tree.nested_labels()):
            groups[ctx][label] += 1
    words = sum(sum(c.values()) for c in groups.values())
    best = sum(max(c.values()) for c in groups.values())
    rep = [c for c in groups.values() if sum(c.values()) > 1]
    rep_words = sum(sum(c.values()) for c in rep)
    rep_best = sum(max(c.values()) for c in rep)
    return {"k": k, "words": words, "contexts": len(groups),
            "ceiling": best / words if words else 0.0,
            "repeated_word_share": rep_words / words if words else 0.0,
            "repeated_agreement": rep_best / rep_words if rep_words else 1.0}


def leave_one_out_context(trees: Sequence[ChunkTree], k: int = 3) -> dict:
    """Accuracy of the file's own context-majority labeller, each word left out of its own
    table: a word gets the most frequent label of the *other* words sharing its ±k context
    (words + POS), backing off to ±(k-1) … ±0 when it has none, and ``O`` when even its word
    and tag are unique; ties go to the label first seen. This is a labeller trained on the
    very file it is tested on, with every other description (duplicates included) as training
    data. Keys: ``k``, ``words``, ``accuracy``, ``by_width`` (words decided at each width)."""
    tables = []
    ordered: list[list[tuple[tuple, str]]] = []
    for width in range(k, -1, -1):
        groups: dict[tuple, Counter] = defaultdict(Counter)
        for tree in trees:
            for ctx, label in zip(_contexts(tree, width), tree.nested_labels()):
                groups[ctx][label] += 1
        tables.append((width, groups))
    right = words = 0
    by_width: Counter = Counter()
    for tree in trees:
        labels = tree.nested_labels()
        contexts = {width: _contexts(tree, width) for width, _ in tables}
        for i, gold in enumerate(labels):
            words += 1
            guess, used = OUTSIDE, -1
            for width, groups in tables:
                counts = groups[contexts[width][i]].copy()
                counts[gold] -= 1
                counts = +counts
                if counts:
                    guess, used = counts.most_common(1)[0][0], width
                    break
            by_width[used] += 1
            right += guess == gold
    return {"k": k, "words": words, "accuracy": right / words if words else 0.0,
            "by_width": {str(w): n for w, n in sorted(by_width.items(), reverse=True)}}


def ngram_agreement(trees: Sequence[ChunkTree], n: int, min_count: int = 2) -> dict:
    """For word n-grams (with POS) occurring ≥ ``min_count`` times: the share of occurrences
    labelled (all n nested labels) as that n-gram's most frequent labelling. Keys: ``n``,
    ``ngrams``, ``occurrences``, ``agreement``, ``examples`` (the n-grams with most
    occurrences off their majority: n-gram text, occurrences, distinct labellings)."""
    groups: dict[tuple, Counter] = defaultdict(Counter)
    for tree in trees:
        items = list(zip(tree.words, tree.pos_tags))
        labels = tree.nested_labels()
        for i in range(len(items) - n + 1):
            groups[tuple(items[i:i + n])][tuple(labels[i:i + n])] += 1
    kept = {g: c for g, c in groups.items() if sum(c.values()) >= min_count}
    occ = sum(sum(c.values()) for c in kept.values())
    agree = sum(max(c.values()) for c in kept.values())
    off = sorted(kept.items(), key=lambda gc: -(sum(gc[1].values()) - max(gc[1].values())))
    return {"n": n, "ngrams": len(kept), "occurrences": occ,
            "agreement": agree / occ if occ else 1.0,
            "examples": [{"ngram": " ".join(w for w, _ in g), "occurrences": sum(c.values()),
                          "labellings": len(c)} for g, c in off[:5]]}


def duplicate_agreement(trees: Sequence[ChunkTree]) -> dict:
    """Descriptions with identical words: how many groups, and the pairwise per-word
    agreement of their nested labels (each unordered pair of a group counts once)."""
    groups: dict[tuple, list[list[str]]] = defaultdict(list)
    for tree in trees:
        groups[tuple(tree.words)].append(tree.nested_labels())
    dup = {w: ls for w, ls in groups.items() if len(ls) > 1}
    same = total = identical = pairs = 0
    for labellings in dup.values():
        for i in range(len(labellings)):
            for j in range(i + 1, len(labellings)):
                a, b = labellings[i], labellings[j]
                pairs += 1
                identical += a == b
                total += len(a)
                same += sum(x == y for x, y in zip(a, b))
    return {"groups": len(dup), "descriptions": sum(len(v) for v in dup.values()),
            "pairs": pairs, "identical_pairs": identical,
            "pairwise_word_agreement": same / total if total else 1.0}


# --------------------------------------------------------------------------------------------
# annotation conventions, construction by construction

_MOTION = frozenset({"go", "walk", "move", "head", "come", "continue", "proceed"})
_TURN = frozenset({"turn", "take", "make", "hang"})
_FILLERS = frozenset({"um", "uh", "umm", "uhh", "er", "hmm"})
_LEAD = frozenset({"um", "uh", "umm", "uhh", "er", "okay", "ok", "so", "well", "alright", "oh"})
_HEDGE2 = frozenset({("i", "think"), ("i", "believe"), ("i", "guess")})


def _top(label: str) -> str:
    return label.split("-")[0]


def conventions(trees: Sequence[ChunkTree]) -> dict[str, Counter]:
    """How a corpus annotates the constructions where corpora disagree; each value counts
    the label choices made (see the keys' names)."""
    out: dict[str, Counter] = {key: Counter() for key in (
        "leading motion verb: outermost label", "leading motion + 'and' + turn: motion label",
        "first turn verb before a direction: label", "motion verb + to/into + room word: verb label",
        "'there is/'s': outermost label", "'you will/'ll see': outermost label",
        "filler um/uh: inside a chunk?", "hedge 'i think/believe/guess': label",
        "object phrase spans the furniture phrase after is/'s/will", "object phrases per description",
        "outermost chunks", "first word")}
    for tree in trees:
        w, p, lab = tree.words, tree.pos_tags, tree.nested_labels()
        n = len(w)
        if not n:
            continue
        i = 0
        while i < n and (w[i] in _LEAD or p[i] in ("WHO", "IGN")):
            i += 1
        if i < n and w[i] in _MOTION:
            out["leading motion verb: outermost label"][_top(lab[i])] += 1
            j = i + 1
            while j < n and j < i + 4 and w[j] != "and":
                j += 1
            if j + 1 < n and w[j] == "and" and w[j + 1] in _TURN:
                out["leading motion + 'and' + turn: motion label"][_top(lab[i])] += 1
        for j in range(n):
            if w[j] in _TURN and any(p[m] == "DIR" for m in range(j + 1, min(n, j + 4))):
                out["first turn verb before a direction: label"][lab[j]] += 1
                break
        for j in range(n - 2):
            if w[j] in _MOTION and w[j + 1] in ("to", "into") and "RM" in p[j + 2:j + 6]:
                out["motion verb + to/into + room word: verb label"][lab[j]] += 1
            if w[j] == "there" and w[j + 1] in ("is", "'s"):
                out["'there is/'s': outermost label"][_top(lab[j])] += 1
            if w[j] == "you" and w[j + 1] in ("will", "'ll") and w[j + 2] == "see":
                out["'you will/'ll see': outermost label"][_top(lab[j])] += 1
        for j in range(n):
            if w[j] in _FILLERS:
                out["filler um/uh: inside a chunk?"]["inside" if lab[j] != OUTSIDE else "outside"] += 1
            if j + 1 < n and (w[j], w[j + 1]) in _HEDGE2:
                out["hedge 'i think/believe/guess': label"][lab[j]] += 1
            if w[j] in ("is", "'s", "are", "will", "should") and lab[j].startswith("OBTP"):
                nxt = [lab[m] for m in range(j + 1, min(n, j + 4)) if "FURTP" in lab[m]]
                if nxt:
                    out["object phrase spans the furniture phrase after is/'s/will"][
                        "yes" if nxt[0].startswith("OBTP") else "no"] += 1
        tops = [chunk.label for chunk, _, depth in tree.chunks() if depth == 0]
        out["object phrases per description"][str(min(tops.count("OBTP"), 3)).replace("3", "3+")] += 1
        out["outermost chunks"].update(tops)
        out["first word"]["outside" if lab[0] == OUTSIDE else "in a chunk"] += 1
    return out


#: the annotation decisions a (gold, predicted) label pair belongs to, in the order tested
CONSTRUCTIONS = (
    "leading motion / where the room phrase starts (O ↔ ORMTP)",
    "extent of the turn in the room phrase (ORMTP ↔ ORMTP-ORMRP)",
    "room-entering turn vs in-room move (ORMTP… ↔ IRMRP)",
    "object phrase scope vs furniture phrase (OBTP… ↔ FURTP…)",
    "move nested in the furniture phrase (FURTP-IRMRP ↔ IRMRP / FURTP)",
    "words between chunks (O ↔ a chunk)",
    "reference phrases (FURRP / OBRP / none)",
    "nesting inside the object phrase",
    "other",
)


def construction_of(gold: str, predicted: str) -> str:
    """The annotation decision behind one wrong nested label (one of :data:`CONSTRUCTIONS`)."""
    pair = {gold, predicted}
    if pair <= {OUTSIDE, "ORMTP"}:
        return CONSTRUCTIONS[0]
    if pair == {"ORMTP", "ORMTP-ORMRP"}:
        return CONSTRUCTIONS[1]
    if pair & {"ORMTP", "ORMTP-ORMRP"} and "IRMRP" in pair:
        return CONSTRUCTIONS[2]
    if ("OBTP" in gold) != ("OBTP" in predicted) and ("FURTP" in gold or "FURTP" in predicted):
        return CONSTRUCTIONS[3]
    if (gold.startswith("FURTP") or predicted.startswith("FURTP")) and \
            ("IRMRP" in gold) != ("IRMRP" in predicted):
        return CONSTRUCTIONS[4]
    if OUTSIDE in pair:
        return CONSTRUCTIONS[5]
    if ("FURRP" in gold) != ("FURRP" in predicted) or ("OBRP" in gold) != ("OBRP" in predicted):
        return CONSTRUCTIONS[6]
    if gold.startswith("OBTP") and predicted.startswith("OBTP"):
        return CONSTRUCTIONS[7]
    return CONSTRUCTIONS[8]


def errors_by_construction(confusions: Counter) -> list[tuple[str, int]]:
    """Chunk-label errors ((gold, predicted) → count) summed per :data:`CONSTRUCTIONS` entry,
    largest first."""
    out: Counter = Counter()
    for (gold, predicted), n in confusions.items():
        if gold != predicted:
            out[construction_of(gold, predicted)] += n
    return out.most_common()


def consistency_report(trees: Sequence[ChunkTree], windows=(0, 1, 2, 3), ngrams=(2, 3, 4)) -> dict:
    """All self-consistency measures of one corpus (JSON-ready)."""
    return {
        "descriptions": len(trees),
        "words": sum(len(t.words) for t in trees),
        "window_ceiling": [window_ceiling(trees, k) for k in windows],
        "leave_one_out_context": [leave_one_out_context(trees, k) for k in windows],
        "ngram_agreement": [ngram_agreement(trees, n) for n in ngrams],
        "duplicates": duplicate_agreement(trees),
        "conventions": {k: dict(v.most_common()) for k, v in conventions(trees).items()},
    }
