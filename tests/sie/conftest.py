"""Configuration of the sie tests: tests that set mpmath's working precision leave the rest
of the suite its own."""
import mpmath
import pytest


@pytest.fixture(autouse=True)
def _mpmath_precision():
    """mpmath's working precision restored after every test."""
    dps = mpmath.mp.dps
    yield
    mpmath.mp.dps = dps
