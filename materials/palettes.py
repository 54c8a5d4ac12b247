"""Palettes of real products, per kind of object, as data (family specs, see
:func:`~infmob_usd.materials.families.split_spec`).

Categories name a family (``"painted"``, ``"plastic"`` ...); where a kind of product is only
sold in some colours, its category passes the name through a palette here, e.g.
``appliance("painted")`` -> ``"painted:white|black|graphite|retro_cream"``: no pastel
microwave bodies, no toy-coloured oven knobs.  The sRGB values of the variants live in
:data:`~infmob_usd.materials.families.FAMILIES`.
"""

from __future__ import annotations

from .families import split_spec

__all__ = ["APPLIANCE", "BULB_GLASS", "appliance"]

APPLIANCE: dict[str, str] = {
    # Finishes sold for microwaves, ovens, wine/beverage fridges and dishwashers by Bosch,
    # Whirlpool, GE, Samsung and LG: stainless steel, white, black, and a dark metallic grey
    # ("black stainless" / GE "Slate" / Bosch "black inox": our graphite); the named retro
    # variant is Smeg's "Cream" of its 50's Style range (e.g. FAB28, MOE25).  Colours are
    # approximate sRGB of the makers' product photographs.
    "painted": "painted:white|black|graphite|retro_cream",
    "enamel": "enamel:white|black|graphite|cream",
    "brushed_metal": "brushed_metal:stainless|stainless_dark|stainless_warm",
    # trims, knobs, buttons, door frames: black, greys or white plastic, never toy colours
    "plastic": "plastic:black|dark_grey|light_grey|white",
    # door windows: tinted (smoked) glass over the cavity, or clear on glass-door fridges
    "glass": "glass:smoked|clear",
}
"""Appliance finishes: family -> the variants real appliances are sold in."""

BULB_GLASS = "glass:frosted"
"""A household bulb: opal (frosted) warm-white glass, as the common A19/A60 LED and
incandescent bulbs (Philips, Osram, IKEA)."""


def appliance(spec: str) -> str:
    """``spec`` restricted to appliance finishes; a spec that names its variants, or a family
    without an appliance palette (chrome, rubber ...), is returned unchanged."""
    family, variants = split_spec(spec)
    return spec if variants else APPLIANCE.get(family, spec)
