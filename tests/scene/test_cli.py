"""The ``contact`` command (contact.cli): the default scene end to end in a subprocess, the
shape of result.json, serial = --jobs 2 = a Dask cluster, the helpers, and user errors that
exit non-zero with a message and no traceback."""
from __future__ import annotations

import contextlib
import csv
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import contact
from contact import cli
from contact.scene import FIELDS, load_scene, run_scene

from cli_helpers import child_env, run_cli

SCENES = Path(__file__).resolve().parents[2] / "validation" / "scenes"


def contact_command(*args, cwd):
    """Run ``python -m contact ARGS`` in ``cwd``; the project is importable from anywhere."""
    return subprocess.run([sys.executable, "-m", "contact", *args], cwd=cwd, env=child_env(),
                          capture_output=True, text=True, timeout=300)


def cases_of(path):
    """The cases of a result.json, without the timing (which differs run to run)."""
    return json.loads(Path(path).read_text())["cases"]


# --------------------------------------------------------------------------
# the default scene, end to end
# --------------------------------------------------------------------------
@pytest.fixture(scope="module")
def default_run(tmp_path_factory):
    cwd = tmp_path_factory.mktemp("default")
    return contact_command("run", cwd=cwd), cwd


@pytest.mark.slow
def test_default_run_prints_the_table(default_run):
    proc, _ = default_run
    assert proc.returncode == 0, proc.stderr
    assert "Traceback" not in proc.stderr
    out = proc.stdout
    for column in ("x_left", "x_right", "alpha", "beta", "max p (sampled)", "K_left", "K_right",
                   "min sigma_xx", "max sigma_xx", "time ms", "c_R = 0.99361473"):
        assert column in out, column
    ref = contact.solve(contact.zhou2014(), contact.CylindricalPunch(100.0), load=0.01,
                        speed=0.6, friction=0.3, direction=-1)
    assert f"{ref.ends[0]:.10g}" in out and f"{ref.alpha:.8g}" in out


@pytest.mark.slow
def test_default_run_writes_into_contact_out(default_run):
    _, cwd = default_run
    out = cwd / "contact-out"
    names = {p.name for p in out.iterdir()}
    assert names == {"result.json", "sweep.csv", "pressure.csv", "sigma_xx.csv", "pressure.png",
                     "sigma_xx.png"}
    for png in ("pressure.png", "sigma_xx.png"):
        assert (out / png).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert (out / png).stat().st_size > 10_000


@pytest.mark.slow
def test_result_json_shape(default_run):
    _, cwd = default_run
    result = json.loads((cwd / "contact-out" / "result.json").read_text())
    assert list(result)[:4] == ["scene", "scene_file", "cases", "version"]
    assert {"timing_s", "units", "warnings"} <= set(result)
    assert result["version"] == "0.1.0" and result["timing_s"] > 0
    assert "stress" in result["units"]["statement"]
    echo = result["scene"]
    assert echo["motion"] == {"load": 0.01, "speed": 0.6, "friction": 0.3, "direction": -1}
    assert echo["punch"] == {"kind": "cylindrical", "radius": 100.0}
    (case,) = result["cases"]
    assert list(case) == ["inputs", "ends", "exponents", "pressure", "sigma_xx", "sif",
                          "diagnostics"]
    assert case["inputs"] == {"speed": 0.6, "friction": 0.3, "direction": -1, "load": 0.01,
                              "radius": 100.0}
    assert set(case["diagnostics"]) == {"n", "residual", "load_check"}
    for absent in set(FIELDS) - set(case):       # one zone: ends, exponents, sif, no zones
        assert absent in ("zones", "shear", "roots", "constants", "subsurface")
    ref = contact.solve(contact.zhou2014(), contact.CylindricalPunch(100.0), load=0.01,
                        speed=0.6, friction=0.3, direction=-1)
    assert case["ends"] == list(ref.ends)
    assert case["exponents"] == {"left": ref.beta, "right": ref.alpha}
    assert case["sif"] == {}                      # both ends free: no singular end
    X = np.round(np.linspace(-0.8, 0.8, 801), 3)      # the clean decimals -0.8, -0.798, ...
    for name in ("pressure", "sigma_xx"):
        assert case[name]["x"] == X.tolist()
        np.testing.assert_array_equal(case[name]["values"], getattr(ref, name)(X))
    with open(cwd / "contact-out" / "pressure.csv") as fh:
        rows = list(csv.reader(fh))
    assert rows[0] == ["X", "pressure"] and len(rows) == 802
    assert float(rows[401][1]) == case["pressure"]["values"][400]


