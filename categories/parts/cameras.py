"""Cameras standing on their base plate: a DSLR with a zoom lens, a mirrorless camera with a short retracting
zoom, a compact with a telescoping lens, an instant camera, an action camera.

Local frame: the camera stands on z = 0, its lens along +x, its back (the screen, the film door) at x = 0,
centred on y = 0; a hand holds the grip at -y (the camera's right, seen from behind). Sizes from the
products named beside each figure; moving parts keep :data:`GAP` from what carries them, and what turns
about the lens axis or slides along it is a hollow tube (a wall of revolution) so the parts nest.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import Frame
from infmob_usd.grasps import Grasp
from infmob_usd.physical import MIN_HULL_WIDTH
from infmob_usd.profiles import sections_for

from .handtools import hull
from .usb import slab

SPAN = 0.003  # m, the least length of a rounded block's collision piece (no end sliver for the core to widen)
GAP = 0.0004  # m, between a moving part and its carrier (moulded barrels, rings and doors: 0.2-0.5 mm)
WALL = MIN_HULL_WIDTH  # m, a barrel's or a door's wall (1.5-2 mm moulded polycarbonate)


@dataclass(frozen=True)
class CameraDesign:
    """One kind of camera (metres): body width (y), height (z) and depth (x, lens and grip excluded), the
    lens's radius and length at rest and how far it extends, the shutter button's radius."""

    width: tuple[float, float]
    height: tuple[float, float]
    depth: tuple[float, float]
    lens: tuple[float, float]  # radius range
    length: float  # lens length out of the body at rest (DSLR: the whole zoom lens)
    travel: float  # how far the lens (each stage) extends
    shutter: float


DESIGNS = {
    # Canon EOS 250D 122.4 x 92.6 x 69.8 mm (grip included), 449 g with battery; Nikon D3500 124 x 97 x 69.5 mm,
    # 415 g; EF-S 18-55 mm f/4-5.6 IS STM 66.5 mm across, 61.8 mm long, extends ~20 mm at 55 mm
    "dslr": CameraDesign((0.120, 0.135), (0.090, 0.102), (0.048, 0.056), (0.031, 0.036), 0.062, 0.020, 0.0045),
    # Sony RX100 III 101.6 x 58.1 x 41 mm, 290 g; Canon PowerShot SX620 HS 97 x 57 x 28 mm, 182 g: a lens in two
    # telescoping stages, ~12 mm each at full zoom
    "compact": CameraDesign((0.096, 0.110), (0.056, 0.064), (0.030, 0.042), (0.017, 0.022), 0.0025, 0.011, 0.0038),
    # Fujifilm Instax Mini 12 104 x 122 x 66.6 mm, 306 g; Polaroid Now 150 x 112 x 94 mm, 457 g: the lens barrel
    # pops out ~12 mm to switch on
    "instant": CameraDesign((0.104, 0.118), (0.112, 0.124), (0.060, 0.072), (0.026, 0.031), 0.004, 0.012, 0.0055),
    # Sony a6400 120 x 66.9 x 59.7 mm (grip included), 403 g; Nikon Z50 126.5 x 93.5 x 60 mm (EVF hump included),
    # 450 g; Canon EOS R50 116.3 x 85.5 x 68.8 mm, 375 g: a body ~40 mm deep with a shallow grip; kit zooms
    # Sony E PZ 16-50 (64.7 mm across, 29.9 mm long), Nikon Z DX 16-50 (70 x 32 mm) unlock ~10 mm longer
    "mirrorless": CameraDesign((0.116, 0.127), (0.066, 0.076), (0.036, 0.044), (0.028, 0.033), 0.036, 0.010,
                               0.0042),
    # GoPro HERO12 Black 71.8 x 50.8 x 33.6 mm, 154 g; DJI Osmo Action 4 70.5 x 44.2 x 32.8 mm, 145 g: a block
    # with a fixed wide-angle lens in a square cover off to one side, a front status screen, the shutter on top
    # and the battery door on the side; its front element ~18 mm across
    "action": CameraDesign((0.0705, 0.0720), (0.044, 0.051), (0.026, 0.030), (0.0085, 0.0100), 0.004, 0.0, 0.0040),
}
"""Designs -> sizes (maker data sheets named beside each)."""

ZOOM_TURN = math.radians(75.0)  # the zoom ring's throw, 18 to 55 mm (EF-S 18-55, AF-P 18-55: 70-80 degrees)
SHUTTER_TRAVEL = 0.0012  # m, half-press and full press of a shutter button (~0.5 + 0.7 mm)
SCREEN_TILT = math.radians(175.0)  # a tilting screen turns up to face the front for selfies (Sony RX100 III+)
DOOR_OPENS = math.radians(100.0)  # a side card door or a film door on its hinge
GRIP_OUT = {"dslr": 0.019, "mirrorless": 0.017}
"""m, how far a grip stands out of the body's front (EOS 250D: 69.8 mm deep overall over a ~50 mm body; a6400:
59.7 mm over ~42 mm)."""
VIEWFINDERS = ("hump", "corner")
"""A mirrorless camera's electronic viewfinder: in a hump over the lens (Nikon Z50, Canon R50, Fujifilm X-T30) or
in the body's top corner with a flat top plate, rangefinder style (Sony a6400, Fujifilm X-E4)."""


