"""Framers: pure byte-stream splitters, one per wire format, with no I/O."""

from drivers.framers.base import Framer

__all__ = ["Framer"]
