"""The layers of the package, read from its import statements (ast): no module runs.

The physics (``sie``, ``contact`` but its application) never imports the application (the
scene, the command line, the punch registry they read); no module imports a private name
(``_x``) from another package; the application imports only what ``contact.__all__`` and
``sie.__all__`` export (and its own modules); and no two modules import each other, however
indirectly.
"""
import ast
from pathlib import Path

import pytest

import contact
import sie

ROOT = Path(contact.__file__).resolve().parent.parent
PACKAGES = ("sie", "contact")
#: The application: what runs scenes and commands on top of the public API.
APPLICATION = ("contact.scene", "contact.cli", "contact.__main__", "contact.registry")
PUBLIC = {"sie": set(sie.__all__), "contact": set(contact.__all__)}


def _module_name(path):
    parts = path.relative_to(ROOT).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports():
    """[(importer, target module, names or None, line)] for every import of sie / contact,
    including those inside functions."""
    out = []
    for pkg in PACKAGES:
        for path in sorted((ROOT / pkg).rglob("*.py")):
            mod = _module_name(path)
            package = mod if path.name == "__init__.py" else mod.rpartition(".")[0]
            for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
                if isinstance(node, ast.ImportFrom):
                    if node.level:
                        base = package.split(".")
                        base = base[:len(base) - node.level + 1]
                        target = ".".join(base + ([node.module] if node.module else []))
                    else:
                        target = node.module or ""
                    if target.split(".")[0] in PACKAGES:
                        out.append((mod, target, [a.name for a in node.names], node.lineno))
                elif isinstance(node, ast.Import):
                    for a in node.names:
                        if a.name.split(".")[0] in PACKAGES:
                            out.append((mod, a.name, None, node.lineno))
    return out


IMPORTS = _imports()


def _in_app(mod):
    return any(mod == a or mod.startswith(a + ".") for a in APPLICATION)


def test_the_walk_sees_the_package():
    """The walk finds the imports it judges (a walk that found none would pass anything)."""
    importers = {m for m, *_ in IMPORTS}
    assert {"contact.solver", "sie.solver", "contact.scene.run", "contact.cli"} <= importers
    assert len(IMPORTS) > 100


def test_the_physics_does_not_import_the_application():
    bad = [(m, t, ln) for m, t, names, ln in IMPORTS if not _in_app(m)
           and (_in_app(t) or any(_in_app(f"{t}.{n}") for n in names or ()))]
    assert not bad, bad


def test_no_private_name_is_imported_from_another_package():
    bad = [(m, t, n, ln) for m, t, names, ln in IMPORTS for n in names or ()
           if n.startswith("_") and t.split(".")[0] != m.split(".")[0]]
    assert not bad, bad


def test_the_application_uses_the_public_api_only():
    """Beside its own modules, the application imports ``sie`` and ``contact`` and the names
    their ``__all__`` export, nothing else of them."""
    bad = []
    for m, t, names, ln in IMPORTS:
        if not _in_app(m) or _in_app(t):
            continue
        if names is None:
            if t not in PACKAGES:
                bad.append((m, t, ln))
            continue
        for n in names:
            if _in_app(f"{t}.{n}"):
                continue
            if t not in PACKAGES or n not in PUBLIC[t]:
                bad.append((m, f"{t}.{n}", ln))
    assert not bad, bad


def test_no_import_cycle():
    """No two modules import each other, however indirectly, counting the imports inside
    functions too (an import put off into a function to break a cycle is still one)."""
    modules = {_module_name(p) for pkg in PACKAGES for p in (ROOT / pkg).rglob("*.py")}
    edges = {m: set() for m in modules}
    for m, t, names, _ in IMPORTS:
        for x in [t] + [f"{t}.{n}" for n in names or ()]:
            # a module depends on the modules it names; ``import contact`` or ``from sie
            # import ...`` (the package's public face) is not an edge into its __init__
            if x in modules and x != m and x not in PACKAGES:
                edges[m].add(x)
    state, stack, cycles = {}, [], []

    def visit(m):
        state[m] = 1
        stack.append(m)
        for t in sorted(edges[m]):
            if state.get(t) == 1:
                cycles.append(stack[stack.index(t):] + [t])
            elif t not in state:
                visit(t)
        stack.pop()
        state[m] = 2
    for m in sorted(edges):
        if m not in state:
            visit(m)
    assert not cycles, cycles
