"""Motion Panel's stages as Bluesky devices (ophyd-async): `Stage(port, protocol, name=...)`.
Needs the `lab` extra (`pip install motion-panel[lab]`: bluesky, ophyd-async)."""

from __future__ import annotations

from drivers.bluesky.stage import Stage, StageAxis

__all__ = ["Stage", "StageAxis"]
