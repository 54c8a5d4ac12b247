"""Scene kinds: one module per kind of room (a kitchen, a bathroom ...), each declaring
``KIND = SceneKind(...)``: its parameters, its growth grammar and its layout (see
:mod:`infmob_usd.scenes`). Registration is discovery, as for categories."""

from __future__ import annotations

import importlib
import pkgutil


def _discover() -> dict:
    found = {}
    for info in sorted(pkgutil.iter_modules(__path__), key=lambda i: i.name):
        if info.name.startswith("_"):
            continue
        found[info.name] = importlib.import_module(f"{__name__}.{info.name}").KIND
    return found


KINDS = _discover()
