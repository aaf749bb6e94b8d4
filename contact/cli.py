"""The ``contact`` command: run scenes, print Table 1 and the surface constants.

    contact run [SCENE.toml] [--out DIR] [--jobs N] [--quiet] [--no-figures]
                [--scheduler ADDRESS]
    contact table1 [--digits D]
    contact constants --speed C [SCENE.toml]
    contact punches

A user error (a bad scene, an inadmissible speed, a profile that loses contact) prints one
message naming the file, the key and what is allowed, and exits with status 2 (a bad scene or
argument, or an --out that cannot be written, found before anything is solved) or 1 (a case
that failed while it was solved, or a worker process that died) -- never a traceback.
Stopped by Ctrl-C or SIGTERM, ``contact run`` removes its partial outputs and exits with 130
or 143 (128 + the signal).

A standard output closed by its reader (``contact table1 | head -3``) ends the command
quietly, as it ends the standard Unix tools, which SIGPIPE kills: no message, and the
status 141 (128 + SIGPIPE) those report, so that a pipeline under ``set -o pipefail`` sees
the output cut short; ``contact run`` still finishes writing its files into --out.
"""
from __future__ import annotations

import argparse
import contextlib
import gc
import io
import multiprocessing
import os
import signal
import sys
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool

import contact
import sie

from . import scene as scenes
from .scene.processes import cyclic_gc_paused
from .registry import KINDS

#: The 14 relative speeds of Table 1 in Zhou, Lee & Jang 2014.
TABLE1_SPEEDS = (0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.5, 2.0, 10.0)

EXIT_BAD_INPUT = 2
EXIT_CASE_FAILED = 1
#: The shell's status of a command stopped by SIGINT (Ctrl-C) or SIGTERM: 128 + the signal.
EXIT_INTERRUPTED = 128 + signal.SIGINT
EXIT_TERMINATED = 128 + signal.SIGTERM
#: The status of a command whose standard output was closed by its reader, as a shell
#: reports a Unix tool killed by SIGPIPE: 128 + 13 (the number, where Windows has no SIGPIPE).
EXIT_BROKEN_PIPE = 128 + getattr(signal, "SIGPIPE", 13)


class UsageError(Exception):
    """A command-line problem that is not about the scene file (e.g. --scheduler without
    the dask extra)."""


class Terminated(Exception):
    """The command was asked to stop by SIGTERM (``kill``, a batch system's time limit):
    raised where it runs, so that it stops as on Ctrl-C, its partial outputs removed."""