@dataclass(frozen=True)
class Camera:
    design: str
    width: float
    height: float
    depth: float
    lens: float  # radius
    round: float  # 0-1: from crisp to soft edges
    reach: float = 1.0  # a DSLR lens's length and zoom travel over the kit zoom's (1.5: an 18-135 mm)
    evf: str = "hump"  # a mirrorless camera's viewfinder (:data:`VIEWFINDERS`)

    @property
    def length(self) -> float:
        return self.d.length * self.reach

    @property
    def travel(self) -> float:
        return self.d.travel * self.reach

    @property
    def d(self) -> CameraDesign:
        return DESIGNS[self.design]

    @property
    def interchangeable(self) -> bool:
        """A body with a lens mount and a grip (DSLR, mirrorless)."""
        return self.design in GRIP_OUT

    @property
    def edge(self) -> float:
        soft = {"dslr": 0.1, "mirrorless": 0.12, "action": 0.1}.get(self.design, 0.18)
        return (0.06 + soft * self.round) * min(self.depth, self.height)

    @property
    def axis(self) -> tuple[float, float]:
        """(y, z) of the lens axis: low on a lens mount (its barrel just clears the table), centred on a compact,
        above the middle of an instant camera, high and off to the side on an action camera."""
        y = {"dslr": 0.06, "mirrorless": 0.1, "compact": 0.18, "action": 0.2}.get(self.design, 0.0) * self.width
        z = {"compact": 0.5, "instant": 0.42, "action": 0.62}.get(self.design, 0.0) * self.height
        return y, max(z, self.lens + 0.004)

    @property
    def grip(self) -> tuple[float, float]:
        """A grip's width (y) and how far it stands out of the front (x)."""
        return (0.26 if self.design == "dslr" else 0.22) * self.width, GRIP_OUT[self.design]


def camera(design: str, size: float, shape: float, roundness: float, reach: float = 1.0, evf: str = "hump"
           ) -> Camera:
    d = DESIGNS[design]
    lerp = lambda r, t: r[0] + t * (r[1] - r[0])  # noqa: E731
    height, lens = lerp(d.height, shape), lerp(d.lens, size)
    if design == "mirrorless":  # its mount's flange (4 mm round the lens) stays under the top plate
        lens = min(lens, 0.5 * height - 0.0045)
    return Camera(design, lerp(d.width, size), height, lerp(d.depth, 1 - shape), lens, roundness,
                  reach if design == "dslr" else 1.0, evf)


# -- helpers ----------------------------------------------------------------------------------------
def along_lens(c: Camera, piece: g.Piece) -> g.Piece:
    """A piece made about +z (a revolve or a shell, z along the lens) turned onto the lens axis (+x)."""
    y, z = c.axis
    return piece.transformed(Frame.at((0.0, y, z), z=(1, 0, 0), x=(0, 0, 1)).matrix)


