"""Protocols: typed commands to frames, frames to typed events."""