def _raise_terminated(signum, frame):
    raise Terminated(signal.Signals(signum).name)


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="contact",
        description="Moving frictional contact on an orthotropic half-space (Zhou, Lee & Jang "
                    "2014, corrected): run TOML scenes, print the paper's Table 1 and the "
                    "surface constants.",
        epilog="Scene format: see the docstring of contact.scene (python -c 'import "
               "contact.scene as s; help(s)') and the examples in validation/scenes/.  Punch "
               f"kinds: {', '.join(KINDS)} (contact punches lists their scene keys).")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)

    run = sub.add_parser(
        "run", help="run a scene (or the embedded default) and write result.json, CSV, PNG",
        description="Run a scene file (without one: the embedded default, the paper's material "
                    "and a cylindrical punch at c = 0.6, mu = 0.3), print a short table and "
                    "write result.json, sweep.csv (one row per case), one CSV per sampled "
                    "curve and PNG figures into --out.")
    run.add_argument("scene", nargs="?", metavar="SCENE.toml",
                     help="scene file (default: the embedded default scene)")
    run.add_argument("--out", default="contact-out", metavar="DIR",
                     help="output directory (default: ./contact-out)")
    run.add_argument("--jobs", type=_jobs, default=1, metavar="N",
                     help="solve sweep points in N worker processes (0: one per CPU this "
                          "process may use; default 1)")
    run.add_argument("--scheduler", metavar="ADDRESS",
                     help="send the sweep to a Dask cluster at ADDRESS (needs the optional "
                          "extra: pip install 'sie-contact[dask]')")
    run.add_argument("--quiet", action="store_true",
                     help="no progress bar, no table, no list of files written")
    run.add_argument("--no-figures", dest="figures", action="store_false",
                     help="write no PNG figures (as [outputs] figures = false in the scene)")
    run.set_defaults(handler=cmd_run)

    t1 = sub.add_parser(
        "table1", help="print Table 1 of the paper: characteristic roots at its 14 speeds",
        description="Characteristic roots eta1, -eta1, eta3, -eta3 of eq. (3.1) for the paper's "
                    "material at the 14 relative speeds of its Table 1.")
    t1.add_argument("--digits", type=int, default=4, help="decimals shown (default 4)")
    t1.set_defaults(handler=cmd_table1)

    k = sub.add_parser(
        "constants", help="print the surface constants N11, N12, N21, N22 and c_R",
        description="Surface constants of eqs. (4.5)-(4.6) (dv/dX = N12 q + N11 Hc[p], "
                    "sigma_XX = N21 p + N22 Hc[q]) and the Rayleigh speed c_R, for the scene's "
                    "material (default: the paper's).")
    k.add_argument("scene", nargs="?", metavar="SCENE.toml",
                   help="take the material (and, without --speed, the speeds) from this scene")
    k.add_argument("--speed", type=float, metavar="C",
                   help="relative speed c = V / sqrt(C33/rho), 0 <= c < c_R")
    k.set_defaults(handler=cmd_constants)

    pk = sub.add_parser(
        "punches", help="list the punch kinds a scene can name, with their scene keys",
        description="The punch kinds of [punch] kind = ... in a scene: the class each builds, "
                    "its scene keys and whether the paper's closed form exists "
                    "(numerics.method = \"closed_form\").")
    pk.set_defaults(handler=cmd_punches)
    return parser


def _jobs(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be an integer >= 0, got {text!r}") from None
    if n < 0:
        raise argparse.ArgumentTypeError(f"must be an integer >= 0, got {n}")
    return n


def main(argv=None) -> int:
    """Entry point of the ``contact`` console script and ``python -m contact``; returns the
    exit status."""
    args = build_parser().parse_args(argv)
    try:
        status = args.handler(args)
        sys.stdout.flush()                     # a reader gone shows here at the latest
        return status
    except BrokenPipeError as exc:
        if _stdout_gone():
            _silence_stdout()
            return EXIT_BROKEN_PIPE
        _error(str(exc))                       # a pipe other than stdout: as any OSError
        return EXIT_CASE_FAILED
    except (scenes.SceneError, UsageError) as exc:
        _error(str(exc))
        return EXIT_BAD_INPUT
    except scenes.CaseError as exc:
        _error(str(exc))
        return EXIT_CASE_FAILED
    except (contact.ContactInputError, sie.SIEInputError) as exc:
        _error(f"{type(exc).__name__}: {exc}")
        return EXIT_BAD_INPUT
    except OSError as exc:                     # e.g. --out is not writable
        _error(str(exc))
        return EXIT_CASE_FAILED
    except BrokenProcessPool as exc:
        _error(f"a worker process of --jobs died before its cases were done "
               f"({type(exc).__name__}); a worker killed by the system is most often out of "
               "memory")
        return EXIT_CASE_FAILED
    except KeyboardInterrupt:
        _error("interrupted")
        return EXIT_INTERRUPTED
    except Terminated as exc:
        _error(f"terminated ({exc})")
        return EXIT_TERMINATED


def console():
    """The ``contact`` console script and ``python -m contact``: :func:`main` on the command
    line, then the process exits with its status.

    Before the interpreter tears itself down, the objects still alive are moved out of the
    cyclic collector's reach (:func:`gc.freeze`): its passes at exit over every object of
    numpy, numba and scipy would cost each run a noticeable share of a short run's time.
    Files are closed by main() itself; reference counting still frees what is torn down.

    SIGTERM stops the command as Ctrl-C does (:class:`Terminated`): its partial outputs are
    removed and it exits with status 143.  The workers of ``--jobs`` leave both signals to
    it (:func:`_worker_signals`).
    """
    signal.signal(signal.SIGTERM, _raise_terminated)
    status = main()
    signal.signal(signal.SIGTERM, signal.SIG_DFL)       # main is done: nothing left to stop
    gc.freeze()
    sys.exit(status)


def _error(message: str):
    with contextlib.suppress(OSError):         # a closed stderr: nowhere left to say it
        print(f"contact: error: {message}", file=sys.stderr)


def _stdout_gone() -> bool:
    """Whether the standard output is a pipe (or socket) whose reader has gone: poll(2)
    reports POLLERR (POLLHUP on some systems) on its file descriptor.  False where stdout
    has no descriptor (replaced in-process) or the platform has no poll."""
    import select
    try:
        fd = sys.stdout.fileno()
        poller = select.poll()
        poller.register(fd, select.POLLOUT)
        events = poller.poll(0)
    except (AttributeError, ValueError, OSError, io.UnsupportedOperation):
        return False
    return any(ev & (select.POLLERR | select.POLLHUP) for _, ev in events)


def _silence_stdout() -> None:
    """Point the standard output's descriptor at the null device (the Python documentation's
    recipe for SIGPIPE): what is still buffered, and anything printed after, goes there
    instead of raising BrokenPipeError again when the interpreter flushes it at exit."""
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, sys.stdout.fileno())
    finally:
        os.close(devnull)


