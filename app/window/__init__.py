"""motionpanel: the Qt window, its docks and tools, and the worker thread that drives the device."""
