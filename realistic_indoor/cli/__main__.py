"""``python -m realistic_indoor.cli``."""

import sys

from realistic_indoor.cli import main

sys.exit(main())
