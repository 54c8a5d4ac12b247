"""Computer mice: a moulded shell with two hinged main buttons, a scroll wheel between them, side (thumb)
buttons, DPI buttons and a cable.

Local frame: the mouse stands on z = 0, its nose (the buttons' front) toward +x, its left side (the thumb
side of a right-handed mouse) toward +y. Along the length ``t`` runs from 0 at the back to 1 at the nose; a
cross-section at ``t`` is a superellipse dome ``z = h (1 - |u / b|^p)^(1/p)`` over the half-width ``b``.

Parts: the body is the palm (behind the buttons), the side walls beside the buttons and a core under them;
each main button is the dome's top between the wheel slot and the side wall, hinged across its rear edge
(its front presses down, ~1 mm at the tip, on a microswitch spring); the wheel turns on an axle across the
slot; side buttons stand proud of the left (and on ambidextrous mice the right) wall and press in; DPI buttons
stand on the top behind the wheel and press down. The body's collision is kept clear of every pressed
button (its hulls are clipped under and beside them), as the real shell's openings are.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame
from infmob_usd.grasps import Grasp

from .handtools import rrect, sweep


@dataclass(frozen=True)
class MouseDesign:
    """One kind of mouse, from real products (metres): length, width and height ranges, where the hump
    peaks (share of the length from the back), the section's squareness (superellipse exponent), the main
    buttons' share of the length, the wheel (radius, width) and the cable (radius; 0: wireless)."""

    length: tuple[float, float]
    width: tuple[float, float]
    height: tuple[float, float]
    peak: float
    square: float
    buttons: float
    wheel: tuple[float, float]
    cable: float


MICE = {
    # Dell MS116 (113 x 61 x 36 mm, 85 g), Logitech M100 (113 x 62 x 38 mm), Microsoft Basic Optical (113 x 58 x
    # 37 mm): symmetric corded office mice, a 3 mm PVC cable out of the nose
    "wired": MouseDesign((0.108, 0.116), (0.058, 0.063), (0.035, 0.039), 0.40, 2.3, 0.50, (0.0100, 0.0065), 0.0015),
    # Logitech M185 (99 x 60 x 39 mm, 75 g with its AA cell), M330 Silent (105 x 68 x 38 mm), M705 (109 x 71 x 43
    # mm): cordless, often shorter and higher in the back
    "wireless": MouseDesign((0.099, 0.110), (0.060, 0.068), (0.037, 0.042), 0.36, 2.2, 0.48, (0.0095, 0.0065), 0.0),
    # Logitech G502 HERO (132 x 75 x 40 mm, 121 g), Razer DeathAdder V2 (127 x 73 x 43 mm, 82 g), Razer Naga
    # Trinity (120 x 75 x 43 mm, 120 g, 2/7/12 side buttons), Logitech G Pro X Superlight (125 x 64 x 40 mm, 63 g):
    # braided 3.5 mm cable
    "gaming": MouseDesign((0.120, 0.132), (0.064, 0.075), (0.039, 0.043), 0.42, 2.9, 0.52, (0.0110, 0.0075),
                          0.00175),
}
"""Designs -> sizes (maker spec sheets named beside each)."""

