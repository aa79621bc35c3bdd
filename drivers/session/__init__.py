"""One connected device as every front end drives it: `DeviceSession` and its parts."""
