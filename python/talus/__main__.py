"""`python3 -m talus`: figures and studies of many runs (talus.studies.cli)."""
import sys

from .studies.cli import main

sys.exit(main())
