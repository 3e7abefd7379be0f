"""Does a corpus generator read the real CSISL descriptions better? Mean over generator seeds.

Run from the repository root::

    .venv/bin/python benchmarks/csisl_corpus_seeds.py                    # tools/corpus, 3 seeds
    .venv/bin/python benchmarks/csisl_corpus_seeds.py --scale 1.0 --scale 1.5
    git archive <commit> tools/corpus | tar -x -C /tmp/old               # an earlier generator …
    .venv/bin/python benchmarks/csisl_corpus_seeds.py --generator /tmp/old/tools/corpus --scale 0

Every change to the generator reshuffles its random stream, so one corpus measured once moves
by about ±1 point on the real CSISL descriptions for reasons that have nothing to do with the
change. This generates the corpus with several seeds (into a temporary folder, never into
``corpus/``), trains the nested chunker on each (gold POS as input, the product's settings) and
prints per-word chunk accuracy on the real descriptions and the 149 templates, per seed and
as mean. ``--scale 0`` calls a generator without the ``--scale`` option (earlier versions).
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def main(argv=None) -> int:
    from assistant.language.chunker import NestedChunker
    from assistant.language.corpus import read_corpus

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--generator", type=Path, default=ROOT / "tools" / "corpus",
                    help="folder holding generate.py (default tools/corpus)")
    ap.add_argument("--csisl", type=Path, default=ROOT.parent / "shared" / "realdata" / "csisl")
    ap.add_argument("--seeds", type=int, nargs="+", default=[20141014, 1, 2])
    ap.add_argument("--scale", type=float, action="append",
                    help="generator --scale (repeatable; default: the generator's own)")
    args = ap.parse_args(argv)
    real_path = args.csisl / "csisl_real_descriptions_annotated.xml"
    tpl_path = args.csisl / "csisl_templates149_annotated.xml"
    if not (real_path.exists() and tpl_path.exists()):
        print(f"CSISL files not found in {args.csisl} (give --csisl DIR)", file=sys.stderr)
        return 2
    real, tpl = read_corpus(real_path).trees(), read_corpus(tpl_path).trees()
    for scale in args.scale or [None]:
        r_acc, t_acc = [], []
        for seed in args.seeds:
            with tempfile.TemporaryDirectory(prefix="corpus-seed-") as tmp:
                cmd = [sys.executable, str(args.generator / "generate.py"), "--out", tmp, "--seed", str(seed)]
                if scale:
                    cmd += ["--scale", str(scale)]
                subprocess.run(cmd, check=True, capture_output=True, text=True)
                trees = read_corpus(Path(tmp) / "descriptions.xml").trees()
            started = time.perf_counter()
            chunker = NestedChunker().fit(trees)
            seconds = time.perf_counter() - started
            r_acc.append(chunker.accuracy(real))
            t_acc.append(chunker.accuracy(tpl))
            print(f"scale {scale or 'default'} seed {seed}: {len(trees)} descriptions, chunker "
                  f"trained in {seconds:.1f} s; real {100 * r_acc[-1]:.2f}%, templates "
                  f"{100 * t_acc[-1]:.2f}%", flush=True)
        print(f"scale {scale or 'default'}: MEAN real {100 * statistics.mean(r_acc):.2f}% "
              f"(min {100 * min(r_acc):.2f}, max {100 * max(r_acc):.2f}), templates "
              f"{100 * statistics.mean(t_acc):.2f}% (min {100 * min(t_acc):.2f})", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
