"""Eyewear lying on a table: frame fronts (rims, lenses, bridge, end pieces, nose pads) and temples.

Local frame: a pair of glasses put down as one does, the lenses face down on the table and the folded
temples on top. The front's width runs along Y, its height (brow to cheek) along X with the brow toward
+X, its back (where the temples are) up (+Z). Sizes follow the boxing system printed inside a temple
(``A-DBL-temple``: the lens width, the distance between the lenses, the temple length).

Rest pose: the temples folded, the one on the +Y end piece (``under``) flat behind the front, the other
(``over``) lying on it at a slight slope; each opens about its end piece's hinge (axis along X) up to
stand square to the front and, with a spring hinge, past it. A folding reader's front folds at its bridge
hinge: the -Y half turns up about X over the +Y half.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame

from .handtools import hull, rrect, sweep

GAP = 0.0003  # m, between a hinge's knuckles along its screw (0.1-0.3 mm: a temple turns stiffly, not loose)
LENS = 0.002  # m, lens thickness at its edge: CR-39 / polycarbonate single-vision lenses 1.8-2.5 mm (edging)


@dataclass(frozen=True)
class LensShape:
    """A lens outline: its height as a share of its width (B/A), the superellipse exponent (2: an ellipse,
    higher: squarer), how much wider its top is than its bottom, and how far its nasal bottom drops."""

    ratio: float
    exponent: float
    taper: float = 0.0
    droop: float = 0.0


SHAPES = {
    # B/A from maker size charts: Ray-Ban RB3447 Round Metal 50 x 44 mm; RB2140 Wayfarer 50 x 40 mm (its top
    # wider); RB3025 Aviator 58 x 50 mm (deepest at the nose); rectangular frames 52-54 x 30-34 mm; ovals 0.7
    "round": LensShape(0.88, 2.0),
    "oval": LensShape(0.70, 2.2),
    "rectangle": LensShape(0.60, 4.0, 0.04),
    "wayfarer": LensShape(0.80, 3.2, 0.16),
    "aviator": LensShape(0.86, 2.3, 0.06, 0.22),
}


SHAPE_SHARES = {"round": 0.2, "oval": 0.2, "rectangle": 0.25, "wayfarer": 0.2, "aviator": 0.15}
"""How often each outline is drawn: rectangles and ovals lead optical frames, wayfarers and aviators
sunglasses (retailers' shape filters list them in about this order)."""

ACETATES = {"black": 0.35, "dark_grey": 0.15, "blue": 0.12, "red": 0.1, "teal": 0.1, "white": 0.08, "green": 0.1}
"""Acetate frame colours and how often each is drawn (black and greys lead every maker's range)."""


@dataclass(frozen=True)
class EyeDesign:
    """One kind of glasses, from real products (metres)."""

    eye: tuple[float, float]  # lens width A
    dbl: tuple[float, float]  # distance between the lenses (bridge size)
    temple: tuple[float, float]  # temple length, hinge to tip along it
    rim: str  # "full", "half" (top rim, nylon thread below) or "rimless" (drilled lenses)
    metal: tuple[float, float]  # rim (width in plan, thickness) of a metal frame
    acetate: tuple[float, float]  # the same of a moulded acetate frame (0: metal only)
    depth: float  # the end pieces' depth behind the front: the hinge's height lying down
    pads: bool = True  # metal nose pads on arms (a moulded acetate front has its own nose bridge)
    fold: bool = False  # a bridge hinge: the front folds in half
    brow: bool = False  # a second bridge bar over the first (aviators)


DESIGNS = {
    # Ray-Ban RB5154 / RB6335, Silhouette and Lindberg full-rim frames: 49-55 mm eyes, 16-21 mm bridges,
    # 140-145 mm temples; metal rims 2 x 2.5 mm, acetate fronts 5-6 mm wide and 4-5 mm thick
    "full_rim": EyeDesign((0.049, 0.055), (0.016, 0.021), (0.140, 0.145), "full", (0.0022, 0.0026),
                          (0.0055, 0.0045), 0.007),
    # Ray-Ban RB5154 Clubmaster 49-51 mm, 21 mm bridge, 140-145 mm temples; Supra (nylon-thread) frames
    "half_rim": EyeDesign((0.050, 0.055), (0.017, 0.021), (0.140, 0.145), "half", (0.0024, 0.0028),
                          (0.0060, 0.0045), 0.007),
    # Silhouette Titan Minimal Art 50-54 mm, 17-19 mm bridge, 140-150 mm temples (1.8 g frame, drilled lenses)
    "rimless": EyeDesign((0.050, 0.054), (0.017, 0.019), (0.140, 0.150), "rimless", (0.0, 0.0), (0.0, 0.0),
                         0.006),
    # Ray-Ban RB2140 Wayfarer 50-22-150 / 54-18-150, RB3025 Aviator 55-14-135 / 58-14-135 / 62-14-140
    "sunglasses": EyeDesign((0.052, 0.060), (0.014, 0.020), (0.135, 0.150), "full", (0.0024, 0.0028),
                            (0.0070, 0.0055), 0.009, brow=True),
    # Foster Grant Micro Vision / Peepers folding readers: 46-48 mm eyes, 19-20 mm bridge, 130-135 mm temples
    "folding_readers": EyeDesign((0.046, 0.049), (0.019, 0.020), (0.130, 0.135), "full", (0.0024, 0.0028),
                                 (0.0045, 0.0040), 0.006, fold=True),
}
"""Designs -> sizes (maker size charts named beside each)."""

DESIGN_SHARES = {"full_rim": 0.3, "half_rim": 0.17, "rimless": 0.15, "sunglasses": 0.23, "folding_readers": 0.15}
"""How often each design is drawn."""

BEND = 0.74  # the temple's straight share before its ear bend (length to bend 100-110 mm of 140-150)
DROP = math.radians(50.0)  # the ear bend's turn down round the ear, at its tip (40-60 degrees)
TEMPLE = {"metal": (0.0032, 0.0028, 0.0014), "acetate": (0.0085, 0.0045, 0.0035)}
"""Temple (height at the hinge, at the tip, thickness): metal temples 1.2-1.5 mm wire-flat, 3 mm high;
acetate temples 8-10 mm high at the hinge, tapering to 4-5 mm, 3-4 mm thick (Ray-Ban RB2140, RB5154)."""
STACK = 0.0015
"""Folded, the temple folded last lies on the other, parallel to it (not crossing it at a slope): its end piece
carries the hinge one temple's thickness and this much higher (the ear sock's 0.55 mm wall and a 1 mm gap), as
a pair's end pieces differ where one temple rides over the other (Ray-Ban RB3447, Lindberg strip titanium)."""


@dataclass(frozen=True)
class Glasses:
    design: EyeDesign
    shape: LensShape
    eye: float  # A
    dbl: float
    temple: float
    acetate: bool
    depth: float = 1.0  # the lens height's scale on its shape's B/A
    lift: float = 0.0  # how much higher the -Y end piece's hinge sits (its temple folds over the other)

    @property
    def height(self) -> float:
        return self.eye * self.shape.ratio * self.depth

    @property
    def rim(self) -> tuple[float, float]:
        """(width in plan, thickness) of the rim; 0 for rimless."""
        return self.design.acetate if self.acetate else self.design.metal

    @property
    def face(self) -> float:
        """z of the front's back face (the rims' top lying down; the lenses' for rimless)."""
        return max(self.rim[1], LENS + 0.0004)

    @property
    def temple_size(self) -> tuple[float, float, float]:
        return TEMPLE["acetate" if self.acetate else "metal"]

    @property
    def hinge(self) -> np.ndarray:
        """The +Y end piece's hinge point (its axis is X)."""
        a, d = self.eye, self.design
        x = 0.28 * self.height / 2
        y = self.dbl / 2 + a + (self.rim[0] / 2 if d.rim != "rimless" else -0.002) + 0.0025
        return np.array([x, y, self.face + d.depth])

    def hinge_at(self, side: int) -> np.ndarray:
        """The hinge point of the ``side`` end piece, y unsigned (:attr:`hinge`; the -Y one :attr:`lift` higher)."""
        return self.hinge + (0.0, 0.0, self.lift if side < 0 else 0.0)

    @property
    def knuckle(self) -> float:
        """The hinge barrels' radius."""
        return 0.55 * self.temple_size[2] + 0.0004


def glasses(design: str, shape: str, size: float, bridge: float, temple: float, acetate: bool,
            depth: float = 0.0) -> Glasses:
    """Sizes of one pair: ``size``, ``bridge`` and ``temple`` (0-1) within the design's ranges; ``depth`` moves
    the lens's height from its shape's by that share (a shallow or a deep version of an outline)."""
    d = DESIGNS[design]
    acetate = acetate and d.acetate[0] > 0
    lift = 0.0 if d.fold else TEMPLE["acetate" if acetate else "metal"][2] + STACK
    return Glasses(d, SHAPES[shape], _lerp(d.eye, size), _lerp(d.dbl, bridge), _lerp(d.temple, temple), acetate,
                   1.0 + depth, lift)


def _lerp(r: tuple[float, float], t: float) -> float:
    return r[0] + t * (r[1] - r[0])


# -- the front ----------------------------------------------------------------------------------------
def outline(gl: Glasses, grow: float = 0.0, n: int = 40) -> np.ndarray:
    """``(n, 2)`` lens outline (u: across, + toward the temple; v: up, + toward the brow) about the lens
    centre, counter-clockwise, grown outward by ``grow``."""
    s, a, b = gl.shape, gl.eye / 2, gl.height / 2
    th = 2 * math.pi * np.arange(n) / n
    c, sn = np.cos(th), np.sin(th)
    e = 2.0 / s.exponent
    u = a * np.sign(c) * np.abs(c) ** e
    v = b * np.sign(sn) * np.abs(sn) ** e
    u = u * (1 + s.taper * v / b)
    v = np.where(v < 0, v * (1 + s.droop * (1 - u / a) / 2), v)
    pts = np.c_[u, v]
    if grow:
        d = np.roll(pts, -1, 0) - np.roll(pts, 1, 0)
        nrm = np.c_[d[:, 1], -d[:, 0]]
        nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
        pts = pts + grow * nrm
    return pts


def _plan(gl: Glasses, uv: np.ndarray, side: int) -> np.ndarray:
    """Lens-local (u, v) points to the table's (x, y) for the lens on the ``side`` (+1: +Y) of the bridge."""
    cy = gl.dbl / 2 + gl.eye / 2
    return np.c_[uv[:, 1], side * (cy + uv[:, 0])]


def lens(gl: Glasses, side: int, material: str) -> g.Piece:
    z0 = 0.0004 if gl.design.rim != "rimless" else 0.0
    xy = _plan(gl, outline(gl), side)
    return hull([(x, y, z) for x, y in xy for z in (z0, z0 + LENS)], material, "lens")


def rim(gl: Glasses, side: int, material: str, thread: str) -> list[g.Piece]:
    """The rim round one lens (its inner edge 0.5 mm over the lens: the groove), the top only of a half rim
    with its nylon thread below; nothing for rimless."""
    w, t = gl.rim
    if gl.design.rim == "rimless":
        return []
    ring = outline(gl, w / 2 - 0.0005)
    sec = rrect(w, t, 0.45 * min(w, t))
    if gl.design.rim == "full":
        return [sweep(_plan(gl, ring, side), sec, material, closed=True, group=4, name="rim")]
    keep = np.nonzero(ring[:, 1] > -0.25 * gl.height / 2)[0]
    k0 = int(np.argmax(np.diff(np.r_[keep, keep[0] + len(ring)]) > 1)) + 1  # first index after the gap
    top = ring[np.roll(keep, -k0)]
    low = outline(gl, 0.0002)
    low = low[low[:, 1] <= -0.2 * gl.height / 2]
    low = low[np.argsort(np.arctan2(low[:, 1], low[:, 0]) % (2 * math.pi))]
    return [sweep(_plan(gl, top, side), sec, material, group=4, name="rim"),
            sweep(_plan(gl, low, side), rrect(0.0006, 0.0008, 0.0003, 0.0008), thread, group=4, name="thread")]


def _nasal_corner(gl: Glasses, grow: float) -> np.ndarray:
    """The lens outline's upper nasal corner (u, v), grown by ``grow``: where the bridge meets the rim."""
    ring = outline(gl, grow)
    return ring[np.argmin(ring[:, 0] - 0.6 * ring[:, 1])]


def _bridge_section(gl: Glasses) -> tuple[float, float, float]:
    """(width, thickness, z0) of the bridge bar: a moulded acetate saddle or a metal bar."""
    w, t = gl.rim if gl.design.rim != "rimless" else (0.0018, 0.0016)
    bar = 1.3 * w if gl.acetate else max(0.0018, 0.8 * w)
    tz = max(t, 0.0016)
    return bar, tz, (gl.face - tz) / 2


def bridge(gl: Glasses, side: int, material: str, start: float = 0.0) -> list[g.Piece]:
    """One side's half of the bridge bar, arching over the nose from ``start`` (y >= 0 on the +Y side) to the
    lens's upper nasal corner (and of an aviator's brow bar over it)."""
    w = gl.rim[0] if gl.design.rim != "rimless" else 0.0018
    bar, tz, z0 = _bridge_section(gl)
    nasal = _nasal_corner(gl, w / 2)
    y0 = gl.dbl / 2 + gl.eye / 2 + nasal[0] + 0.3 * w + (0.003 if gl.design.rim == "rimless" else 0.0)
    arch = 0.1 * gl.height / 2 * (1.0 if gl.acetate else 1.5)
    ys = np.linspace(start, y0, 5)
    xs = nasal[1] - 0.2 * bar + arch * (1 - (ys / y0) ** 2)
    out = [sweep(np.c_[xs, side * ys], rrect(bar, tz, 0.4 * min(bar, tz), z0), material, name="bridge")]
    if gl.design.brow and not gl.acetate:  # an aviator's brow bar, rim to rim over the lenses' tops
        yb = gl.dbl / 2 + 0.3 * gl.eye
        yy = np.linspace(start, yb, 5)
        xb = gl.height / 2 + 0.4 * w + 0.0015 * (1 - (yy / yb) ** 2)
        out.append(sweep(np.c_[xb, side * yy], rrect(0.0017, 0.0017, 0.0007, z0), material, name="brow_bar"))
    return out


def fold_knuckle(gl: Glasses, side: int, material: str) -> tuple[g.Piece, Frame]:
    """A folding front's bridge hinge: this side's barrel on the axis (along X over the bridge's crown, as high
    behind the front as the folded temples, which the halves close on) and its post down to the half bridge;
    the hinge frame (+ folds the -Y half up)."""
    bar, tz, z0 = _bridge_section(gl)
    nasal = _nasal_corner(gl, gl.rim[0] / 2)
    xk = nasal[1] - 0.2 * bar + 0.15 * gl.height / 2
    r = 0.0011
    zk = gl.hinge[2] + gl.temple_size[2] / 2 + 0.0014  # over the folded temples: they fold in between
    x0, x1 = (xk - 0.0026, xk - GAP) if side > 0 else (xk + GAP, xk + 0.0026)
    pts = [(x, r * math.cos(a), zk + r * math.sin(a)) for x in (x0, x1) for a in np.linspace(0, 2 * math.pi, 12)]
    pts += [(x, side * y, z) for x in (x0, x1) for y in (0.0014, 0.0030) for z in (z0, z0 + tz)]
    return hull(pts, material, "knuckle"), Frame.at((xk, 0.0, zk), z=(-1, 0, 0))


def end_piece(gl: Glasses, side: int, material: str) -> list[g.Piece]:
    """The end piece at the rim's temple side: a block down to the rim (on the lens, rimless) and the
    hinge's lower barrel on the axis; the temple's barrel stacks on it along X."""
    hx, hy, hz = gl.hinge_at(side)
    kl, rb = _knuckle_length(gl), gl.knuckle
    hh = max(gl.temple_size[0], 2 * kl)
    top = hz - rb - 0.0006
    inner = hy - 0.0035 - gl.rim[0] - (0.003 if gl.design.rim == "rimless" else 0.0)
    z0 = 0.0 if gl.design.rim != "rimless" else 0.0008
    block = sweep(np.array([(hx, side * inner), (hx, side * (hy + rb))]), rrect(hh, top - z0, 0.4 * min(hh, top - z0),
                                                                                   z0), material, name="end_piece")
    barrel = [(x, side * (hy + rb * math.cos(a)), hz + rb * math.sin(a)) for x in (hx - kl, hx - GAP)
              for a in np.linspace(0, 2 * math.pi, 12)]
    lug = barrel + [(x, side * y, top - 0.0005) for x in (hx - kl, hx - GAP) for y in (hy - rb, hy + rb)]
    return [block, hull(lug, material, "hinge")]


def _knuckle_length(gl: Glasses) -> float:
    return max(0.0014, 0.35 * gl.temple_size[0])


PAD_ARM = (0.0011, 0.007)
"""A nose pad's arm: 1.0-1.2 mm nickel-silver wire (m) and how far along the rim above the pad it is soldered
on (m); it runs back from the rim and bends in to the pad's clamp box (Hilco, Silhouette pad arms: 12-16 mm
long, the pad 5-7 mm behind the lens)."""


def nose_pad(gl: Glasses, side: int, metal: str, pad: str) -> list[g.Piece]:
    """A nose pad on its wire arm from the rim's nasal side: a 10 x 6 mm silicone oval facing the nose, the
    clamp box on its back and the arm bent from the rim back and in to the box."""
    cx, cy = -0.35 * gl.height / 2, side * (gl.dbl / 2 + 0.0008)
    cz = gl.face + 0.0045
    th = np.linspace(0, 2 * math.pi, 14, endpoint=False)
    n = np.array([0.0, -side * 0.8, 0.6])  # facing the nose and back toward the face
    along = np.array([1.0, 0.0, 0.0])
    up = np.cross(n, along)
    centre = np.array([cx, cy, cz])
    ring = [centre + 0.005 * math.cos(a) * along + 0.0028 * math.sin(a) * up + d * n
            for a in th for d in (0.0, 0.0012)]
    wire, rise = PAD_ARM
    r = wire / 2
    root = np.array([cx + rise, side * (gl.dbl / 2 + 0.0012 + gl.rim[0] / 2), gl.face / 2])
    box = centre - 0.0009 * n
    elbow = np.array([root[0] - 0.0015, side * (abs(box[1]) + 0.0024), box[2] - 0.0005])
    clamp = [box + sx * 0.0014 * along + sy * 0.0009 * up + sz * 0.0005 * n for sx in (-1, 1) for sy in (-1, 1)
             for sz in (-1, 1)]
    return [hull(ring, pad, "nose_pad"), hull(clamp, metal, "pad_box"),
            hull([q + dv for q in (root, elbow) for dv in _wire(r)], metal, "pad_arm"),
            hull([q + dv for q in (elbow, box) for dv in _wire(r)], metal, "pad_arm")]


def _wire(r: float) -> list[np.ndarray]:
    return [np.array([dx, dy, dz]) for dx in (-r, r) for dy in (-r, r) for dz in (-r, r)]


def front(gl: Glasses, sides: tuple[int, ...], slots: dict, label: str, bridge_from: float = 0.0) -> Assembly:
    """The front (or, folding, one half of it): lenses, rims, bridge, end pieces and nose pads of ``sides``;
    anchors ``hinge+`` / ``hinge-`` at the end pieces (z: the temple's opening axis, x: along the folded
    temple) and ``fold`` on a folding bridge."""
    pieces, anchors = [], {}
    frame = slots["frame"] if gl.design.rim != "rimless" else slots["metal"]
    for s in sides:
        pieces += [lens(gl, s, slots["lens"]), *rim(gl, s, frame, slots["pad"]),
                   *bridge(gl, s, frame, bridge_from), *end_piece(gl, s, frame)]
        if gl.design.pads and not gl.acetate:
            pieces += nose_pad(gl, s, slots["metal"], slots["pad"])
        if gl.design.fold:
            knuckle, anchors["fold"] = fold_knuckle(gl, s, slots["metal"])
            pieces.append(knuckle)
        hx, hy, hz = gl.hinge_at(s)
        anchors["hinge+" if s > 0 else "hinge-"] = Frame.at((hx, s * hy, hz), z=(-s, 0, 0), x=(0, -s, 0))
    return Assembly.single(label, pieces, anchors)


# -- temples ------------------------------------------------------------------------------------------
def temple_path(gl: Glasses) -> tuple[np.ndarray, int]:
    """The +Y temple's centreline folded (plan, from its barrel toward -Y) and the index where its ear bend
    begins. The bend starts at its usual share of the length (:data:`BEND`), earlier where needed so that
    by the other end piece it has dropped clear of that hinge (-X): a folded temple reaching past the other
    end piece passes under its hinge, as real ones do, not into the other temple's swing."""
    hx, hy, _ = gl.hinge
    h0, h1, _ = gl.temple_size
    rc = gl.knuckle + 0.0009
    clear = max(h0, 2 * _knuckle_length(gl)) / 2 + h1 / 2 + 0.0035  # the drop needed at the other hinge
    for share in np.linspace(1 - BEND, 0.5, 7):
        straight, turn = (1 - share) * gl.temple, min(math.radians(75.0), DROP * share / (1 - BEND))
        path = [(hx, y) for y in np.linspace(hy - rc, hy - straight, 6)]
        step = share * gl.temple / 6
        for k in range(1, 7):
            phi = turn * (k - 0.5) / 6
            x, y = path[-1]
            path.append((x - step * math.sin(phi), y - step * math.cos(phi)))
        path = np.array(path)
        beyond = path[:, 1] < -hy + rc + 0.002
        if not beyond.any() or np.interp(-hy + rc + 0.002, path[::-1, 1], path[::-1, 0]) < hx - clear:
            break
    return path, 5


def temple(gl: Glasses, side: int, frame: str, tip: str) -> Assembly:
    """The temple of the ``side`` end piece folded behind the front (pointing -side * Y), its ear bend
    dropping toward -X (:func:`temple_path`); its barrel on the hinge axis beside the end piece's. Anchor
    ``hinge`` as the end piece's."""
    hx, hy, hz = gl.hinge_at(side)
    h0, h1, t = gl.temple_size
    path, bend = temple_path(gl)
    path = path * [1, side]
    u = np.linspace(0, 1, len(path))
    secs = [rrect(h0 + (h1 - h0) * min(1.0, q / BEND), t, 0.45 * t, hz - t / 2) for q in u]
    pieces = [sweep(path, secs, frame, group=2, name="temple")]
    if not gl.acetate:  # the plastic temple tip (ear sock) over the metal wire's bend
        pieces.append(sweep(path[bend:], rrect(h1 + 0.001, t + 0.0011, 0.0009, hz - t / 2 - 0.00055), tip,
                            group=2, name="temple_tip"))
    pieces.append(_temple_knuckle(gl, side, frame))
    anchor = Frame.at((hx, side * hy, hz), z=(-side, 0, 0), x=(0, -side, 0))
    return Assembly.single("temple", pieces, {"hinge": anchor})


def over_slope(gl: Glasses, under: Assembly) -> float:
    """The angle (rad) the temple folded last rests at over the other, from its own hinge: its underside
    clears the first's top where the first first lies below it (0 where its hinge's :attr:`Glasses.lift`
    already does: it lies parallel on the other)."""
    hx, hy, _ = gl.hinge
    h0, _, t = gl.temple_size
    band = max(h0, 2 * _knuckle_length(gl)) / 2 + 0.001
    v = np.vstack([p.vertices for p in under.pieces])
    near = v[np.abs(v[:, 0] - hx) < band]
    r = float(np.min(near[:, 1] + hy)) if len(near) else gl.temple
    return math.asin(min(0.5, max(0.0, t + 0.0012 - gl.lift) / max(r, 1e-3)))


# -- a folding reader's telescoping temples -----------------------------------------------------------
TELESCOPE = (0.012, math.radians(60.0))
"""A folding reader's collapsed telescoping temple (Foster Grant Micro Vision, Peepers fold-flat readers): its
short ear bend's length (m) and turn; folded, each temple stays on its own half so that the front can fold
at the bridge."""


def telescoping_temple(gl: Glasses, side: int, frame: str, tip: str) -> Assembly:
    """The collapsed telescoping temple on the ``side`` end piece, folded: its tube ending short of the bridge,
    the rod inside it and the short ear bend beyond. Anchor ``hinge`` as the end piece's."""
    hx, hy, hz = gl.hinge
    h0, h1, t = gl.temple_size
    rc = gl.knuckle + 0.0009
    bend, turn = TELESCOPE
    end = 0.0022 + bend * math.cos(turn / 2)  # the tube's end: the bend beyond it stops short of the bridge
    tube = np.array([(hx, side * y) for y in np.linspace(hy - rc, end, 4)])
    pieces = [sweep(tube, rrect(h0, t, 0.45 * t, hz - t / 2), frame, name="temple"), _temple_knuckle(gl, side, frame)]
    rod = np.array([(hx, side * y) for y in np.linspace(hy - rc - 0.003, end - 0.0005, 3)])
    path = list(rod[-1:])
    for k in range(1, 5):
        phi = turn * (k - 0.5) / 4
        x, y = path[-1]
        path.append((x - bend / 4 * math.sin(phi), y - side * bend / 4 * math.cos(phi)))
    r = 0.42 * min(h0, t)
    pieces += [sweep(rod, rrect(0.8 * r, 0.8 * r, 0.3 * r, hz - 0.4 * r), frame, name="rod"),
               sweep(np.array(path), rrect(h1 + 0.001, t + 0.0008, 0.0009, hz - t / 2 - 0.0004), tip,
                     name="temple_tip")]
    anchor = Frame.at((hx, side * hy, hz), z=(-side, 0, 0), x=(0, -side, 0))
    return Assembly.single("temple", pieces, {"hinge": anchor})


def _temple_knuckle(gl: Glasses, side: int, frame: str) -> g.Piece:
    """The temple's barrel on the hinge axis (beside the end piece's) and its web to the temple."""
    hx, hy, hz = gl.hinge_at(side)
    t = gl.temple_size[2]
    kl, rb = _knuckle_length(gl), gl.knuckle
    barrel = [(x, side * (hy + rb * math.cos(a)), hz + rb * math.sin(a)) for x in (hx + GAP, hx + kl)
              for a in np.linspace(0, 2 * math.pi, 12)]
    web = [(x, side * (hy - rb - 0.0014), z) for x in (hx + GAP, hx + kl) for z in (hz - t / 2, hz + t / 2)]
    return hull(barrel + web, frame, "hinge")
