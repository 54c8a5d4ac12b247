"""infmob-usd: procedural, simulation-ready articulated objects as OpenUSD and URDF.

>>> import infmob_usd
>>> obj = infmob_usd.generate("kitchen_cabinet", seed=3)
>>> folder = infmob_usd.save(obj, "out")        # out/kitchen_cabinet_000003/
>>> room = infmob_usd.save_scene(infmob_usd.scene("kitchen", seed=3), "out")  # out/kitchen_000003/scene.usda
>>> infmob_usd.export("partnet-mobility", "out", "dataset", split="train=0.8,val=0.1,test=0.1")  # docs/export.md
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
from .export import ExportError, export  # the function; its modules stay importable as infmob_usd.export.*
from .model import ArticulatedObject
from .scenes import load_sapien as _load_sapien_scene
from .scenes import save_scene
from .scenes import scene as scene

scene.load_sapien = _load_sapien_scene  # infmob_usd.scene(kind, seed) makes one; .load_sapien(folder) loads it

__all__ = [
    "ArgumentTypeError",
    "ArticulatedObject",
    "ExportError",
    "GeometryError",
    "InfmobError",
    "ModelError",
    "OutputError",
    "ParameterError",
    "UnknownCategoryError",
    "__version__",
    "export",
    "generate",
    "get_category",
    "list_categories",
    "save",
    "save_scene",
    "scene",
]
