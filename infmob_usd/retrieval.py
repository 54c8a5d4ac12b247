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

from .partlib import LABELS
from .seeding import category_id

ACTIVE: contextvars.ContextVar = contextvars.ContextVar("infmob_retriever", default=None)
PARTS_STREAM = zlib.crc32(b"parts")


@dataclass(frozen=True)
class Fit:
    """A placement: ``(4, 4)`` matrix library frame -> procedural frame, and how the feet land."""

    matrix: np.ndarray
    gaps: dict  # support -> signed distance of the library foot from the procedural one, away from what
    # carries it along z (m): + a gap, - a penetration
    lateral: dict  # support -> distance across the mount normal (m)


def _scale_box(lib_bounds: np.ndarray, bounds: np.ndarray, policy: dict) -> np.ndarray:
    ext_l = np.maximum(np.ptp(lib_bounds, axis=0), 1e-9)
    ext_p = np.ptp(bounds, axis=0)
    s = ext_p / ext_l
    return np.array([np.clip(s[i], *policy["xyz"[i]]) for i in range(3)])


CARRIED_FROM_ABOVE = frozenset({"top", "axle_b"})
"""Support points whose carrier lies on their +z side (a leg's top under the table top, a wheel's
axle end against the fork's +z cheek); every other support rests on a carrier below it along z."""


def _measure(m: np.ndarray, lib_sup: dict, targets: dict) -> tuple[dict, dict]:
    gaps, lat = {}, {}
    for k, q in targets.items():
        p = m[:3, :3] @ lib_sup[k] + m[:3, 3]
        gaps[k] = float(q[2] - p[2]) if k in CARRIED_FROM_ABOVE else float(p[2] - q[2])
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
    translation; with supports on one line along z (a leg, a wheel) it scales z to their spacing.
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
        elif np.ptp(P[:, 2]) > 1e-9:
            # supports along one line on z (a leg's foot and top, a wheel's axle ends): z scaled so their
            # spacing is the target's, within the policy (a leg's stud stays out of its length)
            s = s.copy()
            s[2] = float(np.clip(s[2] * np.ptp(Q[:, 2]) / np.ptp(P[:, 2]), *lib.scale["z"]))
            P = np.array([s * lib.supports[k] for k in names])
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


FIT_ANCHOR = "part_frame"
"""The anchor a procedural part names its part frame by when it is not its local frame (the label's
convention of :mod:`infmob_usd.partlib`: a caster wheel built with its axle along x declares a frame
with z along the axle); absent: the local frame is the part frame."""


def part_frame(asm):
    """``(frame or None, (2, 3) bounds, {support: point})`` of a one-part assembly in its part frame."""
    frame = asm.anchors.get(FIT_ANCHOR)
    if frame is None:
        return None, asm.bounds(), dict(asm.supports)
    inv = frame.inverse()
    v = np.vstack([inv.point(pc.vertices) for pc in asm.parts[asm.root].pieces])
    return frame, np.array([v.min(0), v.max(0)]), {k: inv.point(p) for k, p in asm.supports.items()}


