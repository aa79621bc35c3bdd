"""A lost port's path, watched for its return (a USB adapter plugged in again, a
`motionsim --link` started again), so that the worker connects again as before."""

from __future__ import annotations

import os
from dataclasses import dataclass, replace

from app.window.device.connect_options import ConnectOptions

PORT_WATCH_S = 0.5  # s between looks for a lost port's path coming back
PORT_RETRY_S = 5.0  # s after which a lost port's path that never went away is tried again


def device_node(path: str) -> tuple[int, int] | None:
    """(device number, inode) of the file `path` names, a symlink followed; None if missing."""
    try:
        info = os.stat(path)
    except OSError:
        return None
    return info.st_rdev, info.st_ino


def watchable(url: str) -> bool:
    """Whether a lost port is watched for its return: a file path (a device, a link to one),
    not a pyserial URL, nor a pseudo-terminal's own /dev/pts/N, whose number the system gives
    the next pty opened by any program (`motionsim --link` gives a pty a name that lasts)."""
    return "://" not in url and not url.startswith("/dev/pts/")


@dataclass
class PortWatch:
    """One lost port: where it was, how it was opened, and what was seen of it since."""

    url: str
    protocol: str
    baud: int
    options: ConnectOptions
    node: tuple[int, int] | None  # the device file when the port was lost (None: gone)
    gone: bool = False  # the path was seen missing since
    next_look: float = 0.0
    retry_at: float = 0.0  # the same device file is tried again from then on

    @classmethod
    def lost(
        cls, url: str, protocol: str, baud: int, options: ConnectOptions, now: float
    ) -> PortWatch:
        """The watch of a port lost at `now` (its position is not known any more)."""
        after = replace(options, position=None, after_loss=True)
        return cls(
            url, protocol, baud, after, device_node(url),
            next_look=now + PORT_WATCH_S, retry_at=now + PORT_RETRY_S,
        )  # fmt: skip

    def back(self, now: float) -> bool:
        """Look (every PORT_WATCH_S): whether the path is back, to be opened again — it went
        away and came again, names another device file, or PORT_RETRY_S passed."""
        if now < self.next_look:
            return False
        self.next_look = now + PORT_WATCH_S
        node = device_node(self.url)
        if node is None:
            self.gone = True
            return False
        if not (self.gone or node != self.node or now >= self.retry_at):
            return False
        self.gone, self.node, self.retry_at = False, node, now + PORT_RETRY_S
        return True
