"""Part-mesh retrieval: procedural parts swapped for library meshes, placed by their support points.

While :func:`infmob_usd.api.generate` builds an object with a part library (``parts=LIB``), every
one-part assembly a layout attaches by an anchor (:meth:`~infmob_usd.assembly.Assembly.attached`)
whose label is in the library and whose support points name a kind the library holds (a bar pull's
``mount_a`` / ``mount_b``, a knob's ``stem``) is, with probability ``parts_share``, replaced by a
library part drawn from a stream seeded by the object's seed (same inputs, same bytes):

1. **bounding-box fit**: per-axis scale of the library mesh to the procedural part's bounds, each
   factor clipped to the part's scale policy;
2. **support-point alignment**: the least-squares similarity (a uniform factor within the scale
   policy, a turn about the mount normal, a translation) taking the library part's support points
   onto the procedural part's, so its feet stand where the procedural feet stood: on the surface,
   with the same gap (0 for a pull, 1 mm sunk for a lid knob), and a knob's stem on its joint axis.

The new pieces keep the procedural part's material slot and name; anchors and supports stay the
procedural ones, so joints declared on them follow the placed mesh. Each swap is recorded
(:attr:`Retriever.records`, written to ``metadata.json`` as ``retrieved_parts``).
"""

from __future__ import annotations

import contextvars
import zlib
from dataclasses import dataclass

import numpy as np

from .seeding import category_id

ACTIVE: contextvars.ContextVar = contextvars.ContextVar("infmob_retriever", default=None)
PARTS_STREAM = zlib.crc32(b"parts")


@dataclass(frozen=True)
class Fit:
    """A placement: ``(4, 4)`` matrix library frame -> procedural frame, and how the feet land."""

    matrix: np.ndarray
    gaps: dict  # support -> signed distance of the library foot above the procedural one, along z (m)
    lateral: dict  # support -> distance across the mount normal (m)


def _scale_box(lib_bounds: np.ndarray, bounds: np.ndarray, policy: dict) -> np.ndarray:
    ext_l = np.maximum(np.ptp(lib_bounds, axis=0), 1e-9)
    ext_p = np.ptp(bounds, axis=0)
    s = ext_p / ext_l
    return np.array([np.clip(s[i], *policy["xyz"[i]]) for i in range(3)])


def _measure(m: np.ndarray, lib_sup: dict, targets: dict) -> tuple[dict, dict]:
    gaps, lat = {}, {}
    for k, q in targets.items():
        p = m[:3, :3] @ lib_sup[k] + m[:3, 3]
        gaps[k] = float(p[2] - q[2])
        lat[k] = float(np.linalg.norm(p[:2] - q[:2]))
    return gaps, lat


def bbox_fit(lib, bounds: np.ndarray, targets: dict) -> Fit:
    """The baseline: the library mesh scaled per axis to the bounds (within its policy), centred."""
    lb = np.array([lib.vertices.min(0), lib.vertices.max(0)])
    s = _scale_box(lb, bounds, lib.scale)
    m = np.eye(4)
    m[:3, :3] = np.diag(s)
    m[:3, 3] = bounds.mean(0) - s * lb.mean(0)
    return Fit(m, *_measure(m, lib.supports, targets))


def support_fit(lib, bounds: np.ndarray, targets: dict) -> Fit:
    """Bounding-box scale, then the least-squares similarity of the support points onto ``targets``.

    The similarity turns about z only (the mount normal: both frames have it along +z), scales
    uniformly within what the scale policy leaves, and translates; with one support point it is a
    translation.
    """
    lb = np.array([lib.vertices.min(0), lib.vertices.max(0)])
    s = _scale_box(lb, bounds, lib.scale)
    names = sorted(targets)
    P = np.array([s * lib.supports[k] for k in names])
    Q = np.array([targets[k] for k in names])
    k, R = 1.0, np.eye(3)
    if len(names) >= 2:
        pc, qc = P[:, :2].mean(0), Q[:, :2].mean(0)
        a, b = P[:, :2] - pc, Q[:, :2] - qc
        var = float((a ** 2).sum())
        if var > 1e-12:
            # 2-D Umeyama: the rotation angle and factor that minimise sum |k R a_i - b_i|^2
            c = float((a * b).sum())
            d = float((a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]).sum())
            th = float(np.arctan2(d, c))
            k = float(np.hypot(c, d) / var)
            lo = max(lib.scale[ax][0] / s[i] for i, ax in enumerate("xyz"))
            hi = min(lib.scale[ax][1] / s[i] for i, ax in enumerate("xyz"))
            k = float(np.clip(k, lo, hi)) if lo <= hi else 1.0
            R = np.array([[np.cos(th), -np.sin(th), 0.0], [np.sin(th), np.cos(th), 0.0], [0.0, 0.0, 1.0]])
    L = k * (R @ np.diag(s))
    t = (Q - P @ (k * R).T).mean(0)
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = L, t
    return Fit(m, *_measure(m, lib.supports, targets))


