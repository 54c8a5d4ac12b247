"""Window: casement, sliding, tilt-and-turn, top-hung awning or double-hung sashes in a frame.

Designs (``style``) beyond the two below: ``tilt_turn`` (casements whose side hinge rides on a tilt
hinge along the bottom rail: flip_revolute, the tilt pressed closed by gravity, the two modes exclusive:
the handle selects tilt or turn), ``awning`` (top-hung
sashes opening outward about a pivot in front of their centre of mass), ``double_hung`` (the lower sash
slides up, the upper one tilts in; a passive down-sliding upper sash would drop without its spring
balance). Optional shutters and curtains as before.

X is depth (the room side faces +X), Y is width, Z is up. The frame (jambs, head,
bottom rail, mullions, an optional transom light and the glazing stops) is the
root; its bottom stands at z = 0, or on an exterior sill slab when there is one.

* ``casement``: each sash (a glazed frame in the ``glass`` slot, optionally
  divided by glazing bars) sits flush with the frame's room-side face and opens
  inward (+X) about a vertical hinge through the front face at its hinge edge, so
  it always moves away from the stop behind it. Sashes in the left half hinge
  on their left edge (axis -Z), those in the right half on their right edge
  (+Z); a middle sash hinges on either side. So neighbours are always separated
  by the plane of a hinge edge and never sweep into each other; the one pair whose
  free edges meet is either split by a mullion or is a French pair (gap wide
  enough for the free corners' outward creep). Handles (lever or knob) are on the
  free stile.
* ``sliding``: the sashes run in two parallel tracks (separated in X by more than
  the back sashes' finger pulls), alternating tracks so neighbours overlap at their
  meeting stiles. Each sash slides along Y toward the larger free space of its
  track, stopping before the frame and before a same-track neighbour that may
  come toward it; a single sliding sash slides over a fixed pane. Sill and head
  carry a track divider and outer lips.

Optional shutters hang outside (-X) on the frame's outer edges: closed at rest,
they turn about Z away from the window up to ``shutter_angle`` (< pi/2); on a wide
window each side is a bifold whose inner leaf folds back over the outer one. Optional
curtain halves hang from a rod on the room side and slide outward along Y from
the centre, or one panel draws to one side (horizontal slides: neutral under gravity). In front of casements the
rod stands off by half a sash width more; the core stops the casements
before they reach the curtains (``limit_to_clearance``). A transom light (fixed glass above a bar)
grows only on frames taller than 1.1 m. Every hinge axis is vertical and every
slide horizontal, so nothing moves under gravity.
"""

from __future__ import annotations

import numpy as np

from infmob_usd.category import Category
from infmob_usd.frames import Frame
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.materials.palettes import furniture
from infmob_usd.params import Choice, Float, Int

from .parts import windows as P

R = P.RANGES  # the parameters' ranges (sourced in windows.Ranges)


def jamb_width(p) -> float:
    """The jambs' and head's face width: ``frame_width``, at most 12 % of the frame's width and height."""
    return min(p["frame_width"], P.JAMB_MAX * p["width"], P.JAMB_MAX * p["height"])


def sashes(p, rng) -> int:
    """sash_count, or round(opening width / sash_width), 1..4"""
    opening = p["width"] - 2 * jamb_width(p)
    return p["sash_count"] or int(np.clip(round(opening / p["sash_width"]), 1, P.MOST_SASHES))


def vents(p, rng) -> int:
    """one per sash (sashes), one over a double-hung pair"""
    return 1 if p["style"] == "double_hung" else sashes(p, rng)


def sash_locks(p, rng) -> int:
    """one cam lock on the meeting rail, two on a frame wider than 0.9 m"""
    return 2 if p["width"] > P.LOCKS_FROM else 1


def curtain_panels(p, rng) -> int:
    """two halves, or one panel (curtain_panels)"""
    return 1 if p["curtain_panels"] == "single" else 2


def shutter_leaves(p, rng) -> int:
    """two leaves, four (bifolds) when a side is wider than shutter_leaf_width"""
    return 4 if p["width"] / 2 > p["shutter_leaf_width"] else 2


