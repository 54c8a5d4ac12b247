"""Wall switches: a wall plate of 1-4 gangs and the devices behind it (toggle, rocker, push buttons, dimmer).

A switch mounts on a wall: the plate's back lies on the wall plane x = 0 and its face looks along +x; the
device bodies reach into the wall box behind it (-x). Built standing on z = 0 (the plate's lower edge),
gangs side by side along y, each centred at :func:`gang_centre`. Two plate standards:

* ``nema``: North American plates (NEMA WD 6): 2.75 x 4.5 in for one gang, 1.81 in more per gang; a toggle
  opening, a Decora (rocker) opening, a round stem hole or two push-button holes per gang, each with its two
  screws.
* ``iec``: European frames of the 55 mm system (Gira System 55, Berker S.1, Busch-Jaeger): 80.8 mm square for
  one gang, 71 mm more per gang (the DIN 49073 box pitch); a 55 mm square opening holds a rocker or push keys,
  a dimmer knob sits on the frame; no visible screws.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import trimesh

from infmob_usd import geometry as g
from infmob_usd.frames import Frame
from infmob_usd.grasps import Grasp

from . import controls

# Plates (m). NEMA WD 6 / Leviton wallplate dimension sheet: standard size 2.75 x 4.5 in (69.9 x 114.3 mm),
# each more gang 1.81 in (46.0 mm); thermoplastic plates stand 5-6 mm off the wall at their rim.
# Gira System 55 "Standard 55" frame: 80.8 x 80.8 mm, 2-gang 151.8 mm wide (71 mm box pitch, DIN 49073),
# 9-10 mm deep with its insert.
PLATES = {
    "nema": {"width": 0.0699, "height": 0.1143, "pitch": 0.0460, "thick": 0.005},
    "iec": {"width": 0.0808, "height": 0.0808, "pitch": 0.0710, "thick": 0.009},
}
# A plate's shell as massed: thermoplastic plates are ~2 mm mouldings, stainless plates 0.8 mm sheet (430
# stainless, NEMA WD 6 "metal plates 0.032 in"); a modelled face counts both sides, so half of each.
SHEET = {"plastic": 0.001, "brushed_metal": 0.0004, "chrome": 0.0004}
BEVEL = 0.4  # of the plate's thickness: the rounded rim of a moulded plate
# Openings (u across, v up; m). NEMA WD 6: toggle 0.406 x 0.94 in, Decora 1.31 x 2.63 in. System 55: 55 mm square.
TOGGLE_HOLE = (0.0103, 0.0239)
DECORA_HOLE = (0.0333, 0.0668)
IEC_HOLE = (0.055, 0.055)
# Screw spacing on a NEMA plate: toggle and round-hole plates 2-3/8 in, Decora plates 3-13/16 in (NEMA WD 6);
# 6-32 oval-head plate screws, 7 mm heads.
SCREWS = {"toggle": 0.0603, "decora": 0.0968}
SCREW_R = 0.0035
MOULDING = 0.0012  # m, the wall of a hollow rocker or key moulding (ABS, 1-1.5 mm)
GAP = 0.0012  # m, a moving part's clearance in its opening (more than the core's 1 mm gap)
RECESS = 0.012  # m, the device's face behind the plate's back: room for a toggle's hub or a pressed button
BODY = (0.033, 0.05, 0.028)  # m, a device body in the wall box (a Leviton 1451 / Gira insert: ~33 x 50 x 28 mm)
# A toggle's bat (Leviton 1451-2, Eaton 1301 product photos): ~16 mm out of the plate, 7.5 mm wide tapering to
# 6 mm, 5 mm thick; it rests ~25 degrees down (off) and throws ~50 degrees to up (on). Pivot 4 mm behind the plate.
TOGGLE = {"out": 0.016, "width": 0.0075, "tip": 0.006, "thick": 0.005, "rest": math.radians(25),
          "pivot": 0.004, "hub": 0.003}
# A rocker rocks about its middle: Decora paddles ~10 degrees end to end, 55 mm rockers ~8 (product photos:
# the pressed end flush, the other 2-3 mm proud); 5 mm thick.
ROCKER = {"nema": math.radians(10), "iec": math.radians(8), "thick": 0.005}
# A slide dimmer (Lutron Diva: a narrow rocker beside a slider in the Decora opening, the slider running its full
# height): a 9 mm channel, a slider 10 mm tall standing 4 mm proud of the plate.
SLIDER = {"channel": 0.009, "height": 0.010, "proud": 0.004}
# Push buttons: vintage two-button switches (Perkins, Cutler-Hammer push-button switches: 1/2 in buttons 3/4 in
# apart, ~4 mm stroke); a System 55 push key (Taster) strokes 1.5 mm.
PUSH = {"nema": controls.Button(half=(0.0062, 0.0062), shape="round", proud=0.004, travel=0.004),
        "pitch": 0.019, "iec_travel": 0.0015, "iec_proud": 0.004}
# Rotary dimmer knobs: Lutron Rotary / Leviton 6681 knobs 1.1-1.35 in across; a UK/EU rotary dimmer 30-36 mm;
# a potentiometer turns ~300 degrees from off to full.
# A push-on/off knob (Lutron Rotary, Leviton 6681 "push on/off") presses ~1.5 mm in to switch.
KNOB = {"radius": (0.014, 0.017), "stem": 0.003, "turns": math.radians(300), "press": 0.0015}


@dataclass(frozen=True)
class Plate:
    """A wall plate: ``standard`` (``nema`` or ``iec``), ``gangs`` and the device of each gang."""

    standard: str
    devices: tuple[str, ...]

    @property
    def size(self) -> dict:
        return PLATES[self.standard]

    @property
    def width(self) -> float:
        return self.size["width"] + self.size["pitch"] * (len(self.devices) - 1)

    @property
    def thick(self) -> float:
        return self.size["thick"]

    def gang_centre(self, k: int) -> tuple[float, float]:
        """Gang ``k``'s centre (y, z) on the plate."""
        n = len(self.devices)
        return (k - (n - 1) / 2) * self.size["pitch"], self.size["height"] / 2

    def face(self, k: int, dz: float = 0.0) -> Frame:
        """Gang ``k``'s mount on the plate's face (z out of the face, x up), ``dz`` above its centre."""
        y, z = self.gang_centre(k)
        return Frame.at((self.thick, y, z + dz), z=(1, 0, 0), x=(0, 0, 1))


