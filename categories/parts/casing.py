"""Sheet casings with rounded corners and cut-outs, lift-out liners and hinge brackets.

A casing is built on the ground plane, centred on the z axis, its front facing +x. Every face has an
anchor named after it (``front``, ``back``, ``left``, ``right``, ``top``: its centre on the outer face,
z out of it; a side face's x points up, the top's x to the front), and a point on a face is given in
that face's own coordinates ``(u, v)`` from its centre: ``u`` along the face frame's y (to the right as
you look at the face), ``v`` along its x. A :class:`Cutout` is a rectangle in those coordinates; the
casing leaves it open and adds an anchor of the cut-out's name at its :attr:`Cutout.anchor` point, so a
part that goes through the hole (a lever, a dial stem, a drawer) is attached there without the
category computing where the hole is.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import trimesh

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.errors import ModelError
from infmob_usd.frames import IDENTITY, Frame
from infmob_usd.grasps import Grasp


@dataclass(frozen=True)
class Cutout:
    """A rectangular hole in one face of a casing: ``lo`` / ``hi`` corners in face coordinates
    ``(u, v)`` (metres from the face centre) and the point ``anchor`` (default: the centre) where the
    casing puts the anchor named after the cut-out (z out of the face, x along v)."""

    face: str
    lo: tuple[float, float]
    hi: tuple[float, float]
    anchor: tuple[float, float] | None = None

    @classmethod
    def around(cls, face: str, at: tuple[float, float], size: tuple[float, float], clearance: float = 0.0
               ) -> Cutout:
        """A hole of ``size`` (u, v) centred on ``at``, ``clearance`` wider all round."""
        du, dv = size[0] / 2 + clearance, size[1] / 2 + clearance
        return cls(face, (at[0] - du, at[1] - dv), (at[0] + du, at[1] + dv), tuple(at))

    @property
    def at(self) -> tuple[float, float]:
        return self.anchor or ((self.lo[0] + self.hi[0]) / 2, (self.lo[1] + self.hi[1]) / 2)


@dataclass(frozen=True)
class CasingSize:
    """A sheet casing: outer ``width`` (y), ``depth`` (x), ``height`` (z); the walls are modelled
    ``wall`` thick (so the simulator sees a solid wall) and massed as ``sheet`` of the slot's material;
    the four upright edges are rounded to ``corner`` radius."""

    width: float
    depth: float
    height: float
    wall: float
    sheet: float
    corner: float

    @property
    def clear_width(self) -> float:
        """Width inside the casing clear of the corner posts (what a tray sliding in may take)."""
        return self.width - 4 * self.corner

    def half(self, face: str) -> tuple[float, float]:
        """Half extents ``(u, v)`` of a face."""
        across = self.depth if face in ("left", "right") else self.width
        return across / 2, (self.depth if face == "top" else self.height) / 2

    def on(self, face: str, fu: float, fv: float) -> tuple[float, float]:
        """A point of ``face`` given as fractions of its half extents (-1 to 1 from its centre)."""
        hu, hv = self.half(face)
        return fu * hu, fv * hv

    def floor_opening(self, face: str, width: float, height: float, clearance: float) -> Cutout:
        """A side face's opening for a tray ``width`` x ``height`` on the floor plate (``clearance`` all round):
        its anchor is where the tray's front centre goes."""
        bottom = self.wall - self.half(face)[1]
        du = width / 2 + clearance
        return Cutout(face, (-du, bottom), (du, bottom + height + 2 * clearance),
                      (0.0, bottom + clearance + height / 2))

    def slots(self, face: str, length: float, width: float, gap: float, count: int = 2) -> dict[str, Cutout]:
        """``count`` parallel slots ``length`` x ``width`` along u, ``gap`` apart, centred on the face
        (a toaster's bread slots): cut-outs ``slot_0`` ...."""
        pitch = width + gap
        return {f"slot_{k}": Cutout.around(face, (0.0, (k - (count - 1) / 2) * pitch), (length, width))
                for k in range(count)}


def face_frames(width: float, depth: float, height: float) -> dict[str, Frame]:
    """The outer face frames of a ``width`` x ``depth`` x ``height`` box standing on z = 0."""
    hx, hy, hz = depth / 2, width / 2, height / 2
    return {
        "front": Frame.at((hx, 0, hz), z=(1, 0, 0), x=(0, 0, 1)),
        "back": Frame.at((-hx, 0, hz), z=(-1, 0, 0), x=(0, 0, 1)),
        "left": Frame.at((0, hy, hz), z=(0, 1, 0), x=(0, 0, 1)),
        "right": Frame.at((0, -hy, hz), z=(0, -1, 0), x=(0, 0, 1)),
        "top": Frame.at((0, 0, height), z=(0, 0, 1), x=(1, 0, 0)),
    }


