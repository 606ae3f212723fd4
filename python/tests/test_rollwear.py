# The bindings against the command line: the same case gives the same numbers to the bit (both run the same
# library code on the same inputs, and the CSV files hold every number in the shortest text that reads back
# exactly), plus closed forms of Hertz's contact; errors as the typed exceptions; Ctrl-C; logging.
import csv
import logging
import math
import os
import signal
import threading
import time

import numpy as np
import pytest

import rollwear

# Hertz's peak pressure p0 = 3 F / (2 pi a b) (docs/physics.md §2) holds to rounding
HERTZ_RTOL = 1e-12
# the mean cell pressures integrate each strip's semi-ellipse exactly; over y the strips are a midpoint rule on
# 80 strips, whose error on the semi-ellipsoid is of order (1/80)^1.5 ~ 1.4e-3
LOAD_QUADRATURE_RTOL = 2e-3


def read_csv(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    header, body = rows[0], rows[1:]
    return {name: [r[i] for r in body] for i, name in enumerate(header)}


def numbers(column):
    return np.array([float(v) for v in column])


PAPER = {  # cases/paper.yaml as a dict
    "name": "paper",
    "bodies": {
        "body1": {"Rx_m": 0.020, "Ry_m": 0.500, "E_Pa": 210.0e9, "nu": 0.28},
        "body2": {"Rx_m": 0.025, "Ry_m": math.inf, "E_Pa": 210.0e9, "nu": 0.28},
    },
    "load": {"normal_load_N": 1500},
    "kinematics": {"speed_m_per_s": 1.0, "xi": 1.0e-3, "eta": 0, "phi_per_m": 0},
    "friction": {"mu": 0.3},
    "solver": {"nx": 80, "ny": 80},  # tangential: the default, relaxed
}


def test_contact_equals_the_command_line(source, cli, tmp_path, monkeypatch):
    monkeypatch.chdir(source)
    # without fields, as --no-fields (both still solve with the fields, which the subsurface stresses need;
    # with subsurface=False, --no-subsurface, neither would: the march sums Fx in another order, 1 ulp apart)
    r = rollwear.contact("cases/paper.yaml", fields=False)  # the path as written in the issue and the README
    p = cli("contact", "cases/paper.yaml", "-o", tmp_path, "--no-fields")
    assert p.returncode == 0, p.stderr
    summary = read_csv(tmp_path / "summary.csv")
    for key in ("a_m", "b_m", "p0_Pa", "approach_m", "C11", "C22", "C23", "C33", "L_m_per_Pa", "Fx_N", "Fy_N",
                "Mz_N_m", "power_W", "creep_work_W", "stick_fraction"):
        assert r["summary"][key] == float(summary[key][0]), key
    assert r["summary"]["scheme"] == summary["scheme"][0]
    strips = read_csv(tmp_path / "strips.csv")
    assert r["strips"].keys() == strips.keys()
    for key, column in strips.items():
        np.testing.assert_array_equal(r["strips"][key], numbers(column), err_msg=key)
    assert r["summary"]["normal_solver"] == "hertz"
    assert r["summary"]["error_estimate"] == "not estimated"  # docs/fidelity.md: a contact run makes none
    assert "not estimated against the exact physics" in cli("contact", "cases/paper.yaml", "-o", tmp_path / "e",
                                                             "--no-fields").stdout
    # the subsurface maxima, as subsurface.csv's (body, measure) rows
    maxima = read_csv(tmp_path / "subsurface.csv")
    assert len(maxima["body"]) == 10
    for body, measure, value, z in zip(maxima["body"], maxima["measure"], maxima["value_Pa"], maxima["z_m"]):
        peak = r["subsurface"]["body" + body][measure]
        assert peak["value_Pa"] == float(value), (body, measure)
        assert peak["z_m"] == float(z), (body, measure)
    assert "fatigue" not in r["subsurface"]["body1"]  # no shear_yield_Pa in the case
    assert "subsurface" not in rollwear.contact("cases/paper.yaml", fields=False, subsurface=False)


def test_contact_dang_van_equals_the_command_lines(source, cli, tmp_path):
    text = (source / "cases" / "paper.yaml").read_text()
    body = "body2: { Rx_m: 0.025, Ry_m: .inf,  E_Pa: 210.0e9, nu: 0.28"
    assert body in text
    text = text.replace(body, body + ", dang_van: { a: 0.3, b_Pa: 300.0e6 }")
    text = text.replace("solver:     { nx: 80, ny: 80", "solver:     { nx: 24, ny: 24")
    case = tmp_path / "paper-dv.yaml"
    case.write_text(text)
    r = rollwear.contact(str(case), fields=False)
    p = cli("contact", case, "-o", tmp_path / "out", "--no-fields")
    assert p.returncode == 0, p.stderr
    rows = read_csv(tmp_path / "out" / "dang_van.csv")
    assert rows["body"] == ["2"]
    d = r["subsurface"]["body2"]["dang_van"]
    for key in ("a", "b_Pa", "index_max", "x_m", "y_m", "z_m", "tau_Pa", "hydrostatic_Pa"):
        assert d[key] == float(rows[key][0]), key
    assert "dang_van" not in r["subsurface"]["body1"]


def test_lubricated_contact_film_and_flash_temperature_equal_the_command_line(source, cli, tmp_path):
    case = "tests/data/lubrication/paper-lubricated.yaml"
    r = rollwear.contact(str(source / case), fields=False)
    p = cli("contact", case, "-o", tmp_path, "--no-fields")
    assert p.returncode == 0, p.stderr
    summary = read_csv(tmp_path / "summary.csv")
    for key in ("entrainment_m_per_s", "Rx_m", "ellipticity_k", "h_min_m", "h_central_m", "lambda", "regime_mu",
                "regime_wear_factor", "v1_m_per_s", "v2_m_per_s", "flash_max_K", "heat_share_body1",
                "peclet_body1", "peclet_body2", "contact_temperature_C", "scuffing_margin_K"):
        assert r["summary"][key] == float(summary[key][0]), key
    assert r["summary"]["regime"] == summary["regime"][0] == "boundary"
    assert "h_min_m" not in rollwear.contact(str(source / "cases" / "paper.yaml"), fields=False)["summary"]


def test_contact_fields_equal_the_command_lines_and_are_hertz(source, cli, tmp_path):
    r = rollwear.contact(str(source / "cases" / "paper.yaml"))
    s, f = r["summary"], r["fields"]
    p = cli("contact", "cases/paper.yaml", "-o", tmp_path)
    assert p.returncode == 0, p.stderr
    fields = read_csv(tmp_path / "fields.csv")  # strip by strip: j outer, i inner
    for key in ("pressure_Pa", "tau_x_Pa", "tau_y_Pa", "slip_x_m_per_s", "slip_y_m_per_s", "power_W_per_m2", "state"):
        np.testing.assert_array_equal(f[key].ravel(order="F"), numbers(fields[key]), err_msg=key)
    assert s["Fx_N"] == float(read_csv(tmp_path / "summary.csv")["Fx_N"][0])
    F = s["normal_load_N"]
    assert s["p0_Pa"] == pytest.approx(3 * F / (2 * math.pi * s["a_m"] * s["b_m"]), rel=HERTZ_RTOL)
    assert f["pressure_Pa"].shape == (s["nx"], s["ny"]) == (80, 80)
    dx, dy = np.diff(f["x_m"][:2])[0], np.diff(f["y_m"][:2])[0]
    assert f["pressure_Pa"].sum() * dx * dy == pytest.approx(F, rel=LOAD_QUADRATURE_RTOL)
    assert set(np.unique(f["state"])) <= {0, 1, 2}
    # the dissipated power per area integrates to the total, and to the strips' powers
    assert f["power_W_per_m2"].sum() * dx * dy == pytest.approx(s["power_W"], rel=1e-12)
    assert r["strips"]["power_W_per_m"].sum() * dy == pytest.approx(s["power_W"], rel=1e-12)


def test_a_dict_is_the_same_case(source):
    from_file = rollwear.contact(str(source / "cases" / "paper.yaml"), fields=False)
    from_dict = rollwear.contact(PAPER, fields=False)
    assert from_dict["summary"] == from_file["summary"]
    assert "fields" not in from_dict


def test_transient_equals_the_command_line(cli, tmp_path):
    case = dict(PAPER, name="startup", solver={"nx": 20, "ny": 20},
                kinematics={"speed_m_per_s": {"ramp": [0.0, 0.0, 1.0e-4, 1.8]}, "xi": 0.001},
                transient={"scheme": "shift", "t_end_s": 2.0e-4, "snapshots_s": [1.0e-4]})
    (tmp_path / "startup.yaml").write_text(rollwear.case_yaml(case))
    p = cli("transient", tmp_path / "startup.yaml", "-o", tmp_path / "out", "-q")
    assert p.returncode == 0, p.stderr
    r = rollwear.transient(case)
    ts = read_csv(tmp_path / "out" / "timeseries.csv")
    for key, column in ts.items():
        if key == "step_scheme":
            assert r["timeseries"][key] == column
        else:
            np.testing.assert_array_equal(r["timeseries"][key], numbers(column), err_msg=key)
    energy = read_csv(tmp_path / "out" / "strip_energy.csv")
    np.testing.assert_array_equal(r["strips"]["energy_J_per_m"], numbers(energy["energy_J_per_m"]))
    power = read_csv(tmp_path / "out" / "strip_power.csv")
    np.testing.assert_array_equal(r["strips"]["power_W_per_m"].ravel(), numbers(power["power_W_per_m"]))
    snap = read_csv(tmp_path / "out" / "snapshot_1.csv")  # strip by strip: j outer, i inner
    np.testing.assert_array_equal(r["snapshots"][0]["tau_x_Pa"].ravel(order="F"), numbers(snap["tau_x_Pa"]))
    summary = read_csv(tmp_path / "out" / "summary.csv")
    assert r["summary"]["dissipated_J"] == float(summary["dissipated_J"][0])
    assert r["summary"]["error_estimate"] == "not estimated"  # docs/fidelity.md: a transient run makes none
    assert r["summary"]["tangential_model"] == "relaxed"


def test_run_with_fatigue_equals_the_command_line(source, cli, tmp_path):
    # the shipped fatigue case (docs/fatigue.md): its life ends by fatigue; the damage column and the margins
    # of report.txt are the Python result's
    case = source / "cases" / "paper-wear-fatigue.yaml"
    p = cli("run", case, "-o", tmp_path, "-q")
    assert p.returncode == 0, p.stderr
    r = rollwear.run(case)
    rows = read_csv(tmp_path / "summary.csv")
    assert "max_damage" in rows
    for key, column in rows.items():
        np.testing.assert_array_equal(r["steps"][key], numbers(column), err_msg=key)
    report = dict(line.split(": ", 1) for line in (tmp_path / "report.txt").read_text().splitlines() if ": " in line)
    assert r["summary"]["ended_by"] == report["ended_by"] == "fatigue"
    assert r["summary"]["fatigue_law"] == report["fatigue_law"] == "burstow"
    for key in ("revolutions", "depth_fraction", "max_damage", "max_damage_y_m", "max_tgamma_N"):
        assert r["summary"][key] == float(report[key]), key
    assert 0 < r["summary"]["depth_fraction"] < 1
    assert not any(key.startswith("dang_van") for key in r["summary"])  # no bodies.bodyN.dang_van


def test_run_with_dang_van_equals_the_command_line(source, cli, tmp_path):
    # Dang Van's index on the final worn contact (docs/fatigue.md §4c): report.txt's keys are the Python result's
    text = (source / "cases" / "paper-wear-fatigue.yaml").read_text()
    text = text.replace("nx: 80, ny: 80", "nx: 24, ny: 24")
    roller = "body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28"
    assert roller in text
    text = text.replace(roller, roller + ", dang_van: { a: 0.3, b_Pa: 300.0e6 }")
    case = tmp_path / "dv.yaml"
    case.write_text(text)
    p = cli("run", case, "-o", tmp_path / "out", "-q")
    assert p.returncode == 0, p.stderr
    r = rollwear.run(case)
    report = dict(line.split(": ", 1) for line in (tmp_path / "out" / "report.txt").read_text().splitlines()
                  if ": " in line)
    for key in ("dang_van_body1_index", "dang_van_body1_depth_m", "dang_van_body1_y_m"):
        assert r["summary"][key] == float(report[key]), key
    assert r["summary"]["dang_van_body1_index"] > 0
    assert "dang_van_body2_index" not in r["summary"]


def test_run_equals_the_command_line(source, cli, tmp_path):
    case = source / "cases" / "paper-wear.yaml"
    p = cli("run", case, "-o", tmp_path, "-q")
    assert p.returncode == 0, p.stderr
    r = rollwear.run(case)
    rows = read_csv(tmp_path / "summary.csv")
    for key, column in rows.items():
        np.testing.assert_array_equal(r["steps"][key], numbers(column), err_msg=key)
    report = dict(line.split(": ", 1) for line in (tmp_path / "report.txt").read_text().splitlines() if ": " in line)
    assert r["summary"]["ended_by"] == report["ended_by"] == "edge"
    assert r["summary"]["revolutions"] == float(report["revolutions"])
    # which models ran and the fast models' error estimate (docs/fidelity.md), as report.txt says
    for key in ("tangential_model", "fidelity", "error_estimate_of"):
        assert r["summary"][key] == report[key]
    assert report["error_estimate_of"] == "the steady duty cycle"
    assert r["summary"]["exact_solves"] == int(report["exact_solves"]) == 1
    for key in ("error_estimate_N", "error_power_rel", "error_power_l1"):
        assert r["summary"][key] == float(report[key]), key
    text = (tmp_path / "summary.csv").read_text()
    assert "# models: normal auto, tangential relaxed, fidelity fast\n" in text
    assert f"per-strip power L1 {report['error_power_l1']}; of the steady duty cycle\n" in text
    body1 = r["profiles"]["body1"]
    last = sorted((tmp_path / "snapshots").glob("snapshot_*_body1.csv"))[-1]
    worn = read_csv(last)
    np.testing.assert_array_equal(body1["depth_m"][-1], numbers(worn["depth_m"]))
    np.testing.assert_array_equal(body1["y_m"], numbers(worn["y_m"]))
    assert body1["revolutions"][-1] == r["summary"]["revolutions"]
    assert body1["depth_m"].shape == (len(body1["revolutions"]), len(body1["y_m"]))


def test_sweep_runs_its_cases(source, tmp_path):
    sweep = tmp_path / "two.yaml"
    sweep.write_text(f"base: {source / 'cases' / 'paper-wear.yaml'}\n"
                     "axes:\n  - { key: friction.mu, values: [0.3, 0.4] }\n")
    s = rollwear.sweep(sweep, output_dir=tmp_path / "out", threads=2)
    res = s["results"]
    np.testing.assert_array_equal(res["index"], [0, 1])
    np.testing.assert_array_equal(res["friction.mu"], [0.3, 0.4])
    assert res["status"] == ["ok", "ok"]
    # case 0 is the base case itself (mu 0.3): the same life as rollwear.run's, to the bit
    alone = rollwear.run(source / "cases" / "paper-wear.yaml")
    assert res["life_revolutions"][0] == alone["summary"]["revolutions"]
    assert res["max_depth_m"][0] == alone["summary"]["max_depth_m"]
    # the fidelity and its error estimate, as the case's report has them (docs/fidelity.md)
    assert res["fidelity"] == ["fast", "fast"]
    np.testing.assert_array_equal(res["exact_solves"], [1, 1])
    assert res["error_power_l1"][0] == alone["summary"]["error_power_l1"]
    assert res["error_power_rel"][0] == alone["summary"]["error_power_rel"]
    assert os.path.exists(os.path.join(s["directory"], "case_0001", "report.txt"))


def test_sweep_carries_the_failure_modes_columns(source, tmp_path):
    # docs/fatigue.md §5: with wear.fatigue, a shear yield stress and a thermal section the sweep's results.csv and
    # the Python result carry max_damage, depth_fraction, shakedown_margin and scuffing_margin_K, each case's
    # report.txt value; one case ends by fatigue (damage 1), the slower one by wear with damage below 1
    text = (source / "cases" / "paper-wear-fatigue.yaml").read_text()
    text = text.replace("nx: 80, ny: 80", "nx: 24, ny: 24")
    text = "\n".join(l for l in text.splitlines() if not l.lstrip().startswith(("snapshots_revolutions", "output:")))
    text = text.replace("body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28 }",
                        "body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28, shear_yield_Pa: 5.0e8 }")
    assert "shear_yield_Pa" in text
    text += ("\nthermal:\n"
             "  body1: { conductivity_W_per_m_K: 46, density_kg_per_m3: 7850, specific_heat_J_per_kg_K: 470 }\n"
             "  body2: { conductivity_W_per_m_K: 46, density_kg_per_m3: 7850, specific_heat_J_per_kg_K: 470 }\n"
             "  bulk_temperature_C: 80\n  critical_temperature_C: 1000\n")
    (tmp_path / "fatigue.yaml").write_text(text)
    sweep = tmp_path / "sweep.yaml"
    sweep.write_text("base: fatigue.yaml\naxes:\n  - { key: kinematics.xi, values: [0.05, 0.1] }\n")
    s = rollwear.sweep(sweep, output_dir=tmp_path / "out", threads=2)
    res = s["results"]
    columns = ("max_damage", "depth_fraction", "shakedown_margin", "scuffing_margin_K")
    table = read_csv(tmp_path / "out" / "results.csv")
    header = (tmp_path / "out" / "results.csv").read_text().splitlines()[0].split(",")
    assert header[header.index("worn_volume_m3") + 1:header.index("worn_volume_m3") + 5] == list(columns)
    assert res["status"] == ["ok", "ok"]
    assert list(res["ended_by"]) == ["edge", "fatigue"]
    for i in range(2):
        report = dict(line.split(": ", 1) for line in
                      (tmp_path / "out" / f"case_{i:04d}" / "report.txt").read_text().splitlines() if ": " in line)
        for key in columns:
            assert math.isfinite(res[key][i]), (key, i)
            assert res[key][i] == float(report[key]) == float(table[key][i]), (key, i)
    assert 0.1 < res["max_damage"][0] < 1
    assert res["max_damage"][1] == pytest.approx(1, abs=1e-9)  # located to the root finding's tolerance
    assert res["shakedown_margin"][0] > 0 and res["scuffing_margin_K"][0] > 0


def test_sweep_arguments_are_checked_as_the_command_line_checks_them(source, tmp_path):
    sweep = tmp_path / "two.yaml"
    sweep.write_text(f"base: {source / 'cases' / 'paper-wear.yaml'}\n"
                     "axes:\n  - { key: friction.mu, values: [0.3, 0.4] }\n")
    # shard as --shard writes it: "K/N" is (K, N); a form neither is refused naming the key
    for bad in ("1-2", "1/2/3", "a/b", 3, (1, 2, 3), (1.0, 2)):
        with pytest.raises(rollwear.InputError) as e:
            rollwear.sweep(sweep, output_dir=tmp_path / "no", shard=bad)
        assert e.value.key == "shard" and "expected (K, N) or \"K/N\"" in str(e.value), (bad, str(e.value))
    with pytest.raises(rollwear.InputError) as e:
        rollwear.sweep(sweep, output_dir=tmp_path / "no", shard="3/2")
    assert e.value.key == "shard" and "1 <= K <= N, got 3/2" in str(e.value)
    # threads: -j -1 is refused by the command line, threads=-1 here; 1.5 is not a count
    for bad in (-1, 1.5, True):
        with pytest.raises(rollwear.InputError) as e:
            rollwear.sweep(sweep, output_dir=tmp_path / "no", threads=bad)
        assert e.value.key == "threads", (bad, str(e.value))
    assert not (tmp_path / "no").exists()
    # "2/2": the second case only, as --shard 2/2 runs it
    s = rollwear.sweep(sweep, output_dir=tmp_path / "half", threads=1, shard="2/2")
    np.testing.assert_array_equal(s["results"]["index"], [1])


def test_a_unit_slip_is_refused_by_the_library_as_by_the_command_line():
    # E in GPa written as Pa: the reader's plausibility bound, the same in Python as in the program
    bodies = dict(PAPER["bodies"], body1=dict(PAPER["bodies"]["body1"], E_Pa=210))
    with pytest.raises(rollwear.InputError) as e:
        rollwear.contact(dict(PAPER, bodies=bodies))
    assert e.value.key == "bodies.body1.E_Pa" and "GPa or MPa written as Pa" in str(e.value), str(e.value)


def test_a_cam_case_is_refused_naming_where_it_runs(source):
    cam = source / "cases" / "cam-follower.yaml"
    line = 1 + next(i for i, l in enumerate(cam.read_text().splitlines()) if l.startswith("cam:"))
    for function in (rollwear.run, rollwear.contact, rollwear.transient):
        with pytest.raises(rollwear.InputError) as e:
            function(cam)
        assert (e.value.file, e.value.line, e.value.key) == (str(cam), line, "cam"), str(e.value)
        assert "rollwear run CASE" in str(e.value) and "bodies: required" not in str(e.value)


def test_a_bad_key_is_an_input_error_with_its_place(source, cli, tmp_path):
    text = (source / "cases" / "paper.yaml").read_text().replace("friction:", "frction:")
    line = 1 + text.splitlines().index(next(l for l in text.splitlines() if l.startswith("frction:")))
    case = tmp_path / "typo.yaml"
    case.write_text(text)
    with pytest.raises(rollwear.InputError) as e:
        rollwear.contact(case)
    assert (e.value.file, e.value.line, e.value.column, e.value.key) == (str(case), line, 1, "frction")
    assert isinstance(e.value, ValueError) and isinstance(e.value, rollwear.Error)
    assert cli("contact", case, "-o", tmp_path / "out").returncode == 2  # the CLI's bad input


def test_a_bad_value_in_a_dict_names_its_key():
    with pytest.raises(rollwear.InputError) as e:
        rollwear.contact(dict(PAPER, friction={"mu": -1}))
    assert e.value.file == "<dict>" and e.value.key == "friction.mu"
    assert rollwear.case_yaml(dict(PAPER, friction={"mu": -1})).splitlines()[e.value.line - 1].startswith("friction:")
    with pytest.raises(rollwear.InputError) as e:
        rollwear.run(PAPER)  # no wear: section
    assert e.value.key == "wear"


@pytest.mark.parametrize("kind, exception", [("case", rollwear.InputError), ("solver", rollwear.SolverError),
                                             ("normal", rollwear.SolverError),
                                             ("invalid_argument", rollwear.SolverError),
                                             ("runtime_error", rollwear.Error)])
def test_each_cpp_error_type_is_its_exception(kind, exception):
    # by the C++ type (lib/errors.h), as the program's exit status: 2 for CaseError, 1 for the others
    with pytest.raises(exception) as e:
        rollwear._rollwear._throw_for_test(kind)
    assert type(e.value) is exception
    if kind == "case":
        assert (e.value.file, e.value.line, e.value.column, e.value.key) == ("f.yaml", 3, 5, "friction.mu")


def test_ctrl_c_interrupts_a_long_call_with_the_gil_released():
    # 5 m rolled in shift steps of 5.6 um on 80 x 80 cells, a creepage ramp all along (no steady stretch to
    # skip): about 12 s if not interrupted (idle machine). The timer thread sending SIGINT runs only if the
    # call released the GIL.
    case = dict(PAPER, transient={"t_end_s": 5.0},
                kinematics={"speed_m_per_s": 1.0, "xi": {"ramp": [0.0, 0.0, 5.0, 1.0e-3]}})
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        rollwear.transient(case, fields=False)
    assert time.monotonic() - start < 3
    timer.join()


def test_transient_refuses_an_absurd_run_at_once_as_the_command_line():
    # t_end_s 1e9 s at 1 m/s: about 1.8e14 shift steps; the arrays would grow without bound (issue 26). The
    # library's check of output.max_bytes refuses it before the run, naming the key and its line.
    case = dict(PAPER, transient={"t_end_s": 1.0e9})
    start = time.monotonic()
    with pytest.raises(rollwear.InputError) as e:
        rollwear.transient(case, fields=False)
    assert time.monotonic() - start < 2
    assert e.value.key == "transient.t_end_s"
    assert "output.max_bytes = 1073741824" in str(e.value) and "force=True" in str(e.value)
    # a small run above a small limit is refused too, and runs with force=True
    small = dict(PAPER, transient={"t_end_s": 2.0e-5}, output={"max_bytes": 1000})
    with pytest.raises(rollwear.InputError):
        rollwear.transient(small, fields=False)
    assert rollwear.transient(small, fields=False, force=True)["summary"]["steps"] > 0


def test_wear_run_refuses_above_solver_max_memory_bytes(source, tmp_path):
    # the memory a wear run needs (the smoothing kernel of the worn profile's nodes) is estimated before the
    # run and refused above solver.max_memory_bytes, naming the profile's key (issue 26)
    text = (source / "cases" / "paper-wear.yaml").read_text().replace(
        "solver:     { normal: auto, nx: 80, ny: 80 }", "solver:     { normal: auto, nx: 80, ny: 80, max_memory_bytes: 1.0e4 }")
    assert "max_memory_bytes" in text
    case = tmp_path / "limited-wear.yaml"
    case.write_text(text)
    start = time.monotonic()
    with pytest.raises(rollwear.InputError) as e:
        rollwear.run(case)
    assert time.monotonic() - start < 2
    assert e.value.key == "profiles.body1"
    assert "solver.max_memory_bytes = 10000" in str(e.value)


def test_messages_go_to_python_logging(source, caplog):
    with caplog.at_level(logging.DEBUG, logger="rollwear"):
        rollwear.contact(str(source / "cases" / "paper.yaml"), fields=False)
    assert any(r.name == "rollwear" and "read from" in r.getMessage() for r in caplog.records)


def test_ctrl_c_stops_a_wear_life(source, tmp_path):
    # paper-wear in fixed steps of 1e4 revolutions: 1e6 steps to its budget, minutes if not interrupted
    text = (source / "cases" / "paper-wear.yaml").read_text().replace(
        "stepping: { method: adaptive, rtol: 1.0e-3, atol_m: 1.0e-9 }",
        "stepping: { method: fixed-revolutions, step_revolutions: 1.0e4, max_steps: 10000000 }")
    assert "fixed-revolutions" in text
    case = tmp_path / "long-wear.yaml"
    case.write_text(text)
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        rollwear.run(case)
    assert time.monotonic() - start < 3
    timer.join()
