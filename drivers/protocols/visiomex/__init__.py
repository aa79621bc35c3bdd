"""The Visiomex VMR2P0R0001 packet protocol: codec, parameters, the firmware's arithmetic."""
