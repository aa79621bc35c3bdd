"""Pure Qt widgets of the panel: they take plain values and emit signals, and know no protocol.

Each widget lives in its own module (`widgets.jog_panel`, `widgets.send_line`, ...); this package
imports none of them, so that importing one widget does not pull in pyqtgraph or OpenGL.
"""
