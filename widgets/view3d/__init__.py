"""The parts of the 3D position view (widgets.position_view_3d), one concept a module."""
