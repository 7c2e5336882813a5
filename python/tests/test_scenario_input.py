"""Scenario input from Python: overrides as the command line's --set, and errors that name the
file, line and key exactly as `talus run` does."""
import tomllib

import pytest

import talus
from conftest import REPOSITORY, SCENARIOS, SETTLING_BOX


def test_overrides_change_values():
    sim = talus.load(SCENARIOS / "free_fall.toml", overrides={"species.ball.radius": 0.02, "run.time_step": 5e-5})
    assert sim.radii[0] == 0.02 and sim.dt == 5e-5
    assert tomllib.loads(sim.scenario_toml)["species"]["ball"]["radius"] == 0.02
    # Vectors and strings take their TOML form; the command line's KEY=VALUE strings work too.
    sim = talus.load(SCENARIOS / "free_fall.toml", overrides={"domain.gravity": [0.0, 0.0, -1.62]})
    assert list(sim.gravity) == [0, 0, -1.62]
    sim = talus.load(SCENARIOS / "free_fall.toml", overrides=["particles[0].velocity=[0.0, 0.5, 0.0]"])
    assert list(sim.velocities[0]) == [0, 0.5, 0]
    sim = talus.load(SETTLING_BOX, overrides={"contact.model": "memoryless", "run.seed": 7})
    scenario = tomllib.loads(sim.scenario_toml)
    assert scenario["contact"]["model"] == "memoryless" and scenario["run"]["seed"] == 7


def test_friction_override_changes_the_run():
    a = talus.load(SETTLING_BOX)
    b = talus.load(SETTLING_BOX, overrides={"contact.friction": 0.1})
    for sim in (a, b):
        sim.run(steps=2000)
    assert (a.positions != b.positions).any()


def test_a_misspelt_key_names_file_line_and_key(tmp_path):
    text = (SCENARIOS / "free_fall.toml").read_text().replace("normal_restitution", "normal_restitutoin")
    line = next(k for k, l in enumerate(text.splitlines(), 1) if "normal_restitutoin" in l)
    path = tmp_path / "typo.toml"
    path.write_text(text)
    with pytest.raises(talus.ScenarioError) as error:
        talus.load(path)
    message = str(error.value)
    assert message.startswith(f"{path}:{line}: contact.normal_restitutoin: unknown key"), message
    assert "did you mean contact.normal_restitution?" in message
    assert isinstance(error.value, ValueError)
    assert error.value.messages == message.splitlines()


def test_a_bad_override_is_blamed_on_the_override():
    with pytest.raises(talus.ScenarioError, match=r"^--set species\.ball\.radius: must be positive"):
        talus.load(SCENARIOS / "free_fall.toml", overrides={"species.ball.radius": -1.0})
    with pytest.raises(talus.ScenarioError, match=r"^--set contact\.fricton: unknown key"):
        talus.load(SCENARIOS / "free_fall.toml", overrides={"contact.fricton": 0.3})


def test_a_missing_file_is_a_scenario_error(tmp_path):
    with pytest.raises(talus.ScenarioError, match="cannot open"):
        talus.load(tmp_path / "none.toml")


def test_a_blow_up_stops_the_run_with_its_step():
    # A sphere that leaves the domain (domain.on_leave = "error"): thrown upwards out of the box.
    sim = talus.load(SCENARIOS / "free_fall.toml", overrides={"particles[0].velocity": [0.0, 0.0, 20.0]})
    with pytest.raises(talus.BlowUpError) as error:
        sim.run(steps=1000)
    assert error.value.quantity == "position" and error.value.particles == [0]
    assert 0 < error.value.step <= 1000 and error.value.step == sim.steps


def test_a_study_scenario_warns_that_its_own_phases_do_not_run():
    with pytest.warns(UserWarning, match="^dam_break: the study's own phases"):
        sim = talus.load(REPOSITORY / "examples" / "dam_break_small.toml")
    assert sim.particle_count == 400
