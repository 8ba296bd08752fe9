"""The ``launchverify`` process: its entry point and what makes its start-up quick."""