def _print_out(text: str) -> bool:
    """Print ``text`` to the standard output now; False (and stdout silenced) when its reader
    has gone, so that a command can finish its other work (``contact run`` its files)."""
    try:
        print(text, flush=True)
    except BrokenPipeError:
        if not _stdout_gone():
            raise
        _silence_stdout()
        return False
    return True


# --------------------------------------------------------------------------
# contact run
# --------------------------------------------------------------------------
def cmd_run(args) -> int:
    """Solve the scene's cases and write each as it comes (:func:`contact.scene.iter_scene`
    into a :class:`contact.scene.SceneWriter`): memory does not grow with the sweep."""
    scene = scenes.load_scene(args.scene) if args.scene else scenes.default_scene()
    try:                                       # before anything is solved
        scenes.check_out_dir(args.out)
    except OSError as exc:
        raise UsageError(f"--out {args.out}: {exc}") from None
    progress = not args.quiet
    with _writing_into(args.out):
        writer = scenes.SceneWriter(scene, args.out, scene.case_count,
                                    figures=None if args.figures else False, table=progress)
    with writer:
        for note in writer.staging_notes:      # a dead run's staging folder, removed
            print(f"contact: warning: {note}", file=sys.stderr, flush=True)
        with _executor(args.jobs, args.scheduler, scene.case_count) as executor, \
                cyclic_gc_paused():
            run = scenes.iter_scene(scene, executor=executor, progress=progress,
                                    encode=writer.encoder())
            for results in run.chunks():
                with _writing_into(args.out):
                    writer.add_all(results)
        # the table to a reader gone: the files are still written (status 141 after)
        reader_gone = progress and not _print_out(writer.table(run.timing_s))
        messages = run.warnings                # a figure that cannot be drawn adds its own
        with _writing_into(args.out):
            written = writer.finish(run.timing_s, messages, progress=progress)
    stale = scenes.stale_outputs(args.out, written)
    if stale:
        messages = [*messages, f"--out {args.out} also holds {', '.join(stale)}, which this "
                    "run did not write (an earlier run's?)"]
    for message in messages:
        print(f"contact: warning: {message}", file=sys.stderr)
    if progress and not reader_gone:
        reader_gone = not _print_out(f"  wrote {', '.join(str(p) for p in written)}")
    return EXIT_BROKEN_PIPE if reader_gone else 0


@contextlib.contextmanager
def _writing_into(out):
    """An OSError while the outputs are written names --out."""
    try:
        yield
    except OSError as exc:
        raise OSError(f"cannot write the outputs into --out {out}: {exc}") from None


