"""Motion Panel application: main window, serial worker, and the command-line entry points."""
