"""infmob-usd: procedural, simulation-ready articulated objects as OpenUSD and URDF.

>>> import infmob_usd
>>> obj = infmob_usd.generate("kitchen_cabinet", seed=3)
>>> folder = infmob_usd.save(obj, "out")        # out/kitchen_cabinet_000003/
"""

from ._version import __version__
from .api import generate, get_category, list_categories, save
from .errors import (
    ArgumentTypeError,
    GeometryError,
    InfmobError,
    ModelError,
    OutputError,
    ParameterError,
    UnknownCategoryError,
)
from .model import ArticulatedObject

__all__ = [
    "ArgumentTypeError",
    "ArticulatedObject",
    "GeometryError",
    "InfmobError",
    "ModelError",
    "OutputError",
    "ParameterError",
    "UnknownCategoryError",
    "__version__",
    "generate",
    "get_category",
    "list_categories",
    "save",
]
