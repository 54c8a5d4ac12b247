"""Folding knives and utility knives lying on their side on a table.

Local frame: the handle lies on its side along X (its back end at x = 0, its front toward +X), its height
along Y (the spine toward +Y, the open side a blade folds into toward -Y), its thickness up (Z). A folding
knife's handle is a stack of layers: the two scales outside, a liner between two tools, one tool per layer,
each turning in its own layer about the front pivot (blades) or the back one (openers, awl) from folded
inside the handle (rest) out through the open side to straight (180 degrees). A utility knife's blade
carrier slides in the channel between the two halves of its handle, out of the nose (+X), moved by the
thumb slider that stands out of the slot along the spine.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame
from infmob_usd.grasps import Grasp

from .casing import moulded_slab
from .handtools import hull, rrect

GAP = 0.0003  # m, between a tool and the liners or scales either side (tools turn stiffly on the pivot)
LINER = 0.0008  # m, the aluminium liner between two layers (Victorinox 'alox' liners 0.8-1 mm)
PIN = 0.0013  # m, the pivot pin's radius (a 2.5-3 mm rivet, Victorinox and Opinel alike)


@dataclass(frozen=True)
class FoldingDesign:
    """A folding knife, from real products (metres)."""

    length: tuple[float, float]  # handle length (closed)
    height: float  # handle height (across, spine to open side)
    scale: float  # one scale's thickness
    tool: float  # one tool's (blade's) thickness
    ends: float  # pivot to the handle's end, as a share of its height


FOLDING = {
    # Opinel No. 7-9 (80-110 mm handle, ~45 g for the No. 8), Buck 110 Folding Hunter (124 mm, 200 g) and
    # Spyderco Delica (111 mm): one blade 2.5-3 mm thick between 3-4 mm scales
    "pocket": FoldingDesign((0.090, 0.125), 0.022, 0.0035, 0.0028, 0.55),
    # Victorinox Spartan / Climber / Huntsman (91 mm, 60-100 g): 2.5 mm scales, tools of 1.5-2 mm steel
    "multi_tool": FoldingDesign((0.084, 0.100), 0.026, 0.0025, 0.0018, 0.5),
}
"""Designs -> sizes (maker catalogues named beside each)."""

TOOLS = {
    # kind: (share of the handle length, height as a share of the handle's, pivot: "front" or "back"); the
    # Victorinox Spartan's large and small blades, can opener, bottle opener with screwdriver and reamer,
    # the Climber's scissors-free saw and the Huntsman's wood saw
    "large_blade": (0.78, 0.62, "front"),
    "small_blade": (0.52, 0.42, "front"),
    "saw": (0.74, 0.5, "front"),
    "can_opener": (0.5, 0.44, "back"),
    "bottle_opener": (0.5, 0.46, "back"),
    "reamer": (0.56, 0.24, "back"),
    "spey_blade": (0.5, 0.4, "back"),  # a stockman's third blade (Case, Schrade Old Timer 8OT)
}
"""Tool kinds -> proportions."""

MULTI_TOOLS = {"large_blade": 0.3, "small_blade": 0.2, "saw": 0.1, "can_opener": 0.15, "bottle_opener": 0.15,
               "reamer": 0.1}
"""A multi-tool's tools and how often each is drawn (Victorinox's range: every model has the large blade)."""

LABELS = {"large_blade": "blade", "small_blade": "blade", "spey_blade": "blade", "saw": "saw",
          "can_opener": "can_opener", "bottle_opener": "bottle_opener", "reamer": "reamer"}
"""Tool kinds -> the semantic label of their part."""


@dataclass(frozen=True)
class Folding:
    design: FoldingDesign
    length: float
    layers: int

    @property
    def pivots(self) -> dict[str, np.ndarray]:
        """The front and back pivots (plan)."""
        e = self.design.ends * self.design.height
        return {"front": np.array([self.length - e, 0.0]), "back": np.array([e, 0.0])}

    def layer(self, k: int) -> tuple[float, float]:
        """(z0, z1) of layer ``k``'s tool."""
        d = self.design
        z0 = d.scale + GAP + k * (d.tool + 2 * GAP + LINER)
        return z0, z0 + d.tool

    @property
    def thickness(self) -> float:
        return 2 * self.design.scale + self.layers * (self.design.tool + 2 * GAP) + (self.layers - 1) * LINER


