"""pytest set-up for the toyhost suite: the package must be importable (PYTHONPATH=BUILD/python,
which CTest sets), and the support module beside the tests."""

import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
