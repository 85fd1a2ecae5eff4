"""Tables as NumPy arrays where NumPy is installed (Debian: python3-numpy), else plain lists."""
try:
    import numpy
except ImportError:  # pragma: no cover - exercised only without NumPy
    numpy = None


def array(rows):
    """A list of equal-length rows (tuples) as a 2-D array, or the list itself without NumPy."""
    return numpy.array(rows, dtype=float) if numpy is not None else [list(r) for r in rows]


def column(values):
    """A list of numbers as a 1-D array, or the list itself without NumPy."""
    values = list(values)
    return numpy.array(values, dtype=float) if numpy is not None else values