MOUSE_DENSITY = 480.0
"""kg/m^3 a mouse's shell weighs as a solid (shell, board, sensor, cell over its volume): Dell MS116 85 g over
~136 cm^3 0.62 t/m^3, Logitech M185 75 g over ~127 cm^3 0.59, G502 121 g over ~218 cm^3 0.56, G Pro X Superlight
63 g over ~175 cm^3 0.36 (volumes as 0.55 x the bounding box of the listed sizes)."""
SHELL = 0.0022  # m, a main button's moulded shell (ABS, 1.8-2.5 mm on Logitech / Razer teardowns)
TIP_TRAVEL = 0.002  # m, a main button's tip to its stop (switch pretravel ~0.5 mm, overtravel to the shell 1-1.5 mm)
UNDER = 0.0014  # m, room under a main button beyond its tip travel
SLOT_GAP = 0.0012  # m, between the wheel and a button's inner edge; between parts at their seams
SEAM = 0.0008  # m, the seam between a button and the palm or a side wall
WHEEL_PROUD = 0.0035  # m, the wheel's top over the shell's centre line (G502 ~4 mm, M100 ~3 mm)
GRIP_DEPTH = 0.0015  # m, of the wheel's top a hand takes (it stands WHEEL_PROUD out of the shell)
WHEEL_AT = 0.45  # the wheel's centre as a share of the buttons' length from their back edge
SIDE = dict(proud=0.0028, travel=0.002, gap=0.0012, clear=0.0012)
"""Side buttons: stand 2.8 mm proud of the wall and press in 2 mm to their stop (G502, DeathAdder, Naga thumb
buttons: ~1 mm to the click, bottoming out 1.5-2 mm in; estimated, not measured)."""
DPI = dict(size=(0.0075, 0.0045), proud=0.0018, travel=0.0012)
"""DPI buttons behind the wheel: 7.5 x 4.5 mm caps, 1.8 mm proud, 1.2 mm to their stop (DeathAdder V2, G502;
estimated)."""
SNIPER = (0.011, 0.009)  # m, G502's sniper button (~11 x 9 mm), in front of the thumb buttons
SNIPER_ROOM = 0.06  # share of the length the thumb grid steps back to make room for it
FOOT = 0.0006  # m, the PTFE skates under the shell (0.6-0.8 mm)
THUMB_GRIDS = {2: 0.35, 3: 0.15, 4: 0.1, 6: 0.15, 7: 0.1, 12: 0.15}
"""Thumb buttons on a gaming mouse: 2 (DeathAdder, G Pro), 3 (Basilisk), 4 (G700s), 6, 7 and 12 (Razer Naga
Pro / Trinity side plates, Logitech G600)."""
GRID = {2: (1, 2), 3: (1, 3), 4: (2, 2), 6: (2, 3), 7: (2, 4), 12: (3, 4)}
"""Side-button count -> (rows, columns) of the thumb grid (the Naga Trinity's 7: a 2 x 4 grid less one)."""


@dataclass(frozen=True)
class Mouse:
    design: MouseDesign
    L: float
    W: float
    H: float
    peak: float
    squareness: float
    taper: float = 0.0  # 0: an office mouse's even plan; 1: an egg, narrowing to its nose (Logitech M185, M330)

    # -- the shell's shape -------------------------------------------------------------------------------
    def x(self, t):
        return (np.asarray(t) - 0.5) * self.L

    def t_of(self, x: float) -> float:
        return x / self.L + 0.5

    def end(self, t):
        return (1.0 - np.abs(2.0 * np.asarray(t) - 1.0) ** 3) ** (1.0 / 3.0)

    def half(self, t):
        """Half-width at ``t``: widest behind the middle, a waist where the thumb lies, rounded ends."""
        even, egg = np.array((0.9, 1.0, 0.93, 0.96, 0.9)), np.array((0.93, 1.0, 0.9, 0.84, 0.74))
        w = np.interp(t, (0.0, 0.3, 0.58, 0.85, 1.0), even + self.taper * (egg - even))
        return 0.5 * self.W * w * self.end(t)

    def height(self, t):
        h = 0.45 + 0.55 * np.exp(-((np.asarray(t) - self.peak) / 0.5) ** 2)
        return self.H * h * self.end(t) ** 0.35

    def ztop(self, t, u):
        """The dome's height above the shell's underside at across-position ``u``."""
        b = self.half(t)
        return self.height(t) * np.clip(1.0 - np.abs(np.asarray(u) / b) ** self.squareness, 0.0, 1.0) ** (
            1.0 / self.squareness)

    def dome(self, t, n: int = 24, u0: float | None = None, u1: float | None = None) -> np.ndarray:
        """``(n + 1, 2)`` (u, z) on the dome from ``u0`` (default +b) to ``u1`` (default -b)."""
        b = float(self.half(t))
        u0 = b if u0 is None else u0
        u1 = -b if u1 is None else u1
        a0 = math.acos(np.clip(np.sign(u0) * abs(u0 / b) ** (self.squareness / 2), -1, 1))
        a1 = math.acos(np.clip(np.sign(u1) * abs(u1 / b) ** (self.squareness / 2), -1, 1))
        th = np.linspace(a0, a1, n + 1)
        c, s = np.cos(th), np.sin(th)
        e = 2.0 / self.squareness
        return np.c_[b * np.sign(c) * np.abs(c) ** e, self.height(t) * np.abs(s) ** e]

    # -- where the parts lie -------------------------------------------------------------------------------
    @property
    def t_buttons(self) -> float:
        """``t`` of the main buttons' rear edge (their hinge)."""
        return 1.0 - self.design.buttons

    def u_edge(self, t) -> float:
        """A main button's outer edge: where the dome turns down into the side wall."""
        return 0.66 * self.half(t)

    @property
    def slot(self) -> float:
        """Half-width of the slot between the buttons: the wheel's half-width and its gap."""
        return self.design.wheel[1] / 2 + SLOT_GAP

    @property
    def wheel_centre(self) -> np.ndarray:
        t = self.t_buttons + WHEEL_AT * self.design.buttons
        return np.array([float(self.x(t)), 0.0, float(self.ztop(t, 0.0)) + WHEEL_PROUD - self.design.wheel[0]])

    def core_top(self, t) -> float:
        """The core's flat top under the buttons: below their lowest edge by the tip travel and some room."""
        return float(self.ztop(t, self.u_edge(t))) - SHELL - TIP_TRAVEL - UNDER