def tube(c: Camera, r: float, x0: float, x1: float, thick: float, material: str, name: str) -> g.Piece:
    """A hollow tube about the lens axis from x0 to x1, outer radius ``r``."""
    # 24 wedges round: a wedge's inner face is a chord, 0.2-0.3 mm inside a 30 mm bore (8 would be 2 mm)
    return along_lens(c, g.shell([(r, x0), (r, x1)], thick, material, sections=round_sections(r), convex_sectors=24,
                                 name=name))


def round_sections(r: float) -> int:
    """Sections round a lens's rings and glass: a camera is seen close up, where the 12-16 facets the chord
    tolerance allows a 1-2 cm ring show as a polygon."""
    return max(32, sections_for(r))


def lens_axis(c: Camera, x: float) -> Frame:
    y, z = c.axis
    return Frame.at((x, y, z), z=(1, 0, 0))


def _front_glass(c: Camera, r: float, x: float, rim: str, glass: str, mark: str) -> list[g.Piece]:
    """The front of a lens: a black rim ring printed with a white ring and the lens's inscription (drawn as
    dashes), the front element behind it a domed meniscus of coated glass (its curve catches a highlight,
    as a real front element does) over the black inside of the barrel."""
    y, z = c.axis
    ge = 0.84 * r
    sag = min(0.3 * ge, 0.0045)  # a front element's dome: 3-5 mm on a compact's or a kit zoom's front lens
    edge = x - 0.0008 - sag  # its apex 0.8 mm inside the rim's face
    back = edge - 0.0012
    dome = [(0.0, back), (ge, back), (ge, edge)]
    dome += [(ge * math.cos(a), edge + sag * math.sin(a)) for a in np.linspace(0.3, math.pi / 2, 7)]
    dome[-1] = (0.0, dome[-1][1])
    face = 0.18 * r  # the rim's front face, from its outside inward
    pieces = [tube(c, r, x - 0.003, x, face, rim, "rim"),
              along_lens(c, g.revolve(dome, glass, sections=round_sections(ge), name="element")),
              g.cylinder((back - 0.0012, y, z), (back - 0.0002, y, z), ge, rim, name="inside").replace(convex=())]
    ring = tube(c, r - 0.62 * face, x, x + 6e-5, 0.08 * face, mark, "print").replace(convex=())
    dashes = []
    for k, a in enumerate(np.linspace(0.25 * math.pi, 1.55 * math.pi, 14)):  # the text round the ring's top
        if k % 5 == 4:
            continue  # word spaces
        rr = r - 0.3 * face
        cy, cz = y + rr * math.cos(a), z + rr * math.sin(a)
        t = np.array([0.0, -math.sin(a), math.cos(a)])
        n = np.array([0.0, math.cos(a), math.sin(a)])
        pts = [np.array([xx, cy, cz]) + u * t * 0.22 * face + v * n * 0.12 * face
               for xx in (x, x + 6e-5) for u in (-1, 1) for v in (-1, 1)]
        dashes.append(hull(pts, mark, "print"))
    return pieces + [ring, *_merged(dashes, mark, "inscription")]


def strap_lugs(c: Camera, metal: str, sides: tuple[int, ...] = (-1, 1)) -> list[g.Piece]:
    """The strap lugs: a steel eyelet standing out of each of ``sides`` of the body near its top (DSLRs and
    instant cameras carry two, a compact one on its right; Canon EOS 250D, Instax Mini 12, Sony RX100).
    Drawn: a strap's ring is no collision shape."""
    out = []
    for s in sides:
        yw = s * c.width / 2
        zc, xc = 0.78 * c.height, 0.62 * c.depth
        ring = [(xc + 0.0028 * math.cos(a), 0.0, zc + 0.0020 * math.sin(a))
                for a in np.linspace(0, 2 * math.pi, 13)[:-1]]
        for a, b in zip(ring, ring[1:] + ring[:1], strict=True):
            pts = [(p[0], yw + s * dy, p[2] + dz) for p in (a, b) for dy in (0.0003, 0.0016)
                   for dz in (-0.00045, 0.00045)]
            out.append(hull(pts, metal, "lug").replace(convex=()))
    return _merged(out, metal, "strap_lugs")


