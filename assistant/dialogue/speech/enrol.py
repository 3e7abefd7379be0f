"""Speaker enrolment: pocketsphinx's acoustic model adapted to one person's voice.

The packaged en-US model was trained on other voices; a voice it fits badly (a high voice, an
accent) is misheard whatever the language model says. A person reads the **enrolment script**
(:func:`enrolment_script`: sentences of our annotated corpus, none of them a test sentence); the
recordings' features are computed as the recogniser computes them (the noise floor, the voice's
VTLN warp, dither, the model's own feature parameters), SphinxTrain's ``bw`` collects the
statistics of the model's Gaussians along the known words, and ``map_adapt`` moves the Gaussians,
mixture weights and transitions towards them (maximum a posteriori adaptation). The adapted model
is a folder of the user's data directory, ``speakers/NAME/model`` (:func:`speaker_model`), built
in a temporary folder and renamed into place under a lock, so an interrupted enrolment leaves the
previous one; ``--speaker NAME`` (chat, listen) decodes with it.

The packaged model ships its mixture weights only compressed (``sendump``, 8 bits each) and its
``mdef`` in binary form; both are expanded once into the cache (:func:`training_model`).
SphinxTrain's tools come from the system (Debian: ``sphinxtrain``, ``sphinxbase-utils``,
``pocketsphinx``; ``make setup`` installs them); without them enrolment says what to install.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import struct
import subprocess
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from assistant.dialogue.speech.errors import RecogniserError

#: how many sentences a person reads (40 in the measurement, docs/speech.md), and the most the
#: script holds (a script of N sentences is the first N of it, whatever N)
ENROL_SENTENCES = 40
SCRIPT_MAX = 200
#: shortest and longest script sentence (words)
SCRIPT_WORDS = (5, 14)
#: recordings needed at the least (fewer adapt too little to be worth a model)
MIN_RECORDINGS = 10
SPHINXTRAIN_DIR = Path("/usr/lib/sphinxtrain")
INSTALL_HINT = "install SphinxTrain: sudo apt-get install sphinxtrain sphinxbase-utils pocketsphinx (or make setup)"
#: the packaged model's front end (its feat.params) for sphinx_fe, and its features for bw
FRONT_END = ("-lowerf", "130", "-upperf", "6800", "-nfilt", "25", "-transform", "dct", "-lifter", "22",
             "-samprate", "16000", "-dither", "yes", "-seed", "1", "-remove_silence", "no", "-remove_noise", "yes")
FEATURES = ("-feat", "1s_c_d_dd", "-svspec", "0-12/13-25/26-38", "-cmn", "batch", "-agc", "none", "-varnorm", "no")
NAME_RE = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_-]{0,39}$")


@dataclass(frozen=True)
class Enrolment:
    """An enrolled speaker: ``name``, the adapted ``model`` folder, how many ``recordings``."""

    name: str
    model: Path
    recordings: int


def tools() -> dict[str, Path | None]:
    """The SphinxTrain and sphinxbase programs enrolment runs (None: not installed)."""
    def find(name: str) -> Path | None:
        local = SPHINXTRAIN_DIR / name
        found = local if local.is_file() else shutil.which(name)
        return Path(found) if found else None

    return {name: find(name) for name in ("bw", "map_adapt", "sphinx_fe", "pocketsphinx_mdef_convert")}


def require_tools() -> dict[str, Path]:
    found = tools()
    missing = [name for name, path in found.items() if path is None]
    if missing:
        raise RecogniserError(f"speaker enrolment needs {', '.join(missing)}: {INSTALL_HINT}")
    return found  # type: ignore[return-value]


def enrolment_script(count: int = ENROL_SENTENCES) -> list[str]:
    """The first ``count`` sentences a person reads: corpus descriptions of 5–14 words whose every
    word the home model can pronounce, spread through the corpus (the same list every time, and
    the first sentences the same whatever ``count``: recordings of a longer script still match)."""
    from assistant.dialogue.speech.language_model import build_home_model, read_pronunciations
    from assistant.dialogue.speech.vocabulary import corpus_sentences

    known = read_pronunciations(build_home_model().dictionary)
    low, high = SCRIPT_WORDS
    pool = [s for s in dict.fromkeys(corpus_sentences())
            if low <= len(s.split()) <= high and all(w in known for w in s.split())]
    # golden-ratio order: any first N sentences are spread through the whole corpus
    order = sorted(range(len(pool)), key=lambda k: (k * 0.6180339887498949) % 1.0)
    return [pool[k] for k in order[:min(count, SCRIPT_MAX)]]


def check_name(name: str) -> str:
    if not NAME_RE.match(name or ""):
        raise RecogniserError(f"speaker name {name!r}: use 1–40 letters, digits, '-' or '_', starting with a "
                              "letter or digit")
    return name


def speaker_model(name: str, data_dir: Path | None = None) -> Path:
    """The folder of ``name``'s adapted model (it may not exist yet)."""
    from assistant.fileio import user_data_dir

    return Path(data_dir or user_data_dir()) / "speakers" / check_name(name) / "model"