def mouse(design: str, size: float, width: float, height: float, peak: float, taper: float = 0.0) -> Mouse:
    """Sizes from the parameters, each a fraction (0..1) of its design's sourced range; ``peak`` moves the hump,
    ``taper`` (0..1) narrows the front half from an even plan to an egg's."""
    d = MICE[design]
    def lerp(r, f):
        return r[0] + f * (r[1] - r[0])

    return Mouse(d, lerp(d.length, size), lerp(d.width, width), lerp(d.height, height), d.peak + peak, d.square,
                 taper)


# -- meshes ------------------------------------------------------------------------------------------------
def _ts(t0: float, t1: float, n: int) -> np.ndarray:
    return t0 + (t1 - t0) * np.linspace(0.0, 1.0, n)


def _clip(poly: np.ndarray, a: float, b: float, c: float) -> np.ndarray:
    """The convex polygon ``poly`` ((k, 2) u, z) cut to ``a u + b z <= c`` (Sutherland-Hodgman)."""
    out = []
    k = len(poly)
    for i in range(k):
        p, q = poly[i], poly[(i + 1) % k]
        fp, fq = a * p[0] + b * p[1] - c, a * q[0] + b * q[1] - c
        if fp <= 0:
            out.append(p)
        if fp * fq < 0:
            out.append(p + (q - p) * (fp / (fp - fq)))
    return np.asarray(out).reshape(-1, 2)


def _ring3(m: Mouse, t: float, poly: np.ndarray, lift: float = FOOT) -> np.ndarray:
    return np.c_[np.full(len(poly), float(m.x(t))), poly[:, 0], poly[:, 1] + lift]


def _block(m: Mouse, ts: np.ndarray, cut, material: str, name: str, group: int = 3) -> g.Piece | None:
    """The shell between the sections ``ts`` cut by ``cut(t)`` (a list of half-planes ``(a, b, c)``): a mesh of
    the hulls of consecutive sections, colliding as hulls of ``group`` sections each."""
    rings = []
    for t in ts:
        poly = m.dome(t)
        for a, b, c in cut(t):
            poly = _clip(poly, a, b, c)
        if len(poly) >= 3:
            rings.append(_ring3(m, t, poly))
    if len(rings) < 2:
        return None
    vs, fs, n = [], [], 0
    for r0, r1 in zip(rings, rings[1:], strict=False):
        v, f = g.hull_arrays(np.vstack([r0, r1]))
        vs.append(v)
        fs.append(f + n)
        n += len(v)
    convex = [np.vstack(rings[i:i + group + 1]) for i in range(0, len(rings) - 1, group)]
    return g.Piece(np.vstack(vs), np.vstack(fs), material, convex, name, wall=0.0)


