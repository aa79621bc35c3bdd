"""Telling the auto-repeat of a held key from a real release and press, by their times."""

from __future__ import annotations

PAIR_MS = 1  # a press this close to its key's release is the second half of an auto-repeat


class KeyReleases:
    """The time of each key's last release, to tell whether a press pairs with it.

    X11 repeats a held key as a release and a press with the same server time. Qt's xcb plugin
    flags the pair as an auto-repeat only if the press is already read when it handles the
    release; on a loaded machine it often is not, and the pair comes as a real release and a
    real press. No one releases and presses a key again within a millisecond.
    """

    def __init__(self) -> None:
        self._at: dict[int, int] = {}

    def released(self, key: int, timestamp: int) -> None:
        """`key` was released at `timestamp` (the key event's, in ms; 0: unknown)."""
        if timestamp:
            self._at[key] = timestamp

    def pairs(self, key: int, timestamp: int) -> bool:
        """Whether a press of `key` at `timestamp` (ms; 0: unknown) came at its last release's
        time: the press of an auto-repeat pair, the key still down."""
        released = self._at.get(key)
        if not timestamp or released is None:
            return False
        return abs(timestamp - released) <= PAIR_MS
