"""Material families as data, and seeded sampling of one appearance (a :class:`Look`).

A :class:`Family` describes a kind of material: its physical density, the
palette it is painted from, the ranges of its PBR parameters and the ranges of
the knobs that drive texture synthesis (see :mod:`infmob_usd.materials.synth`).

Looks come from a finite library: each palette variant of a family has
:data:`LOOKS_PER_VARIANT` looks, :func:`library_look` ``(family, variant, index)``,
each a pure function of those three (colour jitter, roughness, synthesis knobs and
noise seed drawn from a generator seeded by them).  :func:`sample_look` draws a
variant and an index with an explicitly passed :class:`numpy.random.Generator`.
Because the set of looks is finite, their encoded texture maps are made once and
reused by every object that wears them (:mod:`infmob_usd.materials.cache`);
making the maps is most of the cost of an object otherwise.  A look is plain,
hashable, JSON-able data that fully determines its synthesized texture maps.

Colour conventions: palettes are written as sRGB hex strings (as one would pick
them in an image editor); :attr:`Look.base_color` is *linear* RGB.
"""

from __future__ import annotations

import colorsys
import math
import zlib
from dataclasses import asdict, dataclass, field, replace
from typing import Any

import numpy as np

__all__ = [
    "CONTACT", "FAMILIES", "NONVISUAL", "NONVISUAL_METAL", "LOOKS_PER_VARIANT", "WOOD_SPECIES", "Contact", "Family",
    "Look", "Wear", "library", "library_look", "nonvisual", "sample_look", "sample_wear", "srgb_to_linear",
]

LOOKS_PER_VARIANT = 16
"""Looks per palette variant of a family in the look library (``len(library())`` looks over all families)."""

Range = tuple[float, float]


@dataclass(frozen=True)
class Family:
    """One material family.

    Attributes
    ----------
    name : str
        Family key, e.g. ``"wood"``.
    density : float
        Density of the solid material in kg/m^3.
    style : str
        Texture synthesis style used by :func:`~infmob_usd.materials.synth.synthesize`:
        one of ``"wood"``, ``"brushed"``, ``"coating"``, ``"speckle"``, ``"woven"``, ``"corrugated"``,
        ``"polished"``.
    palette : tuple of (str, str)
        ``(variant name, sRGB hex colour)`` pairs; one is drawn uniformly.
    hsv_jitter : tuple of float
        ``(hue shift, relative saturation, relative value)`` half-widths of the
        uniform jitter applied to the drawn palette colour (in sRGB HSV).
    roughness : tuple of float
        Range of the mean roughness.
    metallic : float
        Metallic value (constant over the surface).
    opacity : tuple of float
        Range of the opacity (``(1, 1)`` for opaque families).
    color_variation : tuple of float
        Range of the relative per-pixel colour variation (std of the tint field).
    roughness_variation : tuple of float
        Range of the absolute roughness variation around the mean.
    bump : tuple of float
        Range of the RMS slope of the normal map (tangent of the typical tilt).
    scale : tuple of float
        Range of the main feature frequency in cycles per **metre** of surface
        (growth rings crossed per metre of radius for wood, streaks for brushed
        metal, orange peel for coatings, speckle for plastics, threads for
        fabric): real sizes, laid at the one texel density of every family
        (:data:`~infmob_usd.materials.synth.TILE_METRES` per texture repeat).
    anisotropy : tuple of float
        Range of the elongation of the main features along U (1 = isotropic).
        U runs along each part's long axis, so grain and brushing follow the part.
    variant_opacity : tuple of (str, (float, float))
        Per-variant opacity ranges that replace ``opacity`` (tinted bottle glass is
        denser than window glass, a frosted bulb nearly opaque).
    ior : float
        Index of refraction (written for see-through materials).
    specular_anisotropy : float
        Strength in [0, 1] of the anisotropic highlight of a brushed or grained finish, stretched
        across the texture's U (the part's long axis, :attr:`anisotropy`): glTF's
        ``KHR_materials_anisotropy`` ``anisotropyStrength`` (UsdPreviewSurface has no such input, and
        Assimp's MTL reader fails on the MTL PBR extension's ``aniso``).  0: isotropic.
    wall : float
        Wall thickness in metres of this family's parts where they are hollow (a steel tube or
        casing, a ceramic bowl, a glass bottle, a moulded plastic shell): a piece without its own
        ``sheet`` or ``wall`` is massed as a shell of this wall over its closed mesh, or solid
        where it is thinner than two walls (:func:`infmob_usd.mass.inertial`). 0: solid.
    """

    name: str
    density: float
    style: str
    palette: tuple[tuple[str, str], ...]
    hsv_jitter: tuple[float, float, float]
    roughness: Range
    metallic: float
    opacity: Range
    color_variation: Range
    roughness_variation: Range
    bump: Range
    scale: Range
    anisotropy: Range
    variant_opacity: tuple[tuple[str, Range], ...] = ()
    ior: float = 1.5
    wall: float = 0.0
    specular_anisotropy: float = 0.0


