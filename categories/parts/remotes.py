"""Hand-held remotes lying on a table: a TV remote, an air-conditioner remote with a flip cover, a presenter.

Local frame: the remote lies on its back on z = 0, its long axis along X with the end that points at the set
(the infrared window) at +x, Y across, its keys on the top face (z = ``thick``). A body is one moulded shell
(a rounded slab: its plan a rounded rectangle, its edges rounded; massed as a 2.5 mm ABS shell), its keys
rubber or plastic caps standing ``proud`` of the top face that press straight down (-z) by ``travel`` against
their return springs (role ``button``). Keys are laid out in the sections of real keypads, from the front end
back (:func:`tv_plan`, :func:`ac_plan`, :func:`presenter_plan`): each section returns its keys as
:class:`Spot` s, and the body is as long as its sections need (never shorter than its design's range).

The battery door is a plate let into the back of the underside, 0.6 mm above the table, that slides out
towards -x (prismatic); an air-conditioner remote's lower keys lie under a cover hinged at its back edge that
flips up and over towards -x (revolute).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.assembly import Assembly
from infmob_usd.frames import IDENTITY, Frame
from infmob_usd.grasps import Grasp

from . import hardware

SINK = 0.0005  # m a key reaches below the top face at rest (the skirt of a rubber key in its hole)
KEYMAT = 0.0022  # m from the face down to the keymat a pressed key's skirt stops above (2 mm top shell)
RIM = 0.0015  # m of the top shell's hole edge around the keypad's keys
DOOR_LIFT = 0.0006  # m the battery door's outer face lies above the table: the shell's rim carries the remote
DOOR_PLATE = 0.0012  # m, a moulded battery door (1-1.5 mm ABS)
DOOR_ROOM = 0.0013  # m between the door and the bay's lid above it (the batteries' room, drawn as the gap)
COVER_PLATE = 0.0015  # m, a flip cover (1.5 mm)
COVER_CLEAR = 0.0012  # m between the covered keys' tops and the cover's underside
TAB = (0.004, 0.014)  # m, the cover's thumb tab: how far it reaches past the cover's front edge, and its width
COVER_OPENS = math.radians(175)  # a flip cover turns over until it lies flat behind its hinge
SECTION_GAP = 0.004  # m between keypad sections
FRONT = 0.010  # m from the front end to the first section (the infrared window's end)
DOOR_SLIDE = 0.6  # share of its length a battery door slides out (it comes off past its rails)


@dataclass(frozen=True)
class Design:
    """One kind of remote, from real products (metres, kg)."""

    length: tuple[float, float]
    width: tuple[float, float]
    thick: tuple[float, float]
    taper: float  # back width / front width
    corner: float  # plan corner radius as a share of the width
    edge: tuple[float, float]  # top and bottom edge radii as shares of the thickness
    door: tuple[float, float]  # battery door length and width as shares of the width
    proud: float  # key caps stand this far above the face
    travel: float  # a key's press (rubber dome keypads: 1-1.5 mm)


DESIGNS = {
    # Samsung BN59-01199F (45 x 213 x 18 mm, 90 g with 2 AAA), LG AKB75095307 (46 x 176 x 21 mm), Sony RMT-TX300E
    # (45 x 209 x 22 mm): a long slab, rubber keys 1.5-2 mm proud, 1.2 mm dome travel; 2 x AAA side by side
    "tv": Design((0.170, 0.215), (0.042, 0.050), (0.017, 0.023), 0.92, 0.22, (0.22, 0.35), (1.15, 0.70),
                 0.0018, 0.0012),
    # Daikin ARC466A (55 x 150 x 19 mm, ~100 g), Mitsubishi KM09 (57 x 158 x 20 mm), Gree YB1FA (53 x 157 x 18 mm):
    # a wide slab with an LCD at the top and the timer / swing keys under a flip cover; 2 x AAA
    "ac": Design((0.145, 0.175), (0.052, 0.060), (0.017, 0.022), 0.95, 0.20, (0.35, 0.30), (1.00, 0.65),
                 0.0015, 0.0012),
    # Logitech R400 (118 x 38 x 26 mm? listed 115 x 36 x 26 mm, 50 g with batteries), Kensington K33374
    # (125 x 32 x 18 mm), Targus AMP13 (113 x 36 x 22 mm): a pebble, wider at the keys, 2 x AAA
    "presenter": Design((0.105, 0.125), (0.033, 0.040), (0.018, 0.025), 0.82, 0.42, (0.50, 0.22), (1.25, 0.72),
                        0.0015, 0.0010),
    # Amazon Fire TV Alexa Voice Remote 3rd gen (142 x 38 x 17 mm, 2 x AAA), Chromecast with Google TV Voice Remote
    # (122 x 38 x 17 mm, 2 x AAA), Apple Siri Remote 2021 (136 x 35 x 9.3 mm, 63 g, built-in battery): a slim bar
    # with round ends, a large round pad and a dozen keys or fewer
    "streaming": Design((0.122, 0.145), (0.035, 0.039), (0.011, 0.018), 1.0, 0.45, (0.30, 0.40), (1.35, 0.62),
                        0.0012, 0.0010),
}
"""Designs -> sizes (maker spec sheets and retail listings named beside each)."""


@dataclass(frozen=True)
class Key:
    """A key cap: ``size`` (along x, across y), ``shape`` ``"rect"``, ``"round"`` or ``"pill"``, standing
    ``proud`` of the face and pressing down ``travel``."""

    size: tuple[float, float]
    shape: str
    proud: float
    travel: float

    def outline(self, inset: float = 0.0) -> np.ndarray:
        """``(n, 2)`` plan points (x, y) of the cap, ``inset`` inside its edge."""
        lx, ly = self.size[0] / 2 - inset, self.size[1] / 2 - inset
        if self.shape == "round":
            return _ellipse(lx, ly, 20)
        r = min(lx, ly) if self.shape == "pill" else 0.3 * min(lx, ly)
        return _rounded(lx, ly, r)

    def build(self, material: str) -> Assembly:
        """Anchors ``mount`` (its face centre, z out of the face) and ``press`` (on its top, z down)."""
        bev = min(0.4 * self.proud, 0.2 * min(self.size))
        pts = np.vstack([_lift(self.outline(), -SINK), _lift(self.outline(), self.proud - bev),
                         _lift(self.outline(bev), self.proud)])
        v, f = g.hull_arrays(pts)
        narrow = (1, 0, 0) if self.size[0] < self.size[1] else (0, 1, 0)
        grasp = Grasp.make((0, 0, self.proud), (0, 0, -1), narrow, min(self.size), self.proud / 2)
        piece = g.Piece(v, f, material, [v], "key", wall=0.0, grasps=[grasp])
        return Assembly.single("button", [piece], {"mount": IDENTITY,
                                                   "press": Frame.at((0, 0, self.proud), z=(0, 0, -1), x=(1, 0, 0))})


@dataclass(frozen=True)
class Spot:
    """A key's place on the top face: ``x`` (from the section's top edge, negative back), ``y``, its cap, its
    material slot and its turn about z (radians)."""

    x: float
    y: float
    key: Key
    slot: str = "key"
    turn: float = 0.0


@dataclass(frozen=True)
class Section:
    """A keypad section: its ``height`` along x, its key spots and fixed trim pieces drawn on the face (in the
    section's frame: x = 0 its top edge, z = 0 the face)."""

    height: float
    spots: tuple[Spot, ...]
    trim: tuple = ()


@dataclass(frozen=True)
class Plan:
    """A remote's body and where its sections lie: ``tops[i]`` the x of section i's top edge."""

    design: str
    length: float
    width: float
    thick: float
    sections: tuple[Section, ...]
    tops: tuple[float, ...]
    d: Design = field(repr=False)

    def key_frame(self, section: int, spot: Spot) -> Frame:
        return Frame.at((self.tops[section] + spot.x, spot.y, self.thick)).turned("z", spot.turn)


# -- outlines ------------------------------------------------------------------------------------------------
def _ellipse(ax: float, ay: float, n: int) -> np.ndarray:
    th = 2 * math.pi * np.arange(n) / n
    return np.c_[ax * np.cos(th), ay * np.sin(th)]


def _rounded(lx: float, ly: float, r: float, n: int = 4) -> np.ndarray:
    """Plan points of a rectangle ``2 lx`` by ``2 ly`` with corners of radius ``r``."""
    r = max(min(r, lx, ly), 1e-5)
    out = []
    for cx, cy, a0 in ((lx - r, ly - r, 0.0), (-lx + r, ly - r, 90.0), (-lx + r, -ly + r, 180.0),
                       (lx - r, -ly + r, 270.0)):
        for a in np.radians(a0 + np.linspace(0.0, 90.0, n + 1)):
            out.append((cx + r * math.cos(a), cy + r * math.sin(a)))
    return np.array(out)


def _lift(xy: np.ndarray, z: float) -> np.ndarray:
    return np.c_[xy, np.full(len(xy), z)]


def _plan_outline(p: Plan, inset: float) -> np.ndarray:
    """The body's plan (tapering from the front width to ``taper`` of it at the back), ``inset`` inside."""
    c = p.d.corner * p.width
    hw = (p.width / 2, p.d.taper * p.width / 2)
    pts = []
    for x, w in ((p.length / 2 - c, hw[0]), (-p.length / 2 + c, hw[1])):
        for s in (1, -1):
            ring = _ellipse(c - inset, c - inset, 24) + (x, s * (w - c))
            pts.append(ring)
    return np.vstack(pts)


def keypad_box(p: Plan) -> tuple[float, float, float]:
    """The keys' extent on the face: (back x, front x, half width across), caps' outlines included."""
    xs, ys = [], []
    for top, s in zip(p.tops, p.sections, strict=True):
        for sp in s.spots:
            r = max(sp.key.size) / 2 if sp.turn else sp.key.size[0] / 2
            xs += [top + sp.x - r, top + sp.x + r]
            ys.append(abs(sp.y) + (max(sp.key.size) / 2 if sp.turn else sp.key.size[1] / 2))
    return min(xs), max(xs), max(ys)


def shell(p: Plan) -> tuple[np.ndarray, np.ndarray]:
    """``(vertices, faces)`` of the moulded shell: its plan with rounded top and bottom edges (convex)."""
    et, eb = (min(e * p.thick, 0.9 * p.d.corner * p.width) for e in p.d.edge)
    rings = []
    for a in np.radians(np.linspace(0.0, 90.0, 5)):
        rings.append(_lift(_plan_outline(p, eb * (1 - math.sin(a))), eb * (1 - math.cos(a))))
        rings.append(_lift(_plan_outline(p, et * (1 - math.sin(a))), p.thick - et * (1 - math.cos(a))))
    return g.hull_arrays(np.vstack(rings))


def body(p: Plan, material: str, door: bool = True) -> g.Piece:
    """The moulded shell: its plan with rounded top and bottom edges (one convex hull). It collides as the
    shell between the battery bay's lid and the keymat (:data:`KEYMAT` under the face), the rim of the top
    around the keys, as a real top shell with a hole for each key (a key presses down into the room under it),
    and the rim of the underside around the battery door and in front of it (the door slides out backwards;
    ``door`` False: a slab with no bay). The top's rims stand on the keymat's slab rather than reach down through
    it: one bottom face under a phone's screen half (with two, PhysX pushed a half sliding 2.5 mm over the keypad
    down onto a key and stopped it)."""
    v, f = shell(p)
    import manifold3d

    solid = manifold3d.Manifold.hull_points(v)
    x0, x1, hy = keypad_box(p)
    floor = p.thick - KEYMAT - p.d.travel
    dx, hd = door_box(p)
    ceiling = DOOR_LIFT + DOOR_PLATE + DOOR_ROOM if door else 0.0
    up, under, rim = ((0, 0, 1), ceiling), ((0, 0, -1), -ceiling), ((0, 0, 1), floor)
    pieces = [(up, ((0, 0, -1), -floor)), (rim, ((-1, 0, 0), RIM - x0)), (rim, ((1, 0, 0), x1 + RIM)),
              (rim, ((0, 1, 0), hy + RIM)), (rim, ((0, -1, 0), hy + RIM))]
    if door:
        pieces += [(under, ((1, 0, 0), dx[1] + RIM)), (under, ((0, 1, 0), hd + RIM)), (under, ((0, -1, 0), hd + RIM))]
    convex = []
    for planes in pieces:
        cut = solid
        for n, o in planes:
            cut = cut.trim_by_plane(n, o)
        pts = np.asarray(cut.to_mesh().vert_properties)[:, :3]
        if len(pts) >= 4:
            convex.append(pts)
    return g.Piece(v, f, material, convex, "shell")


def window(p: Plan, material: str) -> g.Piece:
    """The infrared window: a dark lens let into the front end, proud of it by 0.3 mm."""
    x = p.length / 2
    hw, hz = 0.14 * p.width, 0.12 * p.thick
    return g.box_between((x - 0.003, -hw, p.thick / 2 - hz), (x + 0.0006, hw, p.thick / 2 + hz), material,
                         bevel=0.8 * hz)


def section_trim(p: Plan) -> list[g.Piece]:
    """Every section's fixed trim, placed on the face."""
    out = []
    for top, s in zip(p.tops, p.sections, strict=True):
        out += [t.translated((top, 0.0, p.thick)) for t in s.trim]
    return out


# -- plans ---------------------------------------------------------------------------------------------------
def plan(design: str, size: float, sections: list[Section], lead: float = 0.0, table=None) -> Plan:
    """A body just long enough for ``sections`` below a ``lead`` (an LCD), at least its design's length at
    ``size`` (0 shortest, 1 longest of its range); ``table``: the designs (default :data:`DESIGNS`)."""
    d = (DESIGNS if table is None else table)[design]
    width = d.width[0] + size * (d.width[1] - d.width[0])
    thick = d.thick[0] + (1 - size) * (d.thick[1] - d.thick[0])  # longer remotes of a range are slimmer
    need = FRONT + lead + sum(s.height + SECTION_GAP for s in sections) + d.door[0] * width * 0.6
    length = max(d.length[0] + size * (d.length[1] - d.length[0]), need)
    tops, x = [], length / 2 - FRONT - lead
    for s in sections:
        tops.append(x)
        x -= s.height + SECTION_GAP
    return Plan(design, length, width, thick, tuple(sections), tuple(tops), d)


def door_box(p: Plan) -> tuple[tuple[float, float], float]:
    """The battery door's x range and half width: in the flat of the underside at the back, inside its
    rounded edges and corners."""
    flat = p.d.taper * p.width - 2 * p.d.edge[1] * p.thick - 2 * RIM
    x0 = -p.length / 2 + p.d.corner * p.width
    return (x0, x0 + p.d.door[0] * p.width), min(p.d.door[1] * p.width, flat) / 2


def battery_door(p: Plan, material: str) -> Assembly:
    """The door in its bay in the underside; anchor ``slide`` (z along -x: it slides out backwards)."""
    (x0, x1), hw = door_box(p)
    z0 = DOOR_LIFT
    plate = g.box_between((x0, -hw, z0), (x1, hw, z0 + DOOR_PLATE), material, bevel=0.0004)
    # a thumb's push on the ribbed grip at its back end, along -x
    grip = Grasp.make((x1 - 0.006, 0, z0), (0, 0, 1), (1, 0, 0), 0.012, 0.0005)
    return Assembly.single("door", [plate.with_grasps(grip)],
                           {"slide": Frame.at((x0, 0, z0), z=(-1, 0, 0), x=(0, 0, 1))})


def door_travel(p: Plan) -> float:
    return DOOR_SLIDE * p.d.door[0] * p.width


# -- a TV remote's sections ----------------------------------------------------------------------------------
def _cols(n: int, span: float) -> list[float]:
    """``n`` positions across, evenly over ``span`` (centred; one: the middle)."""
    return [0.0] if n == 1 else list(np.linspace(span / 2, -span / 2, n))


def top_row(width: float, n: int, proud: float, travel: float) -> Section:
    """Power (round, red) at the left end, input / settings / mute keys across the rest."""
    ys = _cols(n, 0.62 * width)
    power = Spot(-0.006, ys[0], Key((0.0085, 0.0085), "round", proud, travel), "power")
    small = Key((0.0055, 0.0085), "pill", proud, travel)
    return Section(0.012, (power, *(Spot(-0.006, y, small) for y in ys[1:])))


def apps(width: float, n: int, proud: float, travel: float) -> Section:
    """Streaming shortcut keys (Netflix, Prime Video ...), two to a row: wide pills."""
    key = Key((0.0065, 0.36 * width), "pill", proud, travel)
    rows = (n + 1) // 2
    spots = [Spot(-0.005 - 0.0095 * (k // 2), (0.21 if k % 2 == 0 else -0.21) * width, key, "app")
             for k in range(n)]
    return Section(0.0095 * rows, tuple(spots))


def numpad(width: float, n: int, proud: float, travel: float) -> Section:
    """1-9 in three rows of three, 0 in the middle of the fourth, and 0-2 keys beside it (-/--, pre-ch)."""
    key = Key((0.0068, 0.24 * width), "rect", proud, travel)
    ys = _cols(3, 0.58 * width)
    spots = [Spot(-0.005 - 0.0098 * (k // 3), ys[k % 3], key) for k in range(9)]
    spots.append(Spot(-0.005 - 0.0098 * 3, ys[1], key))
    spots += [Spot(-0.005 - 0.0098 * 3, y, key) for y in (ys[0], ys[2])[:n - 10]]
    return Section(0.040, tuple(spots))


def volume(width: float, n: int, proud: float, travel: float) -> Section:
    """VOL +/- on the left, CH +/- on the right (tall keys), a round mute key between them for five."""
    key = Key((0.0105, 0.17 * width), "pill", proud, travel)
    y = 0.26 * width
    spots = [Spot(-0.006 - 0.013 * r, s * y, key) for s in (1, -1) for r in (0, 1)]
    if n > 4:
        spots.append(Spot(-0.0125, 0.0, Key((0.0075, 0.0075), "round", proud, travel)))
    return Section(0.025, tuple(spots))


def navigation(width: float, n: int, proud: float, travel: float) -> Section:
    """A d-pad: a round OK key in a ring of four arrow keys on a metallic disc, then the menu / back / home
    keys (2-4) in a row below it."""
    rd = min(0.36 * width, 0.017)
    ok = Key((0.36 * rd * 2, 0.36 * rd * 2), "round", proud, travel)
    arrow = Key((0.22 * rd * 2, 0.45 * rd * 2), "pill", proud, travel)
    cx, reach = -rd - 0.001, 0.68 * rd
    spots = [Spot(cx, 0.0, ok)]
    spots += [Spot(cx + reach * math.cos(a), reach * math.sin(a), arrow, "key", a)
              for a in (0.0, math.pi / 2, math.pi, 3 * math.pi / 2)]
    small = Key((0.0055, 0.0085), "pill", proud, travel)
    for y in _cols(n - 5, 0.62 * width):
        spots.append(Spot(cx - rd - 0.007, y, small))
    disc = g.disc((cx, 0.0, 0.0002), rd, 0.0004, "trim", None).replace(convex=())  # a printed ring: no collision
    return Section(2 * rd + 0.013, tuple(spots), (disc,))


COLOURS = ("red", "green", "yellow", "blue")
"""The four colour keys of a DVB / HbbTV remote, left to right (ETSI TS 102 796, teletext Fastext)."""


def colour_keys(width: float, n: int, proud: float, travel: float) -> Section:
    key = Key((0.0042, 0.17 * width), "pill", proud, travel)
    return Section(0.007, tuple(Spot(-0.0035, y, key, f"key_{c}") for y, c in zip(_cols(4, 0.66 * width), COLOURS,
                                                                                  strict=True)))


def playback(width: float, n: int, proud: float, travel: float) -> Section:
    """Transport keys (rewind, play, pause, stop, forward, record ...): small round keys, four to a row."""
    key = Key((0.0062, 0.0062), "round", proud, travel)
    per = 4 if n != 3 and n != 6 else 3
    rows = [list(range(k, min(k + per, n))) for k in range(0, n, per)]
    spots = [Spot(-0.005 - 0.009 * r, y, key) for r, row in enumerate(rows)
             for y in _cols(len(row), (len(row) - 1) / 3 * 0.66 * width)]
    return Section(0.009 * len(rows) + 0.001, tuple(spots))


TV_SECTIONS = {"top_row": top_row, "apps": apps, "numpad": numpad, "volume": volume, "navigation": navigation,
               "colour_keys": colour_keys, "playback": playback}
"""A TV remote's sections, front to back, in the order of Samsung, LG and Sony remotes of the 2010s-2020s."""


def tv_plan(size: float, counts: dict[str, int]) -> Plan:
    """``counts``: section -> keys, for the sections grown (in :data:`TV_SECTIONS` order)."""
    d = DESIGNS["tv"]
    width = d.width[0] + size * (d.width[1] - d.width[0])
    secs = [TV_SECTIONS[k](width, counts[k], d.proud, d.travel) for k in TV_SECTIONS if k in counts]
    return plan("tv", size, secs)


# -- a streaming-stick remote -------------------------------------------------------------------------------
def stream_top(width: float, n: int, proud: float, travel: float) -> Section:
    """Power and the voice (microphone) key, side by side; or the voice key alone (Chromecast's remote)."""
    key = Key((0.0068, 0.0068), "round", proud, travel)
    return Section(0.010, tuple(Spot(-0.005, y, key) for y in _cols(n, 0.42 * width)))


def stream_pad(width: float, n: int, proud: float, travel: float) -> Section:
    """The round pad that fills the remote's width: the select key in a ring of four arrow segments (Fire TV,
    Roku, Chromecast), on a dark printed ring."""
    rd = 0.36 * width
    ok = Key((0.8 * rd, 0.8 * rd), "round", proud, travel)
    arrow = Key((0.24 * rd, 0.62 * rd), "pill", proud, travel)
    cx, reach = -rd - 0.001, 0.7 * rd
    spots = [Spot(cx, 0.0, ok, "pad")] + [Spot(cx + reach * math.cos(a), reach * math.sin(a), arrow, "key", a)
                                          for a in (0.0, math.pi / 2, math.pi, 3 * math.pi / 2)][:n - 1]
    # printed, 0.2 mm high: a key pressed its whole travel sinks to it, not under it
    ring = g.disc((cx, 0.0, 0.0001), rd, 0.0002, "ring", None).replace(convex=())
    return Section(2 * rd + 0.002, tuple(spots), (ring,))


def stream_keys(width: float, n: int, proud: float, travel: float) -> Section:
    """Back, home and menu; rewind, play / pause and forward; volume and mute: round keys three to a row."""
    key = Key((0.0072, 0.0072), "round", proud, travel)
    ys = _cols(3, 0.56 * width)
    spots = [Spot(-0.006 - 0.0105 * (k // 3), ys[k % 3], key) for k in range(n)]
    return Section(0.0105 * ((n + 2) // 3) + 0.002, tuple(spots))


STREAM_SECTIONS = {"stream_top": stream_top, "stream_pad": stream_pad, "stream_keys": stream_keys, "apps": apps}
"""A streaming remote's sections, front to back, as on Fire TV, Roku and Chromecast voice remotes."""


def streaming_plan(size: float, counts: dict[str, int]) -> Plan:
    d = DESIGNS["streaming"]
    width = d.width[0] + size * (d.width[1] - d.width[0])
    secs = [STREAM_SECTIONS[k](width, counts[k], d.proud, d.travel) for k in STREAM_SECTIONS if k in counts]
    return plan("streaming", size, secs)


# -- an air-conditioner remote ------------------------------------------------------------------------------
AC_SCREEN = 0.36  # share of the width the LCD is tall (Daikin ARC466: 36 x 45 mm)


def ac_main(width: float, n: int, proud: float, travel: float) -> Section:
    """On/off (large, round) between mode and fan; temperature - and + below (wide), swing between them for 6."""
    big = Key((0.011, 0.011), "round", proud, travel)
    small = Key((0.0065, 0.2 * width), "pill", proud, travel)
    wide = Key((0.008, 0.27 * width), "pill", proud, travel)
    top = [Spot(-0.0065, 0.0, big, "power")] + [Spot(-0.0065, s * 0.33 * width, small) for s in (1, -1)][:n - 3]
    below = [Spot(-0.019, s * 0.2 * width, wide) for s in (1, -1)]
    if n > 5:
        below = [Spot(-0.019, s * 0.3 * width, small) for s in (1, -1)] + [Spot(-0.019, 0.0, small)]
    return Section(0.025, tuple(top + below))


def ac_covered(width: float, n: int, proud: float, travel: float) -> Section:
    """Timer, swing, sleep, eco ... keys under the cover: three to a row."""
    key = Key((0.0058, 0.22 * width), "rect", proud, travel)
    ys = _cols(3, 0.6 * width)
    spots = [Spot(-0.006 - 0.0092 * (k // 3), ys[k % 3], key) for k in range(n)]
    return Section(0.0092 * ((n + 2) // 3) + 0.004, tuple(spots))


def ac_plan(size: float, main: int, covered: int) -> Plan:
    d = DESIGNS["ac"]
    width = d.width[0] + size * (d.width[1] - d.width[0])
    secs = [ac_main(width, main, d.proud, d.travel), ac_covered(width, covered, d.proud, d.travel)]
    return plan("ac", size, secs, lead=AC_SCREEN * width + 0.004)


def lcd(p: Plan, material: str, bezel: str) -> list[g.Piece]:
    """The segment LCD (grey, unlit) in a dark bezel between the front end and the keys."""
    h, w = AC_SCREEN * p.width, 0.74 * p.width
    x1 = p.length / 2 - FRONT
    frame = g.box_between((x1 - h - 0.0025, -w / 2 - 0.0025, p.thick - 0.001),
                          (x1 + 0.0025, w / 2 + 0.0025, p.thick + 0.0004), bezel, bevel=0.0003)
    glass = g.box_between((x1 - h, -w / 2, p.thick), (x1, w / 2, p.thick + 0.0007), material)
    return [frame, glass]


def cover(p: Plan, material: str) -> Assembly:
    """The flip cover over the covered section (the last): a plate on two side cheeks; anchor ``hinge`` at
    its back edge (z along -y: +angle lifts its front edge up and over towards -x)."""
    s, top = p.sections[-1], p.tops[-1]
    x0, x1 = top - s.height - 0.002, top + 0.002
    hw = 0.47 * p.width
    z0 = p.thick + p.d.proud + COVER_CLEAR
    plate = g.box_between((x0, -hw, z0), (x1, hw, z0 + COVER_PLATE), material, bevel=0.0005)
    cheeks = [g.box_between((x0, s_ * hw - 0.0012 if s_ > 0 else -hw, p.thick + 0.0003),
                            (x1, hw if s_ > 0 else -hw + 0.0012, z0), material) for s_ in (1, -1)]
    # a thumb tab reaching forward over the gap above the main keys: a fingertip lifts it
    tab = g.box_between((x1 - 0.001, -TAB[1] / 2, z0), (x1 + TAB[0], TAB[1] / 2, z0 + COVER_PLATE), material,
                        bevel=0.0005)
    lip = Grasp.make((x1 + TAB[0], 0, z0 + COVER_PLATE / 2), (-1, 0, 0), (0, 0, 1), 0.004, TAB[0] / 2)
    return Assembly.single("lid", [plate, tab.with_grasps(lip), *cheeks, *cover_hinge(p, material)[1]],
                           {"hinge": _cover_axis(p)})


def _cover_axis(p: Plan) -> Frame:
    s, top = p.sections[-1], p.tops[-1]
    return Frame.at((top - s.height - 0.002, 0, p.thick + p.d.proud + COVER_CLEAR + COVER_PLATE / 2), z=(0, -1, 0),
                    x=(1, 0, 0))


def cover_hinge(p: Plan, material: str) -> tuple[list[g.Piece], list[g.Piece]]:
    """The flip cover's barrel hinge on its axis (its back edge): the body's two end knuckles on posts up from
    the face, the cover's middle one (decoration, :func:`~.hardware.barrel_hinge`); returns (body, cover)."""
    axis = _cover_axis(p)
    length, r = 0.7 * p.width, 0.75 * COVER_PLATE
    fixed, moving = hardware.barrel_hinge(length, r, material, moving_share=0.5, sections=10)
    # the pin frame: x over the cover, y up, z along the axis; a post under each end knuckle
    drop = axis.origin[2] - p.thick + 0.0003
    fixed += [hardware.leaf((-r, -drop, z0), (0.0, 0.0, z1), material)
              for z0, z1 in ((-length / 2, -length / 4), (length / 4, length / 2))]
    return [pc.transformed(axis.matrix) for pc in fixed], [pc.transformed(axis.matrix) for pc in moving]


# -- a presenter ---------------------------------------------------------------------------------------------
def presenter_keys(width: float, n: int, proud: float, travel: float) -> Section:
    """Back and forward (two large keys side by side), the laser key (round, red) below, then blank-screen,
    slideshow and timer keys (1-3)."""
    big = Key((0.013, 0.42 * width), "rect", proud, travel)
    spots = [Spot(-0.0075, s * 0.235 * width, big) for s in (1, -1)]
    spots.append(Spot(-0.0215, 0.0, Key((0.0085, 0.0085), "round", proud, travel), "power"))
    small = Key((0.0055, 0.26 * width), "pill", proud, travel)
    spots += [Spot(-0.0325, y, small) for y in _cols(n - 3, 0.6 * width)]
    return Section(0.037, tuple(spots))


def presenter_plan(size: float, n: int) -> Plan:
    d = DESIGNS["presenter"]
    width = d.width[0] + size * (d.width[1] - d.width[0])
    return plan("presenter", size, [presenter_keys(width, n, d.proud, d.travel)])


SWITCH = (0.005, 0.0035, 0.0016, 0.003)  # m: knob length, width, height and throw of a presenter's on/off slide


def power_switch(p: Plan, knob: str, slot: str) -> tuple[Assembly, list[g.Piece]]:
    """A presenter's on/off slide behind its keys: the knob (anchor ``slide``: z along -x, off to on) and its
    slot, a dark inlay on the face (drawn, no collision)."""
    ln, wd, ht, throw = SWITCH
    x = p.tops[-1] - p.sections[-1].height - SECTION_GAP - ln / 2
    knob_piece = g.box_between((x - ln / 2, -wd / 2, p.thick), (x + ln / 2, wd / 2, p.thick + ht), knob,
                               bevel=0.4 * ht)
    # a fingertip on its ridged top pushes it back (along -x)
    grip = Grasp.make((x, 0, p.thick + ht), (0, 0, -1), (1, 0, 0), ln, ht / 2)
    inlay = g.box_between((x - ln / 2 - throw - 0.001, -wd / 2 - 0.001, p.thick - 0.0002),
                          (x + ln / 2 + 0.001, wd / 2 + 0.001, p.thick + 0.0002), slot).replace(convex=())
    frame = Frame.at((x, 0, p.thick), z=(-1, 0, 0), x=(0, 0, 1))
    return Assembly.single("switch", [knob_piece.with_grasps(grip)], {"slide": frame}), [inlay]

