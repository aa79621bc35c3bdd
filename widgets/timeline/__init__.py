"""The parts of the traffic timeline (widgets.traffic_timeline), one concept a module."""
