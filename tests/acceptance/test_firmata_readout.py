"""Issue 19 item 9: a move the device refused never moves the readout."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from PySide6.QtGui import QImage

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import XServer, hold, wait_for

# Firmata's STRING_DATA carries each character as two 7-bit bytes
NUMBER_COLUMNS = slice(90, 260)  # the Machine column's number in the Position panel
NOT_CONFIGURED = b"".join(bytes((c, 0)) for c in b"not configured")


def test_unconfigured_firmata_jog_leaves_the_readout(
    x_server: XServer, rig: Rig, shots: Path
) -> None:
    """Right on an unconfigured board: the board says "not configured"; the readout's pixels
    are the same before and after (the issue saw 9.97 mm in black)."""
    sim = rig.sim("firmata", "--reset-delay", "0.2")
    panel = rig.panel(x_server, "--port", sim.path, "--protocol", "firmata")
    wait_for(lambda: panel.state() == "idle", 30.0, "the board connected")
    x, y, w, _ = panel.geometry()
    readout = (x, y + 90, min(w, 470), 160)  # the Position panel, top left
    before = x_server.grab(shots / "readout-before.png", readout)
    panel.key("Right")
    wait_for(
        lambda: (
            NOT_CONFIGURED in b"".join(e.data for e in panel.logs.entries() if e.direction == "rx")
        ),
        15.0,
        "the board's `not configured`",
    )
    hold(1.5)  # an estimate would be drawn within this, and the poll would come back
    after = x_server.grab(shots / "readout-after.png", readout)
    shown_before, shown_after = _number_shown(before), _number_shown(after)
    assert shown_before is not None, f"no X number found in {shots}/readout-before.png"
    assert shown_after is not None and np.array_equal(shown_before, shown_after), (
        f"the X readout changed: see {shots}"
    )


def _number_shown(image: QImage) -> np.ndarray | None:
    """The pixels of the readout's first large line of text (the X machine position: a band of
    rows at least 15 px high with dark pixels in the number's columns), wherever the panel's
    layout put it."""
    image = image.convertToFormat(QImage.Format.Format_RGB32)
    width, height = image.width(), image.height()
    rgb = np.frombuffer(image.constBits(), dtype=np.uint32, count=width * height)
    pixels = rgb.reshape(height, width)[:, NUMBER_COLUMNS]
    grey = ((pixels >> 16) & 0xFF) // 3 + ((pixels >> 8) & 0xFF) // 3 + (pixels & 0xFF) // 3
    inked = (grey < 200).any(axis=1)
    top = 0
    while top < height:
        if not inked[top]:
            top += 1
            continue
        bottom = top
        while bottom < height and inked[bottom]:
            bottom += 1
        if bottom - top >= 15:
            return pixels[top:bottom].copy()
        top = bottom
    return None
