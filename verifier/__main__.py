"""Allow ``python -m launchverify``."""

from launchverify.command import run

run()
