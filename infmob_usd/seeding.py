"""Seeding: one object is a pure function of (category, seed, overrides).

Each object gets a :class:`numpy.random.SeedSequence` built from its seed and a
stable id of its category, spawned into independent named streams, so adding an
optional part (structure stream) never reshuffles textures (materials stream).
"""

from __future__ import annotations

import zlib

import numpy as np

STREAMS = ("params", "structure", "geometry", "materials")
MAX_SEED = 2**63 - 1
"""Largest seed (object names carry the seed: ``CATEGORY_SSSSSS``, at most 19 digits)."""


def category_id(category: str) -> int:
    """A stable 32-bit id of a category name (CRC-32, identical on every platform)."""
    return zlib.crc32(category.encode("utf-8"))


def streams(category: str, seed: int) -> dict[str, np.random.Generator]:
    """Independent generators for each of :data:`STREAMS`."""
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or not 0 <= seed <= MAX_SEED:
        from .errors import ParameterError

        raise ParameterError(f"seed must be an integer in 0..{MAX_SEED}, got {seed!r}")
    root = np.random.SeedSequence((int(seed), category_id(category)))
    return {name: np.random.default_rng(s) for name, s in zip(STREAMS, root.spawn(len(STREAMS)))}
