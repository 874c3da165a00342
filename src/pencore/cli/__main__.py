"""``python -m pencore.cli``: the ``pencore`` command line."""

import sys

from pencore.cli.main import main

sys.exit(main())
