"""Declarative parameter schemas.

A category declares its parameters once, as a :class:`Schema` of :class:`Float`,
:class:`Int`, :class:`Choice` and :class:`Flag` entries. The schema samples a full
parameter set from a generator, validates user overrides (unknown names, wrong
types and out-of-range values raise :class:`~infmob_usd.errors.ParameterError`), and
prints itself for ``infmob params``.

Types are strict and the same from the API and the CLI (which passes strings): a
:class:`Float` takes a real number or its text, an :class:`Int` an integer or its text
(``2.0`` is refused, as ``"2.0"`` is), a :class:`Flag` ``True``/``False`` or the text
``true``/``false``. Bounds print exactly (``repr``-round-trippable), and a value within
``1e-9`` (relative) of a bound, e.g. one stored rounded in ``metadata.json``, is taken
as that bound.

Every parameter is always drawn, even when overridden, so that overriding one
value never reshuffles the others.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .errors import ParameterError


@dataclass(frozen=True)
class Param:
    """Base of every parameter: a name, a unit and a one-line meaning."""

    name: str
    doc: str = ""
    unit: str = ""

    def draw(self, rng: np.random.Generator) -> Any:  # pragma: no cover - abstract
        raise NotImplementedError

    def coerce(self, value: Any) -> Any:  # pragma: no cover - abstract
        raise NotImplementedError

    def describe(self) -> str:  # pragma: no cover - abstract
        raise NotImplementedError

    def _fail(self, value: Any, expected: str) -> ParameterError:
        return ParameterError(
            f"parameter {self.name!r}: got {value!r}, expected {expected}"
            f" (see `infmob params` for the schema)"
        )


def _num(x: float) -> str:
    """Shortest text of ``x`` that reads back as exactly ``x``."""
    short = f"{x:g}"
    return short if float(short) == x else repr(float(x))


@dataclass(frozen=True)
class Float(Param):
    """A real value in ``[low, high]``, drawn uniform or log-uniform."""

    low: float = 0.0
    high: float = 1.0
    dist: str = "uniform"  # "uniform" | "loguniform"

    def draw(self, rng: np.random.Generator) -> float:
        u = rng.random()
        if self.dist == "loguniform":
            return float(math.exp(math.log(self.low) + u * (math.log(self.high) - math.log(self.low))))
        return float(self.low + u * (self.high - self.low))

    def coerce(self, value: Any) -> float:
        expected = f"a number in [{_num(self.low)}, {_num(self.high)}] {self.unit}".rstrip()
        if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, str, np.integer, np.floating)):
            raise self._fail(value, expected)
        try:
            v = float(value)
        except (TypeError, ValueError):
            raise self._fail(value, expected) from None
        if not math.isfinite(v):
            raise self._fail(value, expected)
        for bound in (self.low, self.high):  # a bound printed or stored with rounding is the bound
            if abs(v - bound) <= 1e-9 * max(1.0, abs(bound)):
                v = float(bound)
        if not (self.low <= v <= self.high):
            raise self._fail(value, expected)
        return v

    def describe(self) -> str:
        tag = "logU" if self.dist == "loguniform" else "U"
        return f"{tag}({_num(self.low)}, {_num(self.high)})"


@dataclass(frozen=True)
class Int(Param):
    """An integer in ``[low, high]``.

    With ``auto=True`` the drawn value is ``None``: the category derives it from
    other parameters (for example a column count from the width) unless the user
    overrides it.
    """

    low: int = 0
    high: int = 1
    auto: bool = False

    def draw(self, rng: np.random.Generator) -> int | None:
        v = int(rng.integers(self.low, self.high + 1))
        return None if self.auto else v

    def coerce(self, value: Any) -> int:
        expected = f"an integer in [{self.low}, {self.high}]" + (" or None (auto)" if self.auto else "")
        if value is None and self.auto:  # as drawn and stored in metadata: derived by the category
            return None
        if isinstance(value, (bool, np.bool_)):
            raise self._fail(value, expected)
        if isinstance(value, str):
            try:
                value = int(value.strip())
            except ValueError:
                raise self._fail(value, expected) from None
        if not isinstance(value, (int, np.integer)) or not (self.low <= value <= self.high):
            raise self._fail(value, expected)
        return int(value)

    def describe(self) -> str:
        rng = f"{self.low}..{self.high}"
        return f"{rng} (auto)" if self.auto else rng


@dataclass(frozen=True)
class Choice(Param):
    """One of a fixed set of strings, drawn with the given weights."""

    choices: tuple[str, ...] = ()
    weights: tuple[float, ...] | None = None

    def draw(self, rng: np.random.Generator) -> str:
        w = np.asarray(self.weights if self.weights else [1.0] * len(self.choices), float)
        return self.choices[int(rng.choice(len(self.choices), p=w / w.sum()))]

    def coerce(self, value: Any) -> str:
        if not isinstance(value, str) or value not in self.choices:
            raise self._fail(value, "one of " + ", ".join(self.choices))
        return value

    def describe(self) -> str:
        if self.weights:
            total = sum(self.weights)
            return " | ".join(f"{c} ({w / total:.2f})" for c, w in zip(self.choices, self.weights))
        return " | ".join(self.choices)


_TRUE = {"true"}
_FALSE = {"false"}


@dataclass(frozen=True)
class Flag(Param):
    """A yes/no growth decision, true with probability ``p``."""

    p: float = 0.5

    def draw(self, rng: np.random.Generator) -> bool:
        return bool(rng.random() < self.p)

    def coerce(self, value: Any) -> bool:
        if isinstance(value, (bool, np.bool_)):
            return bool(value)
        if isinstance(value, str) and value.strip().lower() in _TRUE | _FALSE:
            return value.strip().lower() in _TRUE
        raise self._fail(value, "true or false")

    def describe(self) -> str:
        return f"bool, p(true)={self.p:g}"


@dataclass(frozen=True)
class Schema:
    """The ordered parameters of one category."""

    params: tuple[Param, ...] = field(default_factory=tuple)

    def __post_init__(self) -> None:
        names = [p.name for p in self.params]
        if len(set(names)) != len(names):
            raise ValueError(f"duplicate parameter names in schema: {names}")

    @property
    def names(self) -> list[str]:
        return [p.name for p in self.params]

    def __getitem__(self, name: str) -> Param:
        for p in self.params:
            if p.name == name:
                return p
        raise KeyError(name)

    def validate(self, overrides: dict[str, Any]) -> dict[str, Any]:
        """Coerce and check user overrides; raise ``ParameterError`` on the first bad one."""
        out: dict[str, Any] = {}
        for name, value in overrides.items():
            if name not in self.names:
                raise ParameterError(
                    f"unknown parameter {name!r}; valid parameters: {', '.join(self.names)}"
                )
            out[name] = self[name].coerce(value)
        return out

    def sample(self, rng: np.random.Generator, overrides: dict[str, Any] | None = None) -> dict:
        """Draw every parameter, then apply the (validated) overrides."""
        fixed = self.validate(overrides or {})
        values = {p.name: p.draw(rng) for p in self.params}
        values.update(fixed)
        return values

    def table(self) -> str:
        """A fixed-width table: name, range or choices, unit, meaning."""
        rows = [("name", "range / choices", "unit", "meaning")]
        rows += [(p.name, p.describe(), p.unit or "-", p.doc) for p in self.params]
        w = [max(len(r[i]) for r in rows) for i in range(3)]
        return "\n".join(
            f"{r[0]:<{w[0]}}  {r[1]:<{w[1]}}  {r[2]:<{w[2]}}  {r[3]}".rstrip() for r in rows
        )


def parse_assignment(text: str) -> tuple[str, str]:
    """Split a CLI ``NAME=VALUE`` into its two halves."""
    if "=" not in text:
        raise ParameterError(f"--set expects NAME=VALUE, got {text!r}")
    name, value = text.split("=", 1)
    return name.strip(), value.strip()
