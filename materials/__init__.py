"""Material families and tileable PBR texture synthesis.

Material families are data (:data:`FAMILIES`); :func:`sample_look` draws one
appearance (:class:`Look`) from a family with an explicit
:class:`numpy.random.Generator`; :func:`synthesize` turns a look into seamlessly
tiling basecolor / roughness / metallic / normal maps (one UV unit = one
repeat), and :func:`encode_png` writes them as deterministic PNG bytes.
Looks come from a finite library (:func:`library_look`), so
:func:`texture_maps` serves each look's PNG bytes from a memory and disk cache
(:mod:`infmob_usd.materials.cache`); each object wears its looks differently
(:class:`Wear`: tint, roughness scale, UV offset and rotation as shader inputs).
Palettes of real products (:mod:`infmob_usd.materials.palettes`) restrict the
colours a kind of object is drawn in.
"""

from .cache import texture_maps
from .families import FAMILIES, LOOKS_PER_VARIANT, Family, Look, Wear, library, library_look, sample_look, split_spec
from .palettes import APPLIANCE, BULB_GLASS, appliance
from .synth import TEXTURE_MAPS, encode_png, synthesize

__all__ = [
    "APPLIANCE", "BULB_GLASS", "FAMILIES", "LOOKS_PER_VARIANT", "TEXTURE_MAPS", "Family", "Look", "Wear",
    "appliance", "encode_png", "library", "library_look", "sample_look", "split_spec", "synthesize", "texture_maps",
]
