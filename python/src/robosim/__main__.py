"""``python -m robosim SCRIPT``: runs a controller script for one robot (robosim.runner)."""

import sys

from robosim.runner import main

sys.exit(main())