def box_pts(lo, hi) -> np.ndarray:
    return np.array([(a, b, e) for a in (lo[0], hi[0]) for b in (lo[1], hi[1]) for e in (lo[2], hi[2])])


# -- bodies ----------------------------------------------------------------------------------------
def _shell_body(c: Camera, body: str, bore: float, bore_depth: float) -> g.Piece:
    """The body's rounded block, colliding as boxes round a square bore (``bore`` half side, ``bore_depth``
    deep from the front) where a lens retracts into it."""
    w, h, d = c.width, c.height, c.depth
    visual = slab(0.0, d, w, h, 0.0, c.edge, c.edge, c.edge, body, "body", wall=0.0, span=SPAN)
    if bore <= 0:
        return visual
    y, z = c.axis
    x0 = d - bore_depth
    cells = [((0.0, -w / 2, 0.0), (x0, w / 2, h)),
             ((x0, -w / 2, 0.0), (d, y - bore, h)), ((x0, y + bore, 0.0), (d, w / 2, h)),
             ((x0, y - bore, 0.0), (d, y + bore, z - bore)), ((x0, y - bore, z + bore), (d, y + bore, h))]
    return visual.replace(convex=[box_pts(lo, hi) for lo, hi in cells])


def mount_body(c: Camera, body: str, grip: str, metal: str, lens: str, screen: str | None) -> Assembly:
    """A DSLR's or a mirrorless camera's body: the block, the hand grip, the viewfinder (a DSLR's pentaprism
    hump, a mirrorless camera's EVF hump or corner eyepiece) with the hot shoe, the lens mount and the fixed rear
    barrel of the lens (the zoom ring and the inner barrel are parts of their own), a fixed screen unless it
    tilts."""
    w, h, d = c.width, c.height, c.depth
    gw, gd = c.grip
    y, z = c.axis
    pieces = [_shell_body(c, body, 0.0, 0.0),
              slab(d - 0.012, d + gd, gw, 0.92 * h, 0.0, 0.2 * gw, 0.25 * gw, 0.45 * gd, grip, "grip", wall=0.0,
                   span=SPAN).translated((0.0, -w / 2 + gw / 2, 0.0)),
              *_finder(c, body, grip, metal, lens)]
    r = c.lens
    # the mount's bright steel flange shows as a thin ring between the body and the lens's black base
    mount = tube(c, r + 0.004, d - 0.001, d + 0.0022, 0.006, metal, "mount")
    base = tube(c, r + 0.0025, d + 0.0022, d + 0.006, 0.0045, lens, "lens_base")
    barrel = tube(c, r, d + 0.006, d + c.length * 0.45, 0.004, lens, "barrel")
    pieces += [mount, base, barrel, g.cylinder((d + 0.002, y, z), (d + 0.004, y, z), r - 0.004, body, name="throat")]
    pieces += strap_lugs(c, metal)
    if screen:
        pieces += _screen_pieces(c, -0.0005, screen, body)
    # a DSLR's mode dial on the shoulder left of the prism (seen from behind); a mirrorless camera's on the top
    # plate between the grip and the viewfinder (Nikon Z50, Canon R50, Sony a6400's on the right shoulder)
    dial = (0.5 * d, 0.34 * w, h) if c.design == "dslr" else (0.45 * d, -0.25 * w, h)
    return Assembly.single("body", pieces, {"shutter": Frame.at((d + 0.5 * gd - 0.006, -w / 2 + 0.5 * gw, 0.92 * h)),
                                            "dial": Frame.at(dial)})