@dataclass(frozen=True)
class Wear:
    """How one object wears a library look: shader inputs, no new texture maps.

    Drawn per material slot from the object's materials stream (:func:`sample_look`), so
    two objects wearing the same library look still differ.  Writers apply it as shader
    inputs (USD ``UsdUVTexture`` ``inputs:scale`` and a ``UsdTransform2d``; MTL ``Kd``,
    ``map_Pr -mm`` and the UV transform baked into the OBJ ``vt``).

    Attributes
    ----------
    tint : tuple of float
        Linear RGB multiplier of the base colour map (near 1).
    roughness_scale : float
        Multiplier of the roughness map.
    uv_offset : tuple of float
        Translation of the UVs, in texture repeats, each in [0, 1).
    uv_rotation : float
        Rotation of the UVs about the origin, degrees counter-clockwise: 0 or 180 for
        grained families (wood, brushed metal: the grain stays along the part), a
        quarter turn for weaves, any angle for isotropic finishes.
    """

    tint: tuple[float, float, float] = (1.0, 1.0, 1.0)
    roughness_scale: float = 1.0
    uv_offset: tuple[float, float] = (0.0, 0.0)
    uv_rotation: float = 0.0

    def uv_matrix(self) -> np.ndarray:
        """``(2, 3)`` affine map of UVs: ``uv' = M[:, :2] @ uv + M[:, 2]`` (rotate, then offset)."""
        a = math.radians(self.uv_rotation)
        c, s = math.cos(a), math.sin(a)
        return np.array([[c, -s, self.uv_offset[0]], [s, c, self.uv_offset[1]]])


@dataclass(frozen=True)
class Look:
    """One sampled appearance of a family; plain Python data, hashable and JSON-able.

    Attributes
    ----------
    family : str
        Family key.
    variant : str
        Name of the palette entry the colour was drawn from (e.g. ``"walnut"``).
    base_color : tuple of float
        Mean colour, *linear* RGB in [0, 1].
    roughness : float
        Mean roughness in [0, 1].
    metallic : float
        Metallic value in [0, 1].
    opacity : float
        Opacity in [0, 1]; 1 except for glass.
    noise_seed : int
        Seed of every random draw made by texture synthesis (0 <= seed < 2**53).
    color_variation, roughness_variation, bump, scale, anisotropy : float
        Synthesis knobs, see :class:`Family`.
    index : int
        Position of the look among the :data:`LOOKS_PER_VARIANT` looks of its variant
        (-1 for a look made by hand rather than by :func:`library_look`).
    wear : Wear
        How this object wears the look (:class:`Wear`).  Not part of the look's
        identity: equality, hashing and the texture cache ignore it.
    """

    family: str
    variant: str
    base_color: tuple[float, float, float]
    roughness: float
    metallic: float
    opacity: float
    noise_seed: int
    color_variation: float
    roughness_variation: float
    bump: float
    scale: float
    anisotropy: float
    index: int = -1
    wear: Wear = field(default=Wear(), compare=False)

    def to_dict(self, wear: bool = True) -> dict[str, Any]:
        """Return the look as a JSON-serialisable dict (``base_color`` as a list; ``wear``
        as a dict of lists, left out when ``wear`` is false)."""
        d = asdict(self)
        d["base_color"] = list(self.base_color)
        if wear:
            d["wear"] = {k: list(v) if isinstance(v, tuple) else v for k, v in d["wear"].items()}
        else:
            del d["wear"]
        return d

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> Look:
        """Rebuild a look from :meth:`to_dict` output."""
        w = d.get("wear") or {}
        wear = Wear(**{k: tuple(float(x) for x in v) if isinstance(v, list) else float(v) for k, v in w.items()})
        return cls(**{**d, "base_color": tuple(float(c) for c in d["base_color"]), "wear": wear})


_OPAQUE = (1.0, 1.0)

WOOD_SPECIES: dict[str, dict[str, float]] = {
    # How each wood variant shows its anatomy (weights of the features drawn by the wood
    # synthesis; 0 = absent).  ring_porous: large earlywood pores in a band at the start of
    # every ring (oak, ash; walnut and teak are semi-ring-porous); pores: how visible the
    # pores are at all; rays: the flecks of broad medullary rays (oak only); rings: contrast
    # of latewood against earlywood.  After the USDA Forest Products Laboratory's
    # "Wood Handbook" (FPL-GTR-282, 2021), ch. 2 (structure) and ch. 3 (species descriptions).
    "oak": {"ring_porous": 1.0, "pores": 1.0, "rays": 1.0, "rings": 1.0},
    "walnut": {"ring_porous": 0.5, "pores": 0.7, "rays": 0.0, "rings": 0.7},
    "birch": {"ring_porous": 0.0, "pores": 0.25, "rays": 0.0, "rings": 0.45},
    "cherry": {"ring_porous": 0.0, "pores": 0.3, "rays": 0.0, "rings": 0.6},
    "maple": {"ring_porous": 0.0, "pores": 0.2, "rays": 0.0, "rings": 0.45},
    "teak": {"ring_porous": 0.4, "pores": 0.6, "rays": 0.0, "rings": 0.8},
}
"""Anatomy of each wood variant, read by the wood texture synthesis."""