# --------------------------------------------------------------------------
# sweeps: serial = --jobs 2 = a Dask cluster, in scene order
# --------------------------------------------------------------------------
SWEEP = SCENES / "fig1b_flat_friction.toml"


@pytest.fixture(scope="module")
def serial_sweep(tmp_path_factory):
    cwd = tmp_path_factory.mktemp("serial")
    proc = contact_command("run", str(SWEEP), "--out", "serial", "--quiet", cwd=cwd)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == ""                     # --quiet: no table, no list of files
    return cases_of(cwd / "serial" / "result.json")


@pytest.mark.slow
def test_sweep_with_two_processes_equals_serial(serial_sweep, tmp_path):
    proc = contact_command("run", str(SWEEP), "--out", "jobs2", "--jobs", "2", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    parallel = cases_of(tmp_path / "jobs2" / "result.json")
    assert parallel == serial_sweep
    assert [c["inputs"]["friction"] for c in parallel] == [0.0, 0.1, 0.3, 0.5]
    header = (tmp_path / "jobs2" / "sigma_xx.csv").read_text().splitlines()[0]
    assert header == "X,friction = 0,friction = 0.1,friction = 0.3,friction = 0.5"


@pytest.mark.slow
def test_sweep_on_a_dask_cluster_equals_serial(serial_sweep, tmp_path):
    distributed = pytest.importorskip("distributed", reason="optional extra sie-contact[dask]")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        rc = cli.main(["run", str(SWEEP), "--out", str(tmp_path / "dask"), "--quiet",
                       "--scheduler", cluster.scheduler_address])
    assert rc == 0
    assert cases_of(tmp_path / "dask" / "result.json") == serial_sweep


@pytest.mark.slow
def test_lean_sweep_on_a_dask_cluster_writes_the_serial_files(tmp_path, capsys):
    """A sweep of scalar fields through a cluster: the workers' texts come back a column at
    a time (contact.scene.batch.ChunkResults) and nothing is solved in this process first;
    result.json's cases, sweep.csv and the printed table are those of the serial run."""
    distributed = pytest.importorskip("distributed", reason="optional extra sie-contact[dask]")
    scene = tmp_path / "lean.toml"
    scene.write_text('[material]\npreset = "zhou2014"\n[punch]\nkind = "cylindrical"\n'
                     'radius = 100.0\n[motion]\nload = 0.01\n'
                     f"speed = {[round(0.05 * k, 2) for k in range(12)]}\n"
                     f"friction = {[round(0.04 * k, 2) for k in range(10)]}\n"
                     '[outputs]\nfields = ["ends", "exponents", "sif"]\n')
    def untimed_table(printed):             # each row's last cell is its time; paths differ
        return [line.rsplit(None, 1)[0] for line in printed.splitlines()
                if line.strip() and not line.startswith(("  total time", "  wrote"))]
    assert cli.main(["run", str(scene), "--out", str(tmp_path / "serial")]) == 0
    serial_table = untimed_table(capsys.readouterr().out)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        assert cli.main(["run", str(scene), "--out", str(tmp_path / "dask"),
                         "--scheduler", cluster.scheduler_address]) == 0
    assert untimed_table(capsys.readouterr().out) == serial_table and len(serial_table) > 10
    assert cases_of(tmp_path / "dask" / "result.json") == \
        cases_of(tmp_path / "serial" / "result.json")
    assert (tmp_path / "dask" / "sweep.csv").read_bytes() == \
        (tmp_path / "serial" / "sweep.csv").read_bytes()


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the pool forks on Linux")
def test_jobs_pool_forks_from_the_warm_process_on_linux():
    """--jobs N's workers are forked from the process that has imported the libraries and
    loaded the kernels (whatever the interpreter's default: "forkserver" from Python 3.14
    would have each worker import and load them again)."""
    with cli._executor(2, None) as ex:
        assert ex._mp_context.get_start_method() == "fork"
        assert ex.submit(os.getppid).result() == os.getpid()


#: scipy subpackages whose import would weigh on every start of the command and of every
#: worker that is not forked (scipy.optimize: ~0.15 s of a 0.55 s start), none of which
#: a punch of the paper needs: they are imported where a face of samples or a zone search
#: of a general face uses them.
_HEAVY_AT_START = ("scipy.optimize", "scipy.interpolate", "scipy.differentiate")


@pytest.mark.slow
def test_a_moving_sweep_runs_without_the_heavy_scipy_subpackages(tmp_path):
    """The default scene's punch at a speed (the Rayleigh speed found: the bisection of
    contact.constants) and with friction, from a fresh interpreter: scipy.optimize,
    scipy.interpolate and scipy.differentiate are never imported."""
    scene = tmp_path / "moving.toml"
    scene.write_text('title = "moving"\n[material]\npreset = "zhou2014"\n[punch]\n'
                     'kind = "cylindrical"\nradius = 100.0\n[motion]\nload = 0.01\n'
                     'speed = [0.0, 0.5, 0.9]\nfriction = [0.0, 0.3]\n[outputs]\n'
                     'fields = ["ends", "exponents", "sif"]\n')
    child = ("import sys, contact.cli\n"
             f"status = contact.cli.main(['run', {str(scene)!r}, '--out', "
             f"{str(tmp_path / 'out')!r}, '--quiet', '--no-figures'])\n"
             f"print(status, [m for m in {_HEAVY_AT_START!r} if m in sys.modules])\n")
    proc = subprocess.run([sys.executable, "-c", child], env=child_env(),
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert proc.stdout.split("\n")[-2] == "0 []"
    assert len(cases_of(tmp_path / "out" / "result.json")) == 6


def test_run_scene_through_an_executor_equals_serial():
    from concurrent.futures import ThreadPoolExecutor
    s = load_scene(SCENES / "fig2a_triangular_speed.toml")
    serial = run_scene(s)
    with ThreadPoolExecutor(max_workers=3) as ex:
        threaded = run_scene(s, executor=ex)
    assert [c.index for c in threaded.cases] == [0, 1, 2, 3]
    for a, b in zip(serial.cases, threaded.cases):
        assert a.entry["ends"] == b.entry["ends"]
        np.testing.assert_array_equal(a.curve("sigma_xx")[1], b.curve("sigma_xx")[1])


def test_scheduler_without_the_extra_says_how_to_install(monkeypatch, capsys, tmp_path):
    monkeypatch.setitem(sys.modules, "distributed", None)     # import distributed fails
    assert cli.main(["run", "--scheduler", "tcp://127.0.0.1:1", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "sie-contact[dask]" in err and "Traceback" not in err


@pytest.mark.skipif(not hasattr(os, "sched_setaffinity"), reason="no CPU affinity here")
@pytest.mark.slow
def test_jobs_counts_the_cpus_this_process_may_use(tmp_path):
    """A command held to one CPU (its affinity, as a container's cpuset or taskset sets it):
    --jobs 0 runs one worker, in the process itself (no pool, no warning); --jobs 2 warns
    that its workers share the one CPU, and still runs, giving the same sweep."""
    scene = tmp_path / "sweep.toml"
    scene.write_text('title = "s"\n[material]\npreset = "zhou2014"\n[punch]\n'
                     'kind = "cylindrical"\nradius = 100.0\n[motion]\nload = 0.01\n'
                     'speed = [0.0, 0.5]\nfriction = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, '
                     '0.8, 0.9]\n[outputs]\nfields = ["ends"]\n')
    outs = {}
    for jobs in ("0", "2"):
        child = ("import os, sys, concurrent.futures as cf, contact.cli\n"
                 "os.sched_setaffinity(0, {sorted(os.sched_getaffinity(0))[0]})\n"
                 "pools = []\n"
                 "init = cf.ProcessPoolExecutor.__init__\n"
                 "cf.ProcessPoolExecutor.__init__ = lambda self, *a, **k: "
                 "(pools.append(k.get('max_workers')), init(self, *a, **k))[1]\n"
                 f"status = contact.cli.main(['run', {str(scene)!r}, '--jobs', {jobs!r}, "
                 f"'--out', {str(tmp_path / jobs)!r}, '--quiet', '--no-figures'])\n"
                 "print(status, pools)\n")
        proc = subprocess.run([sys.executable, "-c", child], env=child_env(),
                              capture_output=True, text=True, timeout=300)
        assert proc.returncode == 0, proc.stderr[-3000:]
        outs[jobs] = proc
    assert outs["0"].stdout.split("\n")[-2] == "0 []" and "warning" not in outs["0"].stderr
    assert outs["2"].stdout.split("\n")[-2] == "0 [2]"
    assert "--jobs 2 is more than the 1 CPU(s) this process may use" in outs["2"].stderr
    assert (tmp_path / "2" / "sweep.csv").read_bytes() == \
        (tmp_path / "0" / "sweep.csv").read_bytes()


def test_a_pool_has_no_more_workers_than_cases():
    with cli._executor(8, None, cases=3) as ex:
        assert ex._max_workers == 3
    with cli._executor(8, None, cases=1) as ex:          # one case: solved here
        assert ex is None


def test_jobs_and_scheduler_together_are_refused(capsys, tmp_path):
    assert cli.main(["run", "--jobs", "2", "--scheduler", "x:1", "--out", str(tmp_path)]) == 2
    assert "not both" in capsys.readouterr().err


@pytest.mark.slow
def test_a_cluster_that_loses_every_worker_during_a_sweep_is_said(tmp_path):
    """A LocalCluster that loses its only worker while `contact run --scheduler` runs on it:
    the command says that the sweep waits for new workers, and says so again when one has
    joined; Ctrl-C then stops it."""
    distributed = pytest.importorskip("distributed")
    import signal
    import time
    err_path, out = tmp_path / "stderr.txt", tmp_path / "out"

    def said(text, within=60):
        deadline = time.monotonic() + within
        while text not in err_path.read_text() and time.monotonic() < deadline:
            time.sleep(0.05)
        return text in err_path.read_text()
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1,
                                  dashboard_address=":0") as cluster:
        address = cluster.scheduler_address
        child = ("import sys, contact.cli\ncontact.cli.WATCH_S = 0.2\n"
                 f"sys.exit(contact.cli.main(['run', {str(_endless_sweep(tmp_path))!r}, "
                 f"'--quiet', '--no-figures', '--scheduler', {address!r}, '--out', "
                 f"{str(out)!r}]))\n")
        with open(err_path, "w") as err:
            proc = subprocess.Popen([sys.executable, "-c", child], env=child_env(), stderr=err,
                                    start_new_session=True, preexec_fn=_as_from_a_terminal)
        try:
            deadline = time.monotonic() + 60                # the sweep's chunks reach it
            while not cluster.scheduler.tasks and time.monotonic() < deadline:
                time.sleep(0.05)
            cluster.scale(0)
            assert said(f"contact: warning: --scheduler {address} has no workers left: the "
                        "sweep waits for new ones (Ctrl-C stops)"), err_path.read_text()
            cluster.scale(1)
            assert said(f"contact: --scheduler {address} has workers again"), \
                err_path.read_text()
            os.killpg(proc.pid, signal.SIGINT)
            assert proc.wait(timeout=60) == 130
        finally:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(proc.pid, 9)
    assert err_path.read_text().endswith("contact: error: interrupted\n")


def test_an_earlier_runs_outputs_left_in_out_are_named(tmp_path):
    """A run into an --out that holds an earlier run's outputs which it does not write
    itself (the curve CSV of a field asked then, not now) names them in a warning; the
    user's own files there are not named, and a run that rewrites every output says
    nothing."""
    scene = tmp_path / "s.toml"
    text = ('title = "s"\n[material]\npreset = "zhou2014"\n[punch]\nkind = "cylindrical"\n'
            'radius = 100.0\n[motion]\nload = 0.01\nspeed = [0.0, 0.5]\n[outputs]\n'
            'fields = FIELDS\n')
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    (out / "pressure_fit.csv").write_text("mine")
    scene.write_text(text.replace("FIELDS", '["ends", "pressure"]'))
    rc, _, err = run_cli("run", scene, "--out", out, "--quiet", "--no-figures")
    assert rc == 0 and "warning" not in err
    rc, _, err = run_cli("run", scene, "--out", out, "--quiet", "--no-figures")
    assert rc == 0 and "warning" not in err
    scene.write_text(text.replace("FIELDS", '["ends"]'))
    rc, _, err = run_cli("run", scene, "--out", out, "--quiet", "--no-figures")
    assert rc == 0
    assert err == (f"contact: warning: --out {out} also holds pressure.csv, which this run "
                   "did not write (an earlier run's?)\n")


# --------------------------------------------------------------------------
# stopped from outside: Ctrl-C, SIGTERM, a worker killed
# --------------------------------------------------------------------------
def _endless_sweep(tmp_path):
    """A scene of 1e9 cases (about a day on one core): a run that is stopped, not done."""
    values = ", ".join(str(round(0.01 * k, 2)) for k in range(1000))
    scene = tmp_path / "endless.toml"
    scene.write_text('title = "endless"\n[material]\npreset = "zhou2014"\n[punch]\n'
                     'kind = "cylindrical"\nradius = 100.0\n[motion]\n'
                     f'load = [{", ".join(str(0.01 + 0.001 * k) for k in range(1000))}]\n'
                     f'speed = [{", ".join(str(round(0.0009 * k, 4)) for k in range(1000))}]\n'
                     f'friction = [{values}]\n[outputs]\nfields = ["ends"]\n')
    return scene


def _as_from_a_terminal():
    """preexec_fn of an endless run: SIGINT at its default (as a command started from a
    terminal has it; a background job's children ignore it), and, on Linux, SIGTERM to it
    when the test's process ends, however that ends (PR_SET_PDEATHSIG): an endless run
    never outlives an interrupted test session."""
    import ctypes
    import signal
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    if sys.platform.startswith("linux"):
        ctypes.CDLL(None).prctl(cli._PR_SET_PDEATHSIG, int(signal.SIGTERM), 0, 0, 0)


def _children(pid):
    """The pids of the processes whose parent is ``pid`` (from /proc)."""
    kids = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                stat = (entry / "stat").read_text()
            except OSError:                             # ended meanwhile
                continue
            if int(stat.rsplit(")", 1)[1].split()[1]) == pid:
                kids.append(int(entry.name))
    return kids


def _running_pool(tmp_path, jobs=2):
    """``contact run`` of the endless sweep with ``--jobs`` in a session of its own (SIGINT
    at its default, as in a terminal), once its ``jobs`` workers solve: (process, --out)."""
    import time
    out = tmp_path / "out"
    proc = subprocess.Popen([sys.executable, "-m", "contact", "run", str(_endless_sweep(tmp_path)),
                             "--quiet", "--no-figures", "--jobs", str(jobs), "--out", str(out)],
                            env=child_env(), stderr=subprocess.PIPE, text=True,
                            start_new_session=True, preexec_fn=_as_from_a_terminal)
    deadline = time.monotonic() + 120
    while len(_children(proc.pid)) < jobs and time.monotonic() < deadline:
        time.sleep(0.05)
    assert len(_children(proc.pid)) == jobs and out.is_dir()
    time.sleep(0.5)                                     # the workers well into their chunks
    return proc, out


def _ended(proc):
    """(exit status, stderr) of ``proc``; no process of its group left."""
    try:
        err = proc.communicate(timeout=60)[1]
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, 9)
    return proc.returncode, err


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="signals to a process group")
@pytest.mark.parametrize("name, status, said", [("SIGINT", 130, "contact: error: interrupted"),
                                                ("SIGTERM", 143,
                                                 "contact: error: terminated (SIGTERM)")])
@pytest.mark.slow
def test_a_sweep_stopped_by_a_signal_to_its_group_leaves_nothing(tmp_path, name, status, said):
    """Ctrl-C (SIGINT) and a batch system's SIGTERM reach the command and its workers: the
    command says so, exits with 128 + the signal and removes its partial outputs (--out
    too, which it made); its workers end with it."""
    import signal
    import time
    proc, out = _running_pool(tmp_path)
    os.killpg(proc.pid, getattr(signal, name))
    rc, err = _ended(proc)
    assert rc == status and err.strip() == said
    assert not out.exists()
    time.sleep(0.2)
    with pytest.raises(ProcessLookupError):             # no worker outlived it
        os.killpg(proc.pid, 0)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="/proc")