def opening(plate: Plate, device: str, buttons: int = 1) -> list[tuple[float, float, float, float]]:
    """Gang openings of ``device`` on ``plate`` as (du0, dv0, du1, dv1) about the gang's centre."""
    if plate.standard == "iec" and device in ("rocker", "slide_dimmer", "push"):
        u, v = IEC_HOLE
    elif device == "toggle":
        u, v = TOGGLE_HOLE
    elif device in ("rocker", "slide_dimmer"):
        u, v = DECORA_HOLE
    elif device == "dimmer":
        r = KNOB["stem"] + controls.A.CLEAR
        return [(-r, -r, r, r)]
    else:  # round push buttons, each in its own hole
        r = PUSH["nema"].half[0] + controls.A.CLEAR
        return [(-r, dv - r, r, dv + r) for dv in push_offsets(buttons)]
    return [(-u / 2, -v / 2, u / 2, v / 2)]


def push_offsets(n: int) -> list[float]:
    """Heights of a NEMA gang's ``n`` push buttons about its centre (the top one switches on)."""
    return [(0.5 * (n - 1) - k) * PUSH["pitch"] for k in range(n)]


def _screws(plate: Plate, k: int, device: str, slot: str) -> list[g.Piece]:
    if plate.standard != "nema":
        return []
    y, z = plate.gang_centre(k)
    half = SCREWS["decora" if device in ("rocker", "slide_dimmer") else "toggle"] / 2
    t = plate.thick
    return [g.cylinder((t - 0.0002, y, z + s * half), (t + 0.0012, y, z + s * half), SCREW_R, slot, 16)
            for s in (-1, 1)]


def plate_pieces(plate: Plate, holes: list[list[tuple]], slot: str, device_slot: str, sheet: float
                 ) -> list[g.Piece]:
    """The plate (a moulded or pressed shell massed as ``sheet``) with every gang's openings, each gang's device
    body and face behind it (its sleeve round the openings, ``RECESS`` deep) and the NEMA plate screws.
    ``holes``: per gang, :func:`opening`'s rectangles."""
    t, h, w = plate.thick, plate.size["height"], plate.width
    world = [hole for k, rects in enumerate(holes) for hole in _world(plate, k, rects)]
    round_gangs = {k for k, d in enumerate(plate.devices) if round_hole(plate, d)}
    slab = g.panel((0, -w / 2, 0), (t, w / 2, h), slot, "x", world)
    box = trimesh.creation.box((t, w, h), trimesh.transformations.translation_matrix((t / 2, 0, h / 2)))
    cutters = [_cutter(t, hole, k in round_gangs) for k, rects in enumerate(holes) for hole in _world(plate, k, rects)]
    rounded = _rounded(box, BEVEL * t)
    mesh = g.subtract(rounded, cutters) if cutters else rounded
    pieces = [g.Piece(mesh.vertices, mesh.faces, slot, slab.convex, hulls=slab.hulls(), sheet=sheet)]
    bu, bv, bd = BODY
    for k, rects in enumerate(holes):
        y, z = plate.gang_centre(k)
        su = max(bu, max(c for _, _, c, _ in rects) * 2 + 0.004) / 2
        sv = max(bv, max(d for _, _, _, d in rects) * 2 + 0.004) / 2
        sleeve = [(y + a, z + b, y + c, z + d) for a, b, c, d in rects]
        pieces += [g.panel((-RECESS, y - su, z - sv), (0.0, y + su, z + sv), device_slot, "x", sleeve),
                   g.box_between((-RECESS - bd, y - su, z - sv), (-RECESS, y + su, z + sv), device_slot)]
        pieces += _screws(plate, k, plate.devices[k], slot)
    return pieces


