"""Allow ``python -m launchverify``."""

from launchverify.cli import main

raise SystemExit(main())
