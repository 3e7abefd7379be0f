"""Where the CSISL study's files are: ``../shared/realdata/csisl/`` beside the checkout.

The tagging and grounding evaluations test on them by default when the folder is there; they
are read from that path and never copied into the repository.
"""

from __future__ import annotations

from pathlib import Path


def csisl_folder() -> Path:
    """``../shared/realdata/csisl`` next to the checkout (it may not exist)."""
    from assistant.language.corpus import repo_root

    return repo_root().parent / "shared" / "realdata" / "csisl"
