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
    __version__,
    material,
    materials,
    shape_families,
    shapes,
)

__all__ = [
    "Capacities", "ElasticProperties", "InputError", "Material", "PlasticTorsion", "Section",
    "TorsionConstant", "material", "materials", "shape_families", "shapes",
]
