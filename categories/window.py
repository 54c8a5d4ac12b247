"""Window: casement, sliding, tilt-and-turn, top-hung awning or double-hung sashes in a frame.

Designs (``style``) beyond the two below: ``tilt_turn`` (casements whose side hinge rides on a tilt
hinge along the bottom rail: flip_revolute, the tilt pressed closed by gravity), ``awning`` (top-hung
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
the centre (horizontal slides: neutral under gravity). In front of casements the
rod stands off by half a sash width more; the core stops the casements
before they reach the curtains (``limit_to_clearance``). A transom light (fixed glass above a bar)
grows only on frames taller than 1.1 m. Every hinge axis is vertical and every
slide horizontal, so nothing moves under gravity.
"""

from __future__ import annotations

import numpy as np

from infmob_usd import geometry as g
from infmob_usd.category import Category
from infmob_usd.grammar import Grammar, Layout, Node
from infmob_usd.params import Choice, Float, Int

from .parts import windows as P


def sashes(p, rng) -> int:
    """sash_count, or round(opening width / sash_width), 1..4"""
    opening = p["width"] - 2 * min(p["frame_width"], 0.12 * p["width"], 0.12 * p["height"])
    return p["sash_count"] or int(np.clip(round(opening / p["sash_width"]), 1, 4))


def shutter_leaves(p, rng) -> int:
    """two leaves, four (bifolds) when a side is wider than shutter_leaf_width"""
    return 4 if p["width"] / 2 > p["shutter_leaf_width"] else 2


GRAMMAR = Grammar("window", {
    "window": Node(label="frame", one_of={"casement": 0.3, "sliding": 0.2, "tilt_turn": 0.2, "awning": 0.15,
                                          "double_hung": 0.15}, choice="style",
                   optional={"shutters": 0.2, "curtains": 0.3, "sill": 0.6, "transom": 0.25}),
    "casement": Node(repeat={"sash": sashes}),
    "sliding": Node(repeat={"sash": sashes}),
    "tilt_turn": Node(repeat={"sash": sashes}),
    "awning": Node(repeat={"sash": sashes}),
    "double_hung": Node(repeat={"sash": 2}),
    "sash": Node(label="sash"),
    "sill": Node(), "transom": Node(),
    "shutters": Node(repeat={"shutter": shutter_leaves}),
    "shutter": Node(label="shutter"),
    "curtains": Node(repeat={"curtain": 2}),
    "curtain": Node(label="curtain"),
})
"""A transom light grows only on frames taller than 1.1 m."""