@pytest.mark.slow
def test_a_worker_killed_under_a_sweep_is_named_not_a_traceback(tmp_path):
    """A worker killed outright (SIGKILL: the system's out-of-memory killer) breaks the
    pool: the command says a worker died, exits with status 1 and removes its partial
    outputs."""
    proc, out = _running_pool(tmp_path)
    os.kill(_children(proc.pid)[0], 9)
    rc, err = _ended(proc)
    assert rc == 1 and "Traceback" not in err
    assert err.startswith("contact: error: a worker process of --jobs died")
    assert not out.exists()


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="PR_SET_PDEATHSIG")
@pytest.mark.slow
def test_the_workers_end_with_a_command_killed_outright(tmp_path):
    """The command killed with SIGKILL (which it cannot catch: the out-of-memory killer's):
    its workers, which would otherwise wait for work forever, end with it."""
    import time
    proc, _ = _running_pool(tmp_path)
    workers = _children(proc.pid)
    os.kill(proc.pid, 9)
    proc.wait(timeout=60)
    deadline = time.monotonic() + 30

    def alive():                                        # neither gone nor a zombie
        running = []
        for pid in workers:
            with contextlib.suppress(OSError):
                if Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0] != "Z":
                    running.append(pid)
        return running
    proc.stderr.close()
    while alive() and time.monotonic() < deadline:
        time.sleep(0.05)
    left = alive()
    for pid in left:
        os.kill(pid, 9)
    assert left == []


