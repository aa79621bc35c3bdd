"""pyserial URL handlers for simulated devices (`sim://`); drivers/link/transport.py
registers this package."""
