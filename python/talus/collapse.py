"""The dam break's measurements from Python (Huet et al. 2021, Sec. III C and Appendix C), as
`talus run` reports them in summary.json."""
from . import _talus


def measure_collapse(initial, final, *, initial_length, box_length, width, particle_size=None, pixel=0.43e-3,
                     shapes_of=None):
    """Runout, heights, centre-of-mass shift and regime of the pile `final` that the column
    `initial` (two Snapshots) collapsed into. The column fills x in [0, initial_length] against
    the back wall x = 0; the box spans x in [0, box_length] and y in [0, width] (m).

    particle_size: m, the scale of the regime's tolerances (default: the largest bounding
    diameter). pixel: m, the top view's (0.43 mm, the paper's camera).
    shapes_of: the Simulation whose shapes the particles have; without it each particle is seen
    as its bounding sphere, exact for spheres and wider for any other shape.
    """
    geometry = (initial_length, box_length, width, particle_size, pixel)
    if shapes_of is None:
        return _talus.measure_collapse(initial, final, *geometry)
    return shapes_of._run.measure_collapse(initial, final, *geometry)