# --------------------------------------------------------------------------
# progress bar
# --------------------------------------------------------------------------
def _slow(run_cases, delay):
    import time

    def slow_run_cases(cases):
        time.sleep(delay * len(cases))
        return run_cases(cases)
    return slow_run_cases


@pytest.mark.slow
def test_progress_bar_on_a_slow_sweep_and_quiet_turns_it_off(monkeypatch, capsys, tmp_path):
    import contact.scene as scene_module
    monkeypatch.setattr(scene_module.run, "run_cases", _slow(scene_module.run.run_cases, 0.45))
    assert cli.main(["run", str(SWEEP), "--out", str(tmp_path / "a")]) == 0
    assert "cases" in capsys.readouterr().err                 # tqdm's bar, after ~1 s
    assert cli.main(["run", str(SWEEP), "--out", str(tmp_path / "b"), "--quiet"]) == 0
    captured = capsys.readouterr()
    assert captured.err == "" and captured.out == ""


def test_no_progress_bar_on_a_fast_sweep(capsys, tmp_path):
    run_scene(load_scene(SWEEP))                               # warm up
    assert cli.main(["run", str(SWEEP), "--out", str(tmp_path)]) == 0
    assert "cases" not in capsys.readouterr().err


# --------------------------------------------------------------------------
# helpers and user errors
# --------------------------------------------------------------------------
@pytest.mark.slow
def test_help_lists_every_command(tmp_path):
    proc = contact_command("--help", cwd=tmp_path)
    assert proc.returncode == 0
    for command in ("run", "table1", "constants"):
        assert command in proc.stdout
    run_help = contact_command("run", "--help", cwd=tmp_path).stdout
    for option in ("--out", "--jobs", "--quiet", "--scheduler"):
        assert option in run_help


