"""Issue 28 item 27: on the dark theme (and the light one), an unticked check box and the
control lines' off and unknown lights stand out from the window: the contrast of what is drawn,
measured on a grab of the widgets, is 3:1 or more (WCAG's for a control's outline)."""

from __future__ import annotations

from collections.abc import Iterator
from types import SimpleNamespace

import pytest
from PySide6.QtCore import QRect
from PySide6.QtGui import QColor, QImage, QPalette
from PySide6.QtWidgets import QApplication, QCheckBox, QHBoxLayout, QWidget

from app.window.theme import apply_theme
from widgets._gl_scene import contrast_ratio
from widgets.control_lines_bar import ControlLinesBar

pytestmark = pytest.mark.timeout(30)

MIN_CONTRAST = 3.0
INDICATOR_PX = 18  # a check box's box lies in its first 18 px


@pytest.fixture
def app(qapp: QApplication) -> Iterator[QApplication]:
    """The application, given back with the system theme."""
    yield qapp
    apply_theme(qapp, "system")


def most_contrast(image: QImage, rect: QRect, against: QColor) -> float:
    """The highest contrast with `against` of a pixel in `rect` of `image`."""
    return max(
        contrast_ratio(QColor(image.pixel(x, y)), against)
        for x in range(rect.left(), rect.right() + 1)
        for y in range(rect.top(), rect.bottom() + 1)
    )


@pytest.mark.parametrize("theme", ["dark", "light"])
def test_unticked_boxes_and_unlit_lights_stand_out(qtbot, app: QApplication, theme: str) -> None:
    apply_theme(app, theme)
    holder = QWidget()
    qtbot.addWidget(holder)
    row = QHBoxLayout(holder)
    bridge = QCheckBox("Bridge")
    lines = ControlLinesBar()
    row.addWidget(bridge)
    row.addWidget(lines)
    lines.set_connected(True)
    lines.set_lines(SimpleNamespace(dtr=False, rts=False, cts=False, dsr=True, cd=None, ri=False))
    holder.show()
    qtbot.waitExposed(holder)
    image = holder.grab().toImage()
    window = holder.palette().color(QPalette.ColorRole.Window)
    found = {}
    for name, box in (("Bridge", bridge), ("DTR", lines.dtr_toggle), ("RTS", lines.rts_toggle)):
        assert not box.isChecked()
        place = QRect(box.mapTo(holder, box.rect().topLeft()), box.size())
        found[f"the unticked {name} box"] = most_contrast(
            image, place.adjusted(0, 0, INDICATOR_PX - place.width(), 0), window
        )
    for name in ("cts", "cd", "ri"):  # off, unknown, off
        light = lines.indicators[name]
        place = QRect(light.mapTo(holder, light.rect().topLeft()), light.size())
        found[f"the {lines.indicator_state(name)} {name.upper()} light"] = most_contrast(
            image, place, window
        )
    faint = {name: round(value, 2) for name, value in found.items() if value < MIN_CONTRAST}
    assert not faint, f"{theme}: too faint against the window {window.name()}: {faint}"
