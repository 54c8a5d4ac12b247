"""Reusable parametric parts: each returns an :class:`~infmob_usd.assembly.Assembly` in its own local frame."""

from . import vessel  # noqa: F401  vessel walls, closures, cookware lids and handles
