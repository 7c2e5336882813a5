#!/usr/bin/env python3
"""Checks which runs an ensemble or sweep runs again (talus.studies.dam_break_ensemble, run_all): a
finished run is left alone; one cut off by Ctrl-C or a time limit (its summary says
"interrupted") resumes from its checkpoint; one killed before its first checkpoint starts
again; a cut-off run never enters the statistics. A fake talus records each command."""
import json
import stat
import tempfile
import unittest
from pathlib import Path

from talus.studies import dam_break_ensemble

# Logs its arguments, then writes the summary of a run that ended by itself.
FAKE_TALUS = r"""#!/usr/bin/env python3
import json, sys
from pathlib import Path
args = sys.argv[1:]
out = Path(args[args.index("--out") + 1] if "--out" in args else args[1])
with open(out.parent / "commands.log", "a") as f:
    f.write(" ".join(args[:1] + [Path(a).name for a in args[1:2]]) + "\n")
out.mkdir(parents=True, exist_ok=True)
(out / "summary.json").write_text(json.dumps({"stop_reason": "collapse_over", "regime": "collapsed"}))
"""


class WhichRunsRunAgain(unittest.TestCase):
    def test_finished_are_kept_cut_off_resume_killed_restart(self):
        with tempfile.TemporaryDirectory() as tmp:
            base = Path(tmp)
            talus = base / "talus"
            talus.write_text(FAKE_TALUS)
            talus.chmod(talus.stat().st_mode | stat.S_IEXEC)
            folder = base / "point"
            done, cut, killed, fresh = (folder / f"seed_{k}" for k in (1, 2, 3, 4))
            for d in (done, cut, killed):
                d.mkdir(parents=True)
            (done / "summary.json").write_text(json.dumps({"stop_reason": "collapse_over"}))
            (cut / "summary.json").write_text(json.dumps({"stop_reason": "interrupted"}))
            (cut / "checkpoints").mkdir()
            (cut / "checkpoints" / "latest.h5").write_text("")
            self.assertFalse(dam_break_ensemble.finished(cut))
            self.assertEqual(list(dam_break_ensemble.seed_folders(folder)), [1])
            jobs = [(base / "case.toml", d, ["run.seed=%d" % k]) for k, d in enumerate((done, cut, killed, fresh), 1)]
            failed = dam_break_ensemble.run_all(jobs, 1, str(talus))
            self.assertEqual(failed, [])
            commands = sorted((folder / "commands.log").read_text().splitlines())
            self.assertEqual(commands, ["resume seed_2", "run case.toml", "run case.toml"])
            self.assertTrue(dam_break_ensemble.all_finished(jobs))
            self.assertEqual(list(dam_break_ensemble.seed_folders(folder)), [1, 2, 3, 4])


if __name__ == "__main__":
    unittest.main()
