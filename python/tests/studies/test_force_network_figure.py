"""The force-network figure (Huet et al. 2021, Fig. 14) of a dam break's force_network.csv:
every contact in panel (a), those above five times the mean force in panel (b)."""
from talus.studies import dam_break_plots


def test_strong_contacts_are_those_above_five_times_the_mean(tmp_path):
    # 19 contacts of 1 N and one of 40 N: the mean is 2.95 N, so only the last exceeds 5 <F>.
    rows = ["x_i,y_i,z_i,x_j,y_j,z_j,force,points"]
    for k in range(20):
        force = 40.0 if k == 19 else 1.0
        rows.append(f"{0.01 * k},0,0.0,{0.01 * k + 0.005},0,0.01,{force},1")
    (tmp_path / "force_network.csv").write_text("\n".join(rows) + "\n")
    assert dam_break_plots.force_network_figure(tmp_path) == (20, 1)
    assert (tmp_path / "fig14_force_network.png").stat().st_size > 10_000
