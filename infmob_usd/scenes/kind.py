"""A scene kind: its parameters, its growth grammar and its layout (one per module in ``categories/rooms/``)."""

from __future__ import annotations

from dataclasses import dataclass

from ..grammar import Grammar
from ..params import Schema


@dataclass(frozen=True)
class SceneKind:
    name: str
    doc: str
    params: tuple
    grammar: Grammar
    layout: type

    @property
    def schema(self) -> Schema:
        return Schema(tuple(self.params) + tuple(self.grammar.params()))
