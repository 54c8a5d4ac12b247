"""USB flash drives lying flat on a table: a plastic body, its plug, and what covers the plug.

Local frame: the drive lies on z = 0, its plug toward +x, its back end at x = 0, centred on y = 0.
Three designs (sizes from the products named beside each figure):

* ``swivel``: a U-shaped steel cover turns about a rivet through the body near its back end (axis +z): at
  rest its bight covers the plug, turned half round it lies behind the body and the plug is bare.
* ``capped``: the body steps down to a neck in front; a cap slides over the neck and the plug and pulls off
  along +x (a lift-off part).
* ``slider``: a sleeve with a slot in its top; a sled carrying the plug slides forward under a thumb
  button riding in the slot, the plug coming out through the sleeve's front mouth.

The plug is a USB-A (a 12.0 x 4.5 mm steel shell round a plastic insert, two lock windows on top) or a
USB-C (an 8.25 x 2.4 mm round-ended shell).
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

from .handtools import rrect, sweep

GAP = 0.0002  # m, between a moving part and the body: a moulded slide or a swivel rivet has 0.1-0.3 mm play

# USB 2.0 spec, figure 6-7 (Standard-A plug): shell 12.0 x 4.5 mm, 11.75 mm mating length, 0.3 mm steel;
# the insert carrying the four contacts fills the shell's lower half (1.95 mm)
PLUG_A = {"w": 0.012, "h": 0.0045, "len": 0.0118, "sheet": 0.0003, "insert": 0.00195, "window": 0.0025}
# USB Type-C spec rev 2.0, 3.2: plug overmold shell 8.25 x 2.4 mm, 6.65 mm mating length
PLUG_C = {"w": 0.00825, "h": 0.0024, "len": 0.0067}


@dataclass(frozen=True)
class UsbDesign:
    """One kind of drive (metres): the body's length range (plug excluded), width and thickness."""

    length: tuple[float, float]
    width: tuple[float, float]
    thick: tuple[float, float]


DESIGNS = {
    # Kingston DataTraveler 101 G2: 57.18 x 17.28 x 10.5 mm overall with the cover (plug 12 mm of it);
    # Verbatim Store 'n' Go Swivel, Transcend JetFlash 330: 50-60 x 17-19 x 8-10 mm
    "swivel": UsbDesign((0.038, 0.048), (0.0165, 0.019), (0.0086, 0.0100)),
    # Kingston DataTraveler Exodia: 67.3 x 21.04 x 10.14 mm with its cap; SanDisk Ultra Flair / Cruzer Edge
    # capped: 45-60 x 17-21 x 8-10 mm
    "capped": UsbDesign((0.034, 0.050), (0.017, 0.0215), (0.0080, 0.0105)),
    # SanDisk Cruzer Glide: about 70 x 20 x 9 mm retracted; Kingston DataTraveler SE9 slider, Lexar JumpDrive S70
    # retractable: 55-72 x 18-22 x 8-11 mm
    "slider": UsbDesign((0.052, 0.068), (0.018, 0.022), (0.0082, 0.0108)),
}
"""Designs -> sizes (maker data sheets named beside each)."""

COVER_SHEET = 0.0006  # m, swivel cover steel (0.4-0.6 mm stainless strip on DT101-type drives)
# a plate's collision is widened about its mid-plane to the core's thinnest hull: the body keeps its gap from that
COVER_CLEAR = GAP + (MIN_HULL_WIDTH - COVER_SHEET) / 2
LEAF_CLEAR = 0.0003  # m, a moving part's underside above the table: it turns or slides without dragging on it
FRONT = 0.12  # a body's front plan corners' radius, as a share of its width
CAP_WALL = 0.0009  # m, a moulded cap's wall (0.8-1.0 mm on Kingston / SanDisk caps)
NECK = 0.006  # m, how far the cap's skirt runs over the body's neck
SLEEVE_WALL = 0.0015  # m, a slider's sleeve wall (1-1.5 mm; no thinner than the core's thinnest hull)
BUTTON = (0.008, 0.0055, 0.0012)  # m, a slider's thumb button: length, width, height proud of the sleeve


