"""A registry of named entries: the one vocabulary of every registry in the toolkit.

Force models (:data:`mkm.fem.ladder.MODELS`), surrogate kinds (:data:`mkm.surrogate.kinds.KINDS`)
and bench backends (:data:`mkm.bench.backends.BACKENDS`) are each a :class:`Registry`: entries
are added with :meth:`~Registry.register`, removed with :meth:`~Registry.unregister`, found with
:meth:`~Registry.entry` and listed with :meth:`~Registry.names`; an unknown or taken name is a
one-line ``ValueError`` naming the choices. Every choice list elsewhere is derived from a
registry, so an entry registered once is seen everywhere.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Generic, Protocol, TypeVar


class Named(Protocol):
    name: str


E = TypeVar("E", bound=Named)


class Registry(Generic[E]):
    """Entries by name, in registration order.

    Parameters
    ----------
    what : str
        What an entry is, for messages (``"model"``, ``"surrogate kind"``, ``"backend"``).
    hint : str
        Said after the choices in an unknown-name message (``"see `mkm models`"``).
    shown : callable, optional
        How a choice is shown in that message (default: its name).
    """

    def __init__(self, what: str, hint: str = "", shown: Callable[[E], str] | None = None):
        self.what = what
        self.hint = hint
        self._shown = shown or (lambda e: e.name)
        self._entries: dict[str, E] = {}

    def register(self, entry: E) -> E:
        """Add ``entry``; ``ValueError`` if its name is taken."""
        if entry.name in self._entries:
            raise ValueError(f"{self.what} {entry.name!r} is already registered: expected a "
                             "new name")
        self._entries[entry.name] = entry
        return entry

    def unregister(self, name: str) -> None:
        """Remove the entry ``name``; ``ValueError`` (as :meth:`entry`) if there is none."""
        self.entry(name)
        del self._entries[name]

    def entry(self, name: str) -> E:
        """The entry ``name``; a one-line ``ValueError`` naming the choices otherwise."""
        try:
            return self._entries[name]
        except (KeyError, TypeError):
            shown = repr(name) if len(repr(name)) <= 42 else repr(name)[:40] + "..."
            hint = f" ({self.hint})" if self.hint else ""
            choices = ", ".join(self._shown(e) for e in self._entries.values())
            raise ValueError(f"unknown {self.what} {shown}: expected one of {choices}{hint}") \
                from None

    def names(self, where: Callable[[E], bool] | None = None) -> tuple[str, ...]:
        """Every name, in registration order (``where``: those whose entry passes)."""
        return tuple(n for n, e in self._entries.items() if where is None or where(e))

    def entries(self) -> tuple[E, ...]:
        """Every entry, in registration order."""
        return tuple(self._entries.values())

    def __contains__(self, name: object) -> bool:
        return name in self._entries

    def __iter__(self) -> Iterator[str]:
        return iter(tuple(self._entries))

    def __len__(self) -> int:
        return len(self._entries)
