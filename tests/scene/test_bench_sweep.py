"""validation/bench_sweep.py on a small sweep: every configuration it times runs, the process
pools and Dask clusters give the serial run's results, and ``contact run`` exits with status
0 with ``--jobs`` and ``--scheduler`` alike.  Its timings and targets are for ``make bench``
and are not judged here; what is checked is that the benchmark works and that its Dask
settings reach the workers as the README says (no statistical profiler, MALLOC_TRIM_THRESHOLD_
unset, Dask's one-thread BLAS limits kept).

``contact run`` is timed here once (the module fixture ``cli``: ``--jobs 1`` and ``--jobs 2``,
quiet and printed, and a cluster of 2), with the machine's ceiling read for 0.2 s instead of
the benchmark's 2 s; the tests of its rows share that run.  The rows of the default pool
sizes (1, 2, 4, 8, 16 and the machine's cores, up to them) with 3 repeats each are timed by
``make bench`` (``python -m validation.bench_sweep``)."""
import functools
import math
import os
import threading
import types

import pytest

distributed = pytest.importorskip("distributed")

from contact.scene import parse_scene_text  # noqa: E402
from validation import bench_sweep  # noqa: E402


def _worker_settings():
    import dask
    return (dask.config.get("distributed.worker.profile.enabled"),
            dask.config.get("distributed.admin.tick.interval"),
            os.environ.get("MALLOC_TRIM_THRESHOLD_"), os.environ.get("OMP_NUM_THREADS"))


@pytest.mark.slow
def test_sweep_config_reaches_the_workers():
    with bench_sweep.local_cluster(1) as cluster, distributed.Client(cluster) as client:
        (settings,) = client.run(_worker_settings).values()
    assert settings == (False, "1s", None, "1")


@pytest.fixture(scope="module")
def cli():
    """The rows of ``contact run`` timed once for the tests of this module: a 10 x 12 sweep,
    ``--jobs 1`` and ``--jobs 2`` (what the default pool sizes are on 2 cores), quiet and
    with the table printed, a LocalCluster of 2, one run each; N processes solving alone for
    0.2 s before each ``--jobs N`` run (the benchmark's 2 s only steadies the reading)."""
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(bench_sweep, "processes_alone",
                   functools.partial(bench_sweep.processes_alone, seconds=0.2))
        return bench_sweep.cli_rows(10, 12, repeats=1, counts=[2], printed=True)


def _quiet(rows):
    """The rows of the quiet runs and the machine's ceiling (the printed runs left out)."""
    return [row for row in rows if "table printed" not in row[0]]


@pytest.mark.slow
def test_every_configuration_runs_and_agrees_with_serial(cli):
    scene = parse_scene_text(bench_sweep.sweep_toml(10, 12), source="<bench smoke>")
    rows = bench_sweep.scaling_rows(scene) + _quiet(cli)
    names = [name for name, *_ in rows]
    assert not [n for n in names if "RESULTS DIFFER" in n or "FAILED" in n], names
    assert sum("process pool" in n for n in names) >= 2
    assert sum("Dask LocalCluster" in n for n in names) >= 2
    assert sum("--scheduler" in n for n in names) >= 1
    assert all(wall > 0 for name, wall, *_ in rows if "ceiling" not in name)
    # the machine's ceiling measured for every pool size timed, one process its unit
    (ceiling,) = [ratio for name, _, ratio, _ in rows if "ceiling" in name]
    assert ceiling.startswith("N = 1: 1.00x one (slowest process 1.00x the fastest); N = 2: ")
    cli = [ratio for name, _, ratio, _ in rows if name.startswith("`contact run")]
    assert cli and all("CPU" in ratio for ratio in cli)
    assert all("solving alone just before" in ratio for name, _, ratio, _ in rows
               if name.startswith("`contact run --quiet --jobs"))
    # every phase of each run reached and timed (the driver wraps the chunks' iterator)
    assert all("to the first chunk" in ratio and "?" not in ratio for ratio in cli), cli
    # the forked pools' workers timed handing back their chunks
    pooled = [ratio for name, _, ratio, _ in rows
              if name.startswith("`contact run --quiet --jobs 2")]
    assert pooled and all("its workers handed back" in ratio for ratio in pooled), pooled