@dataclass(frozen=True)
class Usb:
    design: str
    length: float  # body, plug excluded
    width: float
    thick: float
    plug: str  # "a" or "c"
    round: float  # 0-1: from crisp moulded edges to a pebble

    @property
    def edge(self) -> float:
        """Radius of the body's long edges."""
        return (0.1 + 0.32 * self.round) * self.thick

    @property
    def corner(self) -> float:
        """Radius of the body's plan corners (a swivel's back end is round about its rivet)."""
        return (0.04 + 0.26 * self.round) * self.width

    @property
    def plug_size(self) -> dict:
        return PLUG_A if self.plug == "a" else PLUG_C

    @property
    def mid(self) -> float:
        return self.thick / 2

    @property
    def tip(self) -> float:
        """x of the plug's tip when out (a slider's plug: retracted, see :func:`slider_sled`)."""
        return self.length + self.plug_size["len"]


def usb(design: str, size: float, shape: float, plug: str, roundness: float) -> Usb:
    """Sizes of one drive: ``size`` (0-1) its length within the design's range, ``shape`` (0-1) its width and
    thickness within theirs (a slim or a chunky drive of the same length), ``roundness`` (0-1) its edges."""
    d = DESIGNS[design]
    lerp = lambda r, t: r[0] + t * (r[1] - r[0])  # noqa: E731
    return Usb(design, lerp(d.length, size), lerp(d.width, shape), lerp(d.thick, 1 - abs(2 * shape - 1)), plug,
               roundness)


# -- shapes ----------------------------------------------------------------------------------------------
def slab(x0: float, x1: float, width: float, height: float, z0: float, edge: float, back: float, front: float,
         material: str, name: str, wall: float | None = None, span: float = 0.0) -> g.Piece:
    """A rounded bar along x: cross-sections ``width`` x ``height`` with edges rounded ``edge``, its plan
    corners rounded ``back`` (at x0) and ``front`` (at x1); within ``edge`` of an end the section shrinks in
    height too, so the end face is rounded into the top and the bottom. ``span`` > 0: each convex collision
    piece spans at least that much of x (the core widens thinner ones about their middle, past the bar's
    ends); 0: every three sections make one."""
    def inset(r: float, d: float) -> float:
        return r - math.sqrt(max(r * r - (r - d) ** 2, 0.0)) if r > 0 and d < r else 0.0

    reach = (max(back, min(edge, 0.45 * height)), max(front, min(edge, 0.45 * height)))
    xs = [x0 + reach[0] * (1 - math.cos(a)) for a in np.linspace(0, math.pi / 2, 7)]
    xs += [x1 - reach[1] * (1 - math.cos(a)) for a in np.linspace(math.pi / 2, 0, 7)]
    xs = np.unique(np.round(np.clip(xs, x0, x1), 9))  # a square end adds no points
    secs = []
    for x in xs:
        d0, d1 = x - x0, x1 - x
        di = max(inset(back, d0), inset(front, d1))
        dz = min(max(inset(min(edge, 0.45 * height), d0) if back else 0.0,
                     inset(min(edge, 0.45 * height), d1) if front else 0.0), 0.4 * height)
        secs.append(rrect(max(width - 2 * di, 0.1 * width), height - 2 * dz, edge, z0 + dz))
    bar = sweep(np.c_[xs, np.zeros_like(xs)], secs, material, group=3, name=name).replace(wall=wall)
    if span <= 0:
        return bar
    rings = bar.vertices[:len(xs) * len(secs[0])].reshape(len(xs), len(secs[0]), 3)
    cuts = [0]
    for i in range(1, len(xs)):
        if xs[i] - xs[cuts[-1]] >= span and x1 - xs[i] >= span:
            cuts.append(i)
    cuts.append(len(xs) - 1)
    return bar.replace(convex=[rings[a:b + 1].reshape(-1, 3) for a, b in zip(cuts[:-1], cuts[1:], strict=True)])