@pytest.mark.slow
def test_console_script_is_installed(tmp_path):
    script = Path(sys.executable).with_name("contact")
    if not script.exists():
        pytest.skip("the console script is installed by `pip install -e .` (make does it)")
    proc = subprocess.run([str(script), "--help"], capture_output=True, text=True, cwd=tmp_path)
    assert proc.returncode == 0 and "table1" in proc.stdout


def test_table1(capsys):
    assert cli.main(["table1"]) == 0
    out = capsys.readouterr().out.splitlines()
    rows = out[2:]
    assert len(rows) == 14
    assert rows[0].split() == ["0", "5.2506", "-5.2506", "0.6120", "-0.6120"]
    assert rows[11].split() == ["1.5", "5.0359", "-5.0359", "0.6852i", "-0.6852i"]
    assert rows[13].split() == ["10", "8.5829i", "-8.5829i", "5.8365i", "-5.8365i"]


def test_constants(capsys):
    assert cli.main(["constants", "--speed", "0.6"]) == 0
    out = capsys.readouterr().out
    k = contact.surface_constants(contact.zhou2014(), 0.6)
    assert f"{k.N11:.12g}" in out and f"{k.N22:.12g}" in out
    assert "c_R = 0.9936147317" in out
    assert cli.main(["constants", str(SCENES / "fig4a_cylindrical_speed.toml")]) == 0
    rows = capsys.readouterr().out.splitlines()[3:]
    assert [r.split()[0] for r in rows] == ["0", "0.3", "0.6", "0.9"]


