"""Summaries of many validated objects: a pass-count table and a JSON report.

Both take ``rows``: one entry per object, ``(category, results)`` or
``(category, results, object_name)``, ``results`` a list of :class:`CheckResult` (any mix of
USD, SAPIEN, ManiSkill and geometric checks). Check names are listed in the order they first
appear; a check an object did not run counts neither as passed nor in its total.
"""

from __future__ import annotations

import re
import statistics
from collections.abc import Sequence
from typing import Any

from .result import CheckResult

__all__ = ["report_json", "summary_table"]

_SECONDS = re.compile(r"\[(\d+(?:\.\d+)?) s\]\s*$")
ALL = "all"


def _rows(rows: Sequence[tuple]) -> list[tuple[str, list[CheckResult], str]]:
    out = []
    for i, row in enumerate(rows):
        if len(row) == 2:
            category, results = row
            name = f"{category}#{i}"
        elif len(row) == 3:
            category, results, name = row
            name = str(name)
        else:
            raise ValueError(f"row {i}: want (category, results) or (category, results, name)")
        out.append((str(category), list(results), name))
    return out


def _order(items) -> list[str]:
    return list(dict.fromkeys(items))


def seconds(result: CheckResult) -> float | None:
    """The run time a check appended to its detail (``... [0.12 s]``), if any."""
    m = _SECONDS.search(result.detail or "")
    return float(m.group(1)) if m else None


def _counts(rows, category: str | None) -> tuple[dict[str, list[int]], list[int]]:
    """Per check ``[passed, total]`` and per object ``[all passed, objects]``."""
    per_check: dict[str, list[int]] = {}
    objects = [0, 0]
    for cat, results, _name in rows:
        if category is not None and cat != category:
            continue
        objects[1] += 1
        objects[0] += bool(results) and all(r.ok for r in results)
        for r in results:
            c = per_check.setdefault(r.name, [0, 0])
            c[0] += bool(r.ok)
            c[1] += 1
    return per_check, objects


def summary_table(rows: Sequence[tuple]) -> str:
    """A fixed-width table of ``passed/total`` per check (rows) and per category (columns).

    The last column sums all categories; the last row counts objects that passed every check.
    Example::

        check           kitchen_cabinet  microwave  all
        sapien_load     10/10            10/10      20/20
        self_collision  4/10             10/10      14/20
        all checks      4/10             10/10      14/20
    """
    rows = _rows(rows)
    categories = _order(cat for cat, _r, _n in rows)
    checks = _order(r.name for _c, results, _n in rows for r in results)
    columns = [*categories, ALL]
    table = [["check", *columns]]
    counts = {c: _counts(rows, None if c == ALL else c) for c in columns}
    for name in checks:
        cells = []
        for c in columns:
            passed, total = counts[c][0].get(name, [0, 0])
            cells.append(f"{passed}/{total}" if total else "-")
        table.append([name, *cells])
    table.append(["all checks", *(f"{counts[c][1][0]}/{counts[c][1][1]}" for c in columns)])
    widths = [max(len(r[i]) for r in table) for i in range(len(table[0]))]
    lines = ["  ".join(cell.ljust(w) for cell, w in zip(r, widths)).rstrip() for r in table]
    failed = [f"{n}: {r.name}" for _c, results, n in rows for r in results if not r.ok]
    if failed:
        lines.append(f"{len(failed)} failed checks: " + "; ".join(failed[:10])
                     + (f" (+{len(failed) - 10} more)" if len(failed) > 10 else ""))
    return "\n".join(lines)


def _check_stats(rows, category: str | None) -> dict[str, dict[str, Any]]:
    per_check, _ = _counts(rows, category)
    times: dict[str, list[float]] = {}
    for cat, results, _n in rows:
        if category is not None and cat != category:
            continue
        for r in results:
            s = seconds(r)
            if s is not None:
                times.setdefault(r.name, []).append(s)
    out = {}
    for name, (passed, total) in per_check.items():
        entry: dict[str, Any] = {"passed": passed, "total": total}
        if name in times:
            entry["seconds"] = {"median": statistics.median(times[name]), "max": max(times[name])}
        out[name] = entry
    return out


def report_json(rows: Sequence[tuple]) -> dict:
    """A JSON-ready report (for ``infmob validate --report FILE``).

    Returns
    -------
    dict
        ``objects`` and ``passed`` (objects passing every check); ``checks``: per check
        ``passed``, ``total`` and, where the details carry times, ``seconds`` (median, max);
        ``categories``: the same per category with its own ``objects`` and ``passed``;
        ``results``: per object its category, name, ``ok`` and every check (name, ok, detail,
        seconds); ``failures``: every failed check as (category, object, check, detail).
    """
    rows = _rows(rows)
    _, objects = _counts(rows, None)
    categories = {}
    for cat in _order(c for c, _r, _n in rows):
        _, cat_objects = _counts(rows, cat)
        categories[cat] = {"objects": cat_objects[1], "passed": cat_objects[0],
                           "checks": _check_stats(rows, cat)}
    results = []
    failures = []
    for cat, checks, name in rows:
        results.append({
            "category": cat,
            "object": name,
            "ok": bool(checks) and all(r.ok for r in checks),
            "checks": [{"name": r.name, "ok": bool(r.ok), "detail": r.detail, "seconds": seconds(r)}
                       for r in checks],
        })
        failures += [{"category": cat, "object": name, "check": r.name, "detail": r.detail}
                     for r in checks if not r.ok]
    return {
        "objects": objects[1],
        "passed": objects[0],
        "checks": _check_stats(rows, None),
        "categories": categories,
        "results": results,
        "failures": failures,
    }