def _world(plate: Plate, k: int, rects) -> list[tuple[float, float, float, float]]:
    """Gang ``k``'s openings as (y0, z0, y1, z1) on the plate."""
    y, z = plate.gang_centre(k)
    return [(y + a, z + b, y + c, z + d) for a, b, c, d in rects]


def round_hole(plate: Plate, device: str) -> bool:
    """Whether the device's plate holes are round (a push button's or a knob stem's)."""
    return device in ("dimmer", "push") and plate.standard == "nema" or device == "dimmer"


def _cutter(t: float, hole: tuple, rnd: bool) -> trimesh.Trimesh:
    """What cuts one opening out of the plate's look: a box, or the round hole inscribed in it (the collision
    keeps the square: the clearance a round button has in its hole)."""
    y0, z0, y1, z1 = hole
    at = trimesh.transformations.translation_matrix((t / 2, (y0 + y1) / 2, (z0 + z1) / 2))
    if rnd:
        turn = trimesh.transformations.rotation_matrix(math.pi / 2, (0, 1, 0))
        return trimesh.creation.cylinder((y1 - y0) / 2, 3 * t, sections=g.sections_for((y1 - y0) / 2),
                                         transform=at @ turn)
    return trimesh.creation.box((3 * t, y1 - y0, z1 - z0), at)


def _rounded(box: trimesh.Trimesh, r: float) -> trimesh.Trimesh:
    """``box`` with its edges rounded: the Minkowski sum of a box ``r`` smaller with a sphere (a convex hull)."""
    lo, hi = box.bounds
    pts = []
    sphere = trimesh.creation.icosphere(2, r).vertices
    for cx in (lo[0] + r, hi[0] - r):
        for cy in (lo[1] + r, hi[1] - r):
            for cz in (lo[2] + r, hi[2] - r):
                pts.append(sphere + (cx, cy, cz))
    hull = trimesh.convex.convex_hull(np.concatenate(pts))
    hull.fix_normals()
    return hull


def toggle(plate: Plate, k: int, slot: str) -> tuple[list[g.Piece], Frame, float]:
    """Gang ``k``'s toggle bat at rest (down: off) and its pivot (z along -y: a positive turn throws it up);
    returns the pieces, the pivot frame and the throw."""
    y, z = plate.gang_centre(k)
    tg = TOGGLE
    a, length = tg["rest"], tg["pivot"] + plate.thick + tg["out"]
    pivot = np.array((-tg["pivot"], y, z))
    down = (math.cos(a), 0.0, -math.sin(a))
    bat = Frame.at(pivot, x=down, z=(0, -1, 0))  # local x along the bat, local z across it
    w, t = tg["width"], tg["thick"]
    shaft = g.box_between((0.0, -t / 2, -w / 2), (length - t / 2, t / 2, w / 2), slot, bevel=0.0012)
    tip = g.cylinder((length - t / 2, 0, -tg["tip"] / 2), (length - t / 2, 0, tg["tip"] / 2), t / 2, slot, 16)
    hub = g.cylinder((0, 0, -w / 2), (0, 0, w / 2), tg["hub"], slot, 16)
    # flipped up by a fingertip under its tip (local y is the bat's upper side)
    grasp = Grasp.make((length - t, -t / 2, 0), (0, 1, 0), (0, 0, 1), w, t / 2)
    pieces = [p.transformed(bat.matrix) for p in (shaft, tip.with_grasps(grasp), hub)]
    return pieces, Frame.at(pivot, z=(0, -1, 0), x=(1, 0, 0)), 2 * a


def rocker_cells(plate: Plate, n: int) -> list[tuple[float, float, float, float]]:
    """The cells of ``n`` rockers in a gang's opening (u0, v0, u1, v1 about its centre): one fills it; two are
    stacked on a NEMA plate (a Decora dual rocker, Leviton 5634) or side by side in a 55 mm insert (a two-circuit
    "series" switch, Gira 0125xx)."""
    u0, v0, u1, v1 = opening(plate, "rocker")[0]
    if plate.standard == "nema":
        return [(u0, v0 + (v1 - v0) * k / n, u1, v0 + (v1 - v0) * (k + 1) / n) for k in reversed(range(n))]
    return [(u0 + (u1 - u0) * k / n, v0, u0 + (u1 - u0) * (k + 1) / n, v1) for k in range(n)]