def plug(u: Usb, x0: float, steel: str, insert: str, length: float | None = None) -> list[g.Piece]:
    """The plug from ``x0`` forward (its mating length, or ``length`` where more of it is drawn: a slider's
    runs back through the sleeve's mouth), centred on the body's mid-plane."""
    p, zc = u.plug_size, u.mid
    x1 = x0 + (length or p["len"])
    if u.plug == "c":  # a round-ended shell, its dark mouth on the front face
        xs = np.array([x0 - 0.001, x1])
        shell = sweep(np.c_[xs, [0, 0]], rrect(p["w"], p["h"], 0.49 * p["h"], zc - p["h"] / 2), steel,
                      name="plug_shell").replace(sheet=0.0003)
        mouth = sweep(np.c_[[x1 - 1e-4, x1 + 5e-5], [0, 0]], rrect(p["w"] - 0.0008, p["h"] - 0.0008, 0.0008,
                      zc - p["h"] / 2 + 0.0004), insert, name="mouth").replace(convex=())
        return [shell, mouth]
    w, h, t = p["w"], p["h"], p["sheet"]
    lo, hi = zc - h / 2, zc + h / 2
    win = p["window"]
    holes = [(x1 - 0.0035 - win, s * 0.0025 - win / 2, x1 - 0.0035, s * 0.0025 + win / 2) for s in (-1, 1)]
    pieces = [g.panel((x0 - 0.001, -w / 2, hi - t), (x1, w / 2, hi), steel, "z", holes=holes, name="plug_top"),
              g.box_between((x0 - 0.001, -w / 2, lo), (x1, w / 2, lo + t), steel, name="plug_bottom")]
    for s in (-1, 1):
        y0, y1 = sorted((s * w / 2, s * (w / 2 - t)))
        pieces.append(g.box_between((x0 - 0.001, y0, lo + t), (x1, y1, hi - t), steel, name="plug_side"))
    pieces.append(g.box_between((x0 - 0.001, -w / 2 + t, lo + t), (x1 - 0.0004, w / 2 - t, lo + t + p["insert"]),
                                insert, name="insert"))
    # the shell collides as the one box it fills (its 0.3 mm walls would be widened past its outline)
    outline = g.box_between((x0 - 0.001, -w / 2, lo), (x1, w / 2, hi), steel).convex
    return [pieces[0].replace(convex=outline)] + [q.replace(convex=()) for q in pieces[1:]]


# -- the designs' parts ----------------------------------------------------------------------------------
def swivel_body(u: Usb, body: str, steel: str, insert: str) -> Assembly:
    """A swivel drive's body (its back end round about the rivet) and plug; anchor ``pivot`` (+z)."""
    r = u.width / 2
    pieces = [slab(0.0, u.length, u.width, u.thick, 0.0, u.edge, 0.97 * r, FRONT * u.width, body, "body")]
    pieces += plug(u, u.length, steel, insert)
    return Assembly.single("body", pieces, {"pivot": Frame.at((r, 0.0, u.mid), z=(0, 0, 1))})


def swivel_cover(u: Usb, steel: str) -> Assembly:
    """The U-shaped cover: a plate over the body from the rivet forward, a bight in front of the plug's tip
    and a leaf under the plug (it ends short of the body: the body lies on the table, the cover turns clear
    of it); anchor ``pivot`` (+z, turning the bight to +y)."""
    r, t = u.width / 2, COVER_SHEET
    top = u.thick + COVER_CLEAR
    bight = u.tip + 0.0012
    # the leaf starts past the circle the body's front corners turn on
    leaf = r + math.hypot(u.length - r, u.width / 2 - FRONT * u.width * 0.3) + 0.0008
    lo = LEAF_CLEAR
    plate = slab(0.0, bight + t, u.width, t, top, 0.45 * t, 0.97 * r, 0.35 * t, steel, "plate", wall=0.0)
    under = slab(leaf, bight + t, u.width, t, lo, 0.45 * t, 0.0, 0.35 * t, steel, "leaf", wall=0.0)
    # the leaf collides as a hull the core's thinnest wide, grown upward from its underside (not into the table)
    under = under.replace(convex=[np.array([(x, y, z) for x in (leaf, bight + t) for y in (-r, r)
                                            for z in (lo, lo + MIN_HULL_WIDTH)])])
    end = slab(bight, bight + t, u.width, top + t - lo, lo, 0.45 * t, 0.0, 0.35 * t, steel, "bight", wall=0.0)
    # a hand turns the cover by its bight, pinched across its two ends from above (clear of the plug)
    end = end.with_grasps(Grasp.make((bight + t / 2, 0.0, top + t), (0, 0, -1), (0, 1, 0), u.width,
                                     0.5 * (top + t - lo)))
    pieces = [plate, under, end,
              g.cylinder((r, 0, top + t - 1e-4), (r, 0, top + t + 0.0005), 0.0022, steel, name="rivet")]
    return Assembly.single("cover", pieces, {"pivot": Frame.at((r, 0.0, u.mid), z=(0, 0, 1))})


