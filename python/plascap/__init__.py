"""plascap: plastic capacities of structural cross sections, in SI units (m, N, N*m, Pa).

    import plascap
    ipe = plascap.Section.shape("IPE 300", material="S355")
    ipe.capacities().Mx   # 223,000 N*m: Wpl,y * fy = 628.4 cm^3 * 355 MPa

Bad input raises plascap.InputError (a ValueError) with the message the command-line tools print.
See docs/python.md.
"""
from ._plascap import (  # noqa: F401
    Capacities,
    ElasticProperties,
    InputError,
    Material,
    PlasticTorsion,
    Section,
    TorsionConstant,
    YieldCondition,
    __version__,
    engines,
    material,
    materials,
    shape_families,
    shapes,
)
from .arrays import array as _array
from .scenes import run_scene
from .sweep import sweep, table


def _interaction_curve(self, cut, samples=72, N=0.0):
    """Points of a cut through the exact yield surface, in order around it: 'N-Mx' -> (N, Mx) rows,
    'N-Mz' -> (N, Mz), 'Mx-Mz' at the axial force N -> (Mx, Mz); N [N], moments [N*m]. An array of
    shape (samples, 2) with NumPy, else a list of pairs. samples: 8 to 100000."""
    return _array(self._interaction_curve(cut, samples, N))


Section.interaction_curve = _interaction_curve

__all__ = [
    "Capacities", "ElasticProperties", "InputError", "Material", "PlasticTorsion", "Section",
    "TorsionConstant", "YieldCondition", "engines", "material", "materials", "run_scene",
    "shape_families", "shapes", "sweep", "table",
]