# --------------------------------------------------------------------------
# contact run: where its cases are solved (here, a pool of forked workers, a Dask cluster)
# --------------------------------------------------------------------------
def usable_cpus() -> int:
    """The CPUs this process may run on: its affinity mask where the platform keeps one (the
    share of the machine that a container's cpuset or ``taskset`` gives it, which
    ``os.cpu_count()`` does not see), else the machine's CPUs."""
    count = getattr(os, "process_cpu_count", None)          # Python >= 3.13
    if count is not None:
        return count() or 1
    try:
        return len(os.sched_getaffinity(0)) or 1
    except AttributeError:                                   # not Linux
        return os.cpu_count() or 1


@contextlib.contextmanager
def _executor(jobs: int, scheduler: str | None, cases: int | None = None):
    """None (serial), a process pool, or a Dask cluster's concurrent.futures executor.
    ``--jobs 0`` is one worker per CPU this process may use (:func:`usable_cpus`), and a
    pool has no more workers than ``cases`` (where given); more workers than CPUs is a
    warning: they share the CPUs, each forked with its own memory, and run slower than one
    per CPU."""
    if scheduler is not None:
        if jobs not in (0, 1):
            raise UsageError("give --jobs or --scheduler, not both (the cluster decides how "
                             "many workers run the sweep)")
        with _dask_executor(scheduler) as ex:
            yield ex
        return
    cpus, asked = usable_cpus(), jobs
    if jobs == 0:
        jobs = cpus
    if cases is not None:
        jobs = min(jobs, max(cases, 1))
    if jobs > cpus:
        print(f"contact: warning: --jobs {asked} is more than the {cpus} CPU(s) this process "
              f"may use: its workers will share them, each with its own memory, slower than "
              f"one per CPU (--jobs 0)", file=sys.stderr, flush=True)
    if jobs == 1:
        yield None
        return
    with ProcessPoolExecutor(max_workers=jobs, mp_context=_pool_context(),
                             initializer=_worker_start, initargs=(os.getpid(),)) as ex:
        try:
            yield ex
        except BrokenProcessPool:
            _kill_workers(ex)
            raise


def _worker_start(command: int) -> None:
    """What a worker of ``--jobs`` does first: it leaves the signals that stop the command
    to the command (:func:`_worker_signals`) and dies with it (:func:`_die_with`)."""
    _worker_signals()
    _die_with(command)


def _die_with(command: int) -> None:
    """End this process (SIGKILL) when the process ``command``, its parent, ends, however
    it ends (Linux's ``PR_SET_PDEATHSIG``): a pool's worker otherwise outlives a command
    killed outright (SIGKILL, the out-of-memory killer), waiting for work forever, since it
    holds its own end of the pool's queues.  Elsewhere nothing is done."""
    if not sys.platform.startswith("linux"):
        return
    import ctypes
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, int(signal.SIGKILL), 0, 0, 0)
    except (OSError, AttributeError):       # no prctl to be found: as elsewhere
        return
    if os.getppid() != command:             # the command ended before prctl was set
        os._exit(1)


#: prctl's option that sends a signal to a process when its parent ends (linux/prctl.h).
_PR_SET_PDEATHSIG = 1


