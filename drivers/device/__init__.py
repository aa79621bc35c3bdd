"""The device stack under the session: client, motion, the guard, travel, counted position."""
