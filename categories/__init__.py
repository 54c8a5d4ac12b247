"""The categories: one module per category, each describing what that object is.

Every module defines ``SCHEMA`` (its parameters, including the ``has_<branch>``
flags of its growth rules), ``GROWTH`` (its growth rules as data) and
``build(p, structure, geometry) -> Blueprint`` which places parts, names their
material slots (slot -> family in ``Blueprint.materials``) and declares joints in
world coordinates at rest.
"""

from __future__ import annotations

from types import ModuleType

from . import (
    bar_chair,
    beverage_fridge,
    bottle,
    cocktail_table,
    dining_table,
    dishwasher,
    door,
    jar,
    kitchen_cabinet,
    lamp,
    microwave,
    office_chair,
    oven,
    pan,
    plate_rack,
    pot,
    storage_rack,
    tap,
    toilet,
    tv,
    vase,
    window,
)

CATEGORIES: dict[str, ModuleType] = {
    "kitchen_cabinet": kitchen_cabinet,
    "microwave": microwave,
    "lamp": lamp,
    "beverage_fridge": beverage_fridge,
    "dishwasher": dishwasher,
    "oven": oven,
    "tv": tv,
    "tap": tap,
    "toilet": toilet,
    "door": door,
    "window": window,
    "storage_rack": storage_rack,
    "cocktail_table": cocktail_table,
    "dining_table": dining_table,
    "plate_rack": plate_rack,
    "pot": pot,
    "pan": pan,
    "office_chair": office_chair,
    "bar_chair": bar_chair,
    "vase": vase,
    "bottle": bottle,
    "jar": jar,
}
