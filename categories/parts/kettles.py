"""Kettles: a thin-walled body of revolution with a spout, a side handle or a folding bail, a lid hinged at the
back of its opening, and the small controls of each design.

Everything is built round the body's axis (Z up, the spout at +X, the handle at -X), the base centre at the
origin; each moving part is returned with the frame its joint turns or slides about (z the axis, a positive
move opens: the lid's front lifts, the flap swings up off the spout, the bail rises, the switch rocks on, the
release button presses in).

Designs (real product types; sizes below with their sources):

* ``electric``: a jug kettle on its power base, a lid with a release button on top of the handle, an on/off
  rocker under the handle;
* ``whistling``: a stovetop whistling kettle (wide, squat), its spout closed by a whistle flap;
* ``camping``: a small stovetop kettle with a folding wire bail instead of a side handle.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.frames import Frame
from infmob_usd.grasps import Grasp

from . import spouts as S
from .vessel import Profile, lid_gap


@dataclass(frozen=True)
class Design:
    """A kettle design: body ``radius`` (its widest) and ``height`` ranges (m), the top opening as a share of
    the radius, the wall's massed ``sheet`` (m)."""

    radius: tuple[float, float]
    height: tuple[float, float]
    mouth: float
    sheet: float


# Retail spec listings (manufacturer pages, approximate): a 1.7 l jug kettle is ~0.16 m across its body and
# 0.24-0.26 m tall on its base (Russell Hobbs 20460, Bosch TWK7203, Hamilton Beach 40880); a 2-2.5 l stovetop
# whistling kettle is 0.19-0.23 m across and 0.17-0.22 m tall to its rim (OXO Uplift, Le Creuset 1.7 l,
# Cuisinart CTK-SS17); a 1-1.2 l camping kettle 0.13-0.15 m across, 0.11-0.14 m tall (GSI Glacier, Stanley).
DESIGNS = {
    "electric": Design((0.075, 0.085), (0.20, 0.23), 0.55, 0.0006),
    "whistling": Design((0.095, 0.115), (0.15, 0.19), 0.5, 0.0008),
    "camping": Design((0.065, 0.075), (0.11, 0.14), 0.7, 0.0006),
}
WALL = 0.002  # m, the wall as the simulator sees it (massed as the design's sheet)
BASE = (0.012, 0.02)  # m, an electric kettle's power base: overhang round the body, thickness
LID_T = 0.006  # m, the lid's thickness as the simulator sees it
LID_SHEET = 0.0008  # m, pressed steel or moulded plastic of the lid (its mass)
LID_OPENS = math.radians(95)  # kettle lids open to about upright
LID_KNOB = (0.008, 0.015)  # m, the lid's knob: radius, top over the lid's mid-plane
# Spouts (product photos, approximate: Russell Hobbs 20460, Bosch TWK7203 and Smeg KLF03 jugs; Le Creuset 1.7 l,
# OXO Uplift and GSI Glacier stovetop kettles). A jug's spout is a beak moulded into its upper front: it leaves the
# wall over ~7-8 cm of height, ~6 cm across, and narrows to a ~2 cm lip level with the rim, ~3.5 cm proud of
# the wall. A stovetop kettle's is a cone curving up from low on the body, ~5 cm across at the root and 1.6-2 cm
# at the tip, its tip ~5 cm proud of the body at about rim height. ``root``/``tip``: heights as shares of the
# body's; ``reach``: the tip's distance out from the body's widest (m); ``rise``: the centreline's
# angle over level at the root and at the tip; ``across``/``along``: the section's half-widths (m), root, tip.
SPOUT = {"jug": dict(root=0.5, tip=1.02, reach=0.03, rise=(60, 20), across=(0.03, 0.013), along=(0.04, 0.009),
                     flare=2.0),
         "stovetop": dict(root=0.3, tip=1.0, reach=0.05, rise=(30, 60), across=(0.025, 0.01),
                          along=(0.032, 0.01), flare=2.0),
         "camping": dict(root=0.3, tip=1.0, reach=0.035, rise=(30, 55), across=(0.019, 0.008),
                         along=(0.024, 0.008), flare=2.0)}