def test_in_process_rows_time_the_solve_the_scene_and_the_writers_text():
    scene = parse_scene_text(bench_sweep.sweep_toml(6, 5), source="<bench smoke>")
    rows = bench_sweep.in_process_rows(scene)
    names = [name for name, *_ in rows]
    assert names[0] == "30 cases, serial, in process"
    assert sum("contact run adds where a case is solved" in n for n in names) == 2
    assert all(ratio.endswith("us a case") or "us a case," in ratio for _, _, ratio, _ in rows)


def test_phases_of_a_run_add_up_to_its_wall_time():
    """phase_text: the marks of _TIMED_CONTACT_RUN as consecutive intervals that add up to
    the wall time; a phase whose mark is missing (a run that failed before it) is '?'."""
    marks = bench_sweep._phases("noise\nPHASES imported=0.5000 first=0.6000 cpu_first=0.7 "
                                "last=3.1000 cpu_last=1.2 written=3.2500\n")
    assert marks == {"imported": 0.5, "first": 0.6, "cpu_first": 0.7, "last": 3.1,
                     "cpu_last": 1.2, "written": 3.25}
    text = bench_sweep.phase_text(marks, 3.3)
    assert "(the command's process busy 20% of the stream)" in text     # 0.5 s CPU / 2.5 s
    assert "forked" not in text                         # no pool that forks: no fork times
    forked = bench_sweep.phase_text({**marks, "forked_first": 0.55, "forked_last": 0.58}, 3.3)
    assert "to the first chunk 0.10 (workers forked at 0.55-0.58)" in forked
    # a forked pool's workers: 0.5 s handing back 10 chunks, of 2 workers x 2.5 s of stream
    sent = bench_sweep.phase_text({**marks, "forks": 2, "forked_first": 0.55,
                                   "forked_last": 0.58, "sent": 10, "sending": 0.5}, 3.3)
    assert ("(the command's process busy 20% of the stream; its workers handed back 10 chunks "
            "in 0.50 s, 50.0 ms each, 10.0% of their time)") in sent
    parts = [float(w) for w in text.split("(")[0].split() + text.split(")")[1].split()
             if w[0].isdigit()]
    assert parts == [0.5, 0.1, 2.5, 0.15, 0.05] and abs(sum(parts) - 3.3) < 1e-9
    failed = bench_sweep.phase_text(bench_sweep._phases("PHASES imported=0.5"), 0.7)
    assert failed.count("?") == 4 and failed.startswith("imports 0.50")


@pytest.mark.slow
def test_processes_alone_count_what_each_solved():
    """processes_alone: n processes' summed rate is positive and finite, and the slowest of
    them is at least as slow as the fastest.  Two processes count about twice one at most
    (they solve the same cases); the bound is 3.5 times: the readings are 0.2 s apart on
    a shared machine whose speed drifts (2.73 times one was seen), and each process counted
    twice would give about 4 times."""
    with bench_sweep.processes_alone(bench_sweep.sweep_toml(30, 30), cases=300,
                                     seconds=0.2) as alone:
        alone(1)        # (in a fresh clone the first reading was low: 2.8 times one for two)
        (one, spread1), (two, spread2) = alone(1), alone(2)
    assert spread1 == 1.0 and spread2 >= 1.0
    assert 0.0 < one < math.inf and 0.0 < two < 3.5 * one


class _Cases:
    """A scene of cases that are only their index."""

    def iter_cases(self, start, stop):
        return (types.SimpleNamespace(index=i) for i in range(start, stop))


