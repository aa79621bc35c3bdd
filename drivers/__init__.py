"""Motion Panel driver layer: transports, framers, protocols and simulators (no Qt)."""
