"""design: a real robot in SI units, as the command line designs it."""

import pathlib

import pytest

import capsubot
from conftest import cli_json, run_cli, same

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "robot.toml"

# The example robot of docs/design.md (examples/robot.toml).
ROBOT = dict(m1=0.2, L=0.02, mu=0.3, e=0.7, force_amplitude=0.5, force_bias=0.1)
CLI_ROBOT = ["--m1", 0.2, "--L", 0.02, "--mu", 0.3, "--e", 0.7, "--force-amplitude", 0.5,
             "--force-bias", 0.1]


def test_equals_the_command_line():
    found = capsubot.design(**ROBOT, frequency=20)
    assert same(found, cli_json("design", *CLI_ROBOT, "--frequency", 20))
    assert found["status"] == "ok" and found["one_impact"]["status"] == "ok"
    # The gait's robustness, in mu, e and kg (docs/design.md): its lower limit in m2 is the
    # period doubling where the stable design sits, 0.2128 kg.
    assert set(found["robustness"]) == {"mu", "e", "m2_kg"}
    assert found["robustness"]["m2_kg"]["down"]["type"] == "period_doubling"
    assert found["robustness"]["m2_kg"]["down"]["m2_kg"] == pytest.approx(0.2128, abs=1e-4)
    ranged = capsubot.design(**ROBOT, frequency_range=(15, 25), m2_range=(0.01, 1),
                             scan_points=8, rho_max=0.8)
    assert same(ranged, cli_json("design", *CLI_ROBOT, "--frequency-range", "15:25", "--m2-range",
                              "0.01:1", "--scan-points", 8, "--rho-max", 0.8))


def test_band_levels_equal_the_command_line():
    found = capsubot.design(**ROBOT, frequency=20, band_levels=[0.9, 0.8])
    assert same(found, cli_json("design", *CLI_ROBOT, "--frequency", 20, "--band-levels",
                                "0.9,0.8"))
    for name in ("mu", "e", "m2_kg"):
        levels = found["robustness"][name]["band"]["levels"]
        assert [level["level"] for level in levels] == [0.9, 0.8]


def test_fourier_force_equals_the_command_line():
    robot = {k: v for k, v in ROBOT.items() if k != "force_amplitude"}
    found = capsubot.design(**robot, force_sin=[0.5, 0.1], force_cos=[0.0, 0.05], frequency=20)
    assert same(found, cli_json("design", *CLI_ROBOT[:-4], "--force-bias", 0.1, "--force-sin",
                             "0.5,0.1", "--force-cos", "0,0.05", "--frequency", 20))


def test_bad_input_names_the_parameter():
    with pytest.raises(ValueError) as err:
        capsubot.design(**{**ROBOT, "e": 1.3}, frequency=20)
    assert str(err.value) == "restitution e = 1.3 is invalid: expected 0 <= e <= 1"
    # The rules of the command line's settings (the library's), in keyword names.
    with pytest.raises(ValueError) as err:
        capsubot.design(**ROBOT)
    assert str(err.value) == ("setting frequency or frequency_range is missing: give frequency "
                              "(or frequency in the config file)")
    with pytest.raises(ValueError) as err:
        capsubot.design(**ROBOT, frequency=20, frequency_range=(10, 30))
    assert str(err.value) == ("settings frequency and frequency_range are both given as keyword "
                              "arguments: expected one of them")
    with pytest.raises(ValueError) as err:
        capsubot.design(**ROBOT, frequency_range=(30, 10))
    assert str(err.value) == ("frequency_range = 30:10 is invalid: expected MIN:MAX with "
                              "MIN < MAX")
    with pytest.raises(ValueError) as err:
        capsubot.design(**ROBOT, frequency=20, scan_points=6.5)
    assert str(err.value) == ("scan_points = 6.5 is invalid: expected an integer "
                              "-2147483648 <= n <= 2147483647")