def test_a_process_alone_counts_the_cases_of_its_seconds_alone(monkeypatch):
    """_solve_alone on cases of 2 ms each (on a clock that the cases move), in chunks of 15
    (30 ms), for 0.1 s: 50 cases, the chunk running at the end counted for the third of it
    inside the 0.1 s (whole chunks would give 45 or 60), the chunks taken over again once
    both are done; the first chunk solved once before the barrier, outside the count."""
    clock = [100.0]
    monkeypatch.setattr(bench_sweep, "time", types.SimpleNamespace(perf_counter=lambda: clock[0]))
    solved = []

    def two_ms_each(cases):
        clock[0] += 2e-3 * len(cases)
        solved.append((cases[0].index, len(cases)))
        return [None] * len(cases)
    at_barrier = []
    sent = []
    bench_sweep._solve_alone(two_ms_each, _Cases(), [(0, 15), (100, 115)], 0.1,
                             types.SimpleNamespace(wait=lambda: at_barrier.append(len(solved))),
                             types.SimpleNamespace(send=sent.append, close=lambda: None))
    assert at_barrier == [1] and solved[0] == (0, 15)
    assert sent == [pytest.approx(50.0, rel=1e-9)]
    assert solved[1:] == [(0, 15), (100, 15), (0, 15), (100, 15)]


def test_a_ceiling_over_n_times_one_process_is_called_the_machine_drifting():
    """N processes at more than N times one process: only the machine's speed changing
    between the two readings makes that, and the row says so; at or under N it says
    nothing."""
    assert bench_sweep._beyond(16, 16.0) == "" and bench_sweep._beyond(2, 1.98) == ""
    assert "slower spell" in bench_sweep._beyond(16, 18.25)


@pytest.mark.parametrize("argv", [["--cli", "--repeats", "0"], ["--cli", "--repeats"],
                                  ["--cli", "--repeats", "two"], ["--cli", "--counts", "0,2"],
                                  ["--cli", "--counts", "2,x"], ["--cli", "--counts", ""],
                                  ["--cli", "--per-core", "0"], ["--cli", "--per-core", "1e5"]])
def test_a_bad_repeat_count_or_pool_size_is_refused_before_any_run(argv, capsys):
    with pytest.raises(SystemExit) as exc:
        bench_sweep.main(argv)
    assert exc.value.code == 2 and argv[1] in capsys.readouterr().err


def test_the_timed_sweep_has_the_cases_asked_per_core_and_1e5_at_least():
    assert bench_sweep.cli_side(2) ** 2 == 316 ** 2                  # 99 856: 1e5 cases
    assert bench_sweep.cli_side(16) == 894                           # 5e4 a core
    assert bench_sweep.cli_side(16, per_core=200_000) == 1788        # 3.2e6 cases
    assert bench_sweep.cli_side(16, per_core=1000) == 316


@pytest.mark.slow
def test_the_default_run_with_its_table_is_timed_beside_the_quiet_one(cli):
    printed = [(name, ratio) for name, _, ratio, _ in cli if "table printed" in name]
    assert [name for name, _ in printed] == [
        "`contact run --jobs 1` (the table printed, the progress bar)",
        "`contact run --jobs 2` (the table printed, the progress bar)"]
    assert printed[0][1].startswith("1.00x its --jobs 1, ")
    assert all("the time with --quiet" in ratio and "to the first chunk" in ratio
               for _, ratio in printed)


@pytest.mark.slow
def test_the_pool_sizes_asked_are_timed_and_one_besides(cli):
    """--counts 2: --jobs 1 (the reference) and --jobs 2, and the cluster of 2 paired with
    the pool of 2; none of the other default sizes."""
    names = [name for name, *_ in cli]
    assert [n for n in names if n.startswith("`contact run --quiet --jobs")] == \
        ["`contact run --quiet --jobs 1`", "`contact run --quiet --jobs 2`"]
    assert sum("LocalCluster, 2 worker" in n for n in names) == 1
    assert not [n for n in names if "FAILED" in n], names