def folding(design: str, size: float, layers: int) -> Folding:
    d = FOLDING[design]
    return Folding(d, d.length[0] + size * (d.length[1] - d.length[0]), layers)


def _plate(outline: np.ndarray, z0: float, z1: float, material: str, name: str) -> g.Piece:
    """A plate of the plan outline (convex), from z0 to z1."""
    return hull([(x, y, z) for x, y in outline for z in (z0, z1)], material, name)


def handle_outline(f: Folding, grow: float = 0.0) -> np.ndarray:
    """The handle's plan: a stadium (rounded ends the pivots sit in)."""
    h = f.design.height + 2 * grow
    pts = rrect(f.length + 2 * grow, h, 0.49 * h, -h / 2, n=6)
    return pts + [f.length / 2, 0.0]


def folding_handle(f: Folding, scale: str, liner: str, metal: str) -> Assembly:
    """The handle: the two scales, a liner between each two layers, the spine (backspring) along +Y in every
    layer and the pivot pins through all of them. Anchors ``front`` / ``back`` at the pivots (z: +Z)."""
    d, out = f.design, handle_outline(f)
    top = f.thickness
    pieces = [_plate(out, 0.0, d.scale, scale, "scale"), _plate(out, top - d.scale, top, scale, "scale")]
    inner = handle_outline(f, -0.0006)
    for k in range(1, f.layers):
        z = f.layer(k)[0] - GAP - LINER
        pieces.append(_plate(inner, z, z + LINER, liner, "liner"))
    spine = 0.16 * d.height
    e = d.ends * d.height
    pieces.append(hull([(x, y, z) for x in (e, f.length - e) for y in (d.height / 2 - spine, d.height / 2 - 0.0008)
                        for z in (d.scale - 1e-4, top - d.scale + 1e-4)], liner, "spine"))
    anchors = {}
    for name, p in f.pivots.items():
        # the pin runs through the tools' tangs: drawn, not a collision shape (the joint is the pin)
        pieces.append(g.cylinder((*p, -1e-4), (*p, top + 0.0004), PIN, metal, name="pin").replace(convex=()))
        pieces.append(g.cylinder((*p, top - 1e-4), (*p, top + 0.0004), 2.2 * PIN, metal, name="rivet"))
        anchors[name] = Frame.at((*p, 0.0))
    return Assembly.single("body", pieces, anchors)


def _blade_outline(length: float, height: float, point: str) -> np.ndarray:
    """A blade's plan, open (pointing +X from its pivot at the origin): tang round the pivot, spine along +Y,
    edge along -Y, to a drop point, a clip point or a round (sheepsfoot) end. Convex."""
    h = height
    tang = [(0.45 * h * math.cos(a), 0.45 * h * math.sin(a)) for a in np.radians(np.arange(60, 300, 30))]
    spine = [(0.3 * h, 0.42 * h), (0.7 * length, 0.42 * h)]
    if point == "drop":
        tip = [(length, 0.1 * h), (0.92 * length, -0.2 * h)]
    elif point == "clip":
        tip = [(0.85 * length, 0.3 * h), (length, 0.02 * h), (0.93 * length, -0.25 * h)]
    else:  # sheepsfoot: a straight edge and a rounded spine down to it
        tip = [(0.9 * length, 0.35 * h), (length, 0.0), (length, -0.3 * h)]
    edge = [(0.75 * length, -0.45 * h), (0.35 * length, -0.5 * h), (0.3 * h, -0.48 * h)]
    return np.array(tang + spine + tip + edge)