FAMILIES: dict[str, Family] = {
    f.name: f
    for f in (
        Family(
            name="wood",
            density=650.0,
            style="wood",
            # Lacquered heartwood: sRGB of CIELAB (D65) targets inside the ranges spectrophotometer studies
            # report for planed heartwood (oak: Defoirdt et al., "A colour assessment methodology for oak
            # wood", Ann. For. Sci. 69:939, 2012, doi:10.1007/s13595-012-0214-3; 24 central European species
            # and how oil or lacquer darkens and intensifies them: "Wood colour of central European wood
            # species: CIELAB characterisation and colour intensification", Eur. J. Wood Prod., 2017,
            # doi:10.1007/s00107-016-1108-0), a few L* darker for the clear finish.  Chroma C* 14-29: a
            # finished board of C* 35-40 reads as orange paint, not wood.
            palette=(
                ("oak", "#AE8C67"),  # L* 61, a* 8, b* 25 (European/white oak)
                ("walnut", "#6B5040"),  # L* 36, a* 9, b* 14 (black walnut heartwood)
                ("birch", "#C9AD89"),  # L* 72, a* 5, b* 22
                ("cherry", "#92694F"),  # L* 48, a* 13, b* 21 (black cherry, aged)
                ("maple", "#CFB28C"),  # L* 74, a* 5, b* 23 (hard maple)
                ("teak", "#946E48"),  # L* 49, a* 10, b* 27
            ),
            hsv_jitter=(0.012, 0.08, 0.08),
            roughness=(0.4, 0.65),
            metallic=0.0,
            opacity=_OPAQUE,
            # ring, pore and board contrast of a finished board: latewood a few L* darker, not stripes
            color_variation=(0.1, 0.16),
            roughness_variation=(0.04, 0.08),
            bump=(0.02, 0.04),
            # growth rings 2.5-5.5 mm wide (Wood Handbook ch. 2: 4-14 rings per inch in
            # furniture hardwoods)
            scale=(180.0, 400.0),
            anisotropy=(14.0, 30.0),
        ),
        Family(
            name="painted",
            density=750.0,
            style="coating",
            palette=(
                ("white", "#F0F0EC"),
                ("off_white", "#E8E1D0"),
                ("light_grey", "#C6C7C5"),
                ("grey", "#8A8C8E"),
                ("charcoal", "#3C3E41"),
                ("sage", "#9CAF88"),
                ("navy", "#1F2F4F"),
                ("black", "#1C1C1C"),
                ("pastel_blue", "#AFC8DC"),
                ("pastel_pink", "#E6C3C3"),
                ("pastel_yellow", "#EFE0A6"),
                ("pastel_green", "#BFDCC4"),
                # appliance finishes (palettes.APPLIANCE_BODY names the sources)
                ("graphite", "#4A4D51"),
                ("retro_cream", "#EDE1C3"),
            ),
            hsv_jitter=(0.01, 0.06, 0.05),
            roughness=(0.3, 0.55),
            metallic=0.0,
            opacity=_OPAQUE,
            color_variation=(0.008, 0.02),
            roughness_variation=(0.02, 0.04),
            bump=(0.01, 0.025),
            scale=(200.0, 360.0),  # orange peel of a sprayed coat: 3-5 mm
            anisotropy=(1.0, 1.3),
        ),
        Family(
            name="brushed_metal",
            density=7850.0,
            # steel tube and pressed sheet: furniture tube walls 1-1.5 mm (EN 10305-3), appliance panels 0.6-0.8 mm
            wall=0.0012,
            style="brushed",
            # AISI 304 stainless, F0 (linear) 0.669/0.639/0.598 from its complex IOR (physicallybased.info,
            # "Stainless Steel", after refractiveindex.info): sRGB #D6D1CB; appliance sheet is sold in
            # slightly cooler and warmer casts of the same steel.
            palette=(
                ("stainless", "#D6D1CB"),
                ("stainless_dark", "#C9C7C4"),  # a darker, coarser grit brushing
                ("stainless_warm", "#D8D1C8"),
            ),
            hsv_jitter=(0.008, 0.05, 0.03),
            # a No. 4 brushed finish (ASTM A480, 120-180 grit): a satin sheen whose highlight is
            # stretched across the lines; as one isotropic roughness, 0.2-0.32
            roughness=(0.2, 0.32),
            metallic=1.0,
            opacity=_OPAQUE,
            color_variation=(0.008, 0.018),  # brushing lines barely change the colour, only the sheen
            roughness_variation=(0.03, 0.06),
            bump=(0.012, 0.025),
            scale=(700.0, 1100.0),  # abrasive lines 0.5-1.5 mm apart (the finest are sub-texel)
            anisotropy=(150.0, 300.0),  # lines run the length of the part, each many cm long
            # the highlight of a brushed sheet is stretched across the lines, several times longer than
            # wide (Filament's material guide: "brushed metals are anisotropic"); 0.6 chosen, not measured
            specular_anisotropy=0.6,
        ),
        Family(
            name="cast_iron",
            density=7200.0,  # grey cast iron, 7.05-7.35 g/cm3 (ASTM A48 classes 20-40)
            style="speckle",
            # seasoned or matte-enamelled cast iron (pan bodies, hob and range grates): a near-black,
            # semi-matte film over a sand-cast surface; physicallybased.info's "Iron" (F0 0.53/0.51/0.49)
            # shows only where the film wears through, so the film is what is drawn
            palette=(
                ("seasoned", "#232120"),
                ("matte_black", "#1B1B1C"),
            ),
            hsv_jitter=(0.005, 0.05, 0.08),
            roughness=(0.5, 0.7),
            metallic=0.0,
            opacity=_OPAQUE,
            color_variation=(0.04, 0.08),
            roughness_variation=(0.04, 0.08),
            bump=(0.06, 0.12),
            scale=(500.0, 900.0),  # sand-casting grain ~1-2 mm
            anisotropy=(1.0, 1.0),
        ),
        Family(
            name="plastic",
            density=1100.0,
            wall=0.0025,  # injection-moulded shells (chair pans, appliance trims, caps) 2-3 mm nominal wall
            style="speckle",
            palette=(
                ("black", "#1E1E1E"),
                ("white", "#EDEDEA"),
                ("light_grey", "#BEBFC0"),
                ("dark_grey", "#505254"),
                ("red", "#C0282D"),
                ("blue", "#1F5FBF"),
                ("yellow", "#F2C200"),
                ("green", "#2E9E4F"),
                ("orange", "#F26B1D"),
                ("teal", "#138A8A"),
            ),
            hsv_jitter=(0.01, 0.06, 0.06),
            roughness=(0.35, 0.6),
            metallic=0.0,
            opacity=_OPAQUE,
            # injection-moulded shells are one even colour with a fine spark-eroded grain (VDI 3400 Ref 18-30:
            # Ra 0.8-3.2 um, features well under a millimetre): a few-percent tint or a steep bump at the
            # noise's mm-to-cm scale reads as blotchy dough on a hand-held part, so both stay faint
            color_variation=(0.004, 0.01),
            roughness_variation=(0.01, 0.025),
            bump=(0.003, 0.008),
            scale=(220.0, 340.0),
            anisotropy=(1.0, 1.0),
        ),
        Family(
            name="glass",
            density=2500.0,
            # container glass walls 2.5-4 mm (750 ml wine bottles, jars); panes stay solid (thinner than two walls)
            wall=0.0035,
            style="polished",
            palette=(
                # clear glass reflects (4 % a face, physicallybased.info "Glass (Soda-lime)": IOR 1.52,
                # transmission 1), it does not scatter: the colour a viewer blends in at the opacity is a
                # dark, faintly green-grey (the iron tint seen through the edge of a pane), so a pane in
                # front of a dark room reads clear rather than as a milky film of white
                ("clear", "#4A5552"),
                ("clear_blue", "#46535A"),
                ("smoked", "#2B2E33"),  # the tinted window of an oven or microwave door
                # container glass colours: "emerald"/"Georgia green", "amber", "cobalt" of
                # the Glass Packaging Institute's colour names, sRGB as seen in transmission
                ("bottle_green", "#2F5E37"),
                ("bottle_blue", "#2F5A8A"),
                ("amber", "#6E3F16"),
                ("frosted", "#F4EEE0"),  # opal (frosted) warm-white bulb glass
            ),
            hsv_jitter=(0.01, 0.05, 0.04),
            roughness=(0.02, 0.05),
            metallic=0.0,
            opacity=(0.08, 0.14),
            color_variation=(0.002, 0.005),
            roughness_variation=(0.003, 0.006),
            bump=(0.001, 0.003),
            scale=(12.0, 32.0),
            anisotropy=(1.0, 2.0),
            variant_opacity=(
                ("clear_blue", (0.1, 0.16)),
                ("smoked", (0.55, 0.7)),
                ("bottle_green", (0.62, 0.78)),
                ("bottle_blue", (0.58, 0.72)),
                ("amber", (0.62, 0.78)),
                ("frosted", (0.88, 0.94)),
            ),
            ior=1.52,  # soda-lime glass
        ),
        Family(
            name="ceramic",
            density=2400.0,
            wall=0.008,  # vitreous china walls of toilets and basins 6-10 mm (slip casting); vases and jars 4-8 mm
            style="coating",
            palette=(
                ("white", "#F4F2EC"),
                ("cream", "#EFE5CC"),
                ("ivory", "#F3ECDA"),
                ("light_grey", "#D9D9D6"),
                ("pastel_blue", "#BCD3E3"),
                ("pastel_green", "#C9DEC5"),
                ("pastel_pink", "#EBCACA"),
            ),
            hsv_jitter=(0.01, 0.06, 0.03),
            roughness=(0.1, 0.25),
            metallic=0.0,
            opacity=_OPAQUE,
            color_variation=(0.005, 0.012),
            roughness_variation=(0.01, 0.02),
            bump=(0.004, 0.012),
            scale=(40.0, 90.0),  # glaze ripple 1-2.5 cm
            anisotropy=(1.0, 1.2),
        ),
        Family(
            name="rubber",
            density=1200.0,
            style="speckle",
            palette=(
                ("black", "#1A1A1A"),
                ("soft_black", "#222222"),
                ("deep_black", "#141414"),
                ("dark_grey", "#2C2C2C"),
            ),
            hsv_jitter=(0.0, 0.0, 0.08),
            roughness=(0.8, 0.95),
            metallic=0.0,
            opacity=_OPAQUE,
            color_variation=(0.04, 0.07),
            roughness_variation=(0.02, 0.04),
            bump=(0.05, 0.1),
            scale=(300.0, 440.0),
            anisotropy=(1.0, 1.0),
        ),
        Family(
            name="chrome",
            density=7850.0,
            wall=0.0012,  # chromed steel tube and hollow die-cast/stamped trim (lever handles, knob roses) ~1-1.5 mm
            style="polished",
            palette=(
                # electroplated chromium, F0 (linear) 0.654/0.685/0.701 from its complex IOR
                # (physicallybased.info, "Chromium"): sRGB #D3D8DA, the bluish cast of chrome
                ("chrome", "#D3D8DA"),
                ("chrome_cool", "#CDD4DA"),
                ("chrome_bright", "#DADEE0"),
            ),
            hsv_jitter=(0.005, 0.05, 0.02),
            roughness=(0.02, 0.06),  # electroplated chrome: a mirror
            metallic=1.0,
            opacity=_OPAQUE,
            color_variation=(0.001, 0.003),
            roughness_variation=(0.003, 0.006),
            bump=(0.0005, 0.0015),
            scale=(100.0, 180.0),
            anisotropy=(1.0, 1.0),
        ),
        Family(
            name="enamel",
            density=7850.0,
            wall=0.0012,  # enamelled sheet steel (cooktops, oven cavities, rack uprights) 0.6-1.5 mm
            style="coating",
            palette=(
                ("white", "#F1F1EE"),
                ("black", "#181818"),
                ("red", "#B5231F"),
                ("cream", "#EDE1C0"),
                ("cobalt", "#22458C"),
                ("green", "#2F6B4F"),
                ("graphite", "#404347"),
                # oven-cavity enamels: the blue-black speckled and anthracite porcelain of range and
                # wall-oven cavities (Whirlpool, GE, Bosch, Miele), not a saturated blue
                ("midnight", "#272C38"),
                ("anthracite", "#35373B"),
            ),
            hsv_jitter=(0.01, 0.05, 0.05),
            roughness=(0.15, 0.3),
            metallic=0.0,
            opacity=_OPAQUE,
            color_variation=(0.006, 0.015),
            roughness_variation=(0.01, 0.025),
            bump=(0.006, 0.015),
            scale=(80.0, 160.0),
            anisotropy=(1.0, 1.3),
        ),
        Family(
            name="fabric",
            # upholstery as modelled (a cushion is one solid): polyurethane foam 25-45 kg/m^3 under a
            # 300-500 g/m^2 cover, ~100 kg/m^3 over a 5-8 cm cushion (EN 1726 foam grades; was 300)
            density=100.0,
            style="woven",
            palette=(
                ("charcoal", "#3A3B3D"),
                ("grey", "#8B8C8E"),
                ("beige", "#C9B99A"),
                ("navy", "#2A3550"),
                ("denim", "#3D5A80"),
                ("burgundy", "#6E1F2A"),
                ("olive", "#6B6B3A"),
                ("mustard", "#C9A13B"),
                ("teal", "#2D6E6E"),
                ("cream", "#E8DFCC"),
                ("rust", "#A4502B"),
            ),
            hsv_jitter=(0.01, 0.08, 0.08),
            roughness=(0.8, 1.0),
            metallic=0.0,
            opacity=_OPAQUE,
            color_variation=(0.05, 0.1),
            roughness_variation=(0.03, 0.06),
            bump=(0.25, 0.4),
            scale=(500.0, 900.0),  # threads 1.1-2 mm: a coarse linen or upholstery weave
            anisotropy=(4.0, 8.0),
        ),
        Family(
            name="cardboard",
            # corrugated board as modelled (one solid board at its caliper): a C-flute single-wall board is
            # ~4 mm thick and weighs 0.5-0.65 kg/m^2 (125-200 g/m^2 liners and fluting; FEFCO/ECMA code,
            # board grades), ~140 kg/m^3; solid folding-box board (shoe boxes) 1-2 mm of 600-800 kg/m^3 is
            # massed by its slot's substrate
            density=140.0,
            style="corrugated",
            palette=(
                # unbleached kraft liner (brown), mottled white-top liner and the printed coated board of
                # shoe boxes, as seen on retail shipping and shoe boxes (approximate sRGB of product photos)
                ("kraft", "#A47D55"),
                ("kraft_light", "#B99570"),
                ("white_top", "#E4DFD3"),
                ("black", "#2B2B2C"),
                ("orange", "#D9662B"),
                ("blue", "#3E6F9E"),
            ),
            hsv_jitter=(0.01, 0.06, 0.06),
            roughness=(0.8, 0.92),  # uncoated paper: matte
            metallic=0.0,
            opacity=_OPAQUE,
            color_variation=(0.05, 0.09),  # fibre mottling of recycled kraft
            roughness_variation=(0.02, 0.04),
            bump=(0.03, 0.06),
            # C-flute pitch 7.4-8.1 mm, B-flute 6.1-6.9 mm (FEFCO flute profiles): 125-160 flutes a metre
            scale=(125.0, 160.0),
            anisotropy=(1.0, 1.0),
        ),
        Family(
            name="screen",
            density=2500.0,  # the cover glass of a display panel
            style="polished",
            palette=(
                ("black", "#0C0E11"),
                ("blue_black", "#0A0E15"),
            ),
            hsv_jitter=(0.005, 0.05, 0.05),
            roughness=(0.03, 0.07),  # glossy cover glass
            metallic=0.0,
            opacity=_OPAQUE,
            color_variation=(0.002, 0.004),
            roughness_variation=(0.003, 0.006),
            bump=(0.0005, 0.001),
            scale=(100.0, 200.0),
            anisotropy=(1.0, 1.0),
        ),
    )
}


