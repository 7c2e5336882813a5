"""Figures and studies of many runs: `python3 -m talus plot|render|fit|ensemble|sweep|aggregate|
hstop|flowmap` (cli.py). The studies start the talus executable for their runs (engine.py);
the executable never starts them. The reference is docs/guide/cli.md and docs/guide/studies.md."""
