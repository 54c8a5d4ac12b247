"""``infmob bench``: how fast and how lean generation is, measured, never assumed.

The bench runs against its own, initially empty texture cache (a temporary
``INFMOB_USD_CACHE``).  First it builds the texture library (every look's PNG
maps, made once per dataset and reused by every object; see
:mod:`infmob_usd.materials.cache`) with N workers and reports that one-off cost.
Then, for each category, ``count`` objects (seeds 0..count-1) are generated and saved
once in this process to warm up, then timed per stage (``sampling``,
``geometry``, ``textures`` (the maps of the object's looks, from the library),
``textures_io`` (writing them), ``usd``, ``urdf`` (with the OBJ meshes), ``mjcf`` (the XML; it shares the
URDF's meshes), ``metadata``, ``total``). Throughput is measured by
generating the whole set with 1 worker and with N workers (process pool), giving
objects/s and parallel efficiency = rate(N) / (N * rate(1)); both pools are warmed up first
(every worker has imported everything and made one object of each category), so the figures are
steady-state throughput, as in a long dataset run. Peak memory is the
maximum resident set size of a worker process (``ru_maxrss`` of the children).

With ``cold=True`` (``infmob bench --cold``) no library is built and every timed object starts
from an empty cache, on disk and in memory: the ``textures`` stage then synthesizes and encodes
every map the object uses (what the first object of a new look costs); the throughput runs are
skipped.
"""

from __future__ import annotations

import os
import resource
import shutil
import statistics
import tempfile
import time
from pathlib import Path

STAGES = ("sampling", "geometry", "textures", "textures_io", "usd", "urdf", "mjcf", "metadata", "total")


def _stage_times(categories, count, texture_size, tmp: Path, cold: bool = False) -> dict[str, dict[str, float]]:
    from infmob_usd.api import generate, save
    from infmob_usd.materials.cache import forget

    per: dict[str, dict[str, list[float]]] = {}
    for c in categories:  # warm-up: imports, caches
        save(generate(c, seed=10_000, texture_size=texture_size), tmp / "warm")
    per["_rss_mb"] = {"after_warmup": [resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024]}
    for c in categories:
        rows = per.setdefault(c, {s: [] for s in STAGES})
        for seed in range(count):
            if cold:  # an empty cache folder (read through the variable at each use) and memory
                os.environ["INFMOB_USD_CACHE"] = str(tmp / "cold" / f"{c}_{seed}")
                forget()
            t0 = time.perf_counter()
            obj = generate(c, seed=seed, texture_size=texture_size)
            save(obj, tmp / "serial")
            total = time.perf_counter() - t0
            for s in STAGES[:-1]:
                rows[s].append(obj.timings.get(s, 0.0))
            rows["total"].append(total)
    per["_rss_mb"]["after_all"] = [resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024]
    return {c: {s: statistics.median(v) for s, v in rows.items()} for c, rows in per.items()}


def _throughput(categories, count, texture_size, workers, tmp: Path) -> float:
    """Objects/s of a warmed-up pool of ``workers`` (start-up, imports and caches excluded)."""
    from concurrent.futures import ProcessPoolExecutor

    from infmob_usd.batch import Job, run_batch

    jobs = [Job(c, s, (), texture_size) for c in categories for s in range(count)]
    warm = [Job(c, 10_000 + w, (), texture_size) for w in range(workers) for c in categories]
    out = tmp / f"w{workers}"
    with ProcessPoolExecutor(max_workers=workers) as pool:
        run_batch(warm, tmp / f"warm{workers}", workers=workers, overwrite=True, pool=pool)
        t0 = time.perf_counter()
        rows = run_batch(jobs, out, workers=workers, overwrite=True, pool=pool)
        dt = time.perf_counter() - t0
    errors = [r for r in rows if "error" in r]
    if errors:
        raise RuntimeError(f"{len(errors)} objects failed during the benchmark: {errors[0]['error']}")
    return len(jobs) / dt


def _library(texture_size: int, workers: int) -> dict:
    """Build the whole texture library into the (empty) bench cache with ``workers`` processes."""
    from infmob_usd.materials.cache import build

    t0 = time.perf_counter()
    res = build(texture_size, None, workers)
    dt = time.perf_counter() - t0
    return {"looks": res["looks"], "seconds": dt, "workers": workers,
            "seconds_per_look_per_core": dt * workers / res["looks"], "megabytes": res["megabytes"]}