@dataclass(frozen=True)
class Contact:
    """Contact properties of a material family: what a physics material carries.

    ``static`` and ``dynamic`` are the Coulomb friction coefficients of the family's
    surface against itself (or the nearest pair a table lists), ``restitution`` the
    coefficient of restitution of a small object of it dropped on a hard floor;
    ``source`` names where each figure comes from.
    """

    static: float
    dynamic: float
    restitution: float
    source: str


_FRICTION_HOWWHY = "howwhy.nfshost.com/new/book1/motion/coefficients.html"
_FRICTION_TABLE_A1 = "ecampusontario.pressbooks.pub/physicsfundamentals/back-matter/appendix (Table A.1)"
_FRICTION_PLASTICS = "designengineers.blogspot.com/2008/03/coefficients-of-friction-static-ranges.html"
_FRICTION_GLASS = "scribd.com/document/254031261 (Engineering ToolBox table: glass on metal)"
_RESTITUTION = "phunland.com/wiki/Restitution (after The Physics Factbook)"
_KINETIC_RATIO = "dynamic = 0.75 x static (no kinetic figure listed; the listed pairs span 0.5-0.85)"

CONTACT: dict[str, Contact] = {
    "wood": Contact(0.5, 0.3, 0.6, f"friction: wood on wood, {_FRICTION_HOWWHY}; restitution: wooden ball,"
                    f" {_RESTITUTION}"),
    "painted": Contact(0.5, 0.3, 0.6, f"painted wood/MDF panels taken as wood: wood on wood, {_FRICTION_HOWWHY};"
                       f" restitution: wooden ball, {_RESTITUTION}"),
    "brushed_metal": Contact(0.6, 0.3, 0.6, f"friction: steel on steel (dry), {_FRICTION_HOWWHY}; restitution:"
                             f" steel ball bearing, {_RESTITUTION}"),
    "chrome": Contact(0.6, 0.3, 0.6, f"chrome-plated steel taken as steel: steel on steel (dry), {_FRICTION_HOWWHY};"
                      f" restitution: steel ball bearing, {_RESTITUTION}"),
    "cast_iron": Contact(0.6, 0.3, 0.6, f"seasoned or enamelled cast iron taken as steel: steel on steel (dry),"
                         f" {_FRICTION_HOWWHY}; restitution: steel ball bearing, {_RESTITUTION}"),
    "plastic": Contact(0.6, 0.45, 0.69, f"friction: ABS static 0.60-0.75 (lower bound), {_FRICTION_PLASTICS};"
                       f" {_KINETIC_RATIO}; restitution: hollow hard plastic ball, {_RESTITUTION}"),
    "glass": Contact(0.6, 0.25, 0.66, f"friction: glass on metal 0.5-0.7 / 0.2-0.3 (mid-range), {_FRICTION_GLASS};"
                     f" restitution: glass marble, {_RESTITUTION}"),
    "ceramic": Contact(0.6, 0.25, 0.66, f"glazed ceramic taken as glass: glass on metal, {_FRICTION_GLASS};"
                       f" restitution: glass marble, {_RESTITUTION}"),
    "screen": Contact(0.6, 0.25, 0.66, f"a display's cover glass taken as glass: glass on metal, {_FRICTION_GLASS};"
                      f" restitution: glass marble, {_RESTITUTION}"),
    "enamel": Contact(0.6, 0.25, 0.66, f"vitreous enamel (glass fused on steel) taken as glass: glass on metal,"
                      f" {_FRICTION_GLASS}; restitution: glass marble, {_RESTITUTION}"),
    "rubber": Contact(1.0, 0.7, 0.83, f"friction: rubber on dry concrete, {_FRICTION_HOWWHY}; restitution: ball of"
                      f" rubber bands, {_RESTITUTION}"),
    "cardboard": Contact(0.5, 0.375, 0.2, "friction: corrugated board on board, static 0.3-0.6 by the TAPPI T 815"
                         " inclined-plane test (mid-range); " + _KINETIC_RATIO + "; restitution: no published figure"
                         " found, 0.2 chosen (board crushes on impact)"),
    "fabric": Contact(0.3, 0.225, 0.1, f"friction: cotton on cotton, {_FRICTION_TABLE_A1}; {_KINETIC_RATIO};"
                      " restitution: no published figure found, 0.1 chosen (upholstery absorbs impacts)"),
}
"""Physics-material data per family (friction and restitution), with the source of each figure."""