GRAMMAR = Grammar("window", {
    "window": Node(label="frame", one_of={"casement": 0.3, "sliding": 0.2, "tilt_turn": 0.2, "awning": 0.15,
                                          "double_hung": 0.15}, choice="style",
                   optional={"shutters": 0.35, "curtains": 0.4, "sill": 0.6, "transom": 0.25, "trickle_vents": 0.45}),
    "trickle_vents": Node(repeat={"vent": vents}),
    "vent": Node(label="vent"),
    "casement": Node(repeat={"sash": sashes}),
    "sliding": Node(repeat={"sash": sashes}),
    "tilt_turn": Node(repeat={"sash": sashes}),
    "awning": Node(repeat={"sash": sashes}),
    "double_hung": Node(repeat={"sash": 2}, optional={"sash_locks": 0.8}),
    "sash_locks": Node(repeat={"sash_lock": sash_locks}),
    "sash_lock": Node(label="lock"),
    "sash": Node(label="sash", optional={"lever": 1.0}),
    "lever": Node(label="handle"),
    "sill": Node(), "transom": Node(),
    "shutters": Node(repeat={"shutter": shutter_leaves}),
    "shutter": Node(label="shutter"),
    "curtains": Node(repeat={"curtain": curtain_panels}),
    "curtain": Node(label="curtain"),
})
"""A transom light grows only on frames taller than 1.1 m. A casement or tilt-and-turn sash's lever handle
turns (an espagnolette handle: down is locked, a quarter turn unlocks); knobs and pulls are fixed to their sash.
Trickle vents sit on the head's room face, one over each sash (one over a double-hung pair). A double-hung
window's lower sash may carry cam sash locks on its meeting rail, their levers turning about the vertical."""

PARAMS = (
    Float("width", "overall frame width (Y)", "m", *R.width),
    Float("height", "overall frame height, excl. the sill (Z)", "m", *R.height),
    Int("sash_count", "sashes; auto = round(opening width / sash_width), 1..4; lowered to the most of >= 0.25 m "
        "that fit", "", 1, 4, auto=True),
    Float("sash_width", "target sash width for the automatic sash count", "m", *R.sash_width),
    Float("frame_depth", "frame depth (X)", "m", *R.frame_depth),
    Float("frame_width", "face width of jambs and head (the bottom rail is 1.25x)", "m", *R.frame_width),
    Float("mullion_width", "face width of mullions and the transom bar", "m", *R.mullion_width),
    Float("stile_width", "face width of a sash frame", "m", *R.stile_width),
    Choice("frame_finish", "frame and sash material", choices=("painted", "wood", "plastic"),
           weights=(0.4, 0.3, 0.3)),
    Choice("glazing", "plain panes or panes divided by glazing bars", choices=("plain", "bars"),
           weights=(0.65, 0.35)),
    Int("bar_rows", "pane rows of a sash with glazing bars", "", *R.bar_rows),
    Int("bar_cols", "pane columns of a sash with glazing bars", "", *R.bar_cols),
    Choice("meeting", "where two casements' free edges meet: a mullion or a French pair",
           choices=("mullion", "french")),
    Choice("handle_style", "casement handle", choices=("lever", "knob"), weights=(0.7, 0.3)),
    Choice("handle_finish", "handle material", choices=("chrome", "brushed_metal", "plastic")),
    Float("transom_fraction", "height of the transom light as a fraction of the opening", "",
          *R.transom_fraction),
    Float("sill_depth", "exterior sill projection beyond the frame (X)", "m", *R.sill_depth),
    Float("sill_thickness", "exterior sill thickness", "m", *R.sill_thickness),
    Choice("shutter_style", "shutter leaves", choices=("louvred", "panelled", "boarded"), weights=(0.45, 0.3, 0.25)),
    Choice("shutter_finish", "shutter material", choices=("painted", "wood"), weights=(0.7, 0.3)),
    Float("shutter_thickness", "shutter leaf thickness", "m", *R.shutter_thickness),
    Float("shutter_leaf_width", "widest single shutter leaf; a wider side folds in two leaves", "m",
          *R.shutter_leaf_width),
    Float("shutter_angle", "how far a shutter opens (it stops short of the wall plane)", "rad",
          *R.shutter_angle),
    Float("curtain_offset", "clearance from the sash handles to the curtains (casements: + half a sash width)",
          "m", *R.curtain_offset),
    Float("curtain_rise", "height of the curtain rod above the frame", "m", *R.curtain_rise),
    Float("curtain_overhang", "rod and closed curtains reach past each side of the frame", "m",
          *R.curtain_overhang),
    Float("curtain_drop", "curtain length as a fraction of the rod height", "", *R.curtain_drop),
    Choice("curtain_panels", "a pair of curtains drawn apart, or one panel drawn to one side",
           choices=("pair", "single"), weights=(0.65, 0.35)),
    Float("curtain_open", "how far a curtain half slides, as a fraction of its width", "", *R.curtain_open),
    Choice("rod_finish", "curtain rod material", choices=("brushed_metal", "wood", "chrome")),
)