def tool(f: Folding, kind: str, k: int, steel: str, point: str = "clip", polish: str | None = None) -> Assembly:
    """Tool ``kind`` in layer ``k``, folded into the handle about its pivot: a blade lies from the front pivot
    back toward -X, a back-pivot tool from the back pivot toward +X, each with its edge or hook toward the
    open side (-Y); a blade's ground bevel in ``polish`` where given. Anchor ``pivot`` (z: the opening sense)."""
    share, hs, where = TOOLS[kind]
    d = f.design
    length = share * f.length
    h = hs * d.height
    z0, z1 = f.layer(k)
    zc = (z0 + z1) / 2
    if kind in ("large_blade", "small_blade", "saw", "spey_blade"):
        plan = _blade_outline(length, h, {"large_blade": point, "small_blade": "drop"}.get(kind, "sheep"))
        pieces = _ground(plan, z0, z1, zc, steel, kind, polish)
        if kind == "saw":
            pieces += _teeth(length, h, z0, z1, steel)
    else:
        pieces = _opener(kind, length, h, z0, z1, steel)
    piv = f.pivots[where]
    # built open along +X (edge -Y); folded, a front tool is turned half round its pivot (edge toward the
    # spine, +Y), a back tool turned over about X in its layer (pointing +X, edge +Y): each swings out through
    # the open side (-Y), about +Z at the front and -Z at the back
    if where == "front":
        fold, axis = Frame.at((*piv, 0.0), x=(-1, 0, 0)), (0, 0, 1)
    else:
        fold, axis = Frame.at((*piv, z0 + z1), x=(1, 0, 0), z=(0, 0, -1)), (0, 0, -1)
    return Assembly.single(LABELS[kind], pieces).placed(fold).with_anchors(pivot=Frame.at((*piv, 0.0), z=axis))


def _clip_below(plan: np.ndarray, y0: float, below: bool) -> np.ndarray:
    """The part of the convex plan below (or above) the line y = ``y0``, with the points where it crosses."""
    out = []
    for a, b in zip(plan, np.roll(plan, -1, 0), strict=True):
        if (a[1] <= y0) == below:
            out.append(a)
        if (a[1] - y0) * (b[1] - y0) < 0:
            out.append(a + (y0 - a[1]) / (b[1] - a[1]) * (b - a))
    return np.array(out)


def _ground(plan: np.ndarray, z0: float, z1: float, zc: float, steel: str, name: str,
            polish: str | None = None, line: float | None = None) -> list[g.Piece]:
    """A flat-ground blade: full thickness from the spine to the grind line, ground down from it to a
    0.3 mm edge on -Y. With ``polish`` the grind is its own polished band (a satin-finished flat and a
    bright ground bevel, as Victorinox and Opinel blades are sold); the blade collides as one hull. The
    grind starts at y = ``line`` (default: a tenth of the blade's height below its middle)."""
    y = plan[:, 1]
    line = -0.2 * (y.max() - y.min()) / 2 if line is None else line
    edge = y < line
    pts = []
    for (x, yy), sharp in zip(plan, edge, strict=True):
        pts += [(x, yy, zc - 0.00015), (x, yy, zc + 0.00015)] if sharp else [(x, yy, z0), (x, yy, z1)]
    whole = hull(pts, steel, name)
    if polish is None:
        return [whole]
    flat = _clip_below(plan, line, False)
    below = _clip_below(plan, line, True)
    on_line = np.isclose(below[:, 1], line)
    grind = [(x, yy, z) for (x, yy), full in zip(below, on_line, strict=True)
             for z in ((z0, z1) if full else (zc - 0.00015, zc + 0.00015))]
    # the flat overlaps the grind by a hair along the line, so no seam opens between the two meshes
    return [hull([(x, yy, z) for x, yy in flat for z in (z0, z1)], steel, name).replace(convex=whole.convex),
            hull(grind, polish, "grind").replace(convex=())]


def _teeth(length: float, h: float, z0: float, z1: float, steel: str) -> list[g.Piece]:
    """A saw's teeth along its edge (drawn: the blade's hull collides)."""
    y0, out = -0.48 * h, []
    for x in np.arange(0.25 * length, 0.85 * length, 0.0025):
        tooth = [(x, y0 + 0.0003, z0), (x + 0.0025, y0 + 0.0003, z0), (x + 0.0025, y0 + 0.0003, z1),
                 (x, y0 + 0.0003, z1), (x + 0.0025, y0 - 0.0012, (z0 + z1) / 2)]
        out.append(hull(tooth, steel, "tooth").replace(convex=()))
    return out


