"""Check boxes and radio buttons that show on a dark window, ticked or not.

Fusion draws a check box's box from the palette: its outline from the Window colour made darker
and its fill from Base. On the dark theme's window both are within a few shades of the window
(a contrast of 1.2:1): an unticked box (a DXF layer, DTR and RTS, Bridge) was next to
invisible. Those two roles are given other colours for the check boxes and radio buttons only
(QApplication's palette for a class), for an outline and a fill that stand out from the window
(3:1 and more, what WCAG asks of a control's outline); on the light theme the outline was
1.6:1, and is made darker the same way. Only under Fusion: other styles draw their own boxes.
"""

from __future__ import annotations

from PySide6.QtGui import QColor, QPalette
from PySide6.QtWidgets import QApplication

CLASSES = ("QCheckBox", "QRadioButton")
_R, _G = QPalette.ColorRole, QPalette.ColorGroup
# Window: Fusion's outline is this made darker (140 %), then lighter (110 %): about #7f7f84.
DARK_ROLES = {
    _G.Active: {_R.Window: "#b4b4ba", _R.Base: "#3c3c41"},
    _G.Inactive: {_R.Window: "#b4b4ba", _R.Base: "#3c3c41"},
    _G.Disabled: {_R.Window: "#7c7c82", _R.Base: "#2a2a2d"},
}
LIGHT_ROLES = {  # the outline about #7a7a7a on the #efefef window
    _G.Active: {_R.Window: "#9c9c9c"},
    _G.Inactive: {_R.Window: "#9c9c9c"},
    _G.Disabled: {_R.Window: "#c8c8c8"},
}
FUSION = "fusion"


def indicator_palette(palette: QPalette, dark: bool) -> QPalette:
    """`palette` for Fusion's check boxes and radio buttons, `dark` or light: an outline and a
    fill their box can be seen by."""
    result = QPalette(palette)
    for group, roles in (DARK_ROLES if dark else LIGHT_ROLES).items():
        for role, name in roles.items():
            result.setColor(group, role, QColor(name))
    return result


def apply_indicator_palettes(app: QApplication, dark: bool) -> None:
    """Give `app`'s check boxes and radio buttons `indicator_palette` of its palette (under
    Fusion; under another style, the application's palette)."""
    palette = app.palette()
    if app.style().name().lower() == FUSION:
        palette = indicator_palette(palette, dark)
    for name in CLASSES:
        app.setPalette(palette, name)
