"""Exceptions that teach: every message names the problem and the fix."""

from __future__ import annotations


class InfmobError(Exception):
    """Base class of every error infmob-usd raises on purpose."""


class UnknownCategoryError(InfmobError, KeyError):
    """A category id that is not registered."""

    def __str__(self) -> str:  # KeyError would quote the message
        return str(self.args[0])


class ParameterError(InfmobError, ValueError):
    """An override with an unknown name, a wrong type or a value out of range."""


class ArgumentTypeError(ParameterError, TypeError):
    """An argument of the Python API of the wrong type (a ``ParameterError`` and a ``TypeError``)."""


class OutputError(InfmobError, OSError):
    """An output folder that cannot be written."""


class GeometryError(InfmobError, ValueError):
    """A mesh or piece that is malformed (NaN, empty, degenerate)."""


class ModelError(InfmobError, ValueError):
    """A blueprint whose parts or joints do not form a valid articulation tree."""