def _opener(kind: str, length: float, h: float, z0: float, z1: float, steel: str) -> list[g.Piece]:
    """A can opener (a hooked point), a bottle opener (a wide blade with a screwdriver tip and a cap-lifting
    hook) or a reamer (a tapering spike), open along +X from the pivot."""
    if kind == "reamer":
        plan = np.array([(0.0, 0.5 * h), (-0.4 * h, 0.0), (0.0, -0.5 * h), (length, -0.08 * h), (length, 0.08 * h)])
        return [_plate(plan, z0, z1, steel, "reamer")]
    body = np.array([(-0.45 * h, 0.4 * h), (-0.45 * h, -0.4 * h), (0.7 * length, -0.5 * h), (length, -0.3 * h),
                     (length, 0.3 * h), (0.7 * length, 0.5 * h)])
    if kind == "can_opener":
        body = body * [1.0, 0.7]
        hook = np.array([(0.75 * length, -0.35 * h), (length, -0.35 * h), (0.95 * length, -0.75 * h),
                         (0.82 * length, -0.7 * h)])
    else:
        hook = np.array([(0.45 * length, -0.5 * h), (0.62 * length, -0.5 * h), (0.6 * length, -0.68 * h),
                         (0.5 * length, -0.62 * h)])
    return [_plate(body, z0, z1, steel, kind), _plate(hook, z0, z1, steel, "hook")]


# -- utility knives -----------------------------------------------------------------------------------
@dataclass(frozen=True)
class UtilityDesign:
    """A utility knife (metres): a handle of two halves round a channel, a blade carrier sliding in it."""

    length: tuple[float, float]  # handle length
    height: float  # handle height (spine to belly)
    thickness: float
    blade: tuple[float, float, float]  # blade length along its edge, height, thickness
    travel: float  # how far the carrier slides out, its last lock step
    steps: int  # the slider's lock positions past retracted
    snap: float = 0.0  # a snap-off blade's segment pitch (0: a trapezoid blade)


UTILITY = {
    # Stanley 10-099 / 99E retractable utility knives (155-165 mm, 170-200 g): Stanley 1992 trapezoid blades
    # 61 x 19 x 0.6 mm, three lock positions ~8 mm apart
    "retractable": UtilityDesign((0.150, 0.165), 0.034, 0.018, (0.061, 0.019, 0.0006), 0.024, 3),
    # Olfa L-1 / Stanley FatMax 18 mm snap-off cutters (160-170 mm, 50-90 g): 100 x 18 x 0.5 mm blades in
    # 9 mm segments, a ratchet slider locking every segment
    "snap_off": UtilityDesign((0.155, 0.170), 0.026, 0.016, (0.100, 0.018, 0.0005), 0.054, 6, snap=0.009),
}
"""Designs -> sizes (maker listings named beside each)."""

EDGE = 0.0018  # m, the radius of a utility knife handle's outer edges
SHELL = 0.003  # m, one handle half's wall either side of the channel (die-cast or moulded, 2.5-3.5 mm)


@dataclass(frozen=True)
class Utility:
    design: UtilityDesign
    length: float

    @property
    def channel(self) -> tuple[float, float]:
        """(z0, z1) of the channel between the halves."""
        return SHELL, self.design.thickness - SHELL


def utility(design: str, size: float) -> Utility:
    d = UTILITY[design]
    return Utility(d, d.length[0] + size * (d.length[1] - d.length[0]))


def blade_line(u: Utility) -> float:
    """y of the blade's edge: its back edge 4 mm under the spine."""
    return min(-0.1 * u.design.height, u.design.height / 2 - 0.004 - u.design.blade[1])


def _utility_plan(u: Utility) -> np.ndarray:
    """The handle's plan (convex): a retractable knife's tall at the back, its nose tapering to the blade's
    slot; a snap-off cutter's a slim straight bar, its nose square round the blade."""
    L, h, yb = u.length, u.design.height, blade_line(u)
    if u.design.snap:
        return np.array([(0.0, -h / 2), (0.97 * L, -h / 2), (L, yb - 0.002), (L, h / 2 - 0.002), (0.97 * L, h / 2),
                         (0.0, h / 2)])
    return np.array([(0.0, -0.35 * h), (0.04 * L, -h / 2), (0.86 * L, -h / 2), (L, yb - 0.002), (L, _nose_top(u)),
                     (0.8 * L, h / 2), (0.05 * L, h / 2), (0.0, 0.4 * h)])


