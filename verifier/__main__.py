"""Allow ``python -m launchverify``."""

from launchverify.process.command import run

run()