def candidates(library, asm, box: bool = True) -> list[tuple]:
    """``[(library part, support fit)]`` for a one-part assembly: same label, same support kind, the
    procedural bounding box within the scale policy (``box``), and feet that reach the procedural feet
    within :data:`LATERAL_TOL`. Fits are in the assembly's part frame (:func:`part_frame`)."""
    part = asm.parts[asm.root]
    _frame, bounds, tg = part_frame(asm)
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
        self.skipped: dict[str, int] = {}  # "label: reason" -> procedural parts left in place for it
        self.choice: dict = {}

    def summary(self) -> dict:
        """``{"retrievable", "used", "skipped": {"label: reason": count}}`` of the parts seen so far: every
        attached part of a label retrieval knows, used or left procedural, and why."""
        return {"retrievable": len(self.records) + sum(self.skipped.values()), "used": len(self.records),
                "skipped": dict(sorted(self.skipped.items()))}

    def _skip(self, asm, reason: str):
        key = f"{asm.parts[asm.root].label}: {reason}"
        self.skipped[key] = self.skipped.get(key, 0) + 1
        return type(asm)(asm.parts, asm.joints, asm.anchors, asm.supports, retrieved="-")

    def swap(self, asm):
        """``asm`` (in its local frame) with its part replaced by a library part, or ``asm`` itself."""
        # the assembly's own classes, not an import: assembly.py imports this module
        Assembly = type(asm)  # noqa: N806
        SubPart = type(asm.parts[asm.root])  # noqa: N806
        if asm.retrieved or len(asm.parts) != 1 or not asm.supports:
            return asm
        part = asm.parts[asm.root]
        kind = frozenset(asm.supports)
        every = self.library.candidates(part.label, kind)
        if not every:
            if part.label not in LABELS:
                return asm
            return self._skip(asm, f"the library has no part with supports {', '.join(sorted(kind))}")
        key = (part.label, tuple(sorted(kind)))
        if key not in self.choice:  # object-wide: the handles of one cabinet match
            self.choice[key] = (float(self.rng.random()) < self.share, self.rng.permutation(len(every)))
        use, order = self.choice[key]
        if not use:
            return self._skip(asm, "not drawn (--parts-share)")
        found = {id(lib): fit for lib, fit in candidates(self.library, asm)}
        pick = next((every[j] for j in order if id(every[j]) in found), None)
        if pick is None:  # no library part reaches these feet within its scale policy
            _frame, bounds, _tg = part_frame(asm)
            if not any(fits_box(lib, bounds) for lib in every):
                return self._skip(asm, "no library part scales to its size within its scale policy")
            return self._skip(asm, "no library part reaches its support points within its scale policy")
        lib, fit = pick, found[id(pick)]
        frame = asm.anchors.get(FIT_ANCHOR)
        matrix = fit.matrix if frame is None else frame.matrix @ fit.matrix
        first = part.pieces[0]
        piece = lib.piece(first.material, first.name or part.label).transformed(matrix)

        self.records.append({"label": part.label, "id": lib.id, "source": lib.source, "licence": lib.licence,
                             "scale": [round(float(x), 4) for x in np.linalg.norm(fit.matrix[:3, :3], axis=0)],
                             "max_support_gap_mm": round(1000 * max(abs(g) for g in fit.gaps.values()), 4)})
        return Assembly({asm.root: SubPart(part.label, (piece,))}, asm.joints, _hinted(asm, lib, matrix),
                        asm.supports, retrieved=lib.id)


def _hinted(asm, lib, matrix: np.ndarray) -> dict:
    """The anchors of ``asm`` with its label's joint anchor (a wheel's ``axle``) moved onto the library
    part's own axis hint, placed: the joint turns about the mesh's axle, not the procedural one. The
    anchor keeps its sense (z turned to agree with the procedural z) and, as near as it can, its x."""
    anchors = dict(asm.anchors)
    name = LABELS.get(asm.parts[asm.root].label, {}).get("axis_anchor")
    if lib.axis is None or name not in anchors:
        return anchors
    old = anchors[name]
    point = matrix[:3, :3] @ lib.axis[0] + matrix[:3, 3]
    d = matrix[:3, :3] @ lib.axis[1]
    d = d / np.linalg.norm(d)
    if float(d @ old.z) < 0:
        d = -d
    # the anchor's origin: the hint line's point nearest the procedural origin (the wheel's middle)
    point = point + d * float((old.origin - point) @ d)
    x = old.x - d * float(old.x @ d)
    anchors[name] = type(old).at(point, z=d, x=x if np.linalg.norm(x) > 1e-6 else None)
    return anchors


def swap(asm):
    """The hook :meth:`Assembly.attached` calls: a swap when a retriever is active, else ``asm``."""
    r = ACTIVE.get()
    return asm if r is None else r.swap(asm)