def _hole(frame: Frame, c: Cutout) -> tuple[float, float, float, float]:
    """A cut-out as a :func:`~infmob_usd.geometry.panel` hole: its rectangle in the two world axes of the
    face (x, y, z order, the normal skipped)."""
    a = frame.point((c.lo[1], c.lo[0], 0.0))
    b = frame.point((c.hi[1], c.hi[0], 0.0))
    n = int(abs(frame.z).argmax())
    i, j = (k for k in range(3) if k != n)
    return (min(a[i], b[i]), min(a[j], b[j]), max(a[i], b[i]), max(a[j], b[j]))


def sheet_casing(size: CasingSize, material: str, cutouts: Mapping[str, Cutout] | None = None,
                 label: str = "body") -> Assembly:
    """A closed sheet box with rounded upright corners and rectangular cut-outs.

    Four walls and a top and bottom plate (``wall`` thick, massed as ``size.sheet``) and four upright
    corner posts of radius ``corner``; each :class:`Cutout` is a hole through its face (front, back,
    left, right or top) and an anchor of its name. Anchors: the faces (see the module), ``floor`` (the
    bottom plate's top, z up). Supports: the four corners of the footprint.
    """
    s, cutouts = size, dict(cutouts or {})
    faces = face_frames(s.width, s.depth, s.height)
    bad = sorted(k for k, c in cutouts.items() if c.face not in faces)
    if bad:
        raise ModelError(f"cut-outs {bad}: face must be one of {sorted(faces)}")
    holes = {f: [_hole(faces[f], c) for c in cutouts.values() if c.face == f] for f in faces}
    x0, x1, y0, y1, h, t, r = -s.depth / 2, s.depth / 2, -s.width / 2, s.width / 2, s.height, s.wall, s.corner
    pieces = [
        g.panel((x1 - t, y0 + r, 0), (x1, y1 - r, h), material, "x", holes["front"]),
        g.panel((x0, y0 + r, 0), (x0 + t, y1 - r, h), material, "x", holes["back"]),
        g.panel((x0 + r, y1 - t, 0), (x1 - r, y1, h), material, "y", holes["left"]),
        g.panel((x0 + r, y0, 0), (x1 - r, y0 + t, h), material, "y", holes["right"]),
        g.panel((x0 + r, y0 + t, h - t), (x1 - r, y1 - t, h), material, "z", holes["top"]),
        g.box_between((x0 + r, y0 + t, 0), (x1 - r, y1 - t, t), material),
    ]
    for z0, z1 in ((0, t), (h - t, h)):  # the plates' ends between the corner posts
        pieces += [g.box_between((x, y0 + r, z0), (x + r - t, y1 - r, z1), material) for x in (x0 + t, x1 - r)]
    pieces += [g.cylinder((x, y, 0), (x, y, h), r, material, 16) for x in (x0 + r, x1 - r) for y in (y0 + r, y1 - r)]
    pieces = [pc.replace(sheet=s.sheet) for pc in pieces]
    anchors = {**faces, "floor": Frame.at((0, 0, t))}
    for name, c in cutouts.items():
        u, v = c.at
        anchors[name] = faces[c.face] @ Frame.at((v, u, 0))
    supports = {f"foot_{i}": (x, y, 0) for i, (x, y) in enumerate(((x0, y0), (x0, y1), (x1, y0), (x1, y1)))}
    return Assembly.single(label, pieces, anchors, supports)