def _loft(rings: np.ndarray, material: str, name: str, convex, cap_strip: bool = False) -> g.Piece:
    """A closed mesh through ``rings`` ((s, k, 3)); the end caps fan from the ring's centre, or (``cap_strip``)
    pair the ring's first half with its second (a band whose top and underside run in opposite directions)."""
    s, k = rings.shape[:2]
    verts = [rings.reshape(-1, 3)]
    faces = []
    for a in range(s - 1):
        for i in range(k):
            j = (i + 1) % k
            faces += [(a * k + i, a * k + j, (a + 1) * k + j), (a * k + i, (a + 1) * k + j, (a + 1) * k + i)]
    if cap_strip:
        h = k // 2
        # a cap runs its ring edges against the side walls': the first ring's forwards, the last's backwards
        for base, flip in ((0, False), ((s - 1) * k, True)):
            for i in range(h - 1):
                quad = [(base + i, base + k - 1 - i, base + i + 1), (base + i + 1, base + k - 1 - i, base + k - 2 - i)]
                faces += [q[::-1] if flip else q for q in quad]
    else:
        centres = np.vstack([rings[0].mean(0), rings[-1].mean(0)])
        c0, c1 = s * k, s * k + 1
        verts.append(centres)
        last = (s - 1) * k
        for i in range(k):
            j = (i + 1) % k
            faces += [(c0, j, i), (c1, last + i, last + j)]
    v, f = np.vstack(verts), np.asarray(faces, np.int64)
    a, b, c = (v[f[:, i]] for i in range(3))
    if np.einsum("ij,ij->i", a, np.cross(b, c)).sum() < 0:
        f = f[:, ::-1].copy()
    return g.Piece(v, f, material, convex, name, wall=0.0)


# -- the body ------------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Zone:
    """A stretch ``(t0, t1)`` of the body whose collision is cut by ``planes`` ((a, b, c): a u + b z <= c, in
    the section's (u, z) above the skates), clear of the buttons pressed into it."""

    t0: float
    t1: float
    planes: tuple[tuple[float, float, float], ...]


def _convex(m: Mouse, t0: float, t1: float, base, zones: list[Zone], step: float = 0.006,
            group: int = 2) -> list[np.ndarray]:
    """Collision hulls of the shell between ``t0`` and ``t1``: cut by ``base(t)`` and, within each zone, its
    planes; hulls of ``group`` consecutive sections, never across a zone's edge."""
    cuts = sorted({*(z.t0 for z in zones if t0 < z.t0 < t1), *(z.t1 for z in zones if t0 < z.t1 < t1)})
    edges = [t0]
    for t in [*cuts, t1]:  # no stretch under a millimetre: its hulls would be flat
        if (t - edges[-1]) * m.L >= 0.001:
            edges.append(t)
    edges[-1] = t1
    out = []
    for a, b in zip(edges, edges[1:], strict=False):
        mid = 0.5 * (a + b)
        planes = [p for z in zones if z.t0 <= mid <= z.t1 for p in z.planes]
        n = max(2, int(math.ceil((b - a) * m.L / step)) + 1)
        rings = []
        for t in _ts(a, b, n):
            poly = m.dome(t)
            for pa, pb, pc in [*base(t), *planes]:
                poly = _clip(poly, pa, pb, pc)
            if len(poly) >= 3:
                rings.append(_ring3(m, t, poly))
        out += [np.vstack(rings[i:i + group + 1]) for i in range(0, max(1, len(rings) - 1), group)
                if len(rings[i:i + group + 1]) >= 2]
    return out


def _nose_ts(t0: float, n: int) -> np.ndarray:
    """Sections from ``t0`` to the nose, closer where the nose rounds off."""
    s = np.sin(0.5 * math.pi * np.linspace(0.0, 1.0, n))
    return t0 + (1.0 - 0.004 - t0) * s


def body(m: Mouse, zones: list[Zone], shell: str, feet: str) -> list[g.Piece]:
    """The palm, the side walls beside the buttons and the core under them, on four skates."""
    tb = m.t_buttons - SEAM / m.L
    palm_t = 0.004 + (tb - 0.004) * (0.5 - 0.5 * np.cos(math.pi * np.linspace(0.0, 1.0, 22)))
    palm = _loft(np.stack([_ring3(m, t, m.dome(t)) for t in palm_t]), shell, "palm",
                 _convex(m, 0.004, tb, lambda t: [], zones))
    pieces = [palm]
    ts = _nose_ts(m.t_buttons, 16)
    for s in (1, -1):
        def wall(t, s=s):
            us = float(m.u_edge(t)) + SEAM
            d = m.dome(t, 10, s * float(m.half(t)), s * us)
            return np.vstack([d, [(s * us, 0.0)]])
        rings = np.stack([_ring3(m, t, wall(t)) for t in ts])
        # hulls of two sections: over three, the wall's inner edge (curving in to the nose) is a chord that a
        # pressed button's outer edge dips 0.3-0.45 mm into, where MuJoCo's contact jams it past its stop
        pieces.append(_loft(rings, shell, "wall", _convex(m, m.t_buttons, 0.996, lambda t, s=s: [
            (-s, 0.0, -(float(m.u_edge(t)) + SEAM))], zones, group=1)))
    pieces += _core(m, zones, shell)
    for t in (0.1, 0.88):
        for s in (1, -1):
            c = (float(m.x(t)), s * 0.55 * float(m.half(t)), 0.0)
            pieces.append(g.cylinder(c, (c[0], c[1], FOOT + 0.0003), 0.0035, feet, 16, "skate"))
    return pieces