def capped_body(u: Usb, body: str, steel: str, insert: str, neck: str | None = None) -> Assembly:
    """A capped drive's body: the grip, the neck the cap's skirt slides over (moulded in the ``neck`` colour,
    the cap's on two-tone drives), the plug; anchor ``pull`` (+x)."""
    inset = MIN_HULL_WIDTH + GAP  # inside the cap's walls (their collision is the core's thinnest hull)
    grip = u.length - NECK
    pieces = [slab(0.0, grip, u.width, u.thick, 0.0, u.edge, u.corner, 0.0008, body, "body"),
              slab(grip - 0.001, u.length, u.width - 2 * inset, u.thick - LEAF_CLEAR - 2 * inset, LEAF_CLEAR + inset,
                   max(u.edge - inset, 0.0005), 0.0, 0.0005, neck or body, "neck")]
    pieces += plug(u, u.length, steel, insert)
    pieces.append(_lanyard_eye(u, body))
    return Assembly.single("body", pieces, {"pull": Frame.at((u.tip, 0.0, u.mid), z=(1, 0, 0))})


def _lanyard_eye(u: Usb, body: str) -> g.Piece:
    """A loop moulded on the back end for a key ring (a ring of hulls round a 3 mm hole)."""
    h = 0.55 * u.thick
    z0 = u.thick / 2 - h / 2
    ring = [(-0.0025 + 0.0032 * math.cos(a), 0.0040 * math.sin(a)) for a in np.linspace(0, 2 * math.pi, 17)[:-1]]
    return sweep(np.asarray(ring), rrect(0.0016, h, 0.0006, z0), body, closed=True, group=2, name="eye")


def cap(u: Usb, body: str) -> Assembly:
    """The cap: a moulded sleeve, closed in front, over the neck and the plug (its outside flush with the
    body's, its underside just clear of the table); anchor ``pull`` (+x: pulled off the plug)."""
    x0, x1 = u.length - NECK + GAP, u.tip + GAP + CAP_WALL + 0.0006
    w, z0, z1 = u.width, LEAF_CLEAR, u.thick
    visual = slab(x0, x1, w, z1 - z0, z0, u.edge, 0.0008, u.corner, body, "cap", wall=CAP_WALL)
    # collisions: the four walls and the front, each the core's thinnest hull (the moulded wall and its ribs),
    # so the neck and the plug sit in the hollow
    t = MIN_HULL_WIDTH
    boxes = [((x0, -w / 2, z0), (x1, w / 2, z0 + t)), ((x0, -w / 2, z1 - t), (x1, w / 2, z1)),
             ((x0, -w / 2, z0 + t), (x1, -w / 2 + t, z1 - t)), ((x0, w / 2 - t, z0 + t), (x1, w / 2, z1 - t)),
             ((x1 - t, -w / 2 + t, z0 + t), (x1, w / 2 - t, z1 - t))]
    convex = [np.array([(x, y, z) for x in (a[0], b[0]) for y in (a[1], b[1]) for z in (a[2], b[2])]) for a, b in boxes]
    return Assembly.single("cap", [visual.replace(convex=convex)], {"pull": Frame.at((u.tip, 0.0, u.mid), z=(1, 0, 0))})


def cap_engagement(u: Usb) -> float:
    """How far the cap is guided as it comes off: its skirt over the neck and its ribs along the plug shell."""
    return NECK + u.plug_size["len"]


