"""Issue 28 item 9: the mouse wheel over an unfocused number field scrolls the dock and changes
nothing; the next Go sends what was typed (the issue saw Go-to X -40 become -43)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from PySide6.QtCore import QRect
from PySide6.QtGui import QImage

from tests.acceptance.conftest import Rig
from tests.acceptance.xsession import Panel, XServer, numbers, wait_for, write_settings

BOX = ((-50.0, 50.0), (-50.0, 50.0), (-50.0, 50.0))
REFUSED_TINT = 0xF0C9C9  # a refused field's background: a white base with a quarter of #c62828


def _runs(flags: np.ndarray) -> list[tuple[int, int]]:
    """The (first, last) index of each run of True in `flags`."""
    edges = np.diff(np.concatenate(([0], flags.astype(np.int8), [0])))
    return list(zip(np.nonzero(edges == 1)[0], np.nonzero(edges == -1)[0] - 1, strict=True))


def _field_at(image: QImage, rgb: int, tolerance: int = 6) -> tuple[int, int, int, int] | None:
    """The box (left, top, right, bottom) of the largest solid rectangle of colour `rgb` (a
    field's background; not a few such pixels in an anti-aliased label), or None."""
    image = image.convertToFormat(QImage.Format.Format_RGB32)
    flat = np.frombuffer(image.constBits(), dtype=np.uint32, count=image.width() * image.height())
    shifts = np.array([16, 8, 0], dtype=np.uint32)
    channels = (flat.reshape(image.height(), image.width(), 1) >> shifts) & 0xFF
    wanted = (rgb >> shifts) & 0xFF
    close = (np.abs(channels.astype(np.int16) - wanted.astype(np.int16)) <= tolerance).all(axis=2)
    rows = [run for run in _runs(close.sum(axis=1) >= 30) if run[1] - run[0] >= 6]
    if not rows:
        return None
    top, bottom = max(rows, key=lambda run: run[1] - run[0])
    left, right = max(_runs(close[top : bottom + 1].sum(axis=0) > 0), key=lambda r: r[1] - r[0])
    return int(left), int(top), int(right), int(bottom)


def _type_in_x(panel: Panel, text: str) -> None:
    """Type `text` over what the Go to X field holds (Alt+X: its label's mnemonic)."""
    panel.key("alt+x")
    panel.key("ctrl+a")
    panel.type(text)


def test_the_wheel_over_go_to_x_scrolls_and_go_sends_the_typed_value(
    any_screen: XServer, rig: Rig, tmp_path: Path, shots: Path
) -> None:
    """Type X -40, leave the field, wheel over it three notches, Go: the device gets -40."""
    width, height = any_screen.size
    sim = rig.sim("coxiris", "--speed", "100")
    settings = write_settings(
        tmp_path / "settings.ini", protocol="coxiris", port=sim.path, travel=BOX
    )
    panel = rig.panel(any_screen, "--port", sim.path, "--protocol", "coxiris", settings=settings)
    panel.wait_ready(b"DONE GET_SPEED")
    _type_in_x(panel, "80")  # outside the box: the field turns red, which shows where it is
    field = wait_for(
        lambda: _field_at(any_screen.grab(shots / "located.png"), REFUSED_TINT),
        10.0,
        "the Go to X field shown red for 80",
        interval=0.2,
    )
    _type_in_x(panel, "-40")
    panel.key("Tab", "Tab", "Tab")  # on to Y, Z, then the absolute/relative choice
    before = any_screen.grab(shots / f"wheel-before-{width}x{height}.png")

    x, y = (field[0] + field[2]) // 2, (field[1] + field[3]) // 2
    any_screen.xdotool("mousemove", str(x), str(y))
    any_screen.xdotool("click", "--repeat", "3", "--delay", "80", "5")  # wheel down: -43?
    scrolled = any_screen.grab(shots / f"wheel-scrolled-{width}x{height}.png")
    panel.key("alt+x")
    panel.key("Return")  # Go, with what the fields show

    record = sim.record
    moves = wait_for(lambda: record.commands("ABSOLUTE_MOVE"), 15.0, "ABSOLUTE_MOVE at the device")
    assert [numbers(m) for m in moves] == [[-40.0, 0.0, 0.0]], (
        f"typed X -40, wheeled over the fields, Go: the device received {[m.text for m in moves]}"
    )
    left, top, _right, bottom = field
    region = QRect(left - 130, top - 30, 120, bottom - top + 60)  # the label, the choices below
    moved = before.copy(region) != scrolled.copy(region)  # the panel under the pointer moved
    print(f"{width}x{height}: the Go to X field at {field}; the dock scrolled: {moved}")