def _worker_signals():
    """In a worker of ``--jobs``: SIGINT and SIGTERM ignored.  Ctrl-C sends SIGINT to the
    whole process group, and a batch system or service manager SIGTERM to every process of
    the job; the command alone stops on either: it cancels the chunks not started and shuts
    its pool down, whose workers end as they finish their chunk.  A worker that ended on the
    signal would break the pool under the command as it stops, and Python 3.11's pool,
    marking its futures failed, trips over those the command has just cancelled
    (InvalidStateError in its manager thread, which then never closes its queues: the
    command hangs at exit).  A worker that dies otherwise (killed by the system) still
    breaks the pool: :func:`_kill_workers` then ends the others."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_IGN)


def _kill_workers(pool) -> None:
    """Kill (SIGKILL) the workers of a broken process pool: it ends them with SIGTERM,
    which they ignore (:func:`_worker_signals`), and waits for them."""
    kill = getattr(pool, "kill_workers", None)                  # Python >= 3.14
    if kill is not None:
        kill()
        return
    for proc in list((getattr(pool, "_processes", None) or {}).values()):
        with contextlib.suppress(OSError, ValueError):      # ended, or closed, meanwhile
            proc.kill()


def _pool_context():
    """The multiprocessing context of ``--jobs N``'s pool: "fork" on Linux, whatever the
    interpreter's default (from Python 3.14 it is "forkserver" there), so that the workers
    start as copies of this process after its first cases, the libraries imported and
    numba's kernels loaded, instead of spending their start on them again; elsewhere the
    platform's default ("spawn" on macOS and Windows, where forking a process that has
    loaded system frameworks is unsafe)."""
    if sys.platform.startswith("linux"):
        return multiprocessing.get_context("fork")
    return multiprocessing.get_context()


@contextlib.contextmanager
def _dask_executor(address: str):
    try:
        from distributed import Client
    except ImportError:
        raise UsageError("--scheduler needs Dask's distributed scheduler, which is an optional "
                         "extra: pip install 'sie-contact[dask]'") from None
    try:
        client = Client(address, timeout="20s")
    except (OSError, TimeoutError, ValueError) as exc:
        raise UsageError(f"--scheduler {address}: cannot connect to a Dask scheduler there "
                         f"({type(exc).__name__}: {exc})") from None
    with client:
        if not client.nthreads():           # the sweep would wait for workers, silently
            print(f"contact: --scheduler {address} has no workers yet: waiting for one (start "
                  f"them with `dask worker {address}`; Ctrl-C stops)", file=sys.stderr,
                  flush=True)
            client.wait_for_workers(1)
        with _watching_workers(client, address):
            yield client.get_executor(pure=False)


#: Seconds between two looks at a cluster's workers during a sweep (:func:`_watching_workers`).
WATCH_S = 2.0


@contextlib.contextmanager
def _watching_workers(client, address: str):
    """Say when the cluster has lost every worker during the sweep (a cluster waits for new
    ones, and the sweep with it, without a word otherwise: workers ended by a batch system, a
    machine lost) and when it has workers again: a thread looks every ``WATCH_S``."""
    import threading
    stop = threading.Event()

    def watch():
        without = False
        while not stop.wait(WATCH_S):
            try:
                none = not client.nthreads()
            except Exception:               # the client has closed: the sweep says so
                return
            if none and not without:
                print(f"contact: warning: --scheduler {address} has no workers left: the "
                      "sweep waits for new ones (Ctrl-C stops)", file=sys.stderr, flush=True)
            elif without and not none:
                print(f"contact: --scheduler {address} has workers again", file=sys.stderr,
                      flush=True)
            without = none
    watcher = threading.Thread(target=watch, name="contact-workers-watch", daemon=True)
    watcher.start()
    try:
        yield
    finally:
        stop.set()


# --------------------------------------------------------------------------
# contact table1
# --------------------------------------------------------------------------
def cmd_table1(args) -> int:
    if not 0 <= args.digits <= 17:
        raise UsageError(f"--digits must be in [0, 17], got {args.digits}")
    print(format_table1(contact.zhou2014(), args.digits))
    return 0


def format_table1(material, digits: int = 4) -> str:
    """Table 1 of Zhou et al. 2014: the roots (eta1, -eta1, eta3, -eta3) of eq. (3.1) at the
    paper's 14 speeds (|eta1| >= |eta3|; the paper's columns at c = 1 are in another order)."""
    rows = [(f"{c:g}", *(_complex(z, digits) for z in material.characteristic_roots(c)))
            for c in TABLE1_SPEEDS]
    header = ("c", "eta1", "eta2 = -eta1", "eta3", "eta4 = -eta3")
    widths = [max(len(h), *(len(r[k]) for r in rows)) for k, h in enumerate(header)]
    lines = ["Table 1 (Zhou, Lee & Jang 2014): characteristic roots of eq. (3.1), "
             "material C11, C12, C22, C33 = "
             f"{material.C11:.10g}, {material.C12:.10g}, {material.C22:.10g}, {material.C33:.10g}",
             "  ".join(h.rjust(w) for h, w in zip(header, widths))]
    lines += ["  ".join(v.rjust(w) for v, w in zip(r, widths)) for r in rows]
    return "\n".join(lines)


def _complex(z: complex, digits: int) -> str:
    re, im = z.real + 0.0, z.imag + 0.0
    if im == 0.0:
        return f"{re:.{digits}f}"
    if re == 0.0:
        return f"{im:.{digits}f}i"
    return f"{re:.{digits}f}{im:+.{digits}f}i"


# --------------------------------------------------------------------------
# contact constants
# --------------------------------------------------------------------------
def cmd_constants(args) -> int:
    scene = scenes.load_scene(args.scene) if args.scene else None
    material = scene.material.build() if scene else contact.zhou2014()
    spec = scene.material if scene else scenes.MaterialSpec(
        *(getattr(material, k) for k in ("C11", "C12", "C22", "C33")), preset="zhou2014")
    if args.speed is not None:
        speeds = [args.speed]
    elif scene is not None:
        speeds = list(dict.fromkeys(case.speed for case in scene.iter_cases()))
    else:
        raise UsageError("contact constants needs --speed C (or a scene whose [motion] gives "
                         "the speeds)")
    source = scene.source if scene else "zhou2014 (default)"
    print(format_constants(material, speeds, f"{source}, {spec.describe()}"))
    return 0


def format_constants(material, speeds, source: str) -> str:
    """N11, N12, N21, N22 (M12, M21, M22 where a material has them; eta1 eta2, eta1 + eta2,
    "-" for a material without them: :class:`contact.SurfaceConstants`) at each speed, and
    c_R; ``source`` names the material."""
    c_R = contact.rayleigh_speed(material)
    ks = [contact.surface_constants(material, c) for c in speeds]
    # the couplings of a material that is not an aligned orthotropic one, where it has them
    coupled = any(v != 0.0 for k in ks for v in (k.M12, k.M21, k.M22))
    names = ("N11", "N12", "N21", "N22") + (("M12", "M21", "M22") if coupled else ())
    header = ("c",) + names + ("eta1*eta2", "eta1+eta2")
    rows = []
    for c, k in zip(speeds, ks):
        rows.append((f"{c:g}", *("-" if v is None else f"{v:.12g}"
                                 for v in [getattr(k, n) for n in names]
                                 + [k.eta_product, k.eta_sum])))
    widths = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(header)]
    relations = ("dv/dX = N12 q + N11 Hc[p] + M12 Hc[q], sigma_XX = N21 p + N22 Hc[q] + "
                 "M21 Hc[p] + M22 q" if coupled else
                 "dv/dX = N12 q + N11 Hc[p], sigma_XX = N21 p + N22 Hc[q]")
    lines = [f"Surface constants ({relations}); material: {source}; N11, N12"
             f"{', M12' if coupled else ''} in 1/(stress unit)",
             f"Rayleigh speed c_R = {c_R!r} (admissible: 0 <= c < c_R)",
             "  ".join(h.rjust(w) for h, w in zip(header, widths))]
    lines += ["  ".join(v.rjust(w) for v, w in zip(r, widths)) for r in rows]
    return "\n".join(lines)


# --------------------------------------------------------------------------
# contact punches
# --------------------------------------------------------------------------
def cmd_punches(args) -> int:
    print(format_punches())
    return 0


def format_punches() -> str:
    """One row per punch kind of :data:`contact.registry.KINDS`: its class, scene keys and
    closed form, then its summary."""
    header = ("kind", "class", "scene keys", "closed form")
    rows = [(k.name, f"contact.{k.cls.__name__}", ", ".join(k.keys), k.closed_form or "-")
            for k in KINDS.values()]
    widths = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(header)]
    lines = ["Punch kinds ([punch] kind = ...; dimensions may be lists, i.e. sweeps; closed "
             "forms in contact.closed_form)",
             "  ".join(h.ljust(w) for h, w in zip(header, widths)).rstrip()]
    lines += ["  ".join(v.ljust(w) for v, w in zip(r, widths)).rstrip() for r in rows]
    lines.append("")
    lines += [f"{k.name}: {k.summary}" for k in KINDS.values()]
    return "\n".join(lines)
