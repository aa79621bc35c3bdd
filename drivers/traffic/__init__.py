"""Traffic: records from the tap, decoded, paired, indexed, searched, spooled; logs read back."""