def _finder(c: Camera, body: str, eyecup: str, metal: str, window: str) -> list[g.Piece]:
    """The viewfinder: a DSLR's pentaprism hump over the lens (tapering to its top, the hot shoe on it); a
    mirrorless camera's squarer EVF hump, its eyepiece window on its flat back, or a rangefinder-style flat top
    with the eyepiece's rubber cup standing out of the back's top corner away from the grip and the hot shoe on
    the plate."""
    w, h, d = c.width, c.height, c.depth
    y = c.axis[0]
    ph = 0.2 * h
    if c.design == "dslr":
        hump = hull(np.vstack([box_pts((0.18 * d, y - 0.18 * w, h - 0.004), (0.92 * d, y + 0.18 * w, h)),
                               box_pts((0.3 * d, y - 0.13 * w, h + ph - 0.001), (0.72 * d, y + 0.13 * w, h + ph))]),
                    body, "prism")
        return [hump, g.box_between((0.35 * d, y - 0.011, h + ph), (0.65 * d, y + 0.011, h + ph + 0.002), metal,
                                    name="hot_shoe")]
    if c.evf == "hump":
        ph = 0.22 * h
        hump = hull(np.vstack([box_pts((0.0, y - 0.16 * w, h - 0.004), (0.85 * d, y + 0.16 * w, h)),
                               box_pts((0.0, y - 0.12 * w, h + ph - 0.002), (0.62 * d, y + 0.12 * w, h + ph))]),
                    body, "evf")
        eyepiece = g.box_between((-3e-4, y - 0.075 * w, h + 0.12 * ph), (1e-4, y + 0.075 * w, h + 0.78 * ph),
                                 window, bevel=0.0008, name="eyepiece").replace(convex=())
        return [hump, eyepiece, g.box_between((0.15 * d, y - 0.011, h + ph), (0.5 * d, y + 0.011, h + ph + 0.002),
                                              metal, name="hot_shoe")]
    y0, y1, z0, z1 = 0.22 * w, 0.44 * w, 0.72 * h, 0.95 * h
    cup = g.box_between((-0.006, y0, z0), (0.001, y1, z1), eyecup, bevel=0.002, name="eyecup")
    eyepiece = g.box_between((-0.0063, y0 + 0.003, z0 + 0.003), (-0.0059, y1 - 0.003, z1 - 0.003), window,
                             name="eyepiece").replace(convex=())
    shoe = g.box_between((0.25 * d, y - 0.011, h - 1e-4), (0.6 * d, y + 0.011, h + 0.0018), metal, name="hot_shoe")
    return [cup, eyepiece, shoe]


def _screen_pieces(c: Camera, x_back: float, screen: str, frame: str) -> list[g.Piece]:
    """A rear screen lying on the back (x from ``x_back`` back by its frame): a dark frame and the panel."""
    sw, sh = 0.62 * c.width, 0.56 * c.height
    y0 = 0.12 * c.width if c.design != "instant" else 0.0
    z0 = 0.12 * c.height
    t = WALL + 0.004
    return [slab(x_back - t, x_back, sw, sh, z0, 0.002, 0.002, 0.0005, frame, "screen_frame", wall=0.0, span=SPAN)
            .translated((0.0, -y0, 0.0)),
            g.box_between((x_back - t - 2e-4, -y0 - 0.44 * sw, z0 + 0.07 * sh), (x_back - t + 1e-4, -y0 + 0.44 * sw,
                                                                                 z0 + 0.93 * sh), screen,
                          name="lcd").replace(convex=())]


def compact_body(c: Camera, body: str, metal: str, stages: int) -> Assembly:
    """A compact's block with the lens collar round the bore its ``stages`` telescoping barrels retract into."""
    d = c.depth
    r = c.lens
    w, h = c.width, c.height
    pieces = [_shell_body(c, body, r + GAP, bore_depth(c, stages)),
              tube(c, r + 0.004, d - 0.001, d + c.length, 0.004 - 2 * GAP, metal, "collar"),
              # the pop-up flash's window and the AF-assist lamp at the top corner away from the lens
              g.box_between((d - 0.001, -0.42 * w, 0.74 * h), (d + 0.0008, -0.2 * w, 0.88 * h), "flash", bevel=0.0006,
                            name="flash"),
              g.cylinder((d - 0.001, -0.12 * w, 0.8 * h), (d + 0.0008, -0.12 * w, 0.8 * h), 0.0022, "lamp",
                         name="lamp"),
              *strap_lugs(c, metal, (1,))]
    return Assembly.single("body", pieces, {"shutter": Frame.at((0.5 * d, -0.32 * w, h)),
                                            "dial": Frame.at((0.5 * d, -0.12 * w, h))})