def test_from_rest_equals_the_command_line():
    # Small budgets so that the search ends on its evaluation budget, not on the clock (the
    # result is then deterministic); only the search's wall-clock seconds differ.
    budget = dict(from_rest_starts="3x3", reach_starts="2x2", reach_evaluations=6,
                  reach_local_evaluations=2, threads=1)
    found = capsubot.design(**ROBOT, frequency=20, from_rest=True, **budget)
    expected = cli_json("design", *CLI_ROBOT, "--frequency", 20, "--from-rest",
                        "--from-rest-starts", "3x3", "--reach-starts", "2x2",
                        "--reach-evaluations", 6, "--reach-local-evaluations", 2,
                        "--threads", 1)
    assert same(found, expected)  # no wall-clock time in either
    assert set(found["from_rest_best"]) >= {"forward", "backward", "evaluations"}
    assert "from_rest_best" not in capsubot.design(**ROBOT, frequency=20)


def test_config_file_equals_the_command_line():
    found = capsubot.design(config=str(EXAMPLE))
    assert same(found, cli_json("design", "--config", EXAMPLE))
    assert found["status"] == "ok"
    # A keyword overrides the file, as a flag does.
    moved = capsubot.design(config=str(EXAMPLE), frequency=25, mu=0.25)
    assert same(moved, cli_json("design", "--config", EXAMPLE, "--frequency", 25, "--mu", 0.25))
    assert moved["one_impact"]["frequency_hz"] == 25
    assert moved["one_impact"] != found["one_impact"]


def test_config_file_refusals_are_the_command_lines(tmp_path):
    # The file's own messages are the program's word for word (keys as the file writes them).
    bad_key = tmp_path / "bad_key.toml"
    bad_key.write_text(EXAMPLE.read_text() + "mass = 1\n")
    bad_value = tmp_path / "bad_value.toml"
    bad_value.write_text(EXAMPLE.read_text().replace("mu = 0.3", 'mu = "rough"'))
    for path, start, end in [
            (bad_key, "mass = 1 in ", f"{bad_key} is invalid: unknown key, expected one of m1, L, "
             "mu, g, e, force-amplitude, force-bias, force-cos, force-sin, frequency, "
             "frequency-range, m2-range, margin, margin-stroke, stick-margin, rho-max, "
             "scan-points"),
            (bad_value, "mu = ", f"'rough' in {bad_value} is invalid: expected a number")]:
        with pytest.raises(ValueError) as err:
            capsubot.design(config=str(path))
        assert str(err.value).startswith(start) and str(err.value).endswith(end), str(err.value)
        status, _, stderr = run_cli("design", "--config", path)
        assert status == 2
        assert stderr == f"capsubot design: error: {err.value}\n"
    # A missing setting names the keyword and the file's key.
    only_m1 = tmp_path / "m1.toml"
    only_m1.write_text("m1 = 0.2\n")
    with pytest.raises(ValueError) as err:
        capsubot.design(config=str(only_m1), L=0.02, mu=0.3, e=0.7, force_bias=0.1,
                        force_amplitude=0.5)
    assert str(err.value) == ("setting frequency or frequency_range is missing: give frequency "
                              "(or frequency in the config file)")
    with pytest.raises(OSError) as err:
        capsubot.design(config=str(tmp_path / "none.toml"))
    assert str(err.value) == (f"config {tmp_path / 'none.toml'} cannot be read: No such file "
                              "or directory")


# The drive design of the example robot without its force, with small budgets so that the
# search ends on its evaluation budgets (deterministic) within seconds.
DRIVE_ROBOT = dict(m1=0.2, L=0.02, mu=0.3, e=0.7, frequency_range=(15, 25), m2_range=(0.1, 0.4))
CLI_DRIVE_ROBOT = ["--m1", 0.2, "--L", 0.02, "--mu", 0.3, "--e", 0.7, "--frequency-range",
                   "15:25", "--m2-range", "0.1:0.4"]
