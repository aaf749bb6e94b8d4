"""validation/bench_sweep.py on a small sweep: every configuration it times runs, the process
pools and Dask clusters give the serial run's results, and ``contact run`` exits with status
0 with ``--jobs`` and ``--scheduler`` alike.  Its timings and targets are for ``make bench``
and are not judged here; what is checked is that the benchmark works and that its Dask
settings reach the workers as the README says (no statistical profiler, MALLOC_TRIM_THRESHOLD_
unset, Dask's one-thread BLAS limits kept)."""
import os

import pytest

distributed = pytest.importorskip("distributed")

from contact.scene import parse_scene_text  # noqa: E402
from validation import bench_sweep  # noqa: E402


def _worker_settings():
    import dask
    return (dask.config.get("distributed.worker.profile.enabled"),
            dask.config.get("distributed.admin.tick.interval"),
            os.environ.get("MALLOC_TRIM_THRESHOLD_"), os.environ.get("OMP_NUM_THREADS"))


def test_sweep_config_reaches_the_workers():
    with bench_sweep.local_cluster(1) as cluster, distributed.Client(cluster) as client:
        (settings,) = client.run(_worker_settings).values()
    assert settings == (False, "1s", None, "1")


def test_every_configuration_runs_and_agrees_with_serial():
    scene = parse_scene_text(bench_sweep.sweep_toml(10, 12), source="<bench smoke>")
    rows = bench_sweep.scaling_rows(scene) + bench_sweep.cli_rows(10, 12, repeats=1)
    names = [name for name, *_ in rows]
    assert not [n for n in names if "RESULTS DIFFER" in n or "FAILED" in n], names
    assert sum("process pool" in n for n in names) >= 2
    assert sum("Dask LocalCluster" in n for n in names) >= 2
    assert sum("--scheduler" in n for n in names) >= 1
    assert all(wall > 0 for _, wall, *_ in rows)
    assert all("CPU" in ratio for name, _, ratio, _ in rows if name.startswith("`contact run"))


@pytest.mark.parametrize("argv", [["--cli", "--repeats", "0"], ["--cli", "--repeats"],
                                  ["--cli", "--repeats", "two"]])
def test_a_bad_repeat_count_is_refused_before_any_run(argv, capsys):
    with pytest.raises(SystemExit) as exc:
        bench_sweep.main(argv)
    assert exc.value.code == 2 and "--repeats" in capsys.readouterr().err