def rounded_sweep(hx: float, hy: float, r: float, profile, material: str, convex=(), per_corner: int = 7
                  ) -> g.Piece:
    """A closed profile swept round a rounded rectangle (half extents ``hx``, ``hy`` in x, y, corners of radius
    ``r``): each profile point ``(d, z)`` is the rectangle's offset curve ``d`` outward at height ``z``, so the
    corners stay concentric (a moulded bin's wall with its rolled rim, a base ring). Every ``r + d`` must be
    positive. ``convex``: its collision point sets (the walls' boxes; default none), as a moulding's rounded
    corners are drawn, not simulated."""
    prof = np.asarray(profile, float)
    centres = ((hx - r, hy - r, 0.0), (-hx + r, hy - r, 90.0), (-hx + r, -hy + r, 180.0), (hx - r, -hy + r, 270.0))
    angles = [(cx, cy, np.radians(np.linspace(a0, a0 + 90.0, per_corner))) for cx, cy, a0 in centres]
    rings = []
    for d, z in prof:
        ring = [(cx + (r + d) * np.cos(a), cy + (r + d) * np.sin(a)) for cx, cy, a in angles]
        xy = np.hstack([np.vstack(c) for c in ring]).T
        rings.append(np.column_stack([xy, np.full(len(xy), z)]))
    n, m = len(rings[0]), len(rings)
    i, j = np.meshgrid(np.arange(m), np.arange(n), indexing="ij")
    a, b = i * n + j, i * n + (j + 1) % n
    c, e = ((i + 1) % m) * n + (j + 1) % n, ((i + 1) % m) * n + j
    faces = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, e], -1).reshape(-1, 3)])
    v = np.vstack(rings)
    if trimesh.Trimesh(v, faces, process=False).volume < 0:  # the profile ran clockwise: faces inward
        faces = faces[:, ::-1]
    return g.Piece(v, faces, material, convex)


def edged_box(lo, hi, material: str, edge: float, name: str = "") -> g.Piece:
    """A box from corner ``lo`` to ``hi`` with all twelve edges chamfered ``edge`` wide (a rolled steel edge, a
    moulding's radius seen from a metre away): the hull of three copies, each cut back ``edge`` on two axes.
    (:func:`~infmob_usd.geometry.box`'s ``bevel`` cuts the eight corners only: its edges stay sharp.)"""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    e = min(edge, 0.45 * float((hi - lo).min()))
    pts = []
    for keep in range(3):
        a, b = lo + e, hi - e
        a[keep], b[keep] = lo[keep], hi[keep]
        pts += [(x, y, z) for x in (a[0], b[0]) for y in (a[1], b[1]) for z in (a[2], b[2])]
    v, f = g.hull_arrays(np.array(pts))
    return g.Piece(v, f, material, [v], name)


def inset_outline(outline, d: float) -> np.ndarray:
    """A convex outline (``(k, 2)``, counter-clockwise) moved ``d`` inwards, every edge parallel to its own."""
    o = np.asarray(outline, float)
    e = np.roll(o, -1, 0) - o
    n = np.column_stack([-e[:, 1], e[:, 0]]) / np.maximum(np.linalg.norm(e, axis=1, keepdims=True), 1e-12)
    n1, n2 = np.roll(n, 1, 0), n  # the inward normals of the edges before and after each corner
    return o + d * (n1 + n2) / np.maximum(1.0 + (n1 * n2).sum(1, keepdims=True), 1e-6)


def moulded_slab(outline, z0: float, z1: float, edge: float, material: str, name: str = "",
                 ends: tuple[bool, bool] = (True, True), steps: int = 3) -> g.Piece:
    """A convex slab over a convex ``outline`` from ``z0`` to ``z1`` whose bottom and top edges (``ends``) are
    rounded to radius ``edge`` (a moulding's 1-5 mm radius, a die-cast half's): the outline inset along a quarter
    circle towards each rounded face. Collision: its hull."""
    o = np.asarray(outline, float)
    o = o if _ccw(o) else o[::-1]
    e = min(edge, 0.45 * (z1 - z0), 0.45 * float(np.ptp(o, 0).min()))
    quarter = np.radians(np.linspace(0.0, 90.0, steps + 1))
    rings = []
    for rounded, z, s in ((ends[0], z0, 1.0), (ends[1], z1, -1.0)):
        if rounded and e > 0:
            rings += [(e * (1 - math.cos(a)), z + s * e * (1 - math.sin(a))) for a in quarter]
        else:
            rings.append((0.0, z))
    pts = [np.column_stack([inset_outline(o, d), np.full(len(o), z)]) for d, z in rings]
    v, f = g.hull_arrays(np.vstack(pts))
    return g.Piece(v, f, material, [v], name)


def _ccw(o: np.ndarray) -> bool:
    x, y = o[:, 0], o[:, 1]
    return float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y)) > 0


@dataclass(frozen=True)
class LinerSize:
    """An open tray or liner: outer ``width`` (y), ``depth`` (x), ``height`` (z), walls ``wall`` thick
    (massed as ``sheet``), a front plate ``lip`` taller than the walls (0: none) and ``front`` thick."""

    width: float
    depth: float
    height: float
    wall: float
    sheet: float
    lip: float = 0.0
    front: float = 0.0


