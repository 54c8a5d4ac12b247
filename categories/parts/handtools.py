"""Hand tools that lie flat on a table: scissors (and the sweeps their blades and handles are made of).

Local frame: the tool lies on z = 0 with its pivot screw on the z axis, its blades (or jaws) along +x and
its handles along -x. A half is a flat steel plate (blade, boss and tang) and a handle: moulded plastic
shanks and finger loops on office, kitchen and pinking shears, forged steel rings on embroidery scissors.

Rest pose: flat on the side, the fixed half (``body``) lying on the table, the moving half stacked on it at
the pivot screw with its handle beside the other's, on the table too (as scissors lie on a desk); the moving
half turns about the screw (+z) to open: its blade swings to +y, its loop away from the other loop.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import IDENTITY, Frame

BLADE_GAP = 0.0003  # m, between the stacked blades: the pivot screw holds them in light contact (0.1-0.3 mm play)
SEP = 0.0025  # m, between the two handles where they lie side by side, closed
TIP = 0.0008  # m, width left at a pointed tip (a sharpened point is ~0.5-1 mm across at 1 mm from its end)


# -- sweeps -------------------------------------------------------------------------------------------
def rrect(width: float, height: float, radius: float, z0: float = 0.0, n: int = 3) -> np.ndarray:
    """``(4 (n + 1), 2)`` rounded rectangle in (across, z), counter-clockwise, centred across, from ``z0``."""
    r = min(radius, 0.49 * width, 0.49 * height)
    out = []
    for cu, cz, a0 in ((width / 2 - r, height - r, 0.0), (-width / 2 + r, height - r, 90.0),
                       (-width / 2 + r, r, 180.0), (width / 2 - r, r, 270.0)):
        for a in np.radians(a0 + np.linspace(0.0, 90.0, n + 1)):
            out.append((cu + r * math.cos(a), z0 + cz + r * math.sin(a)))
    return np.array(out)


def sweep(path, sections, material: str, closed: bool = False, group: int = 1, wall: float = 0.0,
          name: str = "") -> g.Piece:
    """A solid swept along the plan polyline ``path`` (``(k, 2)``, on z = 0): at each point the convex
    cross-section ``sections[i]`` (``(m, 2)``: across (along the path's left normal), z) stands square to
    the path. Open sweeps are capped; ``closed`` joins the last section to the first (a ring). Every
    ``group`` segments make one convex collision piece (the hull of their sections)."""
    p = np.asarray(path, float)
    s = np.asarray(sections, float)
    if s.ndim == 2:
        s = np.repeat(s[None], len(p), axis=0)
    k, m = s.shape[:2]
    d = (np.roll(p, -1, 0) - np.roll(p, 1, 0)) if closed else np.gradient(p, axis=0)
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    left = np.c_[-d[:, 1], d[:, 0]]
    rings = np.concatenate([p[:, None, :] + s[:, :, :1] * left[:, None, :], s[:, :, 1:]], axis=2)
    verts = rings.reshape(-1, 3)
    faces = []
    for a in range(k if closed else k - 1):
        b = (a + 1) % k
        for i in range(m):
            j = (i + 1) % m
            faces += [(a * m + i, a * m + j, b * m + j), (a * m + i, b * m + j, b * m + i)]
    if not closed:
        c0, c1 = k * m, k * m + 1
        verts = np.vstack([verts, rings[0].mean(0), rings[-1].mean(0)])
        last = (k - 1) * m
        for i in range(m):
            j = (i + 1) % m
            faces += [(c0, j, i), (c1, last + i, last + j)]
    f = np.asarray(faces, np.int64)
    a, b, c = (verts[f[:, i]] for i in range(3))
    if np.einsum("ij,ij->i", a, np.cross(b, c)).sum() < 0:
        f = f[:, ::-1].copy()
    ends = list(range(0, k - 1, group)) if not closed else list(range(0, k, group))
    convex = [np.vstack([rings[(i + q) % k] for q in range(min(group, (k - 1 - i) if not closed else group) + 1)])
              for i in ends]
    return g.Piece(verts, f, material, convex, name, wall=wall)


def hull(points, material: str, name: str = "") -> g.Piece:
    """The convex hull of ``points`` as a solid piece (its own collision piece)."""
    v, f = g.hull_arrays(np.asarray(points, float))
    return g.Piece(v, f, material, [v], name, wall=0.0)


def disc_points(center, radius: float, z0: float, z1: float, n: int = 16) -> np.ndarray:
    th = 2 * math.pi * np.arange(n) / n
    xy = np.c_[center[0] + radius * np.cos(th), center[1] + radius * np.sin(th)]
    return np.vstack([np.c_[xy, np.full(n, z0)], np.c_[xy, np.full(n, z1)]])


def ellipse(center, ax: float, ay: float, n: int = 24) -> np.ndarray:
    """``(n, 2)`` points of an ellipse, counter-clockwise from +x."""
    th = 2 * math.pi * np.arange(n) / n
    return np.c_[center[0] + ax * np.cos(th), center[1] + ay * np.sin(th)]


# -- scissors -----------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ScissorDesign:
    """One kind of scissors, from real products (sizes in metres)."""

    length: tuple[float, float]  # overall, tip to the back of the loops
    blade: float  # blade length (pivot to tip) as a share of the overall length
    width: float  # width of one blade at the pivot
    thick: float  # blade plate thickness
    thumb: tuple[float, float]  # thumb loop opening (x, y)
    finger: tuple[float, float]  # finger loop opening (x, y)
    ring: tuple[float, float]  # loop wall: width in plan, height
    handle: str  # "plastic" moulded handles or "metal" forged rings
    tip: str  # "pointed" or "round"
    teeth: float = 0.0  # pinking teeth pitch (0: a plain edge)
    opener: bool = False  # a bottle-opener hook between the handles
    opens: float = 60.0  # degrees the blades open before a loop meets the other half's tang


SCISSORS = {
    # Fiskars 8" All-Purpose (203 mm, ~70 g), Westcott 7-9" office scissors (178-229 mm): blades 85-100 mm, 15-17 mm
    # wide at the pivot, 2 mm stainless plate; a round thumb loop ~22 mm and a 2-3 finger loop ~45 x 20 mm
    "office": ScissorDesign((0.178, 0.229), 0.45, 0.016, 0.002, (0.022, 0.018), (0.046, 0.020), (0.0055, 0.0075),
                            "plastic", "pointed"),
    # KitchenAid all-purpose shears (221 mm, ~95 g), Wüsthof 5558 (205 mm): 2.5 mm blades 20 mm wide, two large
    # symmetric loops, a bottle opener and nutcracker notch moulded between the handles
    "kitchen": ScissorDesign((0.200, 0.225), 0.42, 0.020, 0.0025, (0.040, 0.022), (0.046, 0.022), (0.006, 0.008),
                             "plastic", "round", opener=True, opens=55.0),
    # Fiskars 9" pinking shears (229 mm, ~170 g): 4 mm blades 20 mm wide cutting a 5 mm zigzag
    "pinking": ScissorDesign((0.215, 0.235), 0.42, 0.020, 0.004, (0.024, 0.020), (0.050, 0.022), (0.0065, 0.009),
                             "plastic", "round", teeth=0.005, opens=50.0),
    # Gingher 4" embroidery scissors (102 mm, ~20 g), Fiskars 4": 1.5 mm blades 8 mm wide, 40 mm long, round 14 mm
    # forged rings
    "embroidery": ScissorDesign((0.090, 0.115), 0.36, 0.0085, 0.0015, (0.015, 0.014), (0.016, 0.014),
                                (0.003, 0.0028), "metal", "pointed", opens=50.0),
}
"""Designs -> sizes (retail listings and maker spec sheets named beside each)."""


@dataclass(frozen=True)
class Scissors:
    design: ScissorDesign
    length: float
    blade: float  # pivot to tip
    width: float

    @property
    def layer(self) -> float:
        """z of the moving half's blade underside."""
        return self.design.thick + BLADE_GAP


def scissors(design: str, size: float, blade_share: float) -> Scissors:
    """Sizes of one pair: ``size`` (0-1) within the design's length range; ``blade_share`` (+-) moves the
    blade's share of the length."""
    d = SCISSORS[design]
    length = d.length[0] + size * (d.length[1] - d.length[0])
    return Scissors(d, length, length * (d.blade + blade_share), d.width * (0.9 + 0.2 * size))


def _blade_sections(s: Scissors, side: int, z0: float) -> tuple[np.ndarray, np.ndarray]:
    """Plan path and cross-sections of one blade (x from the pivot to the tip); ``side`` +1: the lower
    blade, its edge toward +y and its flat inner face on top; -1: the upper one, mirrored."""
    d, t = s.design, s.design.thick
    if d.teeth:
        xs = np.arange(0.0, s.blade, d.teeth / 2)
    else:
        xs = np.linspace(0.0, s.blade, 16)
    xs = np.append(xs[xs < s.blade - 1e-4], s.blade)
    u = xs / s.blade
    if d.tip == "pointed":
        width = TIP + (s.width - TIP) * (1 - u) ** 0.9
    else:
        width = np.maximum(TIP, s.width * np.sqrt(np.clip(1 - u ** 2.2, 0, 1)) * (1 - 0.35 * u))
    edge = 0.32 * s.width * (1 - u)  # the edges cross at the pivot and meet at the tips, closed
    if d.teeth:
        edge = edge - (np.arange(len(xs)) % 2) * 0.35 * d.teeth * (u < 0.97)
        width = np.maximum(width, 0.8 * d.teeth)
    secs = []
    for e, w in zip(edge, width, strict=True):
        bev = min(0.0015, 0.4 * w)
        poly = [(e - w, 0.0), (e - bev, 0.0), (e, 0.5 * t), (e, t), (e - w, t)]
        secs.append([(side * a, z0 + (b if side > 0 else t - b)) for a, b in poly])
    # the upper blade mirrored (two reflections keep the winding)
    return np.c_[xs, np.zeros_like(xs)], np.asarray(secs)


def _handle_frame(s: Scissors, side: int, loop: tuple[float, float]) -> tuple[np.ndarray, float, float]:
    """The loop's centre (plan), its centreline's semi-axes."""
    d = s.design
    ax, ay = loop[0] / 2 + d.ring[0] / 2, loop[1] / 2 + d.ring[0] / 2
    xc = -(s.length - s.blade - ax - d.ring[0] / 2)
    yc = SEP / 2 + ay + d.ring[0] / 2
    return np.array([xc, side * yc]), ax, ay


def scissor_half(s: Scissors, side: int, metal: str, grip: str, screw: str) -> Assembly:
    """One half: the lower (``side`` +1, the body) or the upper (-1) blade with its handle and loop."""
    d, t = s.design, s.design.thick
    z0 = 0.0 if side > 0 else s.layer
    path, secs = _blade_sections(s, side, z0)
    pieces = [sweep(path, secs, metal, group=max(1, len(path) // 6), name="blade")]
    boss = 0.5 * s.width
    loop = d.thumb if side > 0 else d.finger
    centre, ax, ay = _handle_frame(s, side, loop)
    front = centre + np.array([ax, 0.0])
    tang = min(0.45 * abs(front[0]), 0.022 if d.handle == "plastic" else 0.6 * abs(front[0]))
    grip_w = 0.8 * d.ring[0] + 0.0035 if d.handle == "plastic" else 1.4 * d.ring[0]
    reach = (boss * 0.6 + grip_w / 2 + 0.0025) / 2
    p1 = np.array([-tang, side * max(reach, 0.35 * abs(centre[1]))])
    pieces.append(hull(np.vstack([disc_points((0, 0), boss, z0, z0 + t), disc_points(p1, 0.6 * boss, z0, z0 + t, 12)]),
                      metal, "tang"))
    h = d.ring[1]
    shank = np.array([p1 + (p1 / np.linalg.norm(p1)) * -0.002, front])
    # the upper half's handle is carried by the screw just clear of the table (it would drag on it)
    grip_sec = rrect(grip_w, h, 0.35 * min(grip_w, h), z0)
    mat = grip if d.handle == "plastic" else metal
    pieces.append(sweep(shank, grip_sec, mat, name="shank"))
    ring = ellipse(centre, ax, ay, 28)
    pieces.append(sweep(ring, rrect(d.ring[0], h, 0.4 * min(d.ring), z0), mat, closed=True, group=2, name="loop"))
    if side < 0:  # the pivot screw's head on the upper blade (round: it turns with it or not, alike)
        pieces.append(g.cylinder((0, 0, z0 + t - 1e-4), (0, 0, z0 + t + 0.0012), 0.55 * boss, screw, name="screw"))
    if d.opener and side > 0:
        pieces.append(_opener(shank, grip_w, h, metal))
    return Assembly.single("body" if side > 0 else "blade", pieces, {"pivot": IDENTITY})


def _opener(shank: np.ndarray, grip_w: float, h: float, metal: str) -> g.Piece:
    """A bottle-opener hook on the lower handle's inner side, between the handles (kitchen shears):
    a steel tooth whose hooked tip catches a crown cap's skirt."""
    a, b = shank
    mid = a + 0.45 * (b - a)
    along = (b - a) / np.linalg.norm(b - a)
    inward = np.array([-along[1], along[0]])
    inward = -inward if inward[1] > 0 else inward  # toward -y, where the other handle lies
    root = mid + inward * grip_w / 2
    tip = root + inward * 0.003 + along * 0.004
    pts = [root - along * 0.004, root + along * 0.005, tip, tip - along * 0.0015]
    z0, z1 = 0.15 * h, 0.85 * h
    return hull([(x, y, z) for x, y in pts for z in (z0, z1)], metal, "opener")


# -- pliers -------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class PlierDesign:
    """One kind of pliers, from real products (sizes in metres): the halves lie flat, stacked at the pivot
    (each half's plate there is half the tool's thickness) and side by side at the jaws and handles."""

    length: tuple[float, float]  # overall, jaw tip to handle end
    jaw: float  # pivot to jaw tip, as a share of the length
    jaw_width: float  # one jaw's width at its root
    tip: float  # one jaw's width at its tip
    thick: float  # the tool's thickness lying flat
    grip: float  # handle grip width
    opens: float  # degrees the jaws open
    slip: float = 0.0  # slip joint: travel of the pivot between the slot's two holes (0: a fixed rivet)
    lever: bool = False  # a locking plier's release lever on the moving handle


PLIERS = {
    # Knipex 03 02 180 / 200 combination pliers: 180-200 mm, 10 mm thick, jaws 35-40 mm with a cutter
    "combination": PlierDesign((0.160, 0.200), 0.21, 0.011, 0.006, 0.010, 0.016, 30.0),
    # Knipex 26 12 200 needle-nose (snipe nose) pliers: 160-200 mm, long jaws tapering to ~2 mm tips
    "needle_nose": PlierDesign((0.160, 0.200), 0.33, 0.009, 0.0012, 0.009, 0.015, 25.0),
    # Channellock 526 / Irwin 6-8 in slip-joint pliers: 160-200 mm; the pivot moves 5-7 mm between two holes
    "slip_joint": PlierDesign((0.160, 0.200), 0.22, 0.011, 0.005, 0.009, 0.015, 28.0, slip=0.006),
    # Irwin Vise-Grip 7WR / 10WR locking pliers: 180-250 mm; a release lever inside the lower handle
    "locking": PlierDesign((0.180, 0.240), 0.20, 0.012, 0.005, 0.011, 0.014, 25.0, lever=True),
}
"""Designs -> sizes (maker catalogues named beside each)."""

PIVOT_RADIUS = 0.55  # the pivot plate's radius as a share of the tool's width at the pivot (two jaw widths)
LEVER = (0.045, 0.006, 0.004, 20.0)  # release lever: length, width, thickness (m), travel (degrees); Vise-Grip


@dataclass(frozen=True)
class Pliers:
    design: PlierDesign
    length: float
    jaw: float

    @property
    def pivot(self) -> float:
        return PIVOT_RADIUS * 2 * self.design.jaw_width

    @property
    def lift(self) -> float:
        """z of the moving half's underside away from the pivot: clear of the table."""
        return 0.001


def pliers(design: str, size: float) -> Pliers:
    d = PLIERS[design]
    length = d.length[0] + size * (d.length[1] - d.length[0])
    return Pliers(d, length, d.jaw * length)


def _jaw(p: Pliers, side: int, z0: float, z1: float, metal: str) -> g.Piece:
    """One jaw from the pivot plate to its tip, its gripping face on y = 0 (the lower half's toward +y
    from below it, the upper's from above it)."""
    d = p.design
    # clear of the other half's pivot plate, also where a slip joint has moved the upper half back
    xs = np.linspace(p.pivot * 1.08 + (d.slip if side < 0 else 0.0), p.jaw, 10)
    u = (xs - xs[0]) / (xs[-1] - xs[0])
    width = d.jaw_width + (d.tip - d.jaw_width) * u ** 0.8
    gap = 0.0004
    secs = [[(-side * gap, z0), (-side * (gap + w), z0 + 0.15 * (z1 - z0)), (-side * (gap + w), z1 - 0.15 * (z1 - z0)),
             (-side * gap, z1)] for w in width]
    secs = [s if side < 0 else s[::-1] for s in secs]
    return sweep(np.c_[xs, np.zeros_like(xs)], np.asarray(secs), metal, group=3, name="jaw")


def plier_half(p: Pliers, side: int, metal: str, grip: str) -> Assembly:
    """One half: the lower (``side`` +1, the body: jaw toward -y, handle toward +y) or the upper (-1)."""
    d = p.design
    t = d.thick
    lo, hi = (0.0, t) if side > 0 else (p.lift, t + BLADE_GAP)
    plate = (0.0, t / 2) if side > 0 else (t / 2 + BLADE_GAP, t + BLADE_GAP)
    reach = p.pivot * 1.1 + (d.slip if side < 0 else 0.0)
    jaw_root = [(reach, -side * (0.0004 + w), z) for w in (0.0, d.jaw_width) for z in plate]
    jaw_root += [(0.5 * p.pivot, y, z) for _, y, z in jaw_root]  # the plate's web out to the jaw, on its own side
    pieces = [hull(disc_points((0, 0), p.pivot, *plate, 20), metal, "pivot_plate"), hull(jaw_root, metal, "web"),
              _jaw(p, side, lo, hi, metal)]
    hl = p.length - p.jaw
    end = np.array([-hl, side * (SEP / 2 + d.grip * 0.7)])
    # the handle's root just outside the other half's pivot plate; the neck to it in this half's own layer
    root = -p.pivot * 1.15 - 0.45 * d.grip - d.slip
    root = np.array([root * 0.8, side * -root * 0.6])
    neck = np.vstack([disc_points((0, 0), 0.8 * p.pivot, *plate, 12), disc_points(root, 0.45 * d.grip, *plate, 12)])
    pieces.append(hull(neck, metal, "neck"))
    bow = root + (end - root) * 0.5 + np.array([0.0, side * 0.25 * d.grip])
    path = np.array([root, root + (bow - root) * 0.5, bow, bow + (end - bow) * 0.5, end])
    secs = [rrect(d.grip * (0.75 + 0.25 * k / 4), hi - lo + 0.002, 0.004, lo - 0.001 if side > 0 else lo)
            for k in range(5)]
    pieces.append(sweep(path, secs, grip, group=2, name="grip"))
    if d.lever and side > 0:  # a locking plier's knurled adjusting screw out of the fixed handle's end
        out = (end - bow) / np.linalg.norm(end - bow)
        mid = (lo + hi) / 2
        pieces.append(g.cylinder((*(end - 0.004 * out), mid), (*(end + 0.014 * out), mid), 0.42 * (hi - lo), metal,
                                 name="adjuster"))
    anchors = {"pivot": IDENTITY, "slot": Frame.at((0, 0, 0), z=(-1, 0, 0)),
               "lever": Frame.at((end[0] + 0.006, end[1] - LEVER[1] / 2, hi + 0.0015))}
    return Assembly.single("body" if side > 0 else "jaw", pieces, anchors)


def rivet(p: Pliers, metal: str) -> Assembly:
    """The slip joint's pivot bolt and nut (it slides between the slot's two holes)."""
    t = p.design.thick
    top = t + 2 * BLADE_GAP  # just clear of the upper half it holds
    head = g.cylinder((0, 0, top), (0, 0, top + 0.0015), 0.4 * p.pivot, metal, name="bolt")
    return Assembly.single("pivot", [head], {"pivot": IDENTITY, "slot": Frame.at((0, 0, 0), z=(-1, 0, 0))})


def release_lever(p: Pliers, metal: str) -> Assembly:
    """A locking plier's release lever lying along the upper handle, hinged at its end (+z at the hinge)."""
    length, width, thick, _ = LEVER
    body = hull([(x, y, z) for x in (0.0, length) for y in (0.0, width) for z in (0.0, thick)], metal, "lever")
    return Assembly.single("lever", [body], {"hinge": IDENTITY})


# -- staplers -----------------------------------------------------------------------------------------
@dataclass(frozen=True)
class StaplerDesign:
    """One kind of stapler (metres): a base carrying the anvil, a staple magazine (channel) and a top arm
    hinged on one rear pin; the head stands ``rise`` above the anvil on its spring at rest."""

    length: tuple[float, float]  # overall
    width: float
    base: float  # base height
    magazine: float  # channel height
    arm: float  # top arm height (mid-length, where it is arched highest)
    rise: float  # the head's clearance over the anvil at rest


STAPLERS = {
    # Swingline 747 (206 x 44 x 66 mm, ~590 g), Rapid S27, Leitz 5502: full-strip desk staplers
    "desk": StaplerDesign((0.160, 0.210), 0.042, 0.009, 0.012, 0.018, 0.008),
    # Swingline long-reach (12 in throat: ~0.37 m long), Rapid 'Long Arm' 0.30-0.45 m, ~1.1 kg
    "long_reach": StaplerDesign((0.300, 0.420), 0.045, 0.010, 0.012, 0.018, 0.010),
    # Swingline 101 / Rapid K1 plier staplers: 150-190 mm on a slim lower handle
    "plier": StaplerDesign((0.150, 0.190), 0.026, 0.011, 0.010, 0.014, 0.004),
}
"""Designs -> sizes (maker listings named beside each)."""


@dataclass(frozen=True)
class Stapler:
    design: StaplerDesign
    length: float

    @property
    def pin(self) -> np.ndarray:
        """The rear hinge pin's point (its axis is y)."""
        d = self.design
        return np.array([0.012, 0.0, d.base + d.rise + d.magazine / 2])

    @property
    def deck(self) -> float:
        """z of the magazine's underside."""
        return self.design.base + self.design.rise


def stapler(design: str, size: float) -> Stapler:
    d = STAPLERS[design]
    return Stapler(d, d.length[0] + size * (d.length[1] - d.length[0]))


def _bar(x0: float, x1: float, width, height, z0: float, material: str, radius: float, name: str,
         n: int = 2, wall: float | None = None) -> g.Piece:
    """A rounded bar along x; ``width`` and ``height`` are numbers or functions of the fraction along it.
    Massed as a shell of its material's wall (a pressed-steel or moulded casing) unless ``wall`` says."""
    xs = np.linspace(x0, x1, n)
    u = (xs - x0) / (x1 - x0)
    w = [width(t) if callable(width) else width for t in u]
    h = [height(t) if callable(height) else height for t in u]
    secs = [rrect(a, b, radius, z0) for a, b in zip(w, h, strict=True)]
    return sweep(np.c_[xs, np.zeros_like(xs)], secs, material, group=max(1, n // 4), name=name).replace(wall=wall)


def stapler_base(s: Stapler, body: str, steel: str, pad: str) -> Assembly:
    """The base (the lower handle of a plier stapler) with its anvil under the head's front and the rear
    cheeks that carry the hinge pin."""
    d, L, W = s.design, s.length, s.design.width
    pieces = [_bar(0.0, L, W, d.base - 0.0015, 0.0015, body, 0.003, "base"),
              _bar(0.004, L - 0.004, W - 0.004, 0.0015, 0.0, pad, 0.0006, "pad")]
    pieces += _anvil(L - 0.012, d.base, steel, pad)
    for side in (-1, 1):  # cheeks outside the arm's ears
        y0, y1 = sorted((side * 0.44 * W, side * W / 2))
        pieces.append(hull([(x, y, z) for x in (0.0, 0.024) for y in (y0, y1) for z in (d.base - 0.001,
                            s.pin[2] + 0.004)], body, "cheek"))
    pin = Frame.at(s.pin, z=(0, -1, 0))  # +rotation lifts the front
    return Assembly.single("body", pieces, {"pin": pin, "closing": Frame.at(s.pin, z=(0, 1, 0))})


def stapler_magazine(s: Stapler, steel: str, body: str) -> Assembly:
    """The staple channel (0.8-1 mm chromed steel U-channel, massed as its sheet) with its pull tab in front."""
    d, L = s.design, s.length
    w = 0.5 * d.width
    top = s.deck + d.magazine + 0.0003  # under the arm
    pieces = _channel(s, 0.006, L - 0.01, w, steel, body) + [
        # the driver housing over the anvil: the magazine's front cap, pulled to load
        _bar(L - 0.0105, L + 0.002, 1.1 * w, top - s.deck + 0.0015, s.deck - 0.0015, body, 0.002, "nose")]
    slide = Frame.at((L + 0.002, 0.0, s.deck + d.magazine / 2), z=(1, 0, 0))  # pulled out of the front to load
    return Assembly.single("magazine", pieces, {"pin": Frame.at(s.pin, z=(0, -1, 0)), "slide": slide})


def stapler_arm(s: Stapler, body: str) -> Assembly:
    """The top arm (the cover a hand presses): an arched cap along its length with side skirts down over the
    magazine (a real cover hides the channel: opened, it reads as a shell), its rear ears round the pin outside
    the magazine."""
    d, L, W = s.design, s.length, s.design.width
    z0 = s.deck + d.magazine + 0.0008
    def arch(t: float) -> float:  # highest a third of the way along, lowest over the nose
        return d.arm * (0.7 + 0.3 * math.sin(math.pi * min(1.0, 1.2 * t)))

    def half(t: float) -> float:  # the cap narrows a little to its nose
        return 0.43 * W * (1 - 0.12 * t)

    top = _bar(0.002, L + 0.002, lambda t: 2 * half(t), arch, z0, body, 0.35 * d.arm, "arm", n=12)
    pieces = [top] + [_skirt(s, side, half, z0 + 0.3 * d.arm, body) for side in (-1, 1)]
    for side in (-1, 1):
        y0, y1 = sorted((side * (0.25 * W + 0.0012), side * 0.42 * W))
        ear = [(x, y, z) for x in (0.003, 0.022) for y in (y0, y1) for z in (s.pin[2] - 0.004, z0 + 0.001)]
        pieces.append(hull(ear, body, "ear"))
    return Assembly.single("arm", pieces, {"pin": Frame.at(s.pin, z=(0, -1, 0)),
                                           "closing": Frame.at(s.pin, z=(0, 1, 0))})


SKIRT = 0.0015  # m, a cover's side skirt (1-1.5 mm pressed steel or 1.5-2 mm moulded plastic)
STAPLES = (0.6, 0.0055)  # a staple strip's width (share of the channel's) and height (m): 26/6 staples, 12.7 x 6 mm


def _skirt(s: Stapler, side: int, half, z1: float, body: str) -> g.Piece:
    """One side skirt of the cover, inside its cap's edge, from behind the base's cheeks to the nose, down
    to just above the magazine's underside."""
    L = s.length
    xs = np.linspace(0.026, L, 8)
    ys = [side * (half((x - 0.002) / L) - SKIRT / 2 - 0.0008) for x in xs]
    z0 = s.deck + 0.001
    sec = rrect(SKIRT, z1 - z0, 0.0005, z0)
    return sweep(np.c_[xs, ys], sec, body, group=7, name="skirt")  # a solid plate


def _channel(s: Stapler, x0: float, x1: float, w: float, steel: str, body: str) -> list[g.Piece]:
    """The staple channel: a U of chromed sheet (floor and two walls, massed as their sheet) with a strip of
    staples along it and the pusher (follower) that drives the strip forward, at its rear."""
    d = s.design
    t = 0.0009  # 20 ga sheet
    floor = _bar(x0, x1, w, t, s.deck, steel, 0.0003, "channel").replace(sheet=t)
    walls = [g.box_between((x0, y0, s.deck), (x1, y0 + t, s.deck + d.magazine), steel).replace(sheet=t)
             for y0 in (-w / 2, w / 2 - t)]
    sw, sh = STAPLES[0] * w, min(STAPLES[1], d.magazine - t - 0.0005)
    pusher = 0.018
    strip = g.box_between((x0 + pusher + 0.002, -sw / 2, s.deck + t), (x1 - 0.002, sw / 2, s.deck + t + sh), steel,
                          bevel=0.0003).replace(wall=0.0003)  # the wire's section, not a solid block
    follower = g.box_between((x0 + 0.002, -sw / 2, s.deck + t), (x0 + pusher, sw / 2, s.deck + t + sh), body,
                             bevel=0.001).replace(wall=0.001)
    return [floor, *walls, strip, follower]


def _anvil(front: float, z: float, steel: str, pad: str) -> list[g.Piece]:
    """The anvil under the driver: a chromed plate on the base with its two crimp grooves (where the staple's
    legs are bent in)."""
    plate = _bar(front - 0.02, front, 0.016, 0.0012, z - 1e-4, steel, 0.004, "anvil")
    grooves = [g.box_between((front - 0.015, y - 0.0012, z + 0.0011), (front - 0.005, y + 0.0012, z + 0.0013), pad)
               for y in (-0.003, 0.003)]
    return [plate, *grooves]
