"""Many objects, safely: a process pool (or Ray), resume, error isolation, a manifest.

One object is a pure function of ``(category, seed, overrides)``: :func:`make_one`.
:func:`run_batch` maps it over jobs with ``workers`` processes (or on a Ray cluster),
skips objects already complete on disk, removes half-written temporary folders
left by a crash, records a failing object's traceback in ``DIR/errors/`` without
stopping the batch, and keeps ``DIR/manifest.jsonl`` (one row per object).
"""

from __future__ import annotations

import json
import os
import shutil
import sys
import time
import traceback
from collections.abc import Callable, Iterable
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from contextlib import nullcontext
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from tqdm import tqdm

from ._version import __version__

MANIFEST = "manifest.jsonl"
ERRORS = "errors"


@dataclass(frozen=True)
class Job:
    category: str
    seed: int
    overrides: tuple[tuple[str, Any], ...] = ()
    texture_size: int = 512
    formats: tuple[str, ...] = ("usd", "urdf", "mjcf")  # see infmob_usd.layers.FORMATS

    @property
    def name(self) -> str:
        return f"{self.category}_{self.seed:06d}"

    def folder(self, out: Path) -> Path:
        return Path(out) / self.category / self.name


def is_complete(folder: Path) -> bool:
    """An object folder is complete once renamed into place: it always has its metadata (whatever
    formats it holds)."""
    return (folder / "metadata.json").is_file()


def clean_partial(out: Path) -> list[Path]:
    """Remove temporary folders a crashed or interrupted run left behind."""
    removed = []
    for d in Path(out).glob("*/.*.tmp"):
        shutil.rmtree(d, ignore_errors=True)
        removed.append(d)
    for d in Path(out).glob("*/.*.old"):
        shutil.rmtree(d, ignore_errors=True)
    return removed


def make_one(job: Job, out: str) -> dict:
    """Generate and save one object; return its manifest row (or an error row)."""
    from .api import generate, save

    t0 = time.perf_counter()
    try:
        obj = generate(job.category, seed=job.seed, texture_size=job.texture_size, **dict(job.overrides))
        folder = save(obj, Path(out) / job.category, formats=job.formats)
    except Exception as exc:  # one bad object must not stop the batch
        err_dir = Path(out) / ERRORS
        err_dir.mkdir(parents=True, exist_ok=True)
        path = err_dir / f"{job.name}.txt"
        path.write_text(traceback.format_exc())
        return {"category": job.category, "seed": job.seed, "overrides": dict(job.overrides),
                "error": f"{type(exc).__name__}: {exc}", "traceback": os.path.relpath(path, out)}
    movable = [j for j in obj.joints if j.movable]
    kinds = obj.joint_kinds()
    return {
        "category": job.category,
        "seed": job.seed,
        "overrides": dict(job.overrides),
        "folder": os.path.relpath(folder, out),
        "links": sum(1 for link in obj.links if not link.dummy),
        "movable_joints": sum(kinds.values()),
        "simple_movable_joints": len(movable),
        "joint_kinds": kinds,
        "formats": list(job.formats),
        "seconds": {k: round(v, 4) for k, v in obj.timings.items()} | {"total": round(time.perf_counter() - t0, 4)},
        "version": __version__,
    }


def _read_manifest(out: Path) -> dict[tuple[str, int], dict]:
    rows: dict[tuple[str, int], dict] = {}
    path = Path(out) / MANIFEST
    if path.is_file():
        for line in path.read_text().splitlines():
            if line.strip():
                row = json.loads(line)
                rows[(row["category"], row["seed"])] = row
    return rows


def _write_manifest(out: Path, rows: dict[tuple[str, int], dict]) -> None:
    path = Path(out) / MANIFEST
    tmp = path.with_suffix(".jsonl.tmp")
    tmp.write_text("".join(json.dumps(rows[k], sort_keys=True) + "\n" for k in sorted(rows)))
    os.replace(tmp, path)


def run_batch(jobs: Iterable[Job], out: str | Path, workers: int = 1, overwrite: bool = False,
              backend: str = "process", address: str | None = None,
              on_row: Callable[[dict], None] | None = None,
              pool: ProcessPoolExecutor | None = None) -> list[dict]:
    """Generate every job into ``out``; return the rows of this run (errors included).

    Complete objects are skipped (their manifest row kept) unless ``overwrite``.
    ``pool``: an already running executor to use (with ``workers`` its size), e.g.
    one warmed up by a benchmark; by default a pool is started and shut down here.
    """
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    clean_partial(out)
    rows = _read_manifest(out)
    todo = []
    for job in jobs:
        if not overwrite and is_complete(job.folder(out)) and (job.category, job.seed) in rows:
            continue
        todo.append(job)
    # a bar with objects/s and ETA on a terminal; silent when stderr is a file or a pipe
    progress = tqdm(total=len(todo), unit="obj", file=sys.stderr, disable=None, leave=True)
    results: list[dict] = []

    def record(row: dict) -> None:
        results.append(row)
        if "error" not in row:
            rows[(row["category"], row["seed"])] = row
        progress.update()
        if on_row:
            with tqdm.external_write_mode(file=sys.stdout):  # lines print above the bar, not through it
                on_row(row)

    try:
        if backend == "ray":
            _run_ray(todo, str(out), address, record)
        elif workers <= 1 or len(todo) <= 1:
            for job in todo:
                record(make_one(job, str(out)))
        else:
            with (nullcontext(pool) if pool else ProcessPoolExecutor(max_workers=workers)) as pool:
                pending = set()
                it = iter(todo)
                for job in it:  # keep at most 2 jobs per worker in flight: memory stays flat
                    pending.add(pool.submit(make_one, job, str(out)))
                    if len(pending) >= 2 * workers:
                        break
                while pending:
                    done, pending = wait(pending, return_when=FIRST_COMPLETED)
                    for fut in done:
                        record(fut.result())
                        nxt = next(it, None)
                        if nxt is not None:
                            pending.add(pool.submit(make_one, nxt, str(out)))
    finally:
        progress.close()
        _write_manifest(out, rows)
    return results


def _run_ray(todo: list[Job], out: str, address: str | None, record: Callable[[dict], None]) -> None:
    try:
        import ray
    except ImportError:
        raise RuntimeError("the ray backend needs Ray: pip install -e '.[ray]'") from None
    if not ray.is_initialized():
        ray.init(address=address, ignore_reinit_error=True, log_to_driver=False)
    remote = ray.remote(make_one)
    refs = [remote.remote(job, out) for job in todo]
    while refs:
        done, refs = ray.wait(refs, num_returns=1)
        for ref in done:
            record(ray.get(ref))
