"""Words → tokens → POS tags → nested semantic chunks → a chunk tree (dissertation 4.2)."""

from assistant.language.tree import CHUNK_LABELS, OUTSIDE, Chunk, ChunkTree, Token

__all__ = ["CHUNK_LABELS", "OUTSIDE", "Chunk", "ChunkTree", "Token"]
