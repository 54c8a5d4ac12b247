"""Pens: a retractable click pen, a capped stick pen and a multi-colour slider pen.

Local frame: the pen's axis is +z, its rear end at z = 0 and its writing tip at z = ``length``; local +x is the
side its clip is on. :func:`lying` lays it on the table: the axis along world +X (the tip in front), the clip
side up (a pen put down rolls onto the side away from its clip).

The barrels are thin walls of revolution (:func:`infmob_usd.geometry.shell`), hollow like the real moulded
tubes, so a click pen's refill runs inside its barrel and a cap slides over the front section: a click
pen's push button (role ``button``, spring-returned) drives the refill out of the nose (the refill's
joint is coupled to the button's); a capped pen's cap pulls off the front (role ``lift_off``); a
multi-colour pen's sliders run along slots in its upper barrel (each pushes its own refill out; role
``button``, returned by the refill's spring).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import IDENTITY, Frame

from .handtools import hull

WALL = 0.0009  # m, a moulded pen barrel's wall (0.8-1.0 mm: BIC Cristal, Pilot G2 barrels cut open)
CLEAR = 0.001  # m, radial clearance of a refill or plunger in its bore (a 2.5-3 mm refill in a 5 mm bore)
POINT = 0.0006  # m, radius of a ballpoint's metal point (1.0-1.2 mm across at the socket: ISO 12757 refills)
TIP_HOLE = 0.0005  # m, play of the point in the nose hole
CAP_INSET = 0.0005  # m, a cap's radius inside the barrel's: the pen lies on its barrel, its cap clear of the table
CAP_WALL = 0.0012  # m, a moulded cap's wall (1-1.2 mm: BIC Cristal, Pilot V5 caps)
CAP_PLAY = 0.0006  # m, radial play of a cap over the section it covers (a push-fit cap grips on its inner ribs)
REFILL_WALL = 0.0008  # m, a refill massed as a shell: its 0.5-0.6 mm polypropylene tube and the ink film in it
SECTORS = 16  # collision wedges round a barrel: their chords stay within 2 % of its radius, clear of what it holds


@dataclass(frozen=True)
class PenDesign:
    """One kind of pen (metres), from real products."""

    length: tuple[float, float]  # overall, capped or retracted
    radius: tuple[float, float]  # barrel outer radius
    nose: float  # length of the tapering nose cone
    travel: float  # click button or slider stroke
    tip_out: float  # how far the point comes out of the nose when clicked (0: a capped pen's fixed point)
    cap: float = 0.0  # cap length (0: no cap)
    sliders: tuple[int, int] = (0, 0)  # multi-colour: how many colour sliders (fewest, most)


PENS = {
    # Pilot G2 (144 mm, 10.8 mm across the grip, 5 mm click stroke), Parker Jotter (129 mm, 9.5 mm), Uni-ball
    # Signo RT: 128-148 mm, barrels 9-11 mm; the point comes 1.5-2.5 mm out of the nose when clicked
    "click": PenDesign((0.128, 0.148), (0.0046, 0.0055), 0.017, 0.0045, 0.0022),
    # BIC Cristal (149 mm capped, hexagonal barrel 8 mm across its flats, 50 mm cap), Pilot V5 (146 mm, 10 mm
    # round, 55 mm cap)
    "capped": PenDesign((0.140, 0.150), (0.0045, 0.0053), 0.014, 0.0, 0.0, cap=0.052),
    # BIC 4 Colours (144 mm, 13-14 mm barrel, 10 mm slider stroke, 2-4 sliders on its 2-, 3- and 4-colour
    # versions), Zebra Sarasa 2, Pilot Acroball 3
    "multi": PenDesign((0.138, 0.146), (0.0060, 0.0068), 0.022, 0.010, 0.0, sliders=(2, 4)),
}
"""Designs -> sizes (maker listings named beside each)."""

# clip length, width, thickness, stand-off at the root (m): Pilot G2 / Parker Jotter clips stand 1.5-2 mm off the
# barrel at their root and touch it only at the bead
CLIP = (0.045, 0.0036, 0.0009, 0.0017)
CLIP_BEND = 0.82  # share of the clip's length that runs straight before it bends down to its bead
SLIDER = (0.018, 0.0034, 0.0016, 0.0021)  # slider tab length, width, height, hook height (m): BIC 4 Colours
SLIDER_AT = -0.001  # m, the tabs' rear ends from the pen's rear end: their hooks stand 1 mm proud of it
SIDES = {"round": None, "hex": 6}  # a barrel's cross-section: round or a hexagonal stick (BIC Cristal)
CLIP_TURN = {2: 0.0, 3: 60.0, 4: 0.0}  # degrees: the clip between two sliders, none of them under the pen


@dataclass(frozen=True)
class Pen:
    design: PenDesign
    length: float
    radius: float
    sides: int | None = None  # a hexagonal barrel's section count

    @property
    def bore(self) -> float:
        return self.radius - WALL

    @property
    def nose_start(self) -> float:
        return self.length - self.design.nose

    @property
    def tip(self) -> float:
        """Outer radius at the very tip of the nose."""
        return POINT + TIP_HOLE + WALL


def pen(design: str, size: float, girth: float, shape: str = "round") -> Pen:
    """Sizes of one pen: ``size`` and ``girth`` (0-1) place its length and barrel radius in the design's ranges."""
    d = PENS[design]
    return Pen(d, d.length[0] + size * (d.length[1] - d.length[0]), d.radius[0] + girth * (d.radius[1] - d.radius[0]),
               SIDES[shape])


