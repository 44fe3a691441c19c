"""``python -m pentanb``: see :mod:`pentanb.cli`."""

import sys

from .cli import main

sys.exit(main())
