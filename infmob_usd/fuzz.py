"""Fuzzing the generator: random (category, seed, overrides) must give a valid object or a clear error.

The property (``infmob fuzz N``, and ``tests/test_fuzz.py`` with hypothesis): for any category,
seed and overrides drawn from the category's schema (extremes included), either the overrides
are rejected up front with a :class:`~infmob_usd.errors.ParameterError` (the schema's own check,
before anything is built), or :func:`~infmob_usd.api.generate` gives an object whose written
folder passes every USD check and, with ``sim``, SAPIEN's ``sapien_load`` and ``reach``. The
mass-range check is left out: it judges the plausibility of the default draws (``validate --sweep``),
and an override may ask for an unusual object on purpose (the deepest pot with the tallest steamer
tier weighs more than any steamer on sale; that is a valid object, not a bug).
Anything else is a *crash* (an exception that is not a ParameterError raised up front) or an
*invalid* object, printed with the command that reproduces it.
"""

from __future__ import annotations

import shutil
import tempfile
import time
import traceback
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path
from typing import Any

import numpy as np

from .errors import ParameterError
from .params import Choice, Flag, Float, Int, Param

__all__ = ["Case", "check_case", "draw_case", "draw_value", "fuzz", "reproduce"]

Case = tuple[str, int, dict[str, Any]]


def draw_value(p: Param, rng: np.random.Generator) -> Any:
    """A valid value of ``p``: often an end of its range (the extremes find the bugs), else random."""
    if isinstance(p, Float):
        r = rng.random()
        return p.low if r < 0.3 else p.high if r < 0.6 else float(p.low + rng.random() * (p.high - p.low))
    if isinstance(p, Int):
        r = rng.random()
        return p.low if r < 0.3 else p.high if r < 0.6 else int(rng.integers(p.low, p.high + 1))
    if isinstance(p, Choice):
        return p.choices[int(rng.integers(len(p.choices)))]
    if isinstance(p, Flag):
        return bool(rng.random() < 0.5)
    raise TypeError(f"unknown parameter kind {type(p).__name__}")


def draw_case(rng: np.random.Generator, categories: list[str]) -> Case:
    """One draw: a category, a seed, and each parameter overridden with probability 0.35."""
    from .api import get_category

    category = categories[int(rng.integers(len(categories)))]
    seed = int(rng.integers(0, 1_000_000))
    schema = get_category(category).schema
    overrides = {p.name: draw_value(p, rng) for p in schema.params if rng.random() < 0.35}
    return category, seed, overrides


def reproduce(case: Case) -> str:
    """The ``infmob generate`` command that makes this case (values written exactly)."""
    category, seed, overrides = case
    sets = " ".join(f"--set {k}={v!r}" if isinstance(v, float) else f"--set {k}={str(v).lower()}"
                    if isinstance(v, bool) else f"--set {k}={v}" for k, v in overrides.items())
    return f"infmob generate {category} --seed {seed} --texture-size 16 {sets}".rstrip()


def check_case(case: Case, texture_size: int = 16, sim: bool = True, keep: Path | None = None,
               tmp_root: Path | None = None) -> dict:
    """Run one case (its object in a temporary folder, inside ``tmp_root`` if given). Returns
    ``{"outcome": "valid" | "rejected" | "crash" | "invalid", "detail", ...}``."""
    from .api import generate, get_category, save
    from .validate import validate_object

    category, seed, overrides = case
    t0 = time.perf_counter()
    try:
        get_category(category).schema.validate(overrides)
    except ParameterError as e:
        return {"outcome": "rejected", "detail": str(e), "seconds": time.perf_counter() - t0}
    tmp = Path(tempfile.mkdtemp(prefix="infmob-fuzz-", dir=tmp_root))
    try:
        try:
            obj = generate(category, seed=seed, texture_size=texture_size, **overrides)
            folder = save(obj, tmp)
        except Exception as e:  # noqa: BLE001 - the property: nothing but a ParameterError up front
            tb = traceback.extract_tb(e.__traceback__)[-1]
            return {"outcome": "crash", "seconds": time.perf_counter() - t0,
                    "detail": f"{type(e).__name__}: {' '.join(str(e).split())[:300]}"
                              f" ({Path(tb.filename).name}:{tb.lineno})"}
        report = validate_object(folder, sim=sim, mass=False)
        if report.ok:
            return {"outcome": "valid", "detail": "", "seconds": time.perf_counter() - t0}
        if keep is not None:
            keep.mkdir(parents=True, exist_ok=True)
            shutil.copytree(folder, keep / folder.name, dirs_exist_ok=True)
        detail = "; ".join(f"{c.name}: {c.detail}" for c in report.failed)
        return {"outcome": "invalid", "detail": detail[:600], "seconds": time.perf_counter() - t0}
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def _run(args) -> dict:
    case, texture_size, sim, keep, tmp_root = args
    return check_case(case, texture_size, sim, keep, tmp_root)