def run_bench(categories, count: int = 10, texture_size: int = 512, workers: int = 2, cold: bool = False) -> dict:
    tmp = Path(tempfile.mkdtemp(prefix="infmob-bench-"))
    saved = os.environ.get("INFMOB_USD_CACHE")
    os.environ["INFMOB_USD_CACHE"] = str(tmp / "cache")  # inherited by every worker started below
    rate1 = rate_n = None
    try:
        library = None if cold else _library(texture_size, workers)
        stages = _stage_times(categories, count, texture_size, tmp, cold)
        rss = stages.pop("_rss_mb")
        if not cold:
            rate1 = _throughput(categories, count, texture_size, 1, tmp)
            rate_n = _throughput(categories, count, texture_size, workers, tmp) if workers > 1 else rate1
        peak_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
        self_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    finally:
        if saved is None:
            os.environ.pop("INFMOB_USD_CACHE", None)
        else:
            os.environ["INFMOB_USD_CACHE"] = saved
        shutil.rmtree(tmp, ignore_errors=True)
    overall = {s: statistics.median([stages[c][s] for c in stages]) for s in STAGES}
    return {
        "count_per_category": count,
        "texture_size": texture_size,
        "cold_cache": cold,
        "workers": workers,
        "texture_library": library,
        "median_seconds": stages,
        "median_of_category_medians": overall,
        "objects_per_s_1_worker": rate1,
        f"objects_per_s_{workers}_workers": rate_n,
        "parallel_efficiency": None if cold else rate_n / (workers * rate1),
        "peak_rss_mb_worker": peak_mb,
        "peak_rss_mb_main": self_mb,
        "rss_mb_main_after_warmup": rss["after_warmup"],
        "rss_mb_main_after_all": rss["after_all"],
    }


def format_bench(res: dict) -> str:
    head = f"{'category':<20}" + "".join(f"{s:>12}" for s in STAGES)
    lib = res["texture_library"]
    if lib is None:
        lines = ["cold texture cache: no library; every timed object starts from an empty cache (disk and"
                 " memory), so `textures` makes all of its maps", ""]
    else:
        lines = [f"texture library (once per dataset and texture size, then reused): {lib['looks']} looks in"
                 f" {lib['seconds']:.1f} s with {lib['workers']} workers = {lib['seconds_per_look_per_core']:.3f} s"
                 f" per look per core, {lib['megabytes']:.0f} MB; over a 10,000-object dataset"
                 f" {lib['seconds'] * lib['workers'] / 10_000:.4f} s per object per core", ""]
    lines += [f"median seconds per object per core (texture {res['texture_size']} px,"
              f" {res['count_per_category']} objects per category{', cold cache' if lib is None else ''})",
              head, "-" * len(head)]
    for c, row in res["median_seconds"].items():
        lines.append(f"{c:<20}" + "".join(f"{row[s]:>12.4f}" for s in STAGES))
    lines.append("-" * len(head))
    lines.append(f"{'median':<20}" + "".join(f"{res['median_of_category_medians'][s]:>12.4f}" for s in STAGES))
    w = res["workers"]
    lines.append("")
    if res["objects_per_s_1_worker"] is None:  # cold: no pool ran
        lines.append(f"peak memory: main {res['peak_rss_mb_main']:.0f} MB")
    else:
        lines.append(f"objects/s, 1 worker:   {res['objects_per_s_1_worker']:.2f}")
        if w > 1:
            lines += [f"objects/s, {w} workers:  {res[f'objects_per_s_{w}_workers']:.2f}",
                      f"parallel efficiency:   {100 * res['parallel_efficiency']:.0f}%"]
        lines.append(f"peak memory: worker {res['peak_rss_mb_worker']:.0f} MB, main {res['peak_rss_mb_main']:.0f} MB")
    lines += [
        f"main process peak RSS after warm-up {res['rss_mb_main_after_warmup']:.0f} MB, after all"
        f" {len(res['median_seconds']) * res['count_per_category']} objects {res['rss_mb_main_after_all']:.0f} MB"
        " (flat = no growth with object count)",
        "reference method (Infinite Mobility, Blender): 0.46 s per object",
    ]
    return "\n".join(lines)
