"""Exporting a whole folder of objects: ids, the pool, resume, nothing half-written.

``export(FORMAT, SRC, OUT)`` streams SRC's object folders (found without following links) through a
process pool. Each object is written under a temporary name and renamed into place, and a row is
appended (and ``fsync``\\ ed) to ``OUT/export.jsonl``; a killed run resumes where it stopped, and a
folder without its row is redone. Ids are numeric and kept in ``OUT/ids.jsonl`` (one per source
folder, assigned in sorted order, never reused), so resuming or adding objects never renumbers.
At the end come the splits and ``DATASET.md`` (:mod:`.card`), computed from the rows by streaming.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from collections.abc import Callable, Iterator
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from pathlib import Path

from infmob_usd.batch import (
    _PARENT_FDS,
    OutputLock,
    _die_with_parent,
    _remove_temporaries,
    _stop_pool,
    clean_partial,
    progress_bar,
)
from infmob_usd.layers import check_output_dir
from infmob_usd.runs import new_run_id, temp_prefix

from .source import ExportError, find_sources, read_source

FORMATS = ("partnet-mobility", "gapartnet", "cage")
FIRST_ID = 200000  # above PartNet-Mobility's ids (< 105000), so the two can share a folder
IDS = "ids.jsonl"
ROWS = "export.jsonl"


def object_dir(fmt: str, out: Path, obj_id: int, category: str) -> Path:
    """Where one object goes: ``OUT/<id>`` (PartNet-Mobility, GAPartNet) or ``OUT/<Cat>/<id>`` (CAGE)."""
    if fmt == "cage":
        from .partnet import pm_category

        return out / pm_category(category) / str(obj_id)
    return out / str(obj_id)


def export_one(fmt: str, src_root: str, rel: str, obj_id: int, out: str, run_id: str) -> dict:
    """Export one source object (in a pool worker): write it under a temporary name beside its
    final folder, then rename it into place. Returns its row."""
    from .layout import write_object

    src = read_source(Path(src_root) / rel)
    final = object_dir(fmt, Path(out), obj_id, src.category)
    parent = check_output_dir(final.parent)
    prefix = temp_prefix(str(obj_id), run_id)
    tmp = Path(tempfile.mkdtemp(prefix=prefix, suffix=".tmp", dir=parent))
    try:
        row = write_object(fmt, src, obj_id, tmp, rel)
        os.chmod(tmp, 0o755)
        if final.exists() or final.is_symlink():
            if final.is_symlink() or not final.is_dir():
                raise ExportError(f"{final} exists and is not an exported object folder; remove it")
            old = Path(tempfile.mkdtemp(prefix=prefix, suffix=".old", dir=parent))
            os.replace(final, old / "x")
            os.replace(tmp, final)
            shutil.rmtree(old, ignore_errors=True)
        else:
            os.replace(tmp, final)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return row


def _read_jsonl(path: Path, what: str) -> Iterator[dict]:
    if os.path.islink(path):
        raise ExportError(f"{path} is a symbolic link; export never writes through a link: remove it")
    if not path.exists():
        return
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            if not line.strip():
                continue
            try:
                row = json.loads(line)
            except json.JSONDecodeError:
                if not line.endswith("\n"):  # a run killed mid-line: the object is redone
                    return
                raise ExportError(f"{path} line {n} is not JSON; it is not an export's {what}:"
                                  f" choose another --out") from None
            if not isinstance(row, dict):
                raise ExportError(f"{path} line {n} is not an object; choose another --out")
            yield row


def _write_atomic(path: Path, text: str) -> None:
    if os.path.islink(path):
        raise ExportError(f"{path} is a symbolic link; export never writes through a link: remove it")
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".part", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def assign_ids(out: Path, rels: list[str], first_id: int) -> dict[str, int]:
    """Source folder -> id: those in ``OUT/ids.jsonl`` kept, new ones numbered after the largest."""
    ids: dict[str, int] = {}
    for row in _read_jsonl(out / IDS, "id list"):
        if not isinstance(row.get("source"), str) or not isinstance(row.get("id"), int):
            raise ExportError(f"{out / IDS} has a row without source/id; choose another --out")
        ids[row["source"]] = row["id"]
    if len(set(ids.values())) != len(ids):
        raise ExportError(f"{out / IDS} gives one id to two objects; choose another --out")
    nxt = max([first_id - 1, *ids.values()]) + 1
    new = [r for r in rels if r not in ids]
    for r in new:
        ids[r] = nxt
        nxt += 1
    if new or not (out / IDS).exists():
        _write_atomic(out / IDS, "".join(json.dumps({"id": i, "source": s}) + "\n" for s, i in ids.items()))
    return ids


def check_paths(src: Path, out: Path) -> None:
    """Refuse an OUT inside SRC (or equal to it): export never writes into its input."""
    rs, ro = os.path.realpath(src), os.path.realpath(out)
    if ro == rs or ro.startswith(rs.rstrip(os.sep) + os.sep):
        raise ExportError(f"--out {str(out)!r} is inside SRC {str(src)!r}; export never writes into its input:"
                          f" choose an --out elsewhere")


def _pool_map(todo, work: Callable, workers: int, record: Callable[[dict], None]) -> None:
    """Run ``work(*args)`` for each args of ``todo`` (at most ``2 * workers`` in flight: bounded memory)."""
    if workers <= 1:
        for args in todo:
            record(work(*args))
        return
    # workers drop the run's lock and row descriptors and die with the run (as `generate`'s pool does)
    pool = ProcessPoolExecutor(max_workers=workers, initializer=_die_with_parent)
    pending = set()
    try:
        for args in todo:
            pending.add(pool.submit(work, *args))
            if len(pending) >= 2 * workers:
                done, pending = wait(pending, return_when=FIRST_COMPLETED)
                for f in done:
                    record(f.result())
        for f in pending:
            record(f.result())
    except BaseException:
        _stop_pool(pool)
        raise
    pool.shutdown()


def _open_rows(out: Path, overwrite: bool) -> tuple[set[str], int]:
    """The sources already exported and the row file open for appending (a line cut by a killed run
    is dropped first, so the next row starts on its own line)."""
    done = set() if overwrite else {r["source"] for r in _read_jsonl(out / ROWS, "row list") if "source" in r}
    if overwrite and (out / ROWS).exists():
        _write_atomic(out / ROWS, "")
    fd = os.open(out / ROWS, os.O_RDWR | os.O_CREAT | os.O_APPEND | os.O_NOFOLLOW | os.O_CLOEXEC, 0o644)
    size = os.fstat(fd).st_size
    if size and os.pread(fd, 1, size - 1) != b"\n":
        data = os.pread(fd, size, 0)
        os.ftruncate(fd, data.rfind(b"\n") + 1)
    return done, fd


def _write_files(out: Path, files: dict[str, str]) -> None:
    """Write ``{relative name: text}`` under ``out``, each atomically, through no link."""
    for name, text in files.items():
        path = out
        for part in Path(name).parts[:-1]:
            path = path / part
            if path.is_symlink():
                raise ExportError(f"{path} is a symbolic link; export never writes through a link: remove it")
            path.mkdir(exist_ok=True)
        _write_atomic(out / name, text)


def _finish(fmt: str, out: Path, rels: list[str], fractions: dict[str, float], seed: int, command: str) -> dict:
    """Splits, ManiSkill's lists and DATASET.md from the rows of the objects now in SRC."""
    from . import card

    wanted, rows = set(rels), {}
    for row in _read_jsonl(out / ROWS, "row list"):
        if row.get("source") in wanted:
            rows[row["source"]] = row
    rows = [rows[r] for r in rels if r in rows]
    splits = card.assign_splits(rows, fractions, seed) if fractions else {}
    files = card.split_files(fmt, rows, splits, fractions)
    if fmt != "cage":
        for name, data in card.maniskill_meta(rows, splits).items():
            files[f"maniskill/partnet_mobility/meta/{name}"] = json.dumps(data, indent=1) + "\n"
    files["DATASET.md"] = card.card(fmt, rows, splits, fractions, seed, command)
    _write_files(out, files)
    return {"objects": len(rows), "splits": {k: sum(1 for v in splits.values() if v == k) for k in fractions}}


