"""The categories: one module per category, each describing what that object is.

Every module in this package (``parts`` aside) is a category named after the
module: it declares ``CATEGORY = Category(...)`` (see ``infmob_usd.category`` and
``docs/ADDING_A_CATEGORY.md``). Registration is discovery: adding a module adds a
category.
"""

from __future__ import annotations

import importlib
import pkgutil

from infmob_usd.category import of_module

NOT_CATEGORIES = frozenset({"parts", "rooms"})


def _discover() -> dict:
    found = {}
    for info in sorted(pkgutil.iter_modules(__path__), key=lambda i: i.name):
        if info.name.startswith("_") or info.name in NOT_CATEGORIES:
            continue
        module = importlib.import_module(f"{__name__}.{info.name}")
        found[info.name] = of_module(info.name, module)
    return found


CATEGORIES = _discover()
"""Category id -> its :class:`~infmob_usd.category.Category`, sorted by id."""
