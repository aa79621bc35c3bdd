"""pyserial URL handlers of our own: `sim://PROTOCOL` serves a simulated device in-process."""