def _nose_top(u: Utility) -> float:
    """y of the nose's front top corner: 18 % of the height over the middle, or higher where the blade,
    pushed out its full travel, would otherwise stand out through the nose's sloping top edge (the blade
    leaves only through the slot in the nose's front)."""
    L, h = u.length, u.design.height
    x0, need = 0.8 * L, 0.18 * h
    blade = _blade_plan(u) + [u.design.travel, 0.0]
    for (xa, ya), (xb, yb) in zip(blade, np.roll(blade, -1, 0), strict=True):
        for t in np.linspace(0.0, 1.0, 9):  # along each edge of the blade's plan, where it is inside the nose
            x, y = xa + t * (xb - xa), ya + t * (yb - ya)
            if x0 < x <= L:
                need = max(need, h / 2 + (y + 0.0015 - h / 2) * (L - x0) / (x - x0))
    return min(need, h / 2 - 0.002)


def utility_handle(u: Utility, body: str, grip: str) -> Assembly:
    """The two halves (the lower on the table), the belly wall and back cap closing the channel, and the two
    rails either side of the slider's slot along the spine; a rubber grip inlay on the top half."""
    d, L, h = u.design, u.length, u.design.height
    z0, z1 = u.channel
    plan = _utility_plan(u)
    # die-cast or moulded halves: their outer edges rounded (a Stanley 10-099's ~1.5 mm, an Olfa L-1's ~2 mm)
    pieces = [moulded_slab(plan, 0.0, z0, EDGE, body, "half", (True, False)),
              moulded_slab(plan, z1, d.thickness, EDGE, body, "half", (False, True))]
    wall = 0.003
    plan_lo = plan[plan[:, 1] < blade_line(u)]  # the belly's corners, back to the nose under the blade
    for a, b in zip(plan_lo[:-1], plan_lo[1:], strict=True):  # one wall along each edge of the plan
        wall_pts = [(x, y + dy, z) for x, y in (a, b) for dy in (0.0008, min(wall, blade_line(u) - 0.0012 - y))
                    for z in (z0 - 1e-4, z1 + 1e-4)]
        pieces.append(hull(wall_pts, body, "belly"))
    pieces.append(hull([(x, y, z) for x in (0.0, 0.012) for y in (-h / 2 + 0.001, 0.38 * h) for z in (z0, z1)],
                       body, "back"))
    slot = 0.5 * (z1 - z0)
    for lo, hi in ((z0 - 1e-4, (z0 + z1 - slot) / 2), ((z0 + z1 + slot) / 2, z1 + 1e-4)):
        pieces.append(hull([(x, y, z) for x in (0.06 * L, 0.8 * L) for y in (h / 2 - wall, h / 2 - 0.0005)
                            for z in (lo, hi)], body, "rail"))
    pieces += _nose_cheeks(u, plan, body)
    inlay = np.array([(0.08 * L, -0.3 * h), (0.6 * L, -0.36 * h), (0.6 * L, 0.3 * h), (0.1 * L, 0.36 * h)])
    pieces.append(_plate(inlay, d.thickness - 1e-4, d.thickness + 0.0012, grip, "grip"))
    return Assembly.single("body", pieces, {"slide": Frame.at((0.0, 0.0, d.thickness / 2), z=(1, 0, 0))})


def _nose_cheeks(u: Utility, plan: np.ndarray, body: str) -> list[g.Piece]:
    """The nose closed round the blade's slot: the channel filled either side of the blade, as far back as the
    carrier stops short at full travel, so the retracted blade is hidden and the extended one comes out of a
    slot (Stanley 10-099, Olfa L-1: a slot ~1 mm wide in a solid nose)."""
    d, L = u.design, u.length
    z0, z1 = u.channel
    zc, bt = (z0 + z1) / 2, d.blade[2]
    depth = min(0.010, L - _carrier_front(u) - d.travel - 0.001)
    x0 = L - depth
    pts = [tuple(q) for q in plan if q[0] >= x0]
    for a, b in zip(plan, np.roll(plan, -1, 0), strict=True):  # where the plan's edges cross x0
        if (a[0] - x0) * (b[0] - x0) < 0:
            pts.append((x0, a[1] + (x0 - a[0]) / (b[0] - a[0]) * (b[1] - a[1])))
    halves = ((z0 - 1e-4, zc - bt / 2 - GAP), (zc + bt / 2 + GAP, z1 + 1e-4))
    out = [hull([(x, y, z) for x, y in pts for z in zs], body, "nose") for zs in halves]
    for a, b in zip(plan, np.roll(plan, -1, 0), strict=True):  # the nose's top edges, behind the cheeks
        if min(a[1], b[1]) > 0 and max(a[0], b[0]) > 0.6 * L and min(a[0], b[0]) < x0:
            ends = [q if q[0] <= x0 else q + (x0 - q[0]) / (r[0] - q[0]) * (r - q) for q, r in ((a, b), (b, a))]
            out += [hull([(x, y - dy, z) for x, y in ends for dy in (0.0, 0.0008) for z in zs], body, "nose_wall")
                    for zs in halves]
    return out


