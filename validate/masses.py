"""The ``mass`` check: whole-object and moving-part masses within the ranges of real products.

:data:`TABLE` (``mass_ranges.csv`` beside this module) holds, per category, a plausible mass range
of the whole object (part ``*``) and of each kind of moving part (a link label: ``leaf``,
``drawer``, ``knob`` ...), each row with its source; a row of category ``*`` holds for every
category that has no row of its own for that label.

:func:`check_mass` reads a written object: link masses from the URDF's ``<inertial>`` (what a
simulator uses; from ``metadata.json`` where the folder has no URDF), labels, dummy flags and joints
from ``metadata.json``. A moving part is a non-dummy link that is the child of a movable joint. The
object fails when its total mass or a moving part's mass is outside its range, or when the category
has no whole-object row or a moving part's label has no row (add one, with its source): a new
category is held to real products from its first validation, not waved through.
"""

from __future__ import annotations

import csv
import functools
from dataclasses import dataclass
from pathlib import Path

from .files import load_metadata, object_files, parse_urdf
from .result import CheckResult

TABLE = Path(__file__).with_name("mass_ranges.csv")
WHOLE = "*"
ANY = "*"


@dataclass(frozen=True)
class MassRange:
    category: str
    part: str
    lo: float
    hi: float
    source: str

    def holds(self, kg: float) -> bool:
        return self.lo <= kg <= self.hi


@functools.lru_cache(maxsize=4)
def load_table(path: str | Path = TABLE) -> dict[tuple[str, str], MassRange]:
    """``{(category, part): MassRange}`` from the CSV (``#`` lines are comments).

    Raises ValueError on a malformed row (a range that is empty or negative, no source, a duplicate)."""
    path = Path(path)
    lines = [ln for ln in path.read_text().splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    table: dict[tuple[str, str], MassRange] = {}
    for i, row in enumerate(csv.DictReader(lines), start=2):
        try:
            r = MassRange(row["category"].strip(), row["part"].strip(), float(row["min_kg"]),
                          float(row["max_kg"]), (row["source"] or "").strip())
        except (KeyError, TypeError, ValueError) as exc:
            raise ValueError(f"{path.name} row {i}: {exc}") from None
        if not (0 <= r.lo < r.hi) or not r.source or not r.category or not r.part:
            raise ValueError(f"{path.name} row {i}: want 0 <= min_kg < max_kg, a category, a part and a source")
        if (r.category, r.part) in table:
            raise ValueError(f"{path.name} row {i}: a second row for {r.category}/{r.part}")
        table[(r.category, r.part)] = r
    return table


def range_for(category: str, part: str, table: dict | None = None) -> MassRange | None:
    """The row for ``part`` (a link label, or ``*`` for the whole object) of ``category``:
    the category's own row, else the row of category ``*`` (never for the whole object)."""
    table = load_table() if table is None else table
    own = table.get((category, part))
    if own is not None or part == WHOLE:
        return own
    return table.get((ANY, part))


def object_masses(folder: Path) -> tuple[str, float, list[tuple[str, str, float]]]:
    """``(category, total kg, [(link, label, kg) of each moving part])`` of a written object."""
    folder = Path(folder)
    meta = load_metadata(folder)
    masses = {ln["name"]: float(ln["mass"]) for ln in meta["links"]}
    _usd, urdf = object_files(folder, meta)
    if urdf.is_file():
        written = {n: link.mass for n, link in parse_urdf(urdf).links.items() if link.mass is not None}
        masses.update(written)
    movers = {j["child"] for j in meta["joints"] if j["type"] != "fixed"}
    moving = [(ln["name"], ln["label"], masses[ln["name"]]) for ln in meta["links"]
              if ln["name"] in movers and not ln.get("dummy")]
    return str(meta["category"]), float(sum(masses.values())), moving


def check_mass(folder: Path, table: dict | None = None) -> CheckResult:
    """``mass``: the object's total and every moving part's mass within :data:`TABLE` (module docstring)."""
    table = load_table() if table is None else table
    category, total, moving = object_masses(folder)
    problems = []
    whole = range_for(category, WHOLE, table)
    if whole is None:
        problems.append(f"no range for category {category!r} in {TABLE.name} (total {total:.3g} kg): add a row"
                        f" {category},*,MIN_KG,MAX_KG,SOURCE")
    elif not whole.holds(total):
        problems.append(f"total {total:.3g} kg outside {whole.lo:g}-{whole.hi:g} kg")
    heaviest: dict[str, float] = {}
    for name, label, kg in moving:
        r = range_for(category, label, table)
        if r is None:
            problems.append(f"no range for moving part {label!r} ({name}) in {TABLE.name}")
        elif not r.holds(kg):
            problems.append(f"{name} ({label}) {kg:.3g} kg outside {r.lo:g}-{r.hi:g} kg")
        heaviest[label] = max(kg, heaviest.get(label, 0.0))
    if problems:
        more = f" (+{len(problems) - 4} more)" if len(problems) > 4 else ""
        return CheckResult("mass", False, "; ".join(problems[:4]) + more)
    parts = ", ".join(f"{lab} {kg:.3g}" for lab, kg in sorted(heaviest.items()))
    heavy = f"; heaviest moving parts (kg): {parts}" if parts else ""
    return CheckResult("mass", True, f"total {total:.3g} kg" + heavy)
