"""``python -m contact``: the ``contact`` command (see :mod:`contact.cli`)."""
import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