SPOUT_WALL = 0.0015  # m
FILL_LINE = 0.85  # the max-fill mark as a share of the body's height (kettle listings: 1.7 l of ~2 l brimful)
FLAP_OPENS = math.radians(80)
# Side handles (Russell Hobbs 20460, Bosch TWK7203, Le Creuset kettle, product photos): a 10-12 cm grip ~3 cm
# thick with 3-4 cm of room for the fingers between it and the body, on two arms into the wall.
HANDLE_R = 0.015  # m, the grip's radius (solid plastic)
HANDLE_ROOM = 0.035  # m, between the grip and the body's widest
GRIP = 0.1  # m, the upright grip's least length (on a squat kettle its top rises over its upper arm's root)
BAIL_R = 0.0025  # m, a camping kettle's wire bail
BAIL_OPENS = math.radians(95)  # the bail rises from folded back to just past upright
SWITCH = (0.018, 0.02, 0.006)  # m, on/off paddle: reach, width, thickness (product photos)
SWITCH_TURN = math.radians(20)
BUTTON = (0.02, 0.016, 0.006)  # m, lid release button on the handle's top: length, width, height
BUTTON_TRAVEL = 0.003


@dataclass(frozen=True)
class Kettle:
    """A kettle's body ``profile``, its ``radius`` and rim height ``height``, the lift ``z0`` of the body
    (over an electric base) and the mouth's radius."""

    profile: Profile
    radius: float
    height: float
    z0: float
    mouth: float


def kettle(design: str, t: float, u: float) -> Kettle:
    """The body of ``design`` at ``t`` of its radius range and ``u`` of its height range."""
    d = DESIGNS[design]
    r = d.radius[0] + t * (d.radius[1] - d.radius[0])
    h = d.height[0] + u * (d.height[1] - d.height[0])
    z0 = BASE[1] if design == "electric" else 0.0
    mouth = d.mouth * r
    if design == "electric":  # a tapering jug
        ctrl = [(0.95 * r, z0), (r, z0 + 0.1 * h), (0.92 * r, z0 + 0.7 * h), (0.75 * r, z0 + h)]
    else:  # a squat body rounding in to a narrow neck
        ctrl = [(0.9 * r, z0), (r, z0 + 0.35 * h), (0.8 * r, z0 + 0.8 * h), (mouth + WALL, z0 + h)]
    prof = Profile.through(ctrl, WALL, (64, 12))
    return Kettle(prof, r, z0 + h, z0, prof.top_radius - WALL)


def body(k: Kettle, design: str, slot: str, handle_slot: str) -> list[g.Piece]:
    """The wall, its bottom, the spout, the handle (not on a camping kettle: its bail is a part) and an electric
    kettle's power base."""
    d = DESIGNS[design]
    pieces = [k.profile.wall(slot, sheet=d.sheet),
              g.disc((0, 0, k.z0 + WALL), k.profile.base_radius - WALL, 2 * WALL, slot).replace(sheet=d.sheet)]
    pieces.append(spout(k, slot))
    if design != "camping":
        pieces.append(g.tube(handle_path(k), HANDLE_R, handle_slot))
    if design == "electric":
        pieces.append(g.disc((0, 0, BASE[1] / 2), k.radius + BASE[0], BASE[1], "base"))
    return pieces


def _r_at(k: Kettle, z: float) -> float:
    f = k.profile.fine
    return float(f[:, 0][abs(f[:, 1] - z).argmin()])


def spout_of(k: Kettle) -> S.Spout:
    """The spout's centreline and sections: its root centre buried in the front wall (the wide root then
    leaves the wall as a flared bulge), its tip over the fill line and proud of the body."""
    h = k.height - k.z0
    kind = "jug" if k.z0 > 0 else ("camping" if k.radius < DESIGNS["whistling"].radius[0] else "stovetop")
    s = SPOUT[kind]
    za, zb = k.z0 + s["root"] * h, k.z0 + s["tip"] * h
    root = np.array([_r_at(k, za) - 0.4 * s["across"][0], 0.0, za])
    tip = np.array([k.radius + s["reach"], 0.0, zb])
    span = float(np.linalg.norm(tip - root))
    a0, a1 = (math.radians(x) for x in s["rise"])
    c1 = root + 0.4 * span * np.array([math.cos(a0), 0.0, math.sin(a0)])
    c2 = tip - 0.35 * span * np.array([math.cos(a1), 0.0, math.sin(a1)])
    return S.Spout(tuple(map(tuple, (root, c1, c2, tip))), s["across"], s["along"], s["flare"], SPOUT_WALL)


def spout(k: Kettle, slot: str) -> g.Piece:
    """The spout: an open tube tapering from a wide root moulded into the front wall up and out to its tip."""
    return S.spout(spout_of(k), slot)


def spout_tip(k: Kettle) -> tuple[float, float, float]:
    """The centre of the spout's open end."""
    return tuple(spout_of(k).tip)