def liner(size: LinerSize, material: str, front_material: str | None = None, label: str = "drawer") -> Assembly:
    """A lift-out liner (a crumb tray, a drip tray, a bin): an open box on z = 0, its front face at
    x = 0, running back to x = -depth, centred on y; with ``size.front`` > 0 a front plate ``lip`` taller
    than the walls (a pull) in ``front_material``. Anchors: ``front`` (the front face's centre, z out of
    it, x up: a slide along it pulls the liner out), ``seat`` (the bottom's underside centre, z up).
    Supports: the bottom's four corners."""
    s = size
    x0, y0, y1, h, t = -s.depth, -s.width / 2, s.width / 2, s.height, s.wall
    xf = -s.front
    pieces = [
        g.box_between((x0, y0, 0), (xf, y1, t), material),
        g.box_between((x0, y0, t), (x0 + t, y1, h), material),
        g.box_between((x0 + t, y0, t), (xf, y0 + t, h), material),
        g.box_between((x0 + t, y1 - t, t), (xf, y1, h), material),
    ]
    hf = h + s.lip
    if s.front > 0:
        pieces.append(g.box_between((xf, y0, 0), (0, y1, hf), front_material or material))
    else:
        pieces.append(g.box_between((xf - t, y0 + t, t), (xf, y1 - t, h), material))
    pieces = [pc.replace(sheet=s.sheet) for pc in pieces]
    anchors = {"front": Frame.at((0, 0, hf / 2), z=(1, 0, 0), x=(0, 0, 1)), "seat": Frame.at((x0 / 2, 0, 0))}
    supports = {f"corner_{i}": (x, y, 0) for i, (x, y) in enumerate(((x0, y0), (x0, y1), (xf, y0), (xf, y1)))}
    return Assembly.single(label, pieces, anchors, supports)


def pull_tab(size: LinerSize, proud: float, thick: float, material: str) -> g.Piece:
    """A liner's pull tab: an upright lug ``thick`` across standing ``proud`` out of the middle of its front plate
    (x = 0), as tall as the plate, folded from the same sheet. A front that sits flush in its opening leaves no
    gap a finger fits; the tab is what the fingers pinch, from the front across its thickness (the pads beside
    it stay in front of the casing and above the tray's floor, never below the appliance's foot)."""
    hf = size.height + size.lip
    tab = g.box_between((0.0, -thick / 2, 0.0), (proud, thick / 2, hf), material).replace(sheet=size.sheet)
    box = ((proud / 2, 0.0, hf / 2), (proud, thick, hf), IDENTITY.rotation)
    return tab.with_grasps(Grasp.make((proud, 0.0, hf / 2), (-1, 0, 0), (0, 1, 0), thick, proud / 2,
                                      "line_fixed_handle", box))


@dataclass(frozen=True)
class BracketSize:
    """A hinge bracket: a ``plate`` (length along the pin, width, thickness) screwed to a face and a
    knuckle of ``radius`` on its edge, ``knuckle`` long."""

    length: float
    width: float
    thickness: float
    radius: float
    knuckle: float


def hinge_bracket(size: BracketSize, material: str, label: str = "hinge") -> Assembly:
    """A hinge leaf on its mounting face (z = 0 up to ``thickness``) with a knuckle on its edge: the plate
    runs along local y (``length``) from x = -width to x = 0, the knuckle's axis is the line x = 0,
    z = ``radius``, along y. Anchors: ``mount`` (the plate's underside centre, z out of the face),
    ``pin`` (on the knuckle's axis, z along it: a hinge about it turns a leaf on the other side)."""
    s = size
    plate = g.box_between((-s.width, -s.length / 2, 0), (0, s.length / 2, s.thickness), material)
    knuckle = g.cylinder((0, -s.knuckle / 2, s.radius), (0, s.knuckle / 2, s.radius), s.radius, material, 16)
    anchors = {"mount": Frame.at((-s.width / 2, 0, 0)), "pin": Frame.at((0, 0, s.radius), z=(0, 1, 0), x=(1, 0, 0))}
    return Assembly.single(label, [plate, knuckle], anchors,
                           {"screw_a": (-s.width / 2, -s.length / 3, 0), "screw_b": (-s.width / 2, s.length / 3, 0)})