def sleeve(u: Usb, body: str, dark: str) -> Assembly:
    """A slider's sleeve: a hollow moulded shell open in a mouth in front, a slot along its top for the
    thumb button; anchor ``slide`` (+x). Drawn as its rounded outside with the slot and the mouth dark in
    it; it collides as its walls, so the sled and the plug move in the hollow."""
    w, h, L, t = u.width, u.thick, u.length, SLEEVE_WALL
    p = u.plug_size
    s0, s1 = _slot(u)
    bw = BUTTON[1] / 2 + GAP
    mw, mz0, mz1 = p["w"] / 2 + GAP, u.mid - p["h"] / 2 - GAP, u.mid + p["h"] / 2 + GAP
    pieces = [g.box_between((0.0, -w / 2, 0.0), (L, w / 2, t), body, bevel=0.0004, name="floor"),
              g.panel((0.0, -w / 2, h - t), (L, w / 2, h), body, "z", holes=[(s0, -bw, s1, bw)], name="roof"),
              g.box_between((0.0, -w / 2, t), (t, w / 2, h - t), body, name="back")]
    for s in (-1, 1):
        y0, y1 = sorted((s * w / 2, s * (w / 2 - t)))
        pieces.append(g.box_between((0.0, y0, 0.0), (L, y1, h), body, bevel=0.0004, name="side"))
    pieces.append(g.panel((L - t, -w / 2 + t, t), (L, w / 2 - t, h - t), body, "x", holes=[(-mw, mz0, mw, mz1)],
                          name="mouth"))
    shell = slab(0.0, L, w, h, 0.0, u.edge, u.corner, u.corner, body, "sleeve", wall=SLEEVE_WALL)
    shell = shell.replace(convex=[c for q in pieces for c in q.convex])
    slot = g.box_between((s0, -bw, h - 1e-4), (s1, bw, h + 4e-5), dark, name="slot").replace(convex=())
    mouth = g.box_between((L - 1e-4, -mw, mz0), (L + 4e-5, mw, mz1), dark, name="mouth").replace(convex=())
    return Assembly.single("body", [shell, slot, mouth], {"slide": Frame.at((L, 0.0, u.mid), z=(1, 0, 0))})


def _slot(u: Usb) -> tuple[float, float]:
    """x range of the roof's slot: the button's travel and its own length."""
    x1 = u.length - 0.004
    return x1 - BUTTON[0] - slider_travel(u) - 2 * GAP, x1


def slider_travel(u: Usb) -> float:
    """The sled's stroke: the plug's mating length (out of the mouth, its root at the mouth's face)."""
    return u.plug_size["len"]


def slider_sled(u: Usb, body: str, button: str, steel: str, insert: str) -> Assembly:
    """The sled inside the sleeve with the plug on its nose (retracted: its tip just inside the mouth) and
    the ribbed thumb button standing up through the slot; anchor ``slide`` (+x)."""
    t, w, h = SLEEVE_WALL, u.width, u.thick
    s0, _ = _slot(u)
    # the sled's nose stops a gap short of the mouth's wall at full stroke; the plug's tip rests in the mouth
    nose = u.length - t - GAP - slider_travel(u)
    tip = u.length - 0.0005
    sled = g.box_between((t + GAP + 0.002, -w / 2 + t + GAP, t + GAP), (nose, w / 2 - t - GAP, h - t - GAP), body,
                         name="sled")
    b0 = s0 + GAP
    bl, bw, bh = BUTTON
    knob = g.box_between((b0, -bw / 2, h - t - GAP - 1e-4), (b0 + bl, bw / 2, h + bh), button, bevel=0.0004,
                         name="button")
    ribs = [g.box_between((x - 0.0003, -bw / 2 + 0.0006, h + bh - 1e-4), (x + 0.0003, bw / 2 - 0.0006, h + bh + 0.0004),
                          button, name="rib") for x in np.linspace(b0 + 0.0015, b0 + bl - 0.0015, 4)]
    pieces = [sled, knob, *ribs, *plug(u, nose, steel, insert, tip - nose)]
    return Assembly.single("sled", pieces, {"slide": Frame.at((u.length, 0.0, u.mid), z=(1, 0, 0))})
