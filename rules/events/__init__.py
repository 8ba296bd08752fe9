"""Rules about event handlers: loops without end, targets that never run."""
