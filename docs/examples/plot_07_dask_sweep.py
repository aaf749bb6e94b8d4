"""
A sweep on a Dask cluster
=========================

A scene (a TOML file, or its text) sweeps any inputs; :func:`contact.scene.run_scene` solves
its cases in process, on a process pool or on a Dask cluster, in chunks that share the
material and the speed, and returns them in scene order -- the same numbers whichever way.
Here a cylindrical punch on the paper's material, 12 speeds x 6 friction coefficients, on a
``LocalCluster`` of two worker processes.  On a real cluster, start ``dask scheduler`` on one
machine and ``dask worker tcp://scheduler:8786`` on the others, and pass the scheduler's
address (``contact run scene.toml --scheduler tcp://scheduler:8786`` does the same from the
command line).
"""
import matplotlib.pyplot as plt
from distributed import Client, LocalCluster

from contact.scene import parse_scene_text, run_scene

scene = parse_scene_text("""
title = "cylinder: contact ends against speed and friction"
[material]
preset = "zhou2014"
[punch]
kind = "cylindrical"
radius = 100.0
[motion]
load = 0.01
speed = [0.0, 0.08, 0.16, 0.24, 0.32, 0.4, 0.48, 0.56, 0.64, 0.72, 0.8, 0.88]
friction = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5]
[outputs]
fields = ["ends", "exponents"]
""", source="<gallery>")


if __name__ == "__main__":      # worker processes import this file: start the cluster only here
    serial = run_scene(scene)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        distributed = run_scene(scene, executor=client.get_executor(pure=False))

    same = all(repr(a.entry) == repr(b.entry) for a, b in zip(serial.cases, distributed.cases))
    print(f"{len(serial.cases)} cases; identical on the cluster and in process: {same}")

# %%
# The tidy table: one row per case (``sweep.csv`` of ``contact run``).
if __name__ == "__main__":
    df = distributed.to_dataframe()
    print(df.columns.tolist())
    print(df.head().to_string(index=False))

# %%
# The contact width against speed, one line per friction coefficient.
if __name__ == "__main__":
    fig, ax = plt.subplots(figsize=(6.4, 3.8))
    for mu, g in df.groupby("friction"):
        ax.plot(g["speed"], g["x_right"] - g["x_left"], "o-", ms=3, label=f"mu = {mu:g}")
    ax.set_xlabel("relative speed c")
    ax.set_ylabel("contact width x_r - x_l")
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
