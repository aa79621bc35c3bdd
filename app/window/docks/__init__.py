"""The window's docks: program, macros, parameters, work zero, device kinds."""
