"""Fig. 10's published fits (Huet et al. 2021): each channel experiment's two branches, drawn on
their own ranges only (channel_runout_fits.py)."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from talus.studies import dam_break_plots  # noqa: E402
from talus.studies.channel_runout_fits import LAJEUNESSE_2005, LUBE_2005  # noqa: E402


def test_each_branch_is_drawn_on_its_own_range():
    fig, ax = plt.subplots()
    dam_break_plots.channel_runout_lines(ax, 6.0)
    lines = {line.get_label(): line for line in ax.get_lines()}
    plt.close(fig)
    assert set(lines) == {"Lube et al. 2005: 1.2 a (a < 1.8)", r"Lube et al. 2005: 1.9 a$^{2/3}$ (a > 2.8)",
                          "Lajeunesse et al. 2005: 1.8 a (a < 3)", r"Lajeunesse et al. 2005: 2.3 a$^{2/3}$ (a > 3)"}
    low = lines["Lube et al. 2005: 1.2 a (a < 1.8)"]
    assert max(low.get_xdata()) == LUBE_2005.a_low
    high = lines[r"Lajeunesse et al. 2005: 2.3 a$^{2/3}$ (a > 3)"]
    assert min(high.get_xdata()) == LAJEUNESSE_2005.a_high and max(high.get_xdata()) == 6.0
    assert high.get_ydata()[-1] == LAJEUNESSE_2005.runout_ratio(6.0)


def test_a_sweep_below_the_power_laws_draws_the_linear_fits_only():
    fig, ax = plt.subplots()
    dam_break_plots.channel_runout_lines(ax, 2.0)
    labels = [line.get_label() for line in ax.get_lines()]
    plt.close(fig)
    assert labels == ["Lube et al. 2005: 1.2 a (a < 1.8)", "Lajeunesse et al. 2005: 1.8 a (a < 3)"]
    assert LUBE_2005.runout_ratio(2.3) is None  # between Lube's two ranges neither fit is stated
