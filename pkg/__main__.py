"""``python -m hertzmdr``: the ``hertzmdr`` command (the same parser, the same exit codes)."""

import sys

from hertzmdr.numeric.cli import main

if __name__ == "__main__":
    sys.exit(main())