def _carrier_front(u: Utility) -> float:
    """x of the carrier's front, retracted (the blade reaches on beyond it)."""
    return u.length - 0.004 - 0.55 * u.design.blade[0]


def _blade_plan(u: Utility) -> np.ndarray:
    """The blade's plan, retracted: a snap-off strip's end snapped square to a point, or a trapezoid blade
    with its front corner the point, its edge along the blade line."""
    bl, bh, _ = u.design.blade
    tip, yb = u.length - 0.004, blade_line(u)
    if u.design.snap:
        return np.array([(tip - bl, yb), (tip, yb), (tip - bh * 0.6, yb + bh), (tip - bl, yb + bh)])
    return np.array([(tip - bl, yb + 0.2 * bh), (tip, yb), (tip - 0.3 * bl, yb + bh), (tip - 0.75 * bl, yb + bh)])


def blade_carrier(u: Utility, steel: str, slider: str, polish: str | None = None) -> Assembly:
    """The carrier with its blade, retracted: the blade's tip just inside the nose, the carrier behind it in
    the channel and its thumb slider standing out of the slot along the spine. Anchor ``slide`` (z: +X)."""
    d, L, h = u.design, u.length, u.design.height
    z0, z1 = u.channel
    bl, bh, bt = d.blade
    zc = (z0 + z1) / 2
    tip = L - 0.004
    yb = blade_line(u)  # the edge's line, level with the nose slot's lower lip
    plan = _blade_plan(u)
    # the edge bevel of a utility blade is a bright band ~2 mm wide along its edge (Stanley 1992, Olfa LB)
    pieces = _ground(plan, zc - bt / 2, zc + bt / 2, zc, steel, "blade", polish, line=yb + 0.12 * bh)
    if d.snap:  # the snap lines scored across the strip (drawn: the blade's hull collides)
        for x in np.arange(tip - bh * 0.6 - d.snap, tip - bl + 0.005, -d.snap):
            line = [(x + dx + f * 0.6 * bh, yb + f * bh, z) for dx in (0.0, 0.0004) for f in (0.05, 0.95)
                    for z in (zc + bt / 2, zc + bt / 2 + 0.00005)]
            pieces.append(hull(line, steel, "score").replace(convex=()))
    c0, c1 = 0.1 * L, _carrier_front(u)
    top = h / 2 - 0.0035
    pieces.append(hull([(x, y, z) for x in (c0, c1) for y in (-h / 2 + 0.0035, top) for z in (z0 + GAP, z1 - GAP)],
                       slider, "carrier"))
    slot = 0.5 * (z1 - z0)
    xs = (c0 + c1) / 2
    stem = [(x, y, z) for x in (xs - 0.006, xs + 0.006) for y in (top - 0.001, h / 2 + 0.0015)
            for z in (zc - slot / 2 + GAP, zc + slot / 2 - GAP)]
    button = [(x, y, z) for x in (xs - 0.009, xs + 0.009) for y in (h / 2 + 0.0015, h / 2 + 0.0045)
              for z in (z0 - 0.0005, z1 + 0.0005)]
    # a thumb pushes it; a gripper pinches it across the handle's thickness from the spine and slides it
    across = z1 - z0 + 0.001
    grip = Grasp.make((xs, h / 2 + 0.0045, zc), (0, -1, 0), (0, 0, 1), across, 0.0015)
    pieces += [hull(stem, slider, "stem"), hull(button, slider, "thumb_slider").with_grasps(grip)]
    return Assembly.single("blade", pieces, {"slide": Frame.at((tip, yb, zc), z=(1, 0, 0))})