NONVISUAL: dict[str, tuple[str, str]] = {
    # family -> (omni:simready:nonvisual:base, :coating), from the SimReady non-visual material table (base:
    # metals, polymers, glass, other; coating: none, paint, clearcoat, paint_clearcoat). The table has no
    # ceramic: glazed porcelain is taken as stone under a clear glaze; chrome plate as its listed "shiny metal".
    "wood": ("wood", "clearcoat"),  # lacquered or oiled furniture wood
    "painted": ("wood", "paint"),  # painted wood/MDF, as CONTACT takes it; painted sheet steel: NONVISUAL_METAL
    "brushed_metal": ("steel", "none"),
    "chrome": ("silver", "none"),
    "cast_iron": ("iron", "none"),
    "plastic": ("plastic", "none"),
    "glass": ("clear_glass", "none"),
    "ceramic": ("stone", "clearcoat"),
    "screen": ("clear_glass", "none"),  # a display's cover glass
    "enamel": ("steel", "paint"),  # vitreous enamel fused on steel
    "rubber": ("rubber", "none"),
    "fabric": ("fabric", "none"),
    "cardboard": ("cardboard", "none"),  # the table's own "cardboard" (boxes)
}
"""Non-visual (lidar, radar) material of each family, for SimReady NVM.001-003."""