def _core(m: Mouse, zones: list[Zone], shell: str) -> list[g.Piece]:
    """The core under the buttons: two blocks beside the wheel slot, the slot's floor under the wheel and its
    ends before and behind the wheel."""
    ts = _nose_ts(m.t_buttons, 16)
    w = m.wheel_centre
    r = m.design.wheel[0]
    tw0, tw1 = m.t_of(w[0] - r - SLOT_GAP), m.t_of(w[0] + r + SLOT_GAP)
    floor = w[2] - FOOT - r - SLOT_GAP

    def top(t):
        return [(0.0, 1.0, m.core_top(t))]

    out = []
    for s in (1, -1):
        def cut(t, s=s):
            return [*top(t), (-s, 0.0, -m.slot), (s, 0.0, float(m.u_edge(t)) + SEAM)]

        out.append(_block(m, ts, cut, shell, "core"))
    centre = [(1.0, 0.0, m.slot), (-1.0, 0.0, m.slot)]
    under = [(0.0, 1.0, floor), *centre]
    out.append(_block(m, _ts(tw0, tw1, 6), lambda t: under, shell, "slot"))
    out.append(_block(m, _ts(m.t_buttons, tw0, 4), lambda t: [*top(t), *centre], shell, "slot"))
    out.append(_block(m, ts[ts > tw1] if (ts > tw1).sum() > 1 else _ts(tw1, 0.996, 3),
                      lambda t: [*top(t), *centre], shell, "slot"))
    return [p for p in out if p is not None]


# -- the moving parts --------------------------------------------------------------------------------------------
def main_button(m: Mouse, side: int, material: str, label: str) -> Assembly:
    """The left (``side`` +1) or right (-1) main button: the dome's top from the wheel slot to the side wall,
    a shell ``SHELL`` thick, hinged across its rear edge (anchor ``hinge``, z along +y: its front presses
    down)."""
    ts = _nose_ts(m.t_buttons, 16)
    rings = []
    for t in ts:
        top = m.dome(t, 10, side * m.slot, side * float(m.u_edge(t)))
        low = top - (0.0, SHELL)
        rings.append(_ring3(m, t, np.vstack([top, low[::-1]])))
    rings = np.stack(rings)
    convex = [np.vstack(rings[i:i + 2]) for i in range(len(rings) - 1)]
    piece = _loft(rings, material, "button", convex, cap_strip=True)
    tp = m.t_buttons + 0.65 * m.design.buttons  # a fingertip presses two-thirds of the way to the front
    up = side * 0.5 * (m.slot + float(m.u_edge(tp)))
    wide = float(m.u_edge(tp)) - m.slot
    at = (float(m.x(tp)), up, float(m.ztop(tp, up)) + FOOT)
    piece = piece.with_grasps(Grasp.make(at, (0, 0, -1), (0, 1, 0), wide, SHELL / 2))
    hinge_z = float(m.ztop(m.t_buttons, m.u_edge(m.t_buttons))) + FOOT - SHELL
    hinge = Frame.at((float(m.x(m.t_buttons)), 0.0, hinge_z), z=(0, 1, 0), x=(1, 0, 0))
    return Assembly.single(label, [piece], {"hinge": hinge})


def press_angle(m: Mouse) -> float:
    """A main button's travel (rad): its tip moves ``TIP_TRAVEL``."""
    return math.atan2(TIP_TRAVEL, m.design.buttons * m.L)


def wheel(m: Mouse, tyre: str, hub: str) -> Assembly:
    """The scroll wheel: a rubber tyre on a hub, turning about its axle across the slot (anchor ``axle``)."""
    r, w = m.design.wheel
    c = m.wheel_centre + (0.0, 0.0, FOOT)
    # a fingertip (or a gripper's pads, front and back) takes the tyre's top, where it stands out of the slot
    chord = 2.0 * math.sqrt(2.0 * r * GRIP_DEPTH)
    grasp = Grasp.make(c + (0, 0, r), (0, 0, -1), (1, 0, 0), chord, GRIP_DEPTH)
    pieces = [g.cylinder(c - (0, w / 2, 0), c + (0, w / 2, 0), r, tyre, None, "tyre").with_grasps(grasp),
              # the hub's faces inside the tyre's, seen through the slot (decoration)
              g.cylinder(c - (0, w / 2 + 1e-4, 0), c + (0, w / 2 + 1e-4, 0), 0.6 * r, hub, None, "hub").replace(
                  convex=())]
    return Assembly.single("wheel", pieces, {"axle": Frame.at(c, z=(0, 1, 0), x=(1, 0, 0))})