def test_constants_at_or_above_rayleigh_is_a_message(capsys):
    assert cli.main(["constants", "--speed", "0.999"]) == 2
    err = capsys.readouterr().err
    assert "c_R = 0.99361473" in err and "Traceback" not in err
    assert cli.main(["constants"]) == 2
    assert "--speed" in capsys.readouterr().err


@pytest.mark.slow
def test_bad_scene_in_a_subprocess_exits_2_without_traceback(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('[material]\npreset = "zhou2014"\n[punch]\nkind = "flat"\nhalf_width = 1.0\n'
                   "[motion]\nload = 0.01\nsped = 0.3\n")
    proc = contact_command("run", str(bad), cwd=tmp_path)
    assert proc.returncode == 2
    assert proc.stderr.strip() == (
        f"contact: error: {bad}: motion.sped: unknown key; did you mean 'speed'? "
        "(allowed: load, speed, velocity, friction, direction, tangential_load, creepage, "
        "rolling)")
    assert proc.stdout == "" and not (tmp_path / "contact-out").exists()
    broken = tmp_path / "broken.toml"
    broken.write_text("[motion]\nload = 0.01\nspeed = [0.3,\n")
    proc = contact_command("run", str(broken), cwd=tmp_path)
    assert proc.returncode == 2 and "TOML syntax error" in proc.stderr
    assert "Traceback" not in proc.stderr