NONVISUAL_METAL = 2000.0
"""kg/m^3 above which a ``painted`` slot's substrate (the category's ``substrates``) is sheet steel, not wood."""


def nonvisual(family: str, density: float | None, opacity: float) -> tuple[str, str, str]:
    """``(base, coating, attributes)`` of a look for the SimReady non-visual material tokens."""
    base, coating = NONVISUAL[family]
    if family == "painted" and density is not None and density > NONVISUAL_METAL:
        base = "steel"
    return base, coating, "visually_transparent" if opacity < 1.0 else "none"


def srgb_to_linear(c: np.ndarray | float) -> np.ndarray:
    """Apply the inverse sRGB transfer function (values in [0, 1], any shape)."""
    c = np.asarray(c, dtype=np.float64)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def _hex_to_srgb(hex_colour: str) -> tuple[float, float, float]:
    h = hex_colour.lstrip("#")
    return (int(h[0:2], 16) / 255.0, int(h[2:4], 16) / 255.0, int(h[4:6], 16) / 255.0)


def _uniform(rng: np.random.Generator, bounds: Range) -> float:
    return float(rng.uniform(bounds[0], bounds[1]))


def split_spec(spec: str) -> tuple[str, tuple[str, ...]]:
    """``"plastic:black|dark_grey"`` -> ``("plastic", ("black", "dark_grey"))``; no colon: all variants."""
    family, _, variants = spec.partition(":")
    return family, tuple(v for v in variants.split("|") if v)


