"""Encoded texture maps of library looks, made once and reused.

Every look an object can wear is one of the finite library of
:func:`~infmob_usd.materials.families.library_look` (16 per palette variant,
``len(families.library())`` in all), so the PNG maps of a look, which cost 30-45 ms to synthesize and encode at
512 px, are made once and then reused by every object that wears the look.

:func:`texture_maps` returns ``{map name: PNG bytes}`` through two caches:

* a per-process LRU in memory, bounded to :data:`MEMORY_BUDGET` bytes (memory stays
  flat however many objects a process makes);
* a folder on disk shared by every process and every run (:func:`cache_dir`):
  ``$INFMOB_USD_CACHE`` if set (``off`` disables it), else
  ``$XDG_CACHE_HOME/infmob-usd`` or ``~/.cache/infmob-usd``.  Files are written to a
  temporary name and renamed, so concurrent workers and crashes never leave a torn
  file under a real name, and every read checks each file's SHA-256 against the
  ``KEY.sha256.json`` written with it (a damaged entry is made again and overwritten).
  Entries live under a key made of the source of the synthesis code and the
  OpenCV / NumPy versions, so changing either never serves stale maps.  A folder
  that cannot be created or written is skipped (memory cache only).

The bytes are identical whether made now or read from a cache: synthesis and
encoding are deterministic.  :func:`build` fills the disk cache ahead of a large
run (``infmob textures``).
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
import threading
from collections import OrderedDict
from concurrent.futures import ProcessPoolExecutor
from contextlib import nullcontext
from pathlib import Path

import cv2
import numpy as np

from .families import Look, library
from .synth import TEXTURE_MAPS, encode_png, synthesize

__all__ = ["MEMORY_BUDGET", "build", "cache_dir", "code_key", "texture_maps"]

MEMORY_BUDGET = 96 * 2**20
"""Bytes of encoded maps kept in memory per process (about 150 looks at 512 px)."""

_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
_PNG_END = b"IEND\xaeB`\x82"
_HERE = Path(__file__).resolve().parent

_memory: OrderedDict[tuple, dict[str, bytes]] = OrderedDict()
_memory_bytes = 0
_lock = threading.Lock()
_code_key: str | None = None


def code_key() -> str:
    """Hash of everything the bytes of a map depend on besides the look and the size."""
    global _code_key
    if _code_key is None:
        h = hashlib.sha256()
        for name in ("synth.py", "families.py"):
            h.update((_HERE / name).read_bytes())
        h.update(f"cv2 {cv2.__version__} numpy {np.__version__}".encode())
        _code_key = h.hexdigest()[:16]
    return _code_key


def cache_dir() -> Path | None:
    """The disk cache folder for this code version, or ``None`` when disabled or unusable."""
    env = os.environ.get("INFMOB_USD_CACHE")
    if env is not None and env.strip().lower() in ("", "0", "off", "none", "false"):
        return None
    if env:
        root = Path(env).expanduser()
    else:
        base = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
        root = Path(base) / "infmob-usd"
    folder = root / "textures" / code_key()
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError:
        return None
    return folder if os.access(folder, os.W_OK | os.X_OK) else None


def _look_key(look: Look, size: int) -> str:
    blob = json.dumps(look.to_dict(wear=False), sort_keys=True) + f"|{size}"  # the wear is no part of the maps
    digest = hashlib.sha256(blob.encode()).hexdigest()[:16]
    tag = f"{look.family}_{look.variant}_{look.index:02d}" if look.index >= 0 else look.family
    return f"{size}/{tag}_{digest}"


def _whole_png(data: bytes) -> bool:
    return data[:8] == _PNG_SIGNATURE and data[-8:] == _PNG_END


def _digests(maps: dict[str, bytes]) -> dict[str, str]:
    return {name: hashlib.sha256(data).hexdigest() for name, data in sorted(maps.items())}


def _png_size(data: bytes) -> tuple[int, int]:
    return int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")


def _read(folder: Path, key: str, size: int | None = None) -> dict[str, bytes] | None:
    """The maps of ``key`` if every file is there, ``size`` px square, and matches the SHA-256 recorded
    beside them.

    A missing, torn or altered file (a flipped byte keeps the PNG header and end intact) is a
    miss: the caller makes the maps again and overwrites the entry. So is an entry replaced together
    with its hash file by maps of another size: the cache folder is shared, and not trusted that far.
    """
    try:
        want = json.loads((folder / f"{key}.sha256.json").read_text())
    except (OSError, ValueError):
        return None
    maps = {}
    for name in TEXTURE_MAPS:
        try:
            data = (folder / f"{key}_{name}.png").read_bytes()
        except OSError:
            return None
        if not _whole_png(data) or (size is not None and _png_size(data) != (size, size)):
            return None
        maps[name] = data
    if not isinstance(want, dict) or want != _digests(maps):
        return None
    return maps


def _write(folder: Path, key: str, maps: dict[str, bytes]) -> None:
    target = folder / key
    files = {f"{target.name}_{name}.png": data for name, data in maps.items()}
    files[f"{target.name}.sha256.json"] = json.dumps(_digests(maps), sort_keys=True).encode()  # last: seals
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        for fname, data in files.items():
            fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
            try:
                with os.fdopen(fd, "wb") as f:
                    f.write(data)
                os.replace(tmp, target.parent / fname)
            except BaseException:
                Path(tmp).unlink(missing_ok=True)
                raise
    except OSError:
        pass  # a full or read-only disk only costs the reuse


def _remember(key: tuple, maps: dict[str, bytes]) -> None:
    global _memory_bytes
    with _lock:
        if key in _memory:
            _memory.move_to_end(key)
            return
        _memory[key] = maps
        _memory_bytes += sum(map(len, maps.values()))
        while _memory_bytes > MEMORY_BUDGET and len(_memory) > 1:
            _, old = _memory.popitem(last=False)
            _memory_bytes -= sum(map(len, old.values()))


def forget() -> None:
    """Drop the maps held in memory: the next use of a look reads the disk cache or makes it."""
    global _memory_bytes
    with _lock:
        _memory.clear()
        _memory_bytes = 0


def make_maps(look: Look, size: int) -> dict[str, bytes]:
    """Synthesize and encode the maps of ``look`` without any cache."""
    return {name: encode_png(img) for name, img in synthesize(look, size).items()}


def texture_maps(look: Look, size: int, use_cache: bool = True) -> dict[str, bytes]:
    """PNG bytes of every map of ``look`` at ``size`` px (keys :data:`TEXTURE_MAPS`).

    Looks from the library hit the caches after their first use; any other look
    works too (it is keyed by its content).
    """
    if not use_cache:
        return make_maps(look, size)
    key = (look, size)
    with _lock:
        hit = _memory.get(key)
        if hit is not None:
            _memory.move_to_end(key)
            return dict(hit)  # a new dict: a caller editing its object's maps never edits the cache
    maps, _ = _disk_maps(look, size)
    _remember(key, maps)
    return dict(maps)


def _disk_maps(look: Look, size: int) -> tuple[dict[str, bytes], bool]:
    """The maps of ``look`` from the disk cache, or made now and stored there; and whether made."""
    folder = cache_dir()
    key = _look_key(look, size)
    maps = _read(folder, key, size) if folder else None
    if maps is not None:
        return maps, False
    maps = make_maps(look, size)
    if folder:
        _write(folder, key, maps)
    return maps, True


def _build_one(args: tuple[Look, int]) -> bool:
    return _disk_maps(*args)[1]


def build(size: int = 512, family: str | None = None, workers: int = 1, progress=None) -> dict:
    """Fill the disk cache with every library look (of one family spec, or all) at ``size``.

    Returns ``{"looks", "made", "cache", "megabytes"}``: looks in the library, looks
    synthesized now (the others were cached already), the cache folder and its size (every
    texture size).  Raises ``RuntimeError``
    when the disk cache is disabled or unusable.
    """
    folder = cache_dir()
    if folder is None:
        raise RuntimeError(
            "the texture cache folder is disabled or not writable; set INFMOB_USD_CACHE to a writable folder"
        )
    looks = library(family)
    jobs = [(look, size) for look in looks]
    made = 0
    with ProcessPoolExecutor(workers) if workers > 1 else nullcontext() as pool:
        results = pool.map(_build_one, jobs, chunksize=8) if pool else map(_build_one, jobs)
        for i, fresh in enumerate(results):
            made += fresh
            if progress:
                progress(i + 1, len(jobs))
    size = sum(f.stat().st_size for f in folder.rglob("*.png"))
    return {"looks": len(looks), "made": made, "cache": str(folder), "megabytes": size / 2**20}
