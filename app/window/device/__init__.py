"""One device as the window drives it: connection, worker thread, jobs, machine state."""
