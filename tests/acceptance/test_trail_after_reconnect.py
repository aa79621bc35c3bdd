"""Issue 19 item 13: after a reconnection the views draw no motion that never happened."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
from PySide6.QtGui import QImage

from app.window.layout.layout_report import ENVIRONMENT
from tests.acceptance.conftest import Rig
from tests.acceptance.test_layouts_fit import _switch
from tests.acceptance.test_parts_whole import _tab
from tests.acceptance.xsession import (
    SCREENS,
    Sim,
    XServer,
    hold,
    wait_for,
    write_settings,
)

TRAIL = 0x5C6BC0  # the XY view's trail (widgets/view2d/style.py)
TOLERANCE = 40  # the trail is drawn antialiased, 1.5 px wide
MIN_SIDE = 40  # px: a 15 mm side of the XY view at 1600x1000 is about 100 px
MARGIN = 6  # px kept from the square's sides (the line's width, the markers)
OBSERVATION_S = 2.0  # screenshots over this time after the reconnection


def _trail_mask(image: QImage) -> np.ndarray:
    """Where `image` (the whole screen) has the trail's colour."""
    image = image.convertToFormat(QImage.Format.Format_RGB32)
    width, height = image.width(), image.height()
    pixels = np.frombuffer(image.constBits(), dtype=np.uint32, count=width * height)
    pixels = pixels.reshape(height, width)
    close = np.ones(pixels.shape, dtype=bool)
    for shift in (16, 8, 0):
        channel = ((pixels >> shift) & 0xFF).astype(np.int16)
        close &= np.abs(channel - ((TRAIL >> shift) & 0xFF)) <= TOLERANCE
    return close


def _longest_run(line: np.ndarray) -> tuple[int, int]:
    """The longest run of True in `line`: (start, length)."""
    best = (0, 0)
    start = None
    for index, value in enumerate([*line.tolist(), False]):
        if value and start is None:
            start = index
        elif not value and start is not None:
            if index - start > best[1]:
                best = (start, index - start)
            start = None
    return best


def _square(mask: np.ndarray) -> tuple[int, int, int, int] | None:
    """The XY view's trail of X+ then Y+ (an L: a vertical run of the trail's colour whose
    bottom end closes a horizontal run coming from the left) as the square it spans: (left,
    top, right, bottom) pixels; None if not found."""
    for column in range(mask.shape[1]):
        top, run = _longest_run(mask[:, column])
        if run < MIN_SIDE:
            continue
        bottom = top + run - 1
        for row in range(max(bottom - 3, 0), min(bottom + 4, mask.shape[0])):
            near = max(column - 3, 0)
            corner = np.nonzero(mask[row, near : column + 4])[0]
            if not corner.size:
                continue
            right = left = near + int(corner[-1])
            while left > 0 and mask[row, left - 1]:
                left -= 1
            if right - left + 1 >= MIN_SIDE:
                return left, top, right, bottom
    return None


def _inside(mask: np.ndarray, square: tuple[int, int, int, int]) -> int:
    """Trail pixels strictly inside the square (a line from its top right corner to its bottom
    left, the path back to the origin that never happened, crosses it)."""
    left, top, right, bottom = square
    return int(mask[top + MARGIN : bottom - MARGIN, left + MARGIN : right - MARGIN].sum())


def test_reconnection_draws_no_ramp(
    x_server_of: Callable[[tuple[int, int]], XServer], rig: Rig, tmp_path: Path, shots: Path
) -> None:
    """X+ 15 then Y+ 15 draw an L in the XY view; the device is killed and a new one (at the
    origin) served on the same link; after the reconnection no move is sent and, for 2 s of
    screenshots, the XY view has no trail inside the L's square (the issue saw a slow ramp
    joining the old position to the new one)."""
    x_server: XServer = x_server_of(SCREENS[2])  # 1600x1000
    link = tmp_path / "ttyStage"
    first = rig.sim("coxiris", "--speed", "100", link=link)
    settings = write_settings(
        tmp_path / "settings.ini", protocol="coxiris", port=str(link), jog_step=15.0
    )
    report_path = tmp_path / "layout-report.json"
    panel = rig.panel(
        x_server, "--port", str(link), "--protocol", "coxiris", settings=settings,
        env={ENVIRONMENT: str(report_path)},
    )  # fmt: skip
    panel.fit_inside_screen()  # the status bar on the screen: its state is read there
    panel.wait_ready(b"DONE GET_SPEED")
    logs = panel.logs
    # The XY view is the centre's second tab: clicked where the layout report says it is.
    report = _switch(panel, report_path, "operate", lambda r: bool(r["connected"]))
    left, top, _, _ = panel.geometry()
    tx, ty, tw, th = _tab(report, "XY and time")
    x_server.xdotool("mousemove", str(left + tx + tw // 2), str(top + ty + th // 2), "click", "1")

    def position_read(part: int, text: bytes) -> bool:
        connections = logs.connections()
        return len(connections) > part and text in b"".join(
            e.data for e in connections[part] if e.direction == "rx"
        )

    panel.key("Right")
    wait_for(lambda: position_read(0, b"POSITION: 15.00 0.00"), 10.0, "X at 15 read back")
    panel.wait_state("idle", 10.0)
    panel.key("Up")
    wait_for(lambda: position_read(0, b"POSITION: 15.00 15.00"), 10.0, "Y at 15 read back")
    square = wait_for(
        lambda: _square(_trail_mask(x_server.grab(shots / "before.png"))),
        10.0,
        "the L of the two jogs in the XY view",
        interval=0.2,
    )
    assert _inside(_trail_mask(QImage(str(shots / "before.png"))), square) <= 5, square

    first.vanish()
    second: Sim = rig.sim("coxiris", "--speed", "100", link=link)
    panel.wait_ready(b"DONE GET_SPEED", 25.0, count=2)  # the reconnection
    parts = len(logs.connections())
    wait_for(lambda: position_read(parts - 1, b"POSITION: 0.00 0.00"), 10.0, "0 0 read back")

    inside: list[int] = []

    def look() -> None:
        shot = shots / f"after-{len(inside)}.png"
        inside.append(_inside(_trail_mask(x_server.grab(shot)), square))

    hold(OBSERVATION_S, every=look)
    moved = [
        line.text
        for line in logs.sent_lines()
        if line.text.split(" ", 1)[0] in ("DELTA_MOVE", "ABSOLUTE_MOVE")
    ]
    assert moved == ["DELTA_MOVE 15 0 0", "DELTA_MOVE 0 15 0"], moved
    assert not second.record.commands("DELTA_MOVE") and not second.record.commands("ABSOLUTE_MOVE")
    assert len(inside) >= 3 and max(inside) <= 5, (
        f"trail pixels inside the square {square} after the reconnection: {inside} (see {shots})"
    )
