import sys
from pathlib import Path

# Import the package from the source tree (the CMake build puts _core next to it).
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