def enrolled_model(name: str, data_dir: Path | None = None) -> Path:
    """``name``'s adapted model folder, or a clear error when that speaker has not enrolled."""
    folder = speaker_model(name, data_dir)
    if not (folder / "means").is_file():
        raise RecogniserError(f"no enrolled speaker {name!r} (no model in {folder.parent}); enrol first: "
                              f"assistant enrol {name}")
    return folder


def training_model(cache: Path | None = None) -> Path:
    """The packaged model with a text ``mdef`` and expanded mixture weights, as SphinxTrain reads
    it (built once into the cache)."""
    from assistant.fileio import cache_dir

    packaged = packaged_model()
    folder = Path(cache or cache_dir()) / "speech" / "sphinxtrain-en-us"
    if (folder / "mixture_weights").is_file() and (folder / "mdef.txt").is_file():
        return folder
    found = require_tools()
    folder.parent.mkdir(parents=True, exist_ok=True)
    building = Path(tempfile.mkdtemp(prefix=".sphinxtrain-", dir=folder.parent))
    try:
        run_tool(found["pocketsphinx_mdef_convert"], "-text", packaged / "mdef", building / "mdef.txt")
        write_mixture_weights(building / "mixture_weights", expand_sendump(packaged / "sendump"))
        try:
            os.replace(building, folder)
        except OSError:  # another process built it meanwhile: theirs is the same
            if not (folder / "mixture_weights").is_file():
                raise
    finally:
        shutil.rmtree(building, ignore_errors=True)
    return folder


def expand_sendump(path: Path) -> np.ndarray:
    """Mixture weights (senones × streams × densities) from pocketsphinx's 8-bit ``sendump``,
    where each weight is kept as ``-log_1.0001(w)`` shifted right by ``mixw_shift`` bits."""
    data = path.read_bytes()
    pos = 0

    def integer() -> int:
        nonlocal pos
        value = struct.unpack_from("<I", data, pos)[0]
        pos += 4
        return value

    def string() -> str | None:
        nonlocal pos
        n = integer()
        text = data[pos:pos + n - 1].decode("ascii", "replace") if n else None
        pos += n
        return text

    string()  # the format description's title
    header: dict[str, str] = {}
    while (line := string()) is not None:
        key, *value = line.split()
        header[key] = value[0] if value else ""
    if int(header.get("cluster_count", 0)) != 0 or "feature_count" not in header:
        raise RecogniserError(f"{path}: a sendump layout enrolment does not read (cluster_count "
                              f"{header.get('cluster_count')})")
    streams, shift = int(header["feature_count"]), int(header.get("mixw_shift", 10))
    densities, senones = integer(), integer()
    if pos + streams * densities * senones > len(data):
        raise RecogniserError(f"{path}: truncated ({len(data)} bytes for {senones} senones)")
    raw = np.frombuffer(data, np.uint8, streams * densities * senones, pos).reshape(streams, densities, senones)
    weights = np.power(1.0001, -(raw.astype(np.int64) << shift).astype(np.float64))
    return np.ascontiguousarray(weights.transpose(2, 0, 1))


def write_mixture_weights(path: Path, weights: np.ndarray) -> None:
    """A SphinxTrain mixture-weight file: an ``s3`` header, the byte-order word, a 3-d float array."""
    head = b"s3\nversion 1.0\n"
    pad = (4 - (len(head) + len(b"endhdr\n")) % 4) % 4
    d1, d2, d3 = weights.shape
    with open(path, "wb") as f:
        f.write(head + b" " * pad + b"endhdr\n" + struct.pack("=i", 0x11223344))
        f.write(struct.pack("=IIII", d1, d2, d3, d1 * d2 * d3))
        weights.astype("<f4").tofile(f)