def _family(family: str) -> Family:
    fam = FAMILIES.get(family)
    if fam is None:
        raise ValueError(
            f"unknown material family {family!r}; valid families: {', '.join(sorted(FAMILIES))}"
        )
    return fam


def library_look(family: str, variant: str, index: int) -> Look:
    """Look number ``index`` of palette ``variant`` of ``family``: a pure function of the three.

    Raises
    ------
    ValueError
        If the family or variant is unknown or ``index`` is not in
        ``range(LOOKS_PER_VARIANT)``.
    """
    fam = _family(family)
    colours = dict(fam.palette)
    if variant not in colours:
        raise ValueError(f"family {family!r} has no variant {variant!r}; its variants: {', '.join(colours)}")
    if isinstance(index, bool) or not isinstance(index, int | np.integer) or not 0 <= index < LOOKS_PER_VARIANT:
        raise ValueError(f"look index must be an integer in [0, {LOOKS_PER_VARIANT}), got {index!r}")
    key = zlib.crc32(f"{fam.name}/{variant}".encode())
    rng = np.random.default_rng(np.random.SeedSequence((key, int(index))))
    hue, sat, val = colorsys.rgb_to_hsv(*_hex_to_srgb(colours[variant]))
    dh, ds, dv = fam.hsv_jitter
    hue = (hue + _uniform(rng, (-dh, dh))) % 1.0
    sat = min(1.0, sat * (1.0 + _uniform(rng, (-ds, ds))))
    val = min(1.0, val * (1.0 + _uniform(rng, (-dv, dv))))
    linear = srgb_to_linear(np.array(colorsys.hsv_to_rgb(hue, sat, val)))
    return Look(
        family=fam.name,
        variant=variant,
        base_color=(float(linear[0]), float(linear[1]), float(linear[2])),
        roughness=_uniform(rng, fam.roughness),
        metallic=float(fam.metallic),
        opacity=_uniform(rng, dict(fam.variant_opacity).get(variant, fam.opacity)),
        noise_seed=int(rng.integers(0, 2**53)),
        color_variation=_uniform(rng, fam.color_variation),
        roughness_variation=_uniform(rng, fam.roughness_variation),
        bump=_uniform(rng, fam.bump),
        scale=_uniform(rng, fam.scale),
        anisotropy=_uniform(rng, fam.anisotropy),
        index=int(index),
    )


