"""Material families and tileable PBR texture synthesis.

Material families are data (:data:`FAMILIES`); :func:`sample_look` draws one
appearance (:class:`Look`) from a family with an explicit
:class:`numpy.random.Generator`; :func:`synthesize` turns a look into seamlessly
tiling basecolor / roughness / metallic / normal maps (one UV unit = one
repeat), and :func:`encode_png` writes them as deterministic PNG bytes.
Looks come from a finite library (:func:`library_look`), so
:func:`texture_maps` serves each look's PNG bytes from a memory and disk cache
(:mod:`infmob_usd.materials.cache`).
"""

from .cache import texture_maps
from .families import FAMILIES, LOOKS_PER_VARIANT, Family, Look, library, library_look, sample_look, split_spec
from .synth import TEXTURE_MAPS, encode_png, synthesize

__all__ = [
    "FAMILIES", "LOOKS_PER_VARIANT", "TEXTURE_MAPS", "Family", "Look", "encode_png", "library", "library_look",
    "sample_look", "split_spec", "synthesize", "texture_maps",
]