def bore_depth(c: Camera, stages: int) -> float:
    """How deep the lens's stages reach into the body at rest."""
    return min(c.depth - 0.006, c.travel + 0.004 + 0.002 * stages)


def instant_body(c: Camera, body: str, trim: str, glass: str, stages: int) -> Assembly:
    """An instant camera's block: the lens collar round the bore the barrel pops out of, the viewfinder
    window and the flash window on the front, the film slot on top."""
    w, h, d = c.width, c.height, c.depth
    y, z = c.axis
    r = c.lens
    pieces = [_shell_body(c, body, r + GAP, bore_depth(c, stages)),
              tube(c, r + 0.006, d - 0.001, d + c.length, 0.006 - GAP, trim, "collar"),
              g.box_between((d - 0.001, 0.22 * w, 0.80 * h), (d + 0.0015, 0.40 * w, 0.90 * h), glass, bevel=0.0006,
                            name="viewfinder"),
              g.box_between((d - 0.001, -0.42 * w, 0.78 * h), (d + 0.0015, -0.12 * w, 0.92 * h), "flash",
                            bevel=0.0008, name="flash"),
              g.box_between((0.3 * d, -0.32 * w, h - 5e-4), (0.62 * d, 0.32 * w, h + 1e-4), trim,
                            name="film_slot").replace(convex=()),
              *strap_lugs(c, trim)]
    del y, z
    return Assembly.single("body", pieces, {"shutter": Frame.at((d, -0.36 * w, 0.7 * h), z=(1, 0, 0), x=(0, 0, 1))})


def action_body(c: Camera, shell: str, trim: str, element: str, mark: str, screen: str) -> Assembly:
    """An action camera's block: the fixed wide-angle lens behind its square cover glass off to the +y side of
    the front, the square status screen beside it, the touch screen over most of the back (GoPro HERO9-12,
    DJI Osmo Action 3-4)."""
    w, h, d = c.width, c.height, c.depth
    y, z = c.axis
    r, s = c.lens, 1.35 * c.lens  # the square cover: ~26 mm over an ~18 mm front element
    pieces = [_shell_body(c, shell, 0.0, 0.0),
              g.box_between((d - 0.001, y - s, z - s), (d + 0.0035, y + s, z + s), trim, bevel=0.0015,
                            name="lens_cover"),
              *_front_glass(c, r, d + 0.0065, trim, element, mark)]
    side = 0.5 * h  # the front status screen (HERO12: 1.4 in square)
    y1 = y - s - 0.004
    pieces += [g.box_between((d - 0.001, y1 - side - 0.002, 0.22 * h), (d + 0.0008, y1, 0.22 * h + side + 0.002),
                             trim, bevel=0.0006, name="front_bezel"),
               g.box_between((d + 0.0006, y1 - side, 0.22 * h + 0.002), (d + 0.0010, y1 - 0.002, 0.22 * h + side),
                             screen, name="front_screen").replace(convex=())]
    t = 0.0012
    sw, sh = 0.84 * w, 0.78 * h  # the rear touch screen (HERO12: 2.27 in)
    pieces += [slab(-t, 0.0005, sw, sh, 0.11 * h, 0.002, 0.001, 0.0, trim, "screen_frame", wall=0.0, span=0.0),
               g.box_between((-t - 2e-4, -0.45 * sw, 0.11 * h + 0.05 * sh),
                             (-t + 1e-4, 0.45 * sw, 0.11 * h + 0.95 * sh), screen, name="lcd").replace(convex=())]
    return Assembly.single("body", pieces, {"shutter": Frame.at((0.5 * d, -0.2 * w, h))})


