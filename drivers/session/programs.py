"""A session's programs: run one to its end, pause it, stop it early (from any thread)."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from contextlib import AbstractContextManager
from typing import TYPE_CHECKING

from drivers.device.client import Client
from drivers.device.motion import Motion
from drivers.protocols import commands as cmd
from drivers.protocols.capabilities import Capabilities
from drivers.toolpath.loader import from_points
from drivers.toolpath.model import CHORD_TOLERANCE, Toolpath
from drivers.toolpath.point_program import ProgramPoint
from drivers.toolpath.streaming import StreamProgress

if TYPE_CHECKING:
    from drivers.toolpath.runner import ProgramRunner

__all__ = ["ProgressListener", "SessionPrograms"]

ProgressListener = Callable[[StreamProgress], None]
"""Told how far a program has got (a StreamProgress) after each frame or move."""


class SessionPrograms:
    """The session's program runs, one at a time, inside its operation guard."""

    motion: Motion
    client: Client
    _runner: ProgramRunner | None

    @property
    def capabilities(self) -> Capabilities:
        """What the device can do (the session's)."""
        raise NotImplementedError

    def _operation(self) -> AbstractContextManager[None]:
        raise NotImplementedError

    def run_program(
        self,
        program: Toolpath | Iterable[ProgramPoint],
        progress: ProgressListener | None = None,
        group: int | None = None,
        *,
        tolerance: float = CHORD_TOLERANCE,
    ) -> StreamProgress:
        """Run a program and wait until the device has run it: a Toolpath (drivers.toolpath,
        `load_toolpath` reads G-code, DXF, SVG, CSV and JSON) or points. `progress` is told how
        far it got (its `source` names the line under way); arcs are cut into chords within
        `tolerance` mm where the device has no arcs of its own. A program that would leave the
        travel box, or asks a speed the device does not allow, is refused whole before
        anything is sent; `stop` ends it early. Laser-frame streams it to its queue (`group`
        instructions a frame at most), pi-frame gets arcs as arcs, other devices move by move."""
        from drivers.toolpath.runner import ProgramRunner  # numpy: only when a program runs

        toolpath = program if isinstance(program, Toolpath) else from_points(list(program))
        runner = ProgramRunner(
            self.motion, toolpath, tolerance=tolerance, progress=progress, group=group
        )
        with self._operation():
            self._runner = runner
            try:
                state = runner.run()
            finally:
                self._runner = None
            if runner.stopped and self.capabilities.stop:
                self.client.execute(cmd.Stop())  # flushes what the device has queued
            self.motion.position()
        return state

    def pause_program(self, paused: bool = True) -> None:
        """Send nothing more of the program under way until resumed (`paused` False); a
        queue on the device goes on with what it has. Any thread; nothing happens without one."""
        runner = self._runner
        if runner is not None:
            if paused:
                runner.pause()
            else:
                runner.resume()

    def stop_program(self) -> bool:
        """End the program under way early (any thread): `run_program` then stops the device
        where it has a stop (flushing its queue); whether a program was under way."""
        runner = self._runner
        if runner is None:
            return False
        runner.stop()
        return True