# -- side and DPI buttons -----------------------------------------------------------------------------------
@dataclass(frozen=True)
class Key:
    """A small button: its face's centre on the shell ``at`` (z out of the shell, x along the mouse), its face
    size (along x, along the shell's y) and how far it stands proud and presses in."""

    at: Frame
    size: tuple[float, float]
    proud: float
    travel: float


def _normal(m: Mouse, t: float, u: float, z: float) -> np.ndarray:
    """The section's outward normal (u, z) at a point of the dome: the gradient of (u/b)^p + (z/h)^p."""
    b, h, p = float(m.half(t)), float(m.height(t)), m.squareness
    n = np.array([np.sign(u) * abs(u / b) ** (p - 1) / b, (max(z, 0.0) / h) ** (p - 1) / h])
    return n / np.linalg.norm(n)


def on_wall(m: Mouse, t: float, z: float, side: int) -> Frame:
    """The frame on the left (``side`` +1) or right wall at ``t``, height ``z`` over the underside."""
    b, h, p = float(m.half(t)), float(m.height(t)), m.squareness
    u = side * b * max(0.0, 1.0 - (z / h) ** p) ** (1.0 / p)
    nu, nz = _normal(m, t, u, z)
    return Frame.at((float(m.x(t)), u, z + FOOT), z=(0.0, nu, nz), x=(1.0, 0.0, 0.0))


def thumb_grid(m: Mouse, count: int, side: int, sniper: bool) -> list[Key]:
    """``count`` thumb buttons in a grid (:data:`GRID`) on a wall, the front of the grip; with ``sniper`` a
    larger button in front of them (G502's sniper button)."""
    rows, cols = GRID[count]
    t0, t1 = 0.38, 0.66 if cols <= 2 else 0.72
    if sniper:  # the grid steps back to leave the sniper button room behind the nose's rounding
        t0, t1 = t0 - SNIPER_ROOM, t1 - SNIPER_ROOM
    # heights as shares of the shell's: the top row stays under the main buttons' edge when both are pressed
    z0, z1 = {1: (0.40, 0.62), 2: (0.26, 0.64), 3: (0.16, 0.66)}[rows]
    tc = 0.5 * (t0 + t1)
    h = float(m.height(tc))
    gap = SIDE["gap"]
    dx = ((t1 - t0) * m.L - (cols - 1) * gap) / cols
    dz = ((z1 - z0) * h - (rows - 1) * gap) / rows
    keys = []
    for r in range(rows):
        for c in range(cols):
            if count == 7 and r == 1 and c == cols - 1:
                continue
            t = t0 + ((c + 0.5) * (dx + gap)) / m.L
            z = z0 * h + (r + 0.5) * (dz + gap)
            keys.append(Key(on_wall(m, t, z, side), (dx, 0.9 * dz if rows > 1 else dz), SIDE["proud"],
                            SIDE["travel"]))
    if sniper:
        t = t1 + (0.004 + 0.5 * SNIPER[0]) / m.L
        keys.append(Key(on_wall(m, t, 0.5 * (z0 + z1) * h, side), SNIPER, SIDE["proud"], SIDE["travel"]))
    return keys


def dpi_keys(m: Mouse, count: int) -> list[Key]:
    """``count`` DPI buttons on the top's centre line behind the wheel, in a row along it."""
    out = []
    for k in range(count):
        x = float(m.x(m.t_buttons)) - 0.0035 - DPI["size"][0] / 2 - k * (DPI["size"][0] + 0.0025)
        t = m.t_of(x)
        out.append(Key(Frame.at((x, 0.0, float(m.ztop(t, 0.0)) + FOOT), z=(0, 0, 1), x=(1, 0, 0)), DPI["size"],
                       DPI["proud"], DPI["travel"]))
    return out


