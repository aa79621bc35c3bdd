"""The traffic console and the offline log viewer."""
