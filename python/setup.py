"""Packaging glue: the compiled core is built by CMake (``make``), not here.

Declaring an extension makes the wheel platform-specific (cp311-linux), as
the ``_core`` it carries is; installing before ``make`` fails with a clear
message instead of producing a package that cannot import.
"""
from pathlib import Path

from setuptools import setup
from setuptools.dist import Distribution

HERE = Path(__file__).resolve().parent
if not any((HERE / "accsim").glob("_core*.so")):
    raise SystemExit("accsim: accsim/_core*.so is missing; build it first with `make` in the repository root")


class BinaryDistribution(Distribution):
    def has_ext_modules(self):
        return True


setup(distclass=BinaryDistribution)
