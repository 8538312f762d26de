"""Run the command line as ``python -m eulerlib``."""

from eulerlib.cli import main

if __name__ == "__main__":
    raise SystemExit(main())
