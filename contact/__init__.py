"""contact: moving frictional punch on an orthotropic half-space (Zhou, Lee & Jang 2014).

Not implemented yet: this package is the subject of issue 4 and builds on :mod:`sie`.
"""
__all__: list[str] = []