DRIVE_BUDGET = dict(from_rest_starts="2x2", reach_starts="2x2", reach_evaluations=6,
                    reach_local_evaluations=2, threads=1)
CLI_DRIVE_BUDGET = ["--from-rest-starts", "2x2", "--reach-starts", "2x2", "--reach-evaluations",
                    6, "--reach-local-evaluations", 2, "--threads", 1]


def test_drive_equals_the_command_line():
    found = capsubot.design(**DRIVE_ROBOT, drive="sine", force_max=0.6, **DRIVE_BUDGET)
    assert same(found, cli_json("design", *CLI_DRIVE_ROBOT, "--drive", "sine", "--force-max",
                                0.6, *CLI_DRIVE_BUDGET))
    pulse = capsubot.design(**DRIVE_ROBOT, drive="pulse", force_max=0.6, pulse_levels=2,
                            drive_evaluations=4, drive_polishes=1, drive_local_evaluations=2,
                            drive_refine_evaluations=0, drive_screens=0, **DRIVE_BUDGET)
    assert same(pulse, cli_json("design", *CLI_DRIVE_ROBOT, "--drive", "pulse", "--force-max",
                                0.6, "--pulse-levels", 2, "--drive-evaluations", 4,
                                "--drive-polishes", 1, "--drive-local-evaluations", 2,
                                "--drive-refine-evaluations", 0, "--drive-screens", 0,
                                *CLI_DRIVE_BUDGET))
    assert pulse != found


def test_drive_refusals_are_the_command_lines():
    # (keywords, flags, the module's message, the program's): one rule, each in its own names.
    cases = [
        (dict(drive="sine"), ["--drive", "sine"],
         "setting force_max is missing: drive needs the motor's peak force, give force_max",
         "setting force-max is missing: --drive needs the motor's peak force, give --force-max"),
        (dict(drive="sine", force_max=0.6, force_bias=0.1),
         ["--drive", "sine", "--force-max", 0.6, "--force-bias", 0.1],
         "setting force_bias is invalid with drive: expected no motor force (the drive search "
         "chooses it; give the motor's peak with force_max)",
         "setting force-bias is invalid with --drive: expected no motor force (the drive search "
         "chooses it; give the motor's peak with --force-max)"),
        (dict(drive="sine", force_max=0.6, harmonics=3),
         ["--drive", "sine", "--force-max", 0.6, "--harmonics", 3],
         "harmonics is invalid with drive='sine': expected harmonics only with drive='fourier'",
         "--harmonics is invalid with --drive sine: expected --harmonics only with --drive "
         "fourier"),
        (dict(drive="sine", force_max=0.6, from_rest=True),
         ["--drive", "sine", "--force-max", 0.6, "--from-rest"],
         "from_rest is invalid with drive: expected one of them (drive searches the force "
         "itself)",
         "--from-rest is invalid with --drive: expected one of them (--drive searches the force "
         "itself)"),
        (dict(drive="pulse", force_max=0.6, pulse_levels=40),
         ["--drive", "pulse", "--force-max", 0.6, "--pulse-levels", 40],
         "pulse_levels = 40 is invalid: expected 2 <= levels <= 16",
         "--pulse-levels = 40 is invalid: expected 2 <= levels <= 16"),
    ]
    for keywords, flags, module_message, program_message in cases:
        with pytest.raises(ValueError) as err:
            capsubot.design(**DRIVE_ROBOT, **keywords)
        assert str(err.value) == module_message
        status, _, stderr = run_cli("design", *CLI_DRIVE_ROBOT, *flags)
        assert status == 2
        assert stderr == f"capsubot design: error: {program_message}\n"
    with pytest.raises(ValueError) as err:
        capsubot.design(**DRIVE_ROBOT, drive="square", force_max=0.6)
    assert str(err.value) == "drive='square' is invalid: expected 'sine', 'fourier' or 'pulse'"
