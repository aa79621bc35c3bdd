"""The link to a device: ports opened by URL, control lines, the bridge, URL handlers."""