# -- moving parts ------------------------------------------------------------------------------------
def zoom_ring(c: Camera, rubber: str) -> Assembly:
    """A DSLR lens's ribbed zoom ring on the rear barrel (turns about the lens axis, +x)."""
    d, r = c.depth, c.lens
    x0, x1 = d + c.length * 0.45 + GAP, d + c.length * 0.8
    ring = tube(c, r + 0.0015, x0, x1, 0.005, rubber, "zoom_ring")
    y, z = c.axis
    ribs = []
    for k in range(28):
        a = 2 * math.pi * k / 28
        cy, cz = y + (r + 0.0015) * math.cos(a), z + (r + 0.0015) * math.sin(a)
        ribs.append(g.box_between((x0 + 0.002, cy - 0.0008, cz - 0.0008), (x1 - 0.002, cy + 0.0008, cz + 0.0008),
                                  rubber).replace(convex=()))
    top = np.array([(x0 + x1) / 2, y, z + r + 0.0015])
    ring = ring.with_grasps(Grasp.make(top, (0, 0, -1), (1, 0, 0), x1 - x0, 0.004))
    return Assembly.single("zoom_ring", [ring, *_merged(ribs, rubber, "ribs")], {"axis": lens_axis(c, x0)})


def _merged(pieces: list[g.Piece], material: str, name: str) -> list[g.Piece]:
    """Decoration pieces as one mesh (no collision)."""
    v, f, n = [], [], 0
    for p in pieces:
        v.append(p.vertices)
        f.append(p.faces + n)
        n += len(p.vertices)
    return [g.Piece(np.vstack(v), np.vstack(f), material, (), name)]


def inner_barrel(c: Camera, body: str, rim: str, glass: str, mark: str) -> Assembly:
    """A DSLR lens's inner barrel: it slides out of the ring's front as the ring zooms in (+x)."""
    d, r = c.depth, c.lens
    x_front = d + c.length
    back = d + c.length * 0.45 - c.travel  # inside the rear barrel, clear of the mount's throat
    pieces = [tube(c, r - 0.0045 - GAP, back, x_front - 0.003, WALL, body, "inner_barrel"),
              *_front_glass(c, r - 0.0045 - GAP, x_front, rim, glass, mark)]
    return Assembly.single("barrel", pieces, {"slide": lens_axis(c, x_front)})


def lens_stage(c: Camera, k: int, stages: int, body: str, rim: str, glass: str, mark: str) -> Assembly:
    """Stage ``k`` (0 outermost) of a telescoping lens: a tube nested in the last, standing 2 mm further out
    at rest, the front element on the innermost; anchor ``slide`` (+x)."""
    r = c.lens - k * (WALL + GAP)
    front = c.depth + c.length + 0.002 * (k + 1)
    back = c.depth - bore_depth(c, stages) + GAP * (k + 1) + 0.0015 * k
    pieces = [tube(c, r, back, front - (0.003 if k == stages - 1 else 0.0008), WALL, body, "stage")]
    if k == stages - 1:
        pieces += _front_glass(c, r, front, rim, glass, mark)
    else:
        pieces.append(tube(c, r, front - 0.0008, front, WALL + 0.0006, rim, "stage_rim"))
    return Assembly.single("barrel", pieces, {"slide": lens_axis(c, front)})


def shutter(c: Camera, metal: str) -> Assembly:
    """The shutter button in its collar (pressed along the ``press`` anchor's z)."""
    r = c.d.shutter
    cap = g.cylinder((0, 0, SHUTTER_TRAVEL + GAP), (0, 0, SHUTTER_TRAVEL + GAP + 0.0022), r, metal, name="button")
    cap = cap.with_grasps(Grasp.make((0, 0, SHUTTER_TRAVEL + GAP + 0.0022), (0, 0, -1), (1, 0, 0), 2 * r, 0.001))
    return Assembly.single("shutter", [cap], {"mount": Frame.at((0, 0, 0)), "press": Frame.at(
        (0, 0, 0), z=(0, 0, -1))})


def shutter_collar(c: Camera, trim: str) -> g.Piece:
    """The collar round a shutter button (its carrier's piece, in the button's frame)."""
    r = c.d.shutter
    return g.shell([(r + GAP + 0.0016, -0.0005), (r + GAP + 0.0016, SHUTTER_TRAVEL + GAP + 0.0012)], 0.0016, trim,
                   name="collar")


