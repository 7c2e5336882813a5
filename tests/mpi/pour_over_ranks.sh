#!/bin/sh
# Pouring and domain.on_leave = "delete" over ranks: spheres poured in batches, thrown along a
# box open at its far end, some leaving it. Every rank draws the same places and adds those in
# its slab, so ids stay unique; removals anywhere rebuild every rank. On 1, 2 and 4 ranks the
# runs agree to round-off while the flow is not yet chaotic, through the first removals, and all
# pour every sphere. The 2-rank checkpoint restarts on 1 rank (its ids checked unique). The
# 2-rank run's VTK frames, written in one piece per rank, join to the 1-rank run's frames.
# Usage: pour_over_ranks.sh TALUS SCENARIO WORKDIR
set -eu
talus=$1 scenario=$2 work=$3
mpirun="mpirun --oversubscribe --allow-run-as-root -x OMP_NUM_THREADS=1"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$talus" run "$scenario" --out one --threads 1 --quiet --set run.vtk_interval=0.1
$mpirun -n 2 "$talus" run "$scenario" --out two --threads 1 --quiet --set run.vtk_interval=0.1 --set run.snapshot_interval=0.1
$mpirun -n 4 "$talus" run "$scenario" --out four --threads 1 --quiet
# Slabs along z, as run.processors asks, instead of the axis chosen for them (x); and a count of
# sub-domains that is not the number of ranks, refused with the key named.
$mpirun -n 2 "$talus" run "$scenario" --out two_z --threads 1 --quiet --set run.end_time=0.12 --set 'run.processors=[1, 1, 2]'
if $mpirun -n 2 "$talus" run "$scenario" --out two_bad --threads 1 --quiet --set 'run.processors=[1, 1, 4]' 2> bad.err; then
  echo "FAILED: 4 sub-domains on 2 ranks were not refused"; exit 1
fi
grep -q 'run.processors: 4 sub-domains for 2 ranks' bad.err || { echo "FAILED: the refusal does not name the key:"; cat bad.err; exit 1; }
"$talus" run "$scenario" --set run.end_time=0.35 --restart two/checkpoints/latest.h5 --out again --threads 1 --quiet
/usr/bin/python3 - <<'PY'
import csv, glob, json, os, sys
fail = []
def check(ok, what):
    if not ok:
        fail.append(what)
rows = {d: list(csv.DictReader(open(d + "/timeseries.csv"))) for d in ["one", "two", "four", "two_z"]}
summary = {d: json.load(open(d + "/summary.json")) for d in ["one", "two", "four", "again", "two_z"]}
check(summary["two"]["slab_axis"] == "x" and summary["two_z"]["slab_axis"] == "z", "slab axes: chosen x, asked z")
for d in ["one", "two", "four"]:
    s = summary[d]
    check(s["particles"] + s["particles_left_domain"] == 240, f"{d}: poured {s['particles'] + s['particles_left_domain']} of 240")
    check(s["particles_left_domain"] > 0, f"{d}: no sphere left the box")
for d in ["two", "four", "two_z"]:
    check(summary[d]["particles_moved_between_ranks"] > 0, f"{d}: no sphere crossed a cut")
# Up to t = 0.12 (six batches poured, 14 spheres removed): round-off (measured 1e-15).
for a, b, c, z in zip(rows["one"], rows["two"], rows["four"], rows["two_z"]):
    if float(a["time"]) > 0.125:
        break
    k = float(a["kinetic_translational"])
    for other, name in [(b, "two"), (c, "four"), (z, "two_z")]:
        check(abs(float(other["kinetic_translational"]) - k) <= 1e-9 * k, f"{name}: kinetic energy at t = {a['time']}")
        check(other["particles_left_domain"] == a["particles_left_domain"], f"{name}: removals at t = {a['time']}")
check(float(rows["one"][12]["particles_left_domain"]) > 0, "no removal before t = 0.12")
# Frames of the 2-rank run (t = 0, 0.1, 0.2, 0.3), in pieces, one per rank, joined by a .pvtu:
# the first too, since the run is spread before anything is written.
import xml.etree.ElementTree as ET
from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader, vtkXMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy
def frames(folder, stem):
    out = []
    for ds in ET.parse(f"{folder}/vtk/{stem}.pvd").getroot().iter("DataSet"):
        path = f"{folder}/vtk/" + ds.get("file")
        reader = vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu") else vtkXMLUnstructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        out.append((path, reader.GetOutput()))
    return out
def ids(grid, where, name):
    data = grid.GetPointData() if where == "point" else grid.GetCellData()
    return sorted(vtk_to_numpy(data.GetArray(name)).tolist()) if grid.GetNumberOfCells() else []
p1, p2 = frames("one", "particles"), frames("two", "particles")
c1, c2 = frames("one", "contacts"), frames("two", "contacts")
check([os.path.basename(p) for p, _ in p2] == [f"particles_00000{k}.pvtu" for k in (0, 1, 2, 3)], "two: VTK frames")
check(len(glob.glob("two/vtk/particles_00000[0123]_[01].vtu")) == 8, "two: one piece per rank and frame")
for (path, g) in p2:
    every = ids(g, "point", "id")
    check(len(every) == len(set(every)), f"{path}: a particle in two pieces")
# At t = 0.1 (round-off agreement) the same particles and the same contacts, pair by pair.
check(ids(p2[1][1], "point", "id") == ids(p1[1][1], "point", "id"), "two: the particles of the frame at t = 0.1")
def pairs(g):
    if not g.GetNumberOfCells():
        return []
    i, j = (vtk_to_numpy(g.GetCellData().GetArray(n)).tolist() for n in ("i", "j"))
    return sorted((a, b) if b < 0 or a < b else (b, a) for a, b in zip(i, j))
check(len(pairs(c1[1][1])) > 0 and pairs(c2[1][1]) == pairs(c1[1][1]),
      f"two: contacts at t = 0.1, {len(pairs(c2[1][1]))} against {len(pairs(c1[1][1]))} on one rank")
# Every frame has each contact once: as many lines as the run counted contacts at that time.
for (path, g) in c2:
    t = float(ET.parse("two/vtk/contacts.pvd").getroot().find(f".//DataSet[@file='{os.path.basename(path)}']").get("timestep"))
    row = next(r for r in rows["two"] if abs(float(r["time"]) - t) < 1e-9)
    counted = int(float(row["contacts"])) + int(float(row["wall_contacts"]))
    check(g.GetNumberOfCells() == counted, f"{path}: {g.GetNumberOfCells()} contact lines, {counted} contacts counted")
check(c2[-1][1].GetNumberOfCells() > 20, "two: few contacts in the last frame")
check(len(glob.glob("two/snapshots/snapshot_*.h5")) == 4, "two: snapshot files")
again = summary["again"]
check(again["particles"] + again["particles_left_domain"] == 240 and again["final_time"] > 0.349, "the 2-rank checkpoint's restart on 1 rank")
if fail:
    print("FAILED:", *fail, sep="\n  ")
    sys.exit(1)
print("pouring and removal over 1, 2 and 4 ranks: the same spheres, the same removals")
PY