def lying(p: Pen) -> Frame:
    """The pen's frame on the table: its axis along world +X, its clip up."""
    return Frame.at((0.0, 0.0, p.radius), z=(1, 0, 0), x=(0, 0, 1))


def _tube(profile, thickness: float, material: str, name: str, sides: int | None = None) -> g.Piece:
    """A hollow section of barrel: ``profile`` (radius, z) of its outside, rear to front; ``sides``: a
    prism's (a hexagonal barrel), one flat slab per side and band for collisions."""
    piece = g.shell(profile, thickness, material, sections=sides, convex_sectors=SECTORS, name=name)
    if not sides:
        return piece
    th = 2 * math.pi * np.arange(sides + 1) / sides
    slabs = []
    for (r0, z0), (r1, z1) in zip(profile[:-1], profile[1:]):
        for a, b in zip(th[:-1], th[1:]):
            slabs.append([(r * math.cos(t), r * math.sin(t), z) for r, z in ((r0, z0), (r0 - thickness, z0),
                                                                           (r1, z1), (r1 - thickness, z1))
                          for t in (a, b)])
    return piece.replace(convex=[np.asarray(c) for c in slabs])


def _solid(profile, material: str, name: str, wall: float | None = 0.0, sides: int | None = None) -> g.Piece:
    return g.revolve(profile, material, sections=sides, name=name).replace(wall=wall)


def _nose(p: Pen, material: str, r0: float) -> g.Piece:
    """The nose cone from radius ``r0`` down to the hole the point comes out of (hollow)."""
    z0, z1 = p.nose_start, p.length
    prof = [(r0, z0), (0.92 * r0, z0 + 0.25 * (z1 - z0)), (0.5 * (r0 + p.tip), z0 + 0.7 * (z1 - z0)), (p.tip, z1)]
    return _tube(prof, r0 - p.bore if r0 - p.bore > WALL else WALL, material, "nose")


def clip(p: Pen, z0: float, r: float, material: str, forward: bool = True) -> list[g.Piece]:
    """A pocket clip on +x: its root block on the barrel at ``z0`` (radius ``r``), its strip running
    ``forward`` (+z) or back, standing off the barrel along most of its length (the gap a pocket's cloth
    goes in) and bent down at its end to the bead that presses on the barrel."""
    length, width, thick, off = CLIP
    s = 1.0 if forward else -1.0
    z1, zb = z0 + s * length, z0 + s * CLIP_BEND * length
    w = width / 2
    root = hull([(x, y, z) for x in (r - 0.4 * WALL, r + off + thick) for y in (-w, w)
                 for z in (z0, z0 + s * 0.006)], material, "clip_root")
    # the strip closes on the barrel by a fifth of its stand-off over its straight run, then bends down
    strip = hull([(x, y, z) for y in (-w, w) for x, z in ((r + off, z0), (r + off + thick, z0),
                                                          (r + 0.8 * off, zb), (r + 0.8 * off + thick, zb))],
                 material, "clip")
    bend = hull([(x, y, z) for y in (-0.9 * w, 0.9 * w) for x, z in (
        (r + 0.8 * off, zb), (r + 0.8 * off + thick, zb), (r + 0.1 * off, z1), (r + 0.1 * off + thick, z1))],
        material, "clip_end")
    bead = g.sphere((r + 0.1 * off + 0.5 * thick, 0.0, z1), 0.75 * thick, material, name="clip_bead")
    return [root, strip, bend, bead]


# -- click pen ----------------------------------------------------------------------------------------
def _click_layout(p: Pen) -> tuple[float, float, float]:
    """z of the plunger's front end, the refill's rear end and the grip's start."""
    plunger_front = 0.006
    refill_rear = plunger_front + p.design.travel - p.design.tip_out + CLEAR
    return plunger_front, refill_rear, 0.62 * p.length


