"""The tools of ``infmob parts`` that use the project's procedural parts: the built-in library
(``export-builtin``) and the study behind ``check`` (library parts placed on procedural targets of
drawn real sizes, by bounding box and by support points: gap, penetration and lateral offset at each
foot).

An entry point beside the command line (tests/test_layering.py's ``TOP``): it builds parts from
``categories/parts``, which the core modules :mod:`.partlib` and :mod:`.retrieval` must not import.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .partlib import Entry, write_library
from .retrieval import FIT_ANCHOR, bbox_fit, candidates, part_frame, support_fit


def builtin_entries() -> list[Entry]:
    """The procedural handles (bar, edge and bow pulls), knobs, table legs and caster wheels of
    ``categories/parts`` as library parts (in their part frames), with their exact convex pieces."""
    import trimesh

    from .categories.parts import doors, hardware, seating, tables
    from .categories.parts import vessel as V

    made = {
        "builtin_bar_160": hardware.bar_handle(0.16, "main"),
        "builtin_bar_320": hardware.bar_handle(0.32, "main"),
        "builtin_edge_200": hardware.edge_pull(0.20, "main"),
        "builtin_bow_128": hardware.bow_handle(0.128, "main"),
        "builtin_knob_30": hardware.knob_handle(0.015, 0.025, "main"),
        "builtin_lid_knob_20": V.lid_knob(0.02, "main"),
        "builtin_door_knob_28": doors.knob_part(0.028),
        "builtin_leg_turned_400": tables.leg_part("turned", 0.022, 0.40, "main"),
        "builtin_leg_turned_720": tables.leg_part("turned", 0.035, 0.72, "main", kind="dining"),
        "builtin_leg_tapered_720": tables.leg_part("tapered", 0.035, 0.72, "main", kind="dining"),
        "builtin_wheel_single_60": seating.wheels(seating.caster("single", 0.03))[0],
        "builtin_wheel_twin_50": seating.wheels(seating.caster("twin", 0.025))[0],
    }
    out = []
    for pid, asm in made.items():
        frame = asm.anchors.get(FIT_ANCHOR)
        if frame is not None:  # built in another frame (a wheel under its leg tip): into its part frame
            asm = asm.placed(frame.inverse())
        pieces = asm.pieces
        mesh = trimesh.util.concatenate([trimesh.Trimesh(p.vertices, p.faces, process=False) for p in pieces])
        convex = []
        for p in pieces:
            for hv, _hf in p.hulls():
                convex.append(np.asarray(hv, float))
        sup = {k: np.asarray(v, float) for k, v in asm.supports.items()}
        out.append(Entry(asm.parts[asm.root].label, pid, "builtin infmob_usd categories/parts", "Apache-2.0",
                         np.asarray(mesh.vertices, float), np.asarray(mesh.faces, np.int64), sup, convex,
                         bool(mesh.is_watertight), "exported from the procedural part"))
    return out


def export_builtin(out) -> Path:
    return write_library(builtin_entries(), Path(out))

def targets_for(kind: frozenset, rng: np.random.Generator):
    """A procedural part of a kind at a drawn real size (the ranges the categories use)."""
    from .categories.parts import hardware, seating, tables
    from .categories.parts import vessel as V

    if kind == frozenset({"top", "foot"}):  # coffee-table legs (0.3-0.7 m) or dining-table legs
        style = ("turned", "tapered", "square")[int(rng.integers(3))]
        if rng.random() < 0.5:
            return tables.leg_part(style, float(rng.uniform(0.015, 0.03)), float(rng.uniform(0.3, 0.7)), "m")
        return tables.leg_part(style, float(rng.uniform(0.025, 0.045)), float(rng.uniform(0.62, 0.78)), "m",
                               kind="dining")
    if kind == frozenset({"axle_a", "axle_b"}):  # chair and table caster wheels, 44-76 mm across
        c = seating.caster(("twin", "single")[int(rng.integers(2))], float(rng.uniform(0.022, 0.038)))
        ws = seating.wheels(c)
        return ws[int(rng.integers(len(ws)))]

    if kind == frozenset({"stem"}):
        u = rng.random()
        if u < 0.3:
            from .categories.parts import doors

            return doors.knob_part(float(rng.uniform(0.025, 0.032)))
        if u < 0.65:
            return hardware.knob_handle(float(rng.uniform(0.012, 0.02)), float(rng.uniform(0.02, 0.03)), "m")
        return V.lid_knob(float(rng.uniform(0.012, 0.03)), "m")
    if rng.random() < 0.6:
        return hardware.bar_handle(float(rng.uniform(0.096, 0.40)), "m")
    return hardware.edge_pull(float(rng.uniform(0.10, 0.45)), "m", depth=float(rng.uniform(0.014, 0.02)))


def study(library, n: int = 100, seed: int = 0, box: bool = False, label: str | None = None) -> list[dict]:
    """``n`` placements of drawn library parts on drawn procedural targets: bounding-box vs support
    placement, the gap (+) or penetration (-) of each foot along the mount normal and its offset across.

    ``box=False``: every part of the label and kind whose feet reach the target's (the bounding-box fit
    clipped to the scale policy where the box asks for more); ``True``: only the parts generation
    draws (:func:`candidates`: the box within the policy). ``label``: only parts of that label."""
    rng = np.random.default_rng(seed)
    kinds = sorted({p.kind for p in library.parts if label is None or p.label == label}, key=sorted)
    if not kinds:
        return []
    rows = []
    tries = 0
    while len(rows) < 2 * n and tries < 50 * n:
        tries += 1
        asm = targets_for(kinds[int(rng.integers(len(kinds)))], rng)
        found = candidates(library, asm, box)
        if not found:
            continue
        if label is not None:
            found = [x for x in found if x[0].label == label]
            if not found:
                continue
        lib = found[int(rng.integers(len(found)))][0]
        _frame, bounds, tg = part_frame(asm)
        for how, f in (("bbox", bbox_fit), ("support", support_fit)):
            fit = f(lib, bounds, tg)
            rows.append({"part": lib.id, "label": lib.label, "placement": how,
                         "gap_mm": max(0.0, max(fit.gaps.values())) * 1000,
                         "penetration_mm": max(0.0, -min(fit.gaps.values())) * 1000,
                         "lateral_mm": max(fit.lateral.values()) * 1000})
    return rows


def summary(rows: list[dict]) -> dict:
    out = {}
    for how in ("bbox", "support"):
        r = [x for x in rows if x["placement"] == how]
        if not r:
            continue
        err = np.array([max(x["gap_mm"], x["penetration_mm"]) for x in r])
        out[how] = {"placements": len(r),
                    "mean_gap_mm": float(np.mean([x["gap_mm"] for x in r])),
                    "max_gap_mm": float(np.max([x["gap_mm"] for x in r])),
                    "mean_penetration_mm": float(np.mean([x["penetration_mm"] for x in r])),
                    "max_penetration_mm": float(np.max([x["penetration_mm"] for x in r])),
                    "max_lateral_mm": float(np.max([x["lateral_mm"] for x in r])),
                    "within_0.5mm": int((err <= 0.5).sum())}
    return out
