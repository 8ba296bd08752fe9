"""Allow ``python -m launchverify``."""

from launchverify.cli import entry

entry()