def slide_cells(plate: Plate) -> tuple[tuple, tuple]:
    """A slide dimmer's gang (Lutron Diva): its rocker's cell and, beside it, the slider's channel."""
    u0, v0, u1, v1 = opening(plate, "rocker")[0]
    c = u1 - SLIDER["channel"]
    return (u0, v0, c, v1), (c, v0, u1, v1)


def rocker(plate: Plate, k: int, cell: tuple, slot: str) -> tuple[list[g.Piece], Frame, float]:
    """A rocker filling ``cell`` of gang ``k`` (``GAP`` clear all round) at rest (top end out: off) and its pivot
    through its middle (z along -y: a positive turn presses the top in); returns the pieces, the pivot frame and
    its rock."""
    y, z = plate.gang_centre(k)
    u0, v0, u1, v1 = cell
    w, h, t, rock = u1 - u0 - 2 * GAP, v1 - v0 - 2 * GAP, ROCKER["thick"], ROCKER[plate.standard]
    centre = np.array((plate.thick + 0.0005, y + (u0 + u1) / 2, z + (v0 + v1) / 2))
    b = rock / 2  # turned about +y: the top end out
    rest = Frame.at(centre, x=(math.cos(b), 0, -math.sin(b)), z=(math.sin(b), 0, math.cos(b)))
    paddle = g.box_between((-t / 2, -w / 2, -h / 2), (t / 2, w / 2, h / 2), slot, bevel=0.0015).replace(wall=MOULDING)
    press = Grasp.make((t / 2, 0, 0.3 * h), (-1, 0, 0), (0, 1, 0), min(w, 0.02), t / 2)
    return [paddle.with_grasps(press).transformed(rest.matrix)], Frame.at(centre, z=(0, -1, 0), x=(1, 0, 0)), rock


def slider(plate: Plate, k: int, channel: tuple, slot: str) -> tuple[list[g.Piece], Frame, float]:
    """A slide dimmer's slider at the bottom of its ``channel`` (off) on a stem into the wall box; returns its
    pieces, its slide frame (z up the channel) and its travel."""
    y, z = plate.gang_centre(k)
    u0, v0, u1, v1 = channel
    sl = SLIDER
    hw, x1 = (u1 - u0) / 2 - GAP, plate.thick + sl["proud"]
    yc, zb = y + (u0 + u1) / 2, z + v0 + GAP
    knob = g.box_between((plate.thick - 0.002, yc - hw, zb), (x1, yc + hw, zb + sl["height"]), slot, bevel=0.001)
    stem = g.box_between((-RECESS / 2, yc - hw / 2, zb + 0.002), (plate.thick - 0.002, yc + hw / 2,
                                                                   zb + sl["height"] - 0.002), slot)
    # pushed up along its channel by a fingertip under its lower edge
    grip = Grasp.make((x1 - 0.002, yc, zb), (0, 0, 1), (0, 1, 0), 2 * hw, 0.002)
    travel = (v1 - v0) - 2 * GAP - sl["height"]
    return [knob.with_grasps(grip), stem], Frame.at((x1, yc, zb), z=(0, 0, 1), x=(1, 0, 0)), travel


def iec_key(plate: Plate, k: int, j: int, n: int, slot: str) -> tuple[list[g.Piece], Frame, float]:
    """Key ``j`` of ``n`` side by side in gang ``k``'s 55 mm opening (a push key, a Taster: a hollow moulding
    reaching ``RECESS`` / 2 behind the plate's face); returns its pieces, its press frame (z into the wall) and
    its stroke."""
    u, v = IEC_HOLE
    cell = u / n
    y, z = plate.gang_centre(k)
    y += (j - (n - 1) / 2) * cell
    hu, hv, face = cell / 2 - GAP, v / 2 - GAP, plate.thick + PUSH["iec_proud"]
    key = g.box_between((plate.thick - RECESS / 2, y - hu, z - hv), (face, y + hu, z + hv), slot, bevel=0.0015)
    press = Grasp.make((face, y, z), (-1, 0, 0), (0, 1, 0), min(2 * hu, 0.02), PUSH["iec_proud"] / 2)
    return ([key.replace(wall=MOULDING).with_grasps(press)], Frame.at((face, y, z), z=(-1, 0, 0), x=(0, 0, 1)),
            PUSH["iec_travel"])


def knob(size: float) -> controls.Dial:
    """A rotary dimmer's knob, ``size`` (0-1) through its range, turning from off to full."""
    lo, hi = KNOB["radius"]
    return controls.Dial(radius=lo + size * (hi - lo), stem=KNOB["stem"], style="round", turns=KNOB["turns"])
