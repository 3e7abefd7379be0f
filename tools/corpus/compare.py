"""Compare the corpus with the CSISL files: tag / chunk-label distributions, vocabulary
coverage, and how well the corpus grounding rules reproduce the CSISL chunk groundings.

    .venv/bin/python tools/corpus/compare.py ../shared/realdata/csisl [--markdown]

Prints, for POS tags and nested chunk labels, the share of words in our corpus next to the
share in the real CSISL descriptions and in the 149 templates; the share of real words (tokens)
whose word form our corpus never shows, and whose (word, tag) pair it never shows; and the
agreement of :func:`notation.ground_chunk` with the grounding columns of the CSISL template CSV
(a check that the corpus labels chunks by the same conventions).
"""

from __future__ import annotations

import argparse
import csv
import re
import sys
import xml.etree.ElementTree as ET
from collections import Counter
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from notation import CHUNK_LABELS, GROUNDING_FIELDS, Node, Word, ground_chunk  # noqa: E402

REPO = HERE.parents[1]


def read_xml(path: Path) -> list[list[tuple[str, str, str]]]:
    """Descriptions as lists of (word, tag, nested label)."""
    raw = path.read_bytes().decode("utf-8-sig")
    raw = re.sub(r"<\?xml[^>]*\?>", "", raw)
    out = []
    for s in ET.fromstring(raw).iter("S"):
        words: list[tuple[str, str, str]] = []

        def visit(el, path):
            for c in el:
                if len(c) or c.tag in CHUNK_LABELS:
                    visit(c, path + [c.tag] if c.tag in CHUNK_LABELS else path)
                else:
                    w = (c.text or "").strip().lower()
                    if w:
                        words.append((w, c.tag, "-".join(path) or "O"))   # outermost first
        visit(s, [])
        out.append(words)
    return out


def shares(descs, index: int) -> Counter:
    c = Counter(w[index] for d in descs for w in d)
    n = sum(c.values())
    return Counter({k: v / n for k, v in c.items()})


def table(name: str, ours: Counter, real: Counter, tmpl: Counter, top: int, md: bool) -> None:
    keys = sorted(set(ours) | set(real), key=lambda k: -(real.get(k, 0) + ours.get(k, 0)))[:top]
    if md:
        print(f"| {name} | ours % | real CSISL % | templates % |\n|---|---|---|---|")
        for k in keys:
            print(f"| {k} | {100 * ours.get(k, 0):.1f} | {100 * real.get(k, 0):.1f} | {100 * tmpl.get(k, 0):.1f} |")
    else:
        print(f"{name:24s} {'ours%':>7s} {'real%':>7s} {'tmpl%':>7s}")
        for k in keys:
            print(f"{k:24s} {100 * ours.get(k, 0):7.2f} {100 * real.get(k, 0):7.2f} {100 * tmpl.get(k, 0):7.2f}")
    print()


def grounding_agreement(csisl: Path) -> dict:
    """Agreement of the corpus grounding rules with the CSISL template chunk groundings."""
    rows = list(csv.DictReader(open(csisl / "csisl_templates149_chunk_groundings.csv", encoding="utf-8-sig")))
    ok = Counter()
    n = Counter()
    misses = Counter()
    for r in rows:
        toks = r["Chunk Content"].split()
        words = [Word(toks[i + 1], toks[i]) for i in range(0, len(toks) - 1, 2)]
        node = Node(r["Chunk Name"], words)
        room = r["target room"] if r["target room"] != "N/A" else "?"
        g = ground_chunk(node, {"room": room, "object": r["target object"]}, has_ormrp_child=True)
        for f in ("reference", "direction", "target"):
            n[f] += 1
            if g[f] == r[f]:
                ok[f] += 1
            else:
                misses[(r["Chunk Name"], r["Chunk Content"], f, g[f], r[f])] += 1
    return {"agreement": {f: ok[f] / n[f] for f in n}, "misses": misses}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csisl", type=Path, help="directory holding the CSISL files")
    ap.add_argument("--corpus", type=Path, default=REPO / "corpus" / "descriptions.xml")
    ap.add_argument("--markdown", action="store_true")
    ap.add_argument("--chunker-ceiling", action="store_true",
                    help="also train the product's chunker on every other real CSISL description and "
                         "test it on the rest (how consistent the real annotation is)")
    args = ap.parse_args(argv)
    ours = read_xml(args.corpus)
    real = read_xml(args.csisl / "csisl_real_descriptions_annotated.xml")
    tmpl = read_xml(args.csisl / "csisl_templates149_annotated.xml")
    print(f"descriptions: ours {len(ours)}, real {len(real)}, templates {len(tmpl)}")
    print(f"words: ours {sum(map(len, ours))}, real {sum(map(len, real))}, templates {sum(map(len, tmpl))}\n")
    table("POS tag", shares(ours, 1), shares(real, 1), shares(tmpl, 1), 40, args.markdown)
    table("nested chunk label", shares(ours, 2), shares(real, 2), shares(tmpl, 2), 30, args.markdown)
    vocab = {w for d in ours for w, _, _ in d}
    pairs = {(w, t) for d in ours for w, t, _ in d}
    for name, descs in (("real", real), ("templates", tmpl)):
        toks = [(w, t) for d in descs for w, t, _ in d]
        unseen_w = sum(1 for w, _ in toks if w not in vocab) / len(toks)
        unseen_p = sum(1 for p in toks if p not in pairs) / len(toks)
        print(f"{name}: tokens whose word our corpus never shows {100 * unseen_w:.1f}%, "
              f"whose (word, tag) pair it never shows {100 * unseen_p:.1f}%")
    missing = Counter(w for d in real for w, t, _ in d if w not in vocab)
    print("most frequent real words missing from our corpus:",
          ", ".join(f"{w}({c})" for w, c in missing.most_common(40)))
    if args.chunker_ceiling:
        sys.path.insert(0, str(REPO))
        from assistant.language.chunker import NestedChunker
        from assistant.language.corpus import read_corpus
        trees = read_corpus(args.csisl / "csisl_real_descriptions_annotated.xml").trees()
        acc = NestedChunker().fit(trees[::2]).accuracy(trees[1::2])
        print(f"chunker trained on the odd-numbered real descriptions, tested on the even ones: "
              f"{100 * acc:.1f}% nested-label accuracy per word (gold POS)")
    ga = grounding_agreement(args.csisl)
    print("\ngrounding rules vs CSISL template CSV:",
          ", ".join(f"{k} {100 * v:.1f}%" for k, v in ga["agreement"].items()))
    for (lab, content, f, got, want), c in ga["misses"].most_common(12):
        print(f"   {c:3d} {lab} '{content}' {f}: rules {got} / CSISL {want}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
