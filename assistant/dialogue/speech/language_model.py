"""The home language model: a trigram model and a pronunciation dictionary for pocketsphinx,
built from :func:`~assistant.dialogue.speech.vocabulary.build_vocabulary` and cached.

The model is a back-off trigram model in ARPA format (pocketsphinx's own ``ArpaBoLM`` builder,
fixed discount mass ``discount``); the dictionary holds only the words of the model (with
every pronunciation CMUdict gives), which makes the decoder start in a twentieth of a second
instead of seconds. Both live under ``<cache>/speech/`` named by a hash of the text they are
built from, so a change to the corpus, the catalogue or a world builds them again.
"""

from __future__ import annotations

import io
import json
import logging
from dataclasses import dataclass
from pathlib import Path

from assistant.dialogue.speech.vocabulary import SpeechVocabulary, build_vocabulary

log = logging.getLogger(__name__)

#: bump when the way the model is built changes (invalidates the caches)
BUILDER_VERSION = 1
#: back-off discount mass of the trigram model (0.05 gave fewer errors than 0.2 or 0.5 in development)
DEFAULT_DISCOUNT = 0.05


@dataclass(frozen=True)
class HomeModel:
    """Paths of the built model: ``lm`` (ARPA), ``dictionary``, ``phrases`` (JSON list, for
    grammar-based engines); the words left out for lack of a pronunciation."""

    lm: Path
    dictionary: Path
    phrases: Path
    words: int
    dropped: tuple[str, ...]


def default_dictionary() -> Path:
    import pocketsphinx

    return Path(pocketsphinx.get_model_path()) / "en-us" / "cmudict-en-us.dict"


def read_pronunciations(path: Path) -> dict[str, list[str]]:
    """CMUdict-format lines ``word[(n)] PH ON ES`` → word → its pronunciation lines."""
    out: dict[str, list[str]] = {}
    with open(path, encoding="utf-8", errors="replace") as handle:
        for line in handle:
            head = line.split(" ", 1)[0]
            if head:
                out.setdefault(head.split("(", 1)[0], []).append(line if line.endswith("\n") else line + "\n")
    return out


def build_home_model(vocabulary: SpeechVocabulary | None = None, *, world=None, discount: float = DEFAULT_DISCOUNT,
                     cache: Path | None = None) -> HomeModel:
    """The cached model for ``vocabulary`` (default: the repository's corpus and homes)."""
    from assistant.fileio import atomic_write_text, cache_dir

    vocabulary = vocabulary or build_vocabulary(world)
    folder = Path(cache or cache_dir()) / "speech"
    stem = f"home-v{BUILDER_VERSION}-{vocabulary.key}-d{discount:g}"
    paths = HomeModel(folder / f"{stem}.arpa", folder / f"{stem}.dict", folder / f"{stem}.phrases.json", 0, ())
    meta_path = folder / f"{stem}.json"
    if all(p.is_file() for p in (paths.lm, paths.dictionary, paths.phrases, meta_path)):
        try:
            meta = json.loads(meta_path.read_text(encoding="utf-8"))
            return HomeModel(paths.lm, paths.dictionary, paths.phrases, int(meta["words"]), tuple(meta["dropped"]))
        except (ValueError, KeyError, OSError) as error:
            log.warning("rebuilding the speech model: unreadable %s (%s)", meta_path, error)
    pronunciations = read_pronunciations(default_dictionary())
    usable, dropped = vocabulary.restricted(lambda w: w in pronunciations)
    if dropped:
        log.info("speech model: %d words without a pronunciation left out: %s", len(dropped), ", ".join(dropped))
    from pocketsphinx.lm import ArpaBoLM

    builder = ArpaBoLM(text="\n".join(usable.sentences), add_start=True, discount_mass=discount)
    builder.compute()
    arpa = io.StringIO()
    builder.write(arpa)
    words = usable.words
    folder.mkdir(parents=True, exist_ok=True)
    atomic_write_text(paths.lm, arpa.getvalue())
    atomic_write_text(paths.dictionary, "".join(line for w in words for line in pronunciations[w]))
    atomic_write_text(paths.phrases, json.dumps(list(usable.phrases), indent=0) + "\n")
    atomic_write_text(meta_path, json.dumps({"words": len(words), "dropped": dropped,
                                             "sentences": len(usable.sentences)}) + "\n")
    return HomeModel(paths.lm, paths.dictionary, paths.phrases, len(words), tuple(dropped))