def handle_path(k: Kettle) -> list[tuple[float, float, float]]:
    """A D-shaped grip behind the body: level arms from under the rim and from low on the body, their ends
    buried in the wall, and an upright grip :data:`HANDLE_ROOM` clear of the body's widest."""
    h = k.height - k.z0
    zt, zb = k.height - 0.06 * h, k.z0 + 0.1 * h
    xt, xb = -_r_at(k, zt) + HANDLE_R, -_r_at(k, zb) + HANDLE_R  # into the wall, not through it
    out, bend = -k.radius - HANDLE_ROOM - HANDLE_R, 0.015
    top = max(zt, zb + 2 * bend + GRIP)
    return [(xt, 0, zt), (out + bend, 0, top), (out, 0, top - bend), (out, 0, zb + bend), (out + bend, 0, zb),
            (xb, 0, zb)]


def lid(k: Kettle, slot: str, knob_slot: str) -> tuple[list[g.Piece], Frame]:
    """A flat lid over the mouth with a knob, and its hinge at the back of the rim (axis -Y: the front lifts)."""
    zc = k.height + lid_gap(LID_T) + LID_T / 2
    r = k.mouth + 0.006
    # the knob is what the lid is lifted by (its edge lies on the rim: no finger gets under it): pinched across
    # from above, down to the lid's face
    kx, kr, top, face = 0.4 * r, LID_KNOB[0], zc + LID_KNOB[1], zc + LID_T / 2
    grasp = Grasp.make((kx, 0, top), (0, 0, -1), (0, 1, 0), 2 * kr, (top - face) / 2, "round_fixed_handle",
                       ((kx, 0, (top + face) / 2), (2 * kr, 2 * kr, top - face), np.eye(3)))
    pieces = [g.disc((0, 0, zc), r, LID_T, slot).replace(sheet=LID_SHEET),  # pressed sheet, massed so
              g.cylinder((kx, 0, zc), (kx, 0, top), kr, knob_slot).with_grasps(grasp)]
    return pieces, Frame.at((-r, 0, zc), z=(0, -1, 0))


def flap(k: Kettle, slot: str) -> tuple[list[g.Piece], Frame]:
    """The whistle flap over the spout's end, hinged on its top edge (axis -Y: it swings out and up); the hinge
    line is behind the flap's middle, so its weight holds it shut against its stop."""
    sp = spout_of(k)
    axis, tip, r = sp.tip_axis, sp.tip, max(sp.across[1], sp.along[1]) + 0.003
    up = np.array([-axis[2], 0.0, axis[0]])  # across the end face, towards its top edge
    pieces = [g.cylinder(tip + 0.002 * axis, tip + 0.006 * axis, r, slot)]
    return pieces, Frame.at(tuple(tip + 0.002 * axis + r * up), z=(0, -1, 0))


def bail(k: Kettle, slot: str) -> tuple[list[g.Piece], Frame]:
    """A wire bail folded back over the body's back (pivots either side under the rim, axis +Y: it rises)."""
    zp = k.height - 0.15 * (k.height - k.z0)
    y = _r_at(k, zp) + 0.006
    reach = k.radius + 0.03
    path = [(0, -y, zp), (-reach + 0.01, -y, zp), (-reach, -y + 0.01, zp), (-reach, y - 0.01, zp),
            (-reach + 0.01, y, zp), (0, y, zp)]
    lugs = [g.cylinder((0, s * (y - 0.006), zp), (0, s * (y + 0.002), zp), 0.004, "trim") for s in (-1, 1)]
    return [g.tube(path, BAIL_R, slot), *lugs], Frame.at((0, 0, zp), z=(0, 1, 0))


def switch(k: Kettle, slot: str) -> tuple[list[g.Piece], Frame]:
    """The on/off toggle: a paddle out of the power base's back under the handle, tipping up about +Y on its
    root (pressed up to switch on)."""
    ln, w, t = SWITCH
    x, z = -k.radius - BASE[0], BASE[1] / 2
    x -= 0.001  # clear of the base
    pieces = [g.box_between((x - ln, -w / 2, z - t / 2), (x, w / 2, z + t / 2), slot)]
    return pieces, Frame.at((x, 0, z), z=(0, 1, 0))


def release_button(k: Kettle, slot: str) -> tuple[list[g.Piece], Frame]:
    """The lid release button on top of the handle's upper arm, pressed down (a slide along -Z)."""
    (_, _, zt), (xo, _, zo) = handle_path(k)[:2]
    ln, w, ht = BUTTON
    z = zo + HANDLE_R + 0.001
    pieces = [g.box_between((xo, -w / 2, z), (xo + ln, w / 2, z + ht), slot)]
    return pieces, Frame.at((xo + ln / 2, 0, z + ht), z=(0, 0, -1))
