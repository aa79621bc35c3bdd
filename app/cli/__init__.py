"""motionctl: the command line (argument parsing, device commands, logs, macros, bridge)."""
