"""The parts of the 2D position view (widgets.position_view_2d), one concept a module."""