def export(fmt: str, src: str | Path, out: str | Path, *, split: str | dict | None = None, seed: int = 0,
           workers: int = 1, overwrite: bool = False, first_id: int = FIRST_ID, command: str | None = None,
           wait_lock: bool = False) -> dict:
    """Export every object folder under ``src`` to ``out`` in ``fmt`` (one of :data:`FORMATS`).

    Resumes: objects already exported (row in ``OUT/export.jsonl``) are skipped unless ``overwrite``.
    ``split``: ``"train=0.8,val=0.1,test=0.1"`` (or a dict), decided per category by ``seed``.
    Returns ``{"objects": N, "exported": M, "splits": {...}}``.

    Raises
    ------
    ExportError
        A bad format or split, a SRC that is not a folder of objects, an OUT inside SRC, or a source
        object that is malformed or unsafe (the objects before it stay exported; run again to resume).
    OutputError
        OUT cannot be written, is a link, or another run holds it.
    """
    if fmt not in FORMATS:
        raise ExportError(f"unknown export format {fmt!r}; choose one of {', '.join(FORMATS)}")
    from .card import parse_split

    fractions = parse_split(split)
    src, out = Path(src), Path(out)
    rels = find_sources(src)
    if not rels:
        raise ExportError(f"SRC {str(src)!r} holds no object folders (with metadata.json); make some with"
                          f" `infmob generate CATEGORY --out {src}`")
    check_paths(src, out)
    out = check_output_dir(out)
    command = command or "infmob_usd.export(" + ", ".join(map(repr, (fmt, str(src), str(out)))) + ")"
    with OutputLock(out, wait=wait_lock):
        clean_partial(out)
        for row in _read_jsonl(out / ROWS, "row list"):
            if row.get("format") not in (None, fmt):
                raise ExportError(f"--out {str(out)!r} holds a {row.get('format')} export; choose another --out")
            break
        ids = assign_ids(out, rels, first_id)
        done, fd = _open_rows(out, overwrite)
        _PARENT_FDS.add(fd)
        todo = [r for r in rels if r not in done]
        bar = progress_bar(len(todo))

        def record(row: dict) -> None:
            os.write(fd, (json.dumps(row) + "\n").encode())
            os.fsync(fd)
            bar.update(1)

        run_id = new_run_id()
        try:
            _pool_map(((fmt, str(src), r, ids[r], str(out), run_id) for r in todo), export_one, workers, record)
        except BaseException:  # the workers are stopped: what they were writing is this run's, half-written
            pid, token = run_id.split("-")
            _remove_temporaries(out, lambda m: m["pid"] == pid and m["token"] == token)
            raise
        finally:
            _PARENT_FDS.discard(fd)
            os.close(fd)
            bar.close()
        summary = _finish(fmt, out, rels, fractions, seed, command)
    return {**summary, "exported": len(todo)}