def _init_worker() -> None:
    from .batch import _die_with_parent

    _die_with_parent()


def _in_pools(cases: list[Case], workers: int, settings: tuple, note) -> None:
    """Every case on a pool of ``workers``; a worker that dies counts its case as a crash and a fresh pool
    goes on. The workers' temporary folders are made inside one of this process, removed at the end, and
    on SIGTERM or Ctrl-C the workers are stopped at once (the queued cases are not run)."""
    from .batch import _stop_pool

    run_tmp = Path(tempfile.mkdtemp(prefix="infmob-fuzz-run-"))
    i, n = 0, len(cases)
    try:
        while i < n:
            pool = ProcessPoolExecutor(max_workers=min(workers, n - i), initializer=_init_worker)
            try:
                futures = [pool.submit(_run, (case, *settings, run_tmp)) for case in cases[i:]]
                for fut in futures:
                    try:
                        res = fut.result()
                    except Exception as e:  # noqa: BLE001 - BrokenProcessPool: a worker died
                        note(i, cases[i], {"outcome": "crash", "detail": f"worker died: {type(e).__name__}: {e}"})
                        i += 1
                        break
                    note(i, cases[i], res)
                    i += 1
            except BaseException:
                _stop_pool(pool)
                raise
            pool.shutdown(wait=True)
    finally:
        shutil.rmtree(run_tmp, ignore_errors=True)


def fuzz(n: int, seed: int = 0, workers: int = 1, categories: list[str] | None = None, out: Path | None = None,
         sim: bool = True, texture_size: int = 16, stream=None) -> dict:
    """Run ``n`` draws (seeded by ``seed``) on ``workers`` processes; print failures to ``stream``.

    Returns ``{"draws", "valid", "rejected", "crashes", "invalid", "seconds", "failures"}``.
    A worker that dies (a native crash) counts its case as a crash; a fresh pool goes on.
    """
    from .api import list_categories

    categories = categories or list_categories()
    rng = np.random.default_rng(np.random.SeedSequence((seed, 0x0F022)))
    cases = [draw_case(rng, categories) for _ in range(n)]
    counts = {"valid": 0, "rejected": 0, "crash": 0, "invalid": 0}
    failures = []
    t0 = time.perf_counter()
    step = max(1, n // 20)

    def note(i: int, case: Case, res: dict) -> None:
        counts[res["outcome"]] += 1
        if res["outcome"] in ("crash", "invalid"):
            failures.append({"case": list(case), "outcome": res["outcome"], "detail": res["detail"]})
            if stream:
                print(f"{res['outcome'].upper()} #{i}: {reproduce(case)}\n    {res['detail']}", file=stream,
                      flush=True)
        done = sum(counts.values())
        if stream and (done % step == 0 or done == n):
            print(f"[{done}/{n}] valid {counts['valid']}, rejected {counts['rejected']}, crashes {counts['crash']},"
                  f" invalid {counts['invalid']}  ({time.perf_counter() - t0:.0f} s)", file=stream, flush=True)

    if workers <= 1:
        for i, case in enumerate(cases):
            note(i, case, check_case(case, texture_size, sim, out))
    else:
        _in_pools(cases, workers, (texture_size, sim, out), note)
    seconds = time.perf_counter() - t0
    res = {"draws": n, "valid": counts["valid"], "rejected": counts["rejected"], "crashes": counts["crash"],
           "invalid": counts["invalid"], "seconds": round(seconds, 1), "failures": failures}
    if stream:
        print(f"\n{n} draws in {seconds:.0f} s: {counts['valid']} valid objects, {counts['rejected']} rejected up"
              f" front (ParameterError), {counts['crash']} crashes, {counts['invalid']} invalid", file=stream)
    return res
