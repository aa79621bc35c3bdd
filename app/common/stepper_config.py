"""Setting up a Firmata board's stepper through its session (the window and motionctl alike)."""

from __future__ import annotations

from drivers.protocols.firmata import StepperConfig, StepperVersion
from drivers.session.device_session import DeviceSession


def configure_stepper(session: DeviceSession, steps_per_rev: int, pins: tuple[int, ...]) -> int:
    """Configure the motor, then ask the library version (the board answers it once the config
    is taken; a wrong config's error comes before, failing it); the settings keep the config."""
    session.send(StepperConfig(steps_per_rev, pins))
    version = stepper_version(session)
    saved = {f"pin{i}": float(pins[i - 1]) if i <= len(pins) else -1.0 for i in range(1, 5)}
    session.configure({"steps_per_rev": steps_per_rev, **saved})
    return version


def stepper_version(session: DeviceSession) -> int:
    """The board's stepper library version, as it answers."""
    reply = session.send(StepperVersion())
    return int(str(reply.value if reply is not None else None))