def enrol(name: str, recordings: list[tuple[np.ndarray, str]], data_dir: Path | None = None,
          progress=None) -> Enrolment:
    """Adapt the model to ``recordings`` ((16 kHz samples, the words said) pairs) and keep it as
    ``name``'s; an earlier enrolment of ``name`` is replaced only once the new model is complete."""
    from assistant.fileio import file_lock

    check_name(name)
    if len(recordings) < MIN_RECORDINGS:
        raise RecogniserError(f"enrolment needs at least {MIN_RECORDINGS} recordings, got {len(recordings)}")
    found = require_tools()
    base = training_model()
    target = speaker_model(name, data_dir)
    target.parent.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix=".enrol-", dir=target.parent))
    try:
        training_files(recordings, work, found["sphinx_fe"], progress)
        collect_statistics(base, work, found)
        map_adapt(base, work, found)
        (work / "model" / "enrolled.json").write_text(json.dumps(
            {"name": name, "recordings": len(recordings), "when": time.time(),
             "sentences": [text for _, text in recordings]}, indent=1) + "\n")
        with file_lock(target):
            old = target.with_name(".model-old")
            shutil.rmtree(old, ignore_errors=True)
            if target.exists():
                os.replace(target, old)
            os.replace(work / "model", target)
            shutil.rmtree(old, ignore_errors=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return Enrolment(name, target, len(recordings))


def training_files(recordings, work: Path, sphinx_fe: Path, progress=None) -> None:
    """Feature files, control file, transcripts and dictionary for ``bw`` under ``work``."""
    from assistant.dialogue.speech.audio import DEFAULT_FLOOR_DB, with_noise_floor, write_wav
    from assistant.dialogue.speech.language_model import build_home_model, read_pronunciations
    from assistant.dialogue.speech.listener import PAD_S
    from assistant.dialogue.speech.vocabulary import normalise_transcript
    from assistant.dialogue.speech.vtln import pitch_hz, warp_for_pitch

    dictionary = build_home_model().dictionary
    known = read_pronunciations(dictionary)
    ids, lines = [], []
    for n, (samples, text) in enumerate(recordings):
        words = normalise_transcript(text)
        unknown = [w for w in words.split() if w not in known]
        if not words or unknown:
            raise RecogniserError(f"recording {n + 1}: words the model cannot pronounce: {', '.join(unknown) or '(none said)'}")
        pad = np.zeros(int(PAD_S * 16000), dtype=np.float32)
        samples = np.concatenate([pad, np.asarray(samples, dtype=np.float32), pad])
        warp = warp_for_pitch(pitch_hz(samples))  # as a whole utterance is decoded
        uid = f"r{n:03d}"
        wav = write_wav(work / f"{uid}.wav", with_noise_floor(samples, DEFAULT_FLOOR_DB))
        run_tool(sphinx_fe, *FRONT_END, "-warp_type", "inverse_linear", "-warp_params", f"{warp:g}", "-mswav", "yes",
             "-i", wav, "-o", work / f"{uid}.mfc")
        ids.append(uid)
        lines.append(f"<s> {words} </s> ({uid})")
        if progress is not None:
            progress("features", n + 1, len(recordings))
    (work / "ctl").write_text("\n".join(ids) + "\n")
    (work / "trans").write_text("\n".join(lines) + "\n")
    shutil.copy(dictionary, work / "dict")


def packaged_model() -> Path:
    """The folder of pocketsphinx's packaged en-US acoustic model."""
    import pocketsphinx

    return Path(pocketsphinx.get_model_path()) / "en-us" / "en-us"


def collect_statistics(base: Path, work: Path, found: dict[str, Path]) -> Path:
    """``bw`` over the recordings of ``work`` (:func:`training_files`) → its ``accum`` folder."""
    packaged = packaged_model()
    accum = work / "accum"
    accum.mkdir()
    run_tool(found["bw"], "-moddeffn", base / "mdef.txt", "-ts2cbfn", ".ptm.", *FEATURES, "-dictfn", work / "dict",
         "-fdictfn", packaged / "noisedict", "-ctlfn", work / "ctl", "-lsnfn", work / "trans", "-accumdir", accum,
         "-cepdir", work, "-cepext", "mfc", "-mixwfn", base / "mixture_weights", "-meanfn", packaged / "means",
         "-varfn", packaged / "variances", "-tmatfn", packaged / "transition_matrices")
    return accum


def map_adapt(base: Path, work: Path, found: dict[str, Path]) -> Path:
    """``map_adapt`` of the packaged model by ``work``'s statistics into ``work/model`` (decodable)."""
    packaged, accum, model = packaged_model(), work / "accum", work / "model"
    model.mkdir()
    run_tool(found["map_adapt"], "-moddeffn", base / "mdef.txt", "-ts2cbfn", ".ptm.", "-meanfn", packaged / "means",
         "-varfn", packaged / "variances", "-mixwfn", base / "mixture_weights", "-tmatfn",
         packaged / "transition_matrices", "-accumdir", accum, "-mapmeanfn", model / "means",
         "-mapvarfn", model / "variances", "-mapmixwfn", model / "mixture_weights",
         "-maptmatfn", model / "transition_matrices")
    for name in ("mdef", "feat.params", "noisedict"):
        shutil.copy(packaged / name, model / name)
    return model


def run_tool(program, *args) -> None:
    done = subprocess.run([str(program), *map(str, args)], capture_output=True, text=True)
    if done.returncode:
        tail = (done.stderr or done.stdout).strip().splitlines()[-3:]
        raise RecogniserError(f"{Path(str(program)).name} failed (exit {done.returncode}): {' / '.join(tail)}")
