"""contact: a rigid punch sliding with Coulomb friction over an orthotropic half-space.

Zhou, Lee & Jang, "Indentation theory on orthotropic materials subjected to a frictional
moving punch", Arch. Mech. 66 (2014), corrected (see the documentation, Theory: errata of
Zhou et al. 2014) and generalised:
any orthotropic material, any anisotropic one in any orientation (:class:`Anisotropic`), or
any material of one's own with the methods of the :class:`Material` protocol; any punch
profile, both directions of sliding.  The numerical
path goes through :func:`sie.solve`; the paper's closed forms (corrected) are available as
``method="closed_form"`` and serve as regression oracles.
"""
from .anisotropic import Anisotropic, SurfaceResponse
from .constants import (SurfaceConstants, limiting_speed, rayleigh_speed, relative_speed,
                        surface_constants)
from .continuation import Event
from .errors import (CauchyTransformError, ContactInputError, ContactLossError,
                     DirectionError, FrictionError, LoadError, MaterialError,
                     NearRayleighWarning, ProfileCallableError, PunchGeometryError, SpeedError,
                     StressPointError, UnboundedStressError)
from .fretting import FrettingCycle, FrettingState, fretting_cycle
from .material import Isotropic, Orthotropic, zhou2014
from .partial_slip import CoupledPartialSlipError, PartialSlipResult
from .protocol import Material, MaterialModes, SurfaceKernel
from .punches import (CylindricalPunch, FlatPunch, ParabolicPunch, ProfilePunch, Punch,
                      TriangularPunch)
from .result import ContactZone, LoadCurve
from .samples import OutsideSamplesError, SampleError
from .solver import ContactResult, contact_length, load_curve, solve, solve_batch
from .subsurface import Extremum, StressExtrema, StressField, half_space_stress

__all__ = [
    "Material", "MaterialModes", "SurfaceKernel", "Orthotropic", "Isotropic", "zhou2014",
    "Anisotropic", "SurfaceResponse",
    "SurfaceConstants", "surface_constants", "rayleigh_speed", "limiting_speed",
    "relative_speed",
    "Punch", "FlatPunch", "TriangularPunch", "ParabolicPunch", "CylindricalPunch", "ProfilePunch",
    "solve", "solve_batch", "load_curve", "ContactResult", "ContactZone", "LoadCurve", "Event",
    "PartialSlipResult", "CoupledPartialSlipError", "fretting_cycle", "FrettingCycle",
    "FrettingState",
    "contact_length",
    "StressField", "StressExtrema", "Extremum", "half_space_stress",
    "ContactInputError", "MaterialError", "SpeedError", "LoadError", "FrictionError",
    "DirectionError", "PunchGeometryError", "SampleError", "OutsideSamplesError",
    "ProfileCallableError", "ContactLossError",
    "StressPointError", "UnboundedStressError", "CauchyTransformError",
    "NearRayleighWarning",
]
