"""The categories: one module per category, each describing what that object is.

Every module defines ``SCHEMA`` (its parameters), ``GROWTH`` (its growth rules),
``MATERIALS`` (material slot -> family, or the name of the parameter that picks it)
and ``build(p, structure, geometry) -> Blueprint`` which places parts and
declares joints in world coordinates at rest.
"""

from __future__ import annotations

from types import ModuleType

from . import kitchen_cabinet

CATEGORIES: dict[str, ModuleType] = {
    "kitchen_cabinet": kitchen_cabinet,
}
