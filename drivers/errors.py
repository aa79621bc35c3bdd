"""The driver layer's error hierarchy; every failure it raises is one of these."""

from __future__ import annotations


class MotionError(Exception):
    """Base class of every error the driver layer raises."""


class BadInput(MotionError, ValueError):
    """A command or value the device would reject; refused before anything is sent."""


class BadFile(BadInput):
    """A file from others (a profile, a program, a log, the settings) refused whole: missing, not
    a regular file, too large, not text, or malformed; says which file, the line where it can,
    and why. Each reader has its own subclass (drivers/files.py reads them all)."""


class DeviceError(MotionError):
    """The device answered, and its answer reports an error."""


class CommunicationError(MotionError):
    """The link failed: no answer, an unreadable answer, or a port that is gone."""


class DeviceTimeout(CommunicationError, TimeoutError):
    """The device did not answer (or did not finish) in time."""


class PortError(CommunicationError):
    """The port cannot be opened, or failed while in use."""


class DeviceRestarted(CommunicationError):
    """The device restarted (its boot banner came again): what it held in RAM is lost."""


class GarbledReply(CommunicationError):
    """The device answered something the protocol cannot make sense of."""


class FrameError(MotionError):
    """A frame could not be built or taken apart (raised by framers and decoders)."""


class UnknownProtocol(MotionError, LookupError):
    """No protocol is registered under that name."""


class Aborted(MotionError):
    """The wait was abandoned because the owner is closing or cancelled it."""


class Retransmit(CommunicationError):
    """The reply says the frame was damaged on the way: send the kept copy again."""


class QueueFull(DeviceError):
    """The device's queue has no room now: wait and send again (back-pressure, not a loss)."""


class NoControlLines(MotionError):
    """The port has no modem control lines (a pseudo-terminal, a TCP socket): DTR and RTS cannot
    be set, the inputs cannot be read, no break can be sent."""


class PortBusy(PortError):
    """Another program holds the port open (an exclusive lock, or Windows' sharing rule)."""