_FRAME = {"painted": "painted:white|off_white|light_grey|grey|charcoal|black|sage|navy",
          "plastic": "plastic:white|light_grey|dark_grey|black"}
SHUTTER_PAINTS = "painted:sage|navy|charcoal|white|off_white|pastel_blue|pastel_green|grey|black"
MATERIALS = {
    "frame": ("frame_finish", _FRAME), "glass": "glass:clear|clear_blue",
    "handle": ("handle_finish", {"plastic": "plastic:white|black"}),
    "shutter": ("shutter_finish", {"painted": SHUTTER_PAINTS}),
    "curtain": "fabric", "rod": "rod_finish",
}


def _bounds(pieces):
    b = np.array([pc.bounds for pc in pieces])
    return b[:, 0].min(0), b[:, 1].max(0)


def max_sashes(p: dict) -> int:
    """The most sashes the opening holds at P.MIN_SASH each, with a mullion between two."""
    opening = p["width"] - 2 * jamb_width(p)
    mw = min(p["mullion_width"], P.MULLION_MAX * opening)
    return max(1, int((opening + mw) // (P.MIN_SASH + mw)))


def fit_frame(p: dict) -> dict:
    """A transom light only on frames taller than 1.1 m (casements and sliders); sizes per design; a sash
    count that would make sashes narrower than P.MIN_SASH is lowered to the most that fit."""
    p = dict(p)
    for k, (lo, hi) in P.SIZES.get(p["style"], {}).items():
        p[k] = float(min(max(p[k], lo), hi))
    if p["sash_count"]:
        p["sash_count"] = min(p["sash_count"], max_sashes(p))
    if p["style"] in ("awning", "double_hung"):
        p["has_transom"] = False
    p["has_lever"] = p["has_lever"] and p["style"] in ("casement", "tilt_turn") and p["handle_style"] == "lever"
    return {**p, "has_transom": p["has_transom"] and p["height"] > P.TRANSOM_FROM}


class WindowLayout(Layout):
    def window(self, node):
        p = self.p
        W, H, fd = p["width"], p["height"], p["frame_depth"]
        for slot in ("frame", "shutter"):  # painted joinery is softwood
            if p[f"{slot}_finish"] == "painted":
                self.bp.densities[slot] = P.SOFTWOOD
        z0 = p["sill_thickness"] if node.one("sill") else 0.0
        fw = jamb_width(p)
        yi0, yi1 = -W / 2 + fw, W / 2 - fw  # opening
        zi0, zi1 = z0 + P.BOTTOM_RAIL * fw, z0 + H - fw
        mw = min(p["mullion_width"], P.MULLION_MAX * (yi1 - yi0))
        zs1, transom = zi1, None  # top of the sash area, the transom light's hole
        if node.one("transom"):
            zt = zi1 - p["transom_fraction"] * (zi1 - zi0)
            zs1, transom = zt - mw / 2, (yi0, zt + mw / 2, yi1, zi1)
        frame: list = []
        light: list = []

        def middle() -> str:
            return "left" if self.rng.random() < 0.5 else "right"

        style = node.one(node.choice)
        if node.choice in ("casement", "tilt_turn", "awning"):
            build = {"casement": P.casement, "tilt_turn": P.tilt_turn, "awning": P.awning}[node.choice]
            made, x_room = build(frame, light, p, (fd, yi0, yi1, zi0, zs1, mw), transom, middle)
        else:
            build = P.sliding if node.choice == "sliding" else P.double_hung
            made, x_room = build(frame, light, p, (fd, yi0, yi1, zi0, zs1), transom, middle)
        self.add("frame", "frame", frame)
        if node.one("sill"):
            self.grow(node.one("sill"), z0=z0)
        if node.one("transom"):
            self.grow(node.one("transom"), light=light)
        self.grow(style, made=made)
        if node.one("shutters"):
            self.grow(node.one("shutters"), made=P.shutters(p, W, H, fd, z0))
        if node.one("curtains"):
            side = (1 if self.rng.random() < 0.5 else -1) if p["curtain_panels"] == "single" else 0
            self.grow(node.one("curtains"), made=P.curtains(p, W, H, fd, z0, fw, x_room, side))
        if node.one("trickle_vents"):
            spans = [(float(b[0][1]), float(b[1][1])) for b in
                     (_bounds([pc for pc in pieces if pc.material != "handle"]) for _, pieces, _ in made)]
            if node.choice == "double_hung":
                spans = spans[:1]
            self.grow(node.one("trickle_vents"), spans=spans, x=fd / 2, z=(zi1 + z0 + H) / 2, h=z0 + H - zi1)

    def sill(self, node, z0):
        p = self.p
        self.extend("frame", P.sill(p["width"], p["frame_depth"], p["sill_depth"], z0))

    def transom(self, node, light):
        """The transom light's glass; its opening and bar are cut in the frame by the sash layout."""
        self.extend("frame", light)

    def _parts(self, node, kind, made):
        for kid, (name, pieces, spec) in zip(node.of(kind), made, strict=True):
            self.grow(kid, name=name, pieces=pieces, spec=spec)

    def casement(self, node, made):
        self._parts(node, "sash", made)

    sliding = tilt_turn = awning = casement

    def double_hung(self, node, made):
        self._parts(node, "sash", made)
        if node.one("sash_locks"):
            lo, hi = _bounds([pc for pc in made[0][1] if pc.material != "handle"])  # the lower sash
            self.grow(node.one("sash_locks"), sash=made[0][0], lo=lo, hi=hi)

    def sash_locks(self, node, sash, lo, hi):
        kids = node.of("sash_lock")
        for k, kid in enumerate(kids):
            y = lo[1] + (hi[1] - lo[1]) * (k + 1) / (len(kids) + 1)  # centred, or at the third points
            self.grow(kid, k=k, sash=sash, xs=(float(lo[0]), float(hi[0])), y=float(y), z=float(hi[2]))

    def sash_lock(self, node, k, sash, xs, y, z):
        """A cam sash lock on the lower sash's meeting rail: its base screwed to the rail's top, its lever
        lying along the rail (locked) and turning a quarter turn about the vertical toward the room."""
        base, lever, pivot = P.sash_lock(xs, y, z)
        self.extend(sash, base)
        name = self.add(f"lock_{k}", "lock", lever)
        # about -z: the lever turns from along +y toward the room (+x), away from the upper sash
        self.hinge(sash, name, Frame.at(pivot, z=(0, 0, -1)), upper=P.LEVER_TURN, role="knob")

    def sash(self, node, name, pieces, spec):
        lever = [pc for pc in pieces if pc.name == "handle"] if node.one("lever") else []
        self.add(name, "sash", [pc for pc in pieces if pc not in lever or pc is lever[0]])  # the rose stays
        self.join(spec)
        if lever:
            self.grow(node.one("lever"), sash=name, pieces=lever[1:])

    def lever(self, node, sash, pieces):
        """The espagnolette lever (spindle and grip; its rose stays on the sash) turns a quarter turn about the
        sash normal toward the hinge side: hanging under its spindle it is neutral under gravity."""
        spindle, (x0, y, z) = P.free_spindle(pieces[0])
        pieces = [spindle, *pieces[1:]]
        hinge_y = float(self.bp.joints[-1].dofs[0].origin[1])
        toward = 1.0 if hinge_y > y else -1.0
        name = self.add(f"{sash}_lever", "handle", pieces)
        self.hinge(sash, name, Frame.at((x0, y, z), z=(toward, 0, 0)), upper=P.LEVER_TURN, role="knob")

    def trickle_vents(self, node, spans, x, z, h):
        for k, (kid, span) in enumerate(zip(node.of("vent"), spans, strict=True)):
            self.grow(kid, k=k, span=span, x=x, z=z, h=h)

    def vent(self, node, k, span, x, z, h):
        """A trickle vent on the head's room face over one sash: a housing with a slot and a shutter slide
        that covers or opens it (Titon Trimvent / Greenwood slot vents: 250-400 mm housings, ~20 mm high,
        a 30-40 mm slide stroke)."""
        housing, slide, start, travel = P.trickle_vent(span, x, z, h)
        self.extend("frame", housing)
        name = self.add(f"vent_{k}", "vent", slide)
        self.slide("frame", name, Frame.at(start, z=(0, 1, 0)), upper=travel)

    def shutters(self, node, made):
        self._parts(node, "shutter", made)

    def shutter(self, node, name, pieces, spec):
        self.add(name, "shutter", pieces)
        self.join(spec)

    def curtains(self, node, made):
        rod, halves = made
        self.extend("frame", rod)
        self._parts(node, "curtain", halves)

    def curtain(self, node, name, pieces, spec):
        self.add(name, "curtain", pieces)
        self.join(spec)


CATEGORY = Category("window", __doc__.strip().splitlines()[0], PARAMS, GRAMMAR, WindowLayout, MATERIALS,
                    derive=fit_frame, palette=furniture)
