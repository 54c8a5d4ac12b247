"""Vessel designs added for variety (issue 14): vase feet, stoppers and liners; clip-top, hinged and
stopper jar lids; swing-top, pump and sports bottle closures; steamer inserts and pressure-cooker
lids for pots; folding and detachable pan handles.

Like :mod:`.vessel`, every builder returns an :class:`~infmob_usd.assembly.Assembly` in its own
local frame, Z up along the vessel's axis; closures have their ``seat`` anchor at the origin (attach
it to the body's ``lid_seat``). Mechanisms that are more than one part return their joints inside
the assembly (names local to it). Dimensions come from :mod:`.closure_sizes`.
"""

from __future__ import annotations

import math

import numpy as np

from infmob_usd import geometry as g
from infmob_usd import joints as J
from infmob_usd.assembly import Assembly
from infmob_usd.frames import IDENTITY, Frame

from . import closure_sizes as C
from .vessel import SECTIONS, UP, Profile, _at, _closure, _piece, _plug_lid, _supports, lid_gap

# ---------------------------------------------------------------------------
# vase


def stand_foot(body: Profile, slot: str) -> Assembly:
    """A flared foot ring glued under the base of wall ``body`` (``mount`` at its top centre): as wide
    as the base, flaring outward toward the table."""
    f = C.VASE_FOOT
    r_top = body.base_radius - 0.2 * body.thickness
    top = -f["gap"]
    width = min(f["width"], f["width_ratio"] * r_top)
    ring = g.shell([(r_top + f["flare"], top - f["height"]), (r_top, top)], width, slot, sections=SECTIONS)
    return Assembly.single("stand", [ring], {"mount": IDENTITY}, _supports(r_top + f["flare"], top - f["height"]))


def vase_stopper(mouth: Profile, slot: str, sheet: float = 0.0) -> Assembly:
    """A turned stopper for a vase's neck: a flange past the rim, a tall dome and finial, a plug."""
    s = C.VASE_STOPPER
    r_flange = mouth.top_radius + s["overhang"]
    depth = float(np.clip(s["depth"][0] * mouth.height, *s["depth"][1:]))
    knob = float(np.clip(s["knob"][0] * r_flange, *s["knob"][1:]))
    return _plug_lid(mouth, r_flange, s["flange"], depth, s["dome"], knob, slot, sheet, label="stopper")


def liner(mouth: Profile, slot: str, reach: float) -> tuple[Assembly, float]:
    """A removable glass liner hanging from a rolled flange a small gap above the rim, its tube
    ``reach`` x the vase's depth deep with clearance from the wall all the way down (it slides out
    through the narrowest part). Returns it (``seat`` at the rim) and how far it lifts to come out."""
    L = C.LINER
    H = mouth.height
    gap = lid_gap(0.02)
    z_bot = max(H * (1.0 - reach), mouth.thickness * 2 + L["floor_clear"])
    r_out = mouth.free_radius(z_bot, H) - L["room"]
    t = min(L["wall"], 0.3 * r_out)
    z_top = H + gap
    tube = Profile.through([(r_out, z_bot), (r_out, 0.5 * (z_bot + z_top)), (r_out, z_top)], t, (24, 3))
    floor = g.disc((0, 0, z_bot + t / 2), r_out - 0.2 * t, t, slot, SECTIONS)
    r_fl = max(mouth.top_radius + L["flange"], r_out + L["flange"])
    flange = g.shell([(r_fl, z_top), (r_fl, z_top + L["flange_t"])], r_fl - r_out + 0.5 * t, slot,
                     sections=SECTIONS)
    a = _closure("liner", [tube.wall(slot), floor, flange], H, z_top + L["flange_t"])
    return a, min(H - z_bot, L["max_lift"])