def click_body(p: Pen, barrel: str, metal: str, clip_mat: str, grip: bool) -> Assembly:
    """A click pen's barrel (hollow: the plunger and refill run in it), its nose and clip; with a ``grip``
    the front section is left to :func:`click_grip`."""
    r, z_grip, z_nose = p.radius, _click_layout(p)[2], p.nose_start
    pieces = [_tube([(r, 0.0), (r, 0.004), (r, z_grip)], WALL, barrel, "barrel")]
    if not grip:
        pieces.append(_tube([(r, z_grip), (0.97 * r, z_nose)], 0.97 * r - p.bore, barrel, "front_barrel"))
    pieces.append(_nose(p, metal, 0.97 * r if not grip else r))
    pieces += clip(p, 0.002, r, clip_mat)
    anchors = {"button": IDENTITY, "refill": Frame.at((0.0, 0.0, p.length))}
    return Assembly.single("body", pieces, anchors)


def click_grip(p: Pen, grip: str) -> list[g.Piece]:
    """A moulded rubber grip over a click pen's front section, with raised rings at both ends."""
    r, z_grip, z_nose = p.radius, _click_layout(p)[2], p.nose_start
    rg = r + 0.0005
    return [_tube([(r, z_grip), (rg, z_grip + 0.002), (rg, z_nose - 0.002), (r, z_nose)], rg - p.bore, grip, "grip")]


def click_button(p: Pen, material: str) -> Assembly:
    """The push button: a knob out of the rear end and its plunger in the barrel, pressed along +z."""
    front = _click_layout(p)[0]
    rb = p.bore - CLEAR
    out = 0.0015 + p.design.travel + 0.0025  # what stands out of the barrel at rest
    prof = [(0.0, -out), (0.75 * rb, -out), (rb, -out + 0.0012), (rb, front), (0.0, front)]
    return Assembly.single("button", [_solid(prof, material, "button")], {"slide": IDENTITY})


def refill(p: Pen, tube: str, metal: str) -> Assembly:
    """The refill: its ink tube in the bore, its cone and metal point inside the nose (at rest just behind
    the hole), pushed ``tip_out`` forward by the plunger."""
    d = p.design.tip_out
    rear = _click_layout(p)[1]
    rf = p.bore - CLEAR
    # the nose's bore shrinks linearly from the barrel's to the point's hole: the refill keeps CLEAR / 2 inside
    # it also where it has moved forward d
    inner_tip = p.tip - WALL
    slope = (p.bore - inner_tip) / p.design.nose

    def fits(r: float) -> float:  # the z (at rest) from which a section of radius r no longer fits
        return p.nose_start + (p.bore - 0.5 * CLEAR - r) / slope - d

    z_cone = min(fits(rf), p.nose_start - d)
    z_point = p.length - d - 0.0003
    end = p.length - 0.0004
    tube_p = [(0.0, rear), (rf, rear), (rf, z_cone), (POINT + 0.0002, fits(POINT + 0.0002)), (0.0, z_point)]
    point = [(0.0, z_point - 0.001), (POINT, z_point - 0.001), (POINT, end - POINT), (0.6 * POINT, end - 0.3 * POINT),
             (0.0, end)]
    pieces = [_solid(tube_p, tube, "ink_tube", wall=REFILL_WALL), _solid(point, metal, "point")]
    return Assembly.single("refill", pieces, {"slide": Frame.at((0.0, 0.0, p.length))})


# -- capped pen ---------------------------------------------------------------------------------------
def _cap_seat(p: Pen) -> tuple[float, float, float]:
    """z of the cap's mouth, the cap's outer radius (:data:`CAP_INSET` inside the barrel's: the pen lies on its
    barrel, not on its cap) and the radius of the section it covers."""
    rc = p.radius * (math.cos(math.pi / p.sides) if p.sides else 1.0) - CAP_INSET  # under a hexagon's flats
    return p.length + 0.003 - p.design.cap, rc, rc - CAP_WALL - CAP_PLAY


def capped_body(p: Pen, barrel: str, plug: str, metal: str) -> Assembly:
    """A stick pen: its barrel (hexagonal or round) with an end plug, the stepped-down section the cap
    covers and a solid nose with its metal point."""
    r, (mouth, _, rs) = p.radius, _cap_seat(p)
    step = mouth - 0.004
    flat = Frame.at().turned("z", math.pi / p.sides).matrix if p.sides else np.eye(4)  # a flat under the clip
    pieces = [_tube([(0.97 * r, 0.0), (r, 0.003), (r, step)], WALL, barrel, "barrel", p.sides).transformed(flat),
              _solid([(0.0, -0.0035), (0.55 * r, -0.0035), (0.7 * r, -0.0015), (0.7 * r, 0.002), (0.0, 0.002)],
                     plug, "end_plug")]
    nz = p.nose_start  # the section under the cap and the nose: solid (the ink reservoir fills it), its shoulder
    sh = p.bore * (math.cos(math.pi / p.sides) if p.sides else 1.0)  # closing the barrel's front end
    pieces.append(_solid([(0.0, step - 0.005), (sh, step - 0.005), (sh, step), (rs, step + 0.0015), (0.85 * rs, nz),
                          (0.5 * rs, nz + 0.7 * p.design.nose), (p.tip, p.length - 0.0008), (0.0, p.length - 0.0008)],
                         barrel, "nose", wall=None))
    pieces.append(g.sphere((0.0, 0.0, p.length - 0.0006), POINT, metal, name="point"))
    return Assembly.single("body", pieces, {"cap": Frame.at((0.0, 0.0, mouth))})


