from eulerlib.cli import main

raise SystemExit(main())
