"""The window's layouts and how its panels share the screen."""
