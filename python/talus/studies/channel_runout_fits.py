"""Published runouts of granular columns collapsing in a channel (quasi-2D), the experiments
Huet et al. 2021 compare their collapses with in Fig. 10:

    (L_inf - L0) / L0 = lambda1 a  for a < a_low,   lambda2 a^(2/3)  for a > a_high

with a = H0 / L0, as collected by Lagrée, Staron & Popinet 2011 (J. Fluid Mech. 686, 378),
Eq. (3.1). Between a_low and a_high neither fit is stated, so neither is drawn there.

Pure Python (no engine module): tools/validation.py loads this file by its path.
"""
from dataclasses import dataclass


@dataclass(frozen=True)
class ChannelRunoutFit:
    source: str
    material: str
    linear: float  # lambda1
    a_low: float  # the linear fit holds below
    power: float  # lambda2, of a^(2/3)
    a_high: float  # the power law holds above

    def runout_ratio(self, a: float):
        """(L_inf - L0) / L0 at aspect ratio a, or None between the two ranges."""
        if a <= self.a_low:
            return self.linear * a
        if a >= self.a_high:
            return self.power * a ** (2.0 / 3.0)
        return None

    def curve(self, branch: str, a_max: float, points: int = 50):
        """(a, runout ratio) along one branch ("linear" or "power") on its own range up to a_max;
        empty where the range starts beyond a_max."""
        start, end = (0.0, min(self.a_low, a_max)) if branch == "linear" else (self.a_high, a_max)
        if end <= start:
            return [], []
        a = [start + (end - start) * k / (points - 1) for k in range(points)]
        return a, [self.linear * x if branch == "linear" else self.power * x ** (2.0 / 3.0) for x in a]

    def label(self, branch: str) -> str:
        if branch == "linear":
            return f"{self.source}: {self.linear:g} a (a < {self.a_low:g})"
        return f"{self.source}: {self.power:g} a^(2/3) (a > {self.a_high:g})"


# Lube, Huppert, Sparks & Freundt 2005, Phys. Rev. E 72, 041301.
LUBE_2005 = ChannelRunoutFit("Lube et al. 2005", "sand, rice, sugar", 1.2, 1.8, 1.9, 2.8)
# Lajeunesse, Monnier & Homsy 2005, Phys. Fluids 17, 103302.
LAJEUNESSE_2005 = ChannelRunoutFit("Lajeunesse et al. 2005", "glass beads", 1.8, 3.0, 2.3, 3.0)

CHANNEL_RUNOUT_FITS = (LUBE_2005, LAJEUNESSE_2005)


def envelope(a: float):
    """(lowest, highest) of the published fits that hold at a, or None where none holds."""
    values = [v for v in (f.runout_ratio(a) for f in CHANNEL_RUNOUT_FITS) if v is not None]
    return (min(values), max(values)) if values else None