def key_part(k: Key, material: str, label: str) -> Assembly:
    """A small button standing ``proud`` of the shell at ``k.at``, pressed in (anchor ``press``, z into the
    shell), with a fingertip's press on its face."""
    sx, sy = k.size
    piece = g.box_between((-sx / 2, -sy / 2, -0.0005), (sx / 2, sy / 2, k.proud), material,
                          bevel=0.35 * min(k.proud, sy / 2))
    grasp = Grasp.make((0, 0, k.proud), (0, 0, -1), (0, 1, 0) if sy <= sx else (1, 0, 0), min(sx, sy), k.proud / 2)
    piece = piece.replace(wall=0.0).with_grasps(grasp).transformed(k.at.matrix)
    # pressed straight in, square to the mouse's side or top (a thumb pushes across the mouse, not along a tilted
    # face): the face's tilt then puts no weight along the press
    n = k.at.z * (np.abs(k.at.z) == np.abs(k.at.z).max())
    press = Frame.at(k.at.point((0, 0, k.proud)), z=-n / np.linalg.norm(n), x=k.at.x)
    return Assembly.single(label, [piece], {"press": press})


def zones_for(m: Mouse, keys: list[Key]) -> list[Zone]:
    """The body's collision cut clear of each key pressed home (its travel and a gap beyond it), over the
    key's length and a gap either side."""
    out = []
    for k in keys:
        c, n = k.at.origin, k.at.z
        half = k.size[0] / 2 + SIDE["gap"] + 0.001
        depth = 0.0005 + k.travel + SIDE["clear"]
        # a u + b z <= c in the section's (u, z) above the skates
        plane = (float(n[1]), float(n[2]), float(n[1] * c[1] + n[2] * (c[2] - FOOT)) - depth)
        out.append(Zone(m.t_of(c[0] - half), m.t_of(c[0] + half), (plane,)))
    return out


# -- the cable -------------------------------------------------------------------------------------------------------
def cable(m: Mouse, material: str, plug: str, metal: str, bend: float) -> list[g.Piece]:
    """A corded mouse's cable: a strain relief out of the nose, down to the table and off in a loose curve
    (``bend``: -1..1, which way) to a USB-A plug."""
    r = m.design.cable
    x0 = float(m.x(0.996))
    z0 = FOOT + 0.32 * float(m.height(0.9))
    relief = g.cylinder((x0 - 0.003, 0, z0), (x0 + 0.009, 0, z0), 1.6 * r, material, None, "relief")
    s = np.linspace(0.0, 1.0, 40)
    xs = x0 + 0.009 + 0.11 * s
    ys = bend * 0.03 * np.sin(math.pi * s) ** 2 * (1 - 0.5 * s)
    zc = r + (z0 - r) * np.exp(-(s / 0.06) ** 2)
    secs = [rrect(2 * r, 2 * r, r * 0.98, z - r, 2) for z in zc]
    wire = sweep(np.c_[xs, ys], secs, material, group=8, name="cable")
    end = np.array([xs[-1], ys[-1]])
    d = end - np.array([xs[-2], ys[-2]])
    d /= np.linalg.norm(d)
    frame = Frame.at((end[0], end[1], 0.004), z=(d[0], d[1], 0.0), x=(0, 0, 1))
    body_ = g.box_between((-0.004, -0.008, -0.003), (0.0044, 0.008, 0.03), plug, bevel=0.0015, name="plug")
    shell = g.box_between((-0.0022, -0.006, 0.03), (0.0022, 0.006, 0.042), metal, name="usb")
    return [relief, wire, body_.transformed(frame.matrix), shell.transformed(frame.matrix)]


def underside(m: Mouse, cover: str, switch: str) -> list[g.Piece]:
    """A cordless mouse's underside: its battery cover's panel and the power switch's slider (M185, M330: an
    AA cell under a clip-on cover; decoration, the shell collides)."""
    x0, x1 = float(m.x(0.22)), float(m.x(0.62))
    w = 0.55 * float(m.half(0.45))
    panel = g.box_between((x0, -w, FOOT - 0.0002), (x1, w, FOOT + 0.0001), cover, bevel=0.0001, name="cover")
    xs = float(m.x(0.78))
    knob = g.box_between((xs - 0.004, -0.0025, FOOT - 0.0003), (xs + 0.004, 0.0025, FOOT + 0.0001), switch,
                         name="switch")
    return [panel.replace(convex=()), knob.replace(convex=())]
