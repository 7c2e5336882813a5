"""Ensembles (Huet et al. 2021, Fig. 9: each case repeated with different initial
microstructures): the statistics of synthetic summaries, the stable fraction and the verdict
repeatable / intermittent, as `python3 -m talus aggregate DIR` writes them."""
import json
import math

import pytest

from talus.studies import cli


def write_summaries(folder, regimes, runout, static_reached):
    for k, (regime, r, s) in enumerate(zip(regimes, runout, static_reached), 1):
        run = folder / f"seed_{k}"
        run.mkdir(parents=True)
        summary = {"regime": regime, "L0": 0.03,
                   "dam_break": {"runout_ratio": r, "before_gate": {"static_reached": s}}}
        (run / "summary.json").write_text(json.dumps(summary))


def aggregate(folder):
    assert cli.main(["aggregate", str(folder)]) == 0
    return json.loads((folder / "ensemble.json").read_text())


def test_statistics_stable_fraction_and_verdict(tmp_path):
    runout = [1.0, 2.0, 3.5, 6.0]
    write_summaries(tmp_path, ["stable", "collapsed", "collapsed", "fractured"], runout, [True, False, True, True])
    e = aggregate(tmp_path)
    mean = sum(runout) / len(runout)
    std = math.sqrt(sum((v - mean) ** 2 for v in runout) / (len(runout) - 1))  # sample deviation
    r = e["measurements"]["dam_break.runout_ratio"]
    assert e["runs"] == 4
    assert r["mean"] == pytest.approx(mean, abs=1e-12)
    assert r["std"] == pytest.approx(std, abs=1e-12)
    assert (r["min"], r["max"]) == (1.0, 6.0)
    # A flag averages to the share of runs where it held: 3 of 4.
    assert e["measurements"]["dam_break.before_gate.static_reached"]["mean"] == pytest.approx(0.75)
    assert e["stable_fraction"] == pytest.approx(0.25)
    assert e["regime_counts"]["collapsed"] == 2
    assert e["verdict"] == "intermittent"  # one stable run, three that moved
    assert e["majority_regime"] == "collapsed"
    # The table repeats the statistics.
    assert any(line.startswith("dam_break.runout_ratio,4,") for line in (tmp_path / "ensemble.csv").read_text().splitlines())


def test_all_alike_is_repeatable(tmp_path):
    write_summaries(tmp_path / "collapsed", ["collapsed", "fractured", "collapsed"], [2, 2, 2], [True] * 3)
    a = aggregate(tmp_path / "collapsed")
    assert a["verdict"] == "repeatable"  # no run stable: the collapse mode may differ
    assert a["stable_fraction"] == 0.0
    assert a["measurements"]["dam_break.runout_ratio"]["std"] == 0.0
    write_summaries(tmp_path / "stable", ["stable", "stable"], [0, 0], [True, True])
    b = aggregate(tmp_path / "stable")
    assert (b["verdict"], b["stable_fraction"]) == ("repeatable", 1.0)
    write_summaries(tmp_path / "single", ["stable"], [0], [True])
    assert aggregate(tmp_path / "single")["verdict"] == "undetermined"  # one run cannot show intermittency
