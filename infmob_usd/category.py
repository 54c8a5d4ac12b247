"""The category contract: what one module in ``categories/`` hands the core.

A category is a :class:`Category`: its id, a one-line description, its own
parameter schema, its growth :class:`~infmob_usd.grammar.Grammar`, its material
slots as data (slot -> material family, the name of a parameter whose value
is the family, or a ``(parameter, {value: family})`` pair: the core resolves
it), and its :class:`~infmob_usd.grammar.Layout`
(one method per node kind). The module exposes it as ``CATEGORY``; the registry
in ``infmob_usd.categories`` finds every module that does (no list to edit).

The schema a user sees is the category's own parameters followed by those the
grammar owns (object-wide choices and ``has_<branch>`` flags).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType, ModuleType

import numpy as np

from . import lift_off
from .blueprint import Blueprint
from .errors import ModelError
from .grammar import Grammar, Layout
from .params import Schema


@dataclass(frozen=True)
class Same:
    """A material slot that looks like another: ``{"tray_front": Same("body")}`` resolves to whatever
    family ``body`` resolves to (a part finished to match the casing)."""

    slot: str


@dataclass(frozen=True, eq=False)
class Category:
    """One category: id, schema, grammar, materials and layout."""

    id: str
    doc: str
    params: tuple
    grammar: Grammar
    layout: type[Layout]
    materials: Mapping[str, str | Same | tuple[str, Mapping[str, str]]] = field(default_factory=dict)
    substrates: Mapping[str, float | tuple[str, Mapping[str, float]]] = field(default_factory=dict)
    """Slot -> kg/m^3 of what the slot is made of where that is not its family's usual material (its look
    stays the family's): a number, or ``(parameter, {value: kg/m^3})`` for the values that change it (a
    ``"painted"`` casing finish is painted steel, 7850, not the board the painted family weighs)."""
    derive: Callable[[dict], dict] | None = None
    """Parameters that follow from others, applied after sampling and overrides, before growing
    (e.g. a table that would grow no moving part gets its extension)."""
    palette: Callable[[str], str] | None = None
    """Restricts every resolved family spec to the finishes such products are sold in
    (``materials.palettes.appliance``); ``None``: families as they are."""

    def __post_init__(self) -> None:
        if not self.id.isidentifier() or self.id != self.id.lower():
            raise ModelError(f"category id {self.id!r} must be a lower-case identifier")
        object.__setattr__(self, "materials", MappingProxyType(dict(self.materials)))
        object.__setattr__(self, "schema", Schema((*self.params, *self.grammar.params())))
        object.__setattr__(self, "substrates", MappingProxyType(dict(self.substrates)))
        for slot, v in (*self.materials.items(), *self.substrates.items()):
            if isinstance(v, tuple) and (len(v) != 2 or v[0] not in self.schema.names):
                raise ModelError(f"category {self.id}: material slot {slot!r} must name a parameter and a"
                                 f" value table, got {v!r}")
        for slot, v in self.materials.items():
            if isinstance(v, Same) and not isinstance(self.materials.get(v.slot, Same("")), str | tuple):
                raise ModelError(f"category {self.id}: material slot {slot!r} is the same as {v.slot!r},"
                                 " which must be a slot with its own family (not missing, not another alias)")
        for kind in self.grammar.nodes:
            if not callable(getattr(self.layout, kind, None)):
                raise ModelError(f"category {self.id}: layout {self.layout.__name__} has no method for"
                                 f" grammar node {kind!r}")

    schema: Schema = field(init=False)

    def rules(self) -> str:
        """The growth rules as text (what ``infmob params`` prints)."""
        return self.grammar.table()

    def resolve_materials(self, params: dict) -> dict[str, str]:
        """Slot -> family spec.

        A slot's value is a family spec (``"wood"``, ``"plastic:black|dark_grey"``), the name of a
        parameter (or of a value ``derive`` adds) whose value is the family, or
        ``(parameter, {value: family})`` where some values of the parameter name a family spec other
        than themselves (a ``"plastic"`` finish that
        means black plastic), or :class:`Same` as another slot. An ``"auto"`` choice counts as the
        alternative it resolves to.
        """
        params = self.grammar.resolve(params)
        out = {}
        for slot, v in self.materials.items():
            if isinstance(v, Same):
                continue
            if isinstance(v, tuple):
                name, table = v
                out[slot] = table.get(params[name], params[name])
            else:
                out[slot] = params[v] if v in params else v
        out = {slot: out[v.slot] if isinstance(v, Same) else out[slot] for slot, v in self.materials.items()}
        return {k: self.palette(v) for k, v in out.items()} if self.palette else out

    def resolve_substrates(self, params: dict) -> dict[str, float]:
        """Slot -> kg/m^3 of the slots whose substrate :attr:`substrates` names for these parameters."""
        out = {}
        for slot, v in self.substrates.items():
            if isinstance(v, tuple):
                value = params[v[0]]
                if value in v[1]:
                    out[slot] = float(v[1][value])
            else:
                out[slot] = float(v)
        return out

    def build(self, params: dict, structure: np.random.Generator, geometry: np.random.Generator) -> Blueprint:
        """Grow the tree from the structure stream and build it into a blueprint at rest.

        ``derive`` and then the grammar's ``"auto"`` choices (:meth:`Grammar.resolve`) update ``params``
        first: the layout, the materials and the recorded parameters see what was built.
        """
        if self.derive is not None:
            params.update(self.derive(dict(params)))
        params.update(self.grammar.resolve(params))
        tree = self.grammar.grow(params, structure)
        bp = Blueprint(self.id, materials=self.resolve_materials(params), densities=self.resolve_substrates(params))
        layout = self.layout(bp, params, geometry, self.grammar)
        layout.run(tree)
        return lift_off.capped(bp)  # a lift-off travel is a hand's lift (the core's rule)


def of_module(category_id: str, module: ModuleType) -> Category:
    """The category a module declares as ``CATEGORY``."""
    found = getattr(module, "CATEGORY", None)
    if not isinstance(found, Category) or found.id != category_id:
        raise ModelError(f"module {module.__name__}: CATEGORY must be a Category with id {category_id!r}")
    return found