def mode_dial(c: Camera, metal: str, mark: str) -> Assembly:
    """A knurled mode dial standing on the top plate (turns about +z); frame ``mount`` at its foot."""
    r = {"dslr": 0.011, "mirrorless": 0.0085}.get(c.design, 0.0075)
    hgt = {"dslr": 0.0065, "mirrorless": 0.0055}.get(c.design, 0.0045)
    knurl = g.cylinder((0, 0, GAP), (0, 0, GAP + hgt), r, metal, sections=40, name="dial")
    top = g.box_between((0.45 * r, -0.0006, GAP + hgt - 1e-4), (0.9 * r, 0.0006, GAP + hgt + 2e-4), mark,
                        name="index").replace(convex=())
    knurl = knurl.with_grasps(Grasp.make((0, 0, GAP + hgt), (0, 0, -1), (0, 1, 0), 2 * r, 0.6 * hgt))
    return Assembly.single("dial", [knurl, top], {"mount": Frame.at((0, 0, 0)), "axis": Frame.at((0, 0, 0))})


def tilt_screen(c: Camera, frame: str, screen: str) -> Assembly:
    """A tilting rear screen hinged along its top edge (+y: its foot swings out and up)."""
    pieces = _screen_pieces(c, -GAP, screen, frame)
    top = 0.12 * c.height + 0.56 * c.height
    t = WALL + 0.004
    return Assembly.single("screen", pieces, {"hinge": Frame.at((-GAP - t / 2, 0.0, top), z=(0, 1, 0))})


def side_door(c: Camera, body: str, side: int = -1) -> Assembly:
    """A card or battery door on the ``side`` face (-1: -y, the grip's), hinged at its back edge and
    opening outward; a thumb notch at its front edge."""
    w, h, d = c.width, c.height, c.depth
    x0, x1 = 0.22 * d, 0.82 * d
    z0, z1 = 0.3 * h, 0.72 * h
    y1 = side * (w / 2 + GAP)
    y0 = y1 + side * WALL
    lo, hi = (x0, min(y0, y1), z0), (x1, max(y0, y1), z1)
    door = slab(x0, x1, z1 - z0, WALL, 0.0, 0.0005, 0.002, 0.002, body, "door", wall=0.0, span=SPAN)
    door = door.transformed(Frame.at((0, min(y0, y1), (z0 + z1) / 2), z=(0, 1, 0), x=(1, 0, 0)).matrix)
    door = door.replace(convex=[box_pts(lo, hi)])
    door = door.with_grasps(Grasp.make((x1, (y0 + y1) / 2, (z0 + z1) / 2), (-1, 0, 0), (0, 1, 0), WALL, 0.002))
    return Assembly.single("door", [door], {"hinge": Frame.at((x0, (y0 + y1) / 2, 0.0), z=(0, 0, side))})


def film_door(c: Camera, body: str, trim: str) -> Assembly:
    """An instant camera's back: the film door over most of it, hinged on its +y edge, opening outward."""
    w, h = c.width, c.height
    y0, y1, z0, z1 = -0.42 * w, 0.42 * w, 0.1 * h, 0.78 * h
    x1, x0 = -GAP, -GAP - WALL - 0.002
    door = slab(z0, z1, y1 - y0, x1 - x0, 0.0, 0.001, 0.004, 0.004, body, "film_door", wall=0.0, span=SPAN)
    door = door.transformed(Frame.at((x0, (y0 + y1) / 2, 0.0), z=(1, 0, 0), x=(0, 0, 1)).matrix)
    window = g.box_between((x0 - 2e-4, y0 + 0.1 * w, 0.6 * h), (x0 + 1e-4, y0 + 0.3 * w, 0.72 * h), trim,
                           name="counter").replace(convex=())
    door = door.with_grasps(Grasp.make((x0, y0, (z0 + z1) / 2), (0, 1, 0), (1, 0, 0), x1 - x0, 0.003))
    return Assembly.single("door", [door, window], {"hinge": Frame.at((x0, y1, 0.0), z=(0, 0, -1))})