LATERAL_TOL = 0.001
"""A library part is a candidate for a procedural part only if its support points can reach the
procedural ones within this (metres) inside its scale policy: a 160 mm pull cannot stand on the
posts of a 400 mm one."""


def fits_box(lib, bounds: np.ndarray) -> bool:
    """Whether the part fits the bounding box without leaving its scale policy on any axis (a 30 mm
    cabinet knob is no 60 mm door knob, and a round knob stretched on one axis only is no longer round)."""
    ext_l = np.maximum(np.ptp(lib.vertices, axis=0), 1e-9)
    s = np.ptp(bounds, axis=0) / ext_l
    return all(lib.scale[ax][0] <= s[i] <= lib.scale[ax][1] for i, ax in enumerate("xyz"))


def candidates(library, asm, box: bool = True) -> list[tuple]:
    """``[(library part, support fit)]`` for a one-part assembly: same label, same support kind, the
    procedural bounding box within the scale policy (``box``), and feet that reach the procedural feet
    within :data:`LATERAL_TOL`."""
    part = asm.parts[asm.root]
    tg = dict(asm.supports)
    bounds = asm.bounds()
    out = []
    for lib in library.candidates(part.label, frozenset(tg)):
        if box and not fits_box(lib, bounds):
            continue
        fit = support_fit(lib, bounds, tg)
        if max(fit.lateral.values()) <= LATERAL_TOL and max(abs(g) for g in fit.gaps.values()) <= LATERAL_TOL:
            out.append((lib, fit))
    return out


class Retriever:
    """The library, the share and the stream of one object's build."""

    def __init__(self, library, share: float, category: str, seed: int) -> None:
        self.library, self.share = library, float(share)
        ss = np.random.SeedSequence((int(seed), category_id(category), PARTS_STREAM))
        self.rng = np.random.default_rng(ss)
        self.records: list[dict] = []
        self.choice: dict = {}

    def swap(self, asm):
        """``asm`` (in its local frame) with its part replaced by a library part, or ``asm`` itself."""
        from .assembly import Assembly, SubPart

        if asm.retrieved or len(asm.parts) != 1 or not asm.supports:
            return asm
        part = asm.parts[asm.root]
        kind = frozenset(asm.supports)
        every = self.library.candidates(part.label, kind)
        if not every:
            return asm
        key = (part.label, tuple(sorted(kind)))
        if key not in self.choice:  # object-wide: the handles of one cabinet match
            self.choice[key] = (float(self.rng.random()) < self.share, self.rng.permutation(len(every)))
        use, order = self.choice[key]
        if not use:
            return Assembly(asm.parts, asm.joints, asm.anchors, asm.supports, retrieved="-")
        found = {id(lib): fit for lib, fit in candidates(self.library, asm)}
        pick = next((every[j] for j in order if id(every[j]) in found), None)
        if pick is None:  # no library part reaches these feet within its scale policy
            return Assembly(asm.parts, asm.joints, asm.anchors, asm.supports, retrieved="-")
        lib, fit = pick, found[id(pick)]
        first = part.pieces[0]
        piece = lib.piece(first.material, first.name or part.label).transformed(fit.matrix)

        self.records.append({"label": part.label, "id": lib.id, "source": lib.source, "licence": lib.licence,
                             "scale": [round(float(x), 4) for x in np.linalg.norm(fit.matrix[:3, :3], axis=0)],
                             "max_support_gap_mm": round(1000 * max(abs(g) for g in fit.gaps.values()), 4)})
        return Assembly({asm.root: SubPart(part.label, (piece,))}, asm.joints, asm.anchors, asm.supports,
                        retrieved=lib.id)


def swap(asm):
    """The hook :meth:`Assembly.attached` calls: a swap when a retriever is active, else ``asm``."""
    r = ACTIVE.get()
    return asm if r is None else r.swap(asm)


# -- the study behind `infmob parts check` --------------------------------------------------------------
def targets_for(kind: frozenset, rng: np.random.Generator):
    """A procedural part of a kind at a drawn real size (the ranges the categories use)."""
    from .categories.parts import hardware
    from .categories.parts import vessel as V

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


def study(library, n: int = 100, seed: int = 0, box: bool = False) -> list[dict]:
    """``n`` placements of drawn library parts on drawn procedural targets: bounding-box vs support
    placement, the gap (+) or penetration (-) of each foot along the mount normal and its offset across.

    ``box=False``: every part of the label and kind whose feet reach the target's (the bounding-box fit
    clipped to the scale policy where the box asks for more); ``True``: only the parts generation
    draws (:func:`candidates`: the box within the policy)."""
    rng = np.random.default_rng(seed)
    kinds = sorted({p.kind for p in library.parts}, key=sorted)
    rows = []
    tries = 0
    while len(rows) < 2 * n and tries < 50 * n:
        tries += 1
        asm = targets_for(kinds[int(rng.integers(len(kinds)))], rng)
        found = candidates(library, asm, box)
        if not found:
            continue
        lib = found[int(rng.integers(len(found)))][0]
        tg = dict(asm.supports)
        for how, f in (("bbox", bbox_fit), ("support", support_fit)):
            fit = f(lib, asm.bounds(), tg)
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
