"""``python -m contact``: the ``contact`` command (see :mod:`contact.cli`)."""
from .cli import console

if __name__ == "__main__":
    console()
