"""The command line of the figures and studies: `python3 -m talus SUBCOMMAND ...`.

The options are those the talus executable's subcommands of the same names had; each module
is imported only when its subcommand runs (matplotlib and VTK take a while to load)."""
import argparse
import sys
from pathlib import Path

from . import slurm_array


def positive(text):
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"{text}: must be at least 1")
    return value


def non_negative(text):
    value = int(text)
    if value < 0:
        raise argparse.ArgumentTypeError(f"{text}: must be at least 0")
    return value


def add_engine_options(p):
    p.add_argument("--talus", metavar="BIN",
                   help="the talus executable that does the runs (default: $TALUS_BINARY, else the one "
                        "beside this package, else talus on PATH)")
    p.add_argument("--set", dest="overrides", action="append", default=[], metavar="KEY=VALUE",
                   help="override a scenario value for every run (repeatable)")
    slurm_array.add_options(p)


def add_seed_options(p, seeds_required):
    p.add_argument("scenario", metavar="FILE", help="scenario file (TOML)")
    p.add_argument("--seeds", type=positive, required=seeds_required, default=1,
                   help="runs per case, seeds first-seed..first-seed+N-1")
    p.add_argument("--first-seed", type=non_negative, default=1, help="first run.seed")
    p.add_argument("--jobs", type=positive, default=1, help="runs at a time, one thread each")
    p.add_argument("--out", required=True, help="results folder")
    add_engine_options(p)


def command(sub, name, help):
    # No abbreviated options: a Slurm array task's command line drops --slurm and --talus by name.
    return sub.add_parser(name, help=help, allow_abbrev=False)


def parser():
    top = argparse.ArgumentParser(prog="python3 -m talus",
                                  description="Figures and studies of many runs of the talus engine.")
    sub = top.add_subparsers(dest="command", required=True, metavar="SUBCOMMAND")

    p = command(sub, "plot", "draw a results folder's figures (energies; dam-break, ensemble, sweep, "
                             "hopper and chute figures)")
    p.add_argument("dir", help="results folder")
    p.add_argument("--snapshot-times", help="dam-break side snapshots at these times, s after the gate opened, "
                                            "comma separated")
    p = command(sub, "render", "draw a results folder's configuration as a PNG (needs run.vtk_interval)")
    p.add_argument("dir", help="results folder")
    p.add_argument("--time", type=float, default=float("inf"), help="simulated time (s); default: the last frame")
    p.add_argument("--view", choices=["side", "top"], default="side", help="side (x-z) or top (x-y)")
    p.add_argument("--out", help="PNG file (default: DIR/render_<view>_<time>.png)")
    p = command(sub, "fit", "closure fits of a flow map / h_stop folder (DIR/fits.json, DIR/fits.md)")
    p.add_argument("dir", help="results folder")

    add_seed_options(command(sub, "ensemble", "run a scenario for N seeds and aggregate (DIR/ensemble.json)"),
                     seeds_required=True)
    p = command(sub, "sweep", "run an ensemble per grid point (DIR/sweep.csv, flow map)")
    add_seed_options(p, seeds_required=False)
    p.add_argument("--grid", action="append", required=True, metavar="KEY=V1,V2,...",
                   help="values of one scenario key (repeatable: the grid is their product)")
    p = command(sub, "aggregate", "aggregate the seed_* folders already in DIR (DIR/ensemble.json)")
    p.add_argument("dir", help="ensemble folder")

    p = command(sub, "hstop", "h_stop search on a chute scenario (Weinhart et al. 2012, Sect. 6)")
    p.add_argument("scenario", metavar="FILE", help="chute scenario file (TOML)")
    p.add_argument("--lambda", dest="lambdas", default="1", help="comma-separated base diameters")
    p.add_argument("--jobs", type=positive, default=2, help="cases at a time, one thread each")
    p.add_argument("--out", default="results/hstop", help="results folder")
    p.add_argument("--h0", type=float, default=4)
    p.add_argument("--theta0", type=float, default=21)
    p.add_argument("--h-max", type=float, default=40)
    p.add_argument("--theta-min", type=float, default=10)
    p.add_argument("--max-cases", type=int, default=60, help="cases of one staircase at most")
    p.add_argument("--end-time", type=float, default=500, help="Sect. 6: arrest within 500 time units")
    p.add_argument("--checkpoint-interval", type=float, default=50,
                   help="time units between checkpoints of each case, which an interrupted case resumes from")
    add_engine_options(p)

    p = command(sub, "flowmap", "flow-state map over lambda, H, theta (Weinhart et al. 2012, Sect. 8)")
    p.add_argument("scenario", metavar="FILE", help="chute scenario file (TOML)")
    p.add_argument("--lambda", dest="lambdas", default="0,0.5,0.6666666666666666,0.8333333333333334,1,2")
    p.add_argument("--heights", default="10,20,30,40")
    p.add_argument("--angles", default="20,22,24,26,28,30")
    p.add_argument("--end-time", type=float, default=2000)
    p.add_argument("--average", type=float, default=100, help="averaging window T at the end (Sect. 7: 100)")
    p.add_argument("--jobs", type=positive, default=2, help="cases at a time, one thread each")
    p.add_argument("--out", default="results/sweep", help="results folder")
    p.add_argument("--checkpoint-interval", type=float, default=50,
                   help="time units between checkpoints of each case, which an interrupted case resumes from")
    p.add_argument("--continue-from", metavar="DIR",
                   help="an earlier, shorter sweep: a case it ran to its end time goes on from its final checkpoint "
                        "(the same bits as a run from the start)")
    add_engine_options(p)
    return top


CHUTE_FILES = ("chute_profile.csv", "sweep_runs.csv", "hstop_runs.csv")
DAM_BREAK_FILES = ("sweep.json", "ensemble.json", "collapse_speeds.csv", "pile_profile.csv")


def plot(folder: Path, snapshot_times):
    """The figures for what the folder holds: a chute study's, a dam-break or hopper study's, or
    the energies of any other run."""
    if not folder.is_dir():
        sys.exit(f"talus plot: {folder}: no such folder")
    if any((folder / f).exists() for f in CHUTE_FILES):
        from . import plot_chute
        plot_chute.main(folder)
    elif any((folder / f).exists() for f in DAM_BREAK_FILES):
        from . import dam_break_plots
        times = [float(t) for t in snapshot_times.split(",")] if snapshot_times else None
        dam_break_plots.draw(folder, times)
    else:
        from . import plot_timeseries
        plot_timeseries.main(folder)


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    args = parser().parse_args(argv)
    args.argv = argv  # what a Slurm array task runs again
    if args.command == "plot":
        plot(Path(args.dir), args.snapshot_times)
    elif args.command == "render":
        from . import render
        print(render.draw(args.dir, args.time, args.view, args.out))
    elif args.command == "fit":
        from . import chute_fits
        chute_fits.fit_folder(args.dir)
    elif args.command == "aggregate":
        from . import dam_break_ensemble
        dam_break_ensemble.aggregate_folder(args.dir)
    else:
        from . import engine
        args.talus = engine.find_talus(args.talus)
        if args.command == "ensemble":
            from . import dam_break_ensemble
            dam_break_ensemble.run(args)
        elif args.command == "sweep":
            from . import dam_break_sweep
            dam_break_sweep.run(args)
        elif args.command == "hstop":
            from . import chute_hstop
            chute_hstop.run(args)
        else:
            from . import chute_sweep
            chute_sweep.run(args)
    return 0
