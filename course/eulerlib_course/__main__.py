"""Run the course's command line as ``python -m eulerlib_course``."""

from eulerlib_course.cli import main

if __name__ == "__main__":
    raise SystemExit(main())