PARAMS = (
    Float("width", "overall frame width (Y)", "m", 0.6, 2.5),
    Float("height", "overall frame height, excl. the sill (Z)", "m", 0.6, 2.5),
    Int("sash_count", "sashes; auto = round(opening width / sash_width), 1..4", "", 1, 4, auto=True),
    Float("sash_width", "target sash width for the automatic sash count", "m", 0.4, 0.85),
    Float("frame_depth", "frame depth (X)", "m", 0.07, 0.14),
    Float("frame_width", "face width of jambs and head (the bottom rail is 1.25x)", "m", 0.04, 0.09),
    Float("mullion_width", "face width of mullions and the transom bar", "m", 0.04, 0.08),
    Float("stile_width", "face width of a sash frame", "m", 0.035, 0.07),
    Choice("frame_finish", "frame and sash material", choices=("painted", "wood", "plastic"),
           weights=(0.4, 0.3, 0.3)),
    Choice("glazing", "plain panes or panes divided by glazing bars", choices=("plain", "bars"),
           weights=(0.65, 0.35)),
    Int("bar_rows", "pane rows of a sash with glazing bars", "", 2, 4),
    Int("bar_cols", "pane columns of a sash with glazing bars", "", 1, 2),
    Choice("meeting", "where two casements' free edges meet: a mullion or a French pair",
           choices=("mullion", "french")),
    Choice("handle_style", "casement handle", choices=("lever", "knob"), weights=(0.7, 0.3)),
    Choice("handle_finish", "handle material", choices=("chrome", "brushed_metal", "plastic")),
    Float("transom_fraction", "height of the transom light as a fraction of the opening", "",
          0.18, 0.3),
    Float("sill_depth", "exterior sill projection beyond the frame (X)", "m", 0.03, 0.1),
    Float("sill_thickness", "exterior sill thickness", "m", 0.025, 0.05),
    Choice("shutter_style", "shutter leaves", choices=("louvred", "panelled", "boarded"), weights=(0.45, 0.3, 0.25)),
    Choice("shutter_finish", "shutter material", choices=("painted", "wood"), weights=(0.7, 0.3)),
    Float("shutter_thickness", "shutter leaf thickness", "m", 0.025, 0.04),
    Float("shutter_leaf_width", "widest single shutter leaf; a wider side folds in two leaves", "m",
          0.55, 0.8),
    Float("shutter_angle", "how far a shutter opens (it stops short of the wall plane)", "rad",
          1.25, 1.5),
    Float("curtain_offset", "clearance from the sash handles to the curtains (casements: + half a sash width)",
          "m", 0.06, 0.2),
    Float("curtain_rise", "height of the curtain rod above the frame", "m", 0.05, 0.2),
    Float("curtain_overhang", "rod and closed curtains reach past each side of the frame", "m",
          0.05, 0.25),
    Float("curtain_drop", "curtain length as a fraction of the rod height", "", 0.6, 0.98),
    Float("curtain_open", "how far a curtain half slides, as a fraction of its width", "", 0.45, 0.75),
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

TRANSOM_FROM = 1.1  # frames taller than this may have a transom light
SILL_EAR = 0.03  # the sill reaches this far past the frame on each side
BOTTOM_RAIL = 1.25  # the bottom rail is this much wider than the jambs


SIZES = {"tilt_turn": dict(width=(0.6, 1.6), height=(0.6, 2.4)), "awning": dict(width=(0.6, 2.5), height=(0.4, 1.0)),
         "double_hung": dict(width=(0.6, 1.2), height=(0.9, 2.0))}
"""Frame sizes of the designs that come in a narrower range (manufacturers' size tables: Roto, Velfac,
Andersen 400 series): a wider or taller draw is brought into it."""


def transom_fits(p: dict) -> dict:
    """A transom light only on frames taller than 1.1 m (casements and sliders); sizes per design."""
    p = dict(p)
    for k, (lo, hi) in SIZES.get(p["style"], {}).items():
        p[k] = float(min(max(p[k], lo), hi))
    if p["style"] in ("awning", "double_hung"):
        p["has_transom"] = False
    return {**p, "has_transom": p["has_transom"] and p["height"] > TRANSOM_FROM}


class WindowLayout(Layout):
    def window(self, node):
        p = self.p
        W, H, fd = p["width"], p["height"], p["frame_depth"]
        z0 = p["sill_thickness"] if node.one("sill") else 0.0
        fw = min(p["frame_width"], 0.12 * W, 0.12 * H)
        yi0, yi1 = -W / 2 + fw, W / 2 - fw  # opening
        zi0, zi1 = z0 + BOTTOM_RAIL * fw, z0 + H - fw
        mw = min(p["mullion_width"], 0.1 * (yi1 - yi0))
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
            self.grow(node.one("curtains"), made=P.curtains(p, W, H, fd, z0, fw, x_room))

    def sill(self, node, z0):
        p = self.p
        W, fd, sd = p["width"], p["frame_depth"], p["sill_depth"]
        self.extend("frame", [
            g.box_between([-fd / 2 - sd, -W / 2 - SILL_EAR, 0.0], [fd / 2, W / 2 + SILL_EAR, z0], "frame", bevel=0.003),
            g.box_between([-fd / 2 - sd, -W / 2 - SILL_EAR, -0.012], [-fd / 2 - sd + 0.012, W / 2 + SILL_EAR, 0.0],
                          "frame")])  # drip edge

    def transom(self, node, light):
        """The transom light's glass; its opening and bar are cut in the frame by the sash layout."""
        self.extend("frame", light)

    def _parts(self, node, kind, made):
        for kid, (name, pieces, spec) in zip(node.of(kind), made, strict=True):
            self.grow(kid, name=name, pieces=pieces, spec=spec)

    def casement(self, node, made):
        self._parts(node, "sash", made)

    sliding = tilt_turn = awning = double_hung = casement

    def sash(self, node, name, pieces, spec):
        self.add(name, "sash", pieces)
        self.join(spec)

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
                    derive=transom_fits)
