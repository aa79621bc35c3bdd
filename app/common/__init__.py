"""What the window and the command line share: settings, messages, translations, macros, logs."""
