"""The juncture exception family.

Every error juncture raises on bad input is a :class:`JunctureError`. Subclasses carry the
fields a user needs to find the fault (file, line and columns of a deck; component and station
of a geometry), and build their message from them, so the CLI can print one line and exit 2.
"""

from __future__ import annotations

__all__ = [
    "JunctureError",
    "DeckError",
    "GeometryError",
    "ConvergenceError",
    "SpecError",
    "OptionError",
    "MissingDependencyError",
    "JunctureWarning",
]


class JunctureError(Exception):
    """Base class of every error juncture raises on bad input or impossible geometry."""


class DeckError(JunctureError):
    """An input file that cannot be read: names the file, line and columns, and what was expected.

    Parameters
    ----------
    message : str
        What was expected and what was found, e.g. ``"expected a number, found 'l2.5'"``.
    path : str, optional
        The file (``None`` for text given in memory).
    line : int, optional
        1-based line number.
    columns : tuple of int, optional
        1-based first and last column of the offending field.
    """

    def __init__(self, message, path=None, line=None, columns=None):
        self.path = None if path is None else str(path)
        self.line = line
        self.columns = None if columns is None else tuple(columns)
        self.reason = message
        super().__init__(self._compose())

    @property
    def column(self):
        """First column of the offending field (1-based), or ``None``."""
        return None if self.columns is None else self.columns[0]

    def _compose(self):
        where = []
        if self.path is not None:
            where.append(self.path)
        if self.line is not None:
            where.append(f"line {self.line}")
        if self.columns is not None:
            a, b = self.columns
            where.append(f"column {a}" if a == b else f"columns {a}-{b}")
        return (", ".join(where) + ": " if where else "") + self.reason


class GeometryError(JunctureError):
    """Geometry that cannot be built or evaluated: names the component and the station.

    Parameters
    ----------
    message : str
        What is wrong, e.g. ``"radius is negative (-0.2)"``.
    component : str, optional
        Component name, e.g. ``"fuselage"``, ``"fin 1"``.
    station : int or str, optional
        1-based station or section index, or a description such as ``"x = 120.5"``.
    """

    def __init__(self, message, component=None, station=None):
        self.component = component
        self.station = station
        self.reason = message
        where = []
        if component is not None:
            where.append(str(component))
        if station is not None:
            where.append(f"station {station}")
        super().__init__((", ".join(where) + ": " if where else "") + message)


class ConvergenceError(GeometryError):
    """An iteration (root finder, area compensation) did not converge."""


class SpecError(JunctureError):
    """A JSON/TOML specification with a missing, unknown or ill-typed field (names the field)."""


class OptionError(JunctureError):
    """An option outside its allowed values: names the option, the value and what is allowed.

    Parameters
    ----------
    option : str
        The option's name in the Python API, e.g. ``"theta_u_deg"``.
    value : object
        The value given.
    expected : str
        What is allowed, e.g. ``"an angle in (0, 90) deg"``.
    """

    def __init__(self, option, value, expected):
        self.option = option
        self.value = value
        self.expected = expected
        super().__init__(f"{option} = {value!r}: expected {expected}")


class MissingDependencyError(JunctureError):
    """An optional extra is needed for this operation (names the extra to install)."""


class JunctureWarning(UserWarning):
    """Something juncture accepted but a user should know (a range outside documented limits)."""
