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

__all__ = ["APPLIANCE", "BULB_GLASS", "FURNITURE", "appliance", "furniture"]

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

FURNITURE: dict[str, str] = {
    # Painted furniture, kitchen fronts and carcasses, lamp poles: white first (47 % of kitchens in an NKBA
    # survey, grey next at 17 %: tipking.com/kitchen/what-is-the-most-popular-color-for-kitchen-cabinets),
    # then the off-whites, greys, sage / grey-green, navy and matte black that cabinet and furniture paint
    # ranges are sold in (yahoo.com/lifestyle/7-paint-colors-loving-kitchen-212826925.html: Sherwin-Williams
    # Naval and Pewter Green, Benjamin Moore Onyx; homeplaceparts.com/what-color-should-i-paint-my-kitchen-
    # cabinets: sage, cream and off-white, charcoal). No pastel pink, yellow or baby blue carcasses.
    "painted": "painted:white|white|off_white|light_grey|grey|charcoal|sage|navy|black",
    # moulded furniture parts (chair shells and bases, lamp fittings and switches, feet): black, greys, white
    "plastic": "plastic:black|dark_grey|light_grey|white",
}
"""Furniture and lamp finishes: family -> the variants they are sold in (white listed twice: drawn twice as
often)."""

BULB_GLASS = "glass:frosted"
"""A household bulb: opal (frosted) warm-white glass, as the common A19/A60 LED and
incandescent bulbs (Philips, Osram, IKEA)."""


def _restricted(spec: str, palette: dict[str, str]) -> str:
    """``spec`` restricted to ``palette``'s variants; a spec that names its variants, or a family the
    palette has no entry for, is returned unchanged."""
    family, variants = split_spec(spec)
    return spec if variants else palette.get(family, spec)


def appliance(spec: str) -> str:
    """``spec`` restricted to appliance finishes (:data:`APPLIANCE`; chrome, rubber ... unchanged)."""
    return _restricted(spec, APPLIANCE)


def furniture(spec: str) -> str:
    """``spec`` restricted to furniture finishes (:data:`FURNITURE`; wood, chrome, fabric ... unchanged)."""
    return _restricted(spec, FURNITURE)