def cap_engagement(p: Pen) -> float:
    """How far the cap slides before its mouth clears the point: the length of barrel it covers."""
    return p.length - _cap_seat(p)[0]


def cap(p: Pen, material: str, clip_mat: str) -> Assembly:
    """The cap: a tube closed at its front (a vent hole in the dome), pulled off along +z, with its clip
    running back from the front."""
    mouth, rc, _ = _cap_seat(p)
    end = p.length + 0.003
    pieces = [_tube([(rc - 0.0002, mouth), (rc, mouth + 0.003), (rc, end)], CAP_WALL, material, "cap"),
              _solid([(0.0, end), (rc, end), (0.8 * rc, end + 0.003), (0.0, end + 0.0035)], material, "cap_dome")]
    pieces += clip(p, end + 0.001, rc, clip_mat, forward=False)
    return Assembly.single("cap", pieces, {"seat": Frame.at((0.0, 0.0, mouth))})


# -- multi-colour pen ---------------------------------------------------------------------------------
def multi_body(p: Pen, upper: str, lower: str, metal: str, slot: str, count: int) -> Assembly:
    """A multi-colour pen's barrel: the coloured upper half with a dark slot under each slider, the clear-
    ish lower half, the nose with its tip ring, a clip between two sliders; anchors ``slider_<k>``."""
    r, mid = p.radius, 0.48 * p.length
    pieces = [_tube([(0.9 * r, 0.0), (r, 0.0025), (r, mid)], WALL, upper, "upper_barrel"),
              _solid([(0.0, 0.0005), (0.9 * r, 0.0005), (0.9 * r, 0.003), (0.0, 0.003)], upper, "end_cap", wall=None),
              _tube([(r, mid), (0.99 * r, p.nose_start)], WALL, lower, "lower_barrel"), _nose(p, lower, 0.99 * r),
              _solid([(0.0, p.length - 0.0016), (p.tip + 0.0002, p.length - 0.0016), (p.tip, p.length - 0.0002),
                      (0.0, p.length - 0.0002)], metal, "tip_ring")]
    turn, length, width = math.radians(CLIP_TURN[count]), SLIDER[0], SLIDER[1]
    anchors = {}
    for k, phi in enumerate(slider_angles(count)):
        at = Frame.at((0.0, 0.0, SLIDER_AT)).turned("z", phi)
        anchors[f"slider_{k}"] = at
        z1 = SLIDER_AT + length + p.design.travel + 0.001
        groove = hull([(x, y, z) for x in (r - 0.5 * WALL, r + 0.00005) for y in (-0.35 * width, 0.35 * width)
                       for z in (SLIDER_AT - 0.001, z1)], slot, "slot")
        pieces.append(groove.transformed(at.matrix @ Frame.at((0.0, 0.0, -SLIDER_AT)).matrix))
    clip_at = Frame.at((0.0, 0.0, 0.0)).turned("z", turn)
    pieces += [c.transformed(clip_at.matrix) for c in clip(p, SLIDER_AT + length + p.design.travel + 0.003, r, metal)]
    return Assembly.single("body", pieces, anchors)


def slider_angles(count: int) -> list[float]:
    """Radians about the axis from the clip side: the sliders evenly round the barrel, the clip between
    two of them and none under the pen as it lies on the table."""
    c = math.radians(CLIP_TURN[count])
    return [c + math.pi / count + 2 * math.pi * k / count for k in range(count)]


def slider(p: Pen, material: str) -> Assembly:
    """One colour slider: a tab on the barrel (in its own frame on +x at z = 0) with a raised hook at its
    rear end that a thumbnail pushes forward (+z)."""
    length, width, height, hook = SLIDER
    r0, w = p.radius + 0.00035, width / 2
    tab = hull([(x, y, z) for x in (r0, r0 + height) for y in (-w, w) for z in (0.0, length)], material, "tab")
    nib = hull([(x, y, z) for x in (r0, r0 + hook) for y in (-w, w) for z in (0.0, 0.0035)], material, "hook")
    return Assembly.single("slider", [tab, nib], {"slide": IDENTITY})
