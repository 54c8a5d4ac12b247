"""Material families and tileable PBR texture synthesis.

Material families are data (:data:`FAMILIES`); :func:`sample_look` draws one
appearance (:class:`Look`) from a family with an explicit
:class:`numpy.random.Generator`; :func:`synthesize` turns a look into seamlessly
tiling basecolor / roughness / metallic / normal maps (one UV unit = one
repeat), and :func:`encode_png` writes them as deterministic PNG bytes.
"""

from .families import FAMILIES, Family, Look, sample_look, split_spec
from .synth import TEXTURE_MAPS, encode_png, synthesize

__all__ = [
    "FAMILIES", "TEXTURE_MAPS", "Family", "Look", "encode_png", "sample_look", "split_spec", "synthesize",
]