def library(family: str | None = None) -> list[Look]:
    """Every look of the library (of one family spec such as ``"plastic:black|white"``, or all)."""
    specs = [family] if family else list(FAMILIES)
    out = []
    for spec in specs:
        name, only = split_spec(spec)
        fam = _family(name)
        for variant, _ in fam.palette:
            if not only or variant in only:
                out += [library_look(name, variant, k) for k in range(LOOKS_PER_VARIANT)]
    return out


def sample_look(family: str, rng: np.random.Generator) -> Look:
    """Draw one appearance of ``family``: a palette variant, then one of its library looks.

    Parameters
    ----------
    family : str
        A key of :data:`FAMILIES`, optionally restricted to some palette variants:
        ``"plastic:black|dark_grey"`` draws only those colours.
    rng : numpy.random.Generator
        Source of the draws (variant, look index, then the wear).

    Returns
    -------
    Look
        The look, :func:`library_look` of the drawn variant and index, with the
        :class:`Wear` of this object (:func:`sample_wear`, drawn next from ``rng``).

    Raises
    ------
    ValueError
        If ``family`` is not a known family or none of its variants is allowed.
    TypeError
        If ``rng`` is not a :class:`numpy.random.Generator`.
    """
    family, only = split_spec(family)
    fam = _family(family)
    if not isinstance(rng, np.random.Generator):
        raise TypeError(f"rng must be a numpy.random.Generator, got {type(rng).__name__}")
    palette = [entry for entry in fam.palette if not only or entry[0] in only]
    if not palette:
        names = ", ".join(name for name, _ in fam.palette)
        raise ValueError(f"family {family!r} has no variant among {only}; its variants: {names}")
    variant = palette[int(rng.integers(len(palette)))][0]
    look = library_look(family, variant, int(rng.integers(LOOKS_PER_VARIANT)))
    return replace(look, wear=sample_wear(look, rng))


def sample_wear(look: Look, rng: np.random.Generator) -> Wear:
    """Draw how one object wears ``look`` (:class:`Wear`): 5 draws from ``rng``.

    The tint is half the family's palette jitter (so a worn look stays within its
    family's colours), the roughness scale 0.85-1.15 (kept so the roughest texel stays
    below 1), the UV offset anywhere in the repeat, and the rotation follows the grain:
    half turns for wood and brushed metal, quarter turns for weaves, any angle otherwise.
    """
    fam = _family(look.family)
    dh, ds, dv = (0.5 * x for x in fam.hsv_jitter)
    base = np.asarray(look.base_color, dtype=np.float64)
    srgb = np.where(base <= 0.0031308, 12.92 * base, 1.055 * np.maximum(base, 0.0) ** (1 / 2.4) - 0.055)
    hue, sat, val = colorsys.rgb_to_hsv(*np.clip(srgb, 0.0, 1.0))
    hue = (hue + _uniform(rng, (-dh, dh))) % 1.0
    sat = min(1.0, sat * (1.0 + _uniform(rng, (-ds, ds))))
    val = min(1.0, val * (1.0 + _uniform(rng, (-dv, dv))))
    tinted = srgb_to_linear(np.array(colorsys.hsv_to_rgb(hue, sat, val)))
    tint = np.clip(tinted / np.maximum(base, 1e-4), 0.5, 2.0)
    tint = np.where(base > 1e-4, tint, 1.0)
    top = min(1.15, 0.98 / max(look.roughness + 2.5 * look.roughness_variation, 1e-3))
    rough = _uniform(rng, (min(0.85, top), top))
    offset = (float(rng.random()), float(rng.random()))
    turn = float(rng.random())
    if fam.style in ("wood", "brushed", "corrugated"):  # the grain or the flutes stay along the part
        rotation = 180.0 * math.floor(2 * turn)
    elif fam.style == "woven":
        rotation = 90.0 * math.floor(4 * turn)
    else:
        rotation = 360.0 * turn
    return Wear(tint=tuple(round(float(t), 6) for t in tint), roughness_scale=round(rough, 6),
                uv_offset=tuple(round(o, 6) for o in offset), uv_rotation=round(rotation, 4))
